//! Surface › Analysis: Area and Volume, the mass properties of B-reps, surfaces, boxes and
//! planar closed curves.
//!
//! B-reps and surfaces are integrated by the kernel ([`Brep::area_properties`],
//! [`Brep::volume_properties`], [`NurbsSurface::area_properties`]); boxes and circles have
//! exact formulas. A closed planar curve's area is that of the region it bounds, by Green's
//! theorem in the curve's plane: `A = ½∮(u dv − v du)`, with the centroid from
//! `∬u dA = ½∮u² dv` and `∬v dA = −½∮v² du`, integrated with 5-point Gauss–Legendre
//! quadrature on [`PANELS_PER_SPAN`] panels per span (exact for polynomial spans up to degree
//! 5, and to rounding for rational ones such as conics). Curves must lie in a plane to within
//! [`PLANARITY_TOLERANCE`] of their size. Meshes are not supported (locus has no meshes).

use locus_kernel::{Brep, Curve, NurbsSurface, OrientedBox, Plane, Point3, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Value};

use super::brep::surface_node;
use crate::curve::curve_from_value;

/// Id of [`area`].
pub const AREA: &str = "surface.area";
/// Id of [`volume`].
pub const VOLUME: &str = "surface.volume";

/// How far, relative to its size (the diagonal of its bounding box), a curve may leave its
/// plane and still count as planar: 1e-9.
pub const PLANARITY_TOLERANCE: f64 = 1e-9;

/// Quadrature panels per polynomial span of a curve: 16.
pub const PANELS_PER_SPAN: usize = 16;

/// Registers Area and Volume.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(area());
    registry.register(volume());
}

fn geometry_input(what: &str) -> Port {
    Port::new("Geometry", "G", DataType::Generic).doc(what)
}

fn finite_brep(brep: &Brep) -> Result<(), NodeError> {
    let finite = brep.vertices().iter().all(|v| v.point.is_finite())
        && brep.faces().iter().all(|f| f.surface.is_finite());
    if finite {
        Ok(())
    } else {
        Err("the brep has a coordinate that is not finite".into())
    }
}

fn finite_box(b: &OrientedBox) -> Result<(), NodeError> {
    if b.is_finite() {
        Ok(())
    } else {
        Err("the box is not finite".into())
    }
}

/// Area \[Area\]: the area and area centroid of geometry.
pub fn area() -> NodeType {
    surface_node(AREA, "Area", "Area", "Analysis")
        .gh_guid("2e205f24-9279-47b2-b414-d06dcd0b21a7")
        .gh_guid("86b28a7e-94d9-4791-8306-e13e10d5f8d5")
        .description(
            "Solves the area of geometry and the centroid of that area: the total area of a \
             B-rep's faces (within their trims) or of a surface, the six sides of a box, or \
             the region bounded by a closed planar curve (circles exactly, other curves by \
             Green's theorem in their plane). Open or non-planar curves and geometry without \
             area (points, lines, planes) are an error naming the type.",
        )
        .input(geometry_input(
            "The geometry to measure: a B-rep, surface, box, or closed planar curve (circle, \
             polyline, NURBS curve).",
        ))
        .output(Port::new("Area", "A", DataType::Number).doc("The area, in square model units."))
        .output(
            Port::new("Centroid", "C", DataType::Point)
                .doc("The area centroid: the mean of the geometry's points weighted by area."),
        )
        .solve(|s| {
            let value = s
                .value(0)
                .ok_or_else(|| NodeError::from("input G has no item"))?;
            let (a, c) = area_of(&value)?;
            s.set(0, a);
            s.set(1, c);
            Ok(())
        })
}

