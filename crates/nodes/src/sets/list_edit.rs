//! Sets › List, editing and combining lists: Sub List, Insert Items, Replace Items,
//! Pick'n'Choose, Weave, Sift Pattern, Cross Reference and Null Item.
//!
//! Nodes that take items from one list keep it typed ([`Branch::gather`]); nodes that combine
//! several lists build generic values, which the runtime stores as a typed column again when
//! all items have one type. Pick'n'Choose and Weave have a variable number of inputs: the
//! first is the pattern, the others the streams (`inputs: ["P", "0", "1", "2"]`).

use locus_kernel::Interval;
use locus_runtime::{
    Branch, DataType, NodeError, NodeRegistry, NodeType, Port, Solve, Value, number_to_integer,
};

use super::pick_index;
use crate::maths::sequence::MAX_SEQUENCE_LENGTH;

/// Id of [`sub_list`].
pub const SUB_LIST: &str = "sets.sub_list";
/// Id of [`insert_items`].
pub const INSERT_ITEMS: &str = "sets.insert_items";
/// Id of [`replace_items`].
pub const REPLACE_ITEMS: &str = "sets.replace_items";
/// Id of [`pick_n_choose`].
pub const PICK_N_CHOOSE: &str = "sets.pick_n_choose";
/// Id of [`weave`].
pub const WEAVE: &str = "sets.weave";
/// Id of [`sift_pattern`].
pub const SIFT_PATTERN: &str = "sets.sift_pattern";
/// Id of [`cross_reference`].
pub const CROSS_REFERENCE: &str = "sets.cross_reference";
/// Id of [`null_item`].
pub const NULL_ITEM: &str = "sets.null_item";

/// Registers the list editing nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        sub_list(),
        insert_items(),
        replace_items(),
        pick_n_choose(),
        weave(),
        sift_pattern(),
        cross_reference(),
        null_item(),
    ] {
        registry.register(t);
    }
}

fn list_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("List")
}

fn generic_list(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Generic).list().doc(doc)
}

fn branch_of(s: &Solve<'_>, input: usize) -> Branch {
    s.branch(input)
        .cloned()
        .unwrap_or_else(|| Branch::new(DataType::Generic))
}

/// The integers of a list input, nulls skipped.
fn integers(s: &Solve<'_>, input: usize) -> Result<Vec<i64>, NodeError> {
    Ok(s.list::<i64>(input)?.present().copied().collect())
}

/// Sub List \[SubSet\]: the items of a list whose indices are in a domain.
pub fn sub_list() -> NodeType {
    list_node(SUB_LIST, "Sub List", "SubSet")
        .gh_guid("b333ff42-93bd-406b-8e17-15780719b6ec")
        .description(
            "Extracts the items whose indices lie in the domain D, both ends included (the ends \
             are rounded to the nearest integer, halves to even); a decreasing domain lists \
             them backwards. With Wrap, indices outside the list wrap around it; without, the \
             domain is clipped to the list. Index lists the index in L of every item taken.",
        )
        .input(generic_list(
            "List",
            "L",
            "The list to take items from, of any type.",
        ))
        .input(
            Port::new("Domain", "D", DataType::Domain)
                .doc("The domain of indices to take, ends included."),
        )
        .input(
            Port::new("Wrap", "W", DataType::Boolean)
                .doc("Whether indices wrap around the list; default false.")
                .default_value(false),
        )
        .output(generic_list(
            "List",
            "L",
            "The items whose indices are in D.",
        ))
        .output(
            Port::new("Index", "I", DataType::Integer)
                .list()
                .doc("The index in L of each item taken."),
        )
        .solve(|s| {
            let branch = branch_of(s, 0);
            let domain = *s.item::<Interval>(1)?;
            let wrap = *s.item::<bool>(2)?;
            let end = |x: f64| {
                number_to_integer(x)
                    .ok_or_else(|| NodeError(format!("domain end {x} is not an index")))
            };
            let (a, b) = (end(domain.t0)?, end(domain.t1)?);
            let n = i64::try_from(branch.len()).unwrap_or(i64::MAX);
            let (mut a, mut b) = (a, b);
            if !wrap {
                if n == 0 {
                    s.set_branch(0, branch);
                    s.set_list::<i64>(1, Vec::new());
                    return Ok(());
                }
                a = a.clamp(0, n - 1);
                b = b.clamp(0, n - 1);
            }
            let len = a.abs_diff(b).saturating_add(1);
            if len > MAX_SEQUENCE_LENGTH as u64 {
                return Err(NodeError(format!(
                    "the domain {a} to {b} spans more than {MAX_SEQUENCE_LENGTH} indices"
                )));
            }
            let indices: Vec<i64> = if a <= b {
                (a..=b).collect()
            } else {
                (b..=a).rev().collect()
            };
            let mut picked = Vec::with_capacity(indices.len());
            for &i in &indices {
                if n == 0 {
                    break;
                }
                picked.push(pick_index(i, branch.len(), true).unwrap_or(0));
            }
            s.set_branch(0, branch.gather(picked.iter().map(|&i| Some(i))));
            s.set_list(
                1,
                picked
                    .iter()
                    .map(|&i| i64::try_from(i).unwrap_or(i64::MAX))
                    .collect(),
            );
            Ok(())
        })
}

