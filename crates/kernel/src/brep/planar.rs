//! Planar faces bounded by loops of curves (Rhino's `Brep.CreatePlanarBreps`, Grasshopper's
//! Boundary Surfaces), with the grouping of nested closed curves into outer boundaries and
//! holes.
//!
//! A face's trims are its edge curves themselves, mapped exactly into the plane's
//! coordinates (an affine map of the control points), so curved boundaries stay exact: a
//! disc bounded by a circle has exactly the disc's area. The plane is fitted through points
//! sampled along the outer loop (Newell's normal, so that the outer loop runs
//! counter-clockwise); every sample of every loop must lie within the tolerance of it.
//! Containment and crossing tests use the sampled polygons, [`crate::curve::loop_plane::SAMPLES_PER_SPAN`] points per
//! span of each curve.

use crate::brep::builders::{Builder, check_no_crossings, point_in_polygon, signed_area};
use crate::brep::{Brep, LoopKind};
use crate::curve::loop_plane::{check_in_plane, loop_plane, loop_samples};
use crate::{Curve, Error, Interval, NurbsCurve, NurbsSurface, Plane, Point3, Result, Transform};

/// The most boundary curves [`Brep::planar_regions`] takes.
pub const MAX_BOUNDARY_CURVES: usize = 10_000;

/// The boundary curves [`Brep::planar_regions`] left out: each curve's index and why.
pub type FailedBoundaries = Vec<(usize, Error)>;

/// The curve split at its kinks (angles above [`crate::KINK_ANGLE_TOLERANCE`]), as NURBS
/// curves: the pieces Rhino makes edges of (one per polyline segment). A closed curve is also
/// cut at its seam, so that the pieces run from its start to its end.
///
/// # Errors
/// As [`Curve::kinks`] and [`Curve::trim`].
pub(crate) fn split_at_kinks(curve: &Curve) -> Result<Vec<NurbsCurve>> {
    let kinks = curve.kinks(crate::KINK_ANGLE_TOLERANCE)?;
    if kinks.is_empty() {
        return Ok(vec![curve.to_nurbs()]);
    }
    let d = curve.domain();
    let mut bounds = vec![d.t0];
    bounds.extend(kinks);
    bounds.push(d.t1);
    bounds
        .windows(2)
        .map(|w| Ok(curve.trim(Interval::new(w[0], w[1]))?.to_nurbs()))
        .collect()
}

/// The curve in the plane's coordinates, flattened to `z = 0`: a trim curve.
fn to_trim(curve: &NurbsCurve, to_plane: &Transform) -> Result<NurbsCurve> {
    let mapped = curve.transformed(to_plane)?;
    let points = mapped
        .points()
        .iter()
        .map(|p| Point3::new(p.x, p.y, 0.0))
        .collect();
    NurbsCurve::new(
        mapped.degree(),
        points,
        mapped.weights().to_vec(),
        mapped.knots().to_vec(),
    )
}

/// The loop run backwards: the curves in reverse order, each reversed.
fn reversed_loop(curves: &[NurbsCurve]) -> Vec<NurbsCurve> {
    curves.iter().rev().map(NurbsCurve::reversed).collect()
}

/// Checks that consecutive curves of a loop meet end to start and that it closes.
fn check_chained(curves: &[NurbsCurve], tolerance: f64) -> Result<()> {
    if curves.is_empty() {
        return Err(Error::TooFewPoints {
            what: "a boundary loop (curves)",
            needed: 1,
            got: 0,
        });
    }
    let n = curves.len();
    for k in 0..n {
        let gap = curves[k]
            .end_point()
            .distance(curves[(k + 1) % n].start_point());
        if gap.is_nan() || gap > tolerance {
            return Err(Error::InvalidInput(if n == 1 {
                format!("the boundary curve is not closed (its ends are {gap} apart)")
            } else {
                format!("the boundary loop has a gap of {gap} after curve {k}")
            }));
        }
    }
    Ok(())
}

