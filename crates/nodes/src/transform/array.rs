//! Transform › Array: Linear, Rectangular, Polar and Box Array, copies of geometry under a
//! sequence of transforms.
//!
//! Each node works per geometry item and writes, for that item, one list of copies and one
//! list of the transforms that made them, in the same order; the lists go to the branch of the
//! item (`{path;i}`), as Grasshopper's list outputs of item-wise components do. The first copy
//! is always the identity (the geometry where it was). Leaving the geometry unconnected writes
//! only the transforms. Geometry is transformed by [`transform_value`] (the Transform nodes'
//! one dispatch on value types); a copy that cannot be made is an error for that item and a
//! null in its place, so that copies and transforms stay aligned.
//!
//! - *Linear*: copy `k` moved by `k·D`.
//! - *Rectangular*: copy `(i, j)` moved by `i·a + j·b`, `a` and `b` the rectangle's first and
//!   second sides (so the rectangle's size is the spacing and its axes the directions); `i`
//!   runs over X and, for each `i`, `j` over Y.
//! - *Polar*: copy `k` rotated about the plane's normal through its origin by `k·A/N` when
//!   the sweep `A` is a whole turn (the copies do not repeat the first), else by `k·A/(N−1)`,
//!   so that the last copy lies at the end of the sweep.
//! - *Box*: copy `(i, j, k)` moved by `i·x + j·y + k·z`, the box's edges along its plane's
//!   axes, `i` outermost and `k` innermost.
//!
//! Every array holds at most [`MAX_ARRAY_COPIES`] copies; more is an error on the item.

use std::f64::consts::TAU;

use locus_kernel::{Curve, OrientedBox, Plane, Transform, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve};

use super::{apply::transform_value, geometry_input, transform_node};
use crate::params::shapes::not_a_rectangle;

/// Id of [`linear_array`].
pub const LINEAR_ARRAY: &str = "transform.linear_array";
/// Id of [`rectangular_array`].
pub const RECTANGULAR_ARRAY: &str = "transform.rectangular_array";
/// Id of [`polar_array`].
pub const POLAR_ARRAY: &str = "transform.polar_array";
/// Id of [`box_array`].
pub const BOX_ARRAY: &str = "transform.box_array";

/// The most copies one array may hold (100,000): copies of B-reps are heavy, and a typo in a
/// count is an error on the node rather than an exhausted machine.
pub const MAX_ARRAY_COPIES: usize = 100_000;

/// How close to a whole turn (in radians) a polar sweep must be for its copies to divide it
/// into `N` equal steps rather than `N − 1`: 1e-9.
pub const WHOLE_TURN_TOLERANCE: f64 = 1e-9;

/// Registers the Array nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        linear_array(),
        rectangular_array(),
        polar_array(),
        box_array(),
    ] {
        registry.register(t);
    }
}

fn array(id: &str, name: &str, nickname: &str) -> NodeType {
    transform_node(id, name, nickname, "Array").input(geometry_input("array"))
}

fn outputs(node: NodeType) -> NodeType {
    node.output(
        Port::new("Geometry", "G", DataType::Generic)
            .list()
            .doc("The copies of the geometry, one list per geometry item, the first in place."),
    )
    .output(
        Port::new("Transform", "X", DataType::Transform)
            .list()
            .doc("The transform of each copy, in the order of the copies."),
    )
}

fn count_port(name: &str, nickname: &str, what: &str, default: i64) -> Port {
    Port::new(name, nickname, DataType::Integer)
        .doc(&format!(
            "The number of {what}, 0 or more (0 makes no copies); default {default}."
        ))
        .default_value(default)
}

/// The counts of inputs `inputs` (each 0 or more), their product within [`MAX_ARRAY_COPIES`].
fn counts<const N: usize>(
    s: &Solve<'_>,
    inputs: [(usize, &str); N],
) -> Result<[usize; N], NodeError> {
    let mut out = [0_usize; N];
    let mut total = 1_usize;
    for (k, (input, what)) in inputs.into_iter().enumerate() {
        let n = *s.item::<i64>(input)?;
        let n = usize::try_from(n)
            .map_err(|_| NodeError(format!("count {what} must be 0 or more, not {n}")))?;
        total = total.saturating_mul(n);
        out[k] = n;
    }
    if total > MAX_ARRAY_COPIES {
        return Err(NodeError(format!(
            "an array of {} copies is above the limit of {MAX_ARRAY_COPIES}",
            out.iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(" × ")
        )));
    }
    Ok(out)
}