/// Pairs item `k` of `items` with index `k` of `indices`, longest-list style (the shorter
/// list repeats its last element).
fn pairs(items: &Branch, indices: &[i64]) -> Vec<(i64, Option<Value>)> {
    let n = items.len().max(indices.len());
    if items.is_empty() || indices.is_empty() {
        return Vec::new();
    }
    (0..n)
        .map(|k| {
            (
                indices[k.min(indices.len() - 1)],
                items.value(k.min(items.len() - 1)),
            )
        })
        .collect()
}

/// Insert Items \[Ins\]: items inserted into a list at indices.
pub fn insert_items() -> NodeType {
    list_node(INSERT_ITEMS, "Insert Items", "Ins")
        .gh_guid("e2039b07-d3f3-40f8-af88-d74fed238727")
        .description(
            "Inserts items into a list: item k of I goes before the item at index k of i in \
             the original list (an index equal to the list's length appends). Items and indices \
             are paired longest-list style; items given the same index keep their order. With \
             Wrap, indices wrap around the positions 0 to length; without, an index outside \
             them is skipped with a warning.",
        )
        .input(generic_list(
            "List",
            "L",
            "The list to insert into, of any type.",
        ))
        .input(generic_list("Item", "I", "The items to insert; optional.").optional())
        .input(
            Port::new("Indices", "i", DataType::Integer)
                .list()
                .doc("The insertion index of each item, in the original list."),
        )
        .input(
            Port::new("Wrap", "W", DataType::Boolean)
                .doc("Whether indices wrap around the list; default false.")
                .default_value(false),
        )
        .output(generic_list(
            "List",
            "L",
            "The list with the items inserted.",
        ))
        .solve(|s| {
            let list = branch_of(s, 0);
            let items = branch_of(s, 1);
            let indices = integers(s, 2)?;
            let wrap = *s.item::<bool>(3)?;
            let slots = list.len() + 1;
            let mut inserts: Vec<(usize, Option<Value>)> = Vec::new();
            let mut skipped = Vec::new();
            for (index, item) in pairs(&items, &indices) {
                match pick_index(index, slots, wrap) {
                    Ok(at) => inserts.push((at, item)),
                    Err(_) => skipped.push(index),
                }
            }
            if !skipped.is_empty() {
                s.warning(format!(
                    "indices {skipped:?} are outside 0 to {} and were skipped",
                    list.len()
                ));
            }
            inserts.sort_by_key(|(at, _)| *at);
            let mut out = Vec::with_capacity(list.len() + inserts.len());
            let mut next = inserts.into_iter().peekable();
            for k in 0..=list.len() {
                while let Some((_, item)) = next.next_if(|(at, _)| *at == k) {
                    out.push(item);
                }
                if k < list.len() {
                    out.push(list.value(k));
                }
            }
            s.set_list_values(0, out);
            Ok(())
        })
}

