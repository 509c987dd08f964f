//! Object records: the class id, the class data and the end mark around one object.

use crate::binary::{Reader, Writer, tcode};
use crate::{Error, Geometry, Result, Versions, brep, curve, mesh, nurbs, revsurface};

/// An openNURBS class id (`ON_ClassId::Uuid`), in the usual text byte order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ClassId(pub [u8; 16]);

const fn id(d1: u32, d2: u16, d3: u16, d4: [u8; 8]) -> ClassId {
    let a = d1.to_be_bytes();
    let b = d2.to_be_bytes();
    let c = d3.to_be_bytes();
    ClassId([
        a[0], a[1], a[2], a[3], b[0], b[1], c[0], c[1], d4[0], d4[1], d4[2], d4[3], d4[4], d4[5],
        d4[6], d4[7],
    ])
}

const E947: [u8; 8] = [0xBF, 0xE5, 0x00, 0x10, 0x83, 0x01, 0x22, 0xF0];

impl ClassId {
    /// `ON_Mesh`, 4ED7D4E4-E947-11d3-BFE5-0010830122F0.
    pub const MESH: Self = id(0x4ED7_D4E4, 0xE947, 0x11d3, E947);
    /// `ON_NurbsCurve`, 4ED7D4DD-E947-11d3-BFE5-0010830122F0.
    pub const NURBS_CURVE: Self = id(0x4ED7_D4DD, 0xE947, 0x11d3, E947);
    /// `ON_NurbsSurface`, 4ED7D4DE-E947-11d3-BFE5-0010830122F0.
    pub const NURBS_SURFACE: Self = id(0x4ED7_D4DE, 0xE947, 0x11d3, E947);
    /// `ON_LineCurve`, 4ED7D4DB-E947-11d3-BFE5-0010830122F0.
    pub const LINE_CURVE: Self = id(0x4ED7_D4DB, 0xE947, 0x11d3, E947);
    /// `ON_PolylineCurve`, 4ED7D4E6-E947-11d3-BFE5-0010830122F0.
    pub const POLYLINE_CURVE: Self = id(0x4ED7_D4E6, 0xE947, 0x11d3, E947);
    /// `ON_PolyCurve`, 4ED7D4E0-E947-11d3-BFE5-0010830122F0.
    pub const POLY_CURVE: Self = id(0x4ED7_D4E0, 0xE947, 0x11d3, E947);
    /// `ON_ArcCurve`, CF33BE2A-09B4-11d4-BFFB-0010830122F0.
    pub const ARC_CURVE: Self = id(
        0xCF33_BE2A,
        0x09B4,
        0x11d4,
        [0xBF, 0xFB, 0x00, 0x10, 0x83, 0x01, 0x22, 0xF0],
    );
    /// `ON_Brep`, 60B5DBC5-E660-11d3-BFE4-0010830122F0.
    pub const BREP: Self = id(
        0x60B5_DBC5,
        0xE660,
        0x11d3,
        [0xBF, 0xE4, 0x00, 0x10, 0x83, 0x01, 0x22, 0xF0],
    );
    /// `ON_PlaneSurface`, 4ED7D4DF-E947-11d3-BFE5-0010830122F0.
    pub const PLANE_SURFACE: Self = id(0x4ED7_D4DF, 0xE947, 0x11d3, E947);
    /// `ON_RevSurface`, A16220D3-163B-11d4-8000-0010830122F0.
    pub const REV_SURFACE: Self = id(
        0xA162_20D3,
        0x163B,
        0x11d4,
        [0x80, 0x00, 0x00, 0x10, 0x83, 0x01, 0x22, 0xF0],
    );
    /// `ON_SumSurface`, C4CD5359-446D-4690-9FF5-29059732472B.
    pub const SUM_SURFACE: Self = id(
        0xC4CD_5359,
        0x446D,
        0x4690,
        [0x9F, 0xF5, 0x29, 0x05, 0x97, 0x32, 0x47, 0x2B],
    );
    /// `ON_Extrusion`, 36F53175-72B8-4d47-BF1F-B4E6FC24F4B9.
    pub const EXTRUSION: Self = id(
        0x36F5_3175,
        0x72B8,
        0x4d47,
        [0xBF, 0x1F, 0xB4, 0xE6, 0xFC, 0x24, 0xF4, 0xB9],
    );

