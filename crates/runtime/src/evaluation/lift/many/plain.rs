//! The loop without reports of `lift1_with_plain`, `lift2_with_plain`, `lift3_with_plain` and
//! `fast_path2_with_plain`: for the items where a `clean` predicate holds, the reporting item
//! function reports nothing and gives `Ok(plain(..))`, so the loop computes `plain` for every
//! item and pushes each of its outputs straight into its column, in one pass, while it ANDs
//! `clean` of the same items into a flag (no branch on it inside the pass). A chunk of items
//! with an item that is not clean is truncated off the columns and run again with the
//! reporting item function, which records its messages and nulls; the chunks after it take the
//! plain pass again. Either way each item gets what the reporting function gives it, so the
//! outputs and messages are those of `lift2_with`/`lift3_with` (in item order, the same for any
//! thread count).

use std::sync::Arc;

use super::{
    Chunk, ItemReport, Outputs, fall_back, fill, finish, lift1_many, lift2_many, lift3_many,
    run_range,
};
use crate::evaluation::lift::{Full, Lift, LiftOutput, One, Repeat, Src, items};
use crate::{Item, NodeError, NodeType};

/// How many items the plain pass runs before it looks at the chunk's flag: small enough that a
/// chunk that is not clean is cheap to run again (its outputs are still in the cache when they
/// are truncated off), large enough that the look costs nothing.
const CLEAN_CHUNK: usize = 1024;

/// The plain loop over `count` iterations; `tuples(start, end)` gives the input tuple of
/// iteration `start + j` by `j` (references to one item of each input, no null among them); `f(k, report)` is the
/// reporting item function of iteration `k`. `plain` runs on every item, clean or not, so it
/// must not panic on any item (its results for items that are not clean are dropped).
///
/// When at least two chunks have items that are not clean and they are at least half of the
/// chunks run, the rest of the branch runs with the reporting function only, spread over
/// threads when that pays (with `parallel`), so a branch of mostly unclean items costs little
/// more than the reporting loop alone.
fn plain_loop<T: Copy, O: Outputs, I: Fn(usize) -> T>(
    count: usize,
    parallel: bool,
    wanted: &[bool],
    tuples: impl Fn(usize, usize) -> I,
    clean: impl Fn(T) -> bool,
    plain: impl Fn(T) -> O,
    f: &(impl Fn(usize, &mut ItemReport) -> Result<O, NodeError> + Sync),
) -> LiftOutput {
    let mut all = Chunk::new::<O>(count, wanted);
    let no_nulls = |_: usize| false;
    let (mut start, mut chunks, mut unclean) = (0, 0usize, 0usize);
    while start < count {
        let end = (start + CLEAN_CHUNK).min(count);
        let at = tuples(start, end);
        let ok = O::write_chunk(&mut all.columns, end - start, |j| {
            let t = at(j);
            (plain(t), clean(t))
        });
        chunks += 1;
        if !ok {
            O::truncate(&mut all.columns, start);
            unclean += 1;
            if unclean >= 2 && 2 * unclean >= chunks {
                run_range(
                    &mut all,
                    start..count,
                    parallel,
                    false,
                    &no_nulls,
                    f,
                    wanted,
                );
                break;
            }
            fill::<O>(&mut all, start..end, false, &no_nulls, f);
        }
        start = end;
    }
    finish::<O>(all, count)
}

