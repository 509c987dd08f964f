//! `ON_NurbsCurve` and `ON_NurbsSurface` class data.
//!
//! Both store orders (degree + 1), control point counts, knot vectors in Rhino's form
//! (`|knots| = |points| + degree − 1`, the form the kernel uses too) and control points,
//! which for rational geometry are homogeneous: `(w·x, w·y, w·z, w)`. Non-rational control
//! points are written without a weight.

use locus_kernel::{NurbsCurve, NurbsSurface, Point3};

use crate::binary::{Reader, Writer};
use crate::{Error, Result};

/// Writes a rational control point homogeneously, or a non-rational one as `x, y, z`.
fn write_cv(w: &mut Writer, p: Point3, weight: f64, rational: bool) {
    if rational {
        w.f64s(&[p.x * weight, p.y * weight, p.z * weight, weight]);
    } else {
        w.f64s(&[p.x, p.y, p.z]);
    }
}

/// Reads `n` control points of dimension `dim`, homogeneous when `rational`, into Euclidean
/// points and weights.
fn read_cvs(
    r: &mut Reader<'_>,
    n: usize,
    dim: usize,
    rational: bool,
    what: &'static str,
) -> Result<(Vec<Point3>, Vec<f64>)> {
    let cv_size = dim + usize::from(rational);
    let at = r.position();
    let raw = r.f64s(n * cv_size, what)?;
    let mut points = Vec::with_capacity(n);
    let mut weights = Vec::with_capacity(n);
    for (i, cv) in raw.chunks_exact(cv_size).enumerate() {
        let w = if rational { cv[dim] } else { 1.0 };
        if !(w.is_finite() && w > 0.0) {
            return Err(Error::Invalid(format!(
                "{what} {i} at byte {at} has weight {w}; weights must be positive"
            )));
        }
        let c = |k: usize| if k < dim { cv[k] / w } else { 0.0 };
        points.push(Point3::new(c(0), c(1), c(2)));
        weights.push(w);
    }
    Ok((points, weights))
}

/// Reads and checks a dimension: 2 or 3 (a 2-D curve gets `z = 0`).
fn read_dim(r: &mut Reader<'_>, what: &'static str) -> Result<usize> {
    let at = r.position();
    match r.i32(what)? {
        d @ (2 | 3) => Ok(d as usize),
        d => Err(Error::Invalid(format!(
            "{what} at byte {at} is {d}; locus reads 2-D and 3-D geometry"
        ))),
    }
}

/// Reads an order and control point count, checking `2 ≤ order ≤ count`.
fn read_order_count(order: i32, count: i32, what: &'static str) -> Result<(usize, usize)> {
    if order < 2 || count < order {
        return Err(Error::Invalid(format!(
            "{what} has order {order} and {count} control points; needs 2 ≤ order ≤ count"
        )));
    }
    Ok((order as usize, count as usize))
}

/// Reads a knot vector that must hold `order + count − 2` knots.
fn read_knots(
    r: &mut Reader<'_>,
    order: usize,
    count: usize,
    what: &'static str,
) -> Result<Vec<f64>> {
    let at = r.position();
    let n = r.count(8, what)?;
    let expected = order + count - 2;
    if n != expected {
        return Err(Error::Invalid(format!(
            "{what} at byte {at} has {n} knots; order {order} and {count} control points need \
             {expected}"
        )));
    }
    r.f64s(n, what)
}

/// Writes `ON_NurbsCurve` class data (version 1.1, as for 3dm version 60 and later).
///
/// # Errors
/// [`Error::TooLarge`] for more than `i32::MAX` control points.
pub fn write_curve(w: &mut Writer, c: &NurbsCurve) -> Result<()> {
    let rational = c.is_rational();
    w.version(1, 1);
    w.i32(3);
    w.i32(i32::from(rational));
    w.count(c.order())?;
    w.count(c.point_count())?;
    w.i32(0);
    w.i32(0);
    w.empty_bounding_box();
    w.count(c.knots().len())?;
    w.f64s(c.knots());
    w.count(c.point_count())?;
    for (&p, &wt) in c.points().iter().zip(c.weights()) {
        write_cv(w, p, wt, rational);
    }
    // 1.1: "SubD friendly" tag.
    w.bool(false);
    Ok(())
}

