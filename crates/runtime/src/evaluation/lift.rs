//! Item functions lifted over trees: node types declared as plain functions of typed items
//! (`lift1`, `lift2`, `lift3`), which the runtime runs as tight loops over typed columns.
//!
//! A lifted node type also gets an ordinary solve function (reading its items with
//! [`Solve::item`](crate::Solve::item) and setting its one output), so every case the fast loop
//! does not cover (optional inputs, cross reference, extra ports, an input of another type)
//! runs through the general iteration with the same results. The fast loop reproduces the
//! general iteration exactly: longest or shortest list within a branch (shorter branches repeat
//! their last item), a null where a required item is null, and an error message with the path
//! and index of each failing item, which leaves a null. Large branches are split over threads
//! when their items are slow enough for that to pay (measured on the first chunk); errors are
//! reported in item order, so results are identical for any thread count.

use std::sync::{Arc, Mutex, PoisonError};

use rayon::prelude::*;

use super::spread;
use crate::{Branch, DataType, Item, Level, NodeError, NodeType};

pub use many::{ItemReport, Outputs};

/// Items per parallel chunk of a lifted loop.
const LIFT_CHUNK: usize = 16_384;

/// The output branch of a one-output lifted loop, and the failed items as (index, message).
type OneOutput = (Branch, Vec<(usize, String)>);

/// The output branches of a lifted loop (one per output, empty for an output not wanted) and
/// its messages as (index, level, text), in index order.
pub(crate) type LiftOutput = (smallvec::SmallVec<[Branch; 1]>, Vec<(usize, Level, String)>);

/// The loop of a lifted function over one branch pairing: the input branches (each non-empty
/// and of the declared type), the number of iterations, whether to use threads, and which
/// outputs are wanted (the others may be left empty).
pub(crate) type LiftLoop =
    Arc<dyn Fn(&[&Branch], usize, bool, &[bool]) -> LiftOutput + Send + Sync>;

/// A one-output loop's result as a lifted loop's.
fn one_output((branch, errors): OneOutput) -> LiftOutput {
    (
        smallvec::smallvec![branch],
        errors
            .into_iter()
            .map(|(k, text)| (k, Level::Error, text))
            .collect(),
    )
}

/// A lifted item function: its input and output types, and the loop over one branch pairing.
#[derive(Clone)]
pub(crate) struct Lift {
    pub(crate) inputs: Vec<DataType>,
    pub(crate) outputs: Vec<DataType>,
    /// Runs the function over `count` iterations of the given input branches (each non-empty
    /// and of the declared type), in parallel when asked.
    pub(crate) run: LiftLoop,
}

impl std::fmt::Debug for Lift {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Lift")
            .field("inputs", &self.inputs)
            .field("outputs", &self.outputs)
            .finish_non_exhaustive()
    }
}

/// The index into a branch of `len` items at iteration `k` (longest list: the last repeats).
#[inline(always)]
fn at(k: usize, len: usize) -> usize {
    k.min(len - 1)
}

/// Where the items of one input come from, iteration by iteration. Lifted loops are
/// instantiated for each combination, so the common cases (a full branch, one repeated item)
/// index without the longest-list clamp.
trait Src<'a, T: 'a>: Copy + Send + Sync {
    /// The item of iteration `k`.
    fn get(self, k: usize) -> &'a T;
    /// The items of iterations `start..end`, in order.
    fn iter(self, start: usize, end: usize) -> impl Iterator<Item = &'a T>;
    /// The same items as a parallel iterator (slices split into sub-slices).
    fn par(self, start: usize, end: usize) -> impl IndexedParallelIterator<Item = &'a T>;
    /// The source of iterations `start..end` as iterations `0..end - start` (a full branch's
    /// sub-slice, whose indexing by an iteration below `end - start` needs no check).
    fn sub(self, start: usize, end: usize) -> Self;
}

/// A branch with one item per iteration.
struct Full<'a, T>(&'a [T]);
/// One item, used by every iteration.
struct One<'a, T>(&'a T);
/// A shorter branch whose last item repeats (longest list).
struct Repeat<'a, T>(&'a [T]);

macro_rules! src {
    ($($name:ident),*) => {$(
        impl<T> Clone for $name<'_, T> {
            fn clone(&self) -> Self {
                *self
            }
        }
        impl<T> Copy for $name<'_, T> {}
    )*};
}
src!(Full, One, Repeat);

