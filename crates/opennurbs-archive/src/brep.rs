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
//! Reading B-reps is not supported yet: the kernel has no validated constructor from parts.

use locus_kernel::{Brep, LoopKind, Point3, TrimKind};

use crate::binary::{Writer, tcode};
use crate::object::{ClassId, write_record};
use crate::{Result, nurbs};

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