/// The area and area centroid of a value.
///
/// # Errors
/// When the value has no area (see [`area`]) or the geometry is degenerate or not finite.
pub fn area_of(value: &Value) -> Result<(f64, Point3), NodeError> {
    match value {
        Value::Brep(b) => {
            finite_brep(b)?;
            if b.faces().is_empty() {
                return Err("the brep has no faces, so no area".into());
            }
            let p = b.area_properties()?;
            Ok((p.area, p.centroid))
        }
        Value::Surface(srf) => surface_area(srf),
        Value::Box(b) => {
            finite_box(b)?;
            Ok((b.area(), b.center()))
        }
        Value::Line(_) | Value::Arc(_) | Value::Circle(_) | Value::Curve(_) => {
            let curve = curve_from_value(value).ok_or("not a curve")?;
            curve_area(&curve)
        }
        other => Err(NodeError(format!(
            "a {} has no area: give a brep, surface, box or closed planar curve",
            other.data_type().name().to_lowercase()
        ))),
    }
}

fn surface_area(srf: &Shared<NurbsSurface>) -> Result<(f64, Point3), NodeError> {
    if !srf.is_finite() {
        return Err("the surface has a coordinate that is not finite".into());
    }
    let p = srf.area_properties()?;
    Ok((p.area, p.centroid))
}

/// 5-point Gauss–Legendre nodes on `[-1, 1]` and their weights.
const GAUSS_5: [(f64, f64); 5] = [
    (0.0, 0.568_888_888_888_888_9),
    (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
    (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
    (0.906_179_845_938_664, 0.236_926_885_056_189_1),
];

/// The area bounded by a closed planar curve and its centroid.
fn curve_area(curve: &Curve) -> Result<(f64, Point3), NodeError> {
    if !curve.is_valid() {
        return Err("the curve is not valid (not finite, or of zero length)".into());
    }
    if let Curve::Circle { circle, .. } = curve {
        return Ok((
            std::f64::consts::PI * circle.radius * circle.radius,
            circle.plane.origin,
        ));
    }
    if !curve.is_closed() {
        return Err("the curve is not closed, so it bounds no area".into());
    }
    let nurbs = curve.to_nurbs();
    let breaks = nurbs.span_breaks();
    // Samples for the plane: the span ends and points inside each span.
    let mut samples = Vec::new();
    for w in breaks.windows(2) {
        for k in 0..8 {
            samples.push(nurbs.point_at(w[0] + (w[1] - w[0]) * k as f64 / 8.0));
        }
    }
    let plane = curve_plane(&samples)?;
    let origin = plane.origin;
    let local = |p: Point3| {
        let d = p - origin;
        (d.dot(plane.x_axis), d.dot(plane.y_axis))
    };
    // Signed area and first moments in plane coordinates.
    let (mut a, mut mu, mut mv) = (0.0, 0.0, 0.0);
    for w in breaks.windows(2) {
        let h = (w[1] - w[0]) / PANELS_PER_SPAN as f64;
        for panel in 0..PANELS_PER_SPAN {
            let mid = w[0] + h * (panel as f64 + 0.5);
            for (x, weight) in GAUSS_5 {
                let t = mid + 0.5 * h * x;
                let (p, d1, _) = nurbs.point_and_derivatives_at(t);
                let (u, v) = local(p);
                let (du, dv) = (d1.dot(plane.x_axis), d1.dot(plane.y_axis));
                let wt = 0.5 * h * weight;
                a += wt * 0.5 * (u * dv - v * du);
                mu += wt * 0.5 * u * u * dv;
                mv -= wt * 0.5 * v * v * du;
            }
        }
    }
    let size = bbox_diagonal(&samples);
    if !a.is_finite() || a.abs() <= f64::EPSILON * size * size {
        return Err("the curve bounds no area (it is degenerate)".into());
    }
    Ok((a.abs(), plane.point_at(mu / a, mv / a, 0.0)))
}

fn bbox_diagonal(points: &[Point3]) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in points {
        for (k, c) in p.to_array().into_iter().enumerate() {
            lo[k] = lo[k].min(c);
            hi[k] = hi[k].max(c);
        }
    }
    Vector3::new(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]).length()
}

