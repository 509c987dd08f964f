//! The individual conversions of the casting table: rounding numbers to integers, reading
//! numbers, booleans, points and domains from text, and building planes and domains from
//! numbers and points. Each returns `None` for an item that cannot be converted; `cast.rs`
//! turns that into a [`CastError`](crate::CastError). The rules are listed in `docs/casting.md`.

use locus_kernel::{Interval, Plane, Point3};

use crate::file::value_text::parse_number;

/// `2^63` as an `f64`: the first value past the largest `i64`.
const I64_END: f64 = 9_223_372_036_854_775_808.0;

/// Rounds to the nearest integer, halves to even (.NET's `Convert.ToInt64`): 0.5 → 0,
/// 1.5 → 2, 2.5 → 2, −1.5 → −2. NaN, infinities and values outside the `i64` range fail.
pub fn number_to_integer(x: f64) -> Option<i64> {
    let r = x.round_ties_even();
    // NaN is in no range.
    if (-I64_END..I64_END).contains(&r) {
        Some(r as i64)
    } else {
        None
    }
}

/// Zero is false, any other number true; NaN fails.
pub(crate) fn number_to_boolean(x: &f64) -> Option<bool> {
    (!x.is_nan()).then_some(*x != 0.0)
}

/// `x` becomes the domain `0 To x`; NaN and infinities fail.
pub(crate) fn number_to_domain(x: &f64) -> Option<Interval> {
    x.is_finite().then(|| Interval::new(0.0, *x))
}

/// A whole number, else a number rounded as [`number_to_integer`].
pub(crate) fn text_to_integer(t: &str) -> Option<i64> {
    let trimmed = t.trim();
    trimmed
        .parse::<i64>()
        .ok()
        .or_else(|| parse_number(trimmed).and_then(number_to_integer))
}

/// `true`, `yes`, `1` / `false`, `no`, `0`, in any case, after trimming.
pub(crate) fn text_to_boolean(t: &str) -> Option<bool> {
    let t = t.trim();
    if ["true", "yes", "1"]
        .iter()
        .any(|w| t.eq_ignore_ascii_case(w))
    {
        Some(true)
    } else if ["false", "no", "0"]
        .iter()
        .any(|w| t.eq_ignore_ascii_case(w))
    {
        Some(false)
    } else {
        None
    }
}

/// `a To b` (the word in any case), or one number `x` meaning `0 To x`; ends must be finite.
pub(crate) fn text_to_domain(t: &str) -> Option<Interval> {
    let t = t.trim();
    let lower = t.to_ascii_lowercase();
    let domain = match lower.find(" to ") {
        Some(at) => Interval::new(parse_number(&t[..at])?, parse_number(&t[at + 4..])?),
        None => Interval::new(0.0, parse_number(t)?),
    };
    domain.is_finite().then_some(domain)
}

/// Three numbers separated by commas, optionally in braces or parentheses: `1,2,3`,
/// `{1, 2, 3}`, `(1,2,3)`. Two numbers give `z = 0`.
pub(crate) fn parse_xyz(text: &str) -> Option<[f64; 3]> {
    let t = text.trim();
    let inner = if let Some(rest) = t.strip_prefix('{') {
        rest.strip_suffix('}')?
    } else if let Some(rest) = t.strip_prefix('(') {
        rest.strip_suffix(')')?
    } else {
        t
    };
    let mut parts = inner.split(',');
    let x = parse_number(parts.next()?)?;
    let y = parse_number(parts.next()?)?;
    let z = match parts.next() {
        Some(z) => parse_number(z)?,
        None => 0.0,
    };
    if parts.next().is_some() {
        return None;
    }
    Some([x, y, z])
}

