//! Lifted item functions with several outputs and per-item reports (`lift1_with`,
//! `lift2_with`, `lift3_with` and the fast paths `fast_path2_with`, `fast_path3_with`): the
//! function returns a tuple with one item per output and may warn, remark, or fail one output
//! of an item through an [`ItemReport`]; the runtime runs it as a loop over typed columns that
//! pushes each output straight into its own column, records each message with the item's path
//! and index, and skips the outputs that nothing reads. `lift2_with_plain`,
//! `lift3_with_plain` and `fast_path2_with_plain` add a loop without reports for the items
//! that report nothing (see `plain.rs`).
//!
//! The general solve function made from the same item function gives the same outputs and
//! messages in the same order: the report's messages first, then the error of a failing item.

use std::sync::Arc;

use rayon::prelude::*;

use super::{FALL_BACK, Full, LIFT_CHUNK, Lift, LiftOutput, One, Repeat, Src, at, items};
use crate::evaluation::spread;
use crate::{Branch, Column, DataType, Item, Level, NodeError, NodeType, Solve};

/// What one item of a lifted function reports besides its outputs: warnings, remarks and
/// errors, which the runtime records with the item's path and index, and the outputs an error
/// leaves null (the others keep their items, as when a solve function sets some outputs and
/// then reports an error).
#[derive(Debug, Default)]
pub struct ItemReport {
    messages: Vec<(Level, String)>,
    /// Bit `k`: output `k` is null for this item.
    nulls: u32,
}

impl ItemReport {
    /// Reports a warning for this item.
    pub fn warning(&mut self, text: impl Into<String>) {
        self.messages.push((Level::Warning, text.into()));
    }

    /// Reports a remark for this item.
    pub fn remark(&mut self, text: impl Into<String>) {
        self.messages.push((Level::Remark, text.into()));
    }

    /// Reports an error for this item that leaves output `output` null (the other outputs keep
    /// the items the function returns).
    pub fn error(&mut self, output: usize, text: impl Into<String>) {
        self.messages.push((Level::Error, text.into()));
        self.nulls |= 1 << output;
    }

    fn is_quiet(&self) -> bool {
        self.messages.is_empty() && self.nulls == 0
    }

    /// Gives the messages to a solve function's context, in order.
    fn report_to(self, s: &mut Solve<'_>) -> u32 {
        for (level, text) in self.messages {
            match level {
                Level::Error => s.error(text),
                Level::Warning => s.warning(text),
                Level::Remark => s.remark(text),
            }
        }
        self.nulls
    }
}

/// The outputs of a lifted function: a tuple of one to four [`Item`]s, one per output port.
pub trait Outputs: Sized + Send + 'static {
    /// One column per output, `None` for an output nothing reads.
    type Columns: Send;
    /// The outputs' types.
    fn types() -> Vec<DataType>;
    /// Empty columns for the wanted outputs.
    fn columns(capacity: usize, wanted: &[bool]) -> Self::Columns;
    /// Pushes the items onto the wanted outputs' columns.
    fn push(self, columns: &mut Self::Columns);
    /// Truncates the wanted outputs' columns to `len` items.
    fn truncate(columns: &mut Self::Columns, len: usize);
    /// Appends the outputs of `item(j)` for `j` in `0..n` (each with whether its item was
    /// clean) to the wanted outputs' columns in one pass; whether all were clean. When one
    /// output is wanted, or all of them and they are 16 bytes an item or more, the columns are
    /// extended from an exact-size iterator (alone, or as a tuple as `Iterator::unzip` does),
    /// which writes each item once and checks no capacity per item. Otherwise each wanted
    /// column is first filled out with placeholders for the chunk, which the pass then
    /// overwrites by index (a pass that vectorises for narrow items). The caller
    /// truncates the columns to their length before the call when the chunk is not kept.
    fn write_chunk<I: Fn(usize) -> (Self, bool)>(
        columns: &mut Self::Columns,
        n: usize,
        item: I,
    ) -> bool;
    /// [`Outputs::write_chunk`] for the wanted outputs of the bits of `W` (one instance per
    /// set of wanted outputs, so the pass has no test per item of which outputs are wanted).
    #[doc(hidden)]
    fn write_wanted<const W: u32, I: Fn(usize) -> (Self, bool)>(
        columns: &mut Self::Columns,
        n: usize,
        item: I,
    ) -> bool;
    /// The placeholders stored under null items.
    fn placeholder() -> Self;
    /// Appends `other`'s columns to `columns`.
    fn append(columns: &mut Self::Columns, other: Self::Columns);
    /// The columns as runtime columns (`None` for an output that was skipped).
    fn finish(columns: Self::Columns) -> Vec<Option<Column>>;
    /// Sets the items on a solve function's outputs, except those marked null in `nulls`.
    fn set(self, s: &mut Solve<'_>, nulls: u32);
}

