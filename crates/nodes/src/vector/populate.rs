//! Vector › Grid, random points: Populate 2D (a rectangle), Populate 3D (a box) and Populate
//! Geometry (curves, surfaces, B-reps and meshes, through [`GeometrySampler`]).
//!
//! The points are spread by best-candidate sampling ([`best_candidate_samples`]): each new
//! point is the one of [`BEST_CANDIDATES`](locus_kernel::BEST_CANDIDATES) random candidates farthest from the points before it
//! and from the existing points given, so that they spread out rather than clump. The random
//! numbers are .NET's `System.Random(seed)` ([`DotNetRandom`], as the Random node draws
//! them), one generator per solve call, so a seed gives the same points on every run and with
//! any number of threads. Grasshopper's own candidate count and draw order are not published;
//! its points for a seed differ from these, but are spread the same way.

use locus_kernel::{
    Brep, Curve, GeometrySampler, MeshingParameters, OrientedBox, Point3, Vector3,
    best_candidate_samples, spread_points,
};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve, Value};

use crate::params::shapes::not_a_rectangle;
use crate::sets::random::DotNetRandom;

/// Id of [`populate_2d`].
pub const POPULATE_2D: &str = "vector.populate_2d";
/// Id of [`populate_3d`].
pub const POPULATE_3D: &str = "vector.populate_3d";
/// Id of [`populate_geometry`].
pub const POPULATE_GEOMETRY: &str = "vector.populate_geometry";

/// The most points one call may add (one million).
pub const MAX_POPULATION: usize = 1_000_000;

/// Registers the Populate nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(populate_2d());
    registry.register(populate_3d());
    registry.register(populate_geometry());
}

fn populate(id: &str, name: &str, nickname: &str, region: Port) -> NodeType {
    NodeType::new(id, name, nickname, "Vector")
        .subcategory("Grid")
        .input(region)
        .input(
            Port::new("Count", "N", DataType::Integer)
                .doc(&format!(
                    "The number of points to add, 0 to {MAX_POPULATION}; default 100."
                ))
                .default_value(100_i64),
        )
        .input(
            Port::new("Seed", "S", DataType::Integer)
                .doc(
                    "The seed of the random generator: the same seed gives the same points; \
                     only its low 32 bits count; default 1.",
                )
                .default_value(1_i64),
        )
        .input(
            Port::new("Points", "P", DataType::Point)
                .list()
                .optional()
                .doc("Points already there (optional): the new points keep away from them."),
        )
        .output(
            Port::new("Population", "P", DataType::Point)
                .list()
                .doc("The new points, in the order they were placed."),
        )
}

/// The count N (input 1), 0 to [`MAX_POPULATION`].
fn count(s: &Solve<'_>) -> Result<usize, NodeError> {
    let n = *s.item::<i64>(1)?;
    usize::try_from(n)
        .ok()
        .filter(|&n| n <= MAX_POPULATION)
        .ok_or_else(|| NodeError(format!("count N must be 0 to {MAX_POPULATION}, not {n}")))
}

/// Samples `count` points in the frame at `corner` with unit axes `axes` and `extents`, away
/// from the existing points of input 3, and writes them.
fn sample(
    s: &mut Solve<'_>,
    corner: Point3,
    axes: [Vector3; 3],
    extents: [f64; 3],
) -> Result<(), NodeError> {
    let n = count(s)?;
    let seed = *s.item::<i64>(2)? as i32;
    let existing: Vec<Point3> = match s.list::<Point3>(3) {
        Ok(list) => list
            .present()
            .map(|p| {
                let d = *p - corner;
                Point3::new(d.dot(axes[0]), d.dot(axes[1]), d.dot(axes[2]))
            })
            .collect(),
        Err(_) => Vec::new(),
    };
    let mut random = DotNetRandom::new(seed);
    let local = best_candidate_samples(extents, n, &existing, || random.next_double());
    let points = local
        .into_iter()
        .map(|p| corner + axes[0] * p.x + axes[1] * p.y + axes[2] * p.z)
        .collect();
    s.set_list(0, points);
    Ok(())
}

