//! Surface › Analysis: Box Corners, the eight corners of a box.

use locus_kernel::{OrientedBox, Point3};
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::brep::surface_node;

/// Id of [`box_corners`].
pub const BOX_CORNERS: &str = "surface.box_corners";

/// Registers Box Corners.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(box_corners());
}

/// Box Corners \[Box Corners\]: the corners A to H of a box.
pub fn box_corners() -> NodeType {
    let mut node = surface_node(BOX_CORNERS, "Box Corners", "Box Corners", "Analysis")
        .gh_guid("a10e8cdf-7c7a-4aac-aa70-ddb7010ab231")
        .description(
            "Extracts the eight corners of a box: A to D on the bottom face (the start of its \
             z domain) counter-clockwise about the box's z axis from the corner at the start \
             of its x and y domains, then E to H above them on the top face.",
        )
        .input(Port::new("Box", "B", DataType::Box).doc("The box."));
    let docs = [
        "(x0, y0, z0)",
        "(x1, y0, z0)",
        "(x1, y1, z0)",
        "(x0, y1, z0)",
        "(x0, y0, z1)",
        "(x1, y0, z1)",
        "(x1, y1, z1)",
        "(x0, y1, z1)",
    ];
    for (k, at) in docs.iter().enumerate() {
        let letter = char::from(b'A' + k as u8).to_string();
        node = node.output(
            Port::new(&format!("Corner {letter}"), &letter, DataType::Point).doc(&format!(
                "The corner at {at} in the box's plane coordinates."
            )),
        );
    }
    node.solve(|s| {
        let b = *s.item::<OrientedBox>(0)?;
        if !b.is_finite() {
            return Err("box B is not finite".into());
        }
        let corners: [Point3; 8] = b.corners();
        for (k, c) in corners.into_iter().enumerate() {
            s.set(k, c);
        }
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Interval, Plane};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::test_support::{assert_error, only};

    #[test]
    fn corners_a_to_h() {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        );
        let r = NodeCall::new(&box_corners())
            .input(DataTree::from_item(b))
            .run();
        assert_eq!(only::<Point3>(&r, 0), Point3::ORIGIN);
        assert_eq!(only::<Point3>(&r, 2), Point3::new(1.0, 2.0, 0.0));
        assert_eq!(only::<Point3>(&r, 7), Point3::new(0.0, 2.0, 3.0));
        let bad = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(f64::NAN, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        );
        let r = NodeCall::new(&box_corners())
            .input(DataTree::from_item(bad))
            .run();
        assert_error(&r, "box B is not finite");
    }
}
