//! Booleans of planar regions bounded by closed curves: Rhino's `Curve.CreateBooleanUnion`,
//! `CreateBooleanIntersection` and `CreateBooleanDifference`, Grasshopper's Region Union,
//! Region Intersection and Region Difference.
//!
//! Each set of curves bounds the region inside any of its curves (their union). The curves are
//! projected onto the boolean plane, then:
//! 1. every pair of curves is intersected ([`Curve::intersect_curve`]) and each curve is split
//!    at the points and at the ends of the stretches where it overlaps another;
//! 2. each piece is kept when the result lies on exactly one side of it, tested at two points
//!    [`SIDE_OFFSET`] tolerances to either side of its middle, and turned so that the result
//!    lies to its left (seen from the plane's normal);
//! 3. pieces that coincide (the shared stretch of two curves that bound the result on the same
//!    side) are kept once, and the pieces are joined end to end.
//!
//! So outer boundaries run counter-clockwise about the plane's normal and holes clockwise, and
//! the answer does not depend on the direction or seam of the input curves. Pieces shorter than
//! the tolerance are dropped and the join bridges their gap.

use crate::curve::loop_plane::loop_plane;
use crate::{
    BoundingBox, Containment, Curve, Error, Interval, Plane, Point3, Result, Transform, Vector3,
};

/// The classifying points lie this many tolerances to either side of a piece's middle:
/// far enough that a point never counts as on the piece itself, near enough that features
/// down to a few tolerances across are seen.
pub const SIDE_OFFSET: f64 = 4.0;

/// The most curves one region boolean takes (the pairwise intersection is quadratic).
pub const MAX_REGION_CURVES: usize = 2_000;

/// Which region boolean to compute.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RegionOperation {
    /// Inside any curve of either set.
    Union,
    /// Inside the first set and inside the second.
    Intersection,
    /// Inside the first set and not inside the second.
    Difference,
}

impl RegionOperation {
    fn keeps(self, in_a: bool, in_b: bool) -> bool {
        match self {
            Self::Union => in_a || in_b,
            Self::Intersection => in_a && in_b,
            Self::Difference => in_a && !in_b,
        }
    }
}

/// One input curve in the plane, with the set it belongs to and its box.
struct Boundary {
    curve: Curve,
    in_b: bool,
    bbox: BoundingBox,
}

impl Curve {
    /// The plane a closed planar curve lies in (fitted to samples of it, checked within
    /// `tolerance`): the plane a region boolean uses when it is given none.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a curve that leaves its plane by more than `tolerance`;
    /// [`Error::Degenerate`] for one that spans no plane.
    pub fn region_plane(&self, tolerance: f64) -> Result<Plane> {
        loop_plane(&[self.to_nurbs()], tolerance)
    }

