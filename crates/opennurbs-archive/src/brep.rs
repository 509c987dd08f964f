//! `ON_Brep` class data, version 3.3 (3dm version 60 and later).
//!
//! A B-rep is stored as eight arrays, each in an anonymous chunk with a version byte and a
//! count: 2-D trim curves (`m_C2`) and 3-D edge curves (`m_C3`) as object records, surfaces
//! (`m_S`) as object records, then vertices, edges, trims, loops and faces, which refer to
//! the curves, the surfaces and each other by index. Then follow the bounding box, a chunk of
//! render meshes and one of analysis meshes (one flag byte per face), the solid flag and a
//! region topology chunk.
//!
//! locus writes one trim curve per trim, one edge curve per edge and one surface per face, in
//! the kernel's order, so every index is the element's own. Trim curves are written as 2-D
//! curves (`x = u`, `y = v`), as openNURBS requires.
//!
//! On read, each edge and trim takes the part of its curve that its proxy domain selects, in
//! its direction, on its own domain; faces on `ON_NurbsSurface`, `ON_PlaneSurface` and
//! `ON_RevSurface` (untrimmed inside its domain: spheres, cylinders, cones) are read, other
//! surface classes are refused with their class name; back references and trim kinds are
//! recomputed and checked by the kernel's `Brep::from_parts`.

use locus_kernel::{
    Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex, Interval, LoopKind, NurbsCurve,
    NurbsSurface, Point3, TrimKind,
};

use crate::binary::{Reader, Writer, tcode};
use crate::object::{ClassId, read_class, read_object, read_record, write_record};
use crate::{Error, Geometry, Result, Versions, nurbs};

/// The tolerance written for vertices, edges and trims: 0, since the kernel's B-reps are built
/// exactly (edges and trims meet their vertices exactly). openNURBS's validator requires a
/// tolerance ≥ 0.
const TOLERANCE: f64 = 0.0;

fn write_indices(w: &mut Writer, indices: impl ExactSizeIterator<Item = usize>) -> Result<()> {
    w.count(indices.len())?;
    for i in indices {
        w.count(i)?;
    }
    Ok(())
}

/// openNURBS's iso flag of a trim (`ON_Surface::ISO`): 3 west, 4 south, 5 east, 6 north, 1/2
/// for an interior constant-`u`/`v` line, 0 otherwise.
fn iso_flag(brep: &Brep, trim: usize) -> i32 {
    use locus_kernel::SurfaceSide;
    match brep.trim_side(trim) {
        Some(SurfaceSide::West) => 3,
        Some(SurfaceSide::South) => 4,
        Some(SurfaceSide::East) => 5,
        Some(SurfaceSide::North) => 6,
        None => {
            let c = &brep.trims()[trim].curve;
            let p = c.points();
            if p.iter().all(|q| q.x == p[0].x) {
                1
            } else if p.iter().all(|q| q.y == p[0].y) {
                2
            } else {
                0
            }
        }
    }
}

fn trim_type(kind: TrimKind) -> i32 {
    match kind {
        TrimKind::Boundary => 1,
        TrimKind::Mated => 2,
        TrimKind::Seam => 3,
        TrimKind::Singular => 4,
    }
}

/// Writes an array chunk of object records, one per item.
fn object_array<T>(
    w: &mut Writer,
    items: &[T],
    class: ClassId,
    body: impl Fn(&mut Writer, &T) -> Result<()>,
) -> Result<()> {
    w.begin_chunk(tcode::ANONYMOUS_CHUNK);
    w.version(1, 0);
    w.count(items.len())?;
    for item in items {
        w.i32(1);
        write_record(w, class, |w| body(w, item))?;
    }
    w.end_chunk();
    Ok(())
}

/// The bounding box of the B-rep: of its surfaces' control points (which hold every face).
fn bounding_box(b: &Brep) -> [Point3; 2] {
    let mut lo = Point3::new(f64::INFINITY, f64::INFINITY, f64::INFINITY);
    let mut hi = Point3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    for p in b.faces().iter().flat_map(|f| f.surface.points()) {
        lo = Point3::new(lo.x.min(p.x), lo.y.min(p.y), lo.z.min(p.z));
        hi = Point3::new(hi.x.max(p.x), hi.y.max(p.y), hi.z.max(p.z));
    }
    [lo, hi]
}

