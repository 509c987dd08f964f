//! Boundary representations (B-reps): faces on NURBS surfaces bounded by trim loops, joined
//! along edges that meet at vertices, as Rhino's polysurfaces and solids.
//!
//! The topology follows openNURBS's `ON_Brep`:
//! - a [`BrepFace`] is a NURBS surface with one outer loop and any number of inner loops
//!   (holes), and an orientation flag;
//! - a [`BrepLoop`] is a closed chain of trims in the face's parameter rectangle: the outer
//!   loop runs counter-clockwise, inner loops clockwise, so that the face lies to the left;
//! - a [`BrepTrim`] is a curve in the parameter rectangle (stored as a [`NurbsCurve`] with
//!   `z = 0`, so `x` is `u` and `y` is `v`), using one edge, or none where the side of the
//!   surface collapses to a point (a sphere's pole, a cone's apex);
//! - a [`BrepEdge`] is a 3-D curve between two vertices, used by one trim (a naked edge), two
//!   trims (an interior edge: two faces joined, or a seam where a face meets itself), or more
//!   (a non-manifold edge);
//! - a [`BrepVertex`] is a point where edges meet.
//!
//! All indices refer to the owning [`Brep`]'s arrays. B-reps are built by the constructors in
//! this module's siblings (`Brep::from_box_corners`, `Brep::from_sphere`, ...), which
//! guarantee consistent topology; the parts are then read-only.

pub(crate) mod bounding_box;
pub(crate) mod builders;
pub(crate) mod cap;
pub(crate) mod extrude;
pub(crate) mod join;
pub(crate) mod mass;
pub(crate) mod parts;
pub(crate) mod pipe;
pub(crate) mod planar;
pub(crate) mod sweep;
pub(crate) mod wireframe;

use crate::surface::direction::SurfaceSide;
use crate::{Error, NurbsCurve, NurbsSurface, Point3, Result, Transform};

/// A vertex of a B-rep.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepVertex {
    /// The location.
    pub point: Point3,
    /// The edges that start or end here.
    pub edges: Vec<usize>,
}

/// An edge of a B-rep: a 3-D curve from `vertices[0]` to `vertices[1]`.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepEdge {
    /// The 3-D curve, from the first vertex to the second.
    pub curve: NurbsCurve,
    /// The start and end vertices (equal for a closed edge such as a full circle).
    pub vertices: [usize; 2],
    /// The trims that use this edge.
    pub trims: Vec<usize>,
}

/// How a trim relates to the rest of the B-rep (openNURBS's `ON_BrepTrim::TYPE`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TrimKind {
    /// The trim's edge has no other trim: the face's border is open there.
    Boundary,
    /// The trim's edge is shared with a trim of another face.
    Mated,
    /// The trim's edge is shared with another trim of the same face: the face is closed
    /// across it, like the seam of a sphere or cylinder.
    Seam,
    /// The trim has no edge: the side of the surface it runs along collapses to one point.
    Singular,
}

/// A trim: a curve in the parameter rectangle of a face, along the boundary of its trimmed
/// region.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepTrim {
    /// The 2-D curve, `x = u` and `y = v` with `z = 0`, in the direction of its loop.
    pub curve: NurbsCurve,
    /// The edge the trim runs along, or `None` for a singular trim.
    pub edge: Option<usize>,
    /// Whether the trim runs against its edge's direction.
    pub reversed: bool,
    /// How the trim relates to the rest of the B-rep.
    pub kind: TrimKind,
    /// The loop the trim belongs to.
    pub loop_index: usize,
    /// The vertices at the trim's start and end (in the trim's direction).
    pub vertices: [usize; 2],
}

/// Whether a loop bounds a face from outside or cuts a hole into it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LoopKind {
    /// The outer boundary, counter-clockwise in the parameter rectangle.
    Outer,
    /// A hole, clockwise in the parameter rectangle.
    Inner,
}

/// A closed chain of trims in one face.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepLoop {
    /// The face the loop bounds.
    pub face: usize,
    /// Outer boundary or hole.
    pub kind: LoopKind,
    /// The trims in order; each ends where the next starts.
    pub trims: Vec<usize>,
}

/// A face: a NURBS surface restricted to the region its loops bound.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepFace {
    /// The underlying surface.
    pub surface: NurbsSurface,
    /// The loops, the outer one first.
    pub loops: Vec<usize>,
    /// Whether the face's outward direction is opposite to the surface normal `Su × Sv`
    /// (openNURBS's `m_bRev`).
    pub reversed: bool,
}

/// How many faces meet at an edge (Grasshopper's Brep Edges: naked, interior,
/// non-manifold).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum EdgeKind {
    /// Used by one trim: on the open border of the B-rep.
    Naked,
    /// Used by exactly two trims: two faces joined there, or a face closed on itself.
    Interior,
    /// Used by three or more trims.
    NonManifold,
}

