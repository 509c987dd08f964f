//! `ON_RevSurface` class data (surfaces of revolution: Rhino's spheres, cylinders, cones and
//! tori in B-reps), read as their exact NURBS form.
//!
//! A revolution surface turns a profile curve about an axis through an angle interval; its
//! parameters are the angle (mapped linearly onto the domain `m_t`) and the profile's own
//! parameter, swapped when the surface is *transposed*. The NURBS form multiplies the profile's
//! homogeneous control points by a rational arc's, which gives the same surface, but its
//! parameters agree with the revolution's only at the ends of the domains (and the arc's knots):
//! in between, an angle and a rational arc parameter differ. B-rep trims that run along the
//! sides of the parameter rectangle are unaffected; [`crate::brep`] refuses other trims on such
//! faces rather than place them wrongly.

use locus_kernel::{Arc, Circle, Interval, NurbsCurve, NurbsSurface, Plane, Point3, Vector3};

use crate::binary::Reader;
use crate::{Error, Geometry, Result, Versions, object::read_object};

fn geometry(what: &'static str) -> impl FnOnce(locus_kernel::Error) -> Error {
    move |source| Error::Geometry { what, source }
}

/// Reads `ON_RevSurface` class data (version 1.x or 2.x) as a NURBS surface.
///
/// # Errors
/// [`Error::Invalid`] for another version, a missing or non-curve profile, a degenerate axis
/// or angle; [`Error::Geometry`] when the kernel refuses a step.
pub fn read(r: &mut Reader<'_>, v: Versions, depth: usize) -> Result<NurbsSurface> {
    let (major, minor) = r.version("ON_RevSurface version")?;
    if !(1..=2).contains(&major) {
        return Err(Error::Invalid(format!(
            "ON_RevSurface version {major}.{minor} is not supported"
        )));
    }
    let a = r.f64s(6, "ON_RevSurface axis")?;
    let (from, to) = (Point3::new(a[0], a[1], a[2]), Point3::new(a[3], a[4], a[5]));
    let angle = r.f64s(2, "ON_RevSurface angle")?;
    let angle = Interval::new(angle[0], angle[1]);
    let domain = if major >= 2 {
        let t = r.f64s(2, "ON_RevSurface domain")?;
        Interval::new(t[0], t[1])
    } else {
        angle.increasing()
    };
    r.skip(48, "ON_RevSurface bounding box")?;
    let transposed = r.i32("ON_RevSurface transposed flag")? != 0;
    if r.u8("ON_RevSurface curve flag")? == 0 {
        return Err(Error::Invalid("ON_RevSurface has no profile curve".into()));
    }
    let profile = match read_object(r, v, depth + 1)? {
        Geometry::Curve(c) => c.to_nurbs(),
        other => {
            return Err(Error::Invalid(format!(
                "ON_RevSurface profile is a {}, not a curve",
                other.rhino_type_name()
            )));
        }
    };
    let valid_angle = angle.is_finite()
        && angle.t0 < angle.t1
        && angle.length() <= std::f64::consts::TAU * (1.0 + 1e-12);
    if !(valid_angle && domain.is_finite() && domain.t0 < domain.t1) {
        return Err(Error::Invalid(format!(
            "ON_RevSurface angle {} to {} or domain {} to {} is not valid",
            angle.t0, angle.t1, domain.t0, domain.t1
        )));
    }
    revolve(&profile, from, to, angle, domain, transposed)
}

/// The exact NURBS surface of `profile` turned about the axis `from → to` through `angle`,
/// with the angle direction on `domain`.
///
/// # Errors
/// [`Error::Invalid`] for a zero-length axis; [`Error::Geometry`] from the kernel.
pub fn revolve(
    profile: &NurbsCurve,
    from: Point3,
    to: Point3,
    angle: Interval,
    domain: Interval,
    transposed: bool,
) -> Result<NurbsSurface> {
    let z = to - from;
    let len = z.length();
    if !(len.is_finite() && len > 0.0) {
        return Err(Error::Invalid("ON_RevSurface axis has zero length".into()));
    }
    let z = z * (1.0 / len);
    let sweep = angle.t1 - angle.t0;
    let unit = Circle::new(Plane::WORLD_XY, 1.0).map_err(geometry("ON_RevSurface arc"))?;
    let arc = if (sweep - std::f64::consts::TAU).abs() <= 1e-12 * std::f64::consts::TAU {
        // A full turn from angle.t0: the unit circle's NURBS form, turned to start there.
        let c = unit.to_nurbs();
        let (s, k) = angle.t0.sin_cos();
        let pts: Vec<Point3> = c
            .points()
            .iter()
            .map(|p| Point3::new(k * p.x - s * p.y, s * p.x + k * p.y, 0.0))
            .collect();
        NurbsCurve::new(c.degree(), pts, c.weights().to_vec(), c.knots().to_vec())
            .map_err(geometry("ON_RevSurface arc"))?
    } else {
        Arc::new(unit, angle)
            .map_err(geometry("ON_RevSurface arc"))?
            .to_nurbs()
    };
    let arc = arc
        .reparameterized(domain)
        .map_err(geometry("ON_RevSurface domain"))?;
    let (na, np) = (arc.point_count(), profile.point_count());
    let mut points = Vec::with_capacity(na * np);
    let mut weights = Vec::with_capacity(na * np);
    // Row-major over (u, v): u is the angle unless transposed.
    let (nu, nv) = if transposed { (np, na) } else { (na, np) };
    for i in 0..nu {
        for j in 0..nv {
            let (k, m) = if transposed { (j, i) } else { (i, j) };
            let q = arc.points()[k];
            let p = profile.points()[m];
            let rel = p - from;
            let h = rel.dot(z);
            let radial = rel - z * h;
            let rho = radial.length();
            let point = if rho == 0.0 {
                p
            } else {
                let x = radial * (1.0 / rho);
                let y: Vector3 = z.cross(x);
                from + z * h + x * (rho * q.x) + y * (rho * q.y)
            };
            points.push(point);
            weights.push(arc.weights()[k] * profile.weights()[m]);
        }
    }
    let (degrees, knots) = if transposed {
        (
            [profile.degree(), arc.degree()],
            [profile.knots().to_vec(), arc.knots().to_vec()],
        )
    } else {
        (
            [arc.degree(), profile.degree()],
            [arc.knots().to_vec(), profile.knots().to_vec()],
        )
    };
    NurbsSurface::from_flat(degrees, [nu, nv], points, weights, knots)
        .map_err(geometry("ON_RevSurface"))
}
