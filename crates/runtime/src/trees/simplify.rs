//! Simplify: removing the path indices that all branches share.
//!
//! Grasshopper 1 documents the intent ("remove the overlap shared amongst all branches") but
//! not the algorithm for paths of different lengths. The rules here, from the reference's
//! recommendation, are:
//!
//! - A tree with fewer than two branches is left alone (as in Grasshopper 1).
//! - [`SimplifyMode::All`] removes every index position whose value is equal in all paths,
//!   when all paths have the same length.
//! - [`SimplifyMode::Leading`], and `All` on paths of different lengths, removes the shared
//!   positions at the start of the paths only: those are aligned whatever the lengths, while
//!   later positions of paths of different depths are not comparable.
//! - No path is ever emptied: at most the shortest path's length minus one leading positions
//!   go.
//! - If the result would put two branches at one path the tree is left unchanged (this
//!   cannot happen under the rules above; the check guards the invariant).
//!
//! Only paths change; branches are moved, not copied, and their order is kept.

use crate::{DataTree, TreePath};

/// Which shared path indices [`DataTree::simplify`] removes (Grasshopper's
/// `GH_SimplificationMode`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum SimplifyMode {
    /// Shared indices anywhere along the paths (`CollapseAllOverlaps`, the default and the
    /// simplify modifier).
    #[default]
    All,
    /// Shared indices at the start of the paths only (`CollapseLeadingOverlaps`, Simplify Tree
    /// with Front set).
    Leading,
}

impl DataTree {
    /// Removes path indices shared by all branches; see `docs/data-trees.md` for the rules.
    ///
    /// `{0;0;0;1;0} {0;3;0;2;0} {0;8;0;3;0}` becomes `{0;1} {3;2} {8;3}` with
    /// [`SimplifyMode::All`] and `{0;0;1;0} {3;0;2;0} {8;0;3;0}` with
    /// [`SimplifyMode::Leading`].
    pub fn simplify(&mut self, mode: SimplifyMode) {
        let Some(keep) = simplify_mask(self, mode) else {
            return;
        };
        let new_paths: Vec<TreePath> = self
            .paths()
            .map(|p| {
                let kept: Vec<u32> = p
                    .indices()
                    .iter()
                    .enumerate()
                    .filter(|(k, _)| keep.get(*k).copied().unwrap_or(true))
                    .map(|(_, &i)| i)
                    .collect();
                TreePath::new(kept)
            })
            .collect();
        // Removing positions shared by all paths keeps their order; a strictly increasing
        // sequence is therefore also free of duplicates.
        if !new_paths.windows(2).all(|w| w[0] < w[1]) {
            return;
        }
        let branches = std::mem::take(self).into_branches();
        *self = DataTree::from_branches(
            new_paths
                .into_iter()
                .zip(branches)
                .map(|(path, (_, branch))| (path, branch)),
        );
    }
}

/// Per index position (up to the shortest path's length), whether it is kept; `None` when
/// nothing would be removed.
fn simplify_mask(tree: &DataTree, mode: SimplifyMode) -> Option<Vec<bool>> {
    if tree.branch_count() < 2 {
        return None;
    }
    let mut paths = tree.paths();
    let first = paths.next()?.indices();
    let mut shared: Vec<bool> = vec![true; first.len()];
    let mut same_length = true;
    for path in paths {
        let indices = path.indices();
        if indices.len() != first.len() {
            same_length = false;
        }
        shared.truncate(indices.len());
        for (k, s) in shared.iter_mut().enumerate() {
            *s = *s && indices[k] == first[k];
        }
    }
    let min_len = shared.len();
    let remove_anywhere = mode == SimplifyMode::All && same_length;
    let keep: Vec<bool> = if remove_anywhere {
        shared.iter().map(|s| !s).collect()
    } else {
        let leading = shared
            .iter()
            .take_while(|s| **s)
            .count()
            .min(min_len.saturating_sub(1));
        (0..min_len).map(|k| k >= leading).collect()
    };
    // Never empty a path: the shortest keeps at least one index.
    if keep.iter().all(|k| !k) || keep.iter().all(|k| *k) {
        return None;
    }
    Some(keep)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn simplified(text: &str, mode: SimplifyMode) -> String {
        let mut t = DataTree::from_text(text).unwrap();
        t.simplify(mode);
        t.to_text()
    }

    #[test]
    fn the_reference_example() {
        let text = "{0;0;0;1;0}:[1] {0;3;0;2;0}:[2] {0;8;0;3;0}:[3]";
        assert_eq!(
            simplified(text, SimplifyMode::All),
            "{0;1}:[1] {3;2}:[2] {8;3}:[3]"
        );
        assert_eq!(
            simplified(text, SimplifyMode::Leading),
            "{0;0;1;0}:[1] {3;0;2;0}:[2] {8;0;3;0}:[3]"
        );
    }

    #[test]
    fn divide_curve_paths_lose_their_shared_front() {
        let text = "{0;0}:[1] {0;1}:[2] {0;2}:[3]";
        for mode in [SimplifyMode::All, SimplifyMode::Leading] {
            assert_eq!(simplified(text, mode), "{0}:[1] {1}:[2] {2}:[3]");
        }
    }

    #[test]
    fn trailing_overlaps_go_only_in_all_mode() {
        let text = "{1;0}:[1] {2;0}:[2]";
        assert_eq!(simplified(text, SimplifyMode::All), "{1}:[1] {2}:[2]");
        assert_eq!(simplified(text, SimplifyMode::Leading), text);
    }

    #[test]
    fn single_branches_and_empty_trees_are_left_alone() {
        assert_eq!(
            simplified("{0;0;0}:[1, 2]", SimplifyMode::All),
            "{0;0;0}:[1, 2]"
        );
        assert_eq!(simplified("", SimplifyMode::All), "");
    }

    #[test]
    fn paths_of_different_lengths_lose_the_shared_front_only() {
        let text = "{0;0;1}:[1] {0;0;2;5}:[2]";
        assert_eq!(simplified(text, SimplifyMode::All), "{1}:[1] {2;5}:[2]");
        assert_eq!(simplified(text, SimplifyMode::Leading), "{1}:[1] {2;5}:[2]");
        // The trailing 0s are shared by position but the paths are not aligned there.
        let text = "{1;0}:[1] {2;3;0}:[2]";
        assert_eq!(simplified(text, SimplifyMode::All), text);
    }

    #[test]
    fn no_path_is_emptied() {
        let text = "{0}:[1] {0;1}:[2]";
        assert_eq!(simplified(text, SimplifyMode::All), text);
        let text = "{0;1}:[1] {0;1;0}:[2] {0;1;1}:[3]";
        assert_eq!(
            simplified(text, SimplifyMode::All),
            "{1}:[1] {1;0}:[2] {1;1}:[3]"
        );
    }

    #[test]
    fn empty_branches_and_nulls_move_with_their_paths() {
        assert_eq!(
            simplified("{0;0}:[] {0;1}:[null, 2]", SimplifyMode::All),
            "{0}:[] {1}:[null, 2]"
        );
    }
}