    /// The boundaries of a region boolean of the regions inside the curves of `a` and of `b`
    /// (for [`RegionOperation::Union`] the two sets are simply pooled), in `plane`, see the
    /// module documentation. Each result runs with the region to its left about the plane's
    /// normal: outer boundaries counter-clockwise, holes clockwise.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a tolerance that is not finite and positive, more than
    /// [`MAX_REGION_CURVES`] curves, or a curve that is not closed or invalid (naming the set
    /// and index); [`Error::Degenerate`] for a curve that bounds no area in the plane; the
    /// errors of the intersections.
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{Circle, Curve, Plane, Point3, RegionOperation};
    /// let at = |x: f64| -> Curve {
    ///     let plane = Plane::from_normal(Point3::new(x, 0.0, 0.0), Plane::WORLD_XY.z_axis);
    ///     Circle::new(plane.unwrap(), 1.0).unwrap().into()
    /// };
    /// let union = Curve::region_boolean(&[at(0.0), at(1.0)], &[], RegionOperation::Union,
    ///     &Plane::WORLD_XY, 1e-6).unwrap();
    /// assert_eq!(union.len(), 1);
    /// assert!(union[0].is_closed());
    /// ```
    pub fn region_boolean(
        a: &[Curve],
        b: &[Curve],
        operation: RegionOperation,
        plane: &Plane,
        tolerance: f64,
    ) -> Result<Vec<Curve>> {
        if !(tolerance.is_finite() && tolerance > 0.0) {
            return Err(Error::InvalidInput(format!(
                "the tolerance must be finite and positive, got {tolerance}"
            )));
        }
        if a.len() + b.len() > MAX_REGION_CURVES {
            return Err(Error::InvalidInput(format!(
                "{} curves are more than the {MAX_REGION_CURVES} a region boolean takes",
                a.len() + b.len()
            )));
        }
        let mut boundaries = Vec::with_capacity(a.len() + b.len());
        for (set, curves) in [("A", a), ("B", b)] {
            for (i, c) in curves.iter().enumerate() {
                let curve = onto_plane(c, plane, tolerance).map_err(|e| name_curve(e, set, i))?;
                boundaries.push(Boundary {
                    bbox: curve.to_nurbs().bounding_box().inflated(tolerance),
                    curve,
                    in_b: set == "B",
                });
            }
        }
        let cuts = cut_parameters(&boundaries, tolerance)?;
        let offset = SIDE_OFFSET * tolerance;
        let mut kept: Vec<Curve> = Vec::new();
        for (boundary, cuts) in boundaries.iter().zip(&cuts) {
            let pieces = cut(&boundary.curve, cuts, tolerance)?;
            for piece in pieces {
                if piece.length() <= tolerance {
                    continue;
                }
                let Some((middle, tangent)) = side_test_point(&piece) else {
                    continue;
                };
                let left = plane.z_axis.cross(tangent);
                let inside = |p: Point3| -> Result<bool> {
                    let in_a = inside_set(&boundaries, false, p, tolerance)?;
                    let in_b = inside_set(&boundaries, true, p, tolerance)?;
                    Ok(operation.keeps(in_a, in_b))
                };
                let on_left = inside(middle + left * offset)?;
                let on_right = inside(middle - left * offset)?;
                if on_left == on_right {
                    continue;
                }
                let piece = if on_left { piece } else { piece.reversed() };
                if !kept.iter().any(|k| coincide(k, &piece, tolerance)) {
                    kept.push(piece);
                }
            }
        }
        Curve::join(&kept, 2.0 * tolerance, true)
    }
}

/// The curve projected onto the plane (left as it is when it already lies in it), checked to
/// be closed and to bound an area there.
fn onto_plane(curve: &Curve, plane: &Plane, tolerance: f64) -> Result<Curve> {
    if !curve.is_valid() {
        return Err(Error::InvalidInput("is not valid".into()));
    }
    let in_plane = curve
        .to_nurbs()
        .points()
        .iter()
        .all(|&p| plane.distance_to(p) <= tolerance);
    let curve = if in_plane {
        curve.clone()
    } else {
        curve.transformed(&Transform::planar_projection(plane))?
    };
    if !curve.is_closed() {
        return Err(Error::InvalidInput("is not closed".into()));
    }
    let area = signed_area(&curve, plane);
    let size = curve.to_nurbs().bounding_box().diagonal().length();
    if area.is_nan() || area.abs() <= tolerance * size {
        return Err(Error::Degenerate {
            what: "region (the curve bounds no area in the plane)",
        });
    }
    Ok(curve)
}

fn name_curve(error: Error, set: &str, index: usize) -> Error {
    match error {
        Error::InvalidInput(why) => Error::InvalidInput(format!("curve {index} of {set} {why}")),
        other => Error::InvalidInput(format!("curve {index} of {set}: {other}")),
    }
}

/// Where each boundary is cut: the points where it meets another and the ends of the
/// stretches where it overlaps one.
fn cut_parameters(boundaries: &[Boundary], tolerance: f64) -> Result<Vec<Vec<f64>>> {
    let mut cuts = vec![Vec::new(); boundaries.len()];
    for i in 0..boundaries.len() {
        for j in i + 1..boundaries.len() {
            let (bi, bj) = (&boundaries[i], &boundaries[j]);
            if bi.bbox.intersection(&bj.bbox).is_empty() {
                continue;
            }
            let x = bi.curve.intersect_curve(&bj.curve, tolerance)?;
            for hit in &x.points {
                cuts[i].push(hit.t_a);
                cuts[j].push(hit.t_b);
            }
            for overlap in &x.overlaps {
                cuts[i].extend([overlap.a.t0, overlap.a.t1]);
                cuts[j].extend([overlap.b.t0, overlap.b.t1]);
            }
        }
    }
    Ok(cuts)
}

