//! The regions of a split face: walking the arrangement of its trims and cuts in the
//! parameter rectangle (see `face_split.rs` for the rules), and the pieces they become.

use std::f64::consts::TAU;

use crate::boolean::face_split::Piece;
use crate::brep::builders::{Builder, point_in_polygon, signed_area};
use crate::brep::{Brep, LoopKind};
use crate::{Error, NurbsCurve, Point3, Result, Vector3};

/// Samples per directed piece when its loop is measured as a polygon.
const LOOP_SAMPLES: usize = 16;

/// A vertex of the arrangement: its parameters and its point.
#[derive(Clone, Copy, Debug)]
pub(super) struct Vertex {
    pub(super) uv: (f64, f64),
    pub(super) point: Point3,
}

/// A piece of the arrangement: a stretch of a trim or a cut.
#[derive(Clone, Debug)]
pub(super) struct Fragment {
    pub(super) uv: NurbsCurve,
    /// The 3-D curve, running the same way; `None` along a singular trim.
    pub(super) xyz: Option<NurbsCurve>,
    pub(super) from: usize,
    pub(super) to: usize,
    /// The stretch of an original edge this runs along (trims only).
    pub(super) stretch: Option<(usize, usize)>,
    pub(super) cut: bool,
}

/// A fragment walked forwards or backwards.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Half {
    fragment: usize,
    forward: bool,
}

impl Half {
    fn origin(self, fragments: &[Fragment]) -> usize {
        let g = &fragments[self.fragment];
        if self.forward { g.from } else { g.to }
    }

    fn target(self, fragments: &[Fragment]) -> usize {
        let g = &fragments[self.fragment];
        if self.forward { g.to } else { g.from }
    }

    /// The direction in which the half leaves its origin.
    fn departure(self, fragments: &[Fragment]) -> Vector3 {
        let c = &fragments[self.fragment].uv;
        if self.forward {
            end_direction(c, true)
        } else {
            -end_direction(c, false)
        }
    }

    /// The direction back along the half from its target.
    fn back(self, fragments: &[Fragment]) -> Vector3 {
        let c = &fragments[self.fragment].uv;
        if self.forward {
            -end_direction(c, false)
        } else {
            end_direction(c, true)
        }
    }

    /// The parameter-rectangle points along the half, from its origin, its target left out.
    fn samples(self, fragments: &[Fragment]) -> Vec<(f64, f64)> {
        let c = &fragments[self.fragment].uv;
        let d = c.domain();
        (0..LOOP_SAMPLES)
            .map(|k| {
                let s = k as f64 / LOOP_SAMPLES as f64;
                let s = if self.forward { s } else { 1.0 - s };
                let p = c.point_at(d.parameter_at(s));
                (p.x, p.y)
            })
            .collect()
    }
}

/// The unit direction of a curve along itself at its start (`start`) or end: the chord to a
/// point a little way along it.
fn end_direction(c: &NurbsCurve, start: bool) -> Vector3 {
    // The chord to the nearest sample that is clearly away from the end: a derivative would
    // follow a hook of rounding size left where a fitted end was moved onto its vertex.
    let d = c.domain();
    let end = if start { d.t0 } else { d.t1 };
    let p = c.point_at(end);
    let size = c.points().iter().map(|q| q.distance(p)).fold(0.0, f64::max);
    let mut fraction = 1.0 / 1024.0;
    let mut best = Vector3::new(0.0, 0.0, 0.0);
    for _ in 0..10 {
        let s = if start { fraction } else { 1.0 - fraction };
        let q = c.point_at(d.parameter_at(s));
        let chord = if start { q - p } else { p - q };
        let chord = Vector3::new(chord.x, chord.y, 0.0);
        if chord.length() > 1e-9 * size {
            best = chord;
            if chord.length() > 1e-6 * size {
                break;
            }
        }
        fraction *= 2.0;
    }
    best.normalize_or_zero()
}

