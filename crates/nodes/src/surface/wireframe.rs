//! Surface › Analysis: Brep Wireframe, the edges and isocurves of a B-rep (the kernel's
//! `brep/wireframe.rs`).

use locus_kernel::{Curve, MAX_WIRE_DENSITY};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port, Shared, Value};

use super::brep::{brep_item, edge_curve, surface_node};

/// Id of [`brep_wireframe`].
pub const BREP_WIREFRAME: &str = "surface.brep_wireframe";

/// Registers Brep Wireframe.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(brep_wireframe());
}

/// Brep Wireframe \[Wires\]: the wireframe curves of a B-rep.
pub fn brep_wireframe() -> NodeType {
    surface_node(BREP_WIREFRAME, "Brep Wireframe", "Wires", "Analysis")
        .gh_guid("ac750e41-2450-4f98-9658-98fef97b01b2")
        .description(
            "Extracts the wireframe of a B-rep as Rhino draws it: every edge once (straight \
             edges as lines), then face by face the isocurves by the wire density: -1 edges \
             only, 0 also the isocurves at the faces' interior knots, 1 also one isocurve in \
             the middle of a direction without interior knots, N ≥ 2 the knot isocurves and \
             N + 1 more evenly spaced inside every span. On trimmed faces the isocurves are cut \
             to the parts inside the face.",
        )
        .input(
            Port::new("Brep", "B", DataType::Brep)
                .doc("The B-rep (boxes and surfaces are taken as B-reps)."),
        )
        .input(
            Port::new("Density", "D", DataType::Integer)
                .default_value(1i64)
                .doc("Wire density from -1 to 99. Default 1."),
        )
        .output(
            Port::new("Wireframe", "W", DataType::Curve)
                .list()
                .doc("The edges, then the isocurves."),
        )
        .solve(|s| {
            let brep = brep_item(s, 0)?;
            let density = *s.item::<i64>(1)?;
            if !(-1..=i64::from(MAX_WIRE_DENSITY)).contains(&density) {
                return Err(format!(
                    "input D: the density must be from -1 to {MAX_WIRE_DENSITY}, got {density}"
                )
                .into());
            }
            let curves = brep.wireframe(density as i32)?;
            let edges = brep.edges().len();
            let values = curves
                .into_iter()
                .enumerate()
                .map(|(k, c)| {
                    Some(if k < edges {
                        edge_curve(&c)
                    } else {
                        Value::Curve(Shared::new(Curve::Nurbs(c)))
                    })
                })
                .collect();
            s.set_list_values(0, values);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Interval, OrientedBox, Plane};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::test_support::*;

    fn unit_box() -> OrientedBox {
        OrientedBox::new(
            Plane::WORLD_XY,
            Interval::UNIT,
            Interval::UNIT,
            Interval::UNIT,
        )
    }

    #[test]
    fn a_box_wireframe() {
        let run = |d: i64| {
            NodeCall::new(&brep_wireframe())
                .input(DataTree::from_item(unit_box()))
                .input(DataTree::from_item(d))
                .run()
        };
        let r = run(-1);
        assert_clean(&r);
        let c = curves(&r.outputs[0]);
        assert_eq!(c.len(), 12);
        assert!(c.iter().all(|c| matches!(**c, Curve::Line { .. })));
        assert_eq!(curves(&run(1).outputs[0]).len(), 24);
        // Default density 1.
        let r = NodeCall::new(&brep_wireframe())
            .input(DataTree::from_item(unit_box()))
            .run();
        let total: f64 = curves(&r.outputs[0]).iter().map(|c| c.length()).sum();
        assert!((total - 24.0).abs() < 1e-12);
    }

    #[test]
    fn bad_density() {
        let r = NodeCall::new(&brep_wireframe())
            .input(DataTree::from_item(unit_box()))
            .input(DataTree::from_item(100i64))
            .run();
        assert_error(&r, "input D");
        let r = NodeCall::new(&brep_wireframe())
            .input(DataTree::from_item(3.0))
            .run();
        assert_error(&r, "input B");
    }
}
