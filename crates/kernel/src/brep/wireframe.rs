//! The wireframe of a B-rep (Rhino's `Brep.GetWireframe`, Grasshopper's Brep Wireframe): its
//! edges and isocurves of its faces, by a wire density as Rhino's objects have one
//! (`ObjectAttributes.WireDensity`):
//! - `-1`: the edges only;
//! - `0`: the edges and the isocurves at the faces' interior knots;
//! - `1`: as 0, and one isocurve at the middle of a direction that has no interior knot;
//! - `N ≥ 2`: as 0, and `N + 1` isocurves evenly spaced inside every span (a reading of
//!   Rhino's "N + 1 interior wires"; Rhino's exact placement is not published).
//!
//! On a trimmed face an isocurve is cut to the parts inside the face: where the iso line
//! crosses the trims in the parameter rectangle is found on each trim span by bisection (from
//! sign changes at [`CROSSING_SAMPLES`] samples), and the crossings pair off along the line.

use crate::brep::Brep;
use crate::{Error, Interval, NurbsCurve, Result, SurfaceDirection};

/// The highest wire density (Rhino's limit).
pub const MAX_WIRE_DENSITY: i32 = 99;

/// Samples per trim span searched for crossings with an iso line.
pub const CROSSING_SAMPLES: usize = 16;

impl Brep {
    /// The edges (each once) and the faces' isocurves at `density` (see the module
    /// documentation), edges first, then face by face the isocurves of constant `u` and of
    /// constant `v`.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] for a density outside `−1..=99`; the errors of extracting and
    /// trimming isocurves.
    pub fn wireframe(&self, density: i32) -> Result<Vec<NurbsCurve>> {
        if !(-1..=MAX_WIRE_DENSITY).contains(&density) {
            return Err(Error::InvalidInput(format!(
                "the wire density must be from -1 to {MAX_WIRE_DENSITY}, got {density}"
            )));
        }
        let mut out: Vec<NurbsCurve> = self.edges.iter().map(|e| e.curve.clone()).collect();
        if density < 0 {
            return Ok(out);
        }
        for f in 0..self.faces.len() {
            let surface = &self.faces[f].surface;
            let trimmed = !self.is_untrimmed(f);
            for direction in [SurfaceDirection::U, SurfaceDirection::V] {
                let domain = surface.domain(direction);
                for c in wire_parameters(&surface.span_breaks(direction), domain, density) {
                    // Constant u gives the isocurve running along v, and the other way round.
                    let along = direction.other();
                    let iso = surface.isocurve(along, c)?;
                    if !trimmed {
                        out.push(iso);
                        continue;
                    }
                    for piece in self.inside_intervals(f, direction, c) {
                        if piece.length() > 0.0 {
                            out.push(iso.trim(piece)?);
                        }
                    }
                }
            }
        }
        Ok(out)
    }

    /// The intervals of the iso line `direction = c` (in the other parameter) inside face `f`.
    fn inside_intervals(&self, f: usize, direction: SurfaceDirection, c: f64) -> Vec<Interval> {
        let (fixed, free) = match direction {
            SurfaceDirection::U => (0usize, 1usize),
            SurfaceDirection::V => (1, 0),
        };
        let coordinate = |p: crate::Point3, k: usize| if k == 0 { p.x } else { p.y };
        let mut crossings: Vec<f64> = Vec::new();
        for &l in &self.faces[f].loops {
            for &t in &self.loops[l].trims {
                let curve = &self.trims[t].curve;
                for w in curve.span_breaks().windows(2) {
                    let value = |s: f64| coordinate(curve.point_at(s), fixed) - c;
                    let mut a = w[0];
                    let mut fa = value(a);
                    for k in 1..=CROSSING_SAMPLES {
                        let b = w[0] + (w[1] - w[0]) * k as f64 / CROSSING_SAMPLES as f64;
                        let fb = value(b);
                        // A crossing in [a, b): the sign changes, or the line starts at a.
                        if fa == 0.0 || (fa < 0.0) != (fb < 0.0) && fb != 0.0 {
                            let s = if fa == 0.0 {
                                a
                            } else {
                                bisect(&value, a, b, fa)
                            };
                            crossings.push(coordinate(curve.point_at(s), free));
                        }
                        (a, fa) = (b, fb);
                    }
                }
            }
        }
        crossings.sort_by(f64::total_cmp);
        crossings.dedup_by(|b, a| (*b - *a).abs() <= 1e-12 * (1.0 + a.abs()));
        if !crossings.len().is_multiple_of(2) {
            return Vec::new();
        }
        crossings
            .chunks(2)
            .map(|p| Interval::new(p[0], p[1]))
            .collect()
    }
}

