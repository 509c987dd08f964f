//! Assembling a B-rep from parts read elsewhere (a file), with every index checked.

use crate::brep::{Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex, LoopKind};
use crate::{Error, Result};

impl Brep {
    /// A B-rep from its parts, as a reader of a file has them. The back references (the
    /// trims of each edge, the edges at each vertex) and the trim kinds are recomputed from
    /// the forward ones, so the values given for them are ignored.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the part when an index is out of range, a face's loops
    /// or a loop's trims do not refer back to it, a face does not start with exactly one outer
    /// loop, a trim's vertices are not its edge's (in the trim's direction), or a loop's trims
    /// do not chain (each trim ending at the vertex where the next starts).
    pub fn from_parts(
        vertices: Vec<BrepVertex>,
        edges: Vec<BrepEdge>,
        trims: Vec<BrepTrim>,
        loops: Vec<BrepLoop>,
        faces: Vec<BrepFace>,
    ) -> Result<Self> {
        let bad = |m: String| Err(Error::InvalidInput(m));
        for (i, e) in edges.iter().enumerate() {
            if e.vertices.iter().any(|&v| v >= vertices.len()) {
                return bad(format!("edge {i} refers to a vertex past the last"));
            }
        }
        for (i, t) in trims.iter().enumerate() {
            if t.loop_index >= loops.len() {
                return bad(format!(
                    "trim {i} refers to loop {} past the last",
                    t.loop_index
                ));
            }
            if t.vertices.iter().any(|&v| v >= vertices.len()) {
                return bad(format!("trim {i} refers to a vertex past the last"));
            }
            if let Some(e) = t.edge {
                let Some(edge) = edges.get(e) else {
                    return bad(format!("trim {i} refers to edge {e} past the last"));
                };
                let ends = if t.reversed {
                    [edge.vertices[1], edge.vertices[0]]
                } else {
                    edge.vertices
                };
                if ends != t.vertices {
                    return bad(format!(
                        "trim {i} runs from vertex {} to {}, but its edge {e} from {} to {}{}",
                        t.vertices[0],
                        t.vertices[1],
                        edge.vertices[0],
                        edge.vertices[1],
                        if t.reversed { " (reversed)" } else { "" }
                    ));
                }
            } else if t.vertices[0] != t.vertices[1] {
                return bad(format!("singular trim {i} has two different vertices"));
            }
        }
        for (i, l) in loops.iter().enumerate() {
            if l.face >= faces.len() {
                return bad(format!("loop {i} refers to face {} past the last", l.face));
            }
            if !faces[l.face].loops.contains(&i) {
                return bad(format!(
                    "loop {i} is not among the loops of its face {}",
                    l.face
                ));
            }
            if l.trims.is_empty() {
                return bad(format!("loop {i} has no trims"));
            }
            for (k, &t) in l.trims.iter().enumerate() {
                let Some(trim) = trims.get(t) else {
                    return bad(format!("loop {i} refers to trim {t} past the last"));
                };
                if trim.loop_index != i {
                    return bad(format!(
                        "trim {t} of loop {i} says it belongs to loop {}",
                        trim.loop_index
                    ));
                }
                let next_index = l.trims[(k + 1) % l.trims.len()];
                let Some(next) = trims.get(next_index) else {
                    return bad(format!(
                        "loop {i} refers to trim {next_index} past the last"
                    ));
                };
                if trim.vertices[1] != next.vertices[0] {
                    return bad(format!(
                        "loop {i} is not closed: trim {t} ends at vertex {}, the next trim starts at {}",
                        trim.vertices[1], next.vertices[0]
                    ));
                }
            }
        }
        for (i, f) in faces.iter().enumerate() {
            if f.loops
                .iter()
                .any(|&l| l >= loops.len() || loops[l].face != i)
            {
                return bad(format!("face {i} refers to a loop that is not its own"));
            }
            let outer = f
                .loops
                .iter()
                .filter(|&&l| loops[l].kind == LoopKind::Outer)
                .count();
            if outer != 1
                || f.loops
                    .first()
                    .is_none_or(|&l| loops[l].kind != LoopKind::Outer)
            {
                return bad(format!(
                    "face {i} must have exactly one outer loop, listed first"
                ));
            }
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
    use crate::{Brep, Interval, OrientedBox, Plane};

    #[test]
    fn a_box_reassembles_from_its_parts_and_broken_parts_are_refused() {
        let b = Brep::from_box(&OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        ))
        .unwrap();
        let parts = || {
            (
                b.vertices().to_vec(),
                b.edges().to_vec(),
                b.trims().to_vec(),
                b.loops().to_vec(),
                b.faces().to_vec(),
            )
        };
        let (v, e, t, l, f) = parts();
        assert_eq!(Brep::from_parts(v, e, t, l, f).unwrap(), b);
        let (v, e, mut t, l, f) = parts();
        t[3].edge = Some(99);
        assert!(Brep::from_parts(v, e, t, l, f).is_err());
        let (v, e, t, mut l, f) = parts();
        l[0].trims.swap(0, 1);
        assert!(Brep::from_parts(v, e, t, l, f).is_err());
        let (v, mut e, t, l, f) = parts();
        e[0].vertices = [0, 0];
        assert!(Brep::from_parts(v, e, t, l, f).is_err());
    }
}
