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

/// The square root of the machine epsilon as openNURBS spells it (`ON_SQRT_EPSILON`,
/// 1.490116119385e-8).
///
/// Rhino uses it to clean noise out of rotation sines and cosines: a rotation whose sine is within
/// this of zero (angles below about 1.5e-8 rad, or that close to a half turn) is built as the exact
/// identity or half turn, and one whose cosine is this close to zero as an exact quarter turn.
/// [`Transform::rotation`](crate::Transform::rotation) does the same so that our matrices equal
/// Rhino's entry for entry. Surfaces use it too: a partial derivative smaller than this relative
/// to the other counts as negligible, so that the normal must be found as a limit (at poles).
pub const SQRT_EPSILON: f64 = 1.490_116_119_385e-8;

/// How far from singular a transform must be for [`Transform::inverse`](crate::Transform::inverse)
/// to invert it: 1e-12.
///
/// The measure is scale-free: the determinant of the matrix after each row (or, if that is
/// larger, each column) is scaled to unit length, which is the volume of the parallelepiped
/// spanned by the unit rows (columns). It is 1 for rotations, mirrors, translations and any
/// scale, including non-uniform ones, because scaling rows or columns does not make an inverse
/// less accurate; it goes to 0 as the rows become dependent (a projection, or a shear
/// approaching one). Below 1e-12 the inverse would lose more than about 12 of its 16
/// significant digits, so the transform is reported as singular instead. For affine transforms
/// only the 3×3 linear part is measured, so translations, however large, never count.
pub const SINGULAR_TOLERANCE: f64 = 1e-12;

/// The default relative tolerance of arc lengths: adaptive quadrature stops when its error
/// estimate is below 1e-12 of the curve's length.
pub const LENGTH_TOLERANCE: f64 = 1e-12;

/// The default relative tolerance between curvature magnitudes for G2 continuity: 1e-9.
pub const CURVATURE_TOLERANCE: f64 = 1e-9;

/// The document tolerance of Rhino's default templates, 0.001 model units: the distance within
/// which curve ends join ([`Curve::join`](crate::Curve::join)) and within which approximations
/// such as curve offsets are made.
pub const DOCUMENT_TOLERANCE: f64 = 0.001;

/// How close to a circle a NURBS curve must be for [`Curve::offset`](crate::Curve::offset) to
/// treat it as an arc and offset it exactly, by changing its radius: 1e-10 model units (or the
/// offset's own tolerance, when that is smaller).
///
/// Rhino's rational quadratic arcs and circles lie on their circle to rounding (about 1e-15
/// relative), so they pass; a curve that is only close to an arc (a cubic approximating a
/// quarter circle deviates by about 3e-4 of its radius) does not, and is offset by a fit.
pub const ARC_OFFSET_TOLERANCE: f64 = 1e-10;
