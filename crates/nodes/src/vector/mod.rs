//! Vector: points, vectors and planes (Grasshopper's Vector tab).
//!
//! Every node here computes with the kernel's [`Point3`](locus_kernel::Point3),
//! [`Vector3`](locus_kernel::Vector3) and [`Plane`](locus_kernel::Plane). Bad input never
//! panics: a NaN or infinite coordinate, a zero-length vector where a direction is needed, or
//! collinear points where a plane is needed give an error on the node for that item, and a null
//! in its outputs.
//!
//! Nodes with one output that are plain functions of their items (Construct Point, Distance,
//! Point Between, Unit X/Y/Z, Unit Vector, Amplitude, Vector Length, Reverse, Rotate, Dot
//! Product, Construct Plane, Plane 3Pt, Plane Normal, XY/YZ/XZ Plane) are declared with the
//! runtime's `lift1`/`lift2`/`lift3`, which runs them as one loop over the typed columns (see
//! the crate docs, `# Performance`); the others read their items through `Solve`.
//!
//! Vector addition, subtraction and scaling by a number have no nodes of their own here, as in
//! Grasshopper: Maths › Addition, Subtraction and Multiplication take vectors and points, and
//! [Amplitude](vectors::amplitude) sets a vector's length.

pub mod grid;
pub mod plane;
pub mod plane_edit;
pub mod point;
pub mod point_sets;
pub mod populate;
pub mod products;
pub mod pull;
pub mod vectors;

use locus_kernel::{Point3, Vector3};
use locus_runtime::{ItemReport, NodeError, NodeRegistry};

/// Registers every Vector node type.
pub fn register(registry: &mut NodeRegistry) {
    point::register(registry);
    pull::register(registry);
    vectors::register(registry);
    products::register(registry);
    plane::register(registry);
    grid::register(registry);
    plane_edit::register(registry);
    point_sets::register(registry);
    populate::register(registry);
}

/// `x`, or an error saying that `what` is not a finite number.
pub(crate) fn finite_number(x: f64, what: &str) -> Result<f64, NodeError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(NodeError(format!("{what} is not a finite number ({x})")))
    }
}

/// `p`, or an error saying that `what` has a NaN or infinite coordinate.
pub(crate) fn finite_point(p: Point3, what: &str) -> Result<Point3, NodeError> {
    if p.is_finite() {
        Ok(p)
    } else {
        Err(NodeError(format!(
            "{what} has a coordinate that is not finite"
        )))
    }
}

/// `v`, or an error saying that `what` has a NaN or infinite component.
pub(crate) fn finite_vector(v: Vector3, what: &str) -> Result<Vector3, NodeError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(NodeError(format!(
            "{what} has a component that is not finite"
        )))
    }
}

/// Warns, for nodes that take geometry apart, that `what` has a NaN or infinite coordinate:
/// the numbers are still written (as NaN or infinity) so that lists stay aligned.
pub(crate) fn warn_unless_finite(report: &mut ItemReport, finite: bool, what: &str) {
    if !finite {
        report.warning(format!(
            "{what} has a coordinate that is not finite; its numbers are not finite either"
        ));
    }
}

/// The unit vector of `v`, or an error naming `what` when it has zero length or is not finite.
pub(crate) fn unit(v: Vector3, what: &str) -> Result<Vector3, NodeError> {
    finite_vector(v, what)?
        .try_normalize()
        .ok_or_else(|| NodeError(format!("{what} has zero length and no direction")))
}

#[cfg(test)]
pub(crate) mod test_support {
    //! Helpers for the tests of the Vector, Transform and geometry Params nodes: the crate's
    //! [`crate::test_support`].
    pub(crate) use crate::test_support::*;
}
