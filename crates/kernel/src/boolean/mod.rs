//! Solid booleans and splits of B-reps (Rhino's `Brep.CreateBooleanUnion`,
//! `CreateBooleanDifference`, `CreateBooleanIntersection` and `Brep.Split`; Grasshopper's Solid
//! Union, Solid Difference, Solid Intersection and Split Brep).
//!
//! All four follow the same three steps:
//!
//! 1. **Cut.** Where each face of one B-rep meets the other, as 3-D curves with their images in
//!    both faces' parameter rectangles (`cuts.rs`, on the surface | surface intersection).
//! 2. **Split.** Every face is split along its cuts into regions (`face_split.rs`), each a
//!    B-rep of one face; a face without cuts stays whole.
//! 3. **Keep and join.** A split keeps every piece of the first B-rep and joins the pieces
//!    that were neighbours across an original edge. A boolean classifies every piece of each
//!    B-rep by a point well inside it ([`Brep::contains_point`] on the other B-rep): inside,
//!    outside, or on the other's boundary, where the two faces' outward normals point the same
//!    way or opposite ways. It keeps
//!
//!    | operation | pieces of A | pieces of B |
//!    | --- | --- | --- |
//!    | union | outside B, or on it facing the same way | outside A |
//!    | intersection | inside B, or on it facing the same way | inside A |
//!    | difference A − B | outside B, or on it facing the other way | inside A, turned over |
//!
//!    and joins what it keeps along coincident edges ([`Brep::join`]).
//!
//! Faces that lie on each other are split only where the other B-rep's edges cross them (the
//! overlap's outline is not traced), so a boolean of solids whose faces partly overlap may not
//! close up; the result is then an open B-rep (see [`Brep::is_solid`]), which callers report.

pub(crate) mod cuts;
pub(crate) mod face_split;
pub(crate) mod regions;

use crate::boolean::cuts::{Cut, find_cuts};
use crate::boolean::face_split::{EdgeSplits, Piece, attach_ends, split_face};
use crate::brep::join::concatenate;
use crate::intersect::brep_inside::Located;
use crate::intersect::curve_curve::check_tolerance;
use crate::{Brep, Error, NurbsCurve, Result, Vector3};

/// Which solid boolean to take.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BooleanOperation {
    /// Everything inside either solid.
    Union,
    /// Everything inside both solids.
    Intersection,
    /// Everything inside the first solid and outside the second.
    Difference,
}

/// Where a piece of one B-rep lies with respect to the other.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    Inside,
    Outside,
    /// On the other's boundary, the outward normals the same way (`true`) or opposite.
    On(bool),
}

impl Brep {
    /// The solid boolean `self operation other` of two closed B-reps within `tolerance` (see
    /// the module documentation): the joined pieces, one B-rep per connected part (none when
    /// nothing is left, several when the result falls apart). A result that did not close up
    /// is returned open.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when either B-rep is not closed or a face could not be split;
    /// the errors of the intersection and of joining.
    ///
    /// # Examples
    /// ```
    /// use locus_kernel::{BooleanOperation, Brep, Interval, OrientedBox, Plane};
    /// let cube = |a: f64, b: f64| {
    ///     let i = Interval::new(a, b);
    ///     Brep::from_box(&OrientedBox::new(Plane::WORLD_XY, i, i, i)).unwrap()
    /// };
    /// let (a, b) = (cube(0.0, 2.0), cube(1.0, 3.0));
    /// let union = a.boolean(&b, BooleanOperation::Union, 1e-9).unwrap();
    /// assert_eq!(union.len(), 1);
    /// assert!(union[0].is_solid());
    /// assert!((union[0].volume().unwrap() - 15.0).abs() < 1e-9);
    /// let difference = a.boolean(&b, BooleanOperation::Difference, 1e-9).unwrap();
    /// assert!((difference[0].volume().unwrap() - 7.0).abs() < 1e-9);
    /// ```
    pub fn boolean(
        &self,
        other: &Brep,
        operation: BooleanOperation,
        tolerance: f64,
    ) -> Result<Vec<Brep>> {
        check_tolerance(tolerance)?;
        for (name, b) in [("first", self), ("second", other)] {
            if !b.is_solid() {
                return Err(Error::InvalidInput(format!(
                    "the {name} B-rep is not closed: a solid boolean needs closed B-reps"
                )));
            }
        }
        let cuts = find_cuts(self, other, tolerance)?;
        let pieces_a = split_all(self, &cuts.of_a, &cuts.curves, tolerance)?;
        let pieces_b = split_all(other, &cuts.of_b, &cuts.curves, tolerance)?;
        let mut kept: Vec<Brep> = Vec::new();
        for piece in pieces_a {
            let side = side_of(&piece, self, other, tolerance)?;
            let keep = match operation {
                BooleanOperation::Union => matches!(side, Side::Outside | Side::On(true)),
                BooleanOperation::Intersection => matches!(side, Side::Inside | Side::On(true)),
                BooleanOperation::Difference => matches!(side, Side::Outside | Side::On(false)),
            };
            if keep {
                kept.push(piece.brep);
            }
        }
        for piece in pieces_b {
            let side = side_of(&piece, other, self, tolerance)?;
            match operation {
                BooleanOperation::Union if side == Side::Outside => kept.push(piece.brep),
                BooleanOperation::Intersection if side == Side::Inside => kept.push(piece.brep),
                BooleanOperation::Difference if side == Side::Inside => {
                    let mut b = piece.brep;
                    for face in &mut b.faces {
                        face.reversed = !face.reversed;
                    }
                    kept.push(b);
                }
                _ => {}
            }
        }
        let joined = Brep::join(&kept, tolerance)?;
        if operation == BooleanOperation::Difference {
            return with_cavities(joined, tolerance);
        }
        Ok(joined)
    }