macro_rules! outputs {
    ($($t:ident $i:tt $d:ident),* ; $($w:literal),*) => {
        impl<$($t: Item),*> Outputs for ($($t,)*) {
            type Columns = ($(Option<Vec<$t>>,)*);
            fn types() -> Vec<DataType> {
                vec![$($t::TYPE),*]
            }
            fn columns(capacity: usize, wanted: &[bool]) -> Self::Columns {
                ($(wanted.get($i).copied().unwrap_or(true).then(|| Vec::with_capacity(capacity)),)*)
            }
            #[inline(always)]
            fn push(self, columns: &mut Self::Columns) {
                $(if let Some(v) = &mut columns.$i {
                    v.push(self.$i);
                })*
            }
            fn truncate(columns: &mut Self::Columns, len: usize) {
                $(if let Some(v) = &mut columns.$i {
                    v.truncate(len);
                })*
            }
            #[inline(always)]
            fn write_chunk<I: Fn(usize) -> (Self, bool)>(
                columns: &mut Self::Columns,
                n: usize,
                item: I,
            ) -> bool {
                let mut wanted = 0;
                $(if columns.$i.is_some() {
                    wanted |= 1 << $i;
                })*
                match wanted {
                    $($w => Self::write_wanted::<$w, I>(columns, n, item),)*
                    _ => unreachable!("a set of {} outputs", wanted),
                }
            }
            #[inline(always)]
            fn write_wanted<const W: u32, I: Fn(usize) -> (Self, bool)>(
                columns: &mut Self::Columns,
                n: usize,
                item: I,
            ) -> bool {
                let mut clean = true;
                // One output: `Vec::extend` from a range's map writes each item in place.
                $(if W == 1 << $i {
                    if let Some(v) = &mut columns.$i {
                        v.extend((0..n).map(|j| {
                            let (o, ok) = item(j);
                            clean &= ok;
                            o.$i
                        }));
                    }
                    return clean;
                })*
                // Every output, of 16 bytes an item or more: the tuple of columns extended
                // from the same exact-size iterator (as `Iterator::unzip` does), which writes
                // each item in place. Narrower outputs (booleans, say) take the pass by index
                // below, which vectorises, and whose placeholders cost little.
                if W == 0 $(| (1 << $i))* && std::mem::size_of::<Self>() >= 16 {
                    let mut all = ($(columns.$i.take().unwrap_or_default(),)*);
                    all.extend((0..n).map(|j| {
                        let (o, ok) = item(j);
                        clean &= ok;
                        o
                    }));
                    $(columns.$i = Some(all.$i);)*
                    return clean;
                }
                // Some of several: each wanted column filled out with placeholders for the
                // chunk, which the pass overwrites by index (no index check per item).
                $(let $d: &mut [$t] = match &mut columns.$i {
                    Some(v) if W & (1 << $i) != 0 => {
                        let start = v.len();
                        v.resize(start + n, $t::placeholder());
                        &mut v[start..]
                    }
                    _ => &mut [],
                };
                // Known to the compiler from here on: no index check in the pass.
                assert!(W & (1 << $i) == 0 || $d.len() == n);)*
                for j in 0..n {
                    let (o, ok) = item(j);
                    clean &= ok;
                    $(if W & (1 << $i) != 0 {
                        $d[j] = o.$i;
                    })*
                }
                clean
            }
            fn placeholder() -> Self {
                ($($t::placeholder(),)*)
            }
            fn append(columns: &mut Self::Columns, mut other: Self::Columns) {
                $(if let (Some(a), Some(b)) = (&mut columns.$i, &mut other.$i) {
                    a.append(b);
                })*
            }
            fn finish(columns: Self::Columns) -> Vec<Option<Column>> {
                vec![$(columns.$i.map($t::into_column)),*]
            }
            fn set(self, s: &mut Solve<'_>, nulls: u32) {
                $(if nulls & (1 << $i) == 0 {
                    s.set($i, self.$i);
                })*
            }
        }
    };
}
outputs!(A 0 a; 0, 1);
outputs!(A 0 a, B 1 b; 0, 1, 2, 3);
outputs!(A 0 a, B 1 b, C 2 c; 0, 1, 2, 3, 4, 5, 6, 7);
outputs!(A 0 a, B 1 b, C 2 c, D 3 d; 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);

