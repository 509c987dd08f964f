//! Path Mapper: lexical rewriting of paths and item indices with masks, such as
//! `{A;B}(i) → {B;A}(i)` (swap two levels), `{A;B}(i) → {A}` (drop a level, appending),
//! `{A;B}(i) → {A;B;i}` (graft) or `{A;B}(i) → {i}` (flip).
//!
//! A **source mask** names each index of the paths it matches, `{A;B}`, and optionally the
//! item index, `(i)`. A **target mask** gives each index of the new path, and optionally the new
//! item index, as integer expressions of those names and of three constants: `item_count` (items
//! in the current branch), `path_count` (branches in the tree) and `path_index` (position of the
//! current branch). Expressions use `+ - * / \ %` (integer arithmetic; `/` and `\` both divide
//! truncating toward zero), unary minus, parentheses and whole numbers. Names are
//! case-insensitive.
//!
//! Without an item segment in the target, items are appended to their new branch in source
//! order. With one, each item is written at the index the expression gives: gaps are padded
//! with nulls and an item written to an occupied index replaces the one there (so
//! `{A;B}(i) → {A}(i)` keeps only the last branch's items, as in Grasshopper). Every path of the
//! tree must match the source mask (same number of indices); others are an error rather than
//! being dropped silently. See `docs/data-trees.md`.

use std::collections::BTreeMap;
use std::fmt;

use crate::trees::path_mask::{CONSTANTS, Expr, parse_source, parse_target};
use crate::{Branch, DataTree, TreePath};

/// How far past the number of items in the source tree a target item index may reach, so that
/// a runaway expression cannot allocate unbounded null padding.
pub const MAX_ITEM_PADDING: usize = 1 << 20;

/// A parsed pair of source and target masks that rewrites the paths of data trees.
#[derive(Clone, Debug, PartialEq)]
pub struct PathMapper {
    source: String,
    target: String,
    /// The number of indices a matching path has.
    depth: usize,
    target_path: Vec<Expr>,
    target_item: Option<Expr>,
    /// Whether the target path uses the item variable (then items are mapped one by one).
    path_uses_item: bool,
}

/// Why masks could not be parsed or a tree could not be mapped.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum PathMapError {
    /// A mask is not well formed.
    #[error("invalid mask `{mask}` at column {column}: {message}")]
    Syntax {
        /// The mask text.
        mask: String,
        /// The column of the problem, counted in characters from 1.
        column: usize,
        /// What is wrong.
        message: String,
    },
    /// A path of the tree does not have as many indices as the source mask.
    #[error("path {path} does not match the source mask `{mask}`")]
    NoMatch {
        /// The path.
        path: TreePath,
        /// The source mask.
        mask: String,
    },
    /// The target mask gave no valid path or index for a path or item.
    #[error("cannot map path {path}{}: {message}", .item.map(|i| format!(" item {i}")).unwrap_or_default())]
    Evaluation {
        /// The source path.
        path: TreePath,
        /// The item index, when the failure is per item.
        item: Option<usize>,
        /// What went wrong.
        message: String,
    },
}

impl PathMapper {
    /// Parses a source and a target mask.
    ///
    /// # Errors
    /// [`PathMapError::Syntax`] with the column of the first problem: missing braces, empty
    /// elements, numbers or reserved names in the source mask, a name used twice, names in the
    /// target that the source does not define.
    pub fn new(source: &str, target: &str) -> Result<Self, PathMapError> {
        let (names, item_name) = parse_source(source)?;
        let depth = names.len();
        // Environment slots: path variables, the item variable, then the constants.
        let mut scope: Vec<(String, usize)> =
            names.into_iter().enumerate().map(|(k, n)| (n, k)).collect();
        if let Some(item) = item_name {
            scope.push((item, depth));
        }
        for (k, c) in CONSTANTS.iter().enumerate() {
            scope.push(((*c).to_owned(), depth + 1 + k));
        }
        let (target_path, target_item) = parse_target(target, &scope)?;
        let path_uses_item = target_path.iter().any(|e| e.uses(depth));
        Ok(Self {
            source: source.trim().to_owned(),
            target: target.trim().to_owned(),
            depth,
            target_path,
            target_item,
            path_uses_item,
        })
    }

