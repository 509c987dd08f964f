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
        if let Some(id) = id
            && let Some((_, note)) = import.notes.iter().find(|(n, _)| n.0 == id)
        {
            let indent = &line[..line.len() - trimmed.len()];
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