/// Writes `ON_Brep` class data.
///
/// # Errors
/// [`crate::Error::TooLarge`] for counts above `i32::MAX`.
pub fn write(w: &mut Writer, b: &Brep) -> Result<()> {
    w.version(3, 3);
    object_array(w, b.trims(), ClassId::NURBS_CURVE, |w, t| {
        nurbs::write_curve_dim(w, &t.curve, 2)
    })?;
    object_array(w, b.edges(), ClassId::NURBS_CURVE, |w, e| {
        nurbs::write_curve(w, &e.curve)
    })?;
    object_array(w, b.faces(), ClassId::NURBS_SURFACE, |w, f| {
        nurbs::write_surface(w, &f.surface)
    })?;

    // Vertices.
    w.begin_chunk(tcode::ANONYMOUS_CHUNK);
    w.version(1, 0);
    w.count(b.vertices().len())?;
    for (i, v) in b.vertices().iter().enumerate() {
        w.count(i)?;
        w.f64s(&[v.point.x, v.point.y, v.point.z]);
        write_indices(w, v.edges.iter().copied())?;
        w.f64(TOLERANCE);
    }
    w.end_chunk();

    // Edges.
    w.begin_chunk(tcode::ANONYMOUS_CHUNK);
    w.version(1, 0);
    w.count(b.edges().len())?;
    for (i, e) in b.edges().iter().enumerate() {
        let d = e.curve.domain();
        w.count(i)?;
        w.count(i)?; // its curve
        w.i32(0); // proxy curve not reversed
        w.interval(d.t0, d.t1);
        w.count(e.vertices[0])?;
        w.count(e.vertices[1])?;
        write_indices(w, e.trims.iter().copied())?;
        w.f64(TOLERANCE);
        w.interval(d.t0, d.t1);
    }
    w.end_chunk();

    // Trims.
    w.begin_chunk(tcode::ANONYMOUS_CHUNK);
    w.version(1, 0);
    w.count(b.trims().len())?;
    for (i, t) in b.trims().iter().enumerate() {
        let d = t.curve.domain();
        w.count(i)?;
        w.count(i)?; // its curve
        w.interval(d.t0, d.t1);
        match t.edge {
            Some(e) => w.count(e)?,
            None => w.i32(-1),
        }
        w.count(t.vertices[0])?;
        w.count(t.vertices[1])?;
        w.i32(i32::from(t.reversed));
        w.i32(trim_type(t.kind));
        w.i32(iso_flag(b, i));
        w.count(t.loop_index)?;
        w.f64s(&[TOLERANCE, TOLERANCE]);
        w.interval(d.t0, d.t1);
        w.bytes(&[0; 8]); // proxy curve not reversed
        w.bytes(&[0; 24]);
        w.f64s(&[0.0, 0.0]); // legacy 2-D and 3-D tolerances
    }
    w.end_chunk();

    // Loops.
    w.begin_chunk(tcode::ANONYMOUS_CHUNK);
    w.version(1, 0);
    w.count(b.loops().len())?;
    for (i, l) in b.loops().iter().enumerate() {
        w.count(i)?;
        write_indices(w, l.trims.iter().copied())?;
        w.i32(match l.kind {
            LoopKind::Outer => 1,
            LoopKind::Inner => 2,
        });
        w.count(l.face)?;
    }
    w.end_chunk();

    // Faces (1.1: per-face ids follow the faces).
    w.begin_chunk(tcode::ANONYMOUS_CHUNK);
    w.version(1, 1);
    w.count(b.faces().len())?;
    for (i, f) in b.faces().iter().enumerate() {
        w.count(i)?;
        write_indices(w, f.loops.iter().copied())?;
        w.count(i)?; // its surface
        w.i32(i32::from(f.reversed));
        w.i32(0); // material channel
    }
    for _ in b.faces() {
        w.uuid(&[0; 16]);
    }
    w.end_chunk();

    let [lo, hi] = bounding_box(b);
    w.f64s(&[lo.x, lo.y, lo.z, hi.x, hi.y, hi.z]);
    // No render meshes, no analysis meshes.
    for _ in 0..2 {
        w.begin_chunk(tcode::ANONYMOUS_CHUNK);
        for _ in b.faces() {
            w.u8(0);
        }
        w.end_chunk();
    }
    w.i32(0); // solid: not known
    w.begin_versioned_chunk(tcode::ANONYMOUS_CHUNK, 1, 1);
    w.bool(false); // no region topology
    w.end_chunk();
    Ok(())
}