/// The plane of closed-curve samples: Newell's normal through their mean, checked for
/// planarity.
fn curve_plane(samples: &[Point3]) -> Result<Plane, NodeError> {
    let n = samples.len() as f64;
    let mean = samples
        .iter()
        .fold(Vector3::ZERO, |acc, p| acc + p.to_vector())
        / n;
    let centre = Point3::ORIGIN + mean;
    let mut normal = Vector3::ZERO;
    for (i, p) in samples.iter().enumerate() {
        let a = *p - centre;
        let b = samples[(i + 1) % samples.len()] - centre;
        normal += a.cross(b);
    }
    let plane = Plane::from_normal(centre, normal)
        .map_err(|_| NodeError::from("the curve spans no plane, so it bounds no area"))?;
    let size = bbox_diagonal(samples);
    let off = samples
        .iter()
        .map(|&p| plane.distance_to(p))
        .fold(0.0, f64::max);
    if off > PLANARITY_TOLERANCE * size {
        return Err(format!(
            "the curve is not planar (it leaves its plane by {off}), so it bounds no area"
        )
        .into());
    }
    Ok(plane)
}

/// Volume \[Volume\]: the enclosed volume and volume centroid of closed geometry.
pub fn volume() -> NodeType {
    surface_node(VOLUME, "Volume", "Volume", "Analysis")
        .gh_guid("224f7648-5956-4b26-80d9-8d771f3dfd5d")
        .gh_guid("7c0523e8-79c9-45a2-8777-cf0d46bc5432")
        .description(
            "Solves the volume enclosed by closed geometry and the centroid of that volume: a \
             closed B-rep (a solid, with no naked edges), a closed surface such as a sphere, \
             or a box. A B-rep whose faces point inwards gets a negative volume, with a \
             warning. Open B-reps and surfaces enclose no volume and are an error, and so is \
             geometry without volume (points, curves, planes).",
        )
        .input(geometry_input(
            "The closed geometry to measure: a closed B-rep, a closed surface, or a box.",
        ))
        .output(Port::new("Volume", "V", DataType::Number).doc("The volume, in cubic model units."))
        .output(
            Port::new("Centroid", "C", DataType::Point)
                .doc("The volume centroid: the centre of mass of a uniform solid."),
        )
        .solve(|s| {
            let value = s
                .value(0)
                .ok_or_else(|| NodeError::from("input G has no item"))?;
            let (v, c) = match &value {
                Value::Box(b) => {
                    finite_box(b)?;
                    (b.volume(), b.center())
                }
                Value::Brep(b) => closed_volume(b)?,
                Value::Surface(srf) => {
                    if !srf.is_finite() {
                        return Err("the surface has a coordinate that is not finite".into());
                    }
                    closed_volume(&Brep::from_surface((**srf).clone())?)?
                }
                other => {
                    return Err(NodeError(format!(
                        "a {} encloses no volume: give a closed brep, a closed surface or a box",
                        other.data_type().name().to_lowercase()
                    )));
                }
            };
            if v < 0.0 {
                s.warning("the faces point inwards, so the volume is negative");
            }
            s.set(0, v);
            s.set(1, c);
            Ok(())
        })
}