    /// Parses a mapping written `source -> target` (or with `→`).
    ///
    /// # Errors
    /// [`PathMapError::Syntax`] if the arrow is missing or a mask is invalid.
    pub fn parse(mapping: &str) -> Result<Self, PathMapError> {
        let split = mapping.split_once("->").or_else(|| mapping.split_once('→'));
        match split {
            Some((source, target)) => Self::new(source, target),
            None => Err(PathMapError::Syntax {
                mask: mapping.to_owned(),
                column: 1,
                message: "expected `source -> target`".to_owned(),
            }),
        }
    }

    /// The source mask as given.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The target mask as given.
    pub fn target(&self) -> &str {
        &self.target
    }

    /// Maps a tree. Items keep their typed columns; nulls stay null.
    ///
    /// # Errors
    /// [`PathMapError::NoMatch`] for a path with another number of indices than the source
    /// mask, [`PathMapError::Evaluation`] when a target expression divides by zero, overflows,
    /// or gives a negative or too large index.
    pub fn apply(&self, tree: &DataTree) -> Result<DataTree, PathMapError> {
        let depth = self.depth;
        let item_slot = depth;
        let mut env = vec![0_i64; depth + 1 + CONSTANTS.len()];
        env[depth + 2] = to_i64(tree.branch_count());
        let max_item = tree.item_count().saturating_add(MAX_ITEM_PADDING);
        let mut targets: BTreeMap<TreePath, Vec<Slot>> = BTreeMap::new();

        for (b, (path, branch)) in tree.branches().iter().enumerate() {
            if path.len() != depth {
                return Err(PathMapError::NoMatch {
                    path: path.clone(),
                    mask: self.source.clone(),
                });
            }
            for (slot, &index) in env.iter_mut().zip(path.indices()) {
                *slot = i64::from(index);
            }
            env[depth + 1] = to_i64(branch.len());
            env[depth + 3] = to_i64(b);
            let fail = |item: Option<usize>, message: String| PathMapError::Evaluation {
                path: path.clone(),
                item,
                message,
            };

            if !self.path_uses_item {
                env[item_slot] = 0;
                let target = self.eval_path(&env).map_err(|m| fail(None, m))?;
                let slots = targets.entry(target).or_default();
                match &self.target_item {
                    None => append(slots, b, 0..branch.len()),
                    Some(expr) => {
                        for i in 0..branch.len() {
                            env[item_slot] = to_i64(i);
                            let at =
                                eval_item(expr, &env, max_item).map_err(|m| fail(Some(i), m))?;
                            place(slots, at, b, i);
                        }
                    }
                }
                continue;
            }
            for i in 0..branch.len() {
                env[item_slot] = to_i64(i);
                let target = self.eval_path(&env).map_err(|m| fail(Some(i), m))?;
                let slots = targets.entry(target).or_default();
                match &self.target_item {
                    None => append(slots, b, i..i + 1),
                    Some(expr) => {
                        let at = eval_item(expr, &env, max_item).map_err(|m| fail(Some(i), m))?;
                        place(slots, at, b, i);
                    }
                }
            }
        }

        let data_type = crate::trees::tree_ops::storage_type(tree);
        let branches = targets.into_iter().map(|(path, slots)| {
            let mut out = Branch::new(data_type);
            for slot in slots {
                match slot {
                    Slot::Null => out.push_null(),
                    Slot::Items { branch, start, len } => {
                        out.extend_range(&tree.branches()[branch].1, start..start + len);
                    }
                }
            }
            (path, out)
        });
        Ok(DataTree::from_branches(branches))
    }

    fn eval_path(&self, env: &[i64]) -> Result<TreePath, String> {
        let mut indices = Vec::with_capacity(self.target_path.len());
        for expr in &self.target_path {
            let v = expr.eval(env)?;
            let index = u32::try_from(v).map_err(|_| {
                if v < 0 {
                    format!("path index {v} is negative")
                } else {
                    format!("path index {v} is too large")
                }
            })?;
            indices.push(index);
        }
        Ok(TreePath::new(indices))
    }
}

impl fmt::Display for PathMapper {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} → {}", self.source, self.target)
    }
}