/// Reads `ON_NurbsCurve` class data.
///
/// # Errors
/// [`Error::Invalid`] for a version, dimension, order, count or weight that openNURBS would
/// not write, [`Error::Truncated`] for counts past the data, [`Error::Geometry`] when the
/// kernel refuses the curve (e.g. decreasing knots).
pub fn read_curve(r: &mut Reader<'_>) -> Result<NurbsCurve> {
    let (major, minor) = r.version("ON_NurbsCurve version")?;
    if major != 1 {
        return Err(Error::Invalid(format!(
            "ON_NurbsCurve version {major}.{minor} is not supported"
        )));
    }
    let dim = read_dim(r, "ON_NurbsCurve dimension")?;
    let rational = r.i32("ON_NurbsCurve rational flag")? != 0;
    let order = r.i32("ON_NurbsCurve order")?;
    let count = r.i32("ON_NurbsCurve control point count")?;
    let (order, count) = read_order_count(order, count, "ON_NurbsCurve")?;
    r.skip(8 + 48, "ON_NurbsCurve reserved fields")?;
    let knots = read_knots(r, order, count, "ON_NurbsCurve knots")?;
    let at = r.position();
    let cv_size = dim + usize::from(rational);
    let n = r.count(cv_size * 8, "ON_NurbsCurve control points")?;
    if n != count {
        return Err(Error::Invalid(format!(
            "ON_NurbsCurve at byte {at} stores {n} control points, its header says {count}"
        )));
    }
    let (points, weights) = read_cvs(r, n, dim, rational, "ON_NurbsCurve control point")?;
    if minor >= 1 {
        r.bool("ON_NurbsCurve SubD friendly tag")?;
    }
    NurbsCurve::new(order - 1, points, weights, knots).map_err(|source| Error::Geometry {
        what: "ON_NurbsCurve",
        source,
    })
}

/// Writes `ON_NurbsSurface` class data (version 1.0).
///
/// # Errors
/// [`Error::TooLarge`] for more than `i32::MAX` control points.
pub fn write_surface(w: &mut Writer, s: &NurbsSurface) -> Result<()> {
    let rational = s.is_rational();
    w.version(1, 0);
    w.i32(3);
    w.i32(i32::from(rational));
    w.count(s.degree_u() + 1)?;
    w.count(s.degree_v() + 1)?;
    w.count(s.count_u())?;
    w.count(s.count_v())?;
    w.i32(0);
    w.i32(0);
    w.empty_bounding_box();
    w.count(s.knots_u().len())?;
    w.f64s(s.knots_u());
    w.count(s.knots_v().len())?;
    w.f64s(s.knots_v());
    w.count(s.points().len())?;
    // The kernel stores point (i, j) at i·count_v + j, the order openNURBS writes them in.
    for (&p, &wt) in s.points().iter().zip(s.weights()) {
        write_cv(w, p, wt, rational);
    }
    Ok(())
}

/// Reads `ON_NurbsSurface` class data.
///
/// # Errors
/// As [`read_curve`].
pub fn read_surface(r: &mut Reader<'_>) -> Result<NurbsSurface> {
    let (major, minor) = r.version("ON_NurbsSurface version")?;
    if major != 1 {
        return Err(Error::Invalid(format!(
            "ON_NurbsSurface version {major}.{minor} is not supported"
        )));
    }
    let dim = read_dim(r, "ON_NurbsSurface dimension")?;
    let rational = r.i32("ON_NurbsSurface rational flag")? != 0;
    let order_u = r.i32("ON_NurbsSurface order")?;
    let order_v = r.i32("ON_NurbsSurface order")?;
    let count_u = r.i32("ON_NurbsSurface control point count")?;
    let count_v = r.i32("ON_NurbsSurface control point count")?;
    let (order_u, count_u) = read_order_count(order_u, count_u, "ON_NurbsSurface (u)")?;
    let (order_v, count_v) = read_order_count(order_v, count_v, "ON_NurbsSurface (v)")?;
    r.skip(8 + 48, "ON_NurbsSurface reserved fields")?;
    let knots_u = read_knots(r, order_u, count_u, "ON_NurbsSurface u knots")?;
    let knots_v = read_knots(r, order_v, count_v, "ON_NurbsSurface v knots")?;
    let at = r.position();
    let cv_size = dim + usize::from(rational);
    let n = r.count(cv_size * 8, "ON_NurbsSurface control points")?;
    if Some(n) != count_u.checked_mul(count_v) {
        return Err(Error::Invalid(format!(
            "ON_NurbsSurface at byte {at} stores {n} control points, its header says \
             {count_u} × {count_v}"
        )));
    }
    let (points, weights) = read_cvs(r, n, dim, rational, "ON_NurbsSurface control point")?;
    NurbsSurface::from_flat(
        [order_u - 1, order_v - 1],
        [count_u, count_v],
        points,
        weights,
        [knots_u, knots_v],
    )
    .map_err(|source| Error::Geometry {
        what: "ON_NurbsSurface",
        source,
    })
}
