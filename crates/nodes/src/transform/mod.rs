//! Transform: moving, rotating, scaling, shearing, mirroring, projecting and orienting geometry,
//! and building, combining, inverting and inspecting transformation matrices (Grasshopper's
//! Transform tab).
//!
//! Every node that makes a transformation has an optional *Geometry* input and two outputs:
//! the transformed geometry (G) and the matrix itself (X, a 4×4 [`Transform`]). Leaving the
//! geometry unconnected builds only the matrix, which can be inspected with *Deconstruct
//! Transform*, combined with *Compound* and applied later with *Transform*. The geometry input
//! takes any value; [`apply::transform_value`] says what each type becomes.
//!
//! Matrices follow the book and Rhino: they act on column vectors `[x, y, z, 1]`, so the
//! translation is the last column, and the product `B·A` applies `A` first.

pub mod affine;
pub mod apply;
pub mod array;
pub mod euclidean;
pub mod util;

use locus_kernel::Point3;
use locus_kernel::Transform;
use locus_runtime::{DataType, ItemReport, NodeError, NodeRegistry, NodeType, Port, Solve};

use apply::transform_value;

/// Registers every Transform node type.
pub fn register(registry: &mut NodeRegistry) {
    euclidean::register(registry);
    affine::register(registry);
    util::register(registry);
    array::register(registry);
}

/// A node of the Transform category.
fn transform_node(id: &str, name: &str, nickname: &str, subcategory: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Transform").subcategory(subcategory)
}

/// The optional generic Geometry input (input 0 of every transforming node).
fn geometry_input(verb: &str) -> Port {
    Port::new("Geometry", "G", DataType::Generic)
        .doc(&format!(
            "The geometry to {verb} (optional): points, vectors, planes, lines, circles, arcs, \
             curves, surfaces or boxes. Leave it unconnected to build only the transform X."
        ))
        .optional()
}

/// The Geometry output (output 0 of every transforming node).
fn geometry_output(participle: &str) -> Port {
    Port::new("Geometry", "G", DataType::Generic).doc(&format!(
        "The {participle} geometry; null where none was given or it could not be transformed."
    ))
}

/// The Transform output (output 1 of every transforming node).
fn transform_output() -> Port {
    Port::new("Transform", "X", DataType::Transform).doc(
        "The transformation matrix, to inspect with Deconstruct Transform, combine with \
         Compound or apply with Transform.",
    )
}

/// [`finish`] for one point, as the typed fast path of the transforming nodes runs it: the moved
/// point and the transform, or an error on output 0 where the point does not stay finite.
///
/// # Errors
/// When the transform has a NaN or infinite entry, as [`finish`].
#[inline(always)]
fn transform_point(
    p: Point3,
    xform: Transform,
    report: &mut ItemReport,
) -> Result<(Point3, Transform), NodeError> {
    if !xform.is_finite() {
        return Err("the transform has an entry that is not finite".into());
    }
    let q = xform.transform_point(p);
    if !q.is_finite() {
        report.error(0, "the transformed point is not finite");
    }
    Ok((q, xform))
}

/// Writes `xform` to output 1 and, when geometry arrived at input 0, the transformed geometry
/// to output 0. Geometry that cannot be transformed is an error for this item, but the
/// transform is still written.
///
/// # Errors
/// When the transform has a NaN or infinite entry (from a NaN angle, factor or coordinate).
fn finish(s: &mut Solve<'_>, xform: Transform) -> Result<(), NodeError> {
    if !xform.is_finite() {
        return Err("the transform has an entry that is not finite".into());
    }
    s.set(1, xform);
    if let Some(value) = s.value(0) {
        match transform_value(&value, &xform) {
            Ok(out) => s.set_value(0, Some(out)),
            Err(e) => s.error(e.0),
        }
    }
    Ok(())
}