/// Where the items of one target branch come from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Slot {
    Null,
    Items {
        branch: usize,
        start: usize,
        len: usize,
    },
}

fn append(slots: &mut Vec<Slot>, branch: usize, range: std::ops::Range<usize>) {
    if range.is_empty() {
        return;
    }
    if let Some(Slot::Items {
        branch: b,
        start,
        len,
    }) = slots.last_mut()
        && *b == branch
        && *start + *len == range.start
    {
        *len += range.len();
        return;
    }
    slots.push(Slot::Items {
        branch,
        start: range.start,
        len: range.len(),
    });
}

fn place(slots: &mut Vec<Slot>, at: usize, branch: usize, item: usize) {
    if at >= slots.len() {
        slots.resize(at + 1, Slot::Null);
    }
    slots[at] = Slot::Items {
        branch,
        start: item,
        len: 1,
    };
}

fn eval_item(expr: &Expr, env: &[i64], max_item: usize) -> Result<usize, String> {
    let v = expr.eval(env)?;
    match usize::try_from(v) {
        Err(_) => Err(format!("item index {v} is negative")),
        Ok(i) if i > max_item => Err(format!("item index {v} is too large")),
        Ok(i) => Ok(i),
    }
}

fn to_i64(n: usize) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map(source: &str, target: &str, tree: &str) -> String {
        let mapper = PathMapper::new(source, target).unwrap_or_else(|e| panic!("{e}"));
        let tree = DataTree::from_text(tree).unwrap();
        mapper
            .apply(&tree)
            .unwrap_or_else(|e| panic!("{e}"))
            .to_text()
    }

    const GRID: &str = "{0;0}:[1, 2] {0;1}:[3, 4] {1;0}:[5, 6]";

    #[test]
    fn swaps_levels() {
        assert_eq!(
            map("{A;B}(i)", "{B;A}(i)", GRID),
            "{0;0}:[1, 2] {0;1}:[5, 6] {1;0}:[3, 4]"
        );
    }

    #[test]
    fn drops_a_level_by_appending() {
        assert_eq!(map("{A;B}(i)", "{A}", GRID), "{0}:[1, 2, 3, 4] {1}:[5, 6]");
        assert_eq!(map("{A;B}", "{B}", GRID), "{0}:[1, 2, 5, 6] {1}:[3, 4]");
    }

    #[test]
    fn drops_a_level_keeping_item_indices_overwrites() {
        // Grasshopper's known surprise: the same item index from several branches.
        assert_eq!(map("{A;B}(i)", "{A}(i)", GRID), "{0}:[3, 4] {1}:[5, 6]");
    }

    #[test]
    fn grafts_and_flips() {
        assert_eq!(
            map("{A;B}(i)", "{A;B;i}", "{0;0}:[1, 2] {0;1}:[3]"),
            "{0;0;0}:[1] {0;0;1}:[2] {0;1;0}:[3]"
        );
        assert_eq!(
            map("{A;B}(i)", "{i}", "{0;0}:[1, 2] {0;1}:[3, 4]"),
            "{0}:[1, 3] {1}:[2, 4]"
        );
    }

    #[test]
    fn the_documented_examples() {
        let cases = [
            (
                "{A;B}(i)",
                "{B;A}(i)",
                "{0;0}:[1, 2] {0;1}:[5, 6] {1;0}:[3, 4]",
            ),
            ("{A;B}(i)", "{A}", "{0}:[1, 2, 3, 4] {1}:[5, 6]"),
            ("{A;B}(i)", "{A}(i)", "{0}:[3, 4] {1}:[5, 6]"),
            (
                "{A;B}(i)",
                "{A;B;i}",
                "{0;0;0}:[1] {0;0;1}:[2] {0;1;0}:[3] {0;1;1}:[4] {1;0;0}:[5] {1;0;1}:[6]",
            ),
            ("{A;B}(i)", "{i}", "{0}:[1, 3, 5] {1}:[2, 4, 6]"),
            ("{A;B}", "{path_index}", "{0}:[1, 2] {1}:[3, 4] {2}:[5, 6]"),
        ];
        for (source, target, expected) in cases {
            assert_eq!(map(source, target, GRID), expected, "{source} -> {target}");
        }
    }

    #[test]
    fn item_indices_pad_with_nulls() {
        assert_eq!(
            map("{A}(i)", "{A}(i*2)", "{0}:[1, 2, 3]"),
            "{0}:[1, null, 2, null, 3]"
        );
        assert_eq!(
            map("{A}(i)", "{A}(item_count-1-i)", "{0}:[1, 2, 3]"),
            "{0}:[3, 2, 1]"
        );
    }

    #[test]
    fn constants_and_arithmetic() {
        assert_eq!(
            map("{A;B}", "{path_index}", "{3;1}:[1] {5;0}:[2]"),
            "{0}:[1] {1}:[2]"
        );
        assert_eq!(
            map(
                "{A;B}(i)",
                "{(A + 1) * 10 - B % 2; path_count}",
                "{3;1}:[1] {5;0}:[2]"
            ),
            "{39;2}:[1] {60;2}:[2]"
        );
        assert_eq!(
            map("{A}(i)", "{i \\ 2}", "{0}:[1, 2, 3, 4, 5]"),
            "{0}:[1, 2] {1}:[3, 4] {2}:[5]"
        );
        assert_eq!(map("{a}", "{A / 2}", "{5}:[1]"), "{2}:[1]");
    }

    #[test]
    fn empty_branches_and_nulls_are_carried() {
        assert_eq!(
            map("{A;B}", "{B;A}", "{0;1}:[] {2;3}:[null, 1]"),
            "{1;0}:[] {3;2}:[null, 1]"
        );
        assert_eq!(map("{A}(i)", "{A;i}", "{0}:[]"), "");
    }

    #[test]
    fn mappings_parse_with_either_arrow() {
        let m = PathMapper::parse("{A;B}(i) -> {B;A}(i)").unwrap();
        assert_eq!(m.to_string(), "{A;B}(i) → {B;A}(i)");
        assert!(PathMapper::parse("{A;B}(i) → {B}").is_ok());
        assert!(PathMapper::parse("{A;B}(i) {B}").is_err());
    }

    #[test]
    fn evaluation_errors_name_the_path_and_item() {
        let tree = DataTree::from_text("{0;1}:[1, 2] {0}:[3]").unwrap();
        let e = PathMapper::new("{A;B}", "{A}")
            .unwrap()
            .apply(&tree)
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "path {0} does not match the source mask `{A;B}`"
        );
        let tree = DataTree::from_text("{2}:[1, 2]").unwrap();
        let cases = [
            (
                "{A}(i)",
                "{A - 3}",
                "cannot map path {2}: path index -1 is negative",
            ),
            (
                "{A}(i)",
                "{A}(i - 1)",
                "cannot map path {2} item 0: item index -1 is negative",
            ),
            (
                "{A}(i)",
                "{A / i}",
                "cannot map path {2} item 0: division by zero",
            ),
            (
                "{A}(i)",
                "{A % (A - 2)}",
                "cannot map path {2}: division by zero",
            ),
            (
                "{A}(i)",
                "{A * 9999999999}",
                "cannot map path {2}: path index 19999999998 is too large",
            ),
            (
                "{A}(i)",
                "{A * 9999999999 * 9999999999}",
                "cannot map path {2}: arithmetic overflow",
            ),
            (
                "{A}(i)",
                "{A}(i * 100000000)",
                "cannot map path {2} item 1: item index 100000000 is too large",
            ),
        ];
        for (source, target, message) in cases {
            let e = PathMapper::new(source, target)
                .unwrap()
                .apply(&tree)
                .unwrap_err();
            assert_eq!(e.to_string(), message, "{source} -> {target}");
        }
    }

    #[test]
    fn typed_columns_survive() {
        let mut tree = DataTree::new();
        tree.insert(TreePath::from([0, 0]), Branch::from_items(vec![1_i64, 2]));
        tree.insert(TreePath::from([0, 1]), Branch::from_items(vec![3_i64]));
        let out = PathMapper::new("{A;B}", "{A}")
            .unwrap()
            .apply(&tree)
            .unwrap();
        assert_eq!(
            out.branch(&TreePath::zero()).and_then(|b| b.slice::<i64>()),
            Some(&[1, 2, 3][..])
        );
    }
}
