//! The view directions of pictures and plan drawings, and the projection onto them.

use std::str::FromStr;

use locus_kernel::{Point3, Vector3};

/// A direction to look at the model from, as Rhino's standard views.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum View {
    /// From above, looking down −Z (plan).
    Top,
    /// From the front, looking along +Y.
    Front,
    /// From the right, looking along −X.
    Right,
    /// From the south-east, above: Rhino's Perspective direction, drawn in parallel projection.
    #[default]
    Iso,
}

impl FromStr for View {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        match s.to_ascii_lowercase().as_str() {
            "top" | "plan" => Ok(View::Top),
            "front" => Ok(View::Front),
            "right" => Ok(View::Right),
            "iso" | "perspective" => Ok(View::Iso),
            _ => Err(format!("unknown view `{s}` (top, front, right, iso)")),
        }
    }
}

impl View {
    /// The view's screen axes and the direction it looks along, as unit vectors `(right, up,
    /// forward)`: a point's screen coordinates are its dot products with `right` and `up`, and
    /// its depth the dot product with `forward` (larger is farther).
    pub fn axes(self) -> (Vector3, Vector3, Vector3) {
        match self {
            View::Top => (Vector3::X, Vector3::Y, -Vector3::Z),
            View::Front => (Vector3::X, Vector3::Z, Vector3::Y),
            View::Right => (Vector3::Y, Vector3::Z, -Vector3::X),
            View::Iso => {
                let forward = Vector3::new(-1.0, 1.0, -1.0).normalize_or_zero();
                let right = Vector3::new(1.0, 1.0, 0.0).normalize_or_zero();
                let up = right.cross(forward);
                (right, up, forward)
            }
        }
    }

    /// A point's screen coordinates `(x, y)` (y up) and depth.
    pub fn project(self, p: Point3) -> (f64, f64, f64) {
        let (r, u, f) = self.axes();
        let v = p - Point3::ORIGIN;
        (v.dot(r), v.dot(u), v.dot(f))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axes_are_right_handed_and_orthonormal() {
        for view in [View::Top, View::Front, View::Right, View::Iso] {
            let (r, u, f) = view.axes();
            assert!((r.length() - 1.0).abs() < 1e-12 && (u.length() - 1.0).abs() < 1e-12);
            assert!(r.dot(u).abs() < 1e-12 && r.dot(f).abs() < 1e-12 && u.dot(f).abs() < 1e-12);
            // Looking along `forward`, right × up points back at the viewer.
            assert!((r.cross(u) + f).length() < 1e-12, "{view:?}");
        }
        assert_eq!(
            View::Top.project(Point3::new(1.0, 2.0, 3.0)),
            (1.0, 2.0, -3.0)
        );
        assert!("side".parse::<View>().is_err());
    }
}
