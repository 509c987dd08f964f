//! Sets › Tree, pairing and restructuring: Relative Item, Unflatten Tree and Replace Paths.
//!
//! Relative Item reads an offset written `{0;0;+1}[+1]`: one signed offset for each path index,
//! from the first, and an optional item offset. Replace Paths matches paths with the path
//! masks of Split Tree ([`PathMask`]).

use std::collections::HashMap;

use locus_runtime::{
    Branch, DataTree, DataType, NodeError, NodeRegistry, NodeType, Port, TreePath, Value,
};

use super::tree::{tree_node, tree_port};
use super::tree_edit::PathMask;
use super::{parse_path, set_ops::list_of};

/// Id of [`relative_item`].
pub const RELATIVE_ITEM: &str = "sets.relative_item";
/// Id of [`unflatten_tree`].
pub const UNFLATTEN_TREE: &str = "sets.unflatten_tree";
/// Id of [`replace_paths`].
pub const REPLACE_PATHS: &str = "sets.replace_paths";

/// Registers the restructuring tree nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [relative_item(), unflatten_tree(), replace_paths()] {
        registry.register(t);
    }
}

/// A Relative Item offset: one offset per path index (from the first) and an item offset.
#[derive(Clone, Debug, PartialEq)]
pub struct RelativeOffset {
    /// The offsets of the path indices, first index first.
    pub path: Vec<i64>,
    /// The offset of the item index.
    pub item: i64,
}

impl RelativeOffset {
    /// Reads `{0;+1}[-1]`: a `{…}` block of signed integers separated by `;`, then optionally
    /// a `[…]` block with one signed integer. Spaces are allowed anywhere.
    ///
    /// # Errors
    /// A message saying what does not read.
    pub fn parse(text: &str) -> Result<Self, String> {
        let bad = |why: &str| format!("offset {text:?}: {why}");
        let t = text.trim();
        let rest = t
            .strip_prefix('{')
            .ok_or_else(|| bad("it must start with a path offset block {…}"))?;
        let (path, rest) = rest
            .split_once('}')
            .ok_or_else(|| bad("the path offset block has no closing }"))?;
        let int = |s: &str| {
            let s = s.trim();
            s.strip_prefix('+')
                .unwrap_or(s)
                .trim()
                .parse::<i64>()
                .map_err(|_| bad(&format!("{s:?} is not an integer offset")))
        };
        let path = path.split(';').map(int).collect::<Result<Vec<_>, _>>()?;
        let rest = rest.trim();
        let item = if rest.is_empty() {
            0
        } else {
            let inner = rest
                .strip_prefix('[')
                .and_then(|r| r.strip_suffix(']'))
                .ok_or_else(|| bad("only an item offset block […] may follow the path block"))?;
            int(inner)?
        };
        Ok(Self { path, item })
    }
}

/// For each (dimension, prefix of the path before it), the sorted distinct indices at that
/// dimension among the tree's paths: what a wrapped path offset cycles through.
type Siblings = HashMap<(usize, Vec<u32>), Vec<u32>>;

fn siblings(tree: &DataTree, depth: usize) -> Siblings {
    let mut map: Siblings = HashMap::new();
    for path in tree.paths() {
        let ix = path.indices();
        for d in 0..depth.min(ix.len()) {
            map.entry((d, ix[..d].to_vec())).or_default().push(ix[d]);
        }
    }
    for v in map.values_mut() {
        v.sort_unstable();
        v.dedup();
    }
    map
}

/// The path `offset` away from `path`, if that index exists (with `wrap`, each offset cycles
/// through the indices the tree has at that place).
fn offset_path(path: &TreePath, offsets: &[i64], wrap: Option<&Siblings>) -> Option<TreePath> {
    let mut ix = path.indices().to_vec();
    for (d, &o) in offsets.iter().enumerate().take(ix.len()) {
        if o == 0 {
            continue;
        }
        let current = ix[d];
        let target = match wrap.and_then(|w| w.get(&(d, ix[..d].to_vec()))) {
            Some(sib) => {
                let k = sib.iter().position(|&v| v == current)?;
                let n = i64::try_from(sib.len()).ok()?;
                let k = (i64::try_from(k).ok()? + o).rem_euclid(n);
                sib[usize::try_from(k).ok()?]
            }
            None => u32::try_from(i64::from(current).checked_add(o)?).ok()?,
        };
        ix[d] = target;
    }
    Some(TreePath::new(ix))
}

