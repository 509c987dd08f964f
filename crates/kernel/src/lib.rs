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

mod arc;
mod arc_length;
pub mod basis;
mod bezier;
mod bounding_box;
mod brep;
mod brep_builders;
mod brep_join;
mod brep_mass;
mod brep_parts;
mod circle;
mod continuity;
mod curve;
mod curve_closest_point;
mod curve_kinks;
mod curve_measure;
mod curve_split;
mod error;
mod hermite;
mod interpolate;
mod interpolate_periodic;
mod interval;
mod line;
mod mesh;
mod nurbs_curve;
mod nurbs_curve_batch;
mod nurbs_curve_create;
mod nurbs_curve_edit;
mod nurbs_surface;
mod nurbs_surface_edit;
mod oriented_box;
mod oriented_box_boundary;
mod plane;
mod point;
mod polyline;
mod surface_bounding_box;
mod surface_closest_point;
mod surface_curvature;
mod surface_derivatives;
mod surface_direction;
mod surface_forms;
mod surface_grid;
mod surface_isocurve;
mod surface_normal;
pub mod tolerance;
mod transform;
mod vector;

pub use crate::arc::Arc;
pub use crate::arc_length::MAX_DIVISIONS;
pub use crate::bezier::Bezier;
pub use crate::bounding_box::BoundingBox;
pub use crate::brep::{
    Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex, EdgeKind, LoopKind, TrimKind,
};
pub use crate::brep_mass::{AreaProperties, VolumeProperties};
pub use crate::circle::Circle;
pub use crate::continuity::{
    Continuity, ContinuityTolerances, continuity, continuity_with_tolerances,
};
pub use crate::curve::Curve;
pub use crate::curve_closest_point::CurveClosestPoint;
pub use crate::curve_kinks::KINK_ANGLE_TOLERANCE;
pub use crate::error::{Error, Result};
pub use crate::hermite::CubicHermite;
pub use crate::interpolate::{EndTangents, KnotStyle};
pub use crate::interval::Interval;
pub use crate::line::Line;
pub use crate::mesh::{Color, Mesh, MeshFace};
pub use crate::nurbs_curve::NurbsCurve;
pub use crate::nurbs_surface::NurbsSurface;
pub use crate::oriented_box::OrientedBox;
pub use crate::plane::{Plane, perpendicular_to};
pub use crate::point::Point3;
pub use crate::polyline::Polyline;
pub use crate::surface_closest_point::SurfaceClosestPoint;
pub use crate::surface_curvature::SurfaceCurvature;
pub use crate::surface_derivatives::SurfaceDerivatives;
pub use crate::surface_direction::{SurfaceDirection, SurfaceSide};
pub use crate::surface_forms::{Cone, Cylinder, Sphere};
pub use crate::transform::Transform;
pub use crate::vector::{Parallelism, Vector3};
