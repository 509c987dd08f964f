//! Sets › Tree, choosing and cleaning trees: Stream Filter, Stream Gate, Clean Tree, Split
//! Tree and Match Tree.
//!
//! Split Tree matches paths against Grasshopper's path masks ([`PathMask`]). Stream Filter
//! has a variable number of inputs: the first is the gate, the others the streams
//! (`inputs: ["G", "0", "1", "2"]`). Stream Gate has variable outputs, two by default as in
//! Grasshopper (`outputs: ["0", "1", "2"]` for three).

use locus_runtime::{
    Branch, DataTree, DataType, NodeError, NodeRegistry, NodeType, Port, Solve, TreePath, Value,
    number_to_integer,
};

/// Id of [`stream_filter`].
pub const STREAM_FILTER: &str = "sets.stream_filter";
/// Id of [`stream_gate`].
pub const STREAM_GATE: &str = "sets.stream_gate";
/// Id of [`clean_tree`].
pub const CLEAN_TREE: &str = "sets.clean_tree";
/// Id of [`split_tree`].
pub const SPLIT_TREE: &str = "sets.split_tree";
/// Id of [`match_tree`].
pub const MATCH_TREE: &str = "sets.match_tree";

/// Registers the tree choosing and cleaning nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        stream_filter(),
        stream_gate(),
        clean_tree(),
        split_tree(),
        match_tree(),
    ] {
        registry.register(t);
    }
}

fn tree_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("Tree")
}

fn tree_port(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Generic).tree().doc(doc)
}

/// The first item of a tree as an integer gate index.
fn gate_of(tree: &DataTree, name: &str) -> Result<Option<i64>, NodeError> {
    let Some(v) = tree.values().flatten().next() else {
        return Ok(None);
    };
    let g = match &v {
        Value::Integer(i) => Some(*i),
        Value::Number(x) => number_to_integer(*x),
        Value::Boolean(b) => Some(i64::from(*b)),
        Value::Text(t) => t.trim().parse().ok(),
        _ => None,
    };
    g.map(Some)
        .ok_or_else(|| NodeError(format!("gate {name} ({v:?}) is not an integer")))
}

/// Stream Filter \[Filter\]: one of several streams, chosen by a gate index.
pub fn stream_filter() -> NodeType {
    tree_node(STREAM_FILTER, "Stream Filter", "Filter")
        .gh_guid("eeafc956-268e-461d-8e73-ee05c6f72c01")
        .description(
            "Passes on the whole stream (tree) that the gate index names and drops the others. \
             The first input is the gate G (its first item, an integer), the others are the \
             streams 0, 1, … (the graph may name more). A gate without data picks stream 0; a \
             gate that names no stream is an error.",
        )
        .variable_inputs(
            Port::new("Stream", "0", DataType::Generic)
                .tree()
                .optional()
                .doc("The first input (G): the gate, the index of the stream to pass; the others: the streams, of any type; optional."),
            &["G", "0", "1"],
        )
        .output(tree_port("Stream", "S", "The stream the gate names."))
        .solve(|s| {
            let gate = gate_of(s.tree(0)?, "G")?.unwrap_or(0);
            let count = s.input_count() - 1;
            let k = usize::try_from(gate)
                .ok()
                .filter(|&k| k < count)
                .ok_or_else(|| {
                    NodeError(format!(
                        "gate {gate} names no stream (there are {count}, 0 to {})",
                        count.saturating_sub(1)
                    ))
                })?;
            let chosen = s.tree(k + 1)?.clone();
            s.set_tree(0, chosen);
            Ok(())
        })
}

