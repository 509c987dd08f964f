//! Writing `locus run`'s outputs as they are read: JSON through serde_json's serializer straight
//! into a buffered writer (one small JSON value per item at a time, never the whole document)
//! and text line by line, so that the memory used for printing does not grow with the output.
//!
//! The JSON document is the one of `docs/json-output.md`, its trees and messages in the
//! runtime's one JSON form (`locus_runtime::TreeJson`, `MessageJson`); `--max-output-bytes` counts each
//! output's compact JSON size (measured by serializing it into a byte counter first) or, for
//! text, the bytes of the lines written.

use std::io::{self, Write};

use locus_runtime::{DataTree, Message, MessageJson, TreeJson};
use serde::ser::{Serialize, SerializeMap, SerializeSeq, Serializer};

use crate::render;

/// The named outputs that fit the byte budget, in order.
struct OutputsJson<'a>(&'a [(&'a str, &'a DataTree)]);

impl Serialize for OutputsJson<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (name, tree) in self.0 {
            map.serialize_entry(name, &TreeJson(tree))?;
        }
        map.end()
    }
}

/// The messages as a JSON array.
struct MessagesJson<'a>(&'a [&'a Message]);

impl Serialize for MessagesJson<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.0.len()))?;
        for m in self.0 {
            seq.serialize_element(&MessageJson(m))?;
        }
        seq.end()
    }
}

/// Counts the bytes written to it.
#[derive(Default)]
struct Counter(u64);

impl Write for Counter {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        self.0 += buf.len() as u64;
        Ok(buf.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

/// The size of a tree's compact JSON, without keeping it.
pub(crate) fn compact_size(tree: &DataTree) -> u64 {
    let mut counter = Counter::default();
    let _ = serde_json::to_writer(&mut counter, &TreeJson(tree));
    counter.0
}

/// Writes the JSON document of a run (pretty-printed, then a newline): the outputs that fit
/// `max_bytes` of compact JSON in order, the messages, and what was left out. Returns whether
/// outputs were left out.
pub(crate) fn write_json(
    out: &mut impl Write,
    outputs: &[(&str, &DataTree)],
    messages: &[&Message],
    max_bytes: u64,
) -> io::Result<bool> {
    let mut written: u64 = 0;
    let mut kept = Vec::new();
    let mut omitted = Vec::new();
    for &(name, tree) in outputs {
        let size = compact_size(tree);
        if !omitted.is_empty() || written.saturating_add(size) > max_bytes {
            omitted.push(name);
            continue;
        }
        written += size;
        kept.push((name, tree));
    }
    let truncated = !omitted.is_empty();
    let document = Document {
        outputs: OutputsJson(&kept),
        messages: MessagesJson(messages),
        truncated: truncated
            .then(|| serde_json::json!({ "max_output_bytes": max_bytes, "omitted": omitted })),
    };
    serde_json::to_writer_pretty(&mut *out, &document).map_err(io::Error::other)?;
    writeln!(out)?;
    Ok(truncated)
}

/// The whole JSON document, serialized as it is written.
struct Document<'a> {
    outputs: OutputsJson<'a>,
    messages: MessagesJson<'a>,
    truncated: Option<serde_json::Value>,
}

impl Serialize for Document<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let len = if self.truncated.is_some() { 3 } else { 2 };
        let mut map = serializer.serialize_map(Some(len))?;
        map.serialize_entry("outputs", &self.outputs)?;
        map.serialize_entry("messages", &self.messages)?;
        if let Some(t) = &self.truncated {
            map.serialize_entry("truncated", t)?;
        }
        map.end()
    }
}

/// Writes the outputs as text (`name:` then the tree, see [`render::tree_lines`]) line by line,
/// stopping at the last whole line within `max_bytes`; `safe` makes each line safe for a
/// terminal. Returns whether the output was cut.
pub(crate) fn write_text(
    out: &mut impl Write,
    outputs: &[(&str, &DataTree)],
    max_bytes: u64,
    safe: bool,
) -> io::Result<bool> {
    let mut written: u64 = 0;
    let mut line = String::new();
    for &(name, tree) in outputs {
        let mut emit = |line: &str| -> io::Result<bool> {
            if written.saturating_add(line.len() as u64) > max_bytes {
                return Ok(false);
            }
            written += line.len() as u64;
            if safe {
                out.write_all(render::terminal_safe(line).as_bytes())?;
            } else {
                out.write_all(line.as_bytes())?;
            }
            Ok(true)
        };
        line.clear();
        line.push_str(name);
        line.push_str(":\n");
        if !emit(&line)? || !render::tree_lines(tree, &mut line, &mut emit)? {
            return Ok(true);
        }
    }
    Ok(false)
}
