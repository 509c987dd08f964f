//! Choosing parameter values along a curve, or along one direction of a surface, so that the
//! polyline through them meets the meshing limits (angle, chord deviation, edge lengths).
//!
//! A direction is probed as a family of curves `C_k(t)` (one curve for a curve; for a surface,
//! the isocurves at a few values of the other parameter). Each polynomial span is first
//! measured at five points and divided uniformly into as many pieces as its turning angle,
//! chord deviation and length need; each piece is then checked at its midpoint and bisected
//! while it still breaks a limit (bounded depth), so that the result adapts to the curvature
//! within a span as well as between spans.

use crate::mesh::parameters::{MAX_MESH_SAMPLES_PER_DIRECTION, MeshingParameters};
use crate::{Error, Point3, Result, Vector3};

/// One probed point: its location and, where defined, the unit direction whose turning the
/// angle limit bounds (a surface normal, or a curve tangent).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Probe {
    pub point: Point3,
    pub direction: Option<Vector3>,
}

/// How many times a piece may be bisected after the first uniform division.
const MAX_BISECTIONS: usize = 6;

/// How far inside a piece (as a fraction of it) its end probes are taken, so that at a span
/// break the derivatives are those of the piece's own span, not of its neighbour across a kink.
const END_NUDGE: f64 = 1e-9;

/// Slack on the limits when checking a piece after the uniform division, so that rounding on
/// a piece that meets a limit exactly does not double the sample count.
const CHECK_SLACK: f64 = 1.05;

/// The angle between two unit directions (0 when either is missing).
fn angle(a: Option<Vector3>, b: Option<Vector3>) -> f64 {
    match (a, b) {
        (Some(a), Some(b)) => a.dot(b).clamp(-1.0, 1.0).acos(),
        _ => 0.0,
    }
}

/// The angle between two segments' directions (0 when either has no length).
fn turn(a: Vector3, b: Vector3) -> f64 {
    angle(a.try_normalize(), b.try_normalize())
}

/// The distance from `p` to the line through `a` and `b` (to `a` when they coincide).
fn distance_to_chord(p: Point3, a: Point3, b: Point3) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    if len2 == 0.0 {
        return p.distance(a);
    }
    let t = ((p - a).dot(ab) / len2).clamp(0.0, 1.0);
    p.distance(a + ab * t)
}

/// Samples of a family of curves: `eval(t, out)` fills `out` with one probe per curve.
pub(crate) struct Family<'a> {
    eval: &'a mut dyn FnMut(f64, &mut Vec<Probe>),
    buffers: [Vec<Probe>; 5],
}

impl<'a> Family<'a> {
    pub(crate) fn new(eval: &'a mut dyn FnMut(f64, &mut Vec<Probe>)) -> Self {
        Self {
            eval,
            buffers: Default::default(),
        }
    }

    fn probe(&mut self, slot: usize, t: f64) {
        let mut buffer = std::mem::take(&mut self.buffers[slot]);
        buffer.clear();
        (self.eval)(t, &mut buffer);
        self.buffers[slot] = buffer;
    }

    /// How many uniform pieces the span `[a, b]` needs, from five probes.
    fn pieces(&mut self, a: f64, b: f64, limits: &MeshingParameters) -> usize {
        let h = (b - a) * END_NUDGE;
        for i in 0..5 {
            let t = match i {
                0 => a + h,
                4 => b - h,
                _ => a + (b - a) * i as f64 / 4.0,
            };
            self.probe(i, t);
        }
        let mut needed = 1usize;
        let curves = self.buffers[0].len();
        for k in 0..curves {
            let p: [Probe; 5] = std::array::from_fn(|i| self.buffers[i][k]);
            let mut length = 0.0;
            let mut normal_turn = 0.0;
            let mut chord_turn = 0.0;
            for i in 0..4 {
                length += p[i].point.distance(p[i + 1].point);
                normal_turn += angle(p[i].direction, p[i + 1].direction);
                if i < 3 {
                    chord_turn +=
                        turn(p[i + 1].point - p[i].point, p[i + 2].point - p[i + 1].point);
                }
            }
            // Five points of an arc of total angle Θ turn by 3Θ/4 between their chords.
            let total_angle = normal_turn.max(chord_turn * 4.0 / 3.0);
            let deviation = (1..4)
                .map(|i| distance_to_chord(p[i].point, p[0].point, p[4].point))
                .fold(0.0, f64::max);
            let mut n = 1.0f64;
            if limits.max_angle > 0.0 {
                n = n.max((total_angle / limits.max_angle).ceil());
            }
            if limits.max_chord_deviation > 0.0 {
                n = n.max((deviation / limits.max_chord_deviation).sqrt().ceil());
            }
            if limits.max_edge_length > 0.0 {
                n = n.max((length / limits.max_edge_length).ceil());
            }
            if limits.min_edge_length > 0.0 {
                n = n.min((length / limits.min_edge_length).floor().max(1.0));
            }
            let n = if n.is_finite() {
                n.min(MAX_MESH_SAMPLES_PER_DIRECTION as f64) as usize
            } else {
                1
            };
            needed = needed.max(n);
        }
        needed
    }