impl<'a, T: Sync> Src<'a, T> for Full<'a, T> {
    #[inline(always)]
    fn get(self, k: usize) -> &'a T {
        &self.0[k]
    }
    fn iter(self, start: usize, end: usize) -> impl Iterator<Item = &'a T> {
        self.0[start..end].iter()
    }
    fn par(self, start: usize, end: usize) -> impl IndexedParallelIterator<Item = &'a T> {
        self.0[start..end].par_iter()
    }
    fn sub(self, start: usize, end: usize) -> Self {
        Full(&self.0[start..end])
    }
}

impl<'a, T: Sync> Src<'a, T> for One<'a, T> {
    #[inline(always)]
    fn get(self, _: usize) -> &'a T {
        self.0
    }
    fn iter(self, start: usize, end: usize) -> impl Iterator<Item = &'a T> {
        std::iter::repeat_n(self.0, end - start)
    }
    fn par(self, start: usize, end: usize) -> impl IndexedParallelIterator<Item = &'a T> {
        rayon::iter::repeat_n(self.0, end - start)
    }
    fn sub(self, _: usize, _: usize) -> Self {
        self
    }
}

impl<'a, T: Sync> Src<'a, T> for Repeat<'a, T> {
    #[inline(always)]
    fn get(self, k: usize) -> &'a T {
        &self.0[at(k, self.0.len())]
    }
    fn iter(self, start: usize, end: usize) -> impl Iterator<Item = &'a T> {
        let n = self.0.len();
        let last = &self.0[n - 1];
        let own = &self.0[start.min(n)..end.min(n)];
        own.iter()
            .chain(std::iter::repeat_n(last, end - start - own.len()))
    }
    fn par(self, start: usize, end: usize) -> impl IndexedParallelIterator<Item = &'a T> {
        (start..end).into_par_iter().map(move |k| self.get(k))
    }
    fn sub(self, start: usize, _: usize) -> Self {
        // Item `start + j` is `self.0[min(start + j, n - 1)]`: from `min(start, n - 1)` on.
        Repeat(&self.0[start.min(self.0.len() - 1)..])
    }
}

/// Calls `$body` with `$src` bound to the fastest source for the items `$items` over
/// `$count` iterations.
macro_rules! with_src {
    ($items:expr, $count:expr, |$src:ident| $body:expr) => {{
        let items = $items;
        if items.len() == 1 {
            let $src = One(&items[0]);
            $body
        } else if items.len() >= $count {
            let $src = Full(&items[..$count]);
            $body
        } else {
            let $src = Repeat(items);
            $body
        }
    }};
}

/// Whether the measured time of `items` iterations says they are too slow to be bound by
/// memory traffic (see [`spread::PARALLEL_ITEM_NANOS`]).
pub(crate) fn worth_spreading(elapsed: std::time::Duration, items: usize) -> bool {
    elapsed.as_secs_f64() * 1e9 >= spread::PARALLEL_ITEM_NANOS * items as f64
}

