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

/// The relative size below which one partial derivative of a surface counts as negligible
/// beside the other, so that the normal must be found as a limit: √ε ≈ 1.49e-8, openNURBS's
/// `ON_SQRT_EPSILON`.
pub const SQRT_EPSILON: f64 = 1.490_116_119_385e-8;
