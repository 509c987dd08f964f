//! Curve › Primitive, rectangles from points: Rectangle 2Pt and Rectangle 3Pt.
//!
//! Both make closed polylines of four sides, as the Rectangle node does (the runtime has no
//! rectangle value; the Rectangle parameter checks such polylines); a corner radius above 0
//! rounds the corners with tangent arcs, as the Rectangle node does.

use locus_kernel::{Plane, Point3, Polyline};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port};

use super::primitive_more::{curve_of, set_rounded};

/// Id of [`rectangle_2pt`].
pub const RECTANGLE_2PT: &str = "curve.rectangle_2pt";
/// Id of [`rectangle_3pt`].
pub const RECTANGLE_3PT: &str = "curve.rectangle_3pt";

/// Registers the nodes of this module.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(rectangle_2pt());
    registry.register(rectangle_3pt());
}

fn primitive(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Curve").subcategory("Primitive")
}

fn outputs(node: NodeType) -> NodeType {
    node.output(
        Port::new("Rectangle", "R", DataType::Curve)
            .doc("The rectangle, a closed polyline of four sides."),
    )
    .output(Port::new("Length", "L", DataType::Number).doc("The perimeter."))
}

/// The closed polyline `a, a + u, a + u + v, a + v, a`.
fn closed(
    a: Point3,
    u: locus_kernel::Vector3,
    v: locus_kernel::Vector3,
) -> Result<Polyline, NodeError> {
    Ok(Polyline::new(vec![a, a + u, a + u + v, a + v, a])?)
}

/// The rectangle on `plane` spanned by the projections of `a` and `b`: from its corner of
/// least plane coordinates, first along the plane's x axis.
///
/// # Errors
/// When the plane is not valid, a point is not finite, or the projections share an x or a y
/// coordinate (a rectangle of no area).
pub fn rectangle_from_corners(plane: &Plane, a: Point3, b: Point3) -> Result<Polyline, NodeError> {
    if !plane.is_valid() {
        return Err("plane P is not valid".into());
    }
    if !(a.is_finite() && b.is_finite()) {
        return Err("a corner point has a coordinate that is not finite".into());
    }
    let (ua, va) = plane.closest_parameter(a);
    let (ub, vb) = plane.closest_parameter(b);
    let (x0, x1) = (ua.min(ub), ua.max(ub));
    let (y0, y1) = (va.min(vb), va.max(vb));
    if x0 == x1 || y0 == y1 {
        return Err(NodeError(format!(
            "points A and B span {} by {} in the plane, a rectangle of no area",
            x1 - x0,
            y1 - y0
        )));
    }
    let corner = plane.origin + plane.x_axis * x0 + plane.y_axis * y0;
    closed(corner, plane.x_axis * (x1 - x0), plane.y_axis * (y1 - y0))
}

/// Rectangle 2Pt \[Rec 2Pt\]: a rectangle from two opposite corners.
pub fn rectangle_2pt() -> NodeType {
    outputs(
        primitive(RECTANGLE_2PT, "Rectangle 2Pt", "Rec 2Pt")
            .gh_guid("575660b1-8c79-4b8d-9222-7ab4a6ddb359")
            .description(
                "Creates a rectangle on a plane from two opposite corners: the points are \
                 projected onto the plane and the rectangle spans them along its axes, from \
                 the corner of least plane coordinates towards +x. Corners sharing an x or y \
                 coordinate in the plane are an error. A corner radius R above 0 rounds each \
                 corner with the tangent arc of that radius (up to half the shorter side; a \
                 larger one is reduced to it, with a warning).",
            )
            .input(
                Port::new("Plane", "P", DataType::Plane)
                    .doc("The rectangle's plane; default World XY.")
                    .default_value(Plane::WORLD_XY),
            )
            .input(
                Port::new("Point A", "A", DataType::Point)
                    .doc("The first corner; default (0, 0, 0).")
                    .default_value(Point3::ORIGIN),
            )
            .input(
                Port::new("Point B", "B", DataType::Point)
                    .doc("The opposite corner; default (1, 1, 0).")
                    .default_value(Point3::new(1.0, 1.0, 0.0)),
            )
            .input(
                Port::new("Radius", "R", DataType::Number)
                    .doc("The corner radius; 0 (the default) for sharp corners.")
                    .default_value(0.0),
            ),
    )
    .solve(|s| {
        let plane = *s.item::<Plane>(0)?;
        let (a, b) = (*s.item::<Point3>(1)?, *s.item::<Point3>(2)?);
        let radius = *s.item::<f64>(3)?;
        let poly = rectangle_from_corners(&plane, a, b)?;
        let sides = poly.points();
        let half = 0.5
            * (sides[1] - sides[0])
                .length()
                .min((sides[2] - sides[1]).length());
        set_rounded(s, poly, radius, half, "R")
    })
}