    /// The pieces of this B-rep split where `cutter` meets it, within `tolerance` (see the
    /// module documentation): faces split along the intersection, and the pieces that were
    /// neighbours across an edge joined again. A B-rep the cutter does not cut comes back
    /// whole, as the only piece.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] when a face could not be split; the errors of the intersection
    /// and of joining.
    pub fn split_by_brep(&self, cutter: &Brep, tolerance: f64) -> Result<Vec<Brep>> {
        check_tolerance(tolerance)?;
        let cuts = find_cuts(self, cutter, tolerance)?;
        let pieces = split_all(self, &cuts.of_a, &cuts.curves, tolerance)?;
        // Neighbours across an original edge (the same stretch of it) belong together.
        let n = pieces.len();
        let mut group: Vec<usize> = (0..n).collect();
        fn root(group: &mut [usize], mut i: usize) -> usize {
            while group[i] != i {
                group[i] = group[group[i]];
                i = group[i];
            }
            i
        }
        for i in 0..n {
            for j in i + 1..n {
                let shared = pieces[i]
                    .stretches
                    .iter()
                    .any(|s| pieces[j].stretches.contains(s));
                if shared {
                    let (a, b) = (root(&mut group, i), root(&mut group, j));
                    group[a.max(b)] = a.min(b);
                }
            }
        }
        let mut out = Vec::new();
        for g in 0..n {
            if root(&mut group, g) != g {
                continue;
            }
            let members: Vec<Brep> = (0..n)
                .filter(|&i| root(&mut group, i) == g)
                .map(|i| pieces[i].brep.clone())
                .collect();
            out.extend(Brep::join(&members, tolerance)?);
        }
        Ok(out)
    }
}

/// Every face of `brep` split along its cuts; a face without any stays whole.
fn split_all(
    brep: &Brep,
    cuts: &[Vec<Cut>],
    curves: &[NurbsCurve],
    tolerance: f64,
) -> Result<Vec<Piece>> {
    let mut splits = EdgeSplits::new();
    let ends = attach_ends(brep, cuts, curves, &mut splits, tolerance);
    let mut pieces = Vec::new();
    for f in 0..brep.faces().len() {
        pieces.extend(split_face(
            brep, f, &cuts[f], &ends[f], curves, &splits, tolerance,
        )?);
    }
    Ok(pieces)
}

/// The parts of a difference with every closed part that lies inside another made a cavity of
/// it: turned inwards and added to it as a second shell, as Rhino's B-reps hold hollows.
fn with_cavities(parts: Vec<Brep>, tolerance: f64) -> Result<Vec<Brep>> {
    let n = parts.len();
    let mut host: Vec<Option<usize>> = vec![None; n];
    for j in 0..n {
        let Some(p) = parts[j].vertices().first().map(|v| v.point) else {
            continue;
        };
        for i in 0..n {
            if i != j
                && parts[i].is_solid()
                && parts[j].is_solid()
                && parts[i].locate(p, tolerance)? == Located::Inside
            {
                host[j] = Some(i);
                break;
            }
        }
    }
    let mut out = Vec::new();
    for i in 0..n {
        if host[i].is_some() {
            continue;
        }
        let mut shells = vec![parts[i].clone()];
        for j in 0..n {
            if host[j] == Some(i) {
                let mut cavity = parts[j].clone();
                for face in &mut cavity.faces {
                    face.reversed = !face.reversed;
                }
                shells.push(cavity);
            }
        }
        if shells.len() == 1 {
            out.push(shells.pop().expect("one shell"));
        } else {
            out.push(concatenate(shells.iter()));
        }
    }
    Ok(out)
}

/// Where a piece of `own` lies with respect to `other`.
fn side_of(piece: &Piece, own: &Brep, other: &Brep, tolerance: f64) -> Result<Side> {
    let face = &own.faces()[piece.face];
    let (u, v) = piece.inner;
    let d = face.surface.derivatives_at(u, v, 1)?;
    Ok(match other.locate(d.point, tolerance)? {
        Located::Inside => Side::Inside,
        Located::Outside => Side::Outside,
        Located::On {
            face: g,
            u: ou,
            v: ov,
        } => {
            let theirs = &other.faces()[g];
            let e = theirs.surface.derivatives_at(ou, ov, 1)?;
            let outward = |n: Vector3, reversed: bool| if reversed { -n } else { n };
            let mine = outward(d.du.cross(d.dv), face.reversed);
            let their = outward(e.du.cross(e.dv), theirs.reversed);
            Side::On(mine.dot(their) > 0.0)
        }
    })
}
