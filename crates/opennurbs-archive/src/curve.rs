//! Curve classes: `ON_NurbsCurve`, `ON_LineCurve`, `ON_PolylineCurve`, `ON_ArcCurve` and
//! `ON_PolyCurve` (read only, joined into one NURBS curve by [`crate::polycurve`]).

use locus_kernel::{
    Arc, Circle, Curve, Interval, Line, NurbsCurve, Plane, Point3, Polyline, Vector3,
};

use crate::binary::{Reader, Writer};
use crate::object::{ClassId, read_object, write_record};
use crate::{Error, Geometry, Result, Versions, nurbs, polycurve};

/// Polyline parameters within this relative distance of uniform spacing are read as a
/// [`Curve::Polyline`] (whose parameters are uniform); others make a degree-1 NURBS curve with
/// the parameters as knots. The value allows for the rounding of `t0 + i·(t1 − t0)/n`.
pub const UNIFORM_PARAMETER_TOLERANCE: f64 = 1e-12;

fn write_point(w: &mut Writer, p: Point3) {
    w.f64s(&[p.x, p.y, p.z]);
}
fn write_vector(w: &mut Writer, v: Vector3) {
    w.f64s(&[v.x, v.y, v.z]);
}
fn read_point(r: &mut Reader<'_>, what: &'static str) -> Result<Point3> {
    Ok(Point3::new(r.f64(what)?, r.f64(what)?, r.f64(what)?))
}
fn read_interval(r: &mut Reader<'_>, what: &'static str) -> Result<Interval> {
    Ok(Interval::new(r.f64(what)?, r.f64(what)?))
}
fn check_domain(d: Interval, what: &'static str) -> Result<Interval> {
    if d.is_finite() && d.t0 < d.t1 {
        Ok(d)
    } else {
        Err(Error::Invalid(format!(
            "{what} domain {} to {} is not increasing",
            d.t0, d.t1
        )))
    }
}
fn geometry_error(what: &'static str) -> impl FnOnce(locus_kernel::Error) -> Error {
    move |source| Error::Geometry { what, source }
}

/// Writes a curve as one object record of the class that fits it best.
pub(crate) fn write_object(w: &mut Writer, c: &Curve) -> Result<()> {
    match c {
        Curve::Nurbs(n) => write_record(w, ClassId::NURBS_CURVE, |w| nurbs::write_curve(w, n)),
        Curve::Line { line, domain } => write_record(w, ClassId::LINE_CURVE, |w| {
            w.version(1, 0);
            write_point(w, line.from);
            write_point(w, line.to);
            w.interval(domain.t0, domain.t1);
            w.i32(3);
            Ok(())
        }),
        Curve::Polyline { polyline, domain } => write_record(w, ClassId::POLYLINE_CURVE, |w| {
            let points = polyline.points();
            w.version(1, 0);
            w.count(points.len())?;
            for &p in points {
                write_point(w, p);
            }
            w.count(points.len())?;
            let last = points.len() - 1;
            for i in 0..points.len() {
                let t = if i == last {
                    domain.t1
                } else {
                    domain.parameter_at(i as f64 / last as f64)
                };
                w.f64(t);
            }
            w.i32(3);
            Ok(())
        }),
        Curve::Arc { arc, domain } => write_arc(w, &arc.circle, arc.angle, *domain),
        Curve::Circle { circle, domain } => write_arc(
            w,
            circle,
            Interval::new(0.0, std::f64::consts::TAU),
            *domain,
        ),
    }
}

fn write_arc(w: &mut Writer, circle: &Circle, angle: Interval, domain: Interval) -> Result<()> {
    write_record(w, ClassId::ARC_CURVE, |w| {
        let plane = &circle.plane;
        w.version(1, 0);
        write_point(w, plane.origin);
        write_vector(w, plane.x_axis);
        write_vector(w, plane.y_axis);
        write_vector(w, plane.z_axis);
        w.f64s(&plane.equation());
        w.f64(circle.radius);
        // Three legacy points: at angles 0, π/2 and π.
        for a in [0.0, std::f64::consts::FRAC_PI_2, std::f64::consts::PI] {
            write_point(w, circle.point_at(a));
        }
        w.interval(angle.t0, angle.t1);
        w.interval(domain.t0, domain.t1);
        w.i32(3);
        Ok(())
    })
}

