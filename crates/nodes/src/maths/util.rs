//! Maths › Util and Trig: Average, Maximum, Minimum, Round, Radians, Degrees and Smooth
//! Numbers; and Maths › Domain › Bounds.
//!
//! Maximum, Minimum, Round, Radians and Degrees are plain functions of their items, lifted
//! over typed columns. Average takes numbers, points or vectors (the mean of points is their
//! centroid).

use locus_kernel::Interval;
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, number_to_integer};

use super::{invalid_number_warning, set_number};
use crate::expression::{BinaryOp, Operand};

/// Id of [`average`].
pub const AVERAGE: &str = "maths.average";
/// Id of [`maximum`].
pub const MAXIMUM: &str = "maths.maximum";
/// Id of [`minimum`].
pub const MINIMUM: &str = "maths.minimum";
/// Id of [`round`].
pub const ROUND: &str = "maths.round";
/// Id of [`radians`].
pub const RADIANS: &str = "maths.radians";
/// Id of [`degrees`].
pub const DEGREES: &str = "maths.degrees";
/// Id of [`bounds`].
pub const BOUNDS: &str = "maths.bounds";
/// Id of [`pi`].
pub const PI: &str = "maths.pi";
/// Id of [`one_over_x`].
pub const ONE_OVER_X: &str = "maths.one_over_x";
/// Id of [`smooth_numbers`].
pub const SMOOTH_NUMBERS: &str = "maths.smooth_numbers";

/// Registers the utility, trigonometry and Bounds nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        average(),
        maximum(),
        minimum(),
        round(),
        radians(),
        degrees(),
        bounds(),
        pi(),
        one_over_x(),
        smooth_numbers(),
    ] {
        registry.register(t);
    }
}

fn util(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Maths").subcategory("Util")
}

/// Average \[Avr\]: the arithmetic mean of a list.
pub fn average() -> NodeType {
    util(AVERAGE, "Average", "Avr")
        .gh_guid("7986486c-621a-48fb-8f27-a28a22c91cc9")
        .description(
            "Computes the arithmetic mean of a list of numbers, points or vectors (the mean of \
             points is their centroid). Null items are skipped; an empty list gives a null and \
             a warning.",
        )
        .input(
            Port::new("Input", "I", DataType::Generic)
                .list()
                .doc("The items to average: numbers, points or vectors (integers, booleans as 0/1 and text that reads as a number are accepted)."),
        )
        .output(
            Port::new("Arithmetic mean", "AM", DataType::Generic)
                .doc("The sum of the items divided by their count."),
        )
        .solve(|s| {
            let Some(branch) = s.branch(0) else {
                s.warning("input I failed to collect data");
                return Ok(());
            };
            if let Some(xs) = branch.slice::<f64>().filter(|_| !branch.has_nulls()) {
                if xs.is_empty() {
                    s.warning("the list has no items to average");
                    s.set_value(0, None);
                    return Ok(());
                }
                let mean = xs.iter().sum::<f64>() / xs.len() as f64;
                set_number(s, 0, mean, || format!("the mean of the list is {mean}"));
                return Ok(());
            }
            let mut sum: Option<Operand> = None;
            let mut count = 0_usize;
            for (k, value) in branch.values().enumerate() {
                let Some(value) = value else { continue };
                let at = |e: crate::expression::EvalError| {
                    NodeError(format!("item {k} of input I: {e}"))
                };
                // A point plus a point adds the coordinates, so points sum to 'count' times
                // their centroid.
                let x = Operand::from_value_numeric(&value).map_err(at)?;
                sum = Some(match sum {
                    None => x,
                    Some(a) => BinaryOp::Add.apply(&a, &x).map_err(at)?,
                });
                count += 1;
            }
            let Some(sum) = sum else {
                s.warning("the list has no items to average");
                s.set_value(0, None);
                return Ok(());
            };
            let mean = BinaryOp::Divide
                .apply(&sum, &Operand::Number(count as f64))
                .map_err(|e| NodeError(e.to_string()))?;
            if !mean.is_finite() {
                s.warning(invalid_number_warning(&format!("the mean is {mean}")));
            }
            s.set_value(0, Some(mean.with_invalid_as_nan().into_value()));
            Ok(())
        })
}

