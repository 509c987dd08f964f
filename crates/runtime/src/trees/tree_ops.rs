//! Structural operations on data trees: flatten, graft, reverse, trim, shift paths, flip matrix
//! and explode, as Grasshopper's modifiers and Sets › Tree components perform them.
//!
//! Every operation keeps items in their typed columns: items move between branches by typed
//! range copies ([`Branch::extend_range`]), never one boxed value at a time, and operations
//! that only rename paths move branches without copying items. The rules, including the
//! choices made where Grasshopper is not documented, are in `docs/data-trees.md`.

use std::ops::Range;

use crate::{Branch, DataTree, TreePath};

/// Which items and branches [`DataTree::graft`] keeps (Grasshopper's `GH_GraftMode`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct GraftMode {
    /// Null items get a branch holding one null (`GraftNullItems`); otherwise they are
    /// dropped, leaving no branch at their index.
    pub keep_nulls: bool,
    /// An empty branch `{p}` becomes an empty branch `{p;0}` (`GraftEmptyLists`); otherwise it
    /// is dropped.
    pub keep_empty: bool,
}

impl GraftMode {
    /// Keep null items and empty branches (`GraftAll`): the graft modifier of an input.
    pub const ALL: Self = Self {
        keep_nulls: true,
        keep_empty: true,
    };
    /// Drop null items and empty branches.
    pub const ITEMS_ONLY: Self = Self {
        keep_nulls: false,
        keep_empty: false,
    };
}

impl Default for GraftMode {
    fn default() -> Self {
        Self::ALL
    }
}

/// Why a tree operation could not be performed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum TreeError {
    /// Flip matrix needs every path to have the same number of indices.
    #[error("flip matrix needs paths of one length: {first} and {other} differ")]
    VariableDepth {
        /// The first path of the tree.
        first: TreePath,
        /// A path of another length.
        other: TreePath,
    },
    /// Flip matrix needs the paths to differ at one index position only.
    #[error("flip matrix needs paths that differ at one index only: {first} and {other}")]
    SeveralLoci {
        /// The first path of the tree.
        first: TreePath,
        /// A path that differs from it at a second position.
        other: TreePath,
    },
}

impl DataTree {
    /// Puts all items, in path order, into one branch `{0}` (the flatten modifier).
    ///
    /// A tree with branches but no items becomes one empty branch `{0}`; a tree without
    /// branches stays empty.
    pub fn flatten(&mut self) {
        self.flatten_to(TreePath::zero());
    }

    /// Puts all items, in path order, into one branch at `path` (Flatten Tree with a path).
    pub fn flatten_to(&mut self, path: TreePath) {
        if self.is_empty() {
            return;
        }
        let data_type = storage_type(self);
        let total = self.item_count();
        let mut branches = std::mem::take(self).into_branches();
        let merged = if branches.len() == 1 {
            branches
                .pop()
                .map(|(_, b)| b)
                .unwrap_or_else(|| Branch::new(data_type))
        } else {
            let mut merged = Branch::from_column(crate::Column::with_capacity(data_type, total));
            for (_, branch) in &branches {
                merged.extend(branch);
            }
            merged
        };
        self.insert(path, merged);
    }

    /// Gives every item its own branch: item `i` of `{p}` moves to `{p;i}` (the graft
    /// modifier, with [`GraftMode::ALL`]).
    ///
    /// Paths keep the item's index in its original branch, so dropping a null item leaves a
    /// gap in the indices rather than renumbering the items after it.
    pub fn graft(&mut self, mode: GraftMode) {
        let capacity = self.item_count().max(self.branch_count());
        let branches = std::mem::take(self).into_branches();
        let mut out = Vec::with_capacity(capacity);
        for (path, branch) in &branches {
            if branch.is_empty() {
                if mode.keep_empty {
                    out.push((path.with_appended(0), Branch::new(branch.data_type())));
                }
                continue;
            }
            for i in 0..branch.len() {
                if !mode.keep_nulls && branch.is_null(i) {
                    continue;
                }
                let mut item = Branch::new(branch.data_type());
                item.extend_range(branch, i..i + 1);
                out.push((path.with_appended(index_u32(i)), item));
            }
        }
        // Grafting a shorter path can place branches after those of a longer one
        // (`{0;0;0}` from `{0;0}` sorts before `{0;1}` from `{0}`); this sorts them.
        *self = DataTree::from_branches(out);
    }

    /// Reverses the items of every branch (the reverse modifier).
    pub fn reverse_items(&mut self) {
        let mut branches = std::mem::take(self).into_branches();
        for (_, branch) in &mut branches {
            branch.reverse();
        }
        *self = DataTree::from_branches(branches);
    }