/// The plane parallel to World XY through the point; non-finite points fail.
pub(crate) fn point_to_plane(p: &Point3) -> Option<Plane> {
    p.is_finite().then_some(Plane {
        origin: *p,
        ..Plane::WORLD_XY
    })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Transform, Vector3};

    use super::*;
    use crate::{DataType, Value, cast_value};

    fn text(s: &str) -> Value {
        Value::Text(s.to_owned())
    }

    fn ok(v: Value, to: DataType) -> Value {
        cast_value(&v, to).unwrap_or_else(|e| panic!("{e}"))
    }

    fn err(v: Value, to: DataType) -> String {
        match cast_value(&v, to) {
            Ok(c) => panic!("{v:?} cast to {c:?}"),
            Err(e) => e.to_string(),
        }
    }

    #[test]
    fn number_to_integer_rounds_halves_to_even() {
        let cases = [
            (0.5, 0),
            (-0.5, 0),
            (1.5, 2),
            (2.5, 2),
            (-1.5, -2),
            (-2.5, -2),
            (3.5, 4),
            (2.4999, 2),
            (2.5001, 3),
            (-7.0, -7),
        ];
        for (x, i) in cases {
            assert_eq!(
                ok(Value::Number(x), DataType::Integer),
                Value::Integer(i),
                "{x}"
            );
        }
        assert_eq!(
            ok(Value::Number(-I64_END), DataType::Integer),
            Value::Integer(i64::MIN)
        );
    }

    #[test]
    fn non_finite_or_huge_numbers_do_not_become_integers() {
        assert_eq!(
            err(Value::Number(f64::NAN), DataType::Integer),
            "invalid cast: Number NaN → Integer"
        );
        assert_eq!(
            err(Value::Number(f64::INFINITY), DataType::Integer),
            "invalid cast: Number Infinity → Integer"
        );
        assert_eq!(
            err(Value::Number(9.3e18), DataType::Integer),
            "invalid cast: Number 9.3E+18 → Integer"
        );
    }

    #[test]
    fn integers_and_booleans_to_numbers() {
        assert_eq!(
            ok(Value::Integer(-4), DataType::Number),
            Value::Number(-4.0)
        );
        assert_eq!(
            ok(Value::Boolean(true), DataType::Number),
            Value::Number(1.0)
        );
        assert_eq!(
            ok(Value::Boolean(false), DataType::Integer),
            Value::Integer(0)
        );
        assert_eq!(
            ok(Value::Boolean(true), DataType::Integer),
            Value::Integer(1)
        );
    }

    #[test]
    fn numbers_to_booleans_are_zero_or_not() {
        assert_eq!(
            ok(Value::Integer(0), DataType::Boolean),
            Value::Boolean(false)
        );
        assert_eq!(
            ok(Value::Integer(-2), DataType::Boolean),
            Value::Boolean(true)
        );
        assert_eq!(
            ok(Value::Number(0.0), DataType::Boolean),
            Value::Boolean(false)
        );
        assert_eq!(
            ok(Value::Number(-0.0), DataType::Boolean),
            Value::Boolean(false)
        );
        assert_eq!(
            ok(Value::Number(0.25), DataType::Boolean),
            Value::Boolean(true)
        );
        assert_eq!(
            ok(Value::Number(f64::INFINITY), DataType::Boolean),
            Value::Boolean(true)
        );
        assert_eq!(
            err(Value::Number(f64::NAN), DataType::Boolean),
            "invalid cast: Number NaN → Boolean"
        );
    }

    #[test]
    fn text_to_numbers() {
        assert_eq!(ok(text(" 2.5 "), DataType::Number), Value::Number(2.5));
        assert_eq!(ok(text("1e3"), DataType::Number), Value::Number(1000.0));
        assert_eq!(ok(text("-1E+15"), DataType::Number), Value::Number(-1e15));
        assert_eq!(ok(text("42"), DataType::Integer), Value::Integer(42));
        assert_eq!(ok(text("2.5"), DataType::Integer), Value::Integer(2));
        assert_eq!(ok(text("1e3"), DataType::Integer), Value::Integer(1000));
        assert_eq!(
            err(text("abc"), DataType::Number),
            "invalid cast: Text \"abc\" → Number"
        );
        assert_eq!(
            err(text("1,5"), DataType::Number),
            "invalid cast: Text \"1,5\" → Number"
        );
        assert_eq!(
            err(text("NaN"), DataType::Integer),
            "invalid cast: Text \"NaN\" → Integer"
        );
    }

    #[test]
    fn text_to_booleans() {
        for (t, b) in [
            ("true", true),
            ("TRUE", true),
            (" Yes ", true),
            ("1", true),
            ("False", false),
            ("no", false),
            ("0", false),
        ] {
            assert_eq!(ok(text(t), DataType::Boolean), Value::Boolean(b), "{t}");
        }
        assert_eq!(
            err(text("2"), DataType::Boolean),
            "invalid cast: Text \"2\" → Boolean"
        );
        assert_eq!(
            err(text("y"), DataType::Boolean),
            "invalid cast: Text \"y\" → Boolean"
        );
    }

    #[test]
    fn text_to_points_and_vectors() {
        let p = Value::Point(Point3::new(1.0, 2.0, 3.0));
        assert_eq!(ok(text("1,2,3"), DataType::Point), p);
        assert_eq!(ok(text("{1, 2, 3}"), DataType::Point), p);
        assert_eq!(ok(text(" (1,2,3) "), DataType::Point), p);
        assert_eq!(
            ok(text("1,2"), DataType::Point),
            Value::Point(Point3::new(1.0, 2.0, 0.0))
        );
        assert_eq!(
            ok(text("{-1, 0.5, 1e3}"), DataType::Vector),
            Value::Vector(Vector3::new(-1.0, 0.5, 1000.0))
        );
        for bad in ["1", "1,2,3,4", "{1,2,3", "a,b,c", "1;2;3", ""] {
            assert_eq!(
                err(text(bad), DataType::Point),
                format!("invalid cast: Text \"{bad}\" → Point")
            );
        }
    }

    #[test]
    fn text_to_domains() {
        assert_eq!(
            ok(text("0 To 1"), DataType::Domain),
            Value::Domain(Interval::UNIT)
        );
        assert_eq!(
            ok(text("-2.5 to 4"), DataType::Domain),
            Value::Domain(Interval::new(-2.5, 4.0))
        );
        assert_eq!(
            ok(text("3"), DataType::Domain),
            Value::Domain(Interval::new(0.0, 3.0))
        );
        assert!(cast_value(&text("0 To NaN"), DataType::Domain).is_err());
        assert!(cast_value(&text("0 To"), DataType::Domain).is_err());
    }

    #[test]
    fn values_to_text_print_like_grasshopper() {
        let cases = [
            (Value::Number(0.5), "0.5"),
            (Value::Number(1e20), "1E+20"),
            (Value::Integer(-7), "-7"),
            (Value::Boolean(true), "True"),
            (Value::Point(Point3::new(1.0, 2.0, 3.0)), "{1, 2, 3}"),
            (Value::Vector(Vector3::new(0.0, -1.0, 0.5)), "{0, -1, 0.5}"),
            (Value::Domain(Interval::new(0.0, 2.0)), "0 To 2"),
            (Value::Plane(Plane::WORLD_XY), "O{0, 0, 0} Z{0, 0, 1}"),
            (
                Value::Transform(Transform::IDENTITY),
                "{1, 0, 0, 0; 0, 1, 0, 0; 0, 0, 1, 0; 0, 0, 0, 1}",
            ),
        ];
        for (v, t) in cases {
            assert_eq!(ok(v, DataType::Text), text(t));
        }
    }

    #[test]
    fn text_round_trips_through_numbers_and_points() {
        for x in [0.1, -2.5e-9, 1e300, 123.456] {
            let t = ok(Value::Number(x), DataType::Text);
            assert_eq!(ok(t, DataType::Number), Value::Number(x));
        }
        let p = Value::Point(Point3::new(0.1, -2.0, 1e20));
        assert_eq!(ok(ok(p.clone(), DataType::Text), DataType::Point), p);
        let d = Value::Domain(Interval::new(-1.0, 0.25));
        assert_eq!(ok(ok(d.clone(), DataType::Text), DataType::Domain), d);
        let b = Value::Boolean(false);
        assert_eq!(ok(ok(b.clone(), DataType::Text), DataType::Boolean), b);
    }

    #[test]
    fn geometry_casts() {
        let p = Point3::new(1.0, 2.0, 3.0);
        assert_eq!(
            ok(Value::Point(p), DataType::Vector),
            Value::Vector(Vector3::new(1.0, 2.0, 3.0))
        );
        assert_eq!(
            ok(Value::Vector(Vector3::new(1.0, 2.0, 3.0)), DataType::Point),
            Value::Point(p)
        );
        let Value::Plane(plane) = ok(Value::Point(p), DataType::Plane) else {
            panic!("not a plane");
        };
        assert_eq!(plane.origin, p);
        assert_eq!(
            (plane.x_axis, plane.y_axis, plane.z_axis),
            (Vector3::X, Vector3::Y, Vector3::Z)
        );
        assert_eq!(ok(Value::Plane(plane), DataType::Point), Value::Point(p));
        assert!(
            cast_value(
                &Value::Point(Point3::new(f64::NAN, 0.0, 0.0)),
                DataType::Plane
            )
            .is_err()
        );
    }

    #[test]
    fn domains_and_numbers() {
        assert_eq!(
            ok(Value::Number(2.5), DataType::Domain),
            Value::Domain(Interval::new(0.0, 2.5))
        );
        assert_eq!(
            ok(Value::Integer(-3), DataType::Domain),
            Value::Domain(Interval::new(0.0, -3.0))
        );
        assert_eq!(
            ok(Value::Domain(Interval::new(4.0, 1.0)), DataType::Number),
            Value::Number(-3.0)
        );
        assert_eq!(
            err(Value::Number(f64::INFINITY), DataType::Domain),
            "invalid cast: Number Infinity → Domain"
        );
    }
}