/// Runs `f` for iterations `0..count`: a null where `is_null(k)`, and a null and an error
/// where `f` fails. `results(start, end)` gives the same results as `f` for a range of
/// iterations as an iterator, and `par_results` as a parallel iterator (slice iterators compile
/// to the tightest loops). With `parallel`, the first items run on this thread and are timed
/// (see [`spread`]); the rest is spread over threads only if that pays. Either way the results
/// are the same.
fn lift_loop<O: Item, I, P>(
    count: usize,
    parallel: bool,
    any_nulls: bool,
    is_null: impl Fn(usize) -> bool + Sync,
    f: impl Fn(usize) -> Result<O, NodeError> + Sync,
    results: impl Fn(usize, usize) -> I,
    par_results: impl FnOnce(usize, usize) -> P,
) -> OneOutput
where
    I: Iterator<Item = Result<O, NodeError>>,
    P: IndexedParallelIterator<Item = Result<O, NodeError>>,
{
    let mut errors: Vec<(usize, String)> = Vec::new();
    let one = |k: usize, r: Result<O, NodeError>, errors: &mut Vec<(usize, String)>| {
        r.unwrap_or_else(|e| {
            errors.push((k, e.0));
            O::placeholder()
        })
    };
    let items: Vec<O> = if any_nulls {
        // Index by index, skipping null items (null inputs are rare in large trees).
        let item = |k: usize, errors: &mut Vec<(usize, String)>| {
            if is_null(k) {
                O::placeholder()
            } else {
                one(k, f(k), errors)
            }
        };
        if parallel {
            let failed = Mutex::new(Vec::new());
            let mut items = Vec::new();
            (0..count)
                .into_par_iter()
                .with_min_len(LIFT_CHUNK)
                .map(|k| {
                    let mut local = Vec::new();
                    let out = item(k, &mut local);
                    if !local.is_empty() {
                        failed
                            .lock()
                            .unwrap_or_else(PoisonError::into_inner)
                            .append(&mut local);
                    }
                    out
                })
                .collect_into_vec(&mut items);
            errors = failed.into_inner().unwrap_or_else(PoisonError::into_inner);
            items
        } else {
            (0..count).map(|k| item(k, &mut errors)).collect()
        }
    } else if parallel && count > 1 {
        let mut items: Vec<O> = Vec::with_capacity(count);
        let probe = spread::probe(count, LIFT_CHUNK, |start, end| {
            items.extend(
                results(start, end)
                    .enumerate()
                    .map(|(j, r)| one(start + j, r, &mut errors)),
            );
        });
        let done = probe.done;
        if let Some(chunk) = probe.spread_chunk(count - done, LIFT_CHUNK) {
            // Over sub-slices on each thread; failures (rare) go through a lock.
            let failed = Mutex::new(std::mem::take(&mut errors));
            // An indexed parallel iterator extends the vector in place, in order.
            items.par_extend(
                par_results(done, count)
                    .with_min_len(chunk)
                    .enumerate()
                    .map(|(j, r)| {
                        r.unwrap_or_else(|e| {
                            failed
                                .lock()
                                .unwrap_or_else(PoisonError::into_inner)
                                .push((done + j, e.0));
                            O::placeholder()
                        })
                    }),
            );
            errors = failed.into_inner().unwrap_or_else(PoisonError::into_inner);
        } else {
            items.extend(
                results(done, count)
                    .enumerate()
                    .map(|(j, r)| one(done + j, r, &mut errors)),
            );
        }
        items
    } else {
        results(0, count)
            .enumerate()
            .map(|(k, r)| one(k, r, &mut errors))
            .collect()
    };
    errors.sort_by_key(|e| e.0);
    let column = O::into_column(items);
    if !any_nulls && errors.is_empty() {
        return (Branch::from_column(column), errors);
    }
    let mut mask: Vec<bool> = (0..count).map(|k| any_nulls && is_null(k)).collect();
    for &(k, _) in &errors {
        mask[k] = true;
    }
    (Branch::from_parts(column, mask), errors)
}

/// The typed items of a lifted input (the runtime checked the type before calling).
fn items<T: Item>(branch: &Branch) -> &[T] {
    T::slice(branch.column()).unwrap_or(&[])
}

/// The message a fast path's loop records for an item it leaves to the solve function; the
/// runtime then runs the node the general way (see [`NodeType::fast_path2`]).
pub(crate) const FALL_BACK: &str = "\u{0}fall back to the solve function";

/// The lifted loop of a function of two typed items.
fn lift2<A: Item, B: Item, O: Item>(
    g: Arc<impl Fn(&A, &B) -> Result<O, NodeError> + Send + Sync + 'static>,
) -> Lift {
    Lift {
        inputs: vec![A::TYPE, B::TYPE],
        outputs: vec![O::TYPE],
        run: Arc::new(move |b, count, parallel, _| {
            let (a0, a1) = (items::<A>(b[0]), items::<B>(b[1]));
            let (l0, l1) = (a0.len(), a1.len());
            let g = &*g;
            let any_nulls = b[0].has_nulls() || b[1].has_nulls();
            let nulls = move |k| b[0].is_null(at(k, l0)) || b[1].is_null(at(k, l1));
            one_output(with_src!(a0, count, |s0| with_src!(a1, count, |s1| {
                lift_loop(
                    count,
                    parallel,
                    any_nulls,
                    nulls,
                    move |k| g(s0.get(k), s1.get(k)),
                    move |i, j| s0.iter(i, j).zip(s1.iter(i, j)).map(|(x, y)| g(x, y)),
                    move |i, j| s0.par(i, j).zip(s1.par(i, j)).map(|(x, y)| g(x, y)),
                )
            })))
        }),
    }
}