    /// Whether the piece `[a, b]` still breaks a limit, from probes at its ends and middle.
    fn breaks_limits(&mut self, a: f64, b: f64, limits: &MeshingParameters) -> bool {
        let h = (b - a) * END_NUDGE;
        self.probe(0, a + h);
        self.probe(1, 0.5 * (a + b));
        self.probe(2, b - h);
        let curves = self.buffers[0].len();
        (0..curves).any(|k| {
            let (p, m, q) = (self.buffers[0][k], self.buffers[1][k], self.buffers[2][k]);
            let length = p.point.distance(m.point) + m.point.distance(q.point);
            if limits.min_edge_length > 0.0 && length < 2.0 * limits.min_edge_length {
                return false;
            }
            let turned = (angle(p.direction, m.direction) + angle(m.direction, q.direction))
                .max(2.0 * turn(m.point - p.point, q.point - m.point));
            (limits.max_angle > 0.0 && turned > limits.max_angle * CHECK_SLACK)
                || (limits.max_chord_deviation > 0.0
                    && distance_to_chord(m.point, p.point, q.point)
                        > limits.max_chord_deviation * CHECK_SLACK)
                || (limits.max_edge_length > 0.0
                    && p.point.distance(q.point) > limits.max_edge_length * CHECK_SLACK)
        })
    }

    /// Appends the parameters inside `(a, b]` for the piece `[a, b]`, bisecting while it
    /// breaks a limit.
    fn push_piece(
        &mut self,
        a: f64,
        b: f64,
        depth: usize,
        limits: &MeshingParameters,
        out: &mut Vec<f64>,
    ) -> Result<()> {
        if depth < MAX_BISECTIONS && self.breaks_limits(a, b, limits) {
            let m = 0.5 * (a + b);
            if m > a && m < b {
                self.push_piece(a, m, depth + 1, limits, out)?;
                return self.push_piece(m, b, depth + 1, limits, out);
            }
        }
        out.push(b);
        if out.len() > MAX_MESH_SAMPLES_PER_DIRECTION {
            return Err(too_many());
        }
        Ok(())
    }

    /// The parameters from the first break to the last, including every break.
    pub(crate) fn refine(
        &mut self,
        breaks: &[f64],
        limits: &MeshingParameters,
    ) -> Result<Vec<f64>> {
        let mut out = Vec::new();
        let Some(&first) = breaks.first() else {
            return Ok(out);
        };
        out.push(first);
        for w in breaks.windows(2) {
            let (a, b) = (w[0], w[1]);
            let n = self.pieces(a, b, limits);
            if out.len() + n > MAX_MESH_SAMPLES_PER_DIRECTION {
                return Err(too_many());
            }
            for i in 0..n {
                let s = a + (b - a) * i as f64 / n as f64;
                let e = if i + 1 == n {
                    b
                } else {
                    a + (b - a) * (i + 1) as f64 / n as f64
                };
                self.push_piece(s, e, 0, limits, &mut out)?;
            }
        }
        Ok(out)
    }
}

fn too_many() -> Error {
    Error::InvalidInput(format!(
        "meshing would need more than {MAX_MESH_SAMPLES_PER_DIRECTION} samples in one \
         direction; loosen the meshing parameters"
    ))
}

/// At most `limit` values picked evenly from `values` (first and last kept).
pub(crate) fn thin_out(values: &[f64], limit: usize) -> Vec<f64> {
    if values.len() <= limit || limit < 2 {
        return values.to_vec();
    }
    (0..limit)
        .map(|i| values[i * (values.len() - 1) / (limit - 1)])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn circle_params(limits: &MeshingParameters) -> Vec<f64> {
        let mut eval = |t: f64, out: &mut Vec<Probe>| {
            out.push(Probe {
                point: Point3::new(t.cos(), t.sin(), 0.0),
                direction: Some(Vector3::new(-t.sin(), t.cos(), 0.0)),
            });
        };
        Family::new(&mut eval)
            .refine(&[0.0, std::f64::consts::PI], limits)
            .unwrap()
    }

    #[test]
    fn a_half_circle_is_divided_by_the_angle() {
        let limits = MeshingParameters::default();
        let ts = circle_params(&limits);
        let steps = ts.len() - 1;
        let expected = (std::f64::consts::PI / limits.max_angle).ceil() as usize;
        assert_eq!(steps, expected);
        assert!(
            ts.windows(2)
                .all(|w| w[1] - w[0] <= limits.max_angle * CHECK_SLACK)
        );
    }

    #[test]
    fn a_half_circle_meets_a_chord_tolerance() {
        let limits = MeshingParameters::with_chord_deviation(1e-4);
        let ts = circle_params(&limits);
        for w in ts.windows(2) {
            // The sagitta of an arc of angle θ on the unit circle is 1 − cos(θ/2).
            assert!(1.0 - (0.5 * (w[1] - w[0])).cos() <= 1e-4 * CHECK_SLACK);
        }
    }

    #[test]
    fn hostile_limits_fail_with_a_reason() {
        let limits = MeshingParameters {
            max_edge_length: 1e-9,
            min_edge_length: 0.0,
            ..Default::default()
        };
        let mut eval = |t: f64, out: &mut Vec<Probe>| {
            out.push(Probe {
                point: Point3::new(t, 0.0, 0.0),
                direction: None,
            });
        };
        assert!(Family::new(&mut eval).refine(&[0.0, 1.0], &limits).is_err());
    }
}
