//! The RON graph of an import, with the Grasshopper objects as comments.

use crate::import::Import;

/// The canonical RON text of the imported graph, with a comment above each node naming the
/// Grasshopper object it comes from, and a header comment with the import summary.
pub fn to_ron(import: &Import) -> String {
    let text = locus_runtime::write_graph(&import.graph);
    let mut out = String::with_capacity(text.len() + import.notes.len() * 40);
    out.push_str("// Imported from a Grasshopper definition by `locus import`.\n");
    for line in import.report.summary().lines() {
        if line.starts_with("error") || line.starts_with("warning") || line.starts_with("remark") {
            continue;
        }
        out.push_str("// ");
        out.push_str(line);
        out.push('\n');
    }
    let lines: Vec<&str> = text.lines().collect();
    // The nodes whose lines enclose the current one: (indent, id).
    let mut open: Vec<(usize, String)> = Vec::new();
    for (k, line) in lines.iter().enumerate() {
        let trimmed = line.trim_start();
        let id = if let Some(rest) = trimmed.strip_prefix("(id: \"") {
            rest.split('"').next()
        } else if trimmed == "("
            && let Some(next) = lines.get(k + 1)
            && let Some(rest) = next.trim_start().strip_prefix("id: \"")
        {
            rest.split('"').next()
        } else {
            None
        };
        let indent = &line[..line.len() - trimmed.len()];
        // A node inside a sub-graph is indented deeper than its sub-graph node: its note is
        // under the path of the sub-graph nodes it is in (`part/x`).
        let path = id.map(|id| {
            while open.last().is_some_and(|(i, _)| *i >= indent.len()) {
                open.pop();
            }
            open.push((indent.len(), id.to_owned()));
            open.iter()
                .map(|(_, id)| id.as_str())
                .collect::<Vec<_>>()
                .join("/")
        });
        if let Some(path) = path
            && let Some((_, note)) = import.notes.iter().find(|(n, _)| n.0 == path)
        {
            out.push_str(indent);
            out.push_str("// ");
            out.push_str(&note.replace('\n', " "));
            out.push('\n');
        }
        out.push_str(line);
        out.push('\n');
    }
    out
}
