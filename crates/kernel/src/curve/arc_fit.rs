//! Recognizing arcs: whether a curve is a circular arc or a full circle within a tolerance
//! (Rhino's `Curve.TryGetArc` and `TryGetCircle`), so that constructions on it can be exact
//! (a pipe around an arc is a torus, a sweep along an arc a surface of revolution).

use crate::{Arc, Circle, Curve, Interval, Plane, Point3, Vector3};

/// Samples per span (per quarter turn of a circle) checked against the fitted circle.
const ARC_SAMPLES_PER_SPAN: usize = 8;

impl Curve {
    /// The arc (or full circle, an arc of 2π) the curve traces, if every sample of it lies
    /// within `tolerance` of one circle and the samples run around it in order: circles and
    /// arcs as they are, NURBS curves that are arcs in any parameterization (Rhino's rational
    /// quadratic form, or a fit). The arc runs in the curve's direction from its start point.
    /// `None` for lines, polylines and curves that are not arcs.
    pub fn try_arc(&self, tolerance: f64) -> Option<Arc> {
        match self {
            Curve::Arc { arc, .. } => return Some(*arc),
            Curve::Circle { circle, .. } => {
                return Arc::new(*circle, Interval::new(0.0, std::f64::consts::TAU)).ok();
            }
            Curve::Line { .. } | Curve::Polyline { .. } => return None,
            Curve::Nurbs(_) => {}
        }
        if tolerance.is_nan() || tolerance < 0.0 {
            return None;
        }
        let d = self.domain();
        let start = self.start_point();
        let closed = self.is_closed();
        let circle = if closed {
            Circle::from_three_points(
                start,
                self.point_at(d.parameter_at(1.0 / 3.0)),
                self.point_at(d.parameter_at(2.0 / 3.0)),
            )
            .ok()?
        } else {
            Circle::from_three_points(start, self.point_at(d.mid()), self.end_point()).ok()?
        };
        // Seen from the circle's normal the three points run counter-clockwise, as the curve.
        let x = (start - circle.center()).try_normalize()?;
        let plane = Plane {
            origin: circle.center(),
            x_axis: x,
            y_axis: circle.normal().cross(x),
            z_axis: circle.normal(),
        };
        let circle = Circle {
            plane,
            radius: circle.radius,
        };
        let sweep = if closed {
            std::f64::consts::TAU
        } else {
            angle_of(&plane, self.end_point())
        };
        let spans = match self {
            Curve::Nurbs(c) => c.span_count(),
            _ => 1,
        };
        let n = (spans * ARC_SAMPLES_PER_SPAN).max(ARC_SAMPLES_PER_SPAN * 4);
        let mut previous = 0.0;
        for k in 1..n {
            let p = self.point_at(d.parameter_at(k as f64 / n as f64));
            let off_plane = (p - plane.origin).dot(plane.z_axis).abs();
            let off_circle = (p.distance(plane.origin) - circle.radius).abs();
            if off_plane > tolerance || off_circle > tolerance {
                return None;
            }
            let a = angle_of(&plane, p);
            if a < previous || a > sweep {
                return None;
            }
            previous = a;
        }
        Arc::new(circle, Interval::new(0.0, sweep)).ok()
    }
}

/// The angle of `p` about the plane's normal from its x axis, in `[0, 2π)`.
fn angle_of(plane: &Plane, p: Point3) -> f64 {
    let v: Vector3 = p - plane.origin;
    let a = v.dot(plane.y_axis).atan2(v.dot(plane.x_axis));
    if a < 0.0 {
        a + std::f64::consts::TAU
    } else {
        a
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Line, NurbsCurve};
    use std::f64::consts::{FRAC_PI_2, TAU};

    #[test]
    fn nurbs_arcs_and_circles_are_recognized() {
        let plane =
            Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(1.0, -1.0, 2.0)).unwrap();
        let circle = Circle::new(plane, 2.5).unwrap();
        let arc = Arc::new(circle, Interval::new(0.3, 0.3 + 2.0)).unwrap();
        let found = Curve::from(arc.to_nurbs()).try_arc(1e-12).unwrap();
        assert!((found.radius() - 2.5).abs() < 1e-12);
        assert!((found.sweep() - 2.0).abs() < 1e-12);
        assert!(found.start_point().distance(arc.start_point()) < 1e-12);
        assert!(found.end_point().distance(arc.end_point()) < 1e-12);
        let full = Curve::from(circle.to_nurbs()).try_arc(1e-12).unwrap();
        assert!((full.sweep() - TAU).abs() < 1e-15);
        assert!((full.circle.normal() - plane.z_axis).length() < 1e-12);
    }

    #[test]
    fn other_curves_are_not_arcs() {
        let line = Curve::from(Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)));
        assert!(line.try_arc(1e-9).is_none());
        let wavy = Curve::from(
            NurbsCurve::create(
                &[
                    Point3::new(0.0, 0.0, 0.0),
                    Point3::new(1.0, 1.0, 0.0),
                    Point3::new(2.0, 0.0, 0.0),
                    Point3::new(3.0, 1.0, 0.0),
                ],
                3,
                false,
            )
            .unwrap(),
        );
        assert!(wavy.try_arc(1e-6).is_none());
        // A cubic close to a quarter circle is one only within a loose tolerance.
        let k = 0.552_284_749_831;
        let quarter = Curve::from(
            NurbsCurve::create(
                &[
                    Point3::new(1.0, 0.0, 0.0),
                    Point3::new(1.0, k, 0.0),
                    Point3::new(k, 1.0, 0.0),
                    Point3::new(0.0, 1.0, 0.0),
                ],
                3,
                false,
            )
            .unwrap(),
        );
        assert!(quarter.try_arc(1e-9).is_none());
        let loose = quarter.try_arc(1e-3).unwrap();
        assert!((loose.sweep() - FRAC_PI_2).abs() < 1e-9);
    }
}
