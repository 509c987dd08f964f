//! Meshing parameters in the spirit of Rhino's `MeshingParameters`: a maximum angle between
//! neighbouring normals, a maximum chord deviation, maximum and minimum edge lengths, and a
//! simple density that sets the angle for users who want one number.
//!
//! A limit of `0.0` is off, as in Rhino. The default angle is much tighter than Rhino's "jagged
//! and faster" preset (20°) so that a mesh's area is within 1e-3 of the exact area: a regular
//! polygon whose sides subtend θ loses θ²/6 of its circle's area and θ²/24 of its perimeter, and
//! an inscribed sphere mesh about θ²/8 of the sphere's area, so 3.5° (θ²/6 = 6.2e-4) keeps planar
//! caps, cylinders and spheres within the bound.

use crate::{Error, Result};

/// The default maximum angle between the normals of neighbouring mesh vertices (or the tangents
/// at the ends of a polyline segment): 3.5° (0.0611 rad).
pub const DEFAULT_MESH_MAX_ANGLE: f64 = 3.5 * std::f64::consts::PI / 180.0;

/// The default maximum distance between a mesh edge and the surface: 0 (off; the angle governs,
/// which keeps the mesh independent of the model's scale).
pub const DEFAULT_MESH_MAX_CHORD_DEVIATION: f64 = 0.0;

/// The share of the chord deviation each parameter direction of a surface may use: one half.
///
/// A surface is divided along each direction on its own, so that the isocurves' chords
/// deviate by at most the share given to that direction. In a grid cell the deviations of the
/// two directions add: at the middle of a cell of a surface bending by `κ_u` and `κ_v`, and at
/// the middle of the diagonal that splits it into triangles, the distance to the surface is
/// about `(κ_u h_u² + κ_v h_v²) / 8`, the sum of the two isocurves' sagittas. Giving each
/// direction half of the limit keeps that sum within it (a sphere or torus meshed with the
/// whole limit in both directions was up to twice the limit away from its surface). Edge
/// curves, which are single chords, keep the whole limit.
pub const SURFACE_CHORD_SHARE: f64 = 0.5;

/// The default maximum edge length: 0 (off).
pub const DEFAULT_MESH_MAX_EDGE_LENGTH: f64 = 0.0;

/// The default minimum edge length: 1e-4 model units (Rhino's default). Parameter intervals
/// shorter than this on the surface are not subdivided further.
pub const DEFAULT_MESH_MIN_EDGE_LENGTH: f64 = 1e-4;

/// The coarsest maximum angle of [`MeshingParameters::from_density`] (density 0): 20°, Rhino's
/// "jagged and faster".
pub const COARSEST_MESH_ANGLE: f64 = 20.0 * std::f64::consts::PI / 180.0;

/// The finest maximum angle of [`MeshingParameters::from_density`] (density 1): 1°.
pub const FINEST_MESH_ANGLE: f64 = std::f64::consts::PI / 180.0;

/// The most parameter values one face may be sampled at in one direction (4,096), so that
/// hostile parameters (an edge length of 1e-12) fail with a reason instead of exhausting memory.
pub const MAX_MESH_SAMPLES_PER_DIRECTION: usize = 4096;

/// The most vertices one meshing may produce (10,000,000).
pub const MAX_MESH_VERTICES: usize = 10_000_000;

/// How finely to mesh surfaces and B-reps and to approximate curves by polylines.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshingParameters {
    /// The largest angle in radians between the normals (or, along a curve, the tangents) at
    /// the ends of a mesh edge; 0 is off.
    pub max_angle: f64,
    /// The largest distance between a mesh edge's midpoint and the surface or curve; 0 is off.
    pub max_chord_deviation: f64,
    /// The longest mesh edge; 0 is off.
    pub max_edge_length: f64,
    /// Edges shorter than this are not split further, whatever the other limits say.
    pub min_edge_length: f64,
}

impl Default for MeshingParameters {
    fn default() -> Self {
        Self {
            max_angle: DEFAULT_MESH_MAX_ANGLE,
            max_chord_deviation: DEFAULT_MESH_MAX_CHORD_DEVIATION,
            max_edge_length: DEFAULT_MESH_MAX_EDGE_LENGTH,
            min_edge_length: DEFAULT_MESH_MIN_EDGE_LENGTH,
        }
    }
}

impl MeshingParameters {
    /// The default parameters (see the module's constants).
    pub fn new() -> Self {
        Self::default()
    }

    /// Parameters from one density in `[0, 1]` (clamped): the maximum angle goes geometrically
    /// from [`COARSEST_MESH_ANGLE`] at 0 to [`FINEST_MESH_ANGLE`] at 1 (about 4.5° at 0.5); the
    /// other limits keep their defaults. NaN counts as 0.5.
    pub fn from_density(density: f64) -> Self {
        let d = if density.is_nan() {
            0.5
        } else {
            density.clamp(0.0, 1.0)
        };
        let ratio = FINEST_MESH_ANGLE / COARSEST_MESH_ANGLE;
        Self {
            max_angle: COARSEST_MESH_ANGLE * ratio.powf(d),
            ..Self::default()
        }
    }

    /// Parameters with only a chord tolerance (as for curves turned into polylines): the
    /// maximum chord deviation is `tolerance`, the angle limit off.
    pub fn with_chord_deviation(tolerance: f64) -> Self {
        Self {
            max_angle: 0.0,
            max_chord_deviation: tolerance,
            max_edge_length: 0.0,
            min_edge_length: 0.0,
        }
    }

    /// Checks that every limit is finite and not negative, that the maximum angle is below a
    /// half turn, and that at least one of angle, chord deviation and maximum edge length is on.
    ///
    /// # Errors
    /// [`Error::InvalidInput`] naming the bad limit.
    pub fn validate(&self) -> Result<()> {
        let limits = [
            ("maximum angle", self.max_angle),
            ("maximum chord deviation", self.max_chord_deviation),
            ("maximum edge length", self.max_edge_length),
            ("minimum edge length", self.min_edge_length),
        ];
        for (name, value) in limits {
            if !value.is_finite() || value < 0.0 {
                return Err(Error::InvalidInput(format!(
                    "meshing {name} must be finite and not negative, got {value}"
                )));
            }
        }
        if self.max_angle >= std::f64::consts::PI {
            return Err(Error::InvalidInput(format!(
                "meshing maximum angle must be below π, got {}",
                self.max_angle
            )));
        }
        if self.max_angle == 0.0 && self.max_chord_deviation == 0.0 && self.max_edge_length == 0.0 {
            return Err(Error::InvalidInput(
                "meshing needs a maximum angle, chord deviation or edge length".into(),
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn density_spans_the_two_presets() {
        assert!(
            (MeshingParameters::from_density(0.0).max_angle - COARSEST_MESH_ANGLE).abs() < 1e-15
        );
        assert!((MeshingParameters::from_density(1.0).max_angle - FINEST_MESH_ANGLE).abs() < 1e-15);
        assert!(
            MeshingParameters::from_density(0.3).max_angle
                > MeshingParameters::from_density(0.6).max_angle
        );
        assert!(MeshingParameters::from_density(f64::NAN).validate().is_ok());
    }

    #[test]
    fn bad_limits_are_refused() {
        let mut p = MeshingParameters::default();
        assert!(p.validate().is_ok());
        p.max_chord_deviation = f64::NAN;
        assert!(p.validate().is_err());
        p = MeshingParameters::with_chord_deviation(0.0);
        assert!(p.validate().is_err());
        p = MeshingParameters {
            max_angle: 4.0,
            ..Default::default()
        };
        assert!(p.validate().is_err());
    }
}
