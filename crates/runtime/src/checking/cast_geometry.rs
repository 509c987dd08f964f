//! The conversions of the casting table between geometry types: tight world bounding boxes for
//! Box inputs, lines, circles and arcs as curves and back, lengths, domains and planes of
//! curves, planes of circles, arcs and boxes, and the surface of a one-face B-rep. The rules
//! are listed in `docs/casting.md`.

use std::f64::consts::{PI, TAU};

use locus_kernel::{
    Arc, BoundingBox, Brep, Circle, Curve, Line, NurbsSurface, OrientedBox, Plane, Point3,
};

use crate::Shared;

/// The world-aligned box of a bounding box; boxes with a NaN or infinite corner fail.
fn world_box(bbox: BoundingBox) -> Option<OrientedBox> {
    (bbox.is_finite() && bbox.is_valid()).then(|| OrientedBox::from_bounding_box(&bbox))
}

/// The smallest world box around points; `None` for no points or non-finite ones.
fn points_box(points: &[Point3]) -> Option<OrientedBox> {
    BoundingBox::from_points(points).ok().and_then(world_box)
}

/// A point becomes a box of zero size at the point.
pub(crate) fn point_to_box(p: &Point3) -> Option<OrientedBox> {
    points_box(&[*p])
}

/// The world box of a line: its two end points.
pub(crate) fn line_to_box(line: &Line) -> Option<OrientedBox> {
    points_box(&[line.from, line.to])
}

/// The exact world box of a circle: along each world axis `k` the circle reaches
/// `radius · √(x_k² + y_k²)` either side of its centre (`x`, `y` its plane's axes).
fn circle_bounds(circle: &Circle) -> BoundingBox {
    let (x, y, r) = (
        circle.plane.x_axis,
        circle.plane.y_axis,
        circle.radius.abs(),
    );
    let half = [r * x.x.hypot(y.x), r * x.y.hypot(y.y), r * x.z.hypot(y.z)];
    let c = circle.center();
    BoundingBox::new(
        Point3::new(c.x - half[0], c.y - half[1], c.z - half[2]),
        Point3::new(c.x + half[0], c.y + half[1], c.z + half[2]),
    )
}

pub(crate) fn circle_to_box(circle: &Circle) -> Option<OrientedBox> {
    world_box(circle_bounds(circle))
}

/// The exact world box of an arc: its end points, plus each point where a world coordinate
/// is extreme on the circle (two angles per axis) that lies within the arc's angles.
fn arc_bounds(arc: &Arc) -> BoundingBox {
    let circle = &arc.circle;
    let (lo, hi) = (
        arc.angle.t0.min(arc.angle.t1),
        arc.angle.t0.max(arc.angle.t1),
    );
    let mut bbox = BoundingBox::new(circle.point_at(lo), circle.point_at(hi));
    if hi - lo >= TAU {
        return circle_bounds(circle);
    }
    let (x, y) = (circle.plane.x_axis, circle.plane.y_axis);
    for (xk, yk) in [(x.x, y.x), (x.y, y.y), (x.z, y.z)] {
        if xk == 0.0 && yk == 0.0 {
            continue;
        }
        // The coordinate is c + r·(cos θ·xk + sin θ·yk), extreme where tan θ = yk / xk.
        let extreme = yk.atan2(xk);
        for theta in [extreme, extreme + PI] {
            let t = lo + (theta - lo).rem_euclid(TAU);
            if t <= hi {
                bbox.include_point(circle.point_at(t));
            }
        }
    }
    bbox
}

pub(crate) fn arc_to_box(arc: &Arc) -> Option<OrientedBox> {
    world_box(arc_bounds(arc))
}

/// The tight world box of a curve: exact for lines, polylines, circles and arcs; for NURBS
/// curves the kernel's tight box (ends and the points where a coordinate's derivative
/// vanishes, to rounding), not the looser box of the control points.
pub(crate) fn curve_to_box(curve: &Shared<Curve>) -> Option<OrientedBox> {
    match &**curve {
        Curve::Line { line, .. } => line_to_box(line),
        Curve::Polyline { polyline, .. } => points_box(polyline.points()),
        Curve::Circle { circle, .. } => circle_to_box(circle),
        Curve::Arc { arc, .. } => arc_to_box(arc),
        Curve::Nurbs(nurbs) if nurbs.is_finite() => world_box(nurbs.bounding_box()),
        Curve::Nurbs(_) => None,
    }
}

