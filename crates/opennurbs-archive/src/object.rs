//! Object records: the class id, the class data and the end mark around one object.

use crate::binary::{Reader, Writer, tcode};
use crate::{Error, Geometry, Result, Versions, curve, mesh, nurbs};

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
    read_record(r, |r, class| match class {
        ClassId::MESH => mesh::read(r, v).map(Geometry::Mesh),
        ClassId::NURBS_SURFACE => nurbs::read_surface(r).map(Geometry::Surface),
        ClassId::NURBS_CURVE
        | ClassId::LINE_CURVE
        | ClassId::POLYLINE_CURVE
        | ClassId::ARC_CURVE
        | ClassId::POLY_CURVE => curve::read_class(r, class, v, depth).map(Geometry::Curve),
        other => Err(Error::UnsupportedClass {
            id: other.to_string(),
            name: other.name(),
        }),
    })
}