    /// The class openNURBS reads an old or Rhino-internal class id as (`ON_ClassId::ClassId`
    /// "demotes" ids of classes it does not have): `TL_NurbsCurve` (which Rhino 6 writes for
    /// curves internalised in Grasshopper) and the old NURBS curve as `ON_NurbsCurve`,
    /// `TL_NurbsSurface` and the old NURBS surface as `ON_NurbsSurface`, the old poly curve as
    /// `ON_PolyCurve`, the old trimmed surface, old B-rep and `TL_Brep` as `ON_Brep`,
    /// `TL_RevSurface` as `ON_RevSurface`, `TL_SumSurface` as `ON_SumSurface`. Other ids are
    /// themselves.
    pub fn demoted(self) -> Self {
        const BFFE: [u8; 8] = [0xBF, 0xFE, 0x00, 0x10, 0x83, 0x01, 0x22, 0xF0];
        const OLD: [u8; 8] = [0x80, 0x00, 0x00, 0x10, 0x83, 0x01, 0x22, 0xF0];
        const OLD_BREP: [u8; 8] = [0x80, 0x0E, 0x00, 0x10, 0x83, 0x01, 0x22, 0xF0];
        const TL_NURBS_CURVE: ClassId = id(0x5EAF_1119, 0x0B51, 0x11d4, BFFE);
        const OLD_NURBS_CURVE: ClassId = id(0x76A7_09D5, 0x1550, 0x11d4, OLD);
        const TL_NURBS_SURFACE: ClassId = id(0x4760_C817, 0x0BE3, 0x11d4, BFFE);
        const OLD_NURBS_SURFACE: ClassId = id(0xFA4F_D4B5, 0x1613, 0x11d4, OLD);
        const OLD_POLY_CURVE: ClassId = id(0xEF63_8317, 0x154B, 0x11d4, OLD);
        const OLD_TRIMMED_SURFACE: ClassId = id(0x0705_FDEF, 0x3E2A, 0x11d4, OLD_BREP);
        const OLD_BREP_ID: ClassId = id(0x2D4C_FEDB, 0x3E2A, 0x11d4, OLD_BREP);
        const TL_BREP: ClassId = id(
            0xF06F_C243,
            0xA32A,
            0x4608,
            [0x9D, 0xD8, 0xA7, 0xD2, 0xC4, 0xCE, 0x2A, 0x36],
        );
        const TL_REV_SURFACE: ClassId = id(
            0x0A84_01B6,
            0x4D34,
            0x4b99,
            [0x86, 0x15, 0x1B, 0x4E, 0x72, 0x3D, 0xC4, 0xE5],
        );
        const TL_SUM_SURFACE: ClassId = id(
            0x665F_6331,
            0x2A66,
            0x4cce,
            [0x81, 0xD0, 0xB5, 0xEE, 0xBD, 0x9B, 0x54, 0x17],
        );
        match self {
            TL_NURBS_CURVE | OLD_NURBS_CURVE => Self::NURBS_CURVE,
            TL_NURBS_SURFACE | OLD_NURBS_SURFACE => Self::NURBS_SURFACE,
            OLD_POLY_CURVE => Self::POLY_CURVE,
            OLD_TRIMMED_SURFACE | OLD_BREP_ID | TL_BREP => Self::BREP,
            TL_REV_SURFACE => Self::REV_SURFACE,
            TL_SUM_SURFACE => Self::SUM_SURFACE,
            other => other,
        }
    }

    /// The class name, for messages.
    pub fn name(&self) -> &'static str {
        match *self {
            Self::MESH => "ON_Mesh",
            Self::NURBS_CURVE => "ON_NurbsCurve",
            Self::NURBS_SURFACE => "ON_NurbsSurface",
            Self::LINE_CURVE => "ON_LineCurve",
            Self::POLYLINE_CURVE => "ON_PolylineCurve",
            Self::POLY_CURVE => "ON_PolyCurve",
            Self::ARC_CURVE => "ON_ArcCurve",
            Self::BREP => "ON_Brep",
            Self::PLANE_SURFACE => "ON_PlaneSurface",
            Self::REV_SURFACE => "ON_RevSurface",
            Self::SUM_SURFACE => "ON_SumSurface",
            Self::EXTRUSION => "ON_Extrusion",
            _ => "unknown class",
        }
    }
}

impl std::fmt::Display for ClassId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let b = &self.0;
        write!(
            f,
            "{:02X}{:02X}{:02X}{:02X}-{:02X}{:02X}-{:02X}{:02X}-{:02X}{:02X}-{:02X}{:02X}{:02X}{:02X}{:02X}{:02X}",
            b[0],
            b[1],
            b[2],
            b[3],
            b[4],
            b[5],
            b[6],
            b[7],
            b[8],
            b[9],
            b[10],
            b[11],
            b[12],
            b[13],
            b[14],
            b[15]
        )
    }
}

/// Writes a whole object record around `body`, the class data.
pub(crate) fn write_record(
    w: &mut Writer,
    class: ClassId,
    body: impl FnOnce(&mut Writer) -> Result<()>,
) -> Result<()> {
    w.begin_chunk(tcode::OPENNURBS_CLASS);
    w.begin_chunk(tcode::OPENNURBS_CLASS_UUID);
    w.uuid(&class.0);
    w.end_chunk();
    w.begin_chunk(tcode::OPENNURBS_CLASS_DATA);
    body(w)?;
    w.end_chunk();
    w.short_chunk(tcode::OPENNURBS_CLASS_END, 0);
    w.end_chunk();
    Ok(())
}

