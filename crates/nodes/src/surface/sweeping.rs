//! Surface › Freeform: Pipe and Sweep1, profiles carried along a rail on its perpendicular
//! frames (the kernel's `brep/sweep.rs` and `brep/pipe.rs`).
//!
//! Straight pieces of a rail and arcs give exact surfaces; other pieces are fitted within
//! [`SWEEP_TOLERANCE`] (a surface point lies within it of the exact sweep). Faces are joined
//! within the same distance.

use locus_kernel::{Brep, Curve, PipeCaps, SweepMiter};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

use super::brep::surface_node;
use crate::curve::{curve_input, valid_curve};

/// Id of [`pipe`].
pub const PIPE: &str = "surface.pipe";
/// Id of [`sweep1`].
pub const SWEEP1: &str = "surface.sweep1";

/// How far a fitted sweep or pipe may stray from the exact one: 1e-6 model units, a thousandth
/// of Rhino's default document tolerance, so that areas and volumes agree with the exact
/// surface's to about a millionth.
pub const SWEEP_TOLERANCE: f64 = 1e-6;

/// Registers Pipe and Sweep1.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(pipe());
    registry.register(sweep1());
}

/// Pipe \[Pipe\]: a circle swept along a rail, capped.
pub fn pipe() -> NodeType {
    surface_node(PIPE, "Pipe", "Pipe", "Freeform")
        .gh_guid("c277f778-6fdf-4890-8f78-347efb23c406")
        .description(
            "Creates a pipe around a rail curve: a circle of the radius, centred on the rail's \
             start and perpendicular to it, carried along the rail without turning about it \
             (rotation-minimizing frames). Each kink-free piece of the rail is one face, \
             mitred at kinks (both pieces end on the plane bisecting the kink); straight \
             pieces give exact cylinders and arcs exact tori, other pieces are fitted within \
             1e-6. A closed rail gives a closed tube; an open rail's ends are open (caps 0), \
             closed by planar discs (1, the default) or by hemispheres (2). A radius too large \
             for the rail's bends makes a self-intersecting pipe, which is not checked.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("The rail curve."))
        .input(
            Port::new("Radius", "R", DataType::Number)
                .default_value(1.0)
                .doc("The pipe radius, positive. Default 1."),
        )
        .input(
            Port::new("Caps", "E", DataType::Integer)
                .default_value(1i64)
                .doc("End caps: 0 none, 1 flat (the default), 2 round."),
        )
        .output(
            Port::new("Pipe", "P", DataType::Brep)
                .list()
                .doc("The pipe: one B-rep, closed when capped or around a closed rail."),
        )
        .solve(|s| {
            let rail = curve_input(s, 0)?;
            let radius: f64 = *s.item(1)?;
            if !(radius > 0.0 && radius.is_finite()) {
                return Err(format!("input R: the radius must be positive, got {radius}").into());
            }
            let caps = match *s.item::<i64>(2)? {
                0 => PipeCaps::None,
                1 => PipeCaps::Flat,
                2 => PipeCaps::Round,
                other => {
                    return Err(format!(
                        "input E: cap type {other} is not 0 (none), 1 (flat) or 2 (round)"
                    )
                    .into());
                }
            };
            let breps = Brep::pipe(&rail, radius, caps, SWEEP_TOLERANCE)?;
            s.set_list(0, breps.into_iter().map(Shared::new).collect());
            Ok(())
        })
}

/// Sweep1 \[Swp1\]: section curves swept along one rail.
pub fn sweep1() -> NodeType {
    surface_node(SWEEP1, "Sweep1", "Swp1", "Freeform")
        .gh_guid("bb6666e7-d0f4-41ec-a257-df2371619f13")
        .description(
            "Sweeps section curves along a rail. Each section sits at the rail point closest to \
             its centre (the average of points along it) and is carried along the rail without \
             turning about it (rotation-minimizing frames); between sections their control \
             points blend smoothly (cubic Hermite pieces in the rail parameter), before the \
             first and after the last they stay as that section. Sections are made compatible \
             (the highest degree, merged knots). Each kink-free piece of the rail is one face \
             (u along the sections, v along the rail on its parameters), exact on straight \
             pieces and arcs for one section, else fitted within 1e-6. At kinks, Miter 0 \
             (default) keeps the sections square to each piece, so the pieces stay apart; 1 \
             (trim) ends both pieces on the plane bisecting the kink; 2 (rotate) turns the \
             section onto that plane. Faces that meet are joined.",
        )
        .input(Port::new("Rail", "R", DataType::Curve).doc("The rail curve."))
        .input(
            Port::new("Sections", "S", DataType::Curve)
                .list()
                .doc("The section curves; nulls are left out with a warning."),
        )
        .input(
            Port::new("Miter", "M", DataType::Integer)
                .default_value(0i64)
                .doc("At kinks of the rail: 0 none (the default), 1 trim, 2 rotate."),
        )
        .output(
            Port::new("Brep", "S", DataType::Brep)
                .list()
                .doc("The sweep: one B-rep per group of faces that join."),
        )
        .solve(|s| {
            let rail = curve_input(s, 0)?;
            let list = s.list::<Shared<Curve>>(1)?;
            let mut sections = Vec::with_capacity(list.len());
            let mut nulls = 0;
            for (k, c) in list.iter().enumerate() {
                match c {
                    Some(c) => {
                        valid_curve(c, &format!("S (section {k})"))?;
                        sections.push((**c).clone());
                    }
                    None => nulls += 1,
                }
            }
            if nulls > 0 {
                s.warning(format!("input S: {nulls} null item(s) left out"));
            }
            if sections.is_empty() {
                return Err(NodeError::from("input S: no section curves"));
            }
            let miter = match *s.item::<i64>(2)? {
                0 => SweepMiter::None,
                1 => SweepMiter::Trim,
                2 => SweepMiter::Rotate,
                other => {
                    return Err(format!(
                        "input M: miter type {other} is not 0 (none), 1 (trim) or 2 (rotate)"
                    )
                    .into());
                }
            };
            let breps = Brep::sweep(&rail, &sections, miter, SWEEP_TOLERANCE)?;
            s.set_list(0, breps.into_iter().map(Shared::new).collect());
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use locus_kernel::{Circle, Line, Plane, Point3, Polyline};
    use locus_runtime::{DataTree, NodeCall, Value};

    use super::*;
    use crate::test_support::*;

    fn line_rail() -> Value {
        Value::Line(Line::new(Point3::ORIGIN, Point3::new(0.0, 0.0, 2.0)))
    }

    fn breps(r: &locus_runtime::NodeCallResult) -> Vec<Shared<Brep>> {
        all(&r.outputs[0])
    }

    #[test]
    fn pipe_caps() {
        let run = |caps: i64| {
            NodeCall::new(&pipe())
                .input(DataTree::from_item(line_rail()))
                .input(DataTree::from_item(0.5))
                .input(DataTree::from_item(caps))
                .run()
        };
        let open = breps(&run(0));
        assert!(!open[0].is_solid());
        assert!((open[0].area().unwrap() - 2.0 * PI * 0.5 * 2.0).abs() < 1e-12);
        let flat = breps(&run(1));
        assert!((flat[0].volume().unwrap() - PI * 0.25 * 2.0).abs() < 1e-12);
        let round = breps(&run(2));
        let v = PI * 0.25 * 2.0 + 4.0 / 3.0 * PI * 0.125;
        assert!((round[0].volume().unwrap() - v).abs() < 1e-11);
        // The default caps are flat, the default radius 1.
        let r = NodeCall::new(&pipe())
            .input(DataTree::from_item(line_rail()))
            .run();
        assert_clean(&r);
        assert!((breps(&r)[0].volume().unwrap() - PI * 2.0).abs() < 1e-12);
    }

    #[test]
    fn sweep_of_a_square_along_an_l() {
        let rail = Polyline::new(vec![
            Point3::ORIGIN,
            Point3::new(0.0, 0.0, 2.0),
            Point3::new(2.0, 0.0, 2.0),
        ])
        .unwrap();
        let square = Polyline::new(vec![
            Point3::new(-0.5, -0.5, 0.0),
            Point3::new(0.5, -0.5, 0.0),
            Point3::new(0.5, 0.5, 0.0),
            Point3::new(-0.5, 0.5, 0.0),
            Point3::new(-0.5, -0.5, 0.0),
        ])
        .unwrap();
        let run = |miter: i64| {
            NodeCall::new(&sweep1())
                .input(DataTree::from_item(Shared::new(Curve::from(rail.clone()))))
                .input(DataTree::from_item(Shared::new(Curve::from(
                    square.clone(),
                ))))
                .input(DataTree::from_item(miter))
                .run()
        };
        let trimmed = breps(&run(1));
        assert_eq!(trimmed.len(), 1);
        // Mitred square tube: the lateral area is the perimeter times the axis length 4.
        assert!((trimmed[0].area().unwrap() - 16.0).abs() < 1e-9);
        assert_eq!(breps(&run(0)).len(), 2);
    }

    #[test]
    fn bad_input_is_an_error() {
        let r = NodeCall::new(&pipe())
            .input(DataTree::from_item(line_rail()))
            .input(DataTree::from_item(-1.0))
            .run();
        assert_error(&r, "input R");
        let r = NodeCall::new(&pipe())
            .input(DataTree::from_item(line_rail()))
            .input(DataTree::from_item(1.0))
            .input(DataTree::from_item(3i64))
            .run();
        assert_error(&r, "input E");
        let circle = Shared::new(Curve::from(Circle::new(Plane::WORLD_XY, 0.5).unwrap()));
        let r = NodeCall::new(&sweep1())
            .input(DataTree::from_item(line_rail()))
            .input(DataTree::from_item(circle.clone()))
            .input(DataTree::from_item(7i64))
            .run();
        assert_error(&r, "input M");
        let r = NodeCall::new(&sweep1())
            .input(DataTree::from_item(line_rail()))
            .input(DataTree::from_list(vec![circle.clone(), circle]))
            .run();
        assert_error(&r, "same place");
        let r = NodeCall::new(&sweep1())
            .input(DataTree::from_item(Value::Number(1.0)))
            .input(DataTree::from_item(line_rail()))
            .run();
        assert_error(&r, "input R");
    }
}