/// Stream Gate \[Gate\]: a stream sent to one of several outputs.
pub fn stream_gate() -> NodeType {
    tree_node(STREAM_GATE, "Stream Gate", "Gate")
        .gh_guid("71fcc052-6add-4d70-8d97-cfb37ea9d169")
        .description(
            "Sends the whole stream (tree) S to the output the gate index G names; the other \
             outputs stay empty. The outputs are variable, 0, 1, … as Grasshopper names them \
             (two by default); a gate that names no output sends the stream nowhere, with a \
             warning.",
        )
        .input(tree_port(
            "Stream",
            "S",
            "The stream to redirect, of any type.",
        ))
        .input(
            Port::new("Gate", "G", DataType::Integer)
                .tree()
                .doc("The index of the output to send the stream to (its first item); default 0.")
                .default_value(0_i64),
        )
        .variable_outputs(
            tree_port(
                "Target",
                "0",
                "The stream when G is this output's position (0, 1, …).",
            ),
            &["0", "1"],
        )
        .solve(|s| {
            let gate = gate_of(s.tree(1)?, "G")?.unwrap_or(0);
            let outputs = s.output_count();
            match usize::try_from(gate).ok().filter(|&g| g < outputs) {
                Some(g) => {
                    let stream = s.tree(0)?.clone();
                    s.set_tree(g, stream);
                }
                None => s.warning(format!(
                    "gate {gate} names no output (there are {outputs}, 0 to {})",
                    outputs.saturating_sub(1)
                )),
            }
            Ok(())
        })
}

/// Whether a value is invalid in the sense of Clean Tree: a number, point, vector or domain
/// that is not finite, or a plane that is not valid.
fn is_invalid(v: &Value) -> bool {
    match v {
        Value::Number(x) => !x.is_finite(),
        Value::Point(p) => !p.is_finite(),
        Value::Vector(x) => !x.is_finite(),
        Value::Domain(d) => !d.is_finite(),
        Value::Plane(p) => !p.is_valid(),
        _ => false,
    }
}

/// Clean Tree \[Clean\]: nulls, invalid items and empty branches removed.
pub fn clean_tree() -> NodeType {
    tree_node(CLEAN_TREE, "Clean Tree", "Clean")
        .gh_guid("7991bc5f-8a01-4768-bfb0-a39357ac6b84")
        .gh_guid("071c3940-a12d-4b77-bb23-42b5d3314a0d")
        .description(
            "Removes null items from a tree; with X also invalid items (numbers, points, \
             vectors and domains that are not finite, planes that are not valid); with E also \
             the branches left empty. Item order and paths are kept.",
        )
        .input(tree_port("Tree", "T", "The tree to clean, of any type."))
        .input(
            Port::new("Clean Invalid", "X", DataType::Boolean)
                .doc("Whether invalid items are removed too; default false.")
                .default_value(false),
        )
        .input(
            Port::new("Clean Empty", "E", DataType::Boolean)
                .doc("Whether empty branches are removed; default true.")
                .default_value(true),
        )
        .output(tree_port("Tree", "T", "The cleaned tree."))
        .solve(|s| {
            let invalid = flag(s, 1, false)?;
            let empty = flag(s, 2, true)?;
            let tree = s.tree(0)?;
            let mut out = Vec::with_capacity(tree.branch_count());
            for (path, branch) in tree.branches() {
                let keep = (0..branch.len()).filter(|&k| {
                    !(branch.is_null(k)
                        || invalid && branch.value(k).is_some_and(|v| is_invalid(&v)))
                });
                let cleaned = branch.gather(keep.map(Some).collect::<Vec<_>>());
                if !(empty && cleaned.is_empty()) {
                    out.push((path.clone(), cleaned));
                }
            }
            s.set_tree(0, DataTree::from_branches(out));
            Ok(())
        })
}

/// A boolean flag of an item input (the first item, when there are several).
fn flag(s: &Solve<'_>, input: usize, default: bool) -> Result<bool, NodeError> {
    Ok(s.item_opt::<bool>(input).copied().unwrap_or(default))
}

/// One element of a path mask.
#[derive(Clone, Debug, PartialEq)]
enum MaskElement {
    /// `*`: any number of indices, none included.
    Any,
    /// `?`: exactly one index.
    One,
    /// Indices in one of the given inclusive ranges: `3`, `(0,2,4)`, `1 to 4`, `(0, 5 to 7)`.
    Ranges(Vec<(u32, u32)>),
}

