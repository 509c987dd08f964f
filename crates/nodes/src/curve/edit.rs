//! Curve › Util, editing: Join Curves, Explode and Offset Curve.
//!
//! Joining and offsetting work within [`DOCUMENT_TOLERANCE`] (0.001 model units, the absolute
//! tolerance of Rhino's default templates), which stands in for Grasshopper's document
//! tolerance.

use locus_kernel::tolerance::DOCUMENT_TOLERANCE;
use locus_kernel::{Curve, OffsetCorners, Plane, Point3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use super::{curve_from_value, curve_input, input_name, valid_curve};

/// Id of [`join_curves`].
pub const JOIN_CURVES: &str = "curve.join_curves";
/// Id of [`explode`].
pub const EXPLODE: &str = "curve.explode";
/// Id of [`offset_curve`].
pub const OFFSET_CURVE: &str = "curve.offset_curve";

/// Registers the editing nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [join_curves(), explode(), offset_curve()] {
        registry.register(t);
    }
}

fn util(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Curve").subcategory("Util")
}

/// The curves of list input `input` (lines, circles and arcs as curves), nulls left out with a
/// warning.
pub(crate) fn curve_list(s: &mut Solve<'_>, input: usize) -> Result<Vec<Shared<Curve>>, NodeError> {
    let name = input_name(s, input);
    let Some(branch) = s.branch(input) else {
        return Ok(Vec::new());
    };
    let mut out = Vec::with_capacity(branch.len());
    let mut nulls = 0;
    for (i, value) in branch.values().enumerate() {
        let Some(value) = value else {
            nulls += 1;
            continue;
        };
        let curve = curve_from_value(&value).ok_or_else(|| {
            format!(
                "input {name}: item {i}, a {}, is not a curve",
                value.data_type()
            )
        })?;
        valid_curve(&curve, &format!("{name} (item {i})"))?;
        out.push(curve);
    }
    if nulls > 0 {
        s.warning(format!("input {name}: {nulls} null item(s) left out"));
    }
    Ok(out)
}

/// Join Curves \[Join\]: curves joined end to end.
pub fn join_curves() -> NodeType {
    util(JOIN_CURVES, "Join Curves", "Join")
        .gh_guid("8073a420-6bec-49e3-9b18-367f6fd76ac3")
        .description(
            "Joins curves whose ends meet within 0.001 model units (the document tolerance) into \
             as few curves as possible, reversing curves where needed unless directions are \
             preserved. Chains grow greedily from the first unused curve, at its end and then \
             its start, by the nearest matching end; closed curves stay alone. A chain of lines \
             and polylines becomes a polyline; any other chain one NURBS curve of the highest \
             degree among its pieces, with a full-multiplicity knot at each joint (Explode takes \
             it apart again). A single curve passes unchanged.",
        )
        .input(
            Port::new("Curves", "C", DataType::Curve)
                .doc("Curves to join. Nulls are left out.")
                .list(),
        )
        .input(
            Port::new("Preserve", "P", DataType::Boolean)
                .doc("Preserve the direction of the input curves (no curve is reversed). Default false.")
                .default_value(false),
        )
        .output(
            Port::new("Curves", "C", DataType::Curve)
                .doc("The joined curves, in the order of their first input curves.")
                .list(),
        )
        .solve(|s| {
            let curves: Vec<Curve> = curve_list(s, 0)?.iter().map(|c| (**c).clone()).collect();
            let preserve = *s.item::<bool>(1)?;
            let joined = Curve::join(&curves, DOCUMENT_TOLERANCE, preserve)?;
            s.set_list(0, joined.into_iter().map(Shared::new).collect());
            Ok(())
        })
}

