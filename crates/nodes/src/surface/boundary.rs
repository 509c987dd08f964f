//! Surface › Freeform: Boundary Surfaces, planar faces bounded by closed planar curves.
//!
//! Curves in one plane are nested by containment: a curve inside an even number of others is
//! an outer boundary, one inside an odd number a hole of the smallest curve around it. The
//! faces' trims are the boundary curves themselves, mapped exactly into the plane (not
//! polyline approximations), so a circle bounds a disc of area πr² exactly; each curve is
//! split at its kinks into edges (a rectangle has four). Planarity uses
//! [`MODEL_TOLERANCE`](super::extrusion::MODEL_TOLERANCE).

use locus_kernel::Brep;
use locus_runtime::{DataType, NodeType, Port, Shared, Value};

use super::brep::surface_node;
use super::extrusion::MODEL_TOLERANCE;

/// Id of [`boundary_surfaces`].
pub const BOUNDARY_SURFACES: &str = "surface.boundary_surfaces";

/// Id of [`cap_holes`].
pub const CAP_HOLES: &str = "surface.cap_holes";

/// Registers Boundary Surfaces and Cap Holes.
pub fn register(registry: &mut locus_runtime::NodeRegistry) {
    registry.register(boundary_surfaces());
    registry.register(cap_holes());
}

/// Cap Holes \[Cap\]: planar faces on the planar holes of a B-rep.
pub fn cap_holes() -> NodeType {
    surface_node(CAP_HOLES, "Cap Holes", "Cap", "Util")
        .gh_guid("b648d933-ddea-4e75-834c-8f6f3793e311")
        .description(
            "Caps the planar holes of a B-rep: naked edges are chained end to end into closed \
             loops, and every loop that is planar (within 0.001) gets a planar face bounded by \
             those edges, joined to the B-rep (an open tube becomes a closed cylinder). Loops \
             that are open or not planar stay open, with a remark; a closed B-rep is returned \
             unchanged.",
        )
        .input(Port::new("Brep", "B", DataType::Brep).doc("The B-rep to cap."))
        .output(Port::new("Brep", "B", DataType::Brep).doc("The capped B-rep."))
        .solve(|s| {
            let brep = super::brep::brep_item(s, 0)?;
            let naked = brep.edges_of_kind(locus_kernel::EdgeKind::Naked).len();
            let (capped, caps) = brep.cap_planar_holes(MODEL_TOLERANCE)?;
            let still = capped.edges_of_kind(locus_kernel::EdgeKind::Naked).len();
            if naked > 0 && still > 0 {
                s.remark(format!(
                    "{caps} hole(s) capped; {still} naked edge(s) are left (open or non-planar loops)"
                ));
            }
            s.set(0, Shared::new(capped));
            Ok(())
        })
}

/// Boundary Surfaces \[Boundary\]: planar faces from closed planar curves.
pub fn boundary_surfaces() -> NodeType {
    surface_node(
        BOUNDARY_SURFACES,
        "Boundary Surfaces",
        "Boundary",
        "Freeform",
    )
    .gh_guid("d51e9b65-aa4e-4fd6-976c-cef35d421d05")
    .description(
        "Creates planar faces from a list of closed planar curves. Curves in the same \
             plane (within 0.001) are nested: a curve inside an even number of others bounds \
             a face, and one inside an odd number is a hole in the smallest curve around it, \
             so a ring of two circles gives an annulus. Each face is a trimmed plane whose \
             trims are the curves themselves (exact), with one edge per kink-free piece of \
             each curve; faces come out in the order of their outer curves. Open or \
             non-planar curves are left out with a warning.",
    )
    .input(
        Port::new("Edges", "E", DataType::Curve)
            .list()
            .doc("The boundary curves: closed and planar; nulls are left out."),
    )
    .output(
        Port::new("Surfaces", "S", DataType::Brep)
            .list()
            .doc("The planar faces, each a one-face B-rep."),
    )
    .solve(|s| {
        let list = s.list::<Shared<locus_kernel::Curve>>(0)?;
        let mut curves = Vec::with_capacity(list.len());
        let mut left_out = Vec::new();
        for (k, c) in list.iter().enumerate() {
            match c {
                Some(c) if c.is_valid() => curves.push((k, (**c).clone())),
                Some(_) => left_out.push(format!("curve {k} is not valid")),
                None => left_out.push(format!("item {k} is null")),
            }
        }
        let only: Vec<locus_kernel::Curve> = curves.iter().map(|(_, c)| c.clone()).collect();
        let (faces, failed) = Brep::planar_regions(&only, MODEL_TOLERANCE)?;
        for (i, e) in failed {
            left_out.push(format!("curve {}: {e}", curves[i].0));
        }
        for w in left_out {
            s.warning(format!("input E: {w}; left out"));
        }
        let faces = faces
            .into_iter()
            .map(|b| Some(Value::Brep(Shared::new(b))))
            .collect();
        s.set_list_values(0, faces);
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Curve, Plane, Point3, Polyline};
    use locus_runtime::{DataTree, Level, NodeCall};
    use std::f64::consts::PI;

    use super::*;

    fn circle(r: f64) -> Shared<Curve> {
        Shared::new(Curve::from(Circle::new(Plane::WORLD_XY, r).unwrap()))
    }

    #[test]
    fn a_ring_of_circles_is_an_annulus() {
        let r = NodeCall::new(&boundary_surfaces())
            .input(DataTree::from_list(vec![circle(1.0), circle(3.0)]))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let faces: Vec<Value> = r.outputs[0].values().flatten().collect();
        assert_eq!(faces.len(), 1);
        let Value::Brep(b) = &faces[0] else { panic!() };
        assert!((b.area().unwrap() - 8.0 * PI).abs() < 1e-9);
    }

    #[test]
    fn an_open_tube_is_capped() {
        let tube = Brep::from_cylinder(
            &locus_kernel::Cylinder::new(Plane::WORLD_XY, 1.0, 2.0).unwrap(),
            false,
        )
        .unwrap();
        let r = NodeCall::new(&cap_holes())
            .input(DataTree::from_item(Shared::new(tube)))
            .run();
        let Some(Value::Brep(b)) = r.outputs[0].values().next().flatten() else {
            panic!("{:?}", r.messages)
        };
        assert!(b.is_solid());
        assert!((b.volume().unwrap() - 2.0 * PI).abs() < 1e-9);
    }

    #[test]
    fn open_curves_are_left_out_with_a_warning() {
        let open = Shared::new(Curve::from(
            Polyline::new(vec![Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)]).unwrap(),
        ));
        let r = NodeCall::new(&boundary_surfaces())
            .input(DataTree::from_list(vec![open, circle(1.0)]))
            .run();
        assert_eq!(r.outputs[0].values().flatten().count(), 1);
        assert!(
            r.messages
                .iter()
                .any(|m| m.level == Level::Warning && m.text.contains("curve 0")),
            "{:?}",
            r.messages
        );
    }
}