/// Writes the transforms to output 1 and, when geometry arrived at input 0, its copies to
/// output 0 (a null and an error for a copy that cannot be made).
fn finish(s: &mut Solve<'_>, xforms: Vec<Transform>) -> Result<(), NodeError> {
    if let Some(value) = s.value(0) {
        let mut copies = Vec::with_capacity(xforms.len());
        let mut failure = None;
        for xform in &xforms {
            match transform_value(&value, xform) {
                Ok(v) => copies.push(Some(v)),
                Err(e) => {
                    failure.get_or_insert(e.0);
                    copies.push(None);
                }
            }
        }
        s.set_list_values(0, copies);
        if let Some(why) = failure {
            s.error(why);
        }
    }
    s.set_list(1, xforms);
    Ok(())
}

fn finite_vector(v: Vector3, what: &str) -> Result<Vector3, NodeError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(NodeError(format!(
            "{what} has a component that is not finite"
        )))
    }
}

/// Linear Array \[ArrLinear\]: copies along a vector.
pub fn linear_array() -> NodeType {
    outputs(
        array(LINEAR_ARRAY, "Linear Array", "ArrLinear")
            .gh_guid("e87db220-a0a0-4d67-a405-f97fd14b2d7a")
            .description(
                "Creates a linear array of geometry: N copies, copy k moved by k times the \
                 direction D (the first copy stays in place).",
            )
            .input(
                Port::new("Direction", "D", DataType::Vector)
                    .doc(
                        "The step from one copy to the next: direction and spacing. Default \
                         <10, 0, 0>.",
                    )
                    .default_value(Vector3::new(10.0, 0.0, 0.0)),
            )
            .input(count_port("Count", "N", "copies", 10)),
    )
    .solve(|s| {
        let d = finite_vector(*s.item::<Vector3>(1)?, "direction D")?;
        let [n] = counts(s, [(2, "N")])?;
        let xforms = (0..n)
            .map(|k| Transform::translation(d * k as f64))
            .collect();
        finish(s, xforms)
    })
}

/// The first corner and the two sides of a rectangle (a closed polyline of four right-angled
/// sides).
fn rectangle_sides(curve: &Curve) -> Result<(Vector3, Vector3), NodeError> {
    if let Some(why) = not_a_rectangle(curve) {
        return Err(NodeError(format!("cell C is not a rectangle: {why}")));
    }
    let Curve::Polyline { polyline, .. } = curve else {
        return Err("cell C is not a rectangle".into());
    };
    let p = polyline.points();
    Ok((p[1] - p[0], p[3] - p[0]))
}

/// Rectangular Array \[ArrRec\]: copies on a grid of rectangles.
pub fn rectangular_array() -> NodeType {
    outputs(
        array(RECTANGULAR_ARRAY, "Rectangular Array", "ArrRec")
            .gh_guid("e521f7c8-92f4-481c-888b-eea109e3d6e9")
            .description(
                "Creates a rectangular array of geometry: X by Y copies, copy (i, j) moved by i \
                 times the cell's first side and j times its second, so that the cell's size \
                 is the spacing. The copies run over j for each i.",
            )
            .input(Port::new("Cell", "C", DataType::Curve).doc(
                "The array cell, a rectangle: its first side is the step along X, its second \
                 the step along Y.",
            ))
            .input(count_port(
                "X Count",
                "X",
                "copies along the cell's first side",
                5,
            ))
            .input(count_port(
                "Y Count",
                "Y",
                "copies along the cell's second side",
                5,
            )),
    )
    .solve(|s| {
        let (a, b) = rectangle_sides(s.item::<Shared<Curve>>(1)?)?;
        let [nx, ny] = counts(s, [(2, "X"), (3, "Y")])?;
        let mut xforms = Vec::with_capacity(nx * ny);
        for i in 0..nx {
            for j in 0..ny {
                xforms.push(Transform::translation(a * i as f64 + b * j as f64));
            }
        }
        finish(s, xforms)
    })
}

/// The angle between successive copies of a polar array of `n` copies over the sweep `angle`.
pub fn polar_step(angle: f64, n: usize) -> f64 {
    if (angle.abs() - TAU).abs() <= WHOLE_TURN_TOLERANCE || n <= 1 {
        angle / n.max(1) as f64
    } else {
        angle / (n - 1) as f64
    }
}

