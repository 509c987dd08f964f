//! The closest point on the surface of an oriented box: how Grasshopper's *Pull Point* pulls a
//! point onto a box, whose six faces are its geometry (a point inside the box still moves to a
//! face, unlike [`OrientedBox::closest_point`], which returns it unchanged).

use crate::{OrientedBox, Point3};

impl OrientedBox {
    /// The point on the six faces of the box closest to `p`.
    ///
    /// Outside the box this is [`closest_point`](Self::closest_point). Inside (or on the
    /// surface), `p` moves along one of the box's axes to the nearest face; where two faces
    /// are equally near, the x axis wins over y and y over z, and the face at the lower end of
    /// an interval over the one at the upper end. A NaN or infinite `p` gives a non-finite
    /// point.
    pub fn closest_point_on_boundary(&self, p: Point3) -> Point3 {
        let local = self.plane.local_coordinates(p);
        let intervals = [self.x, self.y, self.z];
        let mut clamped = [0.0; 3];
        for k in 0..3 {
            clamped[k] = intervals[k].clamp(local[k]);
        }
        let inside = (0..3).all(|k| clamped[k] == local[k]);
        if inside {
            // The nearest face: the smallest distance from a coordinate to an end of its
            // interval.
            let mut best = (f64::INFINITY, 0, local[0]);
            for k in 0..3 {
                let (lo, hi) = (intervals[k].min(), intervals[k].max());
                for end in [lo, hi] {
                    let d = (local[k] - end).abs();
                    if d < best.0 {
                        best = (d, k, end);
                    }
                }
            }
            clamped[best.1] = best.2;
        }
        self.point_at(clamped[0], clamped[1], clamped[2])
    }
}

#[cfg(test)]
mod tests {
    use crate::{Interval, Plane, Point3, Vector3};

    use super::*;

    fn unit_box_on(plane: Plane) -> OrientedBox {
        OrientedBox::new(
            plane,
            Interval::new(0.0, 4.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 1.0),
        )
    }

    #[test]
    fn outside_points_go_to_the_closest_point() {
        let b = unit_box_on(Plane::WORLD_XY);
        for p in [
            Point3::new(5.0, 1.0, 0.5),
            Point3::new(-1.0, -1.0, -1.0),
            Point3::new(2.0, 3.0, 2.0),
        ] {
            assert_eq!(b.closest_point_on_boundary(p), b.closest_point(p));
        }
        assert_eq!(
            b.closest_point_on_boundary(Point3::new(5.0, 1.0, 0.5)),
            Point3::new(4.0, 1.0, 0.5)
        );
    }

    #[test]
    fn inside_points_go_to_the_nearest_face() {
        let b = unit_box_on(Plane::WORLD_XY);
        // Nearest face is z = 1 (0.2 away).
        assert_eq!(
            b.closest_point_on_boundary(Point3::new(2.0, 1.0, 0.8)),
            Point3::new(2.0, 1.0, 1.0)
        );
        // Nearest face is x = 0 (0.1 away).
        assert_eq!(
            b.closest_point_on_boundary(Point3::new(0.1, 1.0, 0.5)),
            Point3::new(0.0, 1.0, 0.5)
        );
        // A point on a face stays there.
        let on_face = Point3::new(4.0, 1.0, 0.5);
        assert_eq!(b.closest_point_on_boundary(on_face), on_face);
        // Ties: x before z, lower end first (the point is 0.5 from x = 0, z = 0 and z = 1).
        assert_eq!(
            b.closest_point_on_boundary(Point3::new(0.5, 1.0, 0.5)),
            Point3::new(0.0, 1.0, 0.5)
        );
    }

    #[test]
    fn follows_the_box_plane() {
        let plane =
            Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(1.0, -1.0, 2.0)).unwrap();
        let b = unit_box_on(plane);
        let inside = plane.point_at(2.0, 1.0, 0.9);
        let pulled = b.closest_point_on_boundary(inside);
        assert!(pulled.abs_diff_eq(plane.point_at(2.0, 1.0, 1.0), 1e-14));
        assert!((pulled.distance(inside) - 0.1).abs() < 1e-14);
    }

    #[test]
    fn non_finite_input_gives_a_non_finite_point() {
        let b = unit_box_on(Plane::WORLD_XY);
        assert!(
            !b.closest_point_on_boundary(Point3::new(f64::NAN, 0.0, 0.0))
                .is_finite()
        );
    }
}