/// The root of `value` in `[a, b]` where it changes sign (`fa = value(a)`), by bisection to
/// the last bit.
fn bisect(value: &impl Fn(f64) -> f64, mut a: f64, mut b: f64, mut fa: f64) -> f64 {
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m <= a || m >= b {
            break;
        }
        let fm = value(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            (a, fa) = (m, fm);
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// The parameters of the isocurves in one direction: the interior knots, and by `density` a
/// middle wire or `density + 1` wires inside each span.
fn wire_parameters(breaks: &[f64], domain: Interval, density: i32) -> Vec<f64> {
    let interior: Vec<f64> = breaks
        .iter()
        .copied()
        .filter(|&k| k > domain.t0 && k < domain.t1)
        .collect();
    let mut out = interior.clone();
    match density {
        1 if interior.is_empty() => out.push(domain.mid()),
        d if d >= 2 => {
            let n = d as usize + 1;
            for w in breaks.windows(2) {
                for i in 1..=n {
                    out.push(w[0] + (w[1] - w[0]) * i as f64 / (n + 1) as f64);
                }
            }
        }
        _ => {}
    }
    out.sort_by(f64::total_cmp);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Circle, Interval, OrientedBox, Plane, Point3, Sphere};

    #[test]
    fn a_box_is_its_edges() {
        let b = Brep::from_box(&OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::UNIT,
            Interval::UNIT,
        ))
        .unwrap();
        assert_eq!(b.wireframe(-1).unwrap().len(), 12);
        assert_eq!(b.wireframe(0).unwrap().len(), 12);
        // One middle wire each way on each of the six faces.
        assert_eq!(b.wireframe(1).unwrap().len(), 12 + 12);
        // Density 2: three wires inside the one span each way.
        assert_eq!(b.wireframe(2).unwrap().len(), 12 + 36);
        assert!(b.wireframe(100).is_err());
    }

    #[test]
    fn a_sphere_has_its_knot_wires() {
        let b = Brep::from_sphere(&Sphere::new(Point3::ORIGIN, 2.0).unwrap()).unwrap();
        // The seam; 3 meridians at the inner knots of u (4 spans), the equator in v (2 spans).
        let w = b.wireframe(0).unwrap();
        assert_eq!(w.len(), 1 + 3 + 1);
        assert!((w[4].length() - 4.0 * std::f64::consts::PI).abs() < 1e-9);
    }

    #[test]
    fn isocurves_of_a_disc_are_clipped() {
        // A disc of radius 1 on a square plane: the middle wires are diameters of length 2.
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap().to_nurbs();
        let disc = Brep::from_planar_loops(&[vec![circle]], 1e-9).unwrap();
        let w = disc.wireframe(1).unwrap();
        assert_eq!(w.len(), 1 + 2);
        for iso in &w[1..] {
            assert!((iso.length() - 2.0).abs() < 1e-9, "{}", iso.length());
        }
        // An annulus: each middle line crosses the hole, two pieces of length 1 each.
        let outer = Circle::new(Plane::WORLD_XY, 2.0).unwrap().to_nurbs();
        let inner = Circle::new(Plane::WORLD_XY, 1.0).unwrap().to_nurbs();
        let ring = Brep::from_planar_loops(&[vec![outer], vec![inner]], 1e-9).unwrap();
        let w = ring.wireframe(1).unwrap();
        assert_eq!(w.len(), 2 + 4);
        for iso in &w[2..] {
            assert!((iso.length() - 1.0).abs() < 1e-9);
        }
    }
}