/// A boundary representation: faces, loops, trims, edges and vertices.
///
/// # Examples
/// ```
/// use locus_kernel::{Brep, EdgeKind, Interval, OrientedBox, Plane};
/// # fn main() -> locus_kernel::Result<()> {
/// let b = Brep::from_box(&OrientedBox::new(
///     Plane::WORLD_XY,
///     Interval::new(0.0, 2.0),
///     Interval::new(0.0, 3.0),
///     Interval::new(0.0, 4.0),
/// ))?;
/// assert_eq!((b.faces().len(), b.edges().len(), b.vertices().len()), (6, 12, 8));
/// assert!(b.is_solid());
/// // Planar faces are integrated exactly, up to rounding.
/// assert!((b.volume()? - 24.0).abs() < 1e-13);
///
/// // Deconstruct it: each face on its own has four naked edges and an area.
/// let top = b.extract_face(5)?;
/// assert_eq!(top.edges_of_kind(EdgeKind::Naked).len(), 4);
/// assert!((top.area()? - 6.0).abs() < 1e-13);
/// # Ok(())
/// # }
/// ```
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Brep {
    pub(crate) faces: Vec<BrepFace>,
    pub(crate) loops: Vec<BrepLoop>,
    pub(crate) trims: Vec<BrepTrim>,
    pub(crate) edges: Vec<BrepEdge>,
    pub(crate) vertices: Vec<BrepVertex>,
}

impl Brep {
    /// The faces.
    #[inline]
    pub fn faces(&self) -> &[BrepFace] {
        &self.faces
    }

    /// The loops.
    #[inline]
    pub fn loops(&self) -> &[BrepLoop] {
        &self.loops
    }

    /// The trims.
    #[inline]
    pub fn trims(&self) -> &[BrepTrim] {
        &self.trims
    }

    /// The edges.
    #[inline]
    pub fn edges(&self) -> &[BrepEdge] {
        &self.edges
    }

    /// The vertices.
    #[inline]
    pub fn vertices(&self) -> &[BrepVertex] {
        &self.vertices
    }

    /// How many faces meet at edge `index`, or `None` if there is no such edge.
    pub fn edge_kind(&self, index: usize) -> Option<EdgeKind> {
        self.edges.get(index).map(|e| match e.trims.len() {
            0 | 1 => EdgeKind::Naked,
            2 => EdgeKind::Interior,
            _ => EdgeKind::NonManifold,
        })
    }

    /// The indices of the edges of the given kind, in order.
    pub fn edges_of_kind(&self, kind: EdgeKind) -> Vec<usize> {
        (0..self.edges.len())
            .filter(|&i| self.edge_kind(i) == Some(kind))
            .collect()
    }

    /// Whether the B-rep encloses a volume: it has faces and every edge is interior (used by
    /// exactly two trims). Rhino calls such a B-rep a closed polysurface or solid.
    pub fn is_solid(&self) -> bool {
        !self.faces.is_empty() && self.edges.iter().all(|e| e.trims.len() == 2)
    }

    /// The points where a side of a face collapses: the vertices of the singular trims, such
    /// as a sphere's poles and a cone's apex, each once.
    pub fn singular_points(&self) -> Vec<Point3> {
        let mut seen: Vec<usize> = Vec::new();
        for t in &self.trims {
            if t.kind == TrimKind::Singular && !seen.contains(&t.vertices[0]) {
                seen.push(t.vertices[0]);
            }
        }
        seen.into_iter().map(|v| self.vertices[v].point).collect()
    }

    /// The B-rep transformed by `xform`: surfaces, edge curves and vertices are transformed,
    /// trims (which live in parameter space) are kept. A transform that mirrors (negative
    /// determinant) flips every face's orientation flag so that outward stays outward.
    ///
    /// # Errors
    /// As [`NurbsSurface::transformed`] and [`NurbsCurve::transformed`].
    pub fn transformed(&self, xform: &Transform) -> Result<Self> {
        let mut out = self.clone();
        let mirror = xform.matrix.determinant() < 0.0;
        for f in &mut out.faces {
            f.surface = f.surface.transformed(xform)?;
            f.reversed ^= mirror;
        }
        for e in &mut out.edges {
            e.curve = e.curve.transformed(xform)?;
        }
        for v in &mut out.vertices {
            v.point = xform.transform_point(v.point);
            if !v.point.is_finite() {
                return Err(Error::NotFinite {
                    what: "transformed vertex",
                });
            }
        }
        Ok(out)
    }

    /// Face `index` as a B-rep of its own (Rhino's `ExtractFace`, Grasshopper's Deconstruct
    /// Brep): the face with its loops and trims, and the edges and vertices they use. Edges the
    /// face shared with other faces become naked; a seam stays interior.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] if there is no face `index`.
    pub fn extract_face(&self, index: usize) -> Result<Self> {
        self.faces.get(index).ok_or_else(|| {
            Error::InvalidInput(format!(
                "face index {index} is out of range for a brep with {} faces",
                self.faces.len()
            ))
        })?;
        Ok(self.subset(&[index]))
    }