/// Populate 2D \[Pop2D\]: random points spread over a rectangle.
pub fn populate_2d() -> NodeType {
    populate(
        POPULATE_2D,
        "Populate 2D",
        "Pop2D",
        Port::new("Region", "R", DataType::Curve)
            .doc("The rectangle to populate (a closed polyline of four right-angled sides)."),
    )
    .gh_guid("e2d958e8-9f08-44f7-bf47-a684882d0b2a")
    .description(
        "Populates a rectangle with N points, reproducibly from a seed: each point is the best \
         of several random candidates (the one farthest from the points already placed and \
         the existing points P), so the points spread out evenly.",
    )
    .solve(|s| {
        let region = s.item::<Shared<Curve>>(0)?;
        if let Some(why) = not_a_rectangle(region) {
            return Err(NodeError(format!("region R is not a rectangle: {why}")));
        }
        let Curve::Polyline { polyline, .. } = region.as_ref() else {
            return Err("region R is not a rectangle".into());
        };
        let p = polyline.points();
        let (a, b) = (p[1] - p[0], p[3] - p[0]);
        let (ua, ub) = (a.unitize()?, b.unitize()?);
        let axes = [ua, ub, ua.cross(ub)];
        sample(s, p[0], axes, [a.length(), b.length(), 0.0])
    })
}

/// Populate 3D \[Pop3D\]: random points spread through a box.
pub fn populate_3d() -> NodeType {
    populate(
        POPULATE_3D,
        "Populate 3D",
        "Pop3D",
        Port::new("Region", "R", DataType::Box).doc("The box to populate."),
    )
    .gh_guid("e202025b-dc8e-4c51-ae19-4415b172886f")
    .description(
        "Populates a box with N points, reproducibly from a seed: each point is the best of \
         several random candidates (the one farthest from the points already placed and the \
         existing points P), so the points spread out evenly. A box without volume is an \
         error.",
    )
    .solve(|s| {
        let b = s.item::<OrientedBox>(0)?.made_increasing();
        let sizes = b.sizes();
        if !b.is_valid() || sizes.iter().any(|x| !(x.is_finite() && *x > 0.0)) {
            return Err("region R is not a valid box with volume".into());
        }
        let corner = b.point_at(b.x.t0, b.y.t0, b.z.t0);
        let axes = [b.plane.x_axis, b.plane.y_axis, b.plane.z_axis];
        sample(s, corner, axes, sizes)
    })
}

