//! Curve › Analysis and Division: frames on curves — Curve Frame and Perp Frame at a parameter,
//! Curve Frames and Perp Frames at equal lengths along a curve.
//!
//! A curve frame (Rhino's `FrameAt`) has its x axis along the tangent and its y axis towards
//! the centre of curvature. A perpendicular frame has its z axis along the tangent and its x
//! axis carried along the curve without turning about the tangent (a rotation-minimizing frame,
//! Rhino's `GetPerpendicularFrames`); the kernel's `curve/frames.rs` documents how the first
//! frame is chosen. Perp Frames with Align off gives frames found at each point alone, x towards
//! the centre of curvature, which flip where the curve's bending changes side.

use locus_kernel::{Curve, MAX_DIVISIONS, Plane};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Solve};

use super::{curve_input, finite_parameter};

/// Id of [`curve_frame`].
pub const CURVE_FRAME: &str = "curve.curve_frame";
/// Id of [`perp_frame`].
pub const PERP_FRAME: &str = "curve.perp_frame";
/// Id of [`curve_frames`].
pub const CURVE_FRAMES: &str = "curve.curve_frames";
/// Id of [`perp_frames`].
pub const PERP_FRAMES: &str = "curve.perp_frames";

/// Registers the frame nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [curve_frame(), perp_frame(), curve_frames(), perp_frames()] {
        registry.register(t);
    }
}

fn curve_port() -> Port {
    Port::new("Curve", "C", DataType::Curve).doc("Curve to evaluate.")
}

fn parameter_port() -> Port {
    Port::new("Parameter", "t", DataType::Number).doc("Parameter on the curve's domain.")
}

/// Reads parameter input `input`, which must lie on the curve's domain.
fn parameter_in(s: &Solve<'_>, input: usize, curve: &Curve) -> Result<f64, NodeError> {
    let t = finite_parameter(*s.item::<f64>(input)?, "t")?;
    let d = curve.domain();
    if !d.contains(t) {
        return Err(format!(
            "input t: parameter {t} is outside the curve's domain {} to {}",
            d.t0, d.t1
        )
        .into());
    }
    Ok(t)
}

/// The parameters dividing the curve into `count` pieces of equal length (input N).
fn division(s: &Solve<'_>, curve: &Curve, input: usize) -> Result<Vec<f64>, NodeError> {
    let count: i64 = *s.item(input)?;
    if count < 1 {
        return Err(format!("input N: count {count} is below 1 segment").into());
    }
    let count = match usize::try_from(count) {
        Ok(n) if n <= MAX_DIVISIONS => n,
        _ => return Err(format!("input N: count {count} is more than {MAX_DIVISIONS}").into()),
    };
    Ok(curve.divide_by_count(count)?)
}

fn count_port() -> Port {
    Port::new("Count", "N", DataType::Integer)
        .default_value(10i64)
        .doc("Number of segments, at least 1. Default 10.")
}

fn frames_outputs(node: NodeType) -> NodeType {
    node.output(
        Port::new("Frames", "F", DataType::Plane)
            .list()
            .doc("The frames, in order along the curve."),
    )
    .output(
        Port::new("Parameters", "t", DataType::Number)
            .list()
            .doc("Curve parameters of the frames."),
    )
}

/// Curve Frame \[Frame\]: the curvature frame at a parameter.
pub fn curve_frame() -> NodeType {
    NodeType::new(CURVE_FRAME, "Curve Frame", "Frame", "Curve")
        .subcategory("Analysis")
        .gh_guid("6b2a5853-07aa-4329-ba84-0a5d46b51dbd")
        .description(
            "The frame of a curve at a parameter (Rhino's FrameAt): origin on the curve, x axis \
             along the unit tangent, y axis towards the centre of curvature, z axis their cross \
             product (the binormal). Where the curve is straight the y axis is the \
             perpendicular Rhino picks for a plane from its normal. The parameter must lie on \
             the domain.",
        )
        .input(curve_port())
        .input(parameter_port())
        .output(Port::new("Frame", "F", DataType::Plane).doc("The curve frame at t."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let t = parameter_in(s, 1, &curve)?;
            let frame = curve
                .frame_at(t)
                .ok_or_else(|| NodeError(format!("the curve has no tangent at {t}")))?;
            s.set(0, frame);
            Ok(())
        })
}

