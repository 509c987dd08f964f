//! Sets › Sequence, random and recursive: Random, Jitter, Random Reduce and Fibonacci.
//!
//! The random nodes draw from [`DotNetRandom`], a re-statement of .NET's `System.Random(seed)`
//! (Knuth's subtractive generator, the algorithm .NET keeps for seeded instances), which is
//! what Grasshopper's components are built on. A seed gives the same numbers on every run and
//! every machine, and the numbers do not depend on the number of threads: each solve call
//! (one list) starts its own generator from its seed.

use locus_kernel::Interval;
use locus_runtime::{Branch, Column, DataType, NodeError, NodeRegistry, NodeType, Port, Value};

use crate::maths::sequence::MAX_SEQUENCE_LENGTH;

/// Id of [`random`].
pub const RANDOM: &str = "sets.random";
/// Id of [`jitter`].
pub const JITTER: &str = "sets.jitter";
/// Id of [`random_reduce`].
pub const RANDOM_REDUCE: &str = "sets.random_reduce";
/// Id of [`fibonacci`].
pub const FIBONACCI: &str = "sets.fibonacci";

/// Registers the random and Fibonacci nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [random(), jitter(), random_reduce(), fibonacci()] {
        registry.register(t);
    }
}

/// .NET's `System.Random` for a given seed: Knuth's subtractive generator with .NET's seeding
/// (`MSEED` = 161803398, 55 words, lag 21) and its arithmetic wrapping on 32-bit integers.
#[derive(Clone, Debug)]
pub struct DotNetRandom {
    seeds: [i32; 56],
    next: usize,
    next_p: usize,
}

const MBIG: i32 = i32::MAX;
const MSEED: i32 = 161_803_398;

impl DotNetRandom {
    /// The generator `new System.Random(seed)` would be.
    pub fn new(seed: i32) -> Self {
        let mut seeds = [0_i32; 56];
        let subtraction = if seed == i32::MIN {
            i32::MAX
        } else {
            seed.abs()
        };
        let mut mj = MSEED.wrapping_sub(subtraction);
        seeds[55] = mj;
        let mut mk = 1_i32;
        let mut ii = 0_usize;
        for _ in 1..55 {
            ii += 21;
            if ii >= 55 {
                ii -= 55;
            }
            seeds[ii] = mk;
            mk = mj.wrapping_sub(mk);
            if mk < 0 {
                mk = mk.wrapping_add(MBIG);
            }
            mj = seeds[ii];
        }
        for _ in 1..5 {
            for i in 1..56 {
                let mut n = i + 30;
                if n >= 55 {
                    n -= 55;
                }
                seeds[i] = seeds[i].wrapping_sub(seeds[1 + n]);
                if seeds[i] < 0 {
                    seeds[i] = seeds[i].wrapping_add(MBIG);
                }
            }
        }
        Self {
            seeds,
            next: 0,
            next_p: 21,
        }
    }

    fn internal_sample(&mut self) -> i32 {
        self.next += 1;
        if self.next >= 56 {
            self.next = 1;
        }
        self.next_p += 1;
        if self.next_p >= 56 {
            self.next_p = 1;
        }
        let mut r = self.seeds[self.next].wrapping_sub(self.seeds[self.next_p]);
        if r == MBIG {
            r -= 1;
        }
        if r < 0 {
            r = r.wrapping_add(MBIG);
        }
        self.seeds[self.next] = r;
        r
    }

    /// `NextDouble()`: a number in `[0, 1)`.
    pub fn next_double(&mut self) -> f64 {
        f64::from(self.internal_sample()) * (1.0 / f64::from(MBIG))
    }

    /// `Next(min, max)`: an integer in `[min, max)` (`min` when `max <= min`).
    pub fn next_in(&mut self, min: i32, max: i32) -> i32 {
        let range = i64::from(max) - i64::from(min);
        if range <= 0 {
            return min;
        }
        if range <= i64::from(i32::MAX) {
            (self.next_double() * range as f64) as i32 + min
        } else {
            let mut result = self.internal_sample();
            if self.internal_sample() % 2 == 0 {
                result = -result;
            }
            let d =
                (f64::from(result) + f64::from(i32::MAX - 1)) / (2.0 * f64::from(i32::MAX) - 1.0);
            ((d * range as f64) as i64 + i64::from(min)) as i32
        }
    }
}

/// A seed input as the 32-bit seed .NET takes: its low 32 bits.
fn seed32(seed: i64) -> i32 {
    // Truncation is the documented rule.
    seed as i32
}

