//! Persistent data written as locus literals (the RON value forms of `docs/graph-format.md`).

use locus_runtime::{DataType, Literal};

use crate::document::{GhItem, GhTree};

/// A number in Rust's shortest round-trip form, with a decimal point or exponent.
pub fn number(x: f64) -> String {
    if x.is_nan() {
        "NaN".to_owned()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.to_owned()
    } else {
        format!("{x:?}")
    }
}

/// A text as a RON string.
pub fn text(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() => out.push_str(&format!("\\u{{{:x}}}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn triple(p: &[f64]) -> String {
    format!("({}, {}, {})", number(p[0]), number(p[1]), number(p[2]))
}

/// One item as a literal for a port of type `target` (`None` when it has no literal form,
/// such as internalised geometry).
pub fn item(item: &GhItem, target: DataType) -> Option<String> {
    Some(match item {
        GhItem::Number(x) => {
            if target == DataType::Integer && x.fract() == 0.0 && x.abs() < 9.0e15 {
                format!("{}", *x as i64)
            } else {
                number(*x)
            }
        }
        GhItem::Integer(i) => {
            if target == DataType::Number {
                number(*i as f64)
            } else {
                i.to_string()
            }
        }
        GhItem::Boolean(b) => b.to_string(),
        GhItem::Text(s) => text(s),
        GhItem::Point(p) => {
            if target == DataType::Point {
                triple(p)
            } else {
                format!("Point{}", triple(p))
            }
        }
        GhItem::Vector(v) => {
            if target == DataType::Vector {
                triple(v)
            } else {
                format!("Vector{}", triple(v))
            }
        }
        GhItem::Plane(p) => format!(
            "({}, {}, {})",
            triple(&p[0..3]),
            triple(&p[3..6]),
            triple(&p[6..9])
        ),
        GhItem::Domain([a, b]) => format!("({}, {})", number(*a), number(*b)),
        GhItem::Domain2([u0, u1, v0, v1]) => format!(
            "(({}, {}), ({}, {}))",
            number(*u0),
            number(*u1),
            number(*v0),
            number(*v1)
        ),
        // locus has no colour type: a colour is its text "a;r;g;b" as Grasshopper prints it.
        GhItem::Colour([a, r, g, b]) => text(&format!("{a};{r};{g};{b}")),
        // locus has no mesh face type: a face is its text as Grasshopper prints it, which is
        // what Construct Mesh reads (a triangle repeats its third index).
        GhItem::MeshFace([a, b, c, d]) => {
            if c == d {
                text(&format!("T{{{a};{b};{c}}}"))
            } else {
                text(&format!("Q{{{a};{b};{c};{d}}}"))
            }
        }
        // Geometry as its literal form (a B-rep and a mesh have none yet).
        GhItem::Geometry(Ok(v)) => {
            return locus_runtime::Literal::from_value(v).ok().map(|l| l.0);
        }
        GhItem::Geometry(Err(_)) | GhItem::Other(_) => return None,
    })
}

/// A whole tree as a literal for a port of type `target`; items without a literal form are
/// written as `null`.
pub fn tree(tree: &GhTree, target: DataType) -> Literal {
    let branch = |items: &[GhItem]| -> String {
        let parts: Vec<String> = items
            .iter()
            .map(|i| item(i, target).unwrap_or_else(|| "null".to_owned()))
            .collect();
        format!("[{}]", parts.join(", "))
    };
    if let [(path, items)] = tree.branches.as_slice()
        && path.as_slice() == [0]
    {
        if let [single] = items.as_slice() {
            return Literal(item(single, target).unwrap_or_else(|| "null".to_owned()));
        }
        return Literal(branch(items));
    }
    let parts: Vec<String> = tree
        .branches
        .iter()
        .map(|(path, items)| {
            let p: Vec<String> = path.iter().map(i64::to_string).collect();
            format!("\"{{{}}}\": {}", p.join(";"), branch(items))
        })
        .collect();
    Literal(format!("{{{}}}", parts.join(", ")))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literals_read_back_as_the_runtime_reads_them() {
        let t = GhTree {
            branches: vec![
                (vec![0, 1], vec![GhItem::Number(1.0), GhItem::Number(0.25)]),
                (vec![0, 2], vec![]),
            ],
        };
        let lit = tree(&t, DataType::Number);
        assert_eq!(lit.0, r#"{"{0;1}": [1.0, 0.25], "{0;2}": []}"#);
        let parsed = locus_runtime::parse_literal(&lit.0, DataType::Number).unwrap();
        assert_eq!(parsed.to_text(), "{0;1}:[1, 0.25] {0;2}:[]");
        let v = GhTree {
            branches: vec![(vec![0], vec![GhItem::Vector([0.0, 0.0, 1.0])])],
        };
        assert_eq!(tree(&v, DataType::Generic).0, "Vector(0.0, 0.0, 1.0)");
        assert_eq!(text("a\"b\\\n"), r#""a\"b\\\n""#);
        let faces = GhTree {
            branches: vec![(
                vec![0],
                vec![
                    GhItem::MeshFace([0, 1, 2, 3]),
                    GhItem::MeshFace([4, 5, 6, 6]),
                ],
            )],
        };
        let lit = tree(&faces, DataType::Text);
        assert_eq!(lit.0, r#"["Q{0;1;2;3}", "T{4;5;6}"]"#);
        locus_runtime::parse_literal(&lit.0, DataType::Text).unwrap();
    }
}