/// Turns an openNURBS index into an index into an array of `len` items.
fn index(i: i32, len: usize, what: &str) -> Result<usize> {
    usize::try_from(i)
        .ok()
        .filter(|&u| u < len)
        .ok_or_else(|| Error::Invalid(format!("{what} {i} is out of range (there are {len})")))
}

fn read_indices(r: &mut Reader<'_>, what: &'static str) -> Result<Vec<i32>> {
    let n = r.count(4, what)?;
    (0..n).map(|_| r.i32(what)).collect()
}

fn read_interval(r: &mut Reader<'_>, what: &'static str) -> Result<Interval> {
    Ok(Interval::new(r.f64(what)?, r.f64(what)?))
}

/// Opens an array chunk (anonymous, version 1.x) and returns its minor version and count.
fn begin_array(r: &mut Reader<'_>, item_size: usize, what: &'static str) -> Result<(u8, usize)> {
    r.expect_chunk(tcode::ANONYMOUS_CHUNK, what)?;
    let (major, minor) = r.version(what)?;
    if major != 1 {
        return Err(Error::Invalid(format!(
            "{what} version {major}.{minor} is not supported"
        )));
    }
    Ok((minor, r.count(item_size, what)?))
}

/// Reads an array of optional object records.
fn read_objects<T>(
    r: &mut Reader<'_>,
    v: Versions,
    depth: usize,
    what: &'static str,
    pick: impl Fn(Geometry) -> Option<T>,
) -> Result<Vec<Option<T>>> {
    let (_, n) = begin_array(r, 4, what)?;
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        if r.i32(what)? == 1 {
            let g = read_object(r, v, depth + 1)?;
            let name = g.rhino_type_name();
            out.push(Some(pick(g).ok_or_else(|| {
                Error::Invalid(format!("{what} {i} is a {name}"))
            })?));
        } else {
            out.push(None);
        }
    }
    r.end_chunk()?;
    Ok(out)
}

/// Reads the surface array: each surface, and whether it was a surface of revolution (whose
/// NURBS form has other parameters inside its domain; see [`crate::revsurface`]).
fn read_surfaces(
    r: &mut Reader<'_>,
    v: Versions,
    depth: usize,
) -> Result<Vec<Option<(NurbsSurface, bool)>>> {
    let (_, n) = begin_array(r, 4, "ON_Brep surfaces")?;
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        if r.i32("ON_Brep surface flag")? != 1 {
            out.push(None);
            continue;
        }
        let s = read_record(r, |r, class| {
            let g = read_class(r, class, v, depth + 1)?;
            match g {
                Geometry::Surface(s) => Ok((s, class.demoted() == ClassId::REV_SURFACE)),
                other => Err(Error::Invalid(format!(
                    "ON_Brep surface {i} is a {}",
                    other.rhino_type_name()
                ))),
            }
        })?;
        out.push(Some(s));
    }
    r.end_chunk()?;
    Ok(out)
}

/// The part of `curve` on its proxy `sub` domain, reversed if asked, on the domain `domain`.
fn proxy_curve(
    curve: &NurbsCurve,
    sub: Interval,
    reversed: bool,
    domain: Interval,
    what: &'static str,
) -> Result<NurbsCurve> {
    let g = |source| Error::Geometry { what, source };
    let full = curve.domain();
    let mut c = if sub == full {
        curve.clone()
    } else {
        curve.trim(sub).map_err(g)?
    };
    if reversed {
        c = c.reversed();
    }
    if c.domain() != domain {
        c = c.reparameterized(domain).map_err(g)?;
    }
    Ok(c)
}