/// A count input checked to be in `0..=MAX_SEQUENCE_LENGTH`.
fn count(value: i64, what: &str) -> Result<usize, NodeError> {
    match usize::try_from(value) {
        Ok(n) if n <= MAX_SEQUENCE_LENGTH => Ok(n),
        Ok(_) => Err(NodeError(format!(
            "{what} must be at most {MAX_SEQUENCE_LENGTH}, not {value}"
        ))),
        Err(_) => Err(NodeError(format!(
            "{what} must not be negative, not {value}"
        ))),
    }
}

fn sequence(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("Sequence")
}

fn seed_port(default: i64) -> Port {
    Port::new("Seed", "S", DataType::Integer)
        .doc(&format!(
            "The seed of the random generator: the same seed gives the same result; only its \
             low 32 bits count (.NET seeds are 32-bit); default {default}."
        ))
        .default_value(default)
}

/// Random \[Random\]: a list of pseudo-random numbers in a domain.
pub fn random() -> NodeType {
    sequence(RANDOM, "Random", "Random")
        .gh_guid("2ab17f9a-d852-4405-80e1-938c5e57e78d")
        .description(
            "Generates N pseudo-random numbers in the domain R, reproducibly from the seed S: \
             the generator is .NET's System.Random(S), as in Grasshopper, and number k is \
             R.t0 + u·(R.t1 − R.t0) for its k-th NextDouble() u. With the integers setting, \
             the numbers are whole, drawn with Next(a, b + 1) between a = ⌈min R⌉ and \
             b = ⌊max R⌋, both included (a domain that holds no integer is an error). The \
             same seed gives the same list with any number of threads.",
        )
        .input(
            Port::new("Range", "R", DataType::Domain)
                .doc("The domain of the numbers; default 0 to 1.")
                .default_value(Interval::UNIT),
        )
        .input(
            Port::new("Number", "N", DataType::Integer)
                .doc(&format!(
                    "How many numbers to generate, 0 to {MAX_SEQUENCE_LENGTH}; default 10."
                ))
                .default_value(10_i64),
        )
        .input(seed_port(2))
        .output(
            Port::new("Random", "R", DataType::Number)
                .list()
                .doc("The N random numbers."),
        )
        .setting(
            "integers",
            DataType::Boolean,
            Some(Value::Boolean(false)),
            "Whether to generate whole numbers (Grasshopper's Integer Numbers menu option); \
             default false.",
        )
        .solve(|s| {
            let domain = *s.item::<Interval>(0)?;
            let n = count(*s.item::<i64>(1)?, "number N")?;
            let mut rng = DotNetRandom::new(seed32(*s.item::<i64>(2)?));
            if !(domain.t0.is_finite() && domain.t1.is_finite()) {
                return Err(NodeError(format!(
                    "the range {} to {} is not finite",
                    domain.t0, domain.t1
                )));
            }
            let integers = matches!(s.setting("integers"), Some(Value::Boolean(true)));
            let values: Vec<f64> = if integers {
                let lo = domain.t0.min(domain.t1).ceil();
                let hi = domain.t0.max(domain.t1).floor();
                let fits = |x: f64| x >= f64::from(i32::MIN) && x < f64::from(i32::MAX);
                if lo > hi {
                    return Err(NodeError(format!(
                        "the range {} to {} holds no integer",
                        domain.t0, domain.t1
                    )));
                }
                if !fits(lo) || !fits(hi) {
                    return Err(NodeError(format!(
                        "the range {} to {} goes beyond 32-bit integers",
                        domain.t0, domain.t1
                    )));
                }
                let (lo, hi) = (lo as i32, hi as i32);
                (0..n)
                    .map(|_| f64::from(rng.next_in(lo, hi.saturating_add(1))))
                    .collect()
            } else {
                (0..n)
                    .map(|_| domain.t0 + rng.next_double() * (domain.t1 - domain.t0))
                    .collect()
            };
            s.set_list(0, values);
            Ok(())
        })
}