/// The rectangle with side A→B whose opposite side passes through C: corners A, B, then B and A
/// moved by the part of C − A perpendicular to AB.
///
/// # Errors
/// When a point is not finite, A and B coincide, or C lies on the line AB.
pub fn rectangle_from_three_points(a: Point3, b: Point3, c: Point3) -> Result<Polyline, NodeError> {
    let plane = Plane::from_points(a, b, c)
        .map_err(|e| NodeError(format!("points A, B and C make no rectangle: {e}")))?;
    let width = (b - a).length();
    let height = (c - a).dot(plane.y_axis);
    if !(width > 0.0 && height > 0.0) {
        return Err("points A, B and C make no rectangle: C lies on the line AB".into());
    }
    closed(a, b - a, plane.y_axis * height)
}

/// Rectangle 3Pt \[Rec 3Pt\]: a rectangle from a side and a point on the opposite side.
pub fn rectangle_3pt() -> NodeType {
    outputs(
        primitive(RECTANGLE_3PT, "Rectangle 3Pt", "Rec 3Pt")
            .gh_guid("9bc98a1d-2ecc-407e-948a-09a09ed3e69d")
            .description(
                "Creates a rectangle from three points: A to B is its first side and the \
                 opposite side passes through C (its height is the distance of C from the \
                 line AB). Coincident or collinear points are an error.",
            )
            .input(
                Port::new("Point A", "A", DataType::Point)
                    .doc("The first corner; default (0, 0, 0).")
                    .default_value(Point3::ORIGIN),
            )
            .input(
                Port::new("Point B", "B", DataType::Point)
                    .doc("The second corner, along the first side; default (1, 0, 0).")
                    .default_value(Point3::new(1.0, 0.0, 0.0)),
            )
            .input(
                Port::new("Point C", "C", DataType::Point)
                    .doc("A point on the side opposite AB; default (0, 1, 0).")
                    .default_value(Point3::new(0.0, 1.0, 0.0)),
            ),
    )
    .lift3_with(|a: &Point3, b: &Point3, c: &Point3, _report| {
        let poly = rectangle_from_three_points(*a, *b, *c)?;
        let length = poly.length();
        Ok((curve_of(poly), length))
    })
}

#[cfg(test)]
mod tests {
    use locus_kernel::Curve;
    use locus_runtime::{DataTree, NodeCall, NodeCallResult, Shared};

    use super::*;
    use crate::test_support::{assert_error, only};

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    fn corners(r: &NodeCallResult) -> Vec<Point3> {
        match only::<Shared<Curve>>(r, 0).as_ref() {
            Curve::Polyline { polyline, .. } => polyline.points().to_vec(),
            other => panic!("not a polyline: {other:?}"),
        }
    }

