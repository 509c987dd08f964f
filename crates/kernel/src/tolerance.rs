//! Named tolerances used throughout the kernel.
//!
//! Every approximate computation takes its tolerance as an argument; these are the defaults.

/// Lengths at or below this are treated as zero when normalizing or testing degeneracy.
///
/// The value is openNURBS's `ON_ZERO_TOLERANCE` (2⁻³²), so that what Rhino treats as a zero-length
/// vector we treat as one too.
pub const ZERO_TOLERANCE: f64 = 2.328_306_436_538_696_3e-10;

/// The default absolute tolerance for geometric tests (coincidence, parallelism by distance,
/// closest-point convergence): 1e-9 model units.
pub const DEFAULT_TOLERANCE: f64 = 1e-9;

/// The default angle tolerance in radians for parallel, perpendicular and continuity tests:
/// 1e-9 rad.
pub const ANGLE_TOLERANCE: f64 = 1e-9;

/// The default relative tolerance of arc lengths: adaptive quadrature stops when its error
/// estimate is below 1e-12 of the curve's length.
pub const LENGTH_TOLERANCE: f64 = 1e-12;

/// The default relative tolerance between curvature magnitudes for G2 continuity: 1e-9.
pub const CURVATURE_TOLERANCE: f64 = 1e-9;