    /// Removes the last `depth` indices of every path and merges branches that become equal,
    /// in path order (Trim Tree). A path with `depth` indices or fewer becomes `{0}`, so
    /// trimming deeper than the tree flattens it.
    pub fn trim(&mut self, depth: usize) {
        if depth == 0 {
            return;
        }
        self.map_paths(|p| {
            let n = p.len();
            if n > depth {
                TreePath::new(&p[..n - depth])
            } else {
                TreePath::zero()
            }
        });
    }

    /// Shifts the paths by `offset` (Shift Paths): a negative offset removes `-offset` indices
    /// from the end of every path, a positive one `offset` indices from the front. Branches
    /// that end up at the same path merge in path order; a path that loses all its indices
    /// becomes `{0}`.
    pub fn shift_paths(&mut self, offset: i64) {
        let count = usize::try_from(offset.unsigned_abs()).unwrap_or(usize::MAX);
        if offset < 0 {
            self.trim(count);
        } else if offset > 0 {
            self.map_paths(|p| {
                if p.len() > count {
                    TreePath::new(&p[count..])
                } else {
                    TreePath::zero()
                }
            });
        }
    }

    /// Rewrites every path with `f` and merges branches that end up at the same path, in the
    /// original path order. Branches are moved, not copied.
    pub fn map_paths(&mut self, mut f: impl FnMut(&[u32]) -> TreePath) {
        let branches = std::mem::take(self).into_branches();
        *self = DataTree::from_branches(
            branches
                .into_iter()
                .map(|(path, branch)| (f(path.indices()), branch)),
        );
    }

    /// Swaps rows and columns (Flip Matrix): the branches are rows, and item `j` of every
    /// branch goes, in branch order, to the `j`-th output branch. Shorter branches give nulls.
    ///
    /// The paths may differ at one index position only (the locus); the output paths are the
    /// first path with that position set to `j`. A single branch is flipped on its last index:
    /// `{0;0}:[a, b]` becomes `{0;0}:[a] {0;1}:[b]`.
    ///
    /// # Errors
    /// [`TreeError::VariableDepth`] for paths of different lengths and
    /// [`TreeError::SeveralLoci`] for paths that differ at more than one position; the tree is
    /// then unchanged.
    pub fn flip_matrix(&mut self) -> Result<(), TreeError> {
        let Some((first, _)) = self.branches().first() else {
            return Ok(());
        };
        let first = first.clone();
        let depth = first.len();
        let mut locus = None;
        for (path, _) in self.branches() {
            if path.len() != depth {
                return Err(TreeError::VariableDepth {
                    first,
                    other: path.clone(),
                });
            }
            for (k, (a, b)) in first.indices().iter().zip(path.indices()).enumerate() {
                if a == b {
                    continue;
                }
                match locus {
                    None => locus = Some(k),
                    Some(l) if l == k => {}
                    Some(_) => {
                        return Err(TreeError::SeveralLoci {
                            first,
                            other: path.clone(),
                        });
                    }
                }
            }
        }
        let locus = locus.unwrap_or(depth - 1);
        let columns = self
            .branches()
            .iter()
            .map(|(_, b)| b.len())
            .max()
            .unwrap_or(0);
        let data_type = self.data_type();
        let mut out = Vec::with_capacity(columns);
        for j in 0..columns {
            let mut indices = first.indices().to_vec();
            indices[locus] = index_u32(j);
            let rows = self.branch_count();
            let mut column = Branch::from_column(crate::Column::with_capacity(data_type, rows));
            for (_, row) in self.branches() {
                if j < row.len() {
                    column.extend_range(row, j..j + 1);
                } else {
                    column.push_null();
                }
            }
            out.push((TreePath::new(indices), column));
        }
        *self = DataTree::from_branches(out);
        Ok(())
    }

    /// Every branch as a tree of its own, at its path (Explode Tree).
    pub fn explode(&self) -> Vec<DataTree> {
        self.branches()
            .iter()
            .map(|(path, branch)| DataTree::from_branches([(path.clone(), branch.clone())]))
            .collect()
    }
}

impl Branch {
    /// A branch of the items at `indices`, in that order; `None` and indices past the end give
    /// nulls, null items stay null. Runs of consecutive indices are copied as typed ranges.
    ///
    /// This is the primitive behind list item, shift list, cull and dispatch style nodes.
    pub fn gather(&self, indices: impl IntoIterator<Item = Option<usize>>) -> Branch {
        let mut out = Branch::new(self.data_type());
        let mut run: Option<Range<usize>> = None;
        for index in indices {
            match index {
                Some(i) if i < self.len() => match &mut run {
                    Some(r) if r.end == i => r.end += 1,
                    _ => {
                        if let Some(r) = run.replace(i..i + 1) {
                            out.extend_range(self, r);
                        }
                    }
                },
                _ => {
                    if let Some(r) = run.take() {
                        out.extend_range(self, r);
                    }
                    out.push_null();
                }
            }
        }
        if let Some(r) = run {
            out.extend_range(self, r);
        }
        out
    }
}