/// Explode \[Explode\]: the segments and vertices of a curve.
pub fn explode() -> NodeType {
    util(EXPLODE, "Explode", "Explode")
        .gh_guid("afb96615-c59a-45c9-9cac-e27acb1c7ca0")
        .description(
            "Explodes a curve into its segments: a polyline into its lines; a NURBS curve, when \
             recursive, into its pieces between kinks (knots of full multiplicity where the \
             tangent turns by more than 1°, as at the joints Join Curves makes), straight \
             two-point pieces as lines. Lines, circles and arcs, and NURBS curves when not \
             recursive, give themselves (locus has no polycurves: a joined curve is one NURBS \
             curve, so Recursive decides whether it comes apart). The vertices are the segments' \
             start points and, on an open curve, the last end point.",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to explode."))
        .input(
            Port::new("Recursive", "R", DataType::Boolean)
                .doc("Explode NURBS curves at their kinks too. Default true.")
                .default_value(true),
        )
        .output(
            Port::new("Segments", "S", DataType::Curve)
                .doc("The segments, in order along the curve.")
                .list(),
        )
        .output(
            Port::new("Vertices", "V", DataType::Point)
                .doc("The segments' ends, each once.")
                .list(),
        )
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let recursive = *s.item::<bool>(1)?;
            let segments = curve.explode(recursive)?;
            let mut vertices: Vec<Point3> = segments.iter().map(Curve::start_point).collect();
            if !curve.is_closed()
                && let Some(last) = segments.last()
            {
                vertices.push(last.end_point());
            }
            s.set_list(0, segments.into_iter().map(Shared::new).collect());
            s.set_list(1, vertices);
            Ok(())
        })
}

/// Grasshopper's corner style number: 0 none, 1 sharp, 2 round, 3 smooth, 4 chamfer.
fn corners_from(style: i64) -> Result<OffsetCorners, NodeError> {
    Ok(match style {
        0 => OffsetCorners::None,
        1 => OffsetCorners::Sharp,
        2 => OffsetCorners::Round,
        3 => OffsetCorners::Smooth,
        4 => OffsetCorners::Chamfer,
        _ => {
            return Err(format!(
                "corner style {style} is not 0 (none), 1 (sharp), 2 (round), 3 (smooth) or 4 \
                 (chamfer)"
            )
            .into());
        }
    })
}

