//! The plane of a closed loop of curves, fitted through points sampled along it (Newell's
//! normal, so that the loop runs counter-clockwise about it), and the check that every sample
//! lies within a tolerance of that plane. Planar faces ([`crate::Brep::planar_regions`]),
//! extrusions and region booleans all find their plane here.

use crate::{Error, NurbsCurve, Plane, Point3, Result, Vector3};

/// Points sampled per span of a boundary curve for the plane fit and the containment and
/// crossing tests.
pub const SAMPLES_PER_SPAN: usize = 8;
/// The most samples taken along one boundary curve.
const MAX_SAMPLES_PER_CURVE: usize = 4096;
/// Points along the curve from its start, without its end point.
fn samples(curve: &NurbsCurve) -> Vec<Point3> {
    let n = (curve.span_count() * SAMPLES_PER_SPAN).clamp(SAMPLES_PER_SPAN, MAX_SAMPLES_PER_CURVE);
    let d = curve.domain();
    (0..n)
        .map(|k| curve.point_at(d.parameter_at(k as f64 / n as f64)))
        .collect()
}

/// The samples of a loop of curves, in order.
pub(crate) fn loop_samples(curves: &[NurbsCurve]) -> Vec<Point3> {
    curves.iter().flat_map(samples).collect()
}

/// The plane of a closed loop of curves, if every sample lies within `tolerance` of it.
pub(crate) fn loop_plane(curves: &[NurbsCurve], tolerance: f64) -> Result<Plane> {
    let points = loop_samples(curves);
    if points.iter().any(|p| !p.is_finite()) {
        return Err(Error::NotFinite {
            what: "boundary curve",
        });
    }
    let plane = fit_plane(&points)?;
    check_in_plane(&plane, &points, tolerance)?;
    Ok(plane)
}

pub(crate) fn check_in_plane(plane: &Plane, points: &[Point3], tolerance: f64) -> Result<()> {
    let worst = points
        .iter()
        .map(|&p| plane.distance_to(p))
        .fold(0.0f64, f64::max);
    if worst > tolerance {
        return Err(Error::InvalidInput(format!(
            "the boundary is not planar: a point lies {worst} from its plane, more than the \
             tolerance {tolerance}"
        )));
    }
    Ok(())
}

/// The plane of a polygon: Newell's normal (oriented by the polygon's winding), origin at the
/// first point, x axis along the first segment.
pub(crate) fn fit_plane(points: &[Point3]) -> Result<Plane> {
    let n = points.len();
    let mut normal = Vector3::ZERO;
    let c = points[0];
    for i in 0..n {
        let a = points[i] - c;
        let b = points[(i + 1) % n] - c;
        normal += a.cross(b);
    }
    let z = normal.try_normalize().ok_or(Error::Collinear)?;
    let first = points[1] - points[0];
    let x = (first - z * first.dot(z))
        .try_normalize()
        .ok_or(Error::Collinear)?;
    Ok(Plane {
        origin: points[0],
        x_axis: x,
        y_axis: z.cross(x),
        z_axis: z,
    })
}