/// The angle turned clockwise from `from` to `to`, in `[0, 2π)`.
fn clockwise_angle(from: Vector3, to: Vector3) -> f64 {
    let a = from.y.atan2(from.x) - to.y.atan2(to.x);
    a.rem_euclid(TAU)
}

/// The regions the fragments bound, as pieces.
pub(super) fn regions(
    brep: &Brep,
    f: usize,
    vertices: &[Vertex],
    fragments: &[Fragment],
    tolerance: f64,
) -> Result<Vec<Piece>> {
    let mut halves: Vec<Half> = Vec::new();
    for (i, g) in fragments.iter().enumerate() {
        halves.push(Half {
            fragment: i,
            forward: true,
        });
        if g.cut {
            halves.push(Half {
                fragment: i,
                forward: false,
            });
        }
    }
    let mut leaving: Vec<Vec<usize>> = vec![Vec::new(); vertices.len()];
    for (k, h) in halves.iter().enumerate() {
        leaving[h.origin(fragments)].push(k);
    }
    let departures: Vec<Vector3> = halves.iter().map(|h| h.departure(fragments)).collect();
    let next = |k: usize| -> Option<usize> {
        let h = halves[k];
        let back = h.back(fragments);
        leaving[h.target(fragments)]
            .iter()
            .copied()
            .map(|j| {
                let twin = halves[j].fragment == h.fragment && halves[j].forward != h.forward;
                let angle = clockwise_angle(back, departures[j]);
                let angle = if twin || angle <= 0.0 { TAU } else { angle };
                (angle, j)
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|a| a.1)
    };
    let mut used = vec![false; halves.len()];
    // Each loop: its halves, its polygon and its signed area.
    type Loop = (Vec<usize>, Vec<(f64, f64)>, f64);
    let mut loops: Vec<Loop> = Vec::new();
    for start in 0..halves.len() {
        if used[start] {
            continue;
        }
        let mut cycle = Vec::new();
        let mut k = start;
        loop {
            if used[k] || cycle.len() > halves.len() {
                return Err(Error::InvalidInput(format!(
                    "face {f}: its trims and cuts do not close into loops"
                )));
            }
            used[k] = true;
            cycle.push(k);
            k = next(k).ok_or_else(|| {
                Error::InvalidInput(format!("face {f}: a cut or trim ends nowhere"))
            })?;
            if k == start {
                break;
            }
        }
        let polygon: Vec<(f64, f64)> = cycle
            .iter()
            .flat_map(|&k| halves[k].samples(fragments))
            .collect();
        let area = signed_area(&polygon);
        loops.push((cycle, polygon, area));
    }
    let face_area: f64 = loops.iter().map(|l| l.2.abs()).fold(0.0, f64::max);
    let outer: Vec<usize> = (0..loops.len())
        .filter(|&i| loops[i].2 > 1e-12 * face_area)
        .collect();
    let mut holes_of: Vec<Vec<usize>> = vec![Vec::new(); outer.len()];
    for (i, l) in loops.iter().enumerate() {
        if l.2 >= -1e-12 * face_area {
            continue;
        }
        // The region a hole belongs to is not one on the other side of its own fragments.
        let probe = probe_point(&l.0, &halves, fragments);
        let own: Vec<usize> = l.0.iter().map(|&k| halves[k].fragment).collect();
        let host = outer
            .iter()
            .enumerate()
            .filter(|(_, o)| {
                !loops[**o]
                    .0
                    .iter()
                    .any(|&k| own.contains(&halves[k].fragment))
                    && point_in_polygon(probe, &loops[**o].1)
            })
            .min_by(|a, b| loops[*a.1].2.total_cmp(&loops[*b.1].2));
        if let Some((k, _)) = host {
            holes_of[k].push(i);
        }
    }
    let face = &brep.faces()[f];
    let mut pieces = Vec::with_capacity(outer.len());
    for (k, &o) in outer.iter().enumerate() {
        let mut b = Builder::default();
        let fi = b.face(face.surface.clone(), face.reversed);
        let mut ids: Vec<(Point3, usize)> = Vec::new();
        let mut vertex = |b: &mut Builder, p: Point3| -> usize {
            if let Some(&(_, id)) = ids.iter().find(|(q, _)| q.distance(p) <= 10.0 * tolerance) {
                return id;
            }
            let id = b.vertex(p);
            ids.push((p, id));
            id
        };
        let mut stretches = Vec::new();
        let mut polygons = Vec::new();
        for (kind, l) in std::iter::once((LoopKind::Outer, o))
            .chain(holes_of[k].iter().map(|&h| (LoopKind::Inner, h)))
        {
            let li = b.start_loop(fi, kind);
            polygons.push(loops[l].1.clone());
            for &hk in &loops[l].0 {
                let h = halves[hk];
                let g = &fragments[h.fragment];
                let (uv, xyz) = if h.forward {
                    (g.uv.clone(), g.xyz.clone())
                } else {
                    (g.uv.reversed(), g.xyz.as_ref().map(NurbsCurve::reversed))
                };
                let v0 = vertex(&mut b, vertices[h.origin(fragments)].point);
                let v1 = vertex(&mut b, vertices[h.target(fragments)].point);
                let edge = xyz.map(|c| b.edge(c, [v0, v1]));
                let v1 = if edge.is_none() { v0 } else { v1 };
                b.trim(li, uv, edge, false, [v0, v1]);
                stretches.extend(g.stretch);
            }
        }
        pieces.push(Piece {
            face: f,
            brep: b.finish(),
            stretches,
            inner: inner_point(&polygons),
        });
    }
    Ok(pieces)
}

/// A point inside a loop, near the middle of its first half.
fn probe_point(cycle: &[usize], halves: &[Half], fragments: &[Fragment]) -> (f64, f64) {
    let h = halves[cycle[0]];
    let c = &fragments[h.fragment].uv;
    let p = c.point_at(c.domain().mid());
    (p.x, p.y)
}

/// A point of the region the polygons bound (the first the outer boundary, the rest holes)
/// far from its border: the best of a grid over its box by distance to the border.
pub(crate) fn inner_point(polygons: &[Vec<(f64, f64)>]) -> (f64, f64) {
    let outer = &polygons[0];
    let (mut lo, mut hi) = (
        (f64::INFINITY, f64::INFINITY),
        (f64::NEG_INFINITY, f64::NEG_INFINITY),
    );
    for p in outer {
        lo = (lo.0.min(p.0), lo.1.min(p.1));
        hi = (hi.0.max(p.0), hi.1.max(p.1));
    }
    let inside =
        |p: (f64, f64)| polygons.iter().filter(|q| point_in_polygon(p, q)).count() % 2 == 1;
    let clearance = |p: (f64, f64)| {
        let (sx, sy) = ((hi.0 - lo.0).max(1e-300), (hi.1 - lo.1).max(1e-300));
        polygons
            .iter()
            .flat_map(|q| {
                let n = q.len();
                (0..n).map(move |i| (q[i], q[(i + 1) % n]))
            })
            .map(|(a, b)| {
                let (ax, ay, bx, by) = (
                    (a.0 - p.0) / sx,
                    (a.1 - p.1) / sy,
                    (b.0 - p.0) / sx,
                    (b.1 - p.1) / sy,
                );
                let (dx, dy) = (bx - ax, by - ay);
                let l = dx * dx + dy * dy;
                let t = if l > 0.0 {
                    (-(ax * dx + ay * dy) / l).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                (ax + dx * t).hypot(ay + dy * t)
            })
            .fold(f64::INFINITY, f64::min)
    };
    const GRID: usize = 24;
    let mut best = (f64::NEG_INFINITY, outer[0]);
    for i in 0..GRID {
        for j in 0..GRID {
            let p = (
                lo.0 + (hi.0 - lo.0) * (i as f64 + 0.5) / GRID as f64,
                lo.1 + (hi.1 - lo.1) * (j as f64 + 0.5) / GRID as f64,
            );
            if inside(p) {
                let c = clearance(p);
                if c > best.0 {
                    best = (c, p);
                }
            }
        }
    }
    best.1
}