/// The larger of two numbers, NaN when either is NaN.
fn larger(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// The smaller of two numbers, NaN when either is NaN.
fn smaller(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.min(b)
    }
}

/// Maximum \[Max\]: the greater of two numbers.
pub fn maximum() -> NodeType {
    util(MAXIMUM, "Maximum", "Max")
        .gh_guid("0d1e2027-f153-460d-84c0-f9af431b08cb")
        .description(
            "Returns the greater of two numbers. When either is NaN the result is NaN (a NaN \
             is not greater or smaller than anything).",
        )
        .input(Port::new("Value A", "A", DataType::Number).doc("The first number."))
        .input(Port::new("Value B", "B", DataType::Number).doc("The second number."))
        .output(Port::new("Result", "R", DataType::Number).doc("The greater of A and B."))
        .lift2(|a: &f64, b: &f64| Ok(larger(*a, *b)))
}

/// Minimum \[Min\]: the lesser of two numbers.
pub fn minimum() -> NodeType {
    util(MINIMUM, "Minimum", "Min")
        .gh_guid("57308b30-772d-4919-ac67-e86c18f3a996")
        .description(
            "Returns the lesser of two numbers. When either is NaN the result is NaN (a NaN is \
             not greater or smaller than anything).",
        )
        .input(Port::new("Value A", "A", DataType::Number).doc("The first number."))
        .input(Port::new("Value B", "B", DataType::Number).doc("The second number."))
        .output(Port::new("Result", "R", DataType::Number).doc("The lesser of A and B."))
        .lift2(|a: &f64, b: &f64| Ok(smaller(*a, *b)))
}

/// Round \[Round\]: a number rounded to the nearest, lower and upper integers.
pub fn round() -> NodeType {
    util(ROUND, "Round", "Round")
        .gh_guid("a50c4a3b-0177-4c91-8556-db95de6c56c8")
        .description(
            "Rounds a number to integers: the nearest one (halves go to the even integer, as \
             .NET's Math.Round does: 0.5 → 0, 1.5 → 2, 2.5 → 2, −2.5 → −2), the largest not \
             above it (floor) and the smallest not below it (ceiling). NaN, infinities and \
             numbers beyond the 64-bit integer range are errors.",
        )
        .input(Port::new("Number", "x", DataType::Number).doc("The number to round."))
        .output(
            Port::new("Nearest", "N", DataType::Integer)
                .doc("The nearest integer, halves to even."),
        )
        .output(Port::new("Floor", "F", DataType::Integer).doc("The largest integer ≤ x."))
        .output(Port::new("Ceiling", "C", DataType::Integer).doc("The smallest integer ≥ x."))
        .solve(|s| {
            let x = *s.item::<f64>(0)?;
            let out = |y: f64| {
                number_to_integer(y)
                    .ok_or_else(|| NodeError(format!("{x} cannot be rounded to an integer")))
            };
            let (n, f, c) = (out(x)?, out(x.floor())?, out(x.ceil())?);
            s.set(0, n);
            s.set(1, f);
            s.set(2, c);
            Ok(())
        })
}

/// Radians \[Rad\]: degrees to radians.
pub fn radians() -> NodeType {
    NodeType::new(RADIANS, "Radians", "Rad", "Maths")
        .subcategory("Trig")
        .gh_guid("a4cd2751-414d-42ec-8916-476ebf62d7fe")
        .description("Converts an angle in degrees to radians (180° is π).")
        .input(Port::new("Degrees", "D", DataType::Number).doc("The angle in degrees."))
        .output(Port::new("Radians", "R", DataType::Number).doc("The angle in radians."))
        .lift1(|d: &f64| Ok(d.to_radians()))
}

/// Degrees \[Deg\]: radians to degrees.
pub fn degrees() -> NodeType {
    NodeType::new(DEGREES, "Degrees", "Deg", "Maths")
        .subcategory("Trig")
        .gh_guid("0d77c51e-584f-44e8-aed2-c2ddf4803888")
        .description("Converts an angle in radians to degrees (π is 180°).")
        .input(Port::new("Radians", "R", DataType::Number).doc("The angle in radians."))
        .output(Port::new("Degrees", "D", DataType::Number).doc("The angle in degrees."))
        .lift1(|r: &f64| Ok(r.to_degrees()))
}