    /// The B-rep of the given faces (in that order) with their loops and trims, and the edges
    /// and vertices these use, renumbered in order of first use.
    pub(crate) fn subset(&self, faces: &[usize]) -> Self {
        let mut out = Self::default();
        let mut vertex_map: Vec<Option<usize>> = vec![None; self.vertices.len()];
        let mut edge_map: Vec<Option<usize>> = vec![None; self.edges.len()];
        let mut map_vertex = |out: &mut Self, v: usize| -> usize {
            *vertex_map[v].get_or_insert_with(|| {
                out.vertices.push(BrepVertex {
                    point: self.vertices[v].point,
                    edges: Vec::new(),
                });
                out.vertices.len() - 1
            })
        };
        for &f in faces {
            let face = &self.faces[f];
            let face_index = out.faces.len();
            out.faces.push(BrepFace {
                surface: face.surface.clone(),
                loops: Vec::new(),
                reversed: face.reversed,
            });
            for &l in &face.loops {
                let old_loop = &self.loops[l];
                let loop_index = out.loops.len();
                out.loops.push(BrepLoop {
                    face: face_index,
                    kind: old_loop.kind,
                    trims: Vec::new(),
                });
                out.faces[face_index].loops.push(loop_index);
                for &t in &old_loop.trims {
                    let trim = &self.trims[t];
                    let vertices = [
                        map_vertex(&mut out, trim.vertices[0]),
                        map_vertex(&mut out, trim.vertices[1]),
                    ];
                    let edge = trim.edge.map(|e| match edge_map[e] {
                        Some(new) => new,
                        None => {
                            let old = &self.edges[e];
                            let ends = [
                                map_vertex(&mut out, old.vertices[0]),
                                map_vertex(&mut out, old.vertices[1]),
                            ];
                            out.edges.push(BrepEdge {
                                curve: old.curve.clone(),
                                vertices: ends,
                                trims: Vec::new(),
                            });
                            edge_map[e] = Some(out.edges.len() - 1);
                            out.edges.len() - 1
                        }
                    });
                    out.loops[loop_index].trims.push(out.trims.len());
                    out.trims.push(BrepTrim {
                        curve: trim.curve.clone(),
                        edge,
                        reversed: trim.reversed,
                        kind: trim.kind,
                        loop_index,
                        vertices,
                    });
                }
            }
        }
        out.link();
        out
    }

    /// Recomputes the derived topology: the trims of each edge, the edges of each vertex and
    /// the kind of each trim.
    pub(crate) fn link(&mut self) {
        for e in &mut self.edges {
            e.trims.clear();
        }
        for v in &mut self.vertices {
            v.edges.clear();
        }
        for (t, trim) in self.trims.iter().enumerate() {
            if let Some(e) = trim.edge {
                self.edges[e].trims.push(t);
            }
        }
        for (e, edge) in self.edges.iter().enumerate() {
            for &v in &edge.vertices {
                if !self.vertices[v].edges.contains(&e) {
                    self.vertices[v].edges.push(e);
                }
            }
        }
        let face_of =
            |trims: &[BrepTrim], loops: &[BrepLoop], t: usize| loops[trims[t].loop_index].face;
        let kinds: Vec<TrimKind> = (0..self.trims.len())
            .map(|t| match self.trims[t].edge {
                None => TrimKind::Singular,
                Some(e) => {
                    let users = &self.edges[e].trims;
                    if users.len() < 2 {
                        TrimKind::Boundary
                    } else if users.len() == 2
                        && face_of(&self.trims, &self.loops, users[0])
                            == face_of(&self.trims, &self.loops, users[1])
                    {
                        TrimKind::Seam
                    } else {
                        TrimKind::Mated
                    }
                }
            })
            .collect();
        for (trim, kind) in self.trims.iter_mut().zip(kinds) {
            trim.kind = kind;
        }
    }

    /// Whether face `f` is its whole surface: one loop, every trim along a side of the
    /// parameter rectangle.
    pub fn is_untrimmed(&self, f: usize) -> bool {
        let face = &self.faces[f];
        face.loops.len() == 1
            && self.loops[face.loops[0]]
                .trims
                .iter()
                .all(|&t| self.trim_side(t).is_some())
    }

    /// The side of a face's parameter rectangle that a trim runs along, if it runs exactly
    /// along one (an iso-parametric trim on the boundary).
    pub fn trim_side(&self, trim: usize) -> Option<SurfaceSide> {
        let t = self.trims.get(trim)?;
        let surface = &self.faces[self.loops[t.loop_index].face].surface;
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let (a, b) = (t.curve.start_point(), t.curve.end_point());
        let mid = t.curve.point_at(t.curve.domain().mid());
        let all = |f: &dyn Fn(Point3) -> bool| f(a) && f(b) && f(mid);
        if all(&|p| p.y == dv.t0) {
            Some(SurfaceSide::South)
        } else if all(&|p| p.x == du.t1) {
            Some(SurfaceSide::East)
        } else if all(&|p| p.y == dv.t1) {
            Some(SurfaceSide::North)
        } else if all(&|p| p.x == du.t0) {
            Some(SurfaceSide::West)
        } else {
            None
        }
    }
}