/// Offset Curve \[Offset\]: a curve offset in a plane.
pub fn offset_curve() -> NodeType {
    util(OFFSET_CURVE, "Offset Curve", "Offset")
        .gh_guid("1a38d325-98de-455c-93f1-bca431bc1243")
        .description(
            "Offsets a curve by a distance in a plane: every point moves along the tangent \
             crossed with the plane's normal, to the right of the direction of travel, so a \
             counter-clockwise circle grows for a positive distance. Lines, polylines, circles \
             and arcs (NURBS ones too) are offset exactly (a circle changes its radius; an \
             offset that collapses it is an error); polyline corners on the outside of a turn \
             are filled as the Corners input says and trimmed on the inside. Other curves are \
             approximated within 0.001 model units by cubic interpolation of sampled offset \
             points, piece by piece between kinks, the pieces trimmed where they cross on the \
             inside of a kink. Warns where the offset intersects itself locally (a segment \
             trimmed past its length, a distance beyond the radius of curvature).",
        )
        .input(Port::new("Curve", "C", DataType::Curve).doc("Curve to offset."))
        .input(
            Port::new("Distance", "D", DataType::Number)
                .doc("Offset distance; negative offsets to the other side. Default 1.")
                .default_value(1.0),
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("Plane to offset in (its normal decides the side). Default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("Corners", "Cr", DataType::Integer)
                .doc(
                    "Corner fill: 0 none (as sharp), 1 sharp, 2 round, 3 smooth, 4 chamfer. \
                     Default 1.",
                )
                .default_value(1i64),
        )
        .output(Port::new("Curve", "C", DataType::Curve).doc("The offset curve."))
        .solve(|s| {
            let curve = curve_input(s, 0)?;
            let distance = *s.item::<f64>(1)?;
            let plane = *s.item::<Plane>(2)?;
            let corners = corners_from(*s.item::<i64>(3)?)?;
            let offset = curve.offset(distance, &plane, corners, DOCUMENT_TOLERANCE)?;
            for w in offset.warnings {
                s.warning(w);
            }
            s.set(0, Shared::new(offset.curve));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Circle, Line, Polyline};
    use locus_runtime::{Branch, DataTree, Level, NodeCall, TreePath, Value};

    use super::*;
    use crate::curve::test_support::*;

    fn p(x: f64, y: f64) -> Point3 {
        Point3::new(x, y, 0.0)
    }

    fn lines(points: &[(Point3, Point3)]) -> DataTree {
        DataTree::from_list(
            points
                .iter()
                .map(|&(a, b)| Value::Line(Line::new(a, b)))
                .collect::<Vec<_>>(),
        )
    }

    #[test]
    fn join_three_sides_of_a_square() {
        let r = NodeCall::new(&join_curves())
            .input(lines(&[
                (p(0.0, 0.0), p(1.0, 0.0)),
                (p(1.0, 1.0), p(1.0, 0.0)),
                (p(1.0, 1.0), p(0.0, 1.0)),
            ]))
            .run();
        let out = curves(&r.outputs[0]);
        assert_eq!(out.len(), 1);
        assert!(matches!(*out[0], Curve::Polyline { .. }));
        assert_eq!(out[0].length(), 3.0);
        assert_eq!(out[0].end_point(), p(0.0, 1.0));
        // Preserving direction, the reversed middle side joins neither neighbour.
        let r = NodeCall::new(&join_curves())
            .input(lines(&[
                (p(0.0, 0.0), p(1.0, 0.0)),
                (p(1.0, 1.0), p(1.0, 0.0)),
                (p(1.0, 1.0), p(0.0, 1.0)),
            ]))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(curves(&r.outputs[0]).len(), 3);
    }

    #[test]
    fn join_bad_input() {
        let r = NodeCall::new(&join_curves())
            .input(DataTree::from_list(vec![Value::Number(1.0)]))
            .run();
        let e = single_error(&r);
        assert!(
            e.contains("not a curve") || e.contains("invalid cast"),
            "{e}"
        );
        let r = NodeCall::new(&join_curves())
            .input({
                let mut branch = Branch::new(DataType::Line);
                branch.push(Line::new(p(0.0, 0.0), p(1.0, 0.0)));
                branch.push_null();
                DataTree::from_branches([(TreePath::zero(), branch)])
            })
            .run();
        assert_eq!(curves(&r.outputs[0]).len(), 1);
        assert_eq!(messages(&r, Level::Warning).len(), 1);
    }

    #[test]
    fn explode_a_closed_polyline() {
        let square = Polyline::new(vec![
            p(0.0, 0.0),
            p(2.0, 0.0),
            p(2.0, 2.0),
            p(0.0, 2.0),
            p(0.0, 0.0),
        ])
        .unwrap();
        let r = NodeCall::new(&explode()).input(curve_tree(square)).run();
        let segments = curves(&r.outputs[0]);
        assert_eq!(segments.len(), 4);
        assert!(segments.iter().all(|s| s.length() == 2.0));
        assert_eq!(
            points(&r.outputs[1]),
            vec![p(0.0, 0.0), p(2.0, 0.0), p(2.0, 2.0), p(0.0, 2.0)]
        );
        let circle = Circle::new(Plane::WORLD_XY, 1.0).unwrap();
        let r = NodeCall::new(&explode()).input(curve_tree(circle)).run();
        assert_eq!(curves(&r.outputs[0]).len(), 1);
        assert_eq!(points(&r.outputs[1]).len(), 1);
        let r = NodeCall::new(&explode())
            .input(DataTree::from_item(Point3::ORIGIN))
            .run();
        assert!(!messages(&r, Level::Error).is_empty());
    }

    #[test]
    fn offset_a_circle_and_a_square() {
        let circle = Circle::new(Plane::WORLD_XY, 5.0).unwrap();
        let r = NodeCall::new(&offset_curve())
            .input(curve_tree(circle))
            .run();
        let out = curves(&r.outputs[0]);
        let Curve::Circle { circle: c, .. } = &*out[0] else {
            panic!("{out:?}")
        };
        assert_eq!(c.radius, 6.0);
        let r = NodeCall::new(&offset_curve())
            .input(curve_tree(circle))
            .input(DataTree::from_item(-6.0))
            .run();
        assert!(single_error(&r).contains("collapses"));
        let square = Polyline::new(vec![
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(1.0, 1.0),
            p(0.0, 1.0),
            p(0.0, 0.0),
        ])
        .unwrap();
        let r = NodeCall::new(&offset_curve())
            .input(curve_tree(square.clone()))
            .input(DataTree::from_item(1.0))
            .input(DataTree::from_item(Plane::WORLD_XY))
            .input(DataTree::from_item(4i64))
            .run();
        let out = curves(&r.outputs[0]);
        assert!((out[0].length() - (4.0 + 4.0 * 2f64.sqrt())).abs() < 1e-12);
        let r = NodeCall::new(&offset_curve())
            .input(curve_tree(square.clone()))
            .input(DataTree::from_item(-0.75))
            .run();
        assert!(!messages(&r, Level::Warning).is_empty());
        let r = NodeCall::new(&offset_curve())
            .input(curve_tree(square))
            .input(DataTree::from_item(1.0))
            .input(DataTree::from_item(Plane::WORLD_XY))
            .input(DataTree::from_item(7i64))
            .run();
        assert!(single_error(&r).contains("corner style 7"));
    }
}