/// Perp Frame \[PFrame\]: the rotation-minimizing frame at a parameter.
pub fn perp_frame() -> NodeType {
    NodeType::new(PERP_FRAME, "Perp Frame", "PFrame", "Curve")
        .subcategory("Analysis")
        .gh_guid("69f3e5ee-4770-44b3-8851-ae10ae555398")
        .description(
            "The perpendicular (zero-twisting) frame of a curve at a parameter: origin on the \
             curve, z axis along the unit tangent (the outgoing one at a kink), x axis carried \
             from the curve's start without turning about the tangent (a rotation-minimizing \
             frame), y axis z × x. The first frame's x axis points towards the centre of \
             curvature; on a planar curve that starts straight it lies in the curve's plane. \
             The same frame as Perp Frames gives at that parameter. The parameter must lie on \
             the domain.",
        )
        .input(curve_port())
        .input(parameter_port())
        .output(Port::new("Frame", "F", DataType::Plane).doc("The perpendicular frame at t."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let t = parameter_in(s, 1, &curve)?;
            s.set(0, curve.perpendicular_frame_at(t)?);
            Ok(())
        })
}

/// Curve Frames \[Frames\]: curvature frames at equal lengths along a curve.
pub fn curve_frames() -> NodeType {
    frames_outputs(
        NodeType::new(CURVE_FRAMES, "Curve Frames", "Frames", "Curve")
            .subcategory("Division")
            .gh_guid("0e94542a-2e46-4793-9f98-2200b06b28f4")
            .description(
                "Curve frames (x along the tangent, y towards the centre of curvature, as Curve \
                 Frame) at the points that divide a curve into N pieces of equal length: N + 1 \
                 frames on an open curve, N on a closed one, as Divide Curve.",
            )
            .input(curve_port())
            .input(count_port()),
    )
    .solve(|s| {
        let curve = curve_input(s, 0)?;
        let ts = division(s, &curve, 1)?;
        let frames = ts
            .iter()
            .map(|&t| {
                curve
                    .frame_at(t)
                    .ok_or_else(|| NodeError(format!("the curve has no tangent at {t}")))
            })
            .collect::<Result<Vec<Plane>, _>>()?;
        s.set_list(0, frames);
        s.set_list(1, ts);
        Ok(())
    })
}

