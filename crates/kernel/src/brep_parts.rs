//! Assembling a B-rep from its parts, as a reader of stored B-reps (pickles, files) needs.

use crate::{Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex, Error, LoopKind, Result};

impl Brep {
    /// A B-rep from its faces, loops, trims, edges and vertices, with its topology checked.
    ///
    /// Every index must name an existing part; each loop must be listed by its face (the outer
    /// loop first, at most one) and each trim by its loop; the trims of a loop must chain
    /// (each ends at the vertex where the next starts); and a trim's vertices must be its
    /// edge's, in the trim's direction. The derived parts (the trims of each edge, the edges of
    /// each vertex and the kind of each trim) are recomputed, so the values given for them are
    /// ignored. The geometry (curves on their surfaces) is taken as given: it is what a B-rep
    /// written by this kernel holds.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the first part that breaks a rule.
    ///
    /// ```
    /// use locus_kernel::{Brep, Interval, OrientedBox, Plane};
    /// # fn main() -> locus_kernel::Result<()> {
    /// let b = Brep::from_box(&OrientedBox::new(
    ///     Plane::WORLD_XY, Interval::UNIT, Interval::UNIT, Interval::UNIT,
    /// ))?;
    /// let copy = Brep::from_parts(
    ///     b.faces().to_vec(), b.loops().to_vec(), b.trims().to_vec(),
    ///     b.edges().to_vec(), b.vertices().to_vec(),
    /// )?;
    /// assert_eq!(copy, b);
    /// # Ok(())
    /// # }
    /// ```
    pub fn from_parts(
        faces: Vec<BrepFace>,
        loops: Vec<BrepLoop>,
        trims: Vec<BrepTrim>,
        edges: Vec<BrepEdge>,
        vertices: Vec<BrepVertex>,
    ) -> Result<Self> {
        let bad = |message: String| Err(Error::InvalidInput(message));
        for (f, face) in faces.iter().enumerate() {
            if face.loops.is_empty() {
                return bad(format!("B-rep face {f} has no loop"));
            }
            for (k, &l) in face.loops.iter().enumerate() {
                let Some(lp) = loops.get(l) else {
                    return bad(format!(
                        "B-rep face {f} names loop {l}, which does not exist"
                    ));
                };
                if lp.face != f {
                    return bad(format!(
                        "B-rep loop {l} is listed by face {f} but names face {}",
                        lp.face
                    ));
                }
                let outer = lp.kind == LoopKind::Outer;
                if outer != (k == 0) {
                    return bad(format!("B-rep face {f} must list its one outer loop first"));
                }
            }
        }
        for (l, lp) in loops.iter().enumerate() {
            if faces.get(lp.face).is_none_or(|f| !f.loops.contains(&l)) {
                return bad(format!("B-rep loop {l} is not listed by face {}", lp.face));
            }
            if lp.trims.is_empty() {
                return bad(format!("B-rep loop {l} has no trim"));
            }
            for &t in &lp.trims {
                if trims.get(t).is_none_or(|trim| trim.loop_index != l) {
                    return bad(format!(
                        "B-rep loop {l} lists trim {t}, which is not one of its trims"
                    ));
                }
            }
            let n = lp.trims.len();
            for k in 0..n {
                let (a, b) = (&trims[lp.trims[k]], &trims[lp.trims[(k + 1) % n]]);
                if a.vertices[1] != b.vertices[0] {
                    return bad(format!(
                        "B-rep loop {l}: trim {} ends at vertex {} but trim {} starts at vertex {}",
                        lp.trims[k],
                        a.vertices[1],
                        lp.trims[(k + 1) % n],
                        b.vertices[0]
                    ));
                }
            }
        }
        for (t, trim) in trims.iter().enumerate() {
            if loops
                .get(trim.loop_index)
                .is_none_or(|l| !l.trims.contains(&t))
            {
                return bad(format!(
                    "B-rep trim {t} is not listed by loop {}",
                    trim.loop_index
                ));
            }
            if let Some(&v) = trim.vertices.iter().find(|&&v| v >= vertices.len()) {
                return bad(format!(
                    "B-rep trim {t} names vertex {v}, which does not exist"
                ));
            }
            if let Some(e) = trim.edge {
                let Some(edge) = edges.get(e) else {
                    return bad(format!(
                        "B-rep trim {t} names edge {e}, which does not exist"
                    ));
                };
                let ends = if trim.reversed {
                    [edge.vertices[1], edge.vertices[0]]
                } else {
                    edge.vertices
                };
                if ends != trim.vertices {
                    return bad(format!(
                        "B-rep trim {t} runs between other vertices than its edge {e}"
                    ));
                }
            }
        }
        for (e, edge) in edges.iter().enumerate() {
            if let Some(&v) = edge.vertices.iter().find(|&&v| v >= vertices.len()) {
                return bad(format!(
                    "B-rep edge {e} names vertex {v}, which does not exist"
                ));
            }
        }
        if let Some(v) = vertices.iter().position(|v| !v.point.is_finite()) {
            return bad(format!("B-rep vertex {v} is not finite"));
        }
        let mut brep = Self {
            faces,
            loops,
            trims,
            edges,
            vertices,
        };
        brep.link();
        Ok(brep)
    }
}

#[cfg(test)]
mod tests {
    use crate::{
        Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex, Interval, OrientedBox, Plane,
        Sphere,
    };

    /// The parts of a B-rep, as `Brep::from_parts` takes them.
    type Parts = (
        Vec<BrepFace>,
        Vec<BrepLoop>,
        Vec<BrepTrim>,
        Vec<BrepEdge>,
        Vec<BrepVertex>,
    );

    fn parts(b: &Brep) -> Parts {
        (
            b.faces().to_vec(),
            b.loops().to_vec(),
            b.trims().to_vec(),
            b.edges().to_vec(),
            b.vertices().to_vec(),
        )
    }

    #[test]
    fn rebuilds_what_the_constructors_make() {
        let boxed = Brep::from_box(&OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::new(0.0, 2.0),
            Interval::UNIT,
        ))
        .unwrap();
        let sphere = Brep::from_sphere(&Sphere::new(crate::Point3::ORIGIN, 2.0).unwrap()).unwrap();
        for b in [boxed, sphere] {
            let (f, l, t, e, v) = parts(&b);
            assert_eq!(Brep::from_parts(f, l, t, e, v).unwrap(), b);
        }
    }

    #[test]
    fn refuses_broken_topology() {
        let b = Brep::from_box(&OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::UNIT,
            Interval::UNIT,
        ))
        .unwrap();
        let (f, l, t, e, v) = parts(&b);
        let mut t2 = t.clone();
        t2[0].loop_index = 99;
        assert!(Brep::from_parts(f.clone(), l.clone(), t2, e.clone(), v.clone()).is_err());
        let mut e2 = e.clone();
        e2[0].vertices = [0, 100];
        assert!(Brep::from_parts(f.clone(), l.clone(), t.clone(), e2, v.clone()).is_err());
        let mut f2 = f.clone();
        f2[0].loops.clear();
        assert!(Brep::from_parts(f2, l.clone(), t.clone(), e.clone(), v.clone()).is_err());
        let mut t3 = t.clone();
        t3[0].vertices.swap(0, 1);
        assert!(Brep::from_parts(f.clone(), l.clone(), t3, e.clone(), v.clone()).is_err());
        assert!(Brep::from_parts(f, l, t, e, Vec::new()).is_err());
    }
}