/// Replace Items \[Replace\]: items of a list replaced at indices.
pub fn replace_items() -> NodeType {
    list_node(REPLACE_ITEMS, "Replace Items", "Replace")
        .gh_guid("7a218bfb-b93d-4c1f-83d3-5a0b909dd60b")
        .description(
            "Replaces the item at index k of i with item k of I; items and indices are paired \
             longest-list style, and a later pair wins over an earlier one at the same index. \
             With Wrap, indices wrap around the list; without, an index outside it is skipped \
             with a warning.",
        )
        .input(generic_list(
            "List",
            "L",
            "The list to change, of any type.",
        ))
        .input(generic_list("Item", "I", "The replacement items; optional.").optional())
        .input(
            Port::new("Indices", "i", DataType::Integer)
                .list()
                .optional()
                .doc("The index of each replaced item; optional."),
        )
        .input(
            Port::new("Wrap", "W", DataType::Boolean)
                .doc("Whether indices wrap around the list; default true.")
                .default_value(true),
        )
        .output(generic_list(
            "List",
            "L",
            "The list with the items replaced.",
        ))
        .solve(|s| {
            let list = branch_of(s, 0);
            let items = branch_of(s, 1);
            let indices = match s.branch(2) {
                Some(_) => integers(s, 2)?,
                None => Vec::new(),
            };
            let wrap = *s.item::<bool>(3)?;
            let mut out: Vec<Option<Value>> = list.values().collect();
            let mut skipped = Vec::new();
            if !out.is_empty() {
                for (index, item) in pairs(&items, &indices) {
                    match pick_index(index, out.len(), wrap) {
                        Ok(at) => out[at] = item,
                        Err(_) => skipped.push(index),
                    }
                }
            }
            if !skipped.is_empty() {
                s.warning(format!(
                    "indices {skipped:?} are outside the list of {} items and were skipped",
                    out.len()
                ));
            }
            s.set_list_values(0, out);
            Ok(())
        })
}

/// The stream inputs (1, 2, …) of a node whose input 0 is a pattern.
fn streams(s: &Solve<'_>) -> Vec<Branch> {
    (1..s.input_count()).map(|k| branch_of(s, k)).collect()
}

/// The pattern of input 0 (a generic input of a variable-input node) as integers.
fn pattern(s: &Solve<'_>) -> Result<Vec<i64>, NodeError> {
    let branch = branch_of(s, 0);
    let mut out = Vec::with_capacity(branch.len());
    for (k, v) in branch.values().enumerate() {
        let Some(v) = v else { continue };
        let i = match &v {
            Value::Integer(i) => Some(*i),
            Value::Number(x) => number_to_integer(*x),
            Value::Boolean(b) => Some(i64::from(*b)),
            Value::Text(t) => t.trim().parse::<i64>().ok(),
            _ => None,
        };
        out.push(
            i.ok_or_else(|| NodeError(format!("pattern item {k} ({v:?}) is not a stream index")))?,
        );
    }
    Ok(out)
}

fn stream_template(doc: &str) -> Port {
    Port::new("Stream", "0", DataType::Generic)
        .list()
        .optional()
        .doc(doc)
}

/// Pick'n'Choose \[P'n'C\]: item by item, from the stream a pattern names.
pub fn pick_n_choose() -> NodeType {
    list_node(PICK_N_CHOOSE, "Pick'n'Choose", "P'n'C")
        .gh_guid("03b801eb-87cd-476a-a591-257fe5d5bf0f")
        .description(
            "Picks item k of the stream that pattern item k names: result k is item k of \
             stream P[k]. The first input is the pattern (integers), the others are the \
             streams 0, 1, … (the graph may name more). The result has one item per pattern \
             item; a stream without an item k gives a null there, and a pattern item that \
             names no stream is an error.",
        )
        .variable_inputs(
            stream_template(
                "The first input (P): the pattern, stream indices; the others: the streams of \
                 data, of any type.",
            ),
            &["P", "0", "1"],
        )
        .output(generic_list("Result", "R", "The picked items."))
        .solve(|s| {
            let pattern = pattern(s)?;
            let streams = streams(s);
            let mut out = Vec::with_capacity(pattern.len());
            for (k, &p) in pattern.iter().enumerate() {
                let stream = usize::try_from(p)
                    .ok()
                    .and_then(|p| streams.get(p))
                    .ok_or_else(|| no_stream(p, streams.len()))?;
                out.push(if k < stream.len() {
                    stream.value(k)
                } else {
                    None
                });
            }
            s.set_list_values(0, out);
            Ok(())
        })
}