/// Perp Frames \[PFrames\]: perpendicular frames at equal lengths along a curve.
pub fn perp_frames() -> NodeType {
    frames_outputs(
        NodeType::new(PERP_FRAMES, "Perp Frames", "PFrames", "Curve")
            .subcategory("Division")
            .gh_guid("983c7600-980c-44da-bc53-c804067f667f")
            .description(
                "Perpendicular frames (z along the tangent) at the points that divide a curve \
                 into N pieces of equal length: N + 1 frames on an open curve, N on a closed one, \
                 as Divide Curve. Aligned, the x axes are carried along the curve without \
                 turning about it (rotation-minimizing frames, the same as Perp Frame at each \
                 parameter); not aligned, each frame is found on its own with x towards the \
                 centre of curvature, so frames flip where the curve changes its side of \
                 bending.",
            )
            .input(curve_port())
            .input(count_port())
            .input(
                Port::new("Align", "A", DataType::Boolean)
                    .default_value(true)
                    .doc("Carry the frames along the curve (true, the default) or find each one alone."),
            ),
    )
    .solve(|s| {
        let curve = curve_input(s, 0)?;
        let ts = division(s, &curve, 1)?;
        let align: bool = *s.item(2)?;
        let frames = if align {
            curve.perpendicular_frames(&ts)?
        } else {
            ts.iter()
                .map(|&t| curve.curvature_perpendicular_frame_at(t))
                .collect::<Result<Vec<Plane>, _>>()?
        };
        s.set_list(0, frames);
        s.set_list(1, ts);
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, TAU};

    use locus_kernel::{Circle, Line, NurbsCurve, Point3, Polyline, Vector3};
    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::curve::test_support::*;

    fn planes(tree: &DataTree) -> Vec<Plane> {
        all(tree)
    }

    fn near(a: Vector3, b: Vector3) -> bool {
        (a - b).length() < 1e-9
    }

    #[test]
    fn curve_frame_on_a_circle_points_inwards() {
        let circle = Circle::new(Plane::WORLD_XY, 2.0).unwrap();
        let r = NodeCall::new(&curve_frame())
            .input(curve_tree(circle))
            .input(DataTree::from_item(FRAC_PI_2))
            .run();
        let f: Plane = only(&r, 0);
        assert!(f.origin.distance(Point3::new(0.0, 2.0, 0.0)) < 1e-12);
        assert!(near(f.x_axis, -Vector3::X) && near(f.y_axis, -Vector3::Y));
        assert!(near(f.z_axis, Vector3::Z));
    }

    #[test]
    fn perp_frame_has_the_tangent_as_normal() {
        let line = Line::new(Point3::ORIGIN, Point3::new(0.0, 0.0, 4.0));
        let r = NodeCall::new(&perp_frame())
            .input(curve_tree(line))
            .input(DataTree::from_item(1.0))
            .run();
        let f: Plane = only(&r, 0);
        assert_eq!(f.origin, Point3::new(0.0, 0.0, 1.0));
        assert_eq!((f.x_axis, f.z_axis), (Vector3::X, Vector3::Z));
    }

    #[test]
    fn perp_frames_around_a_circle() {
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let r = NodeCall::new(&perp_frames())
            .input(curve_tree(circle))
            .input(DataTree::from_item(4i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let frames = planes(&r.outputs[0]);
        assert_eq!(
            numbers(&r.outputs[1]),
            vec![0.0, FRAC_PI_2, TAU / 2.0, 3.0 * FRAC_PI_2]
        );
        // A closed curve gives N frames; each has z along the tangent and y along the plane
        // normal.
        assert_eq!(frames.len(), 4);
        for f in &frames {
            assert!(near(f.y_axis, Vector3::Z));
            assert!(f.x_axis.dot(f.origin.to_vector()) < -0.999_999);
        }
    }

    #[test]
    fn aligned_and_unaligned_frames_differ_past_an_inflection() {
        // An S curve in the XY plane: aligned frames keep y along the plane normal, frames
        // found alone flip it where the bending changes side.
        let s_curve = NurbsCurve::create(
            &[
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
                Point3::new(2.0, 0.0, 0.0),
                Point3::new(3.0, -1.0, 0.0),
                Point3::new(4.0, 0.0, 0.0),
            ],
            3,
            false,
        )
        .unwrap();
        let run = |align: bool| {
            let r = NodeCall::new(&perp_frames())
                .input(curve_tree(s_curve.clone()))
                .input(DataTree::from_item(6i64))
                .input(DataTree::from_item(align))
                .run();
            planes(&r.outputs[0])
        };
        let aligned = run(true);
        assert_eq!(aligned.len(), 7);
        let first = aligned[0].y_axis;
        assert!(aligned.iter().all(|f| near(f.y_axis, first)));
        let alone = run(false);
        assert!(near(alone[0].y_axis, first));
        assert!(near(alone[6].y_axis, -first));
    }

    #[test]
    fn curve_frames_on_a_polyline() {
        let l = Polyline::new(vec![
            Point3::ORIGIN,
            Point3::new(2.0, 0.0, 0.0),
            Point3::new(2.0, 2.0, 0.0),
        ])
        .unwrap();
        let r = NodeCall::new(&curve_frames())
            .input(curve_tree(l))
            .input(DataTree::from_item(2i64))
            .run();
        let frames = planes(&r.outputs[0]);
        assert_eq!(frames.len(), 3);
        assert!(near(frames[0].x_axis, Vector3::X));
        assert!(near(frames[2].x_axis, Vector3::Y));
    }

    #[test]
    fn bad_input_is_an_error() {
        let line = Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0));
        for node in [perp_frame(), curve_frame()] {
            let r = NodeCall::new(&node)
                .input(curve_tree(line))
                .input(DataTree::from_item(5.0))
                .run();
            assert_error(&r, "outside");
            let r = NodeCall::new(&node)
                .input(curve_tree(line))
                .input(DataTree::from_item(f64::NAN))
                .run();
            assert_error(&r, "not a finite");
        }
        for node in [perp_frames(), curve_frames()] {
            let r = NodeCall::new(&node)
                .input(curve_tree(line))
                .input(DataTree::from_item(0i64))
                .run();
            assert_error(&r, "input N");
        }
        let r = NodeCall::new(&perp_frames())
            .input(DataTree::from_item(3.0))
            .run();
        assert_error(&r, "input C");
    }
}
