//! Printing data trees and messages as text (Grasshopper notation) and as JSON.
//!
//! The JSON shapes are documented in `docs/json-output.md`.

use std::fmt::Write as _;

use locus_runtime::{DataTree, Message, MessageJson, Value, format_value};
use serde_json::Value as Json;

/// One item as text, the way Grasshopper's panel shows it.
pub fn value_text(value: &Value) -> String {
    format_value(value)
}

/// A tree as text, one line at a time (each ending in a newline) through `emit`, built in
/// `line`: each branch as its path and item count, then its items one per line. Stops early,
/// returning `false`, when `emit` returns `false`.
pub fn tree_lines(
    tree: &DataTree,
    line: &mut String,
    emit: &mut impl FnMut(&str) -> std::io::Result<bool>,
) -> std::io::Result<bool> {
    if tree.is_empty() {
        return emit("  (empty tree)\n");
    }
    for (path, branch) in tree.branches() {
        let n = branch.len();
        line.clear();
        let _ = writeln!(line, "  {path} ({n} item{})", if n == 1 { "" } else { "s" });
        if !emit(line)? {
            return Ok(false);
        }
        for (i, v) in branch.values().enumerate() {
            line.clear();
            match v {
                Some(v) => {
                    let _ = writeln!(line, "    {i}. {}", value_text(&v));
                }
                None => {
                    let _ = writeln!(line, "    {i}. <null>");
                }
            }
            if !emit(line)? {
                return Ok(false);
            }
        }
    }
    Ok(true)
}

/// A runtime message as JSON (`locus_runtime::MessageJson`).
pub fn message_json(m: &Message) -> Json {
    serde_json::to_value(MessageJson(m)).unwrap_or(Json::Null)
}

/// Text from a graph made safe for a terminal: control characters other than newline and tab
/// (ANSI escape sequences start with one) and the bidirectional overrides and isolates that
/// reorder what is displayed (U+202A–U+202E, U+2066–U+2069) are written as `\u{…}` escapes.
pub fn terminal_safe(text: &str) -> std::borrow::Cow<'_, str> {
    let unsafe_char = |c: char| {
        (c.is_control() && c != '\n' && c != '\t')
            || ('\u{202a}'..='\u{202e}').contains(&c)
            || ('\u{2066}'..='\u{2069}').contains(&c)
    };
    if !text.chars().any(unsafe_char) {
        return std::borrow::Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if unsafe_char(c) {
            let _ = write!(out, "\\u{{{:x}}}", c as u32);
        } else {
            out.push(c);
        }
    }
    std::borrow::Cow::Owned(out)
}

/// `text` made safe with [`terminal_safe`] when `stream` is a terminal, else as it is.
pub fn for_stream<'a>(
    text: &'a str,
    stream: &impl std::io::IsTerminal,
) -> std::borrow::Cow<'a, str> {
    if stream.is_terminal() {
        terminal_safe(text)
    } else {
        std::borrow::Cow::Borrowed(text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_runtime::{TreeJson, ValueJson};

    #[test]
    fn trees_render_as_json_objects_by_path() {
        let t = DataTree::from_list(vec![locus_kernel::Point3::new(1.0, 2.0, 3.0)]);
        assert_eq!(
            serde_json::to_string(&TreeJson(&t)).unwrap(),
            r#"{"{0}":[{"point":[1.0,2.0,3.0]}]}"#
        );
    }

    #[test]
    fn negative_zero_is_written_as_zero() {
        assert_eq!(
            serde_json::to_string(&ValueJson(&Value::Number(-0.0))).unwrap(),
            "0.0"
        );
    }

    #[test]
    fn terminal_safe_escapes_ansi_and_bidi_controls() {
        assert_eq!(terminal_safe("plain\ttext\n"), "plain\ttext\n");
        assert_eq!(terminal_safe("a\u{1b}[31mred"), "a\\u{1b}[31mred");
        assert_eq!(
            terminal_safe("x\u{202e}y\u{2066}z"),
            "x\\u{202e}y\\u{2066}z"
        );
        assert_eq!(terminal_safe("bell\u{7}"), "bell\\u{7}");
    }
}