/// The tight world box of a surface over its whole domain (Rhino's accurate
/// `GetBoundingBox(true)`); a surface with a NaN or infinite number fails.
pub(crate) fn surface_to_box(surface: &Shared<NurbsSurface>) -> Option<OrientedBox> {
    if !surface.is_finite() {
        return None;
    }
    world_box(surface.bounding_box())
}

/// The tight world box of a B-rep: its vertices, edges and the extremes of its faces inside
/// their trims. An empty B-rep and one with a NaN or infinite number fail.
pub(crate) fn brep_to_box(brep: &Shared<Brep>) -> Option<OrientedBox> {
    if brep.faces().is_empty() && brep.edges().is_empty() && brep.vertices().is_empty() {
        return None;
    }
    let finite = brep.vertices().iter().all(|v| v.point.is_finite())
        && brep.faces().iter().all(|f| f.surface.is_finite())
        && brep.edges().iter().all(|e| e.curve.is_finite());
    if !finite {
        return None;
    }
    world_box(brep.bounding_box())
}

/// The surface of a B-rep with exactly one face: the face's underlying surface, untrimmed
/// (Rhino's `BrepFace.DuplicateSurface`, as Grasshopper casts a one-face B-rep to a surface).
/// B-reps with no face or several fail.
pub(crate) fn brep_to_surface(brep: &Shared<Brep>) -> Option<Shared<NurbsSurface>> {
    match brep.faces() {
        [face] => Some(Shared::new(face.surface.clone())),
        _ => None,
    }
}

/// The line inside a curve, if the curve is a line.
pub(crate) fn curve_to_line(curve: &Shared<Curve>) -> Option<Line> {
    match &**curve {
        Curve::Line { line, .. } => Some(*line),
        _ => None,
    }
}

/// The circle inside a curve, if the curve is a full circle.
pub(crate) fn curve_to_circle(curve: &Shared<Curve>) -> Option<Circle> {
    match &**curve {
        Curve::Circle { circle, .. } => Some(*circle),
        _ => None,
    }
}

/// The arc inside a curve, if the curve is an arc.
pub(crate) fn curve_to_arc(curve: &Shared<Curve>) -> Option<Arc> {
    match &**curve {
        Curve::Arc { arc, .. } => Some(*arc),
        _ => None,
    }
}