fn no_stream(p: i64, count: usize) -> NodeError {
    NodeError(format!(
        "pattern index {p} names no stream (there are {count}, 0 to {})",
        count.saturating_sub(1)
    ))
}

/// Weave \[Weave\]: several lists interleaved by a repeating pattern.
pub fn weave() -> NodeType {
    list_node(WEAVE, "Weave", "Weave")
        .gh_guid("50faccbd-9c92-4175-a5fa-d65e36013db6")
        .description(
            "Weaves streams of data by a repeating pattern: for each pattern item p in turn the \
             next unused item of stream p is added, and the pattern starts again until every \
             stream the pattern names is used up; a stream that is used up is skipped. The \
             first input is the pattern (integers), the others are the streams 0, 1, … (the \
             graph may name more). A pattern item that names no stream is an error. Items of \
             streams the pattern never names are left out, with a warning.",
        )
        .variable_inputs(
            stream_template(
                "The first input (P): the weave pattern, stream indices; the others: the \
                 streams of data, of any type.",
            ),
            &["P", "0", "1"],
        )
        .output(generic_list("Weave", "W", "The woven list."))
        .solve(|s| {
            let pattern = pattern(s)?;
            let streams = streams(s);
            let mut order = Vec::with_capacity(pattern.len());
            for &p in &pattern {
                order.push(
                    usize::try_from(p)
                        .ok()
                        .filter(|&p| p < streams.len())
                        .ok_or_else(|| no_stream(p, streams.len()))?,
                );
            }
            let mut next = vec![0_usize; streams.len()];
            let mut out = Vec::new();
            if !order.is_empty() {
                loop {
                    let before = out.len();
                    for &p in &order {
                        if next[p] < streams[p].len() {
                            out.push(streams[p].value(next[p]));
                            next[p] += 1;
                        }
                    }
                    if out.len() == before {
                        break;
                    }
                }
            }
            let left: usize = streams.iter().zip(&next).map(|(b, &n)| b.len() - n).sum();
            if left > 0 {
                s.warning(format!(
                    "{left} items of streams the pattern does not name were left out"
                ));
            }
            s.set_list_values(0, out);
            Ok(())
        })
}

/// Sift Pattern \[Sift\]: the items of a list sent to outputs by a repeating pattern.
pub fn sift_pattern() -> NodeType {
    list_node(SIFT_PATTERN, "Sift Pattern", "Sift")
        .gh_guid("3249222f-f536-467a-89f4-f0353fba455a")
        .description(
            "Sifts a list into outputs by a repeating pattern of output indices: item k goes \
             to output P[k mod |P|] and every other output gets a null at that place, so all \
             outputs keep the length of the list and stay aligned with it. The outputs are \
             variable, 0, 1, … as Grasshopper names them (two by default); a pattern index \
             that names no output sends its items nowhere, with a warning.",
        )
        .input(generic_list("List", "L", "The list to sift, of any type."))
        .input(
            Port::new("Sift Pattern", "P", DataType::Integer)
                .list()
                .optional()
                .doc(
                    "The output index of each item, repeated along the list; without one (or \
                      with an empty list) [0, 1].",
                ),
        )
        .variable_outputs(
            generic_list(
                "Output",
                "0",
                "The items sifted to this output (0, 1, …), nulls elsewhere.",
            ),
            &["0", "1"],
        )
        .solve(|s| {
            let list = branch_of(s, 0);
            let mut pattern = match s.branch(1) {
                Some(_) => integers(s, 1)?,
                None => Vec::new(),
            };
            if pattern.is_empty() {
                pattern = vec![0, 1];
            }
            let outputs = s.output_count();
            let mut lost = 0_usize;
            for out in 0..outputs {
                let picks = (0..list.len()).map(|k| {
                    let p = pattern[k % pattern.len()];
                    (usize::try_from(p).ok() == Some(out)).then_some(k)
                });
                s.set_branch(out, list.gather(picks));
            }
            for k in 0..list.len() {
                let p = pattern[k % pattern.len()];
                if usize::try_from(p).map_or(true, |p| p >= outputs) {
                    lost += 1;
                }
            }
            if lost > 0 {
                s.warning(format!(
                    "{lost} items have a pattern index that names no output (there are \
                     {outputs}) and were sent nowhere"
                ));
            }
            Ok(())
        })
}