/// Whether `p` lies inside (or on) a curve of the set.
fn inside_set(boundaries: &[Boundary], in_b: bool, p: Point3, tolerance: f64) -> Result<bool> {
    for b in boundaries.iter().filter(|b| b.in_b == in_b) {
        if !b.bbox.contains_point(p) {
            continue;
        }
        if b.curve.contains_point(p, tolerance)?.0 != Containment::Outside {
            return Ok(true);
        }
    }
    Ok(false)
}

/// Whether two pieces run along each other in the same direction: same ends and middle.
fn coincide(a: &Curve, b: &Curve, tolerance: f64) -> bool {
    let close = |p: Point3, q: Point3| p.distance(q) <= 2.0 * tolerance;
    close(a.start_point(), b.start_point())
        && close(a.end_point(), b.end_point())
        && b.closest_point(a.point_at(a.domain().mid()))
            .is_ok_and(|c| c.distance <= 2.0 * tolerance)
}

/// The signed area a closed curve bounds in the plane (positive when it runs counter-clockwise
/// about the normal), by Green's theorem on the sampled polygon: only its sign and rough size
/// are used.
fn signed_area(curve: &Curve, plane: &Plane) -> f64 {
    let nurbs = curve.to_nurbs();
    let breaks = nurbs.span_breaks();
    let mut area = 0.0;
    let mut previous: Option<(f64, f64)> = None;
    let mut first = None;
    for w in breaks.windows(2) {
        for k in 0..16 {
            let p = nurbs.point_at(w[0] + (w[1] - w[0]) * k as f64 / 16.0) - plane.origin;
            let q = (p.dot(plane.x_axis), p.dot(plane.y_axis));
            if let Some((x0, y0)) = previous {
                area += x0 * q.1 - q.0 * y0;
            }
            first.get_or_insert(q);
            previous = Some(q);
        }
    }
    if let (Some((x0, y0)), Some((x1, y1))) = (previous, first) {
        area += x0 * y1 - x1 * y0;
    }
    0.5 * area
}

/// The pieces of a closed curve between its cuts. A cut at the seam counts (the seam is then a
/// piece's end); without one, the piece across the seam is one piece.
fn cut(curve: &Curve, cuts: &[f64], tolerance: f64) -> Result<Vec<Curve>> {
    let d = curve.domain();
    let start = curve.start_point();
    let at_seam = |t: f64| curve.point_at(t).distance(start) <= tolerance;
    let mut inner: Vec<f64> = cuts
        .iter()
        .copied()
        .filter(|&t| t > d.t0 && t < d.t1 && !at_seam(t))
        .collect();
    let seam_cut = cuts.iter().any(|&t| at_seam(t));
    if inner.is_empty() {
        return Ok(vec![curve.clone()]);
    }
    if !seam_cut {
        return curve.split_at_parameters(&inner);
    }
    inner.sort_by(f64::total_cmp);
    inner.dedup();
    let mut ends = vec![d.t0];
    ends.extend(inner);
    ends.push(d.t1);
    ends.windows(2)
        .filter(|w| w[1] > w[0])
        .map(|w| curve.trim(Interval::new(w[0], w[1])))
        .collect()
}

/// Where a piece's sides are tested: the middle of its longest span (never a corner), with
/// the tangent there.
fn side_test_point(piece: &Curve) -> Option<(Point3, Vector3)> {
    let nurbs = piece.to_nurbs();
    let breaks = nurbs.span_breaks();
    let widest = breaks.windows(2).max_by(|a, b| {
        let chord = |w: &[f64]| nurbs.point_at(w[0]).distance(nurbs.point_at(w[1]));
        chord(a).total_cmp(&chord(b))
    })?;
    let t = 0.5 * (widest[0] + widest[1]);
    let (p, d1, _) = nurbs.point_and_derivatives_at(t);
    let tangent = d1.unitize().ok()?;
    Some((p, tangent))
}