/// Pi \[Pi\]: a multiple of π.
pub fn pi() -> NodeType {
    util(PI, "Pi", "Pi")
        .gh_guid("0d2ccfb3-9d41-4759-9452-da6a522c3eaa")
        .description("Returns N times π (π = 3.141592653589793, the nearest double).")
        .input(
            Port::new("Factor", "N", DataType::Number)
                .doc("The factor to multiply π by; default 1.")
                .default_value(1.0),
        )
        .output(Port::new("Output", "y", DataType::Number).doc("N · π."))
        .lift1(|n: &f64| Ok(n * std::f64::consts::PI))
}

/// One Over X \[1/x\]: the reciprocal of a number.
pub fn one_over_x() -> NodeType {
    NodeType::new(ONE_OVER_X, "One Over X", "1/x", "Maths")
        .subcategory("Polynomials")
        .gh_guid("797d922f-3a1d-46fe-9155-358b009b5997")
        .description("Computes 1 / x. Zero has no reciprocal: it is an error for that item.")
        .input(Port::new("Value", "x", DataType::Number).doc("The number."))
        .output(Port::new("Result", "y", DataType::Number).doc("1 / x."))
        .lift1(|x: &f64| {
            if *x == 0.0 {
                Err(NodeError("x is 0, which has no reciprocal".into()))
            } else {
                Ok(1.0 / x)
            }
        })
}

/// Smooth Numbers \[Smooth\]: numbers smoothed over successive solutions; one solution passes
/// them on unchanged.
pub fn smooth_numbers() -> NodeType {
    util(SMOOTH_NUMBERS, "Smooth Numbers", "Smooth")
        .gh_guid("5b424e1c-d061-43cd-8c20-db84564b0502")
        .description(
            "Passes numbers on, smoothed over time. Grasshopper's Smooth Numbers eases each \
             number from its value in the previous solution towards its new value over about \
             two seconds of repeated solutions, for animations driven by sliders; its first \
             solution passes the numbers on unchanged. A locus run is one solution with no \
             history and no clock, so the tree passes through unchanged, paths and nulls \
             included. NaN items pass through too, with a warning naming the input.",
        )
        .input(
            Port::new("Numbers", "N", DataType::Number)
                .tree()
                .optional()
                .doc("The changing numbers, a tree of any shape."),
        )
        .output(
            Port::new("Numbers", "N", DataType::Number)
                .tree()
                .doc("The smoothed numbers: the same tree in one solution."),
        )
        .solve(|s| {
            let tree = s.tree(0)?.clone();
            let nans = tree
                .values()
                .filter(|v| {
                    v.as_ref()
                        .and_then(|v| v.get::<f64>())
                        .is_some_and(f64::is_nan)
                })
                .count();
            if nans > 0 {
                s.warning(format!("input N: {nans} NaN item(s) passed on unchanged"));
            }
            s.set_tree(0, tree);
            Ok(())
        })
}

