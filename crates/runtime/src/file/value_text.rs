//! Values as Grasshopper prints them: the text a value becomes when cast to `Text`, and the
//! spelling of numbers in tree notation and error messages.
//!
//! Numbers use the invariant culture (a full stop as decimal separator, no grouping) and the
//! shortest digits that read back to the same `f64`, switching to `1E+15` / `1E-05` notation
//! at the same exponents as .NET's `Double.ToString()`, which is what Grasshopper shows in
//! Rhino 8. The full table is in `docs/casting.md`.

use std::fmt::Write;

use locus_kernel::{Interval, Plane, Point3, Transform, Vector3};

use crate::Value;

/// The smallest decimal exponent printed without exponent notation (`0.0001`).
const MIN_FIXED_EXPONENT: i32 = -4;
/// The largest decimal exponent printed without exponent notation (`100000000000000`).
const MAX_FIXED_EXPONENT: i32 = 14;

/// A number as Grasshopper prints it: `1`, `0.5`, `-2.25`, `1E+15`, `1.5E-07`, `NaN`,
/// `Infinity`, `-Infinity`.
///
/// The digits are the shortest that parse back to exactly the same `f64`, so
/// `format_number(x).parse::<f64>() == Ok(x)` for every finite `x` (and `parse_number`
/// reads every output back).
pub fn format_number(x: f64) -> String {
    let mut s = String::new();
    write_number(&mut s, x);
    s
}

/// Appends [`format_number`]`(x)` to `out`.
pub fn write_number(out: &mut String, x: f64) {
    if x.is_nan() {
        out.push_str("NaN");
        return;
    }
    if x.is_infinite() {
        out.push_str(if x > 0.0 { "Infinity" } else { "-Infinity" });
        return;
    }
    if x == 0.0 {
        out.push_str(if x.is_sign_negative() { "-0" } else { "0" });
        return;
    }
    // Within these bounds the shortest digits have a decimal exponent from -4 to 14: the bounds
    // are the doubles nearest 1e-4 and exactly 1e15, whose own shortest digits are `1e-4` and
    // `1e15`, so no value inside can print with an exponent outside.
    if (1e-4..1e15).contains(&x.abs()) {
        let _ = write!(out, "{x}");
        return;
    }
    // `{:e}` prints the shortest round-trip digits as `d.ddde±x`.
    let scientific = format!("{x:e}");
    let (mantissa, exponent) = scientific
        .split_once('e')
        .unwrap_or((scientific.as_str(), "0"));
    let exponent: i32 = exponent.parse().unwrap_or(0);
    if (MIN_FIXED_EXPONENT..=MAX_FIXED_EXPONENT).contains(&exponent) {
        let _ = write!(out, "{x}");
    } else {
        let sign = if exponent < 0 { '-' } else { '+' };
        let _ = write!(out, "{mantissa}E{sign}{:02}", exponent.unsigned_abs());
    }
}

/// Reads a number written in the invariant culture, after trimming white space: `1`, `-2.5`,
/// `.5`, `1e3`, `1E+15`, `NaN`, `Infinity`, `inf`, `∞`. Returns `None` for anything else.
pub fn parse_number(text: &str) -> Option<f64> {
    let text = text.trim();
    match text {
        "∞" | "+∞" => return Some(f64::INFINITY),
        "-∞" => return Some(f64::NEG_INFINITY),
        _ => {}
    }
    // Rust's parser accepts a few spellings .NET does not (`inf`), and nothing .NET's
    // invariant parser would read differently; thousands separators are rejected by both.
    text.parse::<f64>().ok()
}

/// A point or vector as Grasshopper prints it: `{1, 2, 3}`.
pub fn format_xyz(x: f64, y: f64, z: f64) -> String {
    let mut s = String::with_capacity(16);
    write_xyz(&mut s, x, y, z);
    s
}

fn write_xyz(out: &mut String, x: f64, y: f64, z: f64) {
    out.push('{');
    write_number(out, x);
    out.push_str(", ");
    write_number(out, y);
    out.push_str(", ");
    write_number(out, z);
    out.push('}');
}

/// A point as Grasshopper prints it: `{1, 2, 3}`.
pub fn format_point(p: Point3) -> String {
    format_xyz(p.x, p.y, p.z)
}

/// A vector as Grasshopper prints it: `{1, 2, 3}`.
pub fn format_vector(v: Vector3) -> String {
    format_xyz(v.x, v.y, v.z)
}