/// Reads `ON_Brep` class data (version 3.x) into a kernel B-rep. Faces on NURBS and plane
/// surfaces are supported; trims are kept in the surface's parameters.
///
/// # Errors
/// [`Error::Invalid`] for versions, indices, trim or loop types that locus does not read,
/// [`Error::Geometry`] when the parts do not make a valid B-rep, and every reading error.
pub fn read(r: &mut Reader<'_>, v: Versions, depth: usize) -> Result<Brep> {
    let (major, minor) = r.version("ON_Brep version")?;
    if major != 3 {
        return Err(Error::Invalid(format!(
            "ON_Brep version {major}.{minor} is not supported (locus reads 3.x)"
        )));
    }
    let curve = |g: Geometry| match g {
        Geometry::Curve(c) => Some(c.to_nurbs()),
        _ => None,
    };
    let c2 = read_objects(r, v, depth, "ON_Brep trim curve", curve)?;
    let c3 = read_objects(r, v, depth, "ON_Brep edge curve", curve)?;
    let srf = read_surfaces(r, v, depth)?;

    let (_, n) = begin_array(r, 40, "ON_Brep vertices")?;
    let mut raw_vertices = Vec::with_capacity(n);
    for _ in 0..n {
        r.i32("ON_Brep vertex index")?;
        let p = Point3::new(r.f64("vertex")?, r.f64("vertex")?, r.f64("vertex")?);
        if !p.is_finite() {
            return Err(Error::Invalid("an ON_Brep vertex is not finite".into()));
        }
        read_indices(r, "ON_Brep vertex edges")?;
        r.f64("ON_Brep vertex tolerance")?;
        raw_vertices.push(p);
    }
    r.end_chunk()?;
    let nv = raw_vertices.len();

    let (_, n) = begin_array(r, 64, "ON_Brep edges")?;
    let mut edges = Vec::with_capacity(n);
    for i in 0..n {
        r.i32("ON_Brep edge index")?;
        let c3i = r.i32("ON_Brep edge curve index")?;
        let reversed = r.i32("ON_Brep edge reversed flag")? != 0;
        let sub = read_interval(r, "ON_Brep edge proxy domain")?;
        let vi = [r.i32("ON_Brep edge vertex")?, r.i32("ON_Brep edge vertex")?];
        read_indices(r, "ON_Brep edge trims")?;
        r.f64("ON_Brep edge tolerance")?;
        let domain = read_interval(r, "ON_Brep edge domain")?;
        let c = c3
            .get(index(c3i, c3.len(), "ON_Brep edge curve index")?)
            .and_then(Option::as_ref)
            .ok_or_else(|| Error::Invalid(format!("ON_Brep edge {i} has no curve")))?;
        edges.push(BrepEdge {
            curve: proxy_curve(c, sub, reversed, domain, "ON_Brep edge")?,
            vertices: [
                index(vi[0], nv, "ON_Brep edge vertex")?,
                index(vi[1], nv, "ON_Brep edge vertex")?,
            ],
            trims: Vec::new(),
        });
    }
    r.end_chunk()?;

    let (_, n) = begin_array(r, 132, "ON_Brep trims")?;
    let mut trims = Vec::with_capacity(n);
    for i in 0..n {
        r.i32("ON_Brep trim index")?;
        let c2i = r.i32("ON_Brep trim curve index")?;
        let sub = read_interval(r, "ON_Brep trim proxy domain")?;
        let ei = r.i32("ON_Brep trim edge")?;
        let vi = [r.i32("ON_Brep trim vertex")?, r.i32("ON_Brep trim vertex")?];
        let rev3d = r.i32("ON_Brep trim reversed flag")? != 0;
        let kind = r.i32("ON_Brep trim type")?;
        r.i32("ON_Brep trim iso flag")?;
        let li = r.i32("ON_Brep trim loop")?;
        r.skip(16, "ON_Brep trim tolerances")?;
        let domain = read_interval(r, "ON_Brep trim domain")?;
        let proxy_reversed = r.bytes(8, "ON_Brep trim proxy flags")?[0] == 1;
        r.skip(24 + 16, "ON_Brep trim legacy fields")?;
        let edge = match kind {
            1..=3 => Some(index(ei, edges.len(), "ON_Brep trim edge")?),
            4 => None,
            k => {
                return Err(Error::Invalid(format!(
                    "ON_Brep trim {i} has type {k}; locus reads boundary, mated, seam and \
                     singular trims"
                )));
            }
        };
        let c = c2
            .get(index(c2i, c2.len(), "ON_Brep trim curve index")?)
            .and_then(Option::as_ref)
            .ok_or_else(|| Error::Invalid(format!("ON_Brep trim {i} has no curve")))?;
        trims.push(BrepTrim {
            curve: proxy_curve(c, sub, proxy_reversed, domain, "ON_Brep trim")?,
            edge,
            reversed: rev3d,
            kind: TrimKind::Boundary, // recomputed by Brep::from_parts
            loop_index: usize::try_from(li)
                .map_err(|_| Error::Invalid(format!("ON_Brep trim {i} has loop index {li}")))?,
            vertices: [
                index(vi[0], nv, "ON_Brep trim vertex")?,
                index(vi[1], nv, "ON_Brep trim vertex")?,
            ],
        });
    }
    r.end_chunk()?;

    let (_, n) = begin_array(r, 16, "ON_Brep loops")?;
    let mut loops = Vec::with_capacity(n);
    for i in 0..n {
        r.i32("ON_Brep loop index")?;
        let ti = read_indices(r, "ON_Brep loop trims")?;
        let kind = match r.i32("ON_Brep loop type")? {
            1 => LoopKind::Outer,
            2 => LoopKind::Inner,
            k => {
                return Err(Error::Invalid(format!(
                    "ON_Brep loop {i} has type {k}; locus reads outer and inner loops"
                )));
            }
        };
        let fi = r.i32("ON_Brep loop face")?;
        loops.push(BrepLoop {
            face: usize::try_from(fi)
                .map_err(|_| Error::Invalid(format!("ON_Brep loop {i} has face index {fi}")))?,
            kind,
            trims: ti
                .iter()
                .map(|&t| index(t, trims.len(), "ON_Brep loop trim"))
                .collect::<Result<_>>()?,
        });
    }
    r.end_chunk()?;

    let (face_minor, n) = begin_array(r, 20, "ON_Brep faces")?;
    let mut faces = Vec::with_capacity(n);
    let mut revolved_faces = Vec::new();
    for i in 0..n {
        r.i32("ON_Brep face index")?;
        let li = read_indices(r, "ON_Brep face loops")?;
        let si = r.i32("ON_Brep face surface")?;
        let reversed = r.i32("ON_Brep face reversed flag")? != 0;
        r.i32("ON_Brep face material channel")?;
        let (surface, revolved) = srf
            .get(index(si, srf.len(), "ON_Brep face surface")?)
            .and_then(Option::as_ref)
            .ok_or_else(|| Error::Invalid(format!("ON_Brep face {i} has no surface")))?
            .clone();
        if revolved {
            revolved_faces.push(i);
        }
        faces.push(BrepFace {
            surface,
            loops: li
                .iter()
                .map(|&l| index(l, loops.len(), "ON_Brep face loop"))
                .collect::<Result<_>>()?,
            reversed,
        });
    }
    if face_minor >= 1 {
        r.skip(
            n.checked_mul(16).ok_or(Error::TooLarge(n))?,
            "ON_Brep face ids",
        )?;
        if face_minor >= 2 && r.bool("ON_Brep face colour flag")? {
            r.skip(n * 4, "ON_Brep face colours")?;
        }
    }
    r.end_chunk()?;

    // Bounding box, then (3.1) render and analysis meshes, (3.2) the solid flag, (3.3) the
    // region topology: read past them so that the class data's CRC is checked.
    r.skip(48, "ON_Brep bounding box")?;
    if minor >= 1 {
        r.skip_chunk()?;
        r.skip_chunk()?;
    }
    if minor >= 2 {
        r.i32("ON_Brep solid flag")?;
    }
    if minor >= 3 {
        r.skip_chunk()?;
    }

    // Trims of faces on surfaces of revolution must run along the sides of the parameter
    // rectangle, where the NURBS form's parameters are the revolution's.
    for &f in &revolved_faces {
        let s = &faces[f].surface;
        let (du, dv) = (s.domain_u(), s.domain_v());
        for &l in &faces[f].loops {
            for &t in loops.get(l).map_or(&[][..], |l| &l.trims[..]) {
                let pts = trims[t].curve.points();
                let along = |c: fn(&Point3) -> f64, a: f64, b: f64| {
                    pts.iter().all(|p| c(p) == a) || pts.iter().all(|p| c(p) == b)
                };
                if !(along(|p| p.x, du.t0, du.t1) || along(|p| p.y, dv.t0, dv.t1)) {
                    return Err(Error::Invalid(format!(
                        "ON_Brep face {f} is a surface of revolution trimmed inside its domain \
                         (trim {t}); locus reads such faces only untrimmed"
                    )));
                }
            }
        }
    }
    let vertices = raw_vertices
        .into_iter()
        .map(|point| BrepVertex {
            point,
            edges: Vec::new(),
        })
        .collect();
    Brep::from_parts(vertices, edges, trims, loops, faces).map_err(|source| Error::Geometry {
        what: "ON_Brep",
        source,
    })
}