/// The lifted loop of `g` (as [`lift1_many`]) with the plain loop for branches without nulls.
fn lift1_many_plain<A: Item, O: Outputs>(
    g: Arc<impl Fn(&A, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static>,
    clean: impl Fn(&A) -> bool + Send + Sync + 'static,
    plain: impl Fn(&A) -> O + Send + Sync + 'static,
) -> Lift {
    let general = lift1_many::<A, O>(Arc::clone(&g));
    let general_run = Arc::clone(&general.run);
    Lift {
        inputs: general.inputs,
        outputs: general.outputs,
        run: Arc::new(move |b, count, parallel, wanted| {
            if b[0].has_nulls() {
                return general_run(b, count, parallel, wanted);
            }
            let a0 = items::<A>(b[0]);
            let g = &*g;
            with_src!(a0, count, |s0| plain_loop(
                count,
                parallel,
                wanted,
                |start, end| {
                    let s0 = s0.sub(start, end);
                    move |j| s0.get(j)
                },
                &clean,
                &plain,
                &move |k, r: &mut ItemReport| g(s0.get(k), r)
            ))
        }),
    }
}

/// The lifted loop of `g` (as [`lift2_many`]) with the plain loop for branch pairings without
/// nulls.
fn lift2_many_plain<A: Item, B: Item, O: Outputs>(
    g: Arc<impl Fn(&A, &B, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static>,
    clean: impl Fn(&A, &B) -> bool + Send + Sync + 'static,
    plain: impl Fn(&A, &B) -> O + Send + Sync + 'static,
) -> Lift {
    let general = lift2_many::<A, B, O>(Arc::clone(&g));
    let general_run = Arc::clone(&general.run);
    Lift {
        inputs: general.inputs,
        outputs: general.outputs,
        run: Arc::new(move |b, count, parallel, wanted| {
            if b[0].has_nulls() || b[1].has_nulls() {
                return general_run(b, count, parallel, wanted);
            }
            let (a0, a1) = (items::<A>(b[0]), items::<B>(b[1]));
            let g = &*g;
            with_src!(a0, count, |s0| with_src!(a1, count, |s1| plain_loop(
                count,
                parallel,
                wanted,
                |start, end| {
                    let (s0, s1) = (s0.sub(start, end), s1.sub(start, end));
                    move |j| (s0.get(j), s1.get(j))
                },
                |(a, b)| clean(a, b),
                |(a, b)| plain(a, b),
                &move |k, r: &mut ItemReport| g(s0.get(k), s1.get(k), r)
            )))
        }),
    }
}

/// The lifted loop of `g` (as [`lift3_many`]) with the plain loop for branch triples without
/// nulls.
fn lift3_many_plain<A: Item, B: Item, C: Item, O: Outputs>(
    g: Arc<impl Fn(&A, &B, &C, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static>,
    clean: impl Fn(&A, &B, &C) -> bool + Send + Sync + 'static,
    plain: impl Fn(&A, &B, &C) -> O + Send + Sync + 'static,
) -> Lift {
    let general = lift3_many::<A, B, C, O>(Arc::clone(&g));
    let general_run = Arc::clone(&general.run);
    Lift {
        inputs: general.inputs,
        outputs: general.outputs,
        run: Arc::new(move |b, count, parallel, wanted| {
            if b.iter().any(|b| b.has_nulls()) {
                return general_run(b, count, parallel, wanted);
            }
            let (a0, a1, a2) = (items::<A>(b[0]), items::<B>(b[1]), items::<C>(b[2]));
            let g = &*g;
            with_src!(a0, count, |s0| with_src!(a1, count, |s1| with_src!(
                a2,
                count,
                |s2| plain_loop(
                    count,
                    parallel,
                    wanted,
                    |start, end| {
                        let (s0, s1, s2) =
                            (s0.sub(start, end), s1.sub(start, end), s2.sub(start, end));
                        move |j| ((s0.get(j), s1.get(j)), s2.get(j))
                    },
                    |((a, b), c)| clean(a, b, c),
                    |((a, b), c)| plain(a, b, c),
                    &move |k, r: &mut ItemReport| g(s0.get(k), s1.get(k), s2.get(k), r)
                )
            )))
        }),
    }
}

impl NodeType {
    /// As [`NodeType::lift1_with`], with the loop without reports of
    /// [`NodeType::lift2_with_plain`]: `clean(a)` says that `f` reports nothing for this item
    /// and gives `Ok(plain(a))`.
    pub fn lift1_with_plain<A: Item, O: Outputs>(
        self,
        clean: impl Fn(&A) -> bool + Send + Sync + 'static,
        plain: impl Fn(&A) -> O + Send + Sync + 'static,
        f: impl Fn(&A, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static,
    ) -> Self {
        let f = Arc::new(f);
        let g = Arc::clone(&f);
        let mut node = self.lift1_with(move |a: &A, r: &mut ItemReport| f(a, r));
        node.lift = Some(lift1_many_plain::<A, O>(g, clean, plain));
        node
    }

    /// As [`NodeType::lift2_with`], with a loop without reports for the common case.
    /// `clean(a, b)` says that `f` reports nothing for these items and gives
    /// `Ok(plain(a, b))`. In a branch pairing without nulls, every item's outputs are `plain`'s,
    /// pushed into their columns in one pass with no report per item, while `clean` of the
    /// items is gathered without a branch; a chunk of items that holds one that is not clean is
    /// run again with `f`. The results are those of `lift2_with` either way, for any thread
    /// count. `plain` is called on items that are not clean too (its results are then
    /// dropped), so it must not panic on any item.
    ///
    /// ```
    /// use locus_runtime::{DataTree, DataType, NodeCall, NodeType, Port};
    /// let larger = NodeType::new("maths.larger", "Larger", "L", "Maths")
    ///     .input(Port::new("A", "A", DataType::Number))
    ///     .input(Port::new("B", "B", DataType::Number))
    ///     .output(Port::new("Larger", ">", DataType::Boolean))
    ///     .lift2_with_plain(
    ///         |a: &f64, b: &f64| !a.is_nan() && !b.is_nan(),
    ///         |a: &f64, b: &f64| (a > b,),
    ///         |a: &f64, b: &f64, report| {
    ///             if a.is_nan() || b.is_nan() {
    ///                 report.warning("NaN");
    ///             }
    ///             Ok((a > b,))
    ///         },
    ///     );
    /// let r = NodeCall::new(&larger)
    ///     .input(DataTree::from_list(vec![1.0, 3.0, f64::NAN]))
    ///     .input(DataTree::from_item(2.0))
    ///     .run();
    /// assert_eq!(r.outputs[0].branches()[0].1.slice::<bool>().unwrap(), &[false, true, false]);
    /// assert_eq!(r.messages.len(), 1);
    /// ```
    pub fn lift2_with_plain<A: Item, B: Item, O: Outputs>(
        self,
        clean: impl Fn(&A, &B) -> bool + Send + Sync + 'static,
        plain: impl Fn(&A, &B) -> O + Send + Sync + 'static,
        f: impl Fn(&A, &B, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static,
    ) -> Self {
        let f = Arc::new(f);
        let g = Arc::clone(&f);
        let mut node = self.lift2_with(move |a: &A, b: &B, r: &mut ItemReport| f(a, b, r));
        node.lift = Some(lift2_many_plain::<A, B, O>(g, clean, plain));
        node
    }

    /// As [`NodeType::lift3_with`], with the loop without reports of
    /// [`NodeType::lift2_with_plain`]: `clean(a, b, c)` says that `f` reports nothing for these
    /// items and gives `Ok(plain(a, b, c))`.
    pub fn lift3_with_plain<A: Item, B: Item, C: Item, O: Outputs>(
        self,
        clean: impl Fn(&A, &B, &C) -> bool + Send + Sync + 'static,
        plain: impl Fn(&A, &B, &C) -> O + Send + Sync + 'static,
        f: impl Fn(&A, &B, &C, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static,
    ) -> Self {
        let f = Arc::new(f);
        let g = Arc::clone(&f);
        let mut node =
            self.lift3_with(move |a: &A, b: &B, c: &C, r: &mut ItemReport| f(a, b, c, r));
        node.lift = Some(lift3_many_plain::<A, B, C, O>(g, clean, plain));
        node
    }

    /// As [`NodeType::fast_path2_with`], with the loop without reports of
    /// [`NodeType::lift2_with_plain`]: `clean(a, b)` says that `f` gives
    /// `Some(Ok(plain(a, b)))` and reports nothing for these items.
    pub fn fast_path2_with_plain<A: Item, B: Item, O: Outputs>(
        mut self,
        clean: impl Fn(&A, &B) -> bool + Send + Sync + 'static,
        plain: impl Fn(&A, &B) -> O + Send + Sync + 'static,
        f: impl Fn(&A, &B, &mut ItemReport) -> Option<Result<O, NodeError>> + Send + Sync + 'static,
    ) -> Self {
        let g = Arc::new(move |a: &A, b: &B, r: &mut ItemReport| {
            f(a, b, r).unwrap_or_else(|| Err(fall_back()))
        });
        self.fast_paths
            .push(lift2_many_plain::<A, B, O>(g, clean, plain));
        self
    }
}