/// A Grasshopper path mask such as `{0;*}`, `{?;1}`, `{0;(1,3)}` or `{0;2 to 5}`.
#[derive(Clone, Debug, PartialEq)]
pub struct PathMask {
    elements: Vec<MaskElement>,
}

impl PathMask {
    /// Reads a mask. Braces may be left out.
    ///
    /// # Errors
    /// A message naming the element that does not read.
    pub fn parse(text: &str) -> Result<Self, String> {
        let t = text.trim();
        let t = t.strip_prefix('{').unwrap_or(t);
        let t = t.strip_suffix('}').unwrap_or(t);
        if t.contains('[') || t.contains(']') {
            return Err(format!("mask {text:?}: item masks [..] are not supported"));
        }
        let mut elements = Vec::new();
        for part in t.split(';') {
            let p = part.trim();
            elements.push(match p {
                "*" => MaskElement::Any,
                "?" => MaskElement::One,
                _ => {
                    let inner = p
                        .strip_prefix('(')
                        .and_then(|q| q.strip_suffix(')'))
                        .unwrap_or(p);
                    let mut ranges = Vec::new();
                    for r in inner.split(',') {
                        let r = r.trim();
                        let bad = || format!("mask {text:?}: element {p:?} does not read");
                        let (a, b) = match r.split_once(" to ") {
                            Some((a, b)) => (a.trim(), b.trim()),
                            None => (r, r),
                        };
                        let a: u32 = a.parse().map_err(|_| bad())?;
                        let b: u32 = b.parse().map_err(|_| bad())?;
                        ranges.push((a.min(b), a.max(b)));
                    }
                    MaskElement::Ranges(ranges)
                }
            });
        }
        Ok(Self { elements })
    }

    /// Whether `path` matches the mask.
    pub fn matches(&self, path: &TreePath) -> bool {
        // The positions in the path that the mask so far can end at: O(mask × path) steps.
        let path = path.indices();
        let mut reachable = vec![false; path.len() + 1];
        reachable[0] = true;
        for e in &self.elements {
            let mut next = vec![false; path.len() + 1];
            match e {
                MaskElement::Any => {
                    let mut any = false;
                    for (k, r) in reachable.iter().enumerate() {
                        any |= *r;
                        next[k] = any;
                    }
                }
                MaskElement::One => {
                    next[1..].copy_from_slice(&reachable[..path.len()]);
                }
                MaskElement::Ranges(ranges) => {
                    for k in 0..path.len() {
                        next[k + 1] =
                            reachable[k] && ranges.iter().any(|(a, b)| (a..=b).contains(&&path[k]));
                    }
                }
            }
            reachable = next;
        }
        reachable[path.len()]
    }
}

/// Split Tree \[Split\]: a tree split by path masks.
pub fn split_tree() -> NodeType {
    tree_node(SPLIT_TREE, "Split Tree", "Split")
        .gh_guid("d8b1e7ac-cd31-4748-b262-e07e53068afc")
        .description(
            "Splits a tree in two by path masks: branches whose path matches any mask go to \
             Positive, the others to Negative. A mask is {e;e;…} with elements * (any number \
             of indices, none included), ? (one index), an index, a set (0,2,4), a range \
             2 to 5, or a set of ranges. Item masks ([0,2]) are not supported and are an error.",
        )
        .input(tree_port("Data", "D", "The tree to split, of any type."))
        .input(
            Port::new("Masks", "M", DataType::Text)
                .tree()
                .doc("The path masks, such as {0;*} or {?;(1,3)}, from every branch."),
        )
        .output(tree_port(
            "Positive",
            "P",
            "The branches that match a mask.",
        ))
        .output(tree_port(
            "Negative",
            "N",
            "The branches that match no mask.",
        ))
        .solve(|s| {
            let masks = s
                .tree(1)?
                .values()
                .flatten()
                .map(|v| match v {
                    Value::Text(t) => PathMask::parse(&t),
                    other => PathMask::parse(&locus_runtime::format_value(&other)),
                })
                .collect::<Result<Vec<_>, _>>()
                .map_err(NodeError)?;
            let tree = s.tree(0)?;
            let (mut pos, mut neg) = (Vec::new(), Vec::new());
            for (path, branch) in tree.branches() {
                let target = if masks.iter().any(|m| m.matches(path)) {
                    &mut pos
                } else {
                    &mut neg
                };
                target.push((path.clone(), branch.clone()));
            }
            s.set_tree(0, DataTree::from_branches(pos));
            s.set_tree(1, DataTree::from_branches(neg));
            Ok(())
        })
}

