//! Curves approximated by polylines within the meshing limits (Rhino's `ToPolyline` with a
//! chord tolerance, angle tolerance and edge lengths).

use crate::mesh::parameters::MeshingParameters;
use crate::mesh::tessellate::curve_parameters;
use crate::{Curve, NurbsCurve, Polyline, Result};

impl NurbsCurve {
    /// A polyline through points of the curve, dividing each span adaptively so that every
    /// segment meets the limits (a chord deviation, a turning angle of the tangent, edge
    /// lengths); span breaks, kinks included, are always vertices.
    ///
    /// # Errors
    /// [`Error::InvalidInput`](crate::Error::InvalidInput) for bad parameters or limits that
    /// would need more than
    /// [`MAX_MESH_SAMPLES_PER_DIRECTION`](crate::MAX_MESH_SAMPLES_PER_DIRECTION) points.
    pub fn to_polyline(&self, parameters: &MeshingParameters) -> Result<Polyline> {
        parameters.validate()?;
        let ts = curve_parameters(self, parameters)?;
        Polyline::new(ts.iter().map(|&t| self.point_at(t)).collect())
    }
}

impl Curve {
    /// The curve as a polyline within the limits (see [`NurbsCurve::to_polyline`]); lines and
    /// polylines come back with their own vertices.
    ///
    /// # Errors
    /// As [`NurbsCurve::to_polyline`].
    pub fn to_polyline(&self, parameters: &MeshingParameters) -> Result<Polyline> {
        self.to_nurbs().to_polyline(parameters)
    }
}

#[cfg(test)]
mod tests {
    use crate::{Circle, Curve, MeshingParameters, Plane, Point3, Polyline};

    #[test]
    fn a_circle_stays_within_the_chord_tolerance() {
        let circle = Circle::new(Plane::WORLD_XY, 10.0).unwrap();
        for tol in [1e-1, 1e-2, 1e-3] {
            let poly = Curve::from(circle)
                .to_polyline(&MeshingParameters::with_chord_deviation(tol))
                .unwrap();
            let p = poly.points();
            assert!(p[0].distance(p[p.len() - 1]) < 1e-12);
            for w in p.windows(2) {
                assert!((w[0].to_vector().length() - 10.0).abs() < 1e-9);
                let sagitta = 10.0 - w[0].midpoint(w[1]).to_vector().length();
                assert!(sagitta <= tol * 1.05, "sagitta {sagitta} > {tol}");
            }
        }
    }

    #[test]
    fn a_polyline_keeps_its_corners() {
        let pts = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
        ];
        let poly = Curve::from(Polyline::new(pts.clone()).unwrap())
            .to_polyline(&MeshingParameters::default())
            .unwrap();
        assert_eq!(poly.points(), &pts[..]);
    }
}