/// Every output of an item null (a null input, or the function failed).
const ALL: u32 = u32::MAX;

/// The outputs, messages and nulls of a range of iterations.
pub(super) struct Chunk<C> {
    columns: C,
    /// (iteration, level, text), in iteration order.
    messages: Vec<(usize, Level, String)>,
    /// (iteration, outputs left null as bits), in iteration order.
    nulls: Vec<(usize, u32)>,
}

/// Runs iterations `start..end` into `chunk`: `f(k, report)` gives iteration `k`'s outputs,
/// `is_null(k)` whether a required input item of iteration `k` is null.
#[inline(always)]
pub(super) fn fill<O: Outputs>(
    chunk: &mut Chunk<O::Columns>,
    range: std::ops::Range<usize>,
    any_nulls: bool,
    is_null: &impl Fn(usize) -> bool,
    f: &impl Fn(usize, &mut ItemReport) -> Result<O, NodeError>,
) {
    for k in range {
        if any_nulls && is_null(k) {
            O::placeholder().push(&mut chunk.columns);
            chunk.nulls.push((k, ALL));
            continue;
        }
        let mut report = ItemReport::default();
        let result = f(k, &mut report);
        if !report.is_quiet() {
            if report.nulls != 0 {
                chunk.nulls.push((k, report.nulls));
            }
            chunk
                .messages
                .extend(report.messages.into_iter().map(|(l, t)| (k, l, t)));
        }
        match result {
            Ok(out) => out.push(&mut chunk.columns),
            Err(e) => {
                O::placeholder().push(&mut chunk.columns);
                chunk.messages.push((k, Level::Error, e.0));
                chunk.nulls.push((k, ALL));
            }
        }
    }
}

impl<C> Chunk<C> {
    fn new<O: Outputs<Columns = C>>(capacity: usize, wanted: &[bool]) -> Self {
        Chunk {
            columns: O::columns(capacity, wanted),
            messages: Vec::new(),
            nulls: Vec::new(),
        }
    }
}

/// The loop of a lifted function with several outputs over `count` iterations; with
/// `parallel`, the first items run on this thread and are timed and the rest is spread over
/// threads only when that pays (see [`spread`]).
fn many_loop<O: Outputs>(
    count: usize,
    parallel: bool,
    any_nulls: bool,
    is_null: impl Fn(usize) -> bool + Sync,
    f: impl Fn(usize, &mut ItemReport) -> Result<O, NodeError> + Sync,
    wanted: &[bool],
) -> LiftOutput {
    let mut all = Chunk::new::<O>(count, wanted);
    run_range(
        &mut all,
        0..count,
        parallel,
        any_nulls,
        &is_null,
        &f,
        wanted,
    );
    finish::<O>(all, count)
}

/// Runs iterations `range` into `all` (which holds the iterations before it), as
/// [`many_loop`] does: with `parallel`, spread over threads only when that pays.
pub(super) fn run_range<O: Outputs>(
    all: &mut Chunk<O::Columns>,
    range: std::ops::Range<usize>,
    parallel: bool,
    any_nulls: bool,
    is_null: &(impl Fn(usize) -> bool + Sync),
    f: &(impl Fn(usize, &mut ItemReport) -> Result<O, NodeError> + Sync),
    wanted: &[bool],
) {
    let (first, count) = (range.start, range.end);
    if parallel && count > first + 1 {
        let probe = spread::probe(count - first, LIFT_CHUNK, |start, end| {
            fill::<O>(all, first + start..first + end, any_nulls, is_null, f);
        });
        let done = first + probe.done;
        if let Some(chunk) = probe.spread_chunk(count - done, LIFT_CHUNK) {
            let starts: Vec<usize> = (done..count).step_by(chunk).collect();
            let chunks: Vec<Chunk<O::Columns>> = starts
                .par_iter()
                .map(|&start| {
                    let end = (start + chunk).min(count);
                    let mut part = Chunk::new::<O>(end - start, wanted);
                    fill::<O>(&mut part, start..end, any_nulls, is_null, f);
                    part
                })
                .collect();
            for part in chunks {
                O::append(&mut all.columns, part.columns);
                all.messages.extend(part.messages);
                all.nulls.extend(part.nulls);
            }
        } else {
            fill::<O>(all, done..count, any_nulls, is_null, f);
        }
    } else {
        fill::<O>(all, range, any_nulls, is_null, f);
    }
}