/// The pairing rules of Cross Reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum CrossMode {
    Holistic,
    Diagonal,
    Coincident,
    LowerTriangle,
    LowerTriangleStrict,
    UpperTriangle,
    UpperTriangleStrict,
}

impl CrossMode {
    const NAMES: [(&'static str, CrossMode); 7] = [
        ("holistic", CrossMode::Holistic),
        ("diagonal", CrossMode::Diagonal),
        ("coincident", CrossMode::Coincident),
        ("lower_triangle", CrossMode::LowerTriangle),
        ("lower_triangle_strict", CrossMode::LowerTriangleStrict),
        ("upper_triangle", CrossMode::UpperTriangle),
        ("upper_triangle_strict", CrossMode::UpperTriangleStrict),
    ];

    fn parse(name: &str) -> Result<Self, NodeError> {
        Self::NAMES
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name.trim()))
            .map(|(_, m)| *m)
            .ok_or_else(|| {
                let names: Vec<&str> = Self::NAMES.iter().map(|(n, _)| *n).collect();
                NodeError(format!(
                    "unknown mode {name:?}: use one of {}",
                    names.join(", ")
                ))
            })
    }

    /// Whether item `i` of A is combined with item `j` of B.
    fn keeps(self, i: usize, j: usize) -> bool {
        match self {
            CrossMode::Holistic => true,
            CrossMode::Diagonal => i != j,
            CrossMode::Coincident => i == j,
            CrossMode::LowerTriangle => i >= j,
            CrossMode::LowerTriangleStrict => i > j,
            CrossMode::UpperTriangle => i <= j,
            CrossMode::UpperTriangleStrict => i < j,
        }
    }
}

/// Cross Reference \[CrossRef\]: the items of two lists combined pair by pair.
pub fn cross_reference() -> NodeType {
    list_node(CROSS_REFERENCE, "Cross Reference", "CrossRef")
        .gh_guid("36947590-f0cb-4807-a8f9-9c90c9b20621")
        .description(
            "Combines the items of lists A and B into pairs and lists each pair's items on the \
             outputs A and B. The pairs are every combination of item i of A and item j of B \
             that the mode keeps, with A varying fastest (as the runtime's cross-reference \
             matching does): holistic (every pair), diagonal (i ≠ j), coincident (i = j), \
             lower_triangle (i ≥ j), lower_triangle_strict (i > j), upper_triangle (i ≤ j), \
             upper_triangle_strict (i < j). The node has Grasshopper's default two inputs. \
             More than ten million pairs is an error.",
        )
        .input(generic_list("List A", "A", "The first list, of any type; optional.").optional())
        .input(generic_list("List B", "B", "The second list, of any type; optional.").optional())
        .output(generic_list("List A", "A", "Item i of A for each pair."))
        .output(generic_list("List B", "B", "Item j of B for each pair."))
        .setting(
            "mode",
            DataType::Text,
            Some(Value::Text("holistic".into())),
            "Which pairs to make: holistic, diagonal, coincident, lower_triangle, \
             lower_triangle_strict, upper_triangle or upper_triangle_strict; default holistic.",
        )
        .solve(|s| {
            let mode = match s.setting("mode") {
                Some(Value::Text(t)) => CrossMode::parse(t)?,
                _ => CrossMode::Holistic,
            };
            let a = branch_of(s, 0);
            let b = branch_of(s, 1);
            if a.len().saturating_mul(b.len()) > MAX_SEQUENCE_LENGTH {
                return Err(NodeError(format!(
                    "{} × {} pairs are more than {MAX_SEQUENCE_LENGTH}",
                    a.len(),
                    b.len()
                )));
            }
            let mut ia = Vec::new();
            let mut ib = Vec::new();
            for j in 0..b.len() {
                for i in 0..a.len() {
                    if mode.keeps(i, j) {
                        ia.push(Some(i));
                        ib.push(Some(j));
                    }
                }
            }
            s.set_branch(0, a.gather(ia));
            s.set_branch(1, b.gather(ib));
            Ok(())
        })
}

