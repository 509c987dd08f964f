//! Writing new expectations into a graph file in place (`locus test --bless`).
//!
//! Only what changed is rewritten: an expected value that still agrees with the output is left
//! exactly as written; one that differs is edited item by item and number by number, so that
//! the numbers that did not change keep their spelling (`1` stays `1`, `0.50` stays `0.50`).
//! Comments anywhere in the file survive, including those inside an edited value (they are
//! put back before the new text). New outputs and new expected messages are appended after the
//! last entry; expected values of outputs the graph no longer names are removed. A file with
//! `\r\n` line endings keeps them.

use std::ops::Range;

use crate::file::canonical::comments;
use crate::file::expected::{ExpectedTree, expectation_node};
use crate::file::format::{Document, expected_messages_node};
use crate::file::literal::LiteralError;
use crate::file::syntax::{self, Kind, Node};
use crate::{
    COMPARE_TOLERANCE, DataTree, DataType, ExpectedMessage, compare_expected, parse_number,
};

/// One named output's current data, for [`Document::bless`].
#[derive(Clone, Copy, Debug)]
pub struct BlessOutput<'a> {
    /// The output's name.
    pub name: &'a str,
    /// The type of the output's port.
    pub data_type: DataType,
    /// The data it produced.
    pub tree: &'a DataTree,
}

/// A replacement of a byte range of the source.
struct Edit {
    span: Range<usize>,
    text: String,
}

impl Document {
    /// The source text with its expectations brought up to date: the expected values of
    /// `outputs` (in place, see the module docs) and `messages` appended to
    /// `expected_messages`. Everything else is kept byte for byte.
    ///
    /// # Errors
    /// A [`LiteralError`] naming the output whose data has no expectation form.
    pub fn bless(
        &self,
        outputs: &[BlessOutput<'_>],
        messages: &[ExpectedMessage],
    ) -> Result<String, LiteralError> {
        let src = self.source();
        let graph = self.graph();
        let mut edits = Vec::new();
        let mut appended = Vec::new();
        for output in outputs {
            let new = expectation_node(output.tree).map_err(|e| LiteralError {
                message: format!("output {}: {}", output.name, e.message),
                span: e.span,
            })?;
            let existing = graph.expected.iter().position(|(n, _)| n == output.name);
            let Some(e) = existing else {
                appended.push(format!(
                    "{}: {}",
                    syntax::quote(output.name),
                    new.to_compact()
                ));
                continue;
            };
            let span = self.map.expected[e][1].clone();
            let old_text = &src[span.clone()];
            if let Ok(want) = ExpectedTree::parse(&graph.expected[e].1, output.data_type)
                && compare_expected(output.tree, &want, COMPARE_TOLERANCE, 1).is_empty()
            {
                continue;
            }
            match syntax::parse(old_text) {
                Ok(old) => merge(src, span.start, &old, &new, &mut edits),
                Err(_) => edits.push(replacement(src, span, new.to_compact())),
            }
        }
        // Expected values of outputs that are gone.
        for (e, (name, _)) in graph.expected.iter().enumerate() {
            if !outputs.iter().any(|o| o.name == name) {
                let [key, value] = &self.map.expected[e];
                edits.push(Edit {
                    span: removal(src, key.start..value.end),
                    text: String::new(),
                });
            }
        }
        let new_messages: Vec<String> = messages
            .iter()
            .map(|m| {
                let Kind::List(items) = expected_messages_node(std::slice::from_ref(m)).kind else {
                    unreachable!("a list of messages")
                };
                items[0].to_compact()
            })
            .collect();
        let mut fields = Vec::new();
        match (&self.map.expected_value, appended.is_empty()) {
            (_, true) => {}
            (Some(span), false) => edits.push(append(src, span.clone(), &appended)),
            (None, false) => fields.push(("expected", "{", "}", appended)),
        }
        match (&self.map.expected_messages_value, new_messages.is_empty()) {
            (_, true) => {}
            (Some(span), false) => edits.push(append(src, span.clone(), &new_messages)),
            (None, false) => fields.push(("expected_messages", "[", "]", new_messages)),
        }
        if !fields.is_empty() {
            edits.push(new_fields(src, self.map.graph_end.min(src.len()), &fields));
        }
        Ok(apply(src, edits))
    }
}

/// Edits that turn `old` (written at `base` in `src`) into `new`, keeping every part of `old`
/// that already agrees.
fn merge(src: &str, base: usize, old: &Node, new: &Node, edits: &mut Vec<Edit>) {
    let span = base + old.span.start..base + old.span.end;
    let same_shape = match (&old.kind, &new.kind) {
        (Kind::Number(a), Kind::Number(b)) => {
            if !numbers_agree(a, b) {
                edits.push(replacement(src, span, b.clone()));
            }
            return;
        }
        (Kind::Tuple(ta, a), Kind::Tuple(tb, b)) if ta == tb && a.len() == b.len() => {
            a.iter()
                .zip(b)
                .for_each(|(x, y)| merge(src, base, x, y, edits));
            true
        }
        (Kind::List(a), Kind::List(b)) if a.len() == b.len() => {
            a.iter()
                .zip(b)
                .for_each(|(x, y)| merge(src, base, x, y, edits));
            true
        }
        (Kind::Struct(ta, a), Kind::Struct(tb, b))
            if ta == tb && a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.name == y.name) =>
        {
            a.iter()
                .zip(b)
                .for_each(|(x, y)| merge(src, base, &x.value, &y.value, edits));
            true
        }
        (Kind::Map(a), Kind::Map(b))
            if a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.0.kind == y.0.kind) =>
        {
            a.iter()
                .zip(b)
                .for_each(|(x, y)| merge(src, base, &x.1, &y.1, edits));
            true
        }
        (a, b) => a == b,
    };
    if !same_shape {
        edits.push(replacement(src, span, new.to_compact()));
    }
}

