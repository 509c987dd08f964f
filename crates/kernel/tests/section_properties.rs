//! Property tests of B-rep sections ([`Brep::intersect_plane`]) on shapes whose sections are
//! known in closed form:
//!
//! - a sphere cut by a random plane at distance `d < R` from its centre: one closed curve, every
//!   point of it on the plane and on the sphere (within the tolerance), of length `2π√(R² − d²)`
//!   (tangent planes are the oracle's case bp-08; a tangent point on the sphere's equator, at a
//!   patch border, still comes out as two points 5e-4 apart: a known gap);
//! - a box cut by a random plane normal to one of its axes, strictly between two faces: one
//!   closed curve, every point on the plane and on the box's boundary, the perimeter of the
//!   box's cross-section (exact: the pieces are lines).

use std::f64::consts::TAU;

use locus_kernel::{Brep, Interval, OrientedBox, Plane, Point3, Sphere, Vector3};
use proptest::prelude::*;

/// The intersection tolerance (the oracle's).
const TOL: f64 = 1e-7;

/// Samples per section curve.
const SAMPLES: usize = 64;

fn arb_unit() -> impl Strategy<Value = Vector3> {
    (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0)
        .prop_filter("not too short", |(x, y, z)| x * x + y * y + z * z > 0.05)
        .prop_map(|(x, y, z)| Vector3::new(x, y, z).normalize_or_zero())
}

fn samples(c: &locus_kernel::Curve) -> Vec<Point3> {
    (0..=SAMPLES)
        .map(|k| c.point_at(c.domain().parameter_at(k as f64 / SAMPLES as f64)))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn a_sphere_section_is_the_circle_of_radius_root_r2_minus_d2(
        centre in (-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0),
        radius in 0.5f64..4.0,
        normal in arb_unit(),
        depth in -0.95f64..0.95,
    ) {
        let centre = Point3::new(centre.0, centre.1, centre.2);
        let brep = Brep::from_sphere(&Sphere::new(centre, radius).unwrap()).unwrap();
        let d = depth * radius;
        let plane = Plane::from_normal(centre + normal * d, normal).unwrap();
        let s = brep.intersect_plane(&plane, TOL).unwrap();
        prop_assert_eq!(s.curves.len(), 1, "{:?}", s);
        prop_assert!(s.points.is_empty(), "{:?}", s.points);
        let c = &s.curves[0];
        prop_assert!(c.is_closed());
        for q in samples(c) {
            prop_assert!(plane.signed_distance_to(q).abs() <= TOL);
            prop_assert!((q.distance(centre) - radius).abs() <= TOL, "{:?}", q);
        }
        let want = TAU * (radius * radius - d * d).sqrt();
        prop_assert!((c.length() - want).abs() <= 1e-9 * want, "{} vs {}", c.length(), want);
    }

    #[test]
    fn a_box_cross_section_is_its_rectangle(
        size in (0.2f64..5.0, 0.2f64..5.0, 0.2f64..5.0),
        axis in 0usize..3,
        at in 0.01f64..0.99,
        frame in arb_unit(),
    ) {
        let base = Plane::from_normal(Point3::new(0.5, -1.0, 2.0), frame).unwrap();
        let b = OrientedBox::new(
            base,
            Interval::new(0.0, size.0),
            Interval::new(0.0, size.1),
            Interval::new(0.0, size.2),
        );
        let brep = Brep::from_box(&b).unwrap();
        let sizes = [size.0, size.1, size.2];
        let axes = [base.x_axis, base.y_axis, base.z_axis];
        let plane = Plane::from_normal(base.origin + axes[axis] * (at * sizes[axis]), axes[axis])
            .unwrap();
        let s = brep.intersect_plane(&plane, TOL).unwrap();
        prop_assert_eq!(s.curves.len(), 1, "{:?}", s);
        let c = &s.curves[0];
        prop_assert!(c.is_closed());
        let others: Vec<usize> = (0..3).filter(|&k| k != axis).collect();
        let want = 2.0 * (sizes[others[0]] + sizes[others[1]]);
        prop_assert!((c.length() - want).abs() <= 1e-10 * want, "{} vs {}", c.length(), want);
        for q in samples(c) {
            prop_assert!(plane.signed_distance_to(q).abs() <= TOL);
            // On the boundary: inside the box, and on one of the four side faces.
            let local: Vec<f64> = axes.iter().map(|a| (q - base.origin).dot(*a)).collect();
            let on_side = others.iter().any(|&k| {
                local[k].abs() <= TOL || (local[k] - sizes[k]).abs() <= TOL
            });
            let inside = (0..3).all(|k| local[k] >= -TOL && local[k] <= sizes[k] + TOL);
            prop_assert!(on_side && inside, "{:?}", q);
        }
    }
}
