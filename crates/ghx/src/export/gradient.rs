//! The Gradient component's `Gradient` chunk, written from the node's `grips` and `linear`
//! settings (the reverse of `import/gradient.rs`).

use locus_runtime::{DataType, GraphNode, Value, cast_value, parse_literal};

use super::{ExportWarning, Out, items_and_chunks, num};

/// One grip: factor, left and right colours as alpha, red, green, blue.
type Grip = (f64, [u8; 4], [u8; 4]);

fn setting(node: &GraphNode, name: &str, data_type: DataType) -> Option<Value> {
    let (_, lit) = node.settings.iter().find(|(k, _)| k == name)?;
    let tree = parse_literal(&lit.0, data_type).ok()?;
    tree.values().next().flatten()
}

fn argb(text: &str) -> Option<[u8; 4]> {
    match cast_value(&Value::Text(text.trim().to_owned()), DataType::Colour) {
        Ok(Value::Colour(c)) => Some([c.a, c.r, c.g, c.b]),
        _ => None,
    }
}

/// The grips of the `grips` text (`FACTOR COLOUR` or `FACTOR LEFT/RIGHT`, separated by `;`).
fn grips(text: &str) -> Option<Vec<Grip>> {
    text.split(';')
        .map(str::trim)
        .filter(|g| !g.is_empty())
        .map(|g| {
            let (factor, colours) = g.split_once(char::is_whitespace)?;
            let factor: f64 = factor.parse().ok()?;
            let (left, right) = colours.split_once('/').unwrap_or((colours, colours));
            Some((factor, argb(left)?, argb(right)?))
        })
        .collect()
}

fn colour(o: &mut Out, index: usize, [a, r, g, b]: [u8; 4]) {
    o.item_start("Colour", Some(index), 36);
    o.text_element("ARGB", &format!("{a};{r};{g};{b}"));
    o.end("item");
}

/// Writes the gradient of a Gradient node, returning the number of chunks written (0 when the
/// node has no grips setting; a grips text that does not read is a warning and is not written).
pub(super) fn write(o: &mut Out, node: &GraphNode, warnings: &mut Vec<ExportWarning>) -> usize {
    let Some(Value::Text(text)) = setting(node, "grips", DataType::Text) else {
        return 0;
    };
    let Some(grips) = grips(&text).filter(|g| !g.is_empty()) else {
        warnings.push(ExportWarning(format!(
            "node \"{}\": the grips \"{text}\" do not read; the gradient is not written",
            node.id.0
        )));
        return 0;
    };
    let linear = matches!(
        setting(node, "linear", DataType::Boolean),
        Some(Value::Boolean(true))
    );
    o.chunk_start("Gradient", None);
    items_and_chunks(
        o,
        |o| {
            o.item("GripCount", None, 3, &grips.len().to_string());
            o.item("Linear", None, 1, if linear { "true" } else { "false" });
            o.item("Locked", None, 1, "false");
            3
        },
        |o| {
            for (k, (factor, left, right)) in grips.iter().enumerate() {
                o.chunk_start("Grip", Some(k));
                items_and_chunks(
                    o,
                    |o| {
                        colour(o, 0, *left);
                        colour(o, 1, *right);
                        o.item("Factor", None, 6, &num(*factor));
                        3
                    },
                    |_| 0,
                );
                o.end("chunk");
            }
            grips.len()
        },
    );
    o.end("chunk");
    1
}