/// A domain as Grasshopper prints it: `0 To 1`.
pub fn format_domain(d: Interval) -> String {
    let mut s = String::new();
    write_number(&mut s, d.t0);
    s.push_str(" To ");
    write_number(&mut s, d.t1);
    s
}

/// A plane as origin and normal, the way Grasshopper summarises it: `O{0, 0, 0} Z{0, 0, 1}`.
pub fn format_plane(p: &Plane) -> String {
    let mut s = String::from("O");
    write_xyz(&mut s, p.origin.x, p.origin.y, p.origin.z);
    s.push_str(" Z");
    write_xyz(&mut s, p.z_axis.x, p.z_axis.y, p.z_axis.z);
    s
}

/// A transform as its four rows, row by row: `{1, 0, 0, 5; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1}`.
pub fn format_transform(t: &Transform) -> String {
    let mut s = String::from("{");
    for (r, row) in t.to_rows().iter().enumerate() {
        if r > 0 {
            s.push_str("; ");
        }
        for (c, x) in row.iter().enumerate() {
            if c > 0 {
                s.push_str(", ");
            }
            write_number(&mut s, *x);
        }
    }
    s.push('}');
    s
}

/// A boolean as .NET prints it: `True` or `False`.
pub fn format_boolean(b: bool) -> &'static str {
    if b { "True" } else { "False" }
}

/// Any value as the text it becomes when cast to `Text` (text itself is returned unquoted).
pub fn format_value(value: &Value) -> String {
    match value {
        Value::Number(x) => format_number(*x),
        Value::Integer(i) => i.to_string(),
        Value::Boolean(b) => format_boolean(*b).to_owned(),
        Value::Text(t) => t.clone(),
        Value::Point(p) => format_point(*p),
        Value::Vector(v) => format_vector(*v),
        Value::Plane(p) => format_plane(p),
        Value::Domain(d) => format_domain(*d),
        Value::Domain2(d) => format!("{} × {}", format_domain(d.u), format_domain(d.v)),
        Value::Transform(t) => format_transform(t),
        Value::Box(b) => format!(
            "Box (O:{} sizes {} × {} × {})",
            format_point(b.plane.origin),
            format_number(b.x.length().abs()),
            format_number(b.y.length().abs()),
            format_number(b.z.length().abs())
        ),
        Value::Line(l) => format!("Line ({} to {})", format_point(l.from), format_point(l.to)),
        Value::Circle(c) => format!(
            "Circle (R:{} at {})",
            format_number(c.radius),
            format_point(c.plane.origin)
        ),
        Value::Arc(a) => format!(
            "Arc (R:{} at {}, angle {})",
            format_number(a.circle.radius),
            format_point(a.circle.plane.origin),
            format_domain(a.angle)
        ),
        Value::Curve(c) => {
            let d = c.domain();
            format!(
                "{} (degree {}, domain {})",
                curve_kind(c),
                c.degree(),
                format_domain(Interval::new(d.t0, d.t1))
            )
        }
        Value::Surface(s) => format!(
            "NURBS Surface (degree {}×{}, {}×{} points)",
            s.degree_u(),
            s.degree_v(),
            s.count_u(),
            s.count_v()
        ),
        Value::Brep(b) => format!(
            "Brep ({} face{}, {} edge{}, {} vert{})",
            b.faces().len(),
            if b.faces().len() == 1 { "" } else { "s" },
            b.edges().len(),
            if b.edges().len() == 1 { "" } else { "s" },
            b.vertices().len(),
            if b.vertices().len() == 1 {
                "ex"
            } else {
                "ices"
            }
        ),
        Value::Mesh(m) => format!("Mesh (V:{} F:{})", m.vertices().len(), m.faces().len()),
        Value::Colour(c) => format_colour(*c),
    }
}

/// A colour as Grasshopper shows it: `R,G,B`, or `A,R,G,B` when it is not opaque.
pub fn format_colour(c: locus_kernel::Color) -> String {
    if c.a == 255 {
        format!("{},{},{}", c.r, c.g, c.b)
    } else {
        format!("{},{},{},{}", c.a, c.r, c.g, c.b)
    }
}

/// The kind of a curve as Rhino names it.
pub fn curve_kind(c: &locus_kernel::Curve) -> &'static str {
    use locus_kernel::Curve;
    match c {
        Curve::Line { .. } => "Line Curve",
        Curve::Polyline { .. } => "Polyline Curve",
        Curve::Circle { .. } | Curve::Arc { .. } => "Arc Curve",
        Curve::Nurbs(_) => "NURBS Curve",
    }
}