/// Polar Array \[ArrPolar\]: copies around an axis.
pub fn polar_array() -> NodeType {
    outputs(
        array(POLAR_ARRAY, "Polar Array", "ArrPolar")
            .gh_guid("fca5ad7e-ecac-401d-a357-edda0a251cbc")
            .description(
                "Creates a polar array of geometry: N copies turned about the plane's normal \
                 through its origin, counter-clockwise, spread over the sweep angle A. A whole \
                 turn (2π) is divided into N equal steps; any other sweep into N − 1, so that \
                 the last copy lies at its end.",
            )
            .input(
                Port::new("Plane", "P", DataType::Plane)
                    .doc("The polar plane: the axis is its normal through its origin. Default World XY.")
                    .default_value(Plane::WORLD_XY),
            )
            .input(count_port("Count", "N", "copies", 10))
            .input(
                Port::new("Angle", "A", DataType::Number)
                    .doc("The sweep angle, in radians, counter-clockwise. Default 2π (a whole turn).")
                    .default_value(TAU),
            ),
    )
    .solve(|s| {
        let plane = *s.item::<Plane>(1)?;
        if !plane.is_valid() {
            return Err("plane P is not valid".into());
        }
        let [n] = counts(s, [(2, "N")])?;
        let angle = *s.item::<f64>(3)?;
        if !angle.is_finite() {
            return Err(NodeError(format!(
                "angle A is not a finite number ({angle})"
            )));
        }
        let step = polar_step(angle, n);
        let xforms = (0..n)
            .map(|k| Transform::rotation(step * k as f64, plane.z_axis, plane.origin))
            .collect::<Result<Vec<_>, _>>()?;
        finish(s, xforms)
    })
}

/// The three edges of a box along its plane's axes.
fn box_edges(b: &OrientedBox) -> Result<[Vector3; 3], NodeError> {
    if !b.is_valid() {
        return Err("cell C is not a valid box".into());
    }
    let [sx, sy, sz] = b.sizes();
    let edges = [
        b.plane.x_axis * sx,
        b.plane.y_axis * sy,
        b.plane.z_axis * sz,
    ];
    if edges.iter().any(|e| !e.is_finite()) {
        return Err("cell C has a size that is not finite".into());
    }
    Ok(edges)
}

