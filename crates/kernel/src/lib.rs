//! The geometry kernel of locus: points, vectors, planes, transforms, NURBS curves and surfaces,
//! and B-reps, following Rhino's conventions so that results can be compared with Rhino's.
//!
//! The kernel knows nothing of graphs, ports or file formats. It computes in `f64` on glam's
//! types and reports bad input as [`Error`] values, never as panics.
//!
//! # Conventions
//! - Right-handed, Z-up world coordinates; angles in radians.
//! - Matrices act on column vectors `[x, y, z, 1]`; `a * b` applies `b` first.
//! - Knot vectors are in Rhino form: `|knots| = |control points| + degree − 1`.
//! - Control points are Euclidean with a separate weight; the homogeneous point is `(w·p, w)`.
//! - Tolerances are named constants in [`tolerance`].
//!
//! # Examples
//! ```
//! use locus_kernel::{Point3, Vector3};
//! let p = Point3::new(2.0, 3.0, 1.0) + Vector3::new(2.0, 2.0, 2.0);
//! assert_eq!(p, Point3::new(4.0, 5.0, 3.0));
//! assert_eq!(Vector3::new(4.0, 3.0, 0.0).length(), 5.0);
//! ```

pub mod basis;
mod bounding_box;
mod error;
mod interval;
mod oriented_box;
mod plane;
mod point;
pub mod tolerance;
mod transform;
mod vector;

pub use crate::bounding_box::BoundingBox;
pub use crate::error::{Error, Result};
pub use crate::interval::Interval;
pub use crate::oriented_box::OrientedBox;
pub use crate::plane::{Plane, perpendicular_to};
pub use crate::point::Point3;
pub use crate::transform::Transform;
pub use crate::vector::{Parallelism, Vector3};