impl Brep {
    /// A planar face bounded by closed loops of curves: `loops[0]` is the outer boundary and
    /// the others are holes inside it. Each loop is a list of curves meeting end to start
    /// within `tolerance` (one closed curve is a loop of one); each curve becomes an edge, and
    /// its exact image in the plane's coordinates the trim. The outer loop runs
    /// counter-clockwise about the plane's normal and holes clockwise, whatever their own
    /// direction. The surface is the plane rectangle around the outer loop's control points.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a negative or NaN tolerance, a loop that does not close, a
    /// curve out of the plane by more than `tolerance`, a hole outside the outer loop, or
    /// loops that cross; [`Error::Collinear`] for a loop that spans no plane.
    pub fn from_planar_loops(loops: &[Vec<NurbsCurve>], tolerance: f64) -> Result<Self> {
        if !tolerance.is_finite() || tolerance < 0.0 {
            return Err(Error::InvalidInput(format!(
                "tolerance must be finite and not negative, got {tolerance}"
            )));
        }
        let Some(outer) = loops.first() else {
            return Err(Error::TooFewPoints {
                what: "a planar face (loops)",
                needed: 1,
                got: 0,
            });
        };
        for l in loops {
            check_chained(l, tolerance)?;
        }
        let plane = loop_plane(outer, tolerance)?;
        let to_plane = Transform::plane_to_plane(&plane, &Plane::WORLD_XY);
        let uv_polygon = |points: &[Point3]| -> Vec<(f64, f64)> {
            points
                .iter()
                .map(|&p| {
                    let [u, v, _] = plane.local_coordinates(p);
                    (u, v)
                })
                .collect()
        };
        let mut oriented: Vec<Vec<NurbsCurve>> = Vec::with_capacity(loops.len());
        let mut polygons: Vec<Vec<(f64, f64)>> = Vec::with_capacity(loops.len());
        for (k, l) in loops.iter().enumerate() {
            let points = loop_samples(l);
            check_in_plane(&plane, &points, tolerance)?;
            let mut polygon = uv_polygon(&points);
            let area = signed_area(&polygon);
            let want_positive = k == 0;
            if area == 0.0 || area.is_nan() {
                return Err(Error::Collinear);
            }
            if (area > 0.0) != want_positive {
                oriented.push(reversed_loop(l));
                polygon.reverse();
            } else {
                oriented.push(l.clone());
            }
            if k > 0 && !point_in_polygon(polygon[0], &polygons[0]) {
                return Err(Error::InvalidInput(
                    "a hole lies outside the outer boundary".into(),
                ));
            }
            polygons.push(polygon);
        }
        check_no_crossings(&polygons)?;

        let mut trims: Vec<Vec<NurbsCurve>> = Vec::with_capacity(oriented.len());
        for l in &oriented {
            trims.push(
                l.iter()
                    .map(|c| to_trim(c, &to_plane))
                    .collect::<Result<_>>()?,
            );
        }
        let (mut u0, mut u1, mut v0, mut v1) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for c in &trims[0] {
            for p in c.points() {
                u0 = u0.min(p.x);
                u1 = u1.max(p.x);
                v0 = v0.min(p.y);
                v1 = v1.max(p.y);
            }
        }
        let surface =
            NurbsSurface::from_plane(&plane, Interval::new(u0, u1), Interval::new(v0, v1))?;
        let mut b = Builder::default();
        let face = b.face(surface, false);
        for (k, (curves, uv)) in oriented.iter().zip(&trims).enumerate() {
            let kind = if k == 0 {
                LoopKind::Outer
            } else {
                LoopKind::Inner
            };
            let l = b.start_loop(face, kind);
            let first = b.brep.vertices.len();
            for c in curves {
                b.vertex(c.start_point());
            }
            let n = curves.len();
            for (i, (c, trim)) in curves.iter().zip(uv).enumerate() {
                let ends = [first + i, first + (i + 1) % n];
                let edge = b.edge(c.clone(), ends);
                b.trim(l, trim.clone(), Some(edge), false, ends);
            }
        }
        Ok(b.finish())
    }

    /// Grasshopper's Boundary Surfaces: planar faces from closed planar curves, each split at
    /// its kinks into edges. Curves in one plane (within `tolerance`) are nested by
    /// containment: a curve inside an even number of others bounds a face, and a curve inside
    /// an odd number is a hole in the smallest curve around it. Each face is its own B-rep,
    /// in the order of their outer curves. A curve that is not closed or not planar is
    /// reported in the second list (its index and why) and left out.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a negative or NaN tolerance or more than
    /// [`MAX_BOUNDARY_CURVES`] curves.
    pub fn planar_regions(
        curves: &[Curve],
        tolerance: f64,
    ) -> Result<(Vec<Brep>, FailedBoundaries)> {
        if !tolerance.is_finite() || tolerance < 0.0 {
            return Err(Error::InvalidInput(format!(
                "tolerance must be finite and not negative, got {tolerance}"
            )));
        }
        if curves.len() > MAX_BOUNDARY_CURVES {
            return Err(Error::InvalidInput(format!(
                "{} boundary curves are more than the {MAX_BOUNDARY_CURVES} allowed",
                curves.len()
            )));
        }
        struct Boundary {
            index: usize,
            pieces: Vec<NurbsCurve>,
            plane: Plane,
            points: Vec<Point3>,
        }
        let mut failed = Vec::new();
        let mut boundaries = Vec::new();
        for (index, curve) in curves.iter().enumerate() {
            let made = split_at_kinks(curve).and_then(|pieces| {
                check_chained(&pieces, tolerance)?;
                let plane = loop_plane(&pieces, tolerance)?;
                let points = loop_samples(&pieces);
                Ok(Boundary {
                    index,
                    pieces,
                    plane,
                    points,
                })
            });
            match made {
                Ok(b) => boundaries.push(b),
                Err(e) => failed.push((index, e)),
            }
        }
        // Groups of coplanar boundaries, each group in the plane of its first member.
        let mut groups: Vec<Vec<usize>> = Vec::new();
        for (k, b) in boundaries.iter().enumerate() {
            let home = groups.iter_mut().find(|g| {
                let plane = &boundaries[g[0]].plane;
                b.points.iter().all(|&p| plane.distance_to(p) <= tolerance)
            });
            match home {
                Some(g) => g.push(k),
                None => groups.push(vec![k]),
            }
        }
        let mut regions: Vec<(usize, Brep)> = Vec::new();
        for g in groups {
            let plane = boundaries[g[0]].plane;
            let polygons: Vec<Vec<(f64, f64)>> = g
                .iter()
                .map(|&k| {
                    boundaries[k]
                        .points
                        .iter()
                        .map(|&p| {
                            let [u, v, _] = plane.local_coordinates(p);
                            (u, v)
                        })
                        .collect()
                })
                .collect();
            let areas: Vec<f64> = polygons.iter().map(|p| signed_area(p).abs()).collect();
            let inside =
                |a: usize, b: usize| a != b && point_in_polygon(polygons[a][0], &polygons[b]);
            let depth: Vec<usize> = (0..g.len())
                .map(|a| (0..g.len()).filter(|&b| inside(a, b)).count())
                .collect();
            for outer in (0..g.len()).filter(|&a| depth[a].is_multiple_of(2)) {
                let holes = (0..g.len()).filter(|&h| {
                    depth[h] == depth[outer] + 1
                        && inside(h, outer)
                        && !(0..g.len()).any(|o| {
                            o != outer
                                && depth[o] == depth[outer]
                                && inside(h, o)
                                && areas[o] < areas[outer]
                        })
                });
                let mut loops = vec![boundaries[g[outer]].pieces.clone()];
                loops.extend(holes.map(|h| boundaries[g[h]].pieces.clone()));
                let index = boundaries[g[outer]].index;
                match Brep::from_planar_loops(&loops, tolerance) {
                    Ok(brep) => regions.push((index, brep)),
                    Err(e) => failed.push((index, e)),
                }
            }
        }
        regions.sort_by_key(|(i, _)| *i);
        failed.sort_by_key(|(i, _)| *i);
        Ok((regions.into_iter().map(|(_, b)| b).collect(), failed))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Polyline, Vector3};
    use std::f64::consts::PI;