/// Why a value is invalid, if it is.
pub(crate) fn invalid_reason(v: &Value) -> Option<String> {
    let bad = |what: &str| Some(what.to_owned());
    match v {
        Value::Number(x) if !x.is_finite() => bad(&format!("the number {x} is not finite")),
        Value::Point(p) if !p.is_finite() => bad("the point has a coordinate that is not finite"),
        Value::Vector(x) if !x.is_finite() => bad("the vector has a component that is not finite"),
        Value::Domain(d) if !(d.t0.is_finite() && d.t1.is_finite()) => {
            bad("the domain has an end that is not finite")
        }
        Value::Plane(p) if !p.is_valid() => bad("the plane is not valid"),
        Value::Line(l) if !(l.from.is_finite() && l.to.is_finite()) || l.length() == 0.0 => {
            bad("the line has no length or is not finite")
        }
        Value::Circle(c) if !(c.radius.is_finite() && c.radius > 0.0) => {
            bad("the circle has no positive radius")
        }
        Value::Arc(a)
            if !(a.circle.radius.is_finite()
                && a.circle.radius > 0.0
                && a.angle.length().is_finite()
                && a.angle.length() != 0.0) =>
        {
            bad("the arc has no positive radius or no angle")
        }
        Value::Brep(b) if b.faces().is_empty() => bad("the B-rep has no faces"),
        _ => None,
    }
}

/// Null Item \[Null\]: whether an item is null or invalid.
pub fn null_item() -> NodeType {
    list_node(NULL_ITEM, "Null Item", "Null")
        .gh_guid("c74efd0e-7fe3-4c2d-8c9d-295c5672fb13")
        .description(
            "Tests items for null and invalid values. Invalid means: a number that is NaN or \
             infinite, a point or vector with such a coordinate, a domain with such an end, a \
             plane that is not valid, a line of zero length, a circle or arc without a \
             positive radius (or an arc without angle), a B-rep without faces. Description \
             says which, or names the type of a valid item.",
        )
        .input(
            Port::new("Item", "I", DataType::Generic)
                .optional()
                .doc("The item to test, of any type."),
        )
        .output(Port::new("Null Flags", "N", DataType::Boolean).doc("True for a null item."))
        .output(
            Port::new("Invalid Flags", "X", DataType::Boolean)
                .doc("True for an invalid item (never for a null)."),
        )
        .output(Port::new("Description", "D", DataType::Text).doc("What the item is."))
        .solve(|s| {
            match s.value(0) {
                None => {
                    s.set(0, true);
                    s.set(1, false);
                    s.set(2, "Null".to_owned());
                }
                Some(v) => {
                    let why = invalid_reason(&v);
                    s.set(0, false);
                    s.set(1, why.is_some());
                    s.set(
                        2,
                        match why {
                            Some(why) => format!("Invalid: {why}"),
                            None => format!("Valid {}", v.data_type().name()),
                        },
                    );
                }
            }
            Ok(())
        })
}

#[cfg(test)]
mod tests;