/// Reads the class data of a curve class.
pub(crate) fn read_class(
    r: &mut Reader<'_>,
    class: ClassId,
    v: Versions,
    depth: usize,
) -> Result<Curve> {
    match class {
        ClassId::NURBS_CURVE => nurbs::read_curve(r).map(Curve::Nurbs),
        ClassId::LINE_CURVE => read_line(r),
        ClassId::POLYLINE_CURVE => read_polyline(r),
        ClassId::ARC_CURVE => read_arc(r),
        ClassId::POLY_CURVE => read_polycurve(r, v, depth),
        other => Err(Error::UnsupportedClass {
            id: other.to_string(),
            name: other.name(),
        }),
    }
}

fn major_1(r: &mut Reader<'_>, what: &'static str) -> Result<()> {
    let (major, minor) = r.version(what)?;
    if major == 1 {
        Ok(())
    } else {
        Err(Error::Invalid(format!(
            "{what} {major}.{minor} is not supported"
        )))
    }
}

fn read_line(r: &mut Reader<'_>) -> Result<Curve> {
    major_1(r, "ON_LineCurve version")?;
    let from = read_point(r, "ON_LineCurve start")?;
    let to = read_point(r, "ON_LineCurve end")?;
    let domain = check_domain(read_interval(r, "ON_LineCurve domain")?, "ON_LineCurve")?;
    r.i32("ON_LineCurve dimension")?;
    let line = Line { from, to };
    if !line.is_finite() {
        return Err(Error::Invalid(
            "ON_LineCurve end points are not finite".into(),
        ));
    }
    Ok(Curve::Line { line, domain })
}

fn read_polyline(r: &mut Reader<'_>) -> Result<Curve> {
    major_1(r, "ON_PolylineCurve version")?;
    let n = r.count(24, "ON_PolylineCurve points")?;
    let points: Vec<Point3> = r
        .f64s(n * 3, "ON_PolylineCurve points")?
        .chunks_exact(3)
        .map(|c| Point3::new(c[0], c[1], c[2]))
        .collect();
    let m = r.count(8, "ON_PolylineCurve parameters")?;
    let t = r.f64s(m, "ON_PolylineCurve parameters")?;
    r.i32("ON_PolylineCurve dimension")?;
    if m != n {
        return Err(Error::Invalid(format!(
            "ON_PolylineCurve has {n} points but {m} parameters"
        )));
    }
    if n < 2 {
        return Err(Error::Invalid(format!(
            "ON_PolylineCurve has {n} points; needs at least 2"
        )));
    }
    if t.iter().any(|x| !x.is_finite()) || t.windows(2).any(|w| w[0] >= w[1]) {
        return Err(Error::Invalid(
            "ON_PolylineCurve parameters are not finite and increasing".into(),
        ));
    }
    let domain = Interval::new(t[0], t[n - 1]);
    let step = domain.length() / (n - 1) as f64;
    let uniform = t.iter().enumerate().all(|(i, &ti)| {
        (ti - (domain.t0 + i as f64 * step)).abs()
            <= UNIFORM_PARAMETER_TOLERANCE * domain.length().max(domain.t0.abs()).max(1.0)
    });
    if uniform {
        let polyline = Polyline::new(points).map_err(geometry_error("ON_PolylineCurve"))?;
        Ok(Curve::Polyline { polyline, domain })
    } else {
        // Degree 1 in Rhino's knot form: one knot per point, the parameters themselves.
        NurbsCurve::new_non_rational(1, points, t)
            .map(Curve::Nurbs)
            .map_err(geometry_error("ON_PolylineCurve"))
    }
}