/// Appends `text` in double quotes, escaping `"`, `\` and control characters, so that
/// [`crate::DataTree::parse_text`] reads it back.
pub fn write_quoted(out: &mut String, text: &str) {
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{{{:x}}}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_print_like_dotnet() {
        let cases = [
            (1.0, "1"),
            (0.5, "0.5"),
            (-2.25, "-2.25"),
            (0.1 + 0.2, "0.30000000000000004"),
            (123456789012345.0, "123456789012345"),
            (1e15, "1E+15"),
            (-2.5e20, "-2.5E+20"),
            (1e100, "1E+100"),
            (0.0001, "0.0001"),
            (0.00009999999999999999, "9.999999999999999E-05"),
            (999999999999999.9, "999999999999999.9"),
            (0.00001, "1E-05"),
            (1.5e-7, "1.5E-07"),
            (0.0, "0"),
            (-0.0, "-0"),
            (f64::NAN, "NaN"),
            (f64::INFINITY, "Infinity"),
            (f64::NEG_INFINITY, "-Infinity"),
        ];
        for (x, text) in cases {
            assert_eq!(format_number(x), text, "{x:?}");
        }
    }

    #[test]
    fn printed_numbers_read_back_exactly() {
        for x in [
            1.0,
            0.1,
            1.0 / 3.0,
            1e15,
            -2.5e20,
            1.5e-7,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ] {
            assert_eq!(parse_number(&format_number(x)), Some(x), "{x:?}");
        }
        assert!(parse_number("NaN").is_some_and(f64::is_nan));
    }

    #[test]
    fn number_parsing_is_invariant_and_trimmed() {
        assert_eq!(parse_number(" 1e3 "), Some(1000.0));
        assert_eq!(parse_number("1E+15"), Some(1e15));
        assert_eq!(parse_number(".5"), Some(0.5));
        assert_eq!(parse_number("-∞"), Some(f64::NEG_INFINITY));
        for bad in ["1,5", "1 000", "abc", "", "1.2.3", "0x10"] {
            assert_eq!(parse_number(bad), None, "{bad}");
        }
    }

    #[test]
    fn geometry_prints_like_grasshopper() {
        assert_eq!(format_point(Point3::new(1.0, 2.0, 3.5)), "{1, 2, 3.5}");
        assert_eq!(format_domain(Interval::new(0.0, 2.5)), "0 To 2.5");
        assert_eq!(format_plane(&Plane::WORLD_XY), "O{0, 0, 0} Z{0, 0, 1}");
        assert_eq!(
            format_transform(&Transform::translation(Vector3::new(5.0, 0.0, 0.0))),
            "{1, 0, 0, 5; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1}"
        );
        assert_eq!(format_value(&Value::Boolean(true)), "True");
    }

    #[test]
    fn geometry_values_print_a_description() {
        use locus_kernel::{Arc, Circle, Curve, Line, NurbsSurface, OrientedBox};

        use crate::Shared;

        let line = Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0));
        let circle = Circle::new(Plane::WORLD_XY, 2.5).unwrap();
        let unit = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let arc = Arc::new(unit, Interval::new(0.0, std::f64::consts::FRAC_PI_2)).unwrap();
        let bx = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::UNIT,
            Interval::new(0.0, 2.0),
        );
        let surface =
            NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::UNIT, Interval::UNIT).unwrap();
        let cases = [
            (Value::Box(bx), "Box (O:{0, 0, 0} sizes 1 × 1 × 2)"),
            (Value::Line(line), "Line ({0, 0, 0} to {1, 0, 0})"),
            (Value::Circle(circle), "Circle (R:2.5 at {0, 0, 0})"),
            (
                Value::Arc(arc),
                "Arc (R:1 at {0, 0, 0}, angle 0 To 1.5707963267948966)",
            ),
            (
                Value::Curve(Shared::new(Curve::from(line))),
                "Line Curve (degree 1, domain 0 To 1)",
            ),
            (
                Value::Surface(Shared::new(surface)),
                "NURBS Surface (degree 1×1, 2×2 points)",
            ),
        ];
        for (value, text) in cases {
            assert_eq!(format_value(&value), text);
        }
    }

    #[test]
    fn quoting_escapes_specials() {
        let mut s = String::new();
        write_quoted(&mut s, "a\"b\\c\nd\u{1}");
        assert_eq!(s, "\"a\\\"b\\\\c\\nd\\u{1}\"");
    }
}