    #[test]
    fn rectangle_2pt_spans_the_projected_corners() {
        let r = NodeCall::new(&rectangle_2pt())
            .skip_input()
            .input(DataTree::from_item(p(3.0, 1.0, 5.0)))
            .input(DataTree::from_item(p(1.0, 2.0, -1.0)))
            .run();
        assert_eq!(
            corners(&r),
            [
                p(1.0, 1.0, 0.0),
                p(3.0, 1.0, 0.0),
                p(3.0, 2.0, 0.0),
                p(1.0, 2.0, 0.0),
                p(1.0, 1.0, 0.0)
            ]
        );
        assert_eq!(only::<f64>(&r, 1), 6.0);
        let r = NodeCall::new(&rectangle_2pt())
            .skip_input()
            .input(DataTree::from_item(p(1.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(1.0, 2.0, 0.0)))
            .run();
        assert_error(&r, "a rectangle of no area");
        let r = NodeCall::new(&rectangle_2pt())
            .skip_input()
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(-0.5))
            .run();
        assert_error(&r, "corner radius R");
    }

    /// A 2 × 1 rectangle with corners of radius 0.25: each corner trades 2r of straight side
    /// for a quarter circle, so the length is 6 − 8r + 2πr; every point lies on the rounded
    /// outline. A radius above half the shorter side is reduced to it (a stadium: two half
    /// circles and two sides of length 1), with a warning.
    #[test]
    fn rounded_rectangle_2pt() {
        let run = |radius: f64| {
            NodeCall::new(&rectangle_2pt())
                .skip_input()
                .input(DataTree::from_item(p(0.0, 0.0, 0.0)))
                .input(DataTree::from_item(p(2.0, 1.0, 0.0)))
                .input(DataTree::from_item(radius))
                .run()
        };
        let r = run(0.25);
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let length = only::<f64>(&r, 1);
        let want = 6.0 - 8.0 * 0.25 + std::f64::consts::TAU * 0.25;
        assert!((length - want).abs() < 1e-12, "{length} {want}");
        let curve = only::<Shared<Curve>>(&r, 0);
        assert!(curve.is_closed());
        for k in 0..200 {
            let d = curve.domain();
            let q = curve.point_at(d.t0 + d.length() * k as f64 / 200.0);
            // Distance from the inner rectangle [0.25, 1.75] × [0.25, 0.75] is the radius.
            let dx = (q.x - q.x.clamp(0.25, 1.75)).abs();
            let dy = (q.y - q.y.clamp(0.25, 0.75)).abs();
            let off = if dx > 0.0 && dy > 0.0 {
                dx.hypot(dy)
            } else {
                dx.max(dy)
            };
            assert!((off - 0.25).abs() < 1e-12, "{q:?} {off}");
        }
        let r = run(0.6);
        let want = 2.0 + std::f64::consts::PI;
        assert!(
            (only::<f64>(&r, 1) - want).abs() < 1e-12,
            "{}",
            only::<f64>(&r, 1)
        );
        assert_eq!(r.messages.len(), 1, "{:?}", r.messages);
        assert!(
            r.messages[0].text.contains("0.5, is used"),
            "{:?}",
            r.messages
        );
    }

    #[test]
    fn rectangle_3pt_takes_the_height_from_c() {
        let r = NodeCall::new(&rectangle_3pt())
            .input(DataTree::from_item(p(0.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(4.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(7.0, 3.0, 0.0)))
            .run();
        let c = corners(&r);
        let expected = [(0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0), (0.0, 0.0)];
        for (q, (x, y)) in c.iter().zip(expected) {
            assert!((*q - p(x, y, 0.0)).length() < 1e-15, "{q:?}");
        }
        assert!((only::<f64>(&r, 1) - 14.0).abs() < 1e-14);
        let r = NodeCall::new(&rectangle_3pt())
            .input(DataTree::from_item(p(0.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(4.0, 0.0, 0.0)))
            .input(DataTree::from_item(p(8.0, 0.0, 0.0)))
            .run();
        assert_error(&r, "make no rectangle");
    }
}