/// Jitter \[Jitter\]: a list shuffled by a random amount.
pub fn jitter() -> NodeType {
    sequence(JITTER, "Jitter", "Jitter")
        .gh_guid("f02a20f6-bb49-4e3d-b155-8ed5d3c6b000")
        .description(
            "Shuffles a list by a random amount, reproducibly from the seed S. Item i of the \
             n items gets the key (1 − J)·i/n + J·u_i, where u_i is the i-th NextDouble() of \
             .NET's System.Random(S); the items are sorted by key (a stable sort). J = 0 keeps \
             the order, J = 1 is a full random shuffle, values in between move items only \
             near their place. This rule is locus's: Grasshopper's own is not documented. \
             J outside 0 to 1 is clamped with a warning; NaN is an error. Nulls are shuffled \
             like any item.",
        )
        .input(
            Port::new("List", "L", DataType::Generic)
                .list()
                .doc("The list to shuffle, of any type."),
        )
        .input(
            Port::new("Jitter", "J", DataType::Number)
                .doc("The amount of shuffling, 0 (none) to 1 (complete); default 0.5.")
                .default_value(0.5),
        )
        .input(seed_port(2))
        .output(
            Port::new("Values", "V", DataType::Generic)
                .list()
                .doc("The shuffled list."),
        )
        .output(
            Port::new("Indices", "I", DataType::Integer)
                .list()
                .doc("For each item of V, its index in L."),
        )
        .solve(|s| {
            let branch = s
                .branch(0)
                .cloned()
                .unwrap_or_else(|| Branch::new(DataType::Generic));
            let mut j = *s.item::<f64>(1)?;
            if j.is_nan() {
                return Err(NodeError("jitter J is NaN".into()));
            }
            if !(0.0..=1.0).contains(&j) {
                s.warning(format!("jitter J = {j} is outside 0 to 1 and was clamped"));
                j = j.clamp(0.0, 1.0);
            }
            let mut rng = DotNetRandom::new(seed32(*s.item::<i64>(2)?));
            let n = branch.len();
            let keys: Vec<f64> = (0..n)
                .map(|i| (1.0 - j) * (i as f64 / n as f64) + j * rng.next_double())
                .collect();
            let mut order: Vec<usize> = (0..n).collect();
            order.sort_by(|&a, &b| keys[a].total_cmp(&keys[b]));
            s.set_branch(0, branch.gather(order.iter().map(|&i| Some(i))));
            s.set_list(
                1,
                order
                    .iter()
                    .map(|&i| i64::try_from(i).unwrap_or(i64::MAX))
                    .collect(),
            );
            Ok(())
        })
}

/// Random Reduce \[Reduce\]: a list with some items removed at random.
pub fn random_reduce() -> NodeType {
    sequence(RANDOM_REDUCE, "Random Reduce", "Reduce")
        .gh_guid("455925fd-23ff-4e57-a0e7-913a4165e659")
        .description(
            "Removes R items at random from a list, reproducibly from the seed S, and keeps \
             the order of the rest: R times, the item at index Next(0, count) of .NET's \
             System.Random(S) is removed. R larger than the list removes every item with a \
             warning; a negative R is an error.",
        )
        .input(
            Port::new("List", "L", DataType::Generic)
                .list()
                .doc("The list to reduce, of any type."),
        )
        .input(
            Port::new("Reduction", "R", DataType::Integer)
                .doc("The number of items to remove; default 1.")
                .default_value(1_i64),
        )
        .input(seed_port(2))
        .output(
            Port::new("List", "L", DataType::Generic)
                .list()
                .doc("The items of L that were kept, in their order."),
        )
        .solve(|s| {
            let branch = s
                .branch(0)
                .cloned()
                .unwrap_or_else(|| Branch::new(DataType::Generic));
            let r = *s.item::<i64>(1)?;
            if r < 0 {
                return Err(NodeError(format!(
                    "reduction R must not be negative, not {r}"
                )));
            }
            let n = branch.len();
            let remove = usize::try_from(r).unwrap_or(usize::MAX);
            if remove > n {
                s.warning(format!(
                    "reduction R = {r} is more than the {n} items of the list: all are removed"
                ));
            }
            let mut rng = DotNetRandom::new(seed32(*s.item::<i64>(2)?));
            let mut kept: Vec<usize> = (0..n).collect();
            for _ in 0..remove.min(n) {
                let len = i32::try_from(kept.len()).unwrap_or(i32::MAX);
                let k = usize::try_from(rng.next_in(0, len)).unwrap_or(0);
                kept.remove(k.min(kept.len() - 1));
            }
            s.set_branch(0, branch.gather(kept.into_iter().map(Some)));
            Ok(())
        })
}