/// Writes `geometry` as one object record.
pub(crate) fn write_object(w: &mut Writer, geometry: &Geometry) -> Result<()> {
    match geometry {
        Geometry::Mesh(m) => write_record(w, ClassId::MESH, |w| mesh::write(w, m)),
        Geometry::Curve(c) => curve::write_object(w, c),
        Geometry::Surface(s) => {
            write_record(w, ClassId::NURBS_SURFACE, |w| nurbs::write_surface(w, s))
        }
        Geometry::Brep(b) => write_record(w, ClassId::BREP, |w| brep::write(w, b)),
    }
}

/// Reads one object record and its class data: the class id, then `body` inside the data
/// chunk, then skips user data up to the end mark.
pub(crate) fn read_record<T>(
    r: &mut Reader<'_>,
    body: impl FnOnce(&mut Reader<'_>, ClassId) -> Result<T>,
) -> Result<T> {
    r.expect_chunk(tcode::OPENNURBS_CLASS, "object record")?;
    r.expect_chunk(tcode::OPENNURBS_CLASS_UUID, "class id")?;
    let class = ClassId(r.uuid("class id")?);
    r.end_chunk()?;
    r.expect_chunk(tcode::OPENNURBS_CLASS_DATA, "class data")?;
    let value = body(r, class)?;
    r.end_chunk()?;
    loop {
        if r.remaining() == 0 {
            return Err(Error::Invalid(format!(
                "object record of {} has no end mark",
                class.name()
            )));
        }
        let tc = r.skip_chunk()?;
        if tc == tcode::OPENNURBS_CLASS_END {
            break;
        }
    }
    r.end_chunk()?;
    Ok(value)
}

/// Reads one object record as geometry. `depth` counts the records around this one (a
/// polycurve's segments are records inside its data).
pub(crate) fn read_object(r: &mut Reader<'_>, v: Versions, depth: usize) -> Result<Geometry> {
    read_record(r, |r, class| read_class(r, class, v, depth))
}

/// Reads the class data of `class` as geometry.
pub(crate) fn read_class(
    r: &mut Reader<'_>,
    class: ClassId,
    v: Versions,
    depth: usize,
) -> Result<Geometry> {
    if depth >= crate::binary::MAX_DEPTH / 4 {
        return Err(Error::Invalid(format!(
            "objects nested deeper than {} levels",
            crate::binary::MAX_DEPTH / 4
        )));
    }
    match class.demoted() {
        ClassId::MESH => mesh::read(r, v).map(Geometry::Mesh),
        ClassId::NURBS_SURFACE => nurbs::read_surface(r).map(Geometry::Surface),
        ClassId::PLANE_SURFACE => nurbs::read_plane_surface(r).map(Geometry::Surface),
        ClassId::REV_SURFACE => revsurface::read(r, v, depth).map(Geometry::Surface),
        ClassId::BREP => brep::read(r, v, depth).map(Geometry::Brep),
        ClassId::NURBS_CURVE
        | ClassId::LINE_CURVE
        | ClassId::POLYLINE_CURVE
        | ClassId::ARC_CURVE
        | ClassId::POLY_CURVE => {
            curve::read_class(r, class.demoted(), v, depth).map(Geometry::Curve)
        }
        other => Err(Error::UnsupportedClass {
            id: other.to_string(),
            name: other.name(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use locus_kernel::{NurbsCurve, Point3};

    use super::*;

    #[test]
    fn rhino_internal_class_ids_read_as_their_opennurbs_classes() {
        let curve = NurbsCurve::new(
            2,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 2.0, 0.0),
                Point3::new(3.0, 1.0, 1.0),
            ],
            vec![1.0; 3],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .expect("a curve");
        // TL_NurbsCurve, 5EAF1119-0B51-11d4-BFFE-0010830122F0, as Rhino 6 writes it.
        let tl = id(
            0x5EAF_1119,
            0x0B51,
            0x11d4,
            [0xBF, 0xFE, 0x00, 0x10, 0x83, 0x01, 0x22, 0xF0],
        );
        assert_eq!(tl.demoted(), ClassId::NURBS_CURVE);
        let mut w = Writer::new();
        write_record(&mut w, tl, |w| nurbs::write_curve(w, &curve)).expect("written");
        let read = crate::decode(&w.into_bytes()).expect("read");
        assert_eq!(read, Geometry::Curve(locus_kernel::Curve::Nurbs(curve)));
        assert_eq!(ClassId::MESH.demoted(), ClassId::MESH);
    }
}