/// Box Array \[ArrBox\]: copies on a grid of boxes.
pub fn box_array() -> NodeType {
    outputs(
        array(BOX_ARRAY, "Box Array", "ArrBox")
            .gh_guid("9f6f954c-ba7b-4428-bf1e-1768cdff666c")
            .description(
                "Creates a box array of geometry: X by Y by Z copies, copy (i, j, k) moved by \
                 i, j and k times the cell box's edges along its plane's x, y and z axes. The \
                 copies run over k, then j, then i.",
            )
            .input(
                Port::new("Cell", "C", DataType::Box)
                    .doc("The array cell, a box: its sizes along its plane's axes are the steps."),
            )
            .input(count_port(
                "X Count",
                "X",
                "copies along the box's x axis",
                5,
            ))
            .input(count_port(
                "Y Count",
                "Y",
                "copies along the box's y axis",
                5,
            ))
            .input(count_port(
                "Z Count",
                "Z",
                "copies along the box's z axis",
                5,
            )),
    )
    .solve(|s| {
        let [ex, ey, ez] = box_edges(s.item::<OrientedBox>(1)?)?;
        let [nx, ny, nz] = counts(s, [(2, "X"), (3, "Y"), (4, "Z")])?;
        let mut xforms = Vec::with_capacity(nx * ny * nz);
        for i in 0..nx {
            for j in 0..ny {
                for k in 0..nz {
                    xforms.push(Transform::translation(
                        ex * i as f64 + ey * j as f64 + ez * k as f64,
                    ));
                }
            }
        }
        finish(s, xforms)
    })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, PI};

    use locus_kernel::{Interval, Point3, Polyline};
    use locus_runtime::{DataTree, NodeCall, Value};

    use super::*;
    use crate::test_support::{all, assert_error, points};

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    fn close(a: Point3, b: Point3) -> bool {
        (a - b).length() < 1e-12
    }

    fn rectangle(w: f64, h: f64) -> DataTree {
        let poly = Polyline::new(vec![
            p(0.0, 0.0, 0.0),
            p(w, 0.0, 0.0),
            p(w, h, 0.0),
            p(0.0, h, 0.0),
            p(0.0, 0.0, 0.0),
        ])
        .unwrap();
        DataTree::from_item(Shared::new(Curve::from(poly)))
    }

    #[test]
    fn linear_array_copies_each_item_into_its_own_branch() {
        let r = NodeCall::new(&linear_array())
            .input(DataTree::from_list(vec![
                p(0.0, 0.0, 0.0),
                p(0.0, 5.0, 0.0),
            ]))
            .input(DataTree::from_item(Vector3::new(2.0, 0.0, 1.0)))
            .input(DataTree::from_item(3_i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let g = &r.outputs[0];
        assert_eq!(g.branch_count(), 2);
        assert_eq!(g.branches()[1].0.to_string(), "{0;1}");
        assert_eq!(
            points(g),
            [
                p(0.0, 0.0, 0.0),
                p(2.0, 0.0, 1.0),
                p(4.0, 0.0, 2.0),
                p(0.0, 5.0, 0.0),
                p(2.0, 5.0, 1.0),
                p(4.0, 5.0, 2.0)
            ]
        );
        let x: Vec<Transform> = all(&r.outputs[1]);
        assert_eq!(x.len(), 6);
        assert_eq!(x[0], Transform::IDENTITY);
        assert_eq!(x[2], Transform::translation(Vector3::new(4.0, 0.0, 2.0)));
    }

    #[test]
    fn linear_array_without_geometry_writes_only_transforms() {
        let r = NodeCall::new(&linear_array())
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(2_i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert_eq!(r.outputs[0].item_count(), 0);
        let x: Vec<Transform> = all(&r.outputs[1]);
        assert_eq!(x[1], Transform::translation(Vector3::new(10.0, 0.0, 0.0)));
    }

    #[test]
    fn rectangular_array_steps_by_the_cell_sides() {
        let r = NodeCall::new(&rectangular_array())
            .input(DataTree::from_item(p(1.0, 1.0, 0.0)))
            .input(rectangle(2.0, 3.0))
            .input(DataTree::from_item(2_i64))
            .input(DataTree::from_item(3_i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert_eq!(
            points(&r.outputs[0]),
            [
                p(1.0, 1.0, 0.0),
                p(1.0, 4.0, 0.0),
                p(1.0, 7.0, 0.0),
                p(3.0, 1.0, 0.0),
                p(3.0, 4.0, 0.0),
                p(3.0, 7.0, 0.0)
            ]
        );
    }

    #[test]
    fn polar_array_divides_a_whole_turn_by_n_and_a_sweep_by_n_minus_one() {
        let run = |n: i64, angle: f64| {
            NodeCall::new(&polar_array())
                .input(DataTree::from_item(p(1.0, 0.0, 0.0)))
                .skip_input()
                .input(DataTree::from_item(n))
                .input(DataTree::from_item(angle))
                .run()
        };
        let whole = points(&run(4, TAU).outputs[0]);
        let expected = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)];
        assert_eq!(whole.len(), 4);
        for (q, (x, y)) in whole.iter().zip(expected) {
            assert!(close(*q, p(x, y, 0.0)), "{q:?}");
        }
        let half = points(&run(3, PI).outputs[0]);
        assert!(close(half[1], p(0.0, 1.0, 0.0)));
        assert!(close(half[2], p(-1.0, 0.0, 0.0)));
        assert_eq!(polar_step(FRAC_PI_2, 1), FRAC_PI_2);
        assert_error(&run(3, f64::NAN), "angle A is not a finite number");
    }

    #[test]
    fn box_array_runs_k_then_j_then_i() {
        let cell = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        );
        let r = NodeCall::new(&box_array())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(cell))
            .input(DataTree::from_item(2_i64))
            .input(DataTree::from_item(1_i64))
            .input(DataTree::from_item(2_i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        assert_eq!(
            points(&r.outputs[0]),
            [
                p(0.0, 0.0, 0.0),
                p(0.0, 0.0, 3.0),
                p(1.0, 0.0, 0.0),
                p(1.0, 0.0, 3.0)
            ]
        );
    }

    #[test]
    fn bad_counts_cells_and_geometry_are_errors() {
        let r = NodeCall::new(&linear_array())
            .input(DataTree::from_item(Point3::ORIGIN))
            .skip_input()
            .input(DataTree::from_item(-1_i64))
            .run();
        assert_error(&r, "count N must be 0 or more, not -1");
        let r = NodeCall::new(&rectangular_array())
            .skip_input()
            .input(rectangle(1.0, 1.0))
            .input(DataTree::from_item(1000_i64))
            .input(DataTree::from_item(1000_i64))
            .run();
        assert_error(&r, "1000 × 1000 copies is above the limit");
        let r = NodeCall::new(&rectangular_array())
            .skip_input()
            .input(rectangle(0.0, 1.0))
            .run();
        assert_error(&r, "cell C is not a rectangle");
        let r = NodeCall::new(&linear_array())
            .input(DataTree::from_item(Value::Number(1.0)))
            .input(DataTree::from_item(Vector3::X))
            .input(DataTree::from_item(2_i64))
            .run();
        assert_error(&r, "cannot transform a number");
        assert_eq!(r.outputs[0].item_count(), 2);
        assert_eq!(r.outputs[1].item_count(), 2);
        let r = NodeCall::new(&linear_array())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_item(Vector3::new(f64::NAN, 0.0, 0.0)))
            .run();
        assert_error(&r, "direction D has a component that is not finite");
    }
}