/// Fibonacci \[Fib\]: a Fibonacci series from two seeds.
pub fn fibonacci() -> NodeType {
    sequence(FIBONACCI, "Fibonacci", "Fib")
        .gh_guid("fe99f302-3d0d-4389-8494-bd53f7935a02")
        .description(
            "Creates a Fibonacci series of N numbers: A, B, then each number the sum of the \
             two before it (0, 1, 1, 2, 3, 5, … for the defaults). N = 1 gives [A], N = 0 an \
             empty list; numbers that overflow are NaN with one warning.",
        )
        .input(
            Port::new("Seed A", "A", DataType::Number)
                .doc("The first number; default 0.")
                .default_value(0.0),
        )
        .input(
            Port::new("Seed B", "B", DataType::Number)
                .doc("The second number; default 1.")
                .default_value(1.0),
        )
        .input(
            Port::new("Number", "N", DataType::Integer)
                .doc(&format!(
                    "How many numbers, 0 to {MAX_SEQUENCE_LENGTH}; default 10."
                ))
                .default_value(10_i64),
        )
        .output(
            Port::new("Series", "S", DataType::Number)
                .list()
                .doc("The N numbers of the series."),
        )
        .solve(|s| {
            let a = *s.item::<f64>(0)?;
            let b = *s.item::<f64>(1)?;
            let n = count(*s.item::<i64>(2)?, "number N")?;
            let mut out = Vec::with_capacity(n);
            for k in 0..n {
                let x = match k {
                    0 => a,
                    1 => b,
                    _ => out[k - 1] + out[k - 2],
                };
                out.push(x);
            }
            if out.iter().any(|x: &f64| !x.is_finite()) {
                s.warning(crate::maths::invalid_number_warning(&format!(
                    "the series from {a} and {b} overflows"
                )));
                for x in &mut out {
                    if !x.is_finite() {
                        *x = f64::NAN;
                    }
                }
            }
            s.set_branch(0, Branch::from_column(Column::Number(out)));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall, TreePath};

    use super::*;
    use crate::sets::test_support::{generic, messages};
    use crate::test_support::{all, numbers};

    #[test]
    fn dot_net_random_is_deterministic_and_in_range() {
        let mut a = DotNetRandom::new(42);
        let mut b = DotNetRandom::new(42);
        for _ in 0..1000 {
            let x = a.next_double();
            assert_eq!(x, b.next_double());
            assert!((0.0..1.0).contains(&x));
        }
        let mut c = DotNetRandom::new(7);
        for _ in 0..1000 {
            let k = c.next_in(-3, 4);
            assert!((-3..4).contains(&k));
        }
        // Extreme seeds and ranges do not overflow.
        for seed in [i32::MIN, i32::MAX, 0, -1] {
            let mut r = DotNetRandom::new(seed);
            let k = r.next_in(i32::MIN, i32::MAX);
            assert!(k < i32::MAX);
        }
    }

    #[test]
    fn dot_net_random_replays_the_values_of_system_random() {
        // Reference values from Mono's System.Random (tools/oracle/dotnet_random.cs).
        let text = include_str!("../../tests/data/dotnet_random.json");
        let json: serde_json::Value = serde_json::from_str(text).expect("the oracle file reads");
        let cases = json["cases"].as_array().expect("a list of cases");
        assert_eq!(cases.len(), 8);
        for case in cases {
            let seed = i32::try_from(case["seed"].as_i64().expect("a seed")).expect("32 bits");
            let mut r = DotNetRandom::new(seed);
            for x in case["doubles"].as_array().expect("doubles") {
                // Round-trip doubles in text, read by Rust's correctly rounded parser (serde_json's
                // own float parsing may be off by an ulp), so equality is exact.
                let x: f64 = x
                    .as_str()
                    .expect("a number as text")
                    .parse()
                    .expect("a number");
                assert_eq!(r.next_double(), x, "seed {seed}");
            }
            for k in case["next_0_10"].as_array().expect("next_0_10") {
                assert_eq!(i64::from(r.next_in(0, 10)), k.as_i64().expect("an integer"));
            }
            for k in case["next_min_max"].as_array().expect("next_min_max") {
                assert_eq!(
                    i64::from(r.next_in(i32::MIN, i32::MAX)),
                    k.as_i64().expect("an integer"),
                    "seed {seed}"
                );
            }
        }
    }

    #[test]
    fn random_is_reproducible_and_in_its_domain() {
        let run = |seed: i64| {
            NodeCall::new(&random())
                .input(DataTree::from_item(Interval::new(5.0, 10.0)))
                .input(DataTree::from_item(100_i64))
                .input(DataTree::from_item(seed))
                .run()
        };
        let a = numbers(&run(3).outputs[0]);
        assert_eq!(a.len(), 100);
        assert!(a.iter().all(|x| (5.0..10.0).contains(x)));
        assert_eq!(a, numbers(&run(3).outputs[0]));
        assert_ne!(a, numbers(&run(4).outputs[0]));
    }

    #[test]
    fn random_integers_cover_both_ends() {
        let r = NodeCall::new(&random())
            .input(DataTree::from_item(Interval::new(1.0, 3.0)))
            .input(DataTree::from_item(200_i64))
            .setting("integers", Value::Boolean(true))
            .run();
        let xs = numbers(&r.outputs[0]);
        for k in [1.0, 2.0, 3.0] {
            assert!(xs.contains(&k), "{k} missing");
        }
        assert!(xs.iter().all(|x| [1.0, 2.0, 3.0].contains(x)));
        let r = NodeCall::new(&random())
            .input(DataTree::from_item(Interval::new(0.2, 0.8)))
            .setting("integers", Value::Boolean(true))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn random_rejects_bad_counts_and_ranges() {
        let r = NodeCall::new(&random())
            .skip_input()
            .input(DataTree::from_item(-1_i64))
            .run();
        assert_eq!(
            messages(&r, Level::Error),
            ["number N must not be negative, not -1"]
        );
        let r = NodeCall::new(&random())
            .input(DataTree::from_item(Interval::new(0.0, f64::INFINITY)))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        let r = NodeCall::new(&random())
            .skip_input()
            .input(DataTree::from_item(i64::MAX))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn random_is_identical_per_branch_for_any_thread_count() {
        // Each list starts its generator from its own seed, so a list does not depend on
        // the lists solved before it.
        let r = NodeCall::new(&random())
            .skip_input()
            .input(DataTree::from_item(5_i64))
            .input(DataTree::from_list(vec![1_i64, 2, 1]))
            .run();
        let paths: Vec<String> = r.outputs[0].paths().map(TreePath::to_string).collect();
        assert_eq!(paths, ["{0;0}", "{0;1}", "{0;2}"]);
        let b = r.outputs[0].branches();
        assert_eq!(b[0].1, b[2].1);
        assert_ne!(b[0].1, b[1].1);
    }

    #[test]
    fn jitter_zero_keeps_and_one_shuffles_a_permutation() {
        let list = generic("{0}:[0, 1, 2, 3, 4, 5, 6, 7, 8, 9]");
        let r = NodeCall::new(&jitter())
            .input(list.clone())
            .input(DataTree::from_item(0.0))
            .run();
        let idx: Vec<i64> = all(&r.outputs[1]);
        assert_eq!(idx, (0..10).collect::<Vec<i64>>());
        let r = NodeCall::new(&jitter())
            .input(list)
            .input(DataTree::from_item(1.0))
            .run();
        let mut idx: Vec<i64> = all(&r.outputs[1]);
        assert_ne!(idx, (0..10).collect::<Vec<i64>>());
        let values: Vec<f64> = numbers(&r.outputs[0]);
        let as_index: Vec<i64> = values.iter().map(|x| *x as i64).collect();
        assert_eq!(as_index, idx);
        idx.sort_unstable();
        assert_eq!(idx, (0..10).collect::<Vec<i64>>());
    }

    #[test]
    fn jitter_clamps_and_rejects_nan() {
        let r = NodeCall::new(&jitter())
            .input(generic("{0}:[1, 2]"))
            .input(DataTree::from_item(3.0))
            .run();
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        let r = NodeCall::new(&jitter())
            .input(generic("{0}:[1, 2]"))
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_eq!(messages(&r, Level::Error), ["jitter J is NaN"]);
    }

    #[test]
    fn random_reduce_removes_items_and_keeps_order() {
        let r = NodeCall::new(&random_reduce())
            .input(generic("{0}:[0, 1, 2, 3, 4, 5, 6, 7]"))
            .input(DataTree::from_item(3_i64))
            .run();
        let kept = numbers(&r.outputs[0]);
        assert_eq!(kept.len(), 5);
        assert!(kept.windows(2).all(|w| w[0] < w[1]));
        let r = NodeCall::new(&random_reduce())
            .input(generic("{0}:[0, 1]"))
            .input(DataTree::from_item(5_i64))
            .run();
        assert_eq!(r.outputs[0].item_count(), 0);
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        let r = NodeCall::new(&random_reduce())
            .input(generic("{0}:[0, 1]"))
            .input(DataTree::from_item(-1_i64))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn fibonacci_series() {
        let r = NodeCall::new(&fibonacci()).run();
        assert_eq!(
            numbers(&r.outputs[0]),
            [0.0, 1.0, 1.0, 2.0, 3.0, 5.0, 8.0, 13.0, 21.0, 34.0]
        );
        let r = NodeCall::new(&fibonacci())
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(0.5))
            .input(DataTree::from_item(1_i64))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [2.0]);
        let r = NodeCall::new(&fibonacci())
            .input(DataTree::from_item(1e308))
            .input(DataTree::from_item(1e308))
            .input(DataTree::from_item(4_i64))
            .run();
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        let r = NodeCall::new(&fibonacci())
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(-2_i64))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }
}