/// Whether two written numbers are the same value within [`COMPARE_TOLERANCE`].
fn numbers_agree(a: &str, b: &str) -> bool {
    if a == b {
        return true;
    }
    match (parse_number(a), parse_number(b)) {
        (Some(x), Some(y)) => {
            x == y
                || (x.is_nan() && y.is_nan())
                || (x - y).abs() <= COMPARE_TOLERANCE * 1f64.max(x.abs()).max(y.abs())
        }
        _ => false,
    }
}

/// Replaces `span` by `text`, putting back the comments written inside `span` before it.
fn replacement(src: &str, span: Range<usize>, text: String) -> Edit {
    let comments = comments(&src[span.clone()]);
    if comments.is_empty() {
        return Edit { span, text };
    }
    let indent = line_indent(src, span.start);
    let mut out = String::new();
    for c in comments {
        out.push_str(c);
        if c.starts_with("//") {
            out.push('\n');
            out.push_str(indent);
        } else {
            out.push(' ');
        }
    }
    out.push_str(&text);
    Edit { span, text: out }
}

/// The whitespace that starts the line holding `offset`.
fn line_indent(src: &str, offset: usize) -> &str {
    let start = src[..offset].rfind('\n').map_or(0, |i| i + 1);
    let line = &src[start..];
    &line[..line.len() - line.trim_start_matches([' ', '\t']).len()]
}

/// The span to delete to remove an entry: the entry, its comma, and its line when nothing else
/// is left on it.
fn removal(src: &str, entry: Range<usize>) -> Range<usize> {
    let mut end = entry.end;
    let rest = &src[end..];
    let trimmed = rest.trim_start_matches([' ', '\t']);
    if trimmed.starts_with(',') {
        end += rest.len() - trimmed.len() + 1;
    }
    let line_start = src[..entry.start].rfind('\n').map_or(0, |i| i + 1);
    let before_blank = src[line_start..entry.start].trim().is_empty();
    let rest = &src[end..];
    let line_end = rest.find('\n').map_or(rest.len(), |i| i + 1);
    if before_blank && rest[..line_end].trim().is_empty() {
        return line_start..end + line_end;
    }
    entry.start..end
}

/// Appends entries to the map or list written at `container` (`{…}` or `[…]`), one per line
/// after the last entry, with its indentation.
fn append(src: &str, container: Range<usize>, entries: &[String]) -> Edit {
    let close = container.end - 1;
    let inner = &src[container.start + 1..close];
    let indent = line_indent(src, container.start);
    if inner.trim().is_empty() {
        // An empty container: write it out anew, one entry per line.
        let mut text = String::from(&src[container.start..=container.start]);
        for e in entries {
            text.push_str(&format!("\n{indent}    {e},"));
        }
        text.push('\n');
        text.push_str(indent);
        text.push_str(&src[close..container.end]);
        return Edit {
            span: container,
            text,
        };
    }
    // After the last thing written inside (an entry or a comment), with a comma if the last
    // entry has none.
    let content_end = container.start + 1 + inner.trim_end().len();
    let before = &src[container.start + 1..content_end];
    let needs_comma = !ends_with_comma(before);
    let entry_indent = format!("{indent}    ");
    let mut text = String::new();
    if needs_comma {
        text.push(',');
    }
    for e in entries {
        text.push_str(&format!("\n{entry_indent}{e},"));
    }
    Edit {
        span: content_end..content_end,
        text,
    }
}

/// Whether the last token of RON text (comments aside) is a comma.
fn ends_with_comma(text: &str) -> bool {
    let mut stripped = text.to_owned();
    for c in comments(text) {
        stripped = stripped.replacen(c, "", 1);
    }
    stripped.trim_end().ends_with(',')
}

