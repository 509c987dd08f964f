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
//! # Performance
//! Batch evaluation is measured by the `curve_eval` and `surface_eval` benchmarks (figures in
//! their headers). Divisions, closest points and sphere construction are measured by the
//! `queries` benchmark beside baselines in the same run, with the figures in
//! `docs/performance-kernel.md`: 1M divisions of a 61-span cubic take 0.76 s of CPU time
//! (about 186 batch point evaluations each), because one length table serves all the divisions.
//! A curve closest point costs about 170 to 230 point evaluations, and a sphere's NURBS surface
//! 0.2 µs.
//!
//! # Examples
//! ```
//! use locus_kernel::{Point3, Vector3};
//! let p = Point3::new(2.0, 3.0, 1.0) + Vector3::new(2.0, 2.0, 2.0);
//! assert_eq!(p, Point3::new(4.0, 5.0, 3.0));
//! assert_eq!(Vector3::new(4.0, 3.0, 0.0).length(), 5.0);
//! ```

mod boolean;
mod brep;
mod curve;
mod error;
mod geometry;
mod intersect;
mod mesh;
mod surface;
mod transform;

pub use crate::boolean::BooleanOperation;
pub use crate::boolean::cuts::TRACE_PRECISION;
pub use crate::brep::mass::{AreaProperties, VolumeProperties};
pub use crate::brep::pipe::PipeCaps;
pub use crate::brep::sweep::{MAX_SWEEP_PROFILES, SweepMiter};
pub use crate::brep::wireframe::MAX_WIRE_DENSITY;
pub use crate::brep::{
    Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex, EdgeKind, LoopKind, TrimKind,
};
pub use crate::curve::Curve;
pub use crate::curve::arc::Arc;
pub use crate::curve::arc_length::MAX_DIVISIONS;
pub use crate::curve::bezier::Bezier;
pub use crate::curve::circle::Circle;
pub use crate::curve::circle_fit::CircleFit;
pub use crate::curve::closest_point::CurveClosestPoint;
pub use crate::curve::containment::Containment;
pub use crate::curve::continuity::{
    Continuity, ContinuityTolerances, DERIVATIVE_TOLERANCE, ParametricContinuity, continuity,
    continuity_with_tolerances,
};
pub use crate::curve::ellipse::Ellipse;
pub use crate::curve::equidistant::EQUIDISTANT_SAMPLES;
pub use crate::curve::extend::{CurveExtension, EXTENSION_LENGTH_TOLERANCE};
pub use crate::curve::fillet::{CurveFillet, SharpCorner};
pub use crate::curve::fit::MAX_FIT_SPANS;
pub use crate::curve::frames::{MAX_FRAME_STEPS, MAX_STEP_TURN, MIN_STEPS_PER_SPAN};
pub use crate::curve::hermite::CubicHermite;
pub use crate::curve::kinks::KINK_ANGLE_TOLERANCE;
pub use crate::curve::line::Line;
pub use crate::curve::nurbs::NurbsCurve;
pub use crate::curve::nurbs::basis;
pub use crate::curve::nurbs::interpolate::{EndTangents, KnotStyle};
pub use crate::curve::offset::{CurveOffset, MAX_OFFSET_SAMPLES, OffsetCorners};
pub use crate::curve::polyline::Polyline;
pub use crate::curve::region::{MAX_REGION_CURVES, RegionOperation, SIDE_OFFSET};
pub use crate::error::{Error, Result};
pub use crate::geometry::best_candidate::{
    BEST_CANDIDATES, best_candidate_points, best_candidate_samples,
};
pub use crate::geometry::bounding_box::BoundingBox;
pub use crate::geometry::interval::{Interval, UvInterval};
pub use crate::geometry::oriented_box::OrientedBox;
pub use crate::geometry::plane::{Plane, perpendicular_to};
pub use crate::geometry::plane_fit::{LINE_SPREAD, PlaneFit};
pub use crate::geometry::point::Point3;
pub use crate::geometry::tolerance;
pub use crate::geometry::vector::{Parallelism, Vector3};
pub use crate::intersect::brep_brep::BrepIntersection;
pub use crate::intersect::brep_curve::{BrepCurveHit, BrepCurveIntersections, BrepCurveOverlap};
pub use crate::intersect::brep_inside::BrepContainment;
pub use crate::intersect::brep_plane::{
    BrepSection, ContourSection, MAX_CONTOUR_PLANES, contour_planes,
};
pub use crate::intersect::curve_curve::{
    CurveCurveHit, CurveCurveIntersections, CurveOverlap, TANGENT_SINE,
};
pub use crate::intersect::curve_plane::{CurveHit, CurveIntersections};
pub use crate::intersect::curve_surface::{
    CurveSurfaceHit, CurveSurfaceIntersections, CurveSurfaceOverlap,
};
pub use crate::intersect::linear::{line_line, line_plane, plane_plane, plane_plane_plane};
pub use crate::intersect::mesh::{mesh_plane, mesh_ray};
pub use crate::mesh::parameters::{
    COARSEST_MESH_ANGLE, DEFAULT_MESH_MAX_ANGLE, DEFAULT_MESH_MAX_CHORD_DEVIATION,
    DEFAULT_MESH_MAX_EDGE_LENGTH, DEFAULT_MESH_MIN_EDGE_LENGTH, FINEST_MESH_ANGLE,
    MAX_MESH_SAMPLES_PER_DIRECTION, MAX_MESH_VERTICES, MeshingParameters, SURFACE_CHORD_SHARE,
};
pub use crate::mesh::{
    Color, FaceTriangle, GRID_COINCIDENT_DISTANCE, GeometrySampler, INDEX_MIN_FACES, Mesh,
    MeshEdge, MeshFace, MeshPoint, PlanarTriangulation, WELD_DISTANCE, spread_points,
};
pub use crate::surface::NurbsSurface;
pub use crate::surface::closest_point::SurfaceClosestPoint;
pub use crate::surface::curvature::SurfaceCurvature;
pub use crate::surface::derivatives::SurfaceDerivatives;
pub use crate::surface::direction::{SurfaceDirection, SurfaceSide};
pub use crate::surface::forms::{Cone, Cylinder, Sphere};
pub use crate::surface::loft::{LoftType, MAX_LOFT_SECTIONS, align_loft_sections};
pub use crate::surface::offset::MAX_OFFSET_GRID;
pub use crate::surface::sphere_fit::SphereFit;
pub use crate::surface::sweep::MAX_SWEEP_SPANS;
pub use crate::transform::Transform;