/// The plane of a circle or arc (the circle's own plane, origin at the centre).
pub(crate) fn circle_plane(circle: &Circle) -> Option<Plane> {
    circle.plane.is_finite().then_some(circle.plane)
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_kernel::{Interval, NurbsCurve, Polyline, Vector3};

    const EPS: f64 = 1e-12;

    fn assert_box(b: Option<OrientedBox>, min: [f64; 3], max: [f64; 3]) {
        let b = b.expect("a box");
        assert_eq!(b.plane, Plane::WORLD_XY);
        for (got, want) in [
            (b.x.t0, min[0]),
            (b.y.t0, min[1]),
            (b.z.t0, min[2]),
            (b.x.t1, max[0]),
            (b.y.t1, max[1]),
            (b.z.t1, max[2]),
        ] {
            assert!((got - want).abs() < EPS, "{b:?}: {got} ≠ {want}");
        }
    }

    #[test]
    fn circles_have_exact_boxes() {
        let flat = Circle::new(
            Plane {
                origin: Point3::new(1.0, 2.0, 3.0),
                ..Plane::WORLD_XY
            },
            2.0,
        )
        .unwrap();
        assert_box(circle_to_box(&flat), [-1.0, 0.0, 3.0], [3.0, 4.0, 3.0]);
        // A circle about the x axis tilted 45°: extent 2·cos45° in y and z.
        let tilted =
            Circle::from_center_normal(Point3::ORIGIN, Vector3::new(0.0, 1.0, 1.0), 2.0).unwrap();
        let h = 2.0 * std::f64::consts::FRAC_1_SQRT_2;
        assert_box(circle_to_box(&tilted), [-2.0, -h, -h], [2.0, h, h]);
    }

    #[test]
    fn arcs_include_the_extremes_they_pass() {
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let quarter = Arc::new(circle, Interval::new(0.0, PI / 2.0)).unwrap();
        assert_box(arc_to_box(&quarter), [0.0, 0.0, 0.0], [1.0, 1.0, 0.0]);
        // From 45° to 180°: passes the top (y = 1) and ends at x = −1.
        let wide = Arc::new(circle, Interval::new(PI / 4.0, PI)).unwrap();
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert_box(arc_to_box(&wide), [-1.0, 0.0, 0.0], [s, 1.0, 0.0]);
        // Angles past 2π wrap: 350° to 370° passes 0° (x = 1).
        let across = Arc::new(
            circle,
            Interval::new(350_f64.to_radians(), 370_f64.to_radians()),
        )
        .unwrap();
        let b = arc_to_box(&across).unwrap();
        assert!((b.x.t1 - 1.0).abs() < EPS);
        let full = Arc::new(circle, Interval::new(0.0, TAU)).unwrap();
        assert_box(arc_to_box(&full), [-1.0, -1.0, 0.0], [1.0, 1.0, 0.0]);
    }

    #[test]
    fn curves_box_by_kind() {
        let line = Line::new(Point3::new(1.0, 5.0, 0.0), Point3::new(-1.0, 2.0, 4.0));
        assert_box(
            curve_to_box(&Shared::new(Curve::from(line))),
            [-1.0, 2.0, 0.0],
            [1.0, 5.0, 4.0],
        );
        let polyline = Polyline::new(vec![
            Point3::ORIGIN,
            Point3::new(2.0, 1.0, 0.0),
            Point3::new(1.0, -3.0, 1.0),
        ])
        .unwrap();
        assert_box(
            curve_to_box(&Shared::new(Curve::from(polyline))),
            [0.0, -3.0, 0.0],
            [2.0, 1.0, 1.0],
        );
        let nurbs = NurbsCurve::new_non_rational(
            2,
            vec![
                Point3::ORIGIN,
                Point3::new(1.0, 2.0, 0.0),
                Point3::new(2.0, 0.0, 0.0),
            ],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap();
        // The box is tight: the parabola peaks at y = 1, its control points reach y = 2.
        assert_box(
            curve_to_box(&Shared::new(Curve::from(nurbs))),
            [0.0, 0.0, 0.0],
            [2.0, 1.0, 0.0],
        );
    }

    #[test]
    fn non_finite_geometry_has_no_box() {
        assert!(point_to_box(&Point3::new(f64::NAN, 0.0, 0.0)).is_none());
        let line = Line::new(Point3::ORIGIN, Point3::new(f64::INFINITY, 0.0, 0.0));
        assert!(line_to_box(&line).is_none());
    }

    #[test]
    fn breps_box_tight_and_unwrap_one_face() {
        // A dome over [0, 2]²: the middle control point at z = 4 lifts the
        // biquadratic surface to z = 1 at its centre only.
        let points = (0..3)
            .map(|i| {
                (0..3)
                    .map(|j| {
                        let z = if (i, j) == (1, 1) { 4.0 } else { 0.0 };
                        Point3::new(i as f64, j as f64, z)
                    })
                    .collect()
            })
            .collect();
        let knots = vec![0.0, 0.0, 1.0, 1.0];
        let surface =
            NurbsSurface::new(2, 2, points, vec![vec![1.0; 3]; 3], knots.clone(), knots).unwrap();
        let loose = surface.control_bounding_box();
        assert_eq!(loose.max.z, 4.0);
        let srf = Shared::new(surface.clone());
        assert_box(surface_to_box(&srf), [0.0, 0.0, 0.0], [2.0, 2.0, 1.0]);
        let brep = Shared::new(Brep::from_surface(surface.clone()).unwrap());
        assert_box(brep_to_box(&brep), [0.0, 0.0, 0.0], [2.0, 2.0, 1.0]);
        assert_eq!(brep_to_surface(&brep).as_deref(), Some(&surface));
        assert!(brep_to_box(&Shared::new(Brep::default())).is_none());
        assert!(brep_to_surface(&Shared::new(Brep::default())).is_none());
    }

    #[test]
    fn curves_unwrap_to_their_own_kind_only() {
        let line = Line::new(Point3::ORIGIN, Point3::new(3.0, 4.0, 0.0));
        let curve = Shared::new(Curve::from(line));
        assert_eq!(curve_to_line(&curve), Some(line));
        assert_eq!(curve_to_circle(&curve), None);
        assert_eq!(curve_to_arc(&curve), None);
    }
}