/// Adds graph fields (`expected`, `expected_messages`) before the `)` that closes the graph.
fn new_fields(src: &str, graph_end: usize, fields: &[(&str, &str, &str, Vec<String>)]) -> Edit {
    let content_end = src[..graph_end].trim_end().len();
    let mut text = String::new();
    if !ends_with_comma(&src[..content_end]) && !src[..content_end].ends_with('(') {
        text.push(',');
    }
    for (name, open, close, entries) in fields {
        text.push_str(&format!("\n    {name}: {open}"));
        for e in entries {
            text.push_str(&format!("\n        {e},"));
        }
        text.push_str(&format!("\n    {close},"));
    }
    Edit {
        span: content_end..content_end,
        text,
    }
}

/// Applies non-overlapping edits, converting the new text's line endings to the file's.
fn apply(src: &str, mut edits: Vec<Edit>) -> String {
    let crlf = src.contains("\r\n");
    edits.sort_by_key(|e| (e.span.start, e.span.end));
    let mut out = String::with_capacity(src.len());
    let mut at = 0;
    for e in edits {
        if e.span.start < at {
            continue; // overlaps an earlier edit (cannot happen for disjoint entries)
        }
        out.push_str(&src[at..e.span.start]);
        if crlf {
            out.push_str(&e.text.replace("\r\n", "\n").replace('\n', "\r\n"));
        } else {
            out.push_str(&e.text);
        }
        at = e.span.end;
    }
    out.push_str(&src[at..]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Level, NodeId};

    const GRAPH: &str = r#"// head
(
    format: 1,
    nodes: [(id: "n", type: "params.number", values: {"Num": [1, 2.50, 3]})],
    outputs: {"a": "n.Num", "b": "n.Num"},
    expected: {
        // the first
        "a": [1, 2.50, /* inline */ 3],
        "b": [1, 2.50, 3], // trailing
    },
)
"#;

    fn bless(src: &str, trees: &[(&str, DataTree)], messages: &[ExpectedMessage]) -> String {
        let doc = Document::parse(src).expect("reads");
        let outputs: Vec<BlessOutput> = trees
            .iter()
            .map(|(name, tree)| BlessOutput {
                name,
                data_type: DataType::Number,
                tree,
            })
            .collect();
        doc.bless(&outputs, messages).expect("blesses")
    }

    #[test]
    fn agreeing_values_are_left_as_written() {
        let t = DataTree::from_list(vec![1.0, 2.5, 3.0]);
        assert_eq!(bless(GRAPH, &[("a", t.clone()), ("b", t)], &[]), GRAPH);
    }

    #[test]
    fn only_changed_numbers_are_rewritten_and_comments_stay() {
        let t = DataTree::from_list(vec![1.0, 2.5, 4.0]);
        let out = bless(GRAPH, &[("a", t.clone()), ("b", t)], &[]);
        let want = GRAPH
            .replace("/* inline */ 3]", "/* inline */ 4.0]")
            .replace("\"b\": [1, 2.50, 3]", "\"b\": [1, 2.50, 4.0]");
        assert_eq!(out, want);
    }

    #[test]
    fn a_changed_shape_keeps_the_comments_inside() {
        let t = DataTree::from_list(vec![1.0, 2.5]);
        let u = DataTree::from_list(vec![1.0, 2.5, 3.0]);
        let out = bless(GRAPH, &[("a", t), ("b", u)], &[]);
        assert!(out.contains("\"a\": /* inline */ [1.0, 2.5],"), "{out}");
        assert!(out.contains("// the first"), "{out}");
    }

    #[test]
    fn new_outputs_and_messages_are_appended_and_old_ones_removed() {
        let t = DataTree::from_list(vec![1.0, 2.5, 3.0]);
        let m = ExpectedMessage {
            node: NodeId::from("n"),
            level: Level::Error,
            text: "boom".to_owned(),
        };
        let out = bless(GRAPH, &[("a", t.clone()), ("c", t)], &[m]);
        assert!(!out.contains("\"b\": ["), "{out}");
        assert!(out.contains("// trailing"), "{out}");
        assert!(
            out.contains("        \"c\": [1.0, 2.5, 3.0],\n    },"),
            "{out}"
        );
        assert!(
            out.ends_with(
                "    expected_messages: [\n        (node: \"n\", level: error, text: \"boom\"),\n    ],\n)\n"
            ),
            "{out}"
        );
        assert!(Document::parse(&out).is_ok(), "{out}");
    }

    #[test]
    fn crlf_files_stay_crlf_and_new_sections_are_added() {
        let src = "(\r\n    format: 1,\r\n    nodes: [(id: \"n\", type: \"params.number\")],\r\n    outputs: {\"a\": \"n.Num\"}\r\n)\r\n";
        let t = DataTree::from_list(vec![1.0]);
        let out = bless(src, &[("a", t)], &[]);
        assert!(!out.replace("\r\n", "").contains('\n'), "{out:?}");
        assert!(
            out.contains(
                "\"n.Num\"},\r\n    expected: {\r\n        \"a\": 1.0,\r\n    },\r\n)\r\n"
            ),
            "{out:?}"
        );
        assert!(Document::parse(&out).is_ok());
    }
}