/// Relative Item \[RelItem\]: every item paired with the item at an offset from it.
pub fn relative_item() -> NodeType {
    tree_node(RELATIVE_ITEM, "Relative Item", "RelItem")
        .gh_guid("fac0d5be-e3ff-4bbb-9742-ec9a54900d41")
        .description(
            "Pairs every item of a tree with the item at a relative offset, written \
             {0;0;+1}[+1]: one signed offset for each path index, from the first (missing ones \
             are 0), and an optional item offset. Item k of the branch at path p goes to A and \
             item k + item offset of the branch at the offset path goes to B, both at path p. \
             Without wrapping, pairs whose partner branch or item does not exist are left out; \
             with Wrap Paths each path offset cycles through the indices the tree has there, \
             with Wrap Items item indices wrap around the partner branch.",
        )
        .input(tree_port(
            "Tree",
            "T",
            "The tree to operate on, of any type.",
        ))
        .input(
            Port::new("Offset", "O", DataType::Text)
                .doc("The relative offset, such as {+1}[0] or {0;0;+1}[-1]; default {0}[+1].")
                .default_value("{0}[+1]".to_owned()),
        )
        .input(
            Port::new("Wrap Paths", "Wp", DataType::Boolean)
                .doc("Whether path offsets wrap around the tree's paths; default false.")
                .default_value(false),
        )
        .input(
            Port::new("Wrap Items", "Wi", DataType::Boolean)
                .doc("Whether item offsets wrap around the branch; default false.")
                .default_value(false),
        )
        .output(tree_port("Item A", "A", "The items that have a partner."))
        .output(tree_port("Item B", "B", "The partner of each item of A."))
        .solve(|s| {
            let offset = RelativeOffset::parse(s.item::<String>(1)?).map_err(NodeError)?;
            let wrap_paths = *s.item::<bool>(2)?;
            let wrap_items = *s.item::<bool>(3)?;
            let tree = s.tree(0)?;
            let sib = wrap_paths.then(|| siblings(tree, offset.path.len()));
            let (mut out_a, mut out_b) = (Vec::new(), Vec::new());
            for (path, branch) in tree.branches() {
                let Some(target) = offset_path(path, &offset.path, sib.as_ref()) else {
                    continue;
                };
                let Some(partner) = tree.branch(&target) else {
                    continue;
                };
                if branch.is_empty() || partner.is_empty() {
                    continue;
                }
                let n = i64::try_from(partner.len()).unwrap_or(i64::MAX);
                let (mut ia, mut ib) = (Vec::new(), Vec::new());
                for k in 0..branch.len() {
                    let Some(p) = i64::try_from(k)
                        .ok()
                        .and_then(|k| k.checked_add(offset.item))
                    else {
                        continue;
                    };
                    let p = if wrap_items { p.rem_euclid(n) } else { p };
                    if let Ok(p) = usize::try_from(p)
                        && p < partner.len()
                    {
                        ia.push(Some(k));
                        ib.push(Some(p));
                    }
                }
                if !ia.is_empty() {
                    out_a.push((path.clone(), branch.gather(ia)));
                    out_b.push((path.clone(), partner.gather(ib)));
                }
            }
            s.set_tree(0, DataTree::from_branches(out_a));
            s.set_tree(1, DataTree::from_branches(out_b));
            Ok(())
        })
}