fn read_arc(r: &mut Reader<'_>) -> Result<Curve> {
    major_1(r, "ON_ArcCurve version")?;
    let origin = read_point(r, "ON_ArcCurve plane")?;
    let x = read_point(r, "ON_ArcCurve plane")? - Point3::ORIGIN;
    let y = read_point(r, "ON_ArcCurve plane")? - Point3::ORIGIN;
    r.skip(3 * 8 + 4 * 8, "ON_ArcCurve plane")?;
    let radius = r.f64("ON_ArcCurve radius")?;
    r.skip(9 * 8, "ON_ArcCurve legacy points")?;
    let angle = read_interval(r, "ON_ArcCurve angle")?;
    let domain = check_domain(read_interval(r, "ON_ArcCurve domain")?, "ON_ArcCurve")?;
    r.i32("ON_ArcCurve dimension")?;
    let plane = Plane::from_frame(origin, x, y).map_err(geometry_error("ON_ArcCurve plane"))?;
    let circle = Circle::new(plane, radius).map_err(geometry_error("ON_ArcCurve"))?;
    let sweep = angle.t1 - angle.t0;
    if (sweep - std::f64::consts::TAU).abs() <= 1e-12 * std::f64::consts::TAU && angle.t0 == 0.0 {
        return Ok(Curve::Circle { circle, domain });
    }
    let arc = Arc::new(circle, angle).map_err(geometry_error("ON_ArcCurve"))?;
    Ok(Curve::Arc { arc, domain })
}

fn read_polycurve(r: &mut Reader<'_>, v: Versions, depth: usize) -> Result<Curve> {
    major_1(r, "ON_PolyCurve version")?;
    // Each segment is an object record of at least 60 bytes.
    let n = r.count(60, "ON_PolyCurve segments")?;
    r.skip(8 + 48, "ON_PolyCurve reserved fields")?;
    let m = r.count(8, "ON_PolyCurve parameters")?;
    let t = r.f64s(m, "ON_PolyCurve parameters")?;
    if n == 0 || m != n + 1 {
        return Err(Error::Invalid(format!(
            "ON_PolyCurve has {n} segments and {m} parameters; needs one more parameter than \
             segments"
        )));
    }
    if depth + 1 >= crate::binary::MAX_DEPTH / 4 {
        return Err(Error::Invalid(
            "ON_PolyCurve segments nested too deeply".into(),
        ));
    }
    let mut segments = Vec::with_capacity(n);
    for i in 0..n {
        match read_object(r, v, depth + 1)? {
            Geometry::Curve(c) => segments.push(c.to_nurbs()),
            other => {
                return Err(Error::Invalid(format!(
                    "ON_PolyCurve segment {i} is a {}, not a curve",
                    other.rhino_type_name()
                )));
            }
        }
    }
    polycurve::join(&segments, &t).map(Curve::Nurbs)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn round_trip(c: Curve) -> Curve {
        let bytes = crate::encode(&Geometry::Curve(c)).unwrap();
        match crate::decode(&bytes).unwrap() {
            Geometry::Curve(c) => c,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn lines_polylines_arcs_and_circles_round_trip() {
        let line = Curve::Line {
            line: Line {
                from: Point3::new(1.0, 2.0, 3.0),
                to: Point3::new(4.0, 6.0, 3.0),
            },
            domain: Interval::new(0.0, 5.0),
        };
        assert_eq!(round_trip(line.clone()), line);
        let pl = Polyline::new(vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(3.0, 1.0, 0.5),
        ])
        .unwrap();
        let polyline = Curve::Polyline {
            polyline: pl,
            domain: Interval::new(0.0, 3.0),
        };
        assert_eq!(round_trip(polyline.clone()), polyline);
        let circle = Circle::new(Plane::WORLD_XY, 2.5).unwrap();
        let c = Curve::Circle {
            circle,
            domain: Interval::new(0.0, std::f64::consts::TAU),
        };
        assert_eq!(round_trip(c.clone()), c);
        let arc = Arc::new(circle, Interval::new(0.5, 2.0)).unwrap();
        let a = Curve::Arc {
            arc,
            domain: Interval::new(0.5, 2.0),
        };
        assert_eq!(round_trip(a.clone()), a);
    }
}