/// The loop of a fast path over two inputs. It first makes one pass without branches over a
/// branch pairing without nulls: each item is `f`'s, or a placeholder and a cleared flag where
/// `f` leaves the item to the solve function. The pass is kept when no item was left and the
/// items are too quick to spread over threads (timed on the first chunk, as `lift_loop` does);
/// otherwise the general loop of [`lift2`] runs, which gives the same items.
fn fast_lift2<A: Item, B: Item, O: Item>(
    f: Arc<impl Fn(&A, &B) -> Option<O> + Send + Sync + 'static>,
) -> Lift {
    let g = {
        let f = Arc::clone(&f);
        Arc::new(move |a: &A, b: &B| f(a, b).ok_or_else(|| NodeError(FALL_BACK.into())))
    };
    let general = lift2::<A, B, O>(g);
    let general_run = Arc::clone(&general.run);
    Lift {
        inputs: general.inputs,
        outputs: general.outputs,
        run: Arc::new(move |b, count, parallel, wanted| {
            if !(b[0].has_nulls() || b[1].has_nulls()) {
                let (a0, a1) = (items::<A>(b[0]), items::<B>(b[1]));
                let f = &*f;
                let done = with_src!(a0, count, |s0| with_src!(a1, count, |s1| {
                    let pass = |start: usize, end: usize, out: &mut Vec<O>| {
                        let mut all = true;
                        out.extend(s0.iter(start, end).zip(s1.iter(start, end)).map(|(x, y)| {
                            let r = f(x, y);
                            all &= r.is_some();
                            r.unwrap_or_else(O::placeholder)
                        }));
                        all
                    };
                    let mut out = Vec::with_capacity(count);
                    let first = if parallel {
                        count.min(LIFT_CHUNK)
                    } else {
                        count
                    };
                    let started = std::time::Instant::now();
                    let kept = pass(0, first, &mut out)
                        && (first == count
                            || (!worth_spreading(started.elapsed(), first)
                                && pass(first, count, &mut out)));
                    kept.then_some(out)
                }));
                if let Some(items) = done {
                    return one_output((Branch::from_column(O::into_column(items)), Vec::new()));
                }
            }
            general_run(b, count, parallel, wanted)
        }),
    }
}

impl NodeType {
    /// The same node type without its lifted loop and fast paths, so that every call runs the
    /// general solve function: for tests and benchmarks that compare the two.
    #[must_use]
    pub fn general_only(mut self) -> Self {
        self.lift = None;
        self.fast_paths.clear();
        self
    }

    /// Sets the solve function to a plain function of one typed item, lifted by the runtime
    /// over trees: input 0 is read as an `A`, the result is output 0. The input and output
    /// ports are declared as usual, with item access and the types of `A` and `O`.
    ///
    /// ```
    /// use locus_runtime::{DataTree, DataType, NodeCall, NodeType, Port};
    /// let negative = NodeType::new("maths.negative", "Negative", "Neg", "Maths")
    ///     .input(Port::new("Value", "x", DataType::Number))
    ///     .output(Port::new("Result", "y", DataType::Number))
    ///     .lift1(|x: &f64| Ok(-x));
    /// let r = NodeCall::new(&negative).input(DataTree::from_list(vec![1.0, -2.0])).run();
    /// assert_eq!(r.outputs[0], DataTree::from_list(vec![-1.0, 2.0]));
    /// ```
    pub fn lift1<A: Item, O: Item>(
        self,
        f: impl Fn(&A) -> Result<O, NodeError> + Send + Sync + 'static,
    ) -> Self {
        let f = Arc::new(f);
        let g = Arc::clone(&f);
        let mut node = self.solve(move |s| {
            let out = f(s.item::<A>(0)?)?;
            s.set(0, out);
            Ok(())
        });
        node.lift = Some(Lift {
            inputs: vec![A::TYPE],
            outputs: vec![O::TYPE],
            run: Arc::new(move |b, count, parallel, _| {
                let a = items::<A>(b[0]);
                let la = a.len();
                let g = &*g;
                let nulls = move |k| b[0].is_null(at(k, la));
                // `move` closures copy the sources, so the loop keeps them in registers.
                one_output(with_src!(a, count, |s0| lift_loop(
                    count,
                    parallel,
                    b[0].has_nulls(),
                    nulls,
                    move |k| g(s0.get(k)),
                    move |i, j| s0.iter(i, j).map(g),
                    move |i, j| s0.par(i, j).map(g)
                )))
            }),
        });
        node
    }

    /// Sets the solve function to a plain function of two typed items (inputs 0 and 1), lifted
    /// by the runtime over trees with the node's matching; the result is output 0.
    ///
    /// ```
    /// use locus_runtime::{DataTree, DataType, NodeCall, NodeType, Port};
    /// let add = NodeType::new("maths.addition", "Addition", "A+B", "Maths")
    ///     .input(Port::new("A", "A", DataType::Number))
    ///     .input(Port::new("B", "B", DataType::Number))
    ///     .output(Port::new("Result", "R", DataType::Number))
    ///     .lift2(|a: &f64, b: &f64| Ok(a + b));
    /// let r = NodeCall::new(&add)
    ///     .input(DataTree::from_list(vec![1.0, 2.0]))
    ///     .input(DataTree::from_item(10.0))
    ///     .run();
    /// assert_eq!(r.outputs[0], DataTree::from_list(vec![11.0, 12.0]));
    /// ```
    pub fn lift2<A: Item, B: Item, O: Item>(
        self,
        f: impl Fn(&A, &B) -> Result<O, NodeError> + Send + Sync + 'static,
    ) -> Self {
        let f = Arc::new(f);
        let g = Arc::clone(&f);
        let mut node = self.solve(move |s| {
            let out = f(s.item::<A>(0)?, s.item::<B>(1)?)?;
            s.set(0, out);
            Ok(())
        });
        node.lift = Some(lift2::<A, B, O>(g));
        node
    }