/// Unflatten Tree \[Unflatten\]: the items of a tree dealt into the branches of a guide.
pub fn unflatten_tree() -> NodeType {
    tree_node(UNFLATTEN_TREE, "Unflatten Tree", "Unflatten")
        .gh_guid("b8e2aa8f-8830-4ee1-bb59-613ea279c281")
        .description(
            "Unflattens a tree by moving its items back into branches: the items of T, in path \
             order, fill the branches of the guide G in order, each with as many items as G's \
             branch has (empty branches of G stay empty). When the items run out, the branch \
             that cannot be filled and those after it are left out, with a warning; items left \
             over are dropped, with a warning.",
        )
        .input(tree_port(
            "Tree",
            "T",
            "The tree to unflatten, of any type.",
        ))
        .input(tree_port(
            "Guide",
            "G",
            "The tree whose paths and branch lengths define the layout.",
        ))
        .output(tree_port("Tree", "T", "The unflattened tree."))
        .solve(|s| {
            let tree = s.tree(0)?;
            let guide = s.tree(1)?;
            let mut flat = Branch::new(tree.data_type());
            for (_, b) in tree.branches() {
                flat.extend(b);
            }
            let mut out = Vec::with_capacity(guide.branch_count());
            let mut at = 0_usize;
            for (path, g) in guide.branches() {
                if at + g.len() > flat.len() {
                    s.warning(format!(
                        "T has {} items, too few for the guide: branch {path} and the ones after \
                         it are left out",
                        flat.len()
                    ));
                    break;
                }
                let mut b = Branch::new(flat.data_type());
                b.extend_range(&flat, at..at + g.len());
                out.push((path.clone(), b));
                at += g.len();
            }
            if at < flat.len() && out.len() == guide.branch_count() {
                s.warning(format!(
                    "the guide holds {at} items; the other {} items of T are dropped",
                    flat.len() - at
                ));
            }
            s.set_tree(0, DataTree::from_branches(out));
            Ok(())
        })
}