/// Bounds \[Bnd\]: the domain from the smallest to the largest number of a list.
pub fn bounds() -> NodeType {
    NodeType::new(BOUNDS, "Bounds", "Bnd", "Maths")
        .subcategory("Domain")
        .gh_guid("f44b92b0-3b5b-493a-86f4-fd7408c3daf3")
        .description(
            "Creates the numeric domain that encompasses a list of numbers: from the smallest \
             to the largest. Null items are skipped; NaN items are skipped with a warning; a \
             list with no number left gives a null and a warning. Infinite numbers are an \
             error (a domain has finite ends).",
        )
        .input(
            Port::new("Numbers", "N", DataType::Number)
                .list()
                .doc("The numbers to encompass."),
        )
        .output(
            Port::new("Domain", "I", DataType::Domain)
                .doc("The domain from the smallest to the largest number."),
        )
        .solve(|s| {
            let list = s.list::<f64>(0)?;
            let mut lo = f64::INFINITY;
            let mut hi = f64::NEG_INFINITY;
            let mut nans = 0_usize;
            let mut count = 0_usize;
            for (k, x) in list.iter().enumerate() {
                let Some(&x) = x else { continue };
                if x.is_nan() {
                    nans += 1;
                    continue;
                }
                if x.is_infinite() {
                    return Err(NodeError(format!(
                        "item {k} is {x}: a domain must have finite ends"
                    )));
                }
                count += 1;
                lo = lo.min(x);
                hi = hi.max(x);
            }
            if nans > 0 {
                s.warning(format!("{nans} NaN items were skipped"));
            }
            if count == 0 {
                s.warning("the list has no numbers");
                s.set_value(0, None);
                return Ok(());
            }
            s.set(0, Interval::new(lo, hi));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Point3, Vector3};
    use locus_runtime::{Branch, DataTree, Level, NodeCall, TreePath, Value};

    use super::*;
    use crate::maths::test_support::{assert_clean, is_null, messages, numbers, only};

    #[test]
    fn pi_and_one_over_x() {
        let r = NodeCall::new(&pi())
            .input(DataTree::from_list(vec![1.0, 2.0, -0.5]))
            .run();
        assert_eq!(
            numbers(&r.outputs[0]),
            [
                std::f64::consts::PI,
                std::f64::consts::TAU,
                -std::f64::consts::FRAC_PI_2
            ]
        );
        let r = NodeCall::new(&one_over_x())
            .input(DataTree::from_list(vec![4.0, 0.0, -0.25]))
            .run();
        let texts = messages(&r, Level::Error);
        assert_eq!(texts.len(), 1, "{texts:?}");
        assert!(texts[0].contains("x is 0"), "{texts:?}");
        assert_eq!(r.messages[0].index, Some(1));
        let out: Vec<Option<f64>> = r.outputs[0]
            .values()
            .map(|v| v.and_then(|v| v.get::<f64>()))
            .collect();
        assert_eq!(out, [Some(0.25), None, Some(-4.0)]);
    }

    fn generic(items: Vec<Option<Value>>) -> DataTree {
        let mut b = Branch::new(DataType::Generic);
        for v in items {
            b.push_option(v);
        }
        DataTree::from_branches([(TreePath::new(vec![0]), b)])
    }

    #[test]
    fn average_of_numbers_and_of_points() {
        let r = NodeCall::new(&average())
            .input(DataTree::from_list(vec![1.0, 2.0, 6.0]))
            .run();
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), 3.0);
        let r = NodeCall::new(&average())
            .input(generic(vec![
                Some(Value::Point(Point3::new(0.0, 0.0, 0.0))),
                None,
                Some(Value::Point(Point3::new(2.0, 4.0, 0.0))),
            ]))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Point3>(&r, 0), Point3::new(1.0, 2.0, 0.0));
        let r = NodeCall::new(&average())
            .input(generic(vec![
                Some(Value::Vector(Vector3::new(2.0, 0.0, 0.0))),
                Some(Value::Vector(Vector3::new(0.0, 2.0, 0.0))),
            ]))
            .run();
        assert_eq!(only::<Vector3>(&r, 0), Vector3::new(1.0, 1.0, 0.0));
    }

    #[test]
    fn average_of_nothing_or_of_text_is_reported() {
        let r = NodeCall::new(&average())
            .input(generic(vec![None, None]))
            .run();
        assert!(is_null(&r, 0));
        assert_eq!(
            messages(&r, Level::Warning),
            ["the list has no items to average"]
        );
        let r = NodeCall::new(&average())
            .input(generic(vec![Some(Value::Text("x".into()))]))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        let r = NodeCall::new(&average())
            .input(DataTree::from_list(vec![f64::MAX, f64::MAX]))
            .run();
        assert!(only::<f64>(&r, 0).is_nan());
        assert_eq!(messages(&r, Level::Warning).len(), 1);
    }

    #[test]
    fn maximum_and_minimum_pair_items_and_propagate_nan() {
        let r = NodeCall::new(&maximum())
            .input(DataTree::from_list(vec![1.0, 5.0, -2.0]))
            .input(DataTree::from_item(2.0))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [2.0, 5.0, 2.0]);
        let r = NodeCall::new(&minimum())
            .input(DataTree::from_list(vec![1.0, 5.0, f64::NAN]))
            .input(DataTree::from_item(2.0))
            .run();
        let out = numbers(&r.outputs[0]);
        assert_eq!(out[..2], [1.0, 2.0]);
        assert!(out[2].is_nan());
    }

    #[test]
    fn round_halves_to_even_and_floors_and_ceils() {
        let r = NodeCall::new(&round())
            .input(DataTree::from_list(vec![0.5, 1.5, 2.5, -2.5, -1.2, 3.7]))
            .run();
        assert_clean(&r);
        let n: Vec<i64> = crate::test_support::all(&r.outputs[0]);
        let f: Vec<i64> = crate::test_support::all(&r.outputs[1]);
        let c: Vec<i64> = crate::test_support::all(&r.outputs[2]);
        assert_eq!(n, [0, 2, 2, -2, -1, 4]);
        assert_eq!(f, [0, 1, 2, -3, -2, 3]);
        assert_eq!(c, [1, 2, 3, -2, -1, 4]);
    }

    #[test]
    fn round_rejects_numbers_without_an_integer() {
        let r = NodeCall::new(&round())
            .input(DataTree::from_list(vec![f64::NAN, 1e300, 1.0]))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 2);
        let n = crate::test_support::items::<i64>(&r.outputs[0]);
        assert_eq!(n, [None, None, Some(1)]);
    }

    #[test]
    fn radians_and_degrees_are_inverse() {
        let r = NodeCall::new(&radians())
            .input(DataTree::from_list(vec![180.0, 90.0, -45.0]))
            .run();
        let rad = numbers(&r.outputs[0]);
        assert_eq!(
            rad,
            [
                std::f64::consts::PI,
                std::f64::consts::FRAC_PI_2,
                -std::f64::consts::FRAC_PI_4
            ]
        );
        let r = NodeCall::new(&degrees())
            .input(DataTree::from_list(rad))
            .run();
        let deg = numbers(&r.outputs[0]);
        for (d, e) in deg.iter().zip([180.0, 90.0, -45.0]) {
            assert!((d - e).abs() < 1e-12);
        }
    }

    #[test]
    fn smooth_numbers_passes_one_solution_through() {
        let mut first = Branch::new(DataType::Number);
        first.push(1.0);
        first.push_null();
        let input = DataTree::from_branches([
            (TreePath::new(vec![0]), first),
            (TreePath::new(vec![1, 2]), Branch::from_items(vec![-3.5])),
        ]);
        let r = NodeCall::new(&smooth_numbers()).input(input.clone()).run();
        assert_clean(&r);
        assert_eq!(r.outputs[0], input);
    }

    #[test]
    fn smooth_numbers_reports_nan_and_takes_no_input() {
        let r = NodeCall::new(&smooth_numbers())
            .input(DataTree::from_list(vec![1.0, f64::NAN, 2.0]))
            .run();
        assert_eq!(
            messages(&r, Level::Warning),
            ["input N: 1 NaN item(s) passed on unchanged"]
        );
        assert_eq!(numbers(&r.outputs[0]).len(), 3);
        let r = NodeCall::new(&smooth_numbers()).run();
        assert!(r.outputs[0].values().next().is_none());
    }

    #[test]
    fn bounds_encompasses_the_numbers() {
        let r = NodeCall::new(&bounds())
            .input(DataTree::from_list(vec![3.0, -1.5, 7.0, 0.0]))
            .run();
        assert_clean(&r);
        assert_eq!(only::<Interval>(&r, 0), Interval::new(-1.5, 7.0));
        let r = NodeCall::new(&bounds())
            .input(DataTree::from_item(4.0))
            .run();
        assert_eq!(only::<Interval>(&r, 0), Interval::new(4.0, 4.0));
    }

    #[test]
    fn bounds_skips_nan_and_rejects_infinity() {
        let r = NodeCall::new(&bounds())
            .input(DataTree::from_list(vec![f64::NAN, 2.0, 1.0]))
            .run();
        assert_eq!(only::<Interval>(&r, 0), Interval::new(1.0, 2.0));
        assert_eq!(messages(&r, Level::Warning), ["1 NaN items were skipped"]);
        let r = NodeCall::new(&bounds())
            .input(DataTree::from_list(vec![1.0, f64::INFINITY]))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        let r = NodeCall::new(&bounds())
            .input(DataTree::from_list(vec![f64::NAN]))
            .run();
        assert!(is_null(&r, 0));
    }
}