    fn square(x0: f64, y0: f64, size: f64, z: f64) -> Curve {
        let pts = vec![
            Point3::new(x0, y0, z),
            Point3::new(x0 + size, y0, z),
            Point3::new(x0 + size, y0 + size, z),
            Point3::new(x0, y0 + size, z),
            Point3::new(x0, y0, z),
        ];
        Curve::from(Polyline::new(pts).unwrap())
    }

    fn circle(x: f64, y: f64, r: f64) -> Curve {
        let plane = Plane::WORLD_XY.translated(Vector3::new(x, y, 0.0));
        Curve::from(Circle::new(plane, r).unwrap())
    }

    #[test]
    fn a_disc_has_the_exact_area() {
        let (faces, failed) = Brep::planar_regions(&[circle(1.0, 2.0, 3.0)], 1e-9).unwrap();
        assert!(failed.is_empty());
        assert_eq!(faces.len(), 1);
        let area = faces[0].area().unwrap();
        assert!((area - 9.0 * PI).abs() < 1e-9, "{area}");
        assert_eq!(faces[0].edges().len(), 1);
    }

    #[test]
    fn nested_curves_make_faces_with_holes() {
        // A 10-square with a circular hole of radius 2, and inside the hole an island square
        // of side 1, plus a separate square elsewhere and an open curve.
        let open =
            Curve::from(Polyline::new(vec![Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)]).unwrap());
        let curves = [
            square(0.0, 0.0, 10.0, 0.0),
            circle(5.0, 5.0, 2.0),
            square(4.5, 4.5, 1.0, 0.0),
            square(20.0, 0.0, 2.0, 0.0),
            open,
            square(0.0, 0.0, 3.0, 5.0),
        ];
        let (faces, failed) = Brep::planar_regions(&curves, 1e-9).unwrap();
        assert_eq!(failed.len(), 1);
        assert_eq!(failed[0].0, 4);
        assert_eq!(faces.len(), 4);
        let areas: Vec<f64> = faces.iter().map(|f| f.area().unwrap()).collect();
        let expected = [100.0 - 4.0 * PI, 1.0, 4.0, 9.0];
        for (a, e) in areas.iter().zip(expected) {
            assert!((a - e).abs() < 1e-9, "{areas:?}");
        }
        // The square's four segments are four edges; the hole's circle one.
        assert_eq!(faces[0].edges().len(), 5);
        assert_eq!(faces[0].loops().len(), 2);
    }

    #[test]
    fn bad_boundaries_are_reported() {
        let bent = Curve::from(
            Polyline::new(vec![
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 1.0),
                Point3::new(0.0, 1.0, 0.0),
                Point3::ORIGIN,
            ])
            .unwrap(),
        );
        let (faces, failed) = Brep::planar_regions(&[bent], 1e-6).unwrap();
        assert!(faces.is_empty());
        assert!(failed[0].1.to_string().contains("not planar"));
        assert!(Brep::planar_regions(&[], f64::NAN).is_err());
        assert!(Brep::from_planar_loops(&[], 0.0).is_err());
    }
}