/// Match Tree \[Match\]: a tree given the structure of a guide tree.
pub fn match_tree() -> NodeType {
    tree_node(MATCH_TREE, "Match Tree", "Match")
        .gh_guid("46372d0d-82dc-4acb-adc3-25d1fde04c4e")
        .description(
            "Gives the items of tree T the structure of the guide tree G. When T has as many \
             branches as G, branch k of T (in path order) gets the path of branch k of G. \
             Otherwise, when T has as many items as G, its items (in path order) are dealt \
             into branches with the paths and lengths of G's. Otherwise it is an error naming \
             both counts.",
        )
        .input(tree_port(
            "Tree",
            "T",
            "The tree to restructure, of any type.",
        ))
        .input(tree_port(
            "Guide",
            "G",
            "The tree whose structure to copy, of any type.",
        ))
        .output(tree_port(
            "Tree",
            "T",
            "The items of T in the structure of G.",
        ))
        .solve(|s| {
            let tree = s.tree(0)?;
            let guide = s.tree(1)?;
            let out = if tree.branch_count() == guide.branch_count() {
                DataTree::from_branches(
                    guide
                        .paths()
                        .cloned()
                        .zip(tree.branches().iter().map(|(_, b)| b.clone())),
                )
            } else if tree.item_count() == guide.item_count() {
                let mut flat = Branch::new(tree.data_type());
                for (_, b) in tree.branches() {
                    flat.extend(b);
                }
                let mut start = 0;
                let mut out = Vec::with_capacity(guide.branch_count());
                for (path, b) in guide.branches() {
                    let mut part = Branch::new(flat.data_type());
                    part.extend_range(&flat, start..start + b.len());
                    start += b.len();
                    out.push((path.clone(), part));
                }
                DataTree::from_branches(out)
            } else {
                return Err(NodeError(format!(
                    "T has {} branches and {} items, G has {} branches and {} items: give T \
                     as many branches or as many items as G",
                    tree.branch_count(),
                    tree.item_count(),
                    guide.branch_count(),
                    guide.item_count()
                )));
            };
            s.set_tree(0, out);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{Level, NodeCall};

    use super::*;
    use crate::sets::test_support::{generic, messages, tree};

    #[test]
    fn stream_filter_passes_the_gated_stream() {
        let r = NodeCall::new(&stream_filter())
            .input(DataTree::from_item(1_i64))
            .input(tree("{0}:[1, 2]"))
            .input(tree("{0}:[3] {1}:[4]"))
            .run();
        assert_eq!(r.outputs[0], tree("{0}:[3] {1}:[4]"));
        let r = NodeCall::new(&stream_filter())
            .input(DataTree::from_item(2_i64))
            .input(tree("{0}:[1]"))
            .input(tree("{0}:[2]"))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        let r = NodeCall::new(&stream_filter())
            .input(generic("{0}:[\"x\"]"))
            .input(tree("{0}:[1]"))
            .input(tree("{0}:[2]"))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn stream_gate_sends_the_stream_to_one_output() {
        let r = NodeCall::new(&stream_gate())
            .input(tree("{0}:[1, 2]"))
            .input(DataTree::from_item(1_i64))
            .run();
        assert!(r.outputs[0].is_empty());
        assert_eq!(r.outputs[1], tree("{0}:[1, 2]"));
        let r = NodeCall::new(&stream_gate())
            .input(tree("{0}:[1, 2]"))
            .input(DataTree::from_item(4_i64))
            .run();
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        assert!(r.outputs[0].is_empty() && r.outputs[1].is_empty());
        // Outputs added on the node: the gate reaches them.
        let r = NodeCall::new(&stream_gate())
            .input(tree("{0}:[1, 2]"))
            .input(DataTree::from_item(3_i64))
            .output_names(&["0", "1", "2", "3"])
            .run();
        assert!(messages(&r, Level::Warning).is_empty());
        assert_eq!(r.outputs.len(), 4);
        assert_eq!(r.outputs[3], tree("{0}:[1, 2]"));
        assert!((0..3).all(|k| r.outputs[k].is_empty()));
    }

    #[test]
    fn clean_tree_removes_nulls_invalid_items_and_empty_branches() {
        let r = NodeCall::new(&clean_tree())
            .input(tree("{0}:[1, null, NaN] {1}:[null] {2}:[]"))
            .run();
        assert_eq!(
            format!("{:?}", r.outputs[0]),
            format!("{:?}", tree("{0}:[1, NaN]"))
        );
        let r = NodeCall::new(&clean_tree())
            .input(tree("{0}:[1, null, NaN] {1}:[null]"))
            .input(DataTree::from_item(true))
            .input(DataTree::from_item(false))
            .run();
        assert_eq!(r.outputs[0], tree("{0}:[1] {1}:[]"));
    }

    #[test]
    fn path_masks_match_like_grasshopper() {
        let m = |mask: &str, path: &str| {
            PathMask::parse(mask)
                .unwrap()
                .matches(&path.parse::<TreePath>().unwrap())
        };
        assert!(m("{0;*}", "{0}"));
        assert!(m("{0;*}", "{0;1;2}"));
        assert!(!m("{0;*}", "{1;0}"));
        assert!(m("{?;1}", "{5;1}"));
        assert!(!m("{?;1}", "{1}"));
        assert!(m("{0;(1,3)}", "{0;3}"));
        assert!(!m("{0;(1,3)}", "{0;2}"));
        assert!(m("{0;2 to 5}", "{0;4}"));
        assert!(m("{*;7}", "{1;2;7}"));
        assert!(!m(
            "{*;*;*;*;*;*;*;*;*;*;*;*;9}",
            "{1;2;3;4;5;6;7;8;9;10;11;12;13;14;15;16;17;18;19;20}"
        ));
        for bad in ["{a}", "{0;[1]}", "{0;1 to x}"] {
            assert!(PathMask::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn split_tree_by_masks() {
        let r = NodeCall::new(&split_tree())
            .input(tree("{0;0}:[1] {0;1}:[2] {1;0}:[3]"))
            .input(DataTree::from_list(vec!["{0;*}".to_owned()]))
            .run();
        assert_eq!(r.outputs[0], tree("{0;0}:[1] {0;1}:[2]"));
        assert_eq!(r.outputs[1], tree("{1;0}:[3]"));
        let r = NodeCall::new(&split_tree())
            .input(tree("{0}:[1]"))
            .input(DataTree::from_list(vec!["{x}".to_owned()]))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }

    #[test]
    fn match_tree_by_branches_or_by_items() {
        let r = NodeCall::new(&match_tree())
            .input(tree("{0}:[1, 2] {1}:[3]"))
            .input(tree("{5;0}:[0] {5;1}:[0, 0]"))
            .run();
        assert_eq!(r.outputs[0], tree("{5;0}:[1, 2] {5;1}:[3]"));
        let r = NodeCall::new(&match_tree())
            .input(tree("{0}:[1, 2, 3]"))
            .input(tree("{0}:[0] {1}:[0, 0]"))
            .run();
        assert_eq!(r.outputs[0], tree("{0}:[1] {1}:[2, 3]"));
        let r = NodeCall::new(&match_tree())
            .input(tree("{0}:[1, 2, 3]"))
            .input(tree("{0}:[0] {1}:[0]"))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }
}