/// Populate Geometry \[PopGeo\]: random points spread over curves, surfaces, B-reps and
/// meshes.
pub fn populate_geometry() -> NodeType {
    populate(
        POPULATE_GEOMETRY,
        "Populate Geometry",
        "PopGeo",
        Port::new("Geometry", "G", DataType::Generic).doc(
            "The geometry to populate: a curve (line, circle, arc), surface, brep, box or mesh.",
        ),
    )
    .gh_guid("c8cb6a5c-2ffd-4095-ba2a-5c35015e09e4")
    .description(
        "Populates a curve, surface, brep or mesh with N points, reproducibly from a seed: \
         candidates are drawn uniformly by length (curves) or area (the rest), and each point \
         is the best of several (the one farthest, in space, from the points already placed \
         and the existing points P), so the points spread out evenly. Points lie exactly on \
         the curve or surface, inside a brep's trims; the draw follows the geometry's mesh \
         (default meshing parameters), so its density is uniform to the mesh's accuracy. \
         Geometry without length or area, or of another type, is an error.",
    )
    .solve(|s| {
        let value = s.value(0).ok_or("input G has no geometry")?;
        let parameters = MeshingParameters::default();
        let brep: Brep;
        let curve: Shared<Curve>;
        let sampler = match &value {
            Value::Curve(_) | Value::Line(_) | Value::Circle(_) | Value::Arc(_) => {
                curve = crate::curve::curve_from_value(&value).ok_or("not a curve")?;
                crate::curve::valid_curve(&curve, "G")?;
                GeometrySampler::curve(&curve, &parameters)?
            }
            Value::Surface(surface) => {
                brep = Brep::from_surface(surface.as_ref().clone())?;
                GeometrySampler::brep(&brep, &parameters)?
            }
            Value::Box(b) => {
                brep = Brep::from_box(b)?;
                GeometrySampler::brep(&brep, &parameters)?
            }
            Value::Brep(b) => GeometrySampler::brep(b, &parameters)?,
            Value::Mesh(m) => GeometrySampler::mesh(m)?,
            other => {
                return Err(format!(
                    "a {} cannot be populated: give a curve, surface, brep, box or mesh",
                    other.data_type().name().to_lowercase()
                )
                .into());
            }
        };
        let n = count(s)?;
        let seed = *s.item::<i64>(2)? as i32;
        let existing: Vec<Point3> = match s.list::<Point3>(3) {
            Ok(list) => list.present().copied().collect(),
            Err(_) => Vec::new(),
        };
        let mut random = DotNetRandom::new(seed);
        let points = spread_points(&sampler, n, &existing, || random.next_double());
        s.set_list(0, points);
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Interval, Plane, Polyline};
    use locus_runtime::{DataTree, NodeCall, Value};

    use super::*;
    use crate::test_support::{assert_error, points};

    fn rectangle(w: f64, h: f64) -> DataTree {
        let p = |x: f64, y: f64| Point3::new(x + 1.0, y, 2.0);
        let poly = Polyline::new(vec![
            p(0.0, 0.0),
            p(w, 0.0),
            p(w, h),
            p(0.0, h),
            p(0.0, 0.0),
        ])
        .unwrap();
        DataTree::from_item(Shared::new(Curve::from(poly)))
    }

    fn run2(n: i64, seed: i64) -> Vec<Point3> {
        let r = NodeCall::new(&populate_2d())
            .input(rectangle(4.0, 2.0))
            .input(DataTree::from_item(n))
            .input(DataTree::from_item(seed))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        points(&r.outputs[0])
    }

    #[test]
    fn populate_2d_is_reproducible_and_inside() {
        let a = run2(50, 7);
        assert_eq!(a.len(), 50);
        assert_eq!(a, run2(50, 7));
        assert_ne!(a, run2(50, 8));
        assert!(
            a.iter()
                .all(|p| (1.0..5.0).contains(&p.x) && (0.0..2.0).contains(&p.y) && p.z == 2.0)
        );
        // The first point is the first candidate (nothing to keep away from): x then y from
        // .NET's first two numbers for seed 7.
        let mut random = DotNetRandom::new(7);
        let (u, v) = (random.next_double(), random.next_double());
        assert_eq!(a[0], Point3::new(1.0 + 4.0 * u, 2.0 * v, 2.0));
    }

    #[test]
    fn populate_3d_fills_a_box_and_avoids_existing_points() {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 1.0),
        );
        let existing = Point3::new(0.5, 0.5, 0.5);
        let r = NodeCall::new(&populate_3d())
            .input(DataTree::from_item(b))
            .input(DataTree::from_item(20_i64))
            .skip_input()
            .input(DataTree::from_list(vec![existing]))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let pts = points(&r.outputs[0]);
        assert_eq!(pts.len(), 20);
        assert!(pts.iter().all(|p| p.distance(existing) > 0.05));
        let flat = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 0.0),
        );
        let r = NodeCall::new(&populate_3d())
            .input(DataTree::from_item(flat))
            .run();
        assert_error(&r, "not a valid box with volume");
    }

    fn run_geometry(geometry: Value, n: i64) -> locus_runtime::NodeCallResult {
        NodeCall::new(&populate_geometry())
            .input(DataTree::from_value(geometry))
            .input(DataTree::from_item(n))
            .run()
    }

    #[test]
    fn populate_geometry_puts_points_on_curves_surfaces_and_meshes() {
        let sphere = locus_kernel::Sphere::new(Point3::ORIGIN, 2.0)
            .unwrap()
            .to_nurbs()
            .unwrap();
        let r = run_geometry(Value::Surface(Shared::new(sphere)), 100);
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let pts = points(&r.outputs[0]);
        assert_eq!(pts.len(), 100);
        assert!(
            pts.iter()
                .all(|p| (p.distance(Point3::ORIGIN) - 2.0).abs() < 1e-9)
        );
        let line = locus_kernel::Line::new(Point3::ORIGIN, Point3::new(10.0, 0.0, 0.0));
        let r = run_geometry(Value::Line(line), 10);
        let pts = points(&r.outputs[0]);
        assert_eq!(pts.len(), 10);
        assert!(
            pts.iter()
                .all(|p| p.y == 0.0 && (0.0..=10.0).contains(&p.x))
        );
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        );
        let r = run_geometry(Value::Box(b), 30);
        let on_boundary = |p: &Point3| {
            let eps = 1e-9;
            [p.x, p.y / 2.0, p.z / 3.0]
                .iter()
                .any(|c| c.abs() < eps || (c - 1.0).abs() < eps)
        };
        assert!(points(&r.outputs[0]).iter().all(on_boundary));
    }

    #[test]
    fn populate_geometry_refuses_what_it_cannot_populate() {
        assert_error(
            &run_geometry(Value::Number(1.0), 5),
            "a number cannot be populated",
        );
        let r = run_geometry(Value::Point(Point3::ORIGIN), 5);
        assert_error(&r, "cannot be populated");
        let empty = locus_kernel::Mesh::default();
        assert_error(&run_geometry(Value::Mesh(Shared::new(empty)), 5), "no area");
    }

    #[test]
    fn bad_counts_and_regions_are_errors() {
        let r = NodeCall::new(&populate_2d())
            .input(rectangle(1.0, 1.0))
            .input(DataTree::from_item(-1_i64))
            .run();
        assert_error(&r, "count N must be 0 to 1000000, not -1");
        let r = NodeCall::new(&populate_2d())
            .input(rectangle(0.0, 1.0))
            .run();
        assert_error(&r, "region R is not a rectangle");
    }
}