/// The column type for branches built from a tree's items: the type of its items, or, for a
/// tree without items, the type its (empty) branches share, so that empty typed branches stay
/// typed.
pub(crate) fn storage_type(tree: &DataTree) -> crate::DataType {
    let data_type = tree.data_type();
    if data_type != crate::DataType::Generic || !tree.has_no_items() {
        return data_type;
    }
    let mut types = tree.branches().iter().map(|(_, b)| b.data_type());
    match types.next() {
        Some(first) if types.all(|t| t == first) => first,
        _ => crate::DataType::Generic,
    }
}

/// An item index as a path index; trees never hold 2^32 items in one branch, and the index
/// saturates rather than wraps if one did.
fn index_u32(i: usize) -> u32 {
    u32::try_from(i).unwrap_or(u32::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{DataType, Value};

    fn tree(text: &str) -> DataTree {
        DataTree::from_text(text).unwrap_or_else(|e| panic!("{text}: {e}"))
    }

    #[test]
    fn flatten_concatenates_in_path_order() {
        let mut t = tree("{1}:[5] {0;0}:[1, null] {0;1}:[] {0;2}:[3, 4]");
        t.flatten();
        assert_eq!(t.to_text(), "{0}:[1, null, 3, 4, 5]");
        let mut t = tree("{2;3}:[1, 2]");
        t.flatten_to(TreePath::from([7]));
        assert_eq!(t.to_text(), "{7}:[1, 2]");
        let mut t = tree("{0;1}:[] {0;2}:[]");
        t.flatten();
        assert_eq!(t.to_text(), "{0}:[]");
        let mut t = DataTree::new();
        t.flatten();
        assert!(t.is_empty());
    }

    #[test]
    fn flatten_keeps_the_column_typed() {
        let mut t = DataTree::new();
        t.insert(TreePath::from([0]), Branch::from_items(vec![1_i64, 2]));
        t.insert(TreePath::from([1]), Branch::from_items(vec![3_i64]));
        t.flatten();
        let b = t.branch(&TreePath::zero()).unwrap();
        assert_eq!(b.slice::<i64>(), Some(&[1, 2, 3][..]));
    }

    #[test]
    fn graft_gives_each_item_a_branch() {
        let mut t = tree("{0}:[1, 2, 3, 4]");
        t.graft(GraftMode::ALL);
        assert_eq!(t.to_text(), "{0;0}:[1] {0;1}:[2] {0;2}:[3] {0;3}:[4]");
        let mut t = tree("{0;0}:[1, 2]");
        t.graft(GraftMode::ALL);
        assert_eq!(t.to_text(), "{0;0;0}:[1] {0;0;1}:[2]");
    }

    #[test]
    fn graft_handles_variable_depth_in_path_order() {
        let mut t = tree("{0}:[1, 2] {0;0}:[3]");
        t.graft(GraftMode::ALL);
        assert_eq!(t.to_text(), "{0;0}:[1] {0;0;0}:[3] {0;1}:[2]");
    }

    #[test]
    fn graft_modes_keep_or_drop_nulls_and_empty_branches() {
        let text = "{0}:[1, null, 3] {1}:[]";
        let mut all = tree(text);
        all.graft(GraftMode::ALL);
        assert_eq!(all.to_text(), "{0;0}:[1] {0;1}:[null] {0;2}:[3] {1;0}:[]");
        let mut items = tree(text);
        items.graft(GraftMode::ITEMS_ONLY);
        assert_eq!(items.to_text(), "{0;0}:[1] {0;2}:[3]");
        let mut nulls_only = tree(text);
        nulls_only.graft(GraftMode {
            keep_nulls: true,
            keep_empty: false,
        });
        assert_eq!(nulls_only.to_text(), "{0;0}:[1] {0;1}:[null] {0;2}:[3]");
    }

    #[test]
    fn reverse_reverses_each_branch() {
        let mut t = tree("{0}:[1, 2, null] {1}:[4] {2}:[]");
        t.reverse_items();
        assert_eq!(t.to_text(), "{0}:[null, 2, 1] {1}:[4] {2}:[]");
    }

    #[test]
    fn trim_drops_outer_indices_and_merges() {
        let mut t = tree("{0;0;0}:[1] {0;0;1}:[2] {0;1;0}:[3] {1;0;0}:[4]");
        t.trim(1);
        assert_eq!(t.to_text(), "{0;0}:[1, 2] {0;1}:[3] {1;0}:[4]");
        t.trim(1);
        assert_eq!(t.to_text(), "{0}:[1, 2, 3] {1}:[4]");
        t.trim(0);
        assert_eq!(t.to_text(), "{0}:[1, 2, 3] {1}:[4]");
        t.trim(1);
        assert_eq!(t.to_text(), "{0}:[1, 2, 3, 4]");
        let mut deep = tree("{3;1}:[1] {4;0}:[2]");
        deep.trim(5);
        assert_eq!(deep.to_text(), "{0}:[1, 2]");
    }

    #[test]
    fn shift_paths_both_ways() {
        let text = "{0;0}:[1] {0;1}:[2] {0;2}:[3]";
        let mut back = tree(text);
        back.shift_paths(-1);
        assert_eq!(back.to_text(), "{0}:[1, 2, 3]");
        let mut front = tree(text);
        front.shift_paths(1);
        assert_eq!(front.to_text(), "{0}:[1] {1}:[2] {2}:[3]");
        let mut none = tree(text);
        none.shift_paths(0);
        assert_eq!(none.to_text(), text);
        let mut all = tree("{1;2;3}:[1] {4;5;6}:[2]");
        all.shift_paths(3);
        assert_eq!(all.to_text(), "{0}:[1, 2]");
        let mut front2 = tree("{1;2;3}:[1] {4;5;6}:[2]");
        front2.shift_paths(2);
        assert_eq!(front2.to_text(), "{3}:[1] {6}:[2]");
        let mut huge = tree(text);
        huge.shift_paths(i64::MIN);
        assert_eq!(huge.to_text(), "{0}:[1, 2, 3]");
    }

    #[test]
    fn flip_matrix_swaps_rows_and_columns() {
        let mut t = tree("{0;0}:[1, 2, 3, 4] {0;1}:[5, 6, 7, 8]");
        t.flip_matrix().unwrap();
        assert_eq!(
            t.to_text(),
            "{0;0}:[1, 5] {0;1}:[2, 6] {0;2}:[3, 7] {0;3}:[4, 8]"
        );
        t.flip_matrix().unwrap();
        assert_eq!(t.to_text(), "{0;0}:[1, 2, 3, 4] {0;1}:[5, 6, 7, 8]");
    }

    #[test]
    fn flip_matrix_fills_ragged_rows_with_nulls() {
        let mut t = tree("{0}:[1, 2, 3] {1}:[4] {2}:[]");
        t.flip_matrix().unwrap();
        assert_eq!(
            t.to_text(),
            "{0}:[1, 4, null] {1}:[2, null, null] {2}:[3, null, null]"
        );
    }

    #[test]
    fn flip_matrix_uses_the_differing_locus() {
        let mut t = tree("{2;0;5}:[1, 2] {2;1;5}:[3, 4]");
        t.flip_matrix().unwrap();
        assert_eq!(t.to_text(), "{2;0;5}:[1, 3] {2;1;5}:[2, 4]");
        let mut single = tree("{0;0}:[1, 2]");
        single.flip_matrix().unwrap();
        assert_eq!(single.to_text(), "{0;0}:[1] {0;1}:[2]");
    }

    #[test]
    fn flip_matrix_rejects_trees_that_are_not_matrices() {
        let mut t = tree("{0;0}:[1] {0;0;1}:[2]");
        let e = t.flip_matrix().unwrap_err();
        assert_eq!(
            e.to_string(),
            "flip matrix needs paths of one length: {0;0} and {0;0;1} differ"
        );
        assert_eq!(t.to_text(), "{0;0}:[1] {0;0;1}:[2]");
        let mut t = tree("{0;0;0}:[1] {0;0;1}:[2] {0;1;0}:[3]");
        let e = t.flip_matrix().unwrap_err();
        assert_eq!(
            e,
            TreeError::SeveralLoci {
                first: TreePath::from([0, 0, 0]),
                other: TreePath::from([0, 1, 0]),
            }
        );
    }

    #[test]
    fn explode_gives_one_tree_per_branch() {
        let t = tree("{0}:[1] {1;2}:[2, 3]");
        let parts: Vec<String> = t.explode().iter().map(DataTree::to_text).collect();
        assert_eq!(parts, ["{0}:[1]", "{1;2}:[2, 3]"]);
    }

    #[test]
    fn gather_copies_runs_and_pads_with_nulls() {
        let b = tree("{0}:[0, 1, null, 3, 4]")
            .branch(&TreePath::zero())
            .cloned()
            .unwrap();
        let g = b.gather([Some(3), Some(4), Some(0), None, Some(9), Some(1), Some(2)]);
        assert_eq!(g.data_type(), DataType::Number);
        let values: Vec<Option<Value>> = g.values().collect();
        let n = |x: f64| Some(Value::Number(x));
        assert_eq!(values, [n(3.0), n(4.0), n(0.0), None, None, n(1.0), None]);
    }
}