    /// Adds a fast path to a node whose solve function is general (generic ports, several
    /// kinds of operand): when the node has exactly two item inputs and every branch of them
    /// holds `A`s and `B`s, the runtime runs `f` as a loop over the typed columns, as for
    /// [`NodeType::lift2`], and output 0 gets `O`s. `f` returns `None` for an item it leaves to
    /// the solve function (one that warns, say): the node then runs the general way, so the
    /// results are always the solve function's. `f` must agree with it wherever it gives
    /// `Some`. Set it after [`NodeType::solve`].
    ///
    /// ```
    /// use locus_runtime::{DataTree, DataType, NodeCall, NodeType, Port, Value};
    /// let add = NodeType::new("maths.addition", "Addition", "A+B", "Maths")
    ///     .input(Port::new("A", "A", DataType::Generic))
    ///     .input(Port::new("B", "B", DataType::Generic))
    ///     .output(Port::new("Result", "R", DataType::Generic))
    ///     .solve(|s| {
    ///         let sum = match (s.value(0), s.value(1)) {
    ///             (Some(Value::Number(a)), Some(Value::Number(b))) => a + b,
    ///             _ => return Err("only numbers here".into()),
    ///         };
    ///         if !sum.is_finite() {
    ///             s.warning("the sum is not finite");
    ///         }
    ///         s.set(0, sum);
    ///         Ok(())
    ///     })
    ///     .fast_path2(|a: &f64, b: &f64| Some(a + b).filter(|r| r.is_finite()));
    /// let r = NodeCall::new(&add)
    ///     .input(DataTree::from_list(vec![1.0, f64::MAX]))
    ///     .input(DataTree::from_item(f64::MAX))
    ///     .run();
    /// // The infinite sum made the node run its solve function, which warns.
    /// assert_eq!(r.messages.len(), 1);
    /// ```
    pub fn fast_path2<A: Item, B: Item, O: Item>(
        mut self,
        f: impl Fn(&A, &B) -> Option<O> + Send + Sync + 'static,
    ) -> Self {
        self.fast_paths.push(fast_lift2::<A, B, O>(Arc::new(f)));
        self
    }

    /// Sets the solve function to a plain function of three typed items (inputs 0, 1 and 2),
    /// lifted by the runtime over trees with the node's matching; the result is output 0.
    pub fn lift3<A: Item, B: Item, C: Item, O: Item>(
        self,
        f: impl Fn(&A, &B, &C) -> Result<O, NodeError> + Send + Sync + 'static,
    ) -> Self {
        let f = Arc::new(f);
        let g = Arc::clone(&f);
        let mut node = self.solve(move |s| {
            let out = f(s.item::<A>(0)?, s.item::<B>(1)?, s.item::<C>(2)?)?;
            s.set(0, out);
            Ok(())
        });
        node.lift = Some(Lift {
            inputs: vec![A::TYPE, B::TYPE, C::TYPE],
            outputs: vec![O::TYPE],
            run: Arc::new(move |b, count, parallel, _| {
                let (a0, a1, a2) = (items::<A>(b[0]), items::<B>(b[1]), items::<C>(b[2]));
                let (l0, l1, l2) = (a0.len(), a1.len(), a2.len());
                let g = &*g;
                one_output(lift_loop(
                    count,
                    parallel,
                    b.iter().any(|b| b.has_nulls()),
                    move |k| {
                        b[0].is_null(at(k, l0))
                            || b[1].is_null(at(k, l1))
                            || b[2].is_null(at(k, l2))
                    },
                    move |k| g(&a0[at(k, l0)], &a1[at(k, l1)], &a2[at(k, l2)]),
                    move |i, j| {
                        (i..j).map(move |k| g(&a0[at(k, l0)], &a1[at(k, l1)], &a2[at(k, l2)]))
                    },
                    move |i, j| {
                        (i..j)
                            .into_par_iter()
                            .map(move |k| g(&a0[at(k, l0)], &a1[at(k, l1)], &a2[at(k, l2)]))
                    },
                ))
            }),
        });
        node
    }
}

// After `with_src!`, which the loops with several outputs use too.
mod many;
