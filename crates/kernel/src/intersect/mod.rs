//! Intersections (Rhino's `Intersection` class): lines and planes in closed form
//! (`linear.rs`); curves with planes and infinite lines (`curve_plane.rs`) by root isolation in
//! Bernstein form (`bernstein.rs`); curves with curves and with themselves (`curve_curve.rs`,
//! `curve_self.rs`) by subdivision of Bézier pieces (`piece.rs`) and Newton's method on the
//! distance (`pair_newton.rs`); curves and lines with surfaces and B-reps (`curve_surface.rs`,
//! `brep_curve.rs`) by subdivision of pieces against Bézier patches (`patch.rs`) and Newton's
//! method on the distance (`surface_newton.rs`); and meshes with rays and planes (`mesh.rs`).
//!
//! Every search takes its tolerance as an argument: inputs closer than it meet. Points are
//! polished to full precision whatever the tolerance; the tolerance decides only what counts as
//! meeting and which nearby events are the same.

pub(crate) mod bernstein;
pub(crate) mod brep_brep;
pub(crate) mod brep_curve;
pub(crate) mod brep_inside;
pub(crate) mod brep_plane;
pub(crate) mod curve_curve;
pub(crate) mod curve_plane;
pub(crate) mod curve_self;
pub(crate) mod curve_surface;
pub(crate) mod face_region;
pub(crate) mod hermite_fit;
pub(crate) mod linear;
pub(crate) mod mesh;
pub(crate) mod pair_newton;
pub(crate) mod patch;
pub(crate) mod piece;
pub(crate) mod surface_newton;
pub(crate) mod surface_plane;
pub(crate) mod surface_surface;