/// Replace Paths \[Replace\]: branches moved to new paths by path masks.
pub fn replace_paths() -> NodeType {
    tree_node(REPLACE_PATHS, "Replace Paths", "Replace")
        .gh_guid("bfaaf799-77dc-4f31-9ad8-2f7d1a80aeb0")
        .description(
            "Finds and replaces paths: every branch whose path matches a search mask (as in \
             Split Tree: {0;*}, {?;(1,3)}, …; the first mask that matches wins) moves to the \
             replacement path paired with that mask; other branches stay. Branches that land \
             on one path are joined in path order. S and R must have as many items.",
        )
        .input(tree_port("Data", "D", "The tree to process, of any type."))
        .input(
            Port::new("Search", "S", DataType::Text)
                .list()
                .doc("The search masks."),
        )
        .input(
            Port::new("Replace", "R", DataType::Text)
                .list()
                .doc("The replacement path for each mask, such as {1;0}."),
        )
        .output(tree_port("Data", "D", "The tree with its paths replaced."))
        .solve(|s| {
            let (search, replace) = (list_of(s, 1), list_of(s, 2));
            if search.len() != replace.len() {
                return Err(NodeError(format!(
                    "S has {} masks but R has {} paths: give one path for each mask",
                    search.len(),
                    replace.len()
                )));
            }
            let text = |v: Option<Value>, what: &str, k: usize| match v {
                Some(Value::Text(t)) => Ok(t),
                Some(other) => Ok(locus_runtime::format_value(&other)),
                None => Err(NodeError(format!("{what} {k} is null"))),
            };
            let mut rules = Vec::with_capacity(search.len());
            for k in 0..search.len() {
                let mask =
                    PathMask::parse(&text(search.value(k), "mask", k)?).map_err(NodeError)?;
                let path = parse_path(&text(replace.value(k), "path", k)?, "R")?;
                rules.push((mask, path));
            }
            let tree = s.tree(0)?;
            let mut out = DataTree::new();
            for (path, branch) in tree.branches() {
                let to = rules
                    .iter()
                    .find(|(m, _)| m.matches(path))
                    .map_or(path, |(_, p)| p);
                out.append(to.clone(), branch);
            }
            s.set_tree(0, out);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{Level, NodeCall};

    use super::*;
    use crate::sets::test_support::{assert_clean, messages, tree};

    fn text(t: &str) -> DataTree {
        DataTree::from_item(t.to_owned())
    }

    #[test]
    fn offsets_read_signed_path_and_item_offsets() {
        let o = RelativeOffset::parse("{0;0;+1}[ -1]").unwrap();
        assert_eq!(
            o,
            RelativeOffset {
                path: vec![0, 0, 1],
                item: -1
            }
        );
        let o = RelativeOffset::parse(" {+2} ").unwrap();
        assert_eq!(
            o,
            RelativeOffset {
                path: vec![2],
                item: 0
            }
        );
        for bad in ["", "[1]", "{a}", "{1}[x]", "{1}(1)", "{1"] {
            assert!(RelativeOffset::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn relative_item_pairs_items_and_branches() {
        let t = || tree("{0}:[1, 2, 3] {1}:[10, 20, 30] {2}:[100, 200]");
        // The next item in the same branch.
        let r = NodeCall::new(&relative_item())
            .input(t())
            .input(text("{0}[+1]"))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0], tree("{0}:[1, 2] {1}:[10, 20] {2}:[100]"));
        assert_eq!(r.outputs[1], tree("{0}:[2, 3] {1}:[20, 30] {2}:[200]"));
        // The same item of the next branch.
        let r = NodeCall::new(&relative_item())
            .input(t())
            .input(text("{+1}"))
            .run();
        assert_eq!(r.outputs[0], tree("{0}:[1, 2, 3] {1}:[10, 20]"));
        assert_eq!(r.outputs[1], tree("{0}:[10, 20, 30] {1}:[100, 200]"));
        // Both wrapped: the last branch pairs with the first, items wrap in the partner.
        let r = NodeCall::new(&relative_item())
            .input(t())
            .input(text("{+1}[+1]"))
            .input(DataTree::from_item(true))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(
            r.outputs[0],
            tree("{0}:[1, 2, 3] {1}:[10, 20, 30] {2}:[100, 200]")
        );
        assert_eq!(
            r.outputs[1],
            tree("{0}:[20, 30, 10] {1}:[200, 100, 200] {2}:[2, 3]")
        );
    }

    #[test]
    fn relative_item_wraps_paths_among_siblings() {
        let t = tree("{0;0}:[1] {0;1}:[2] {1;0}:[3] {1;5}:[4]");
        let r = NodeCall::new(&relative_item())
            .input(t)
            .input(text("{0;-1}"))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(
            r.outputs[0],
            tree("{0;0}:[1] {0;1}:[2] {1;0}:[3] {1;5}:[4]")
        );
        assert_eq!(
            r.outputs[1],
            tree("{0;0}:[2] {0;1}:[1] {1;0}:[4] {1;5}:[3]")
        );
    }

    #[test]
    fn relative_item_reports_a_bad_offset() {
        let r = NodeCall::new(&relative_item())
            .input(tree("{0}:[1]"))
            .input(text("+1"))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn unflatten_tree_deals_items_into_the_guide() {
        let r = NodeCall::new(&unflatten_tree())
            .input(tree("{0}:[1, 2, 3, 4, 5]"))
            .input(tree("{0;0}:[0, 0] {0;1}:[] {1;0}:[0, 0, 0]"))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0], tree("{0;0}:[1, 2] {0;1}:[] {1;0}:[3, 4, 5]"));
        let r = NodeCall::new(&unflatten_tree())
            .input(tree("{0}:[1, 2, 3]"))
            .input(tree("{0}:[0, 0] {1}:[0, 0]"))
            .run();
        assert_eq!(r.outputs[0], tree("{0}:[1, 2]"));
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        let r = NodeCall::new(&unflatten_tree())
            .input(tree("{0}:[1, 2, 3]"))
            .input(tree("{5}:[0]"))
            .run();
        assert_eq!(r.outputs[0], tree("{5}:[1]"));
        assert_eq!(messages(&r, Level::Warning).len(), 1);
    }

    #[test]
    fn replace_paths_moves_matching_branches() {
        let r = NodeCall::new(&replace_paths())
            .input(tree("{0;0}:[1] {0;1}:[2] {1;0}:[3]"))
            .input(DataTree::from_list(vec!["{0;*}".to_owned()]))
            .input(DataTree::from_list(vec!["{7}".to_owned()]))
            .run();
        assert_clean(&r);
        assert_eq!(r.outputs[0], tree("{1;0}:[3] {7}:[1, 2]"));
        let r = NodeCall::new(&replace_paths())
            .input(tree("{0}:[1]"))
            .input(DataTree::from_list(vec![
                "{0}".to_owned(),
                "{1}".to_owned(),
            ]))
            .input(DataTree::from_list(vec!["{2}".to_owned()]))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        let r = NodeCall::new(&replace_paths())
            .input(tree("{0}:[1]"))
            .input(DataTree::from_list(vec!["{x}".to_owned()]))
            .input(DataTree::from_list(vec!["{2}".to_owned()]))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }
}
