//! The canonical form of a graph file, as `locus fmt` writes it: [`Graph::to_ron`](crate::Graph::to_ron)'s
//! layout, with the file's leading comments (its header) kept and its line endings kept.
//!
//! Comments inside the graph have no place in the graph document, so a file that has them is
//! not rewritten: [`Document::canonical`] says where the first one is instead, and the user
//! decides (move it into the header or the description).

use crate::file::format::Document;

/// Why a document was not put in canonical form.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CommentInside {
    /// The 1-based line of the first comment inside the graph.
    pub line: usize,
    /// Its 1-based column.
    pub column: usize,
}

impl std::fmt::Display for CommentInside {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{}: a comment inside the graph would be lost (only the comments before it are kept)",
            self.line, self.column
        )
    }
}

impl Document {
    /// The document in canonical layout: the comments before the graph, then
    /// [`Graph::to_ron`](crate::Graph::to_ron), with the file's line endings (`\r\n` when the
    /// file uses them). A canonical file gives back the same bytes.
    ///
    /// # Errors
    /// [`CommentInside`] when a comment inside the graph would be lost.
    pub fn canonical(&self) -> Result<String, CommentInside> {
        let src = self.source();
        let start = graph_start(src);
        if let Some(first) = comments(&src[start..]).first() {
            // `comments` returns slices of its input: find the offset of the first one.
            let offset = start + (first.as_ptr() as usize - src[start..].as_ptr() as usize);
            let l = self.location(offset);
            return Err(CommentInside {
                line: l.line,
                column: l.column,
            });
        }
        let header = src[..start].trim_end();
        let mut out = String::new();
        if !header.is_empty() {
            out.push_str(&header.replace("\r\n", "\n"));
            out.push('\n');
        }
        out.push_str(&self.graph().to_ron());
        if src.contains("\r\n") {
            out = out.replace('\n', "\r\n");
        }
        Ok(out)
    }
}

/// The offset where the graph's value begins: after leading whitespace and comments.
fn graph_start(src: &str) -> usize {
    let mut at = 0;
    loop {
        let rest = &src[at..];
        let trimmed = rest.trim_start();
        at += rest.len() - trimmed.len();
        if trimmed.starts_with("//") {
            at += trimmed.find('\n').map_or(trimmed.len(), |i| i + 1);
        } else if trimmed.starts_with("/*") {
            let c = comments(trimmed);
            at += c.first().map_or(trimmed.len(), |c| c.len());
        } else {
            return at;
        }
    }
}

/// The comments in RON text, in order (line comments without their newline).
pub(crate) fn comments(text: &str) -> Vec<&str> {
    let bytes = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'"' => {
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                i += 1;
            }
            b'r' if matches!(bytes.get(i + 1), Some(b'#' | b'"'))
                && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_')) =>
            {
                let hashes = bytes[i + 1..].iter().take_while(|&&b| b == b'#').count();
                let close = format!("\"{}", "#".repeat(hashes));
                let open = i + 1 + hashes + 1;
                i = text
                    .get(open..)
                    .and_then(|rest| rest.find(&close))
                    .map_or(bytes.len(), |at| open + at + close.len());
            }
            b'/' if bytes.get(i + 1) == Some(&b'/') => {
                let end = text[i..].find('\n').map_or(bytes.len(), |at| i + at);
                out.push(text[i..end].trim_end_matches('\r'));
                i = end;
            }
            b'/' if bytes.get(i + 1) == Some(&b'*') => {
                let start = i;
                let mut depth = 0usize;
                while i < bytes.len() {
                    if bytes[i..].starts_with(b"/*") {
                        depth += 1;
                        i += 2;
                    } else if bytes[i..].starts_with(b"*/") {
                        depth -= 1;
                        i += 2;
                        if depth == 0 {
                            break;
                        }
                    } else {
                        i += 1;
                    }
                }
                out.push(&text[start..i.min(bytes.len())]);
            }
            _ => i += 1,
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_header_is_kept_and_the_rest_is_canonical() {
        let src = "// A graph.\n/* more */\n(format: 1, nodes: [(id: \"n\", type: \"params.number\",values:{\"Num\":1})],)";
        let doc = Document::parse(src).expect("reads");
        let out = doc.canonical().expect("canonical");
        assert_eq!(
            out,
            "// A graph.\n/* more */\n(\n    format: 1,\n    nodes: [\n        (id: \"n\", type: \"params.number\", values: {\"Num\": 1}),\n    ],\n)\n"
        );
        let again = Document::parse(&out)
            .expect("reads")
            .canonical()
            .expect("canonical");
        assert_eq!(again, out);
    }

    #[test]
    fn comments_inside_are_refused_with_their_place() {
        let src = "(\n    format: 1, // the version\n)\n";
        let e = Document::parse(src)
            .expect("reads")
            .canonical()
            .unwrap_err();
        assert_eq!((e.line, e.column), (2, 16));
    }

    #[test]
    fn crlf_files_stay_crlf() {
        let src = "// h\r\n(format: 1)\r\n";
        let out = Document::parse(src)
            .expect("reads")
            .canonical()
            .expect("canonical");
        assert_eq!(out, "// h\r\n(\r\n    format: 1,\r\n)\r\n");
    }

    #[test]
    fn comments_are_found_outside_strings_only() {
        let text = r##"["a // b", r#"/* x */"#, /* c /* d */ */ 1 // e
        ]"##;
        assert_eq!(comments(text), ["/* c /* d */ */", "// e"]);
    }
}
