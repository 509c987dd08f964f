//! The Gradient component's grips, read from its `Gradient` chunk into the node's `grips` and
//! `linear` settings (the notation of `locus_nodes::display::gradient`).
//!
//! The chunk holds `GripCount`, `Linear` and one `Grip` chunk per grip with its `Factor` and two
//! `Colour` items: index 0 the colour left of the grip, index 1 the colour right of it.

use locus_runtime::Literal;

use crate::archive::{Chunk, Value};
use crate::literal;

/// The most grips read from a file; a file with more is refused for this node.
const MAX_GRIPS: usize = 10_000;

fn hex([a, r, g, b]: [u8; 4]) -> String {
    format!("#{a:02X}{r:02X}{g:02X}{b:02X}")
}

/// The settings for the gradient stored in `container`, or why they cannot be read. `None` when
/// the component has no `Gradient` chunk (the node's default gradient then applies).
pub(super) fn settings(container: &Chunk) -> Option<Result<Vec<(String, Literal)>, String>> {
    let chunk = container.chunk("Gradient")?;
    Some(read(chunk))
}

fn read(chunk: &Chunk) -> Result<Vec<(String, Literal)>, String> {
    let mut grips = Vec::new();
    for (k, grip) in chunk.chunks_named("Grip").enumerate() {
        if k >= MAX_GRIPS {
            return Err(format!("more than {MAX_GRIPS} grips"));
        }
        let factor = grip
            .f64("Factor")
            .filter(|f| f.is_finite())
            .ok_or_else(|| format!("grip {k} has no finite Factor"))?;
        let colours: Vec<[u8; 4]> = grip
            .items_named("Colour")
            .filter_map(|i| match i.value {
                Value::Color(c) => Some(c),
                _ => None,
            })
            .collect();
        let (left, right) = match colours[..] {
            [c] => (c, c),
            [l, r, ..] => (l, r),
            [] => return Err(format!("grip {k} has no colour")),
        };
        let colours = if left == right {
            hex(left)
        } else {
            format!("{}/{}", hex(left), hex(right))
        };
        grips.push(format!("{} {colours}", literal::number(factor)));
    }
    if grips.is_empty() {
        return Err("the gradient has no grips".into());
    }
    let linear = chunk.bool("Linear").unwrap_or(false);
    Ok(vec![
        (
            "grips".to_owned(),
            Literal(literal::text(&grips.join("; "))),
        ),
        ("linear".to_owned(), Literal(linear.to_string())),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::archive::Item;

    fn colour(index: i32, c: [u8; 4]) -> Item {
        Item {
            name: "Colour".into(),
            index: Some(index),
            value: Value::Color(c),
        }
    }

    fn grip(factor: f64, colours: Vec<Item>) -> Chunk {
        let mut items = colours;
        items.push(Item {
            name: "Factor".into(),
            index: None,
            value: Value::Double(factor),
        });
        Chunk {
            name: "Grip".into(),
            index: None,
            items,
            chunks: Vec::new(),
        }
    }

    #[test]
    fn grips_become_settings() {
        let gradient = Chunk {
            name: "Gradient".into(),
            index: None,
            items: vec![Item {
                name: "Linear".into(),
                index: None,
                value: Value::Bool(true),
            }],
            chunks: vec![
                grip(
                    0.0,
                    vec![colour(0, [255, 214, 20, 22]), colour(1, [255, 214, 20, 22])],
                ),
                grip(
                    0.5,
                    vec![colour(0, [255, 0, 0, 0]), colour(1, [128, 255, 255, 255])],
                ),
            ],
        };
        let container = Chunk {
            name: "Container".into(),
            index: None,
            items: Vec::new(),
            chunks: vec![gradient],
        };
        let s = settings(&container).unwrap().unwrap();
        assert_eq!(s[0].0, "grips");
        assert_eq!(s[0].1.0, "\"0.0 #FFD61416; 0.5 #FF000000/#80FFFFFF\"");
        assert_eq!(s[1].1.0, "true");
    }

    #[test]
    fn a_broken_gradient_is_refused() {
        let container = Chunk {
            name: "Container".into(),
            index: None,
            items: Vec::new(),
            chunks: vec![Chunk {
                name: "Gradient".into(),
                index: None,
                items: Vec::new(),
                chunks: vec![grip(f64::NAN, vec![colour(0, [255, 0, 0, 0])])],
            }],
        };
        assert!(
            settings(&container)
                .unwrap()
                .unwrap_err()
                .contains("Factor")
        );
    }
}