fn closed_volume(b: &Brep) -> Result<(f64, Point3), NodeError> {
    finite_brep(b)?;
    if !b.is_solid() {
        let naked = b.edges_of_kind(locus_kernel::EdgeKind::Naked).len();
        return Err(format!(
            "the brep is not closed ({naked} naked edges), so it encloses no volume"
        )
        .into());
    }
    let p = b.volume_properties()?;
    Ok((p.volume, p.centroid))
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use locus_kernel::{Circle, Cylinder, Interval, Line, NurbsCurve, Polyline, Sphere};
    use locus_runtime::{DataTree, NodeCall, NodeCallResult};

    use super::*;
    use crate::vector::test_support::{assert_clean, assert_error, is_null, only};

    fn run(node: NodeType, v: Value) -> NodeCallResult {
        NodeCall::new(&node).input(DataTree::from_value(v)).run()
    }

    fn brep(b: Brep) -> Value {
        Value::Brep(Shared::new(b))
    }

    fn a_box() -> OrientedBox {
        OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
            Interval::new(0.0, 4.0),
        )
    }

    fn assert_near(a: Point3, b: Point3, tol: f64) {
        assert!(a.distance(b) <= tol, "{a:?} vs {b:?}");
    }

    #[test]
    fn areas_of_boxes_and_their_faces() {
        let r = run(area(), Value::Box(a_box()));
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), 52.0);
        assert_eq!(only::<Point3>(&r, 1), Point3::new(1.0, 1.5, 2.0));
        let b = Brep::from_box(&a_box()).unwrap();
        let r = run(area(), brep(b.clone()));
        assert!((only::<f64>(&r, 0) - 52.0).abs() < 1e-12);
        assert_near(only::<Point3>(&r, 1), Point3::new(1.0, 1.5, 2.0), 1e-12);
        // The top face (z = 4) has its centroid at its centre.
        let r = run(area(), brep(b.extract_face(5).unwrap()));
        assert!((only::<f64>(&r, 0) - 6.0).abs() < 1e-12);
        assert_near(only::<Point3>(&r, 1), Point3::new(1.0, 1.5, 4.0), 1e-12);
    }

    #[test]
    fn areas_of_spheres_and_surfaces() {
        let c = Point3::new(1.0, -2.0, 3.0);
        let s = Sphere::new(c, 2.0).unwrap();
        let r = run(area(), brep(Brep::from_sphere(&s).unwrap()));
        assert!((only::<f64>(&r, 0) - 16.0 * PI).abs() < 1e-9);
        assert_near(only::<Point3>(&r, 1), c, 1e-9);
        let srf =
            NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::new(0.0, 2.0), Interval::UNIT)
                .unwrap();
        let r = run(area(), Value::Surface(Shared::new(srf)));
        assert!((only::<f64>(&r, 0) - 2.0).abs() < 1e-12);
        assert_near(only::<Point3>(&r, 1), Point3::new(1.0, 0.5, 0.0), 1e-12);
    }

    #[test]
    fn areas_of_closed_planar_curves() {
        let plane =
            Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(1.0, 1.0, 1.0)).unwrap();
        let circle = Circle::new(plane, 1.5).unwrap();
        let r = run(area(), Value::Circle(circle));
        assert_eq!(only::<f64>(&r, 0), PI * 2.25);
        assert_eq!(only::<Point3>(&r, 1), plane.origin);
        // The same circle as a rational NURBS curve, by quadrature.
        let nurbs = Curve::from(circle).to_nurbs();
        let r = run(area(), Value::Curve(Shared::new(Curve::Nurbs(nurbs))));
        assert!(
            (only::<f64>(&r, 0) - PI * 2.25).abs() < 1e-12,
            "{}",
            only::<f64>(&r, 0)
        );
        assert_near(only::<Point3>(&r, 1), plane.origin, 1e-12);
        // An L-shaped polyline: area 3, centroid by hand from squares at (0.5, 0.5),
        // (1.5, 0.5) and (0.5, 1.5): (5/6, 5/6).
        let l = Polyline::new(vec![
            Point3::ORIGIN,
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(2.0, 1.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(1.0, 2.0, 0.0),
            Point3::new(0.0, 2.0, 0.0),
            Point3::ORIGIN,
        ])
        .unwrap();
        let r = run(area(), Value::Curve(Shared::new(Curve::from(l.clone()))));
        assert!((only::<f64>(&r, 0) - 3.0).abs() < 1e-14);
        assert_near(
            only::<Point3>(&r, 1),
            Point3::new(5.0 / 6.0, 5.0 / 6.0, 0.0),
            1e-14,
        );
        // Clockwise gives the same.
        let mut pts = l.points().to_vec();
        pts.reverse();
        let cw = Polyline::new(pts).unwrap();
        let r = run(area(), Value::Curve(Shared::new(Curve::from(cw))));
        assert!((only::<f64>(&r, 0) - 3.0).abs() < 1e-14);
    }

    #[test]
    fn area_bad_input() {
        let line = Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0));
        assert_error(&run(area(), Value::Line(line)), "not closed");
        assert_error(
            &run(area(), Value::Point(Point3::ORIGIN)),
            "a point has no area",
        );
        let bent = Polyline::new(vec![
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 1.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::ORIGIN,
        ])
        .unwrap();
        assert_error(
            &run(area(), Value::Curve(Shared::new(Curve::from(bent)))),
            "not planar",
        );
        let flat = Polyline::new(vec![
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
            Point3::ORIGIN,
        ])
        .unwrap();
        assert!(
            !run(area(), Value::Curve(Shared::new(Curve::from(flat))))
                .messages
                .is_empty()
        );
        let nan = NurbsCurve::new_non_rational(
            1,
            vec![Point3::ORIGIN, Point3::new(f64::NAN, 0.0, 0.0)],
            vec![0.0, 1.0],
        );
        if let Ok(nan) = nan {
            let r = run(area(), Value::Curve(Shared::new(Curve::Nurbs(nan))));
            assert!(is_null(&r, 0));
        }
        assert_error(&run(area(), brep(Brep::default())), "no faces");
        let nan_box = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, f64::NAN),
            Interval::UNIT,
            Interval::UNIT,
        );
        assert_error(&run(area(), Value::Box(nan_box)), "not finite");
    }

    #[test]
    fn volumes_of_solids() {
        let r = run(volume(), Value::Box(a_box()));
        assert_clean(&r);
        assert_eq!(only::<f64>(&r, 0), 24.0);
        let r = run(volume(), brep(Brep::from_box(&a_box()).unwrap()));
        assert!((only::<f64>(&r, 0) - 24.0).abs() < 1e-12);
        assert_near(only::<Point3>(&r, 1), Point3::new(1.0, 1.5, 2.0), 1e-12);
        let c = Point3::new(1.0, -2.0, 3.0);
        let s = Sphere::new(c, 2.0).unwrap();
        let r = run(volume(), brep(Brep::from_sphere(&s).unwrap()));
        assert!((only::<f64>(&r, 0) - 32.0 / 3.0 * PI).abs() < 1e-9);
        assert_near(only::<Point3>(&r, 1), c, 1e-9);
        // A sphere given as a surface is closed too.
        let r = run(volume(), Value::Surface(Shared::new(s.to_nurbs().unwrap())));
        assert!((only::<f64>(&r, 0) - 32.0 / 3.0 * PI).abs() < 1e-9);
        // A capped cylinder: πr²h, centroid halfway up the axis.
        let cyl =
            Brep::from_cylinder(&Cylinder::new(Plane::WORLD_XY, 1.5, 4.0).unwrap(), true).unwrap();
        let r = run(volume(), brep(cyl));
        assert!((only::<f64>(&r, 0) - PI * 2.25 * 4.0).abs() < 1e-9);
        assert_near(only::<Point3>(&r, 1), Point3::new(0.0, 0.0, 2.0), 1e-9);
    }

    #[test]
    fn volume_bad_input() {
        let b = Brep::from_box(&a_box()).unwrap();
        let r = run(volume(), brep(b.extract_face(0).unwrap()));
        assert_error(&r, "not closed (4 naked edges)");
        assert!(is_null(&r, 0) && is_null(&r, 1));
        let srf =
            NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::UNIT, Interval::UNIT).unwrap();
        assert_error(
            &run(volume(), Value::Surface(Shared::new(srf))),
            "not closed",
        );
        assert_error(
            &run(volume(), Value::Point(Point3::ORIGIN)),
            "a point encloses no volume",
        );
        assert_error(&run(volume(), brep(Brep::default())), "not closed");
        let flat = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::UNIT,
            Interval::new(0.0, 0.0),
        );
        assert_eq!(only::<f64>(&run(volume(), Value::Box(flat)), 0), 0.0);
    }
}