/// The output branches and messages of `count` iterations run into `all`.
pub(super) fn finish<O: Outputs>(all: Chunk<O::Columns>, count: usize) -> LiftOutput {
    let types = O::types();
    let branches = O::finish(all.columns)
        .into_iter()
        .zip(types)
        .enumerate()
        .map(|(o, (column, t))| match column {
            None => Branch::new(t),
            Some(column) => {
                let bit = 1u32 << o;
                if !all.nulls.iter().any(|&(_, b)| b & bit != 0) {
                    return Branch::from_column(column);
                }
                let mut mask = vec![false; count];
                for &(k, b) in &all.nulls {
                    if b & bit != 0 {
                        mask[k] = true;
                    }
                }
                Branch::from_parts(column, mask)
            }
        })
        .collect();
    (branches, all.messages)
}

/// The lifted loop of `g`, a function of one typed item with several outputs.
fn lift1_many<A: Item, O: Outputs>(
    g: Arc<impl Fn(&A, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static>,
) -> Lift {
    Lift {
        inputs: vec![A::TYPE],
        outputs: O::types(),
        run: Arc::new(move |b, count, parallel, wanted| {
            let a0 = items::<A>(b[0]);
            let l0 = a0.len();
            let g = &*g;
            let nulls = move |k| b[0].is_null(at(k, l0));
            with_src!(a0, count, |s0| many_loop(
                count,
                parallel,
                b[0].has_nulls(),
                nulls,
                move |k, r: &mut ItemReport| g(s0.get(k), r),
                wanted
            ))
        }),
    }
}

/// The lifted loop of `g`, a function of two typed items with several outputs.
fn lift2_many<A: Item, B: Item, O: Outputs>(
    g: Arc<impl Fn(&A, &B, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static>,
) -> Lift {
    Lift {
        inputs: vec![A::TYPE, B::TYPE],
        outputs: O::types(),
        run: Arc::new(move |b, count, parallel, wanted| {
            let (a0, a1) = (items::<A>(b[0]), items::<B>(b[1]));
            let (l0, l1) = (a0.len(), a1.len());
            let g = &*g;
            let any_nulls = b[0].has_nulls() || b[1].has_nulls();
            let nulls = move |k| b[0].is_null(at(k, l0)) || b[1].is_null(at(k, l1));
            with_src!(a0, count, |s0| with_src!(a1, count, |s1| many_loop(
                count,
                parallel,
                any_nulls,
                nulls,
                move |k, r: &mut ItemReport| g(s0.get(k), s1.get(k), r),
                wanted
            )))
        }),
    }
}

/// The lifted loop of `g`, a function of three typed items with several outputs.
fn lift3_many<A: Item, B: Item, C: Item, O: Outputs>(
    g: Arc<impl Fn(&A, &B, &C, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static>,
) -> Lift {
    Lift {
        inputs: vec![A::TYPE, B::TYPE, C::TYPE],
        outputs: O::types(),
        run: Arc::new(move |b, count, parallel, wanted| {
            let (a0, a1, a2) = (items::<A>(b[0]), items::<B>(b[1]), items::<C>(b[2]));
            let (l0, l1, l2) = (a0.len(), a1.len(), a2.len());
            let g = &*g;
            let any_nulls = b.iter().any(|b| b.has_nulls());
            let nulls = move |k| {
                b[0].is_null(at(k, l0)) || b[1].is_null(at(k, l1)) || b[2].is_null(at(k, l2))
            };
            with_src!(a0, count, |s0| with_src!(a1, count, |s1| with_src!(
                a2,
                count,
                |s2| many_loop(
                    count,
                    parallel,
                    any_nulls,
                    nulls,
                    move |k, r: &mut ItemReport| g(s0.get(k), s1.get(k), s2.get(k), r),
                    wanted
                )
            )))
        }),
    }
}

/// A fast path's item function: `FALL_BACK` as the error of an item it leaves to the solve
/// function.
fn fall_back() -> NodeError {
    NodeError(FALL_BACK.into())
}

impl NodeType {
    /// Sets the solve function to a function of one typed item (input 0) with one item per
    /// output (a tuple: output 0, output 1, …) and an [`ItemReport`] for warnings and errors,
    /// lifted by the runtime over trees as one loop over typed columns.
    ///
    /// ```
    /// use locus_runtime::{DataTree, DataType, NodeCall, NodeType, Port};
    /// let split = NodeType::new("maths.split", "Split", "Split", "Maths")
    ///     .input(Port::new("Value", "x", DataType::Number))
    ///     .output(Port::new("Whole", "W", DataType::Number))
    ///     .output(Port::new("Fraction", "F", DataType::Number))
    ///     .lift1_with(|x: &f64, report| {
    ///         if x.is_nan() {
    ///             report.warning("x is NaN");
    ///         }
    ///         Ok((x.trunc(), x.fract()))
    ///     });
    /// let r = NodeCall::new(&split).input(DataTree::from_list(vec![1.5, f64::NAN])).run();
    /// assert_eq!(r.outputs[0].branches()[0].1.slice::<f64>().unwrap()[0], 1.0);
    /// assert_eq!(r.messages.len(), 1);
    /// ```
    pub fn lift1_with<A: Item, O: Outputs>(
        self,
        f: impl Fn(&A, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static,
    ) -> Self {
        let f = Arc::new(f);
        let g = Arc::clone(&f);
        let mut node = self.solve(move |s| {
            let mut r = ItemReport::default();
            let out = f(s.item::<A>(0)?, &mut r);
            let nulls = r.report_to(s);
            out?.set(s, nulls);
            Ok(())
        });
        node.lift = Some(lift1_many::<A, O>(g));
        node
    }

    /// As [`NodeType::lift1_with`], for a function of two typed items (inputs 0 and 1).
    pub fn lift2_with<A: Item, B: Item, O: Outputs>(
        self,
        f: impl Fn(&A, &B, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static,
    ) -> Self {
        let f = Arc::new(f);
        let g = Arc::clone(&f);
        let mut node = self.solve(move |s| {
            let mut r = ItemReport::default();
            let out = f(s.item::<A>(0)?, s.item::<B>(1)?, &mut r);
            let nulls = r.report_to(s);
            out?.set(s, nulls);
            Ok(())
        });
        node.lift = Some(lift2_many::<A, B, O>(g));
        node
    }

    /// As [`NodeType::lift1_with`], for a function of three typed items (inputs 0, 1 and 2).
    pub fn lift3_with<A: Item, B: Item, C: Item, O: Outputs>(
        self,
        f: impl Fn(&A, &B, &C, &mut ItemReport) -> Result<O, NodeError> + Send + Sync + 'static,
    ) -> Self {
        let f = Arc::new(f);
        let g = Arc::clone(&f);
        let mut node = self.solve(move |s| {
            let mut r = ItemReport::default();
            let out = f(s.item::<A>(0)?, s.item::<B>(1)?, s.item::<C>(2)?, &mut r);
            let nulls = r.report_to(s);
            out?.set(s, nulls);
            Ok(())
        });
        node.lift = Some(lift3_many::<A, B, C, O>(g));
        node
    }

    /// Adds a fast path with several outputs to a node whose solve function is general
    /// (generic ports, optional inputs): when the node's item inputs hold `A`s and `B`s in
    /// every branch, the runtime runs `f` as a loop over the typed columns, as for
    /// [`NodeType::lift2_with`]. An optional input takes part only where it has data with no
    /// nulls and no empty branch; else the node runs the general way. `f` returns `None` for
    /// an item it leaves to the solve function, and must agree with it wherever it gives
    /// `Some` (outputs, messages and nulls). Set it after [`NodeType::solve`].
    pub fn fast_path2_with<A: Item, B: Item, O: Outputs>(
        mut self,
        f: impl Fn(&A, &B, &mut ItemReport) -> Option<Result<O, NodeError>> + Send + Sync + 'static,
    ) -> Self {
        let g = Arc::new(move |a: &A, b: &B, r: &mut ItemReport| {
            f(a, b, r).unwrap_or_else(|| Err(fall_back()))
        });
        self.fast_paths.push(lift2_many::<A, B, O>(g));
        self
    }

    /// As [`NodeType::fast_path2_with`], for three item inputs.
    pub fn fast_path3_with<A: Item, B: Item, C: Item, O: Outputs>(
        mut self,
        f: impl Fn(&A, &B, &C, &mut ItemReport) -> Option<Result<O, NodeError>> + Send + Sync + 'static,
    ) -> Self {
        let g = Arc::new(move |a: &A, b: &B, c: &C, r: &mut ItemReport| {
            f(a, b, c, r).unwrap_or_else(|| Err(fall_back()))
        });
        self.fast_paths.push(lift3_many::<A, B, C, O>(g));
        self
    }
}

// After the loops it falls back to.
mod plain;
