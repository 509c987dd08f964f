//! Vector › Grid: Square, Rectangular and Hexagonal, planar grids of cells (closed polylines)
//! and points.
//!
//! Each grid is a tree per iteration: column `a` of the grid is the branch `{path;i;a}`, where
//! `{path}` is the iteration's output path and `i` its index in the branch, so that the
//! default inputs give the columns `{0;0;0}`, `{0;0;1}`, … as in Grasshopper. Item `b` of
//! column `a` is the point or cell at `a` along the plane's x axis and `b` along its y axis.
//!
//! - *Square* and *Rectangular*: the points are the cell corners, `a·u + b·v` with
//!   `u = Sx·X`, `v = Sy·Y` (X and Y the plane's axes), `Ex + 1` columns of `Ey + 1` points;
//!   the cells are the `Ex` columns of `Ey` rectangles whose first corner is the point with
//!   the same indices, drawn from it towards +X then +Y (counter-clockwise seen from +Z).
//! - *Hexagonal*: flat-topped hexagons of circumradius `S`. The points are the cell centres,
//!   `a·u + (b − ⌊a/2⌋)·v` with `u = S·(3/2, √3/2)` and `v = S·(0, √3)` in plane
//!   coordinates (odd columns sit half a cell higher), `Ex` columns of `Ey` centres; each cell
//!   is the hexagon around its centre, from the vertex on +X counter-clockwise. The lattice is
//!   the one published for Grasshopper's component; the first vertex of each hexagon is
//!   locus's choice (inferred, documented in `docs/nodes.md`).

use std::f64::consts::FRAC_PI_3;

use locus_kernel::{Plane, Point3, Polyline};
use locus_runtime::{
    Branch, DataTree, DataType, NodeError, NodeRegistry, NodeType, Port, Solve, TreePath,
};

use crate::curve::primitive_more::curve_of;

/// Id of [`square`].
pub const SQUARE: &str = "vector.grid_square";
/// Id of [`rectangular`].
pub const RECTANGULAR: &str = "vector.grid_rectangular";
/// Id of [`hexagonal`].
pub const HEXAGONAL: &str = "vector.grid_hexagonal";

/// The most points one grid may hold (ten million, 240 MB of points): a typo in an extent is an
/// error on the node rather than an exhausted machine.
pub const MAX_GRID_POINTS: usize = 10_000_000;

/// Registers the grid nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(square());
    registry.register(rectangular());
    registry.register(hexagonal());
}

fn grid(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Vector")
        .subcategory("Grid")
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The grid's base plane; default World XY.")
                .default_value(Plane::WORLD_XY),
        )
}

fn extent(name: &str, nickname: &str, axis: &str) -> Port {
    Port::new(name, nickname, DataType::Integer)
        .doc(&format!(
            "The number of cells along the plane's {axis} axis, at least 1; default 5."
        ))
        .default_value(5_i64)
}

fn size(name: &str, nickname: &str, what: &str) -> Port {
    Port::new(name, nickname, DataType::Number)
        .doc(&format!("{what}, above 0; default 1."))
        .default_value(1.0)
}

fn outputs(node: NodeType, cells: &str, points: &str) -> NodeType {
    node.output(Port::new("Cells", "C", DataType::Curve).tree().doc(cells))
        .output(Port::new("Points", "P", DataType::Point).tree().doc(points))
}

/// Square \[SqGrid\]: a grid of square cells.
pub fn square() -> NodeType {
    let node = grid(SQUARE, "Square", "SqGrid")
        .gh_guid("717a1e25-a075-4530-bc80-d43ecc2500d9")
        .description(
            "A 2D grid of square cells of size S on plane P: Ex by Ey cells (closed \
             polylines) and their (Ex + 1) by (Ey + 1) corner points, one branch per column.",
        )
        .input(size("Size", "S", "The side of the cells"))
        .input(extent("Extent X", "Ex", "x"))
        .input(extent("Extent Y", "Ey", "y"));
    outputs(
        node,
        "The cells, one branch per column along x, each a closed polyline of four sides.",
        "The corner points, one branch per column along x.",
    )
    .solve(|s| {
        let plane = valid_plane(s)?;
        let side = positive(*s.item::<f64>(1)?, "size S")?;
        let (ex, ey) = extents(s, 2, 3, 1)?;
        rectangular_grid(s, &plane, side, side, ex, ey)
    })
}

/// Rectangular \[RecGrid\]: a grid of rectangular cells.
pub fn rectangular() -> NodeType {
    let node = grid(RECTANGULAR, "Rectangular", "RecGrid")
        .gh_guid("1a25aae0-0b56-497a-85b2-cc5bf7e4b96b")
        .description(
            "A 2D grid of rectangular cells of Sx by Sy on plane P: Ex by Ey cells (closed \
             polylines) and their (Ex + 1) by (Ey + 1) corner points, one branch per column.",
        )
        .input(size(
            "Size X",
            "Sx",
            "The cells' size along the plane's x axis",
        ))
        .input(size(
            "Size Y",
            "Sy",
            "The cells' size along the plane's y axis",
        ))
        .input(extent("Extent X", "Ex", "x"))
        .input(extent("Extent Y", "Ey", "y"));
    outputs(
        node,
        "The cells, one branch per column along x, each a closed polyline of four sides.",
        "The corner points, one branch per column along x.",
    )
    .solve(|s| {
        let plane = valid_plane(s)?;
        let sx = positive(*s.item::<f64>(1)?, "size Sx")?;
        let sy = positive(*s.item::<f64>(2)?, "size Sy")?;
        let (ex, ey) = extents(s, 3, 4, 1)?;
        rectangular_grid(s, &plane, sx, sy, ex, ey)
    })
}

/// Hexagonal \[HexGrid\]: a grid of hexagonal cells.
pub fn hexagonal() -> NodeType {
    let node = grid(HEXAGONAL, "Hexagonal", "HexGrid")
        .gh_guid("125dc122-8544-4617-945e-bb9a0c101c50")
        .description(
            "A 2D grid of flat-topped hexagons of circumradius S on plane P: Ex columns of Ey \
             cells (closed polylines of six sides) and their centres, one branch per column; \
             odd columns sit half a cell higher. Each hexagon starts at its vertex on the \
             plane's +x side and turns counter-clockwise.",
        )
        .input(size(
            "Size",
            "S",
            "The hexagons' circumradius (centre to vertex)",
        ))
        .input(extent("Extent X", "Ex", "x"))
        .input(extent("Extent Y", "Ey", "y"));
    outputs(
        node,
        "The hexagons, one branch per column along x.",
        "The hexagons' centres, one branch per column along x.",
    )
    .solve(|s| {
        let plane = valid_plane(s)?;
        let r = positive(*s.item::<f64>(1)?, "size S")?;
        let (ex, ey) = extents(s, 2, 3, 0)?;
        let sqrt3 = 3.0_f64.sqrt();
        let at = |x: f64, y: f64| plane.origin + plane.x_axis * x + plane.y_axis * y;
        let centre = |a: usize, b: usize| {
            let (a, b) = (a as f64, b as f64);
            let lift = b - (a / 2.0).floor();
            (r * 1.5 * a, r * (sqrt3 / 2.0 * a + sqrt3 * lift))
        };
        let base = column_base(s);
        let mut cells = Vec::with_capacity(ex);
        let mut points = Vec::with_capacity(ex);
        for a in 0..ex {
            let mut column_cells = Branch::new(DataType::Curve);
            let mut column_points = Branch::new(DataType::Point);
            for b in 0..ey {
                let (cx, cy) = centre(a, b);
                column_points.push(at(cx, cy));
                let corners: Vec<Point3> = (0..=6)
                    .map(|k| {
                        let angle = FRAC_PI_3 * (k % 6) as f64;
                        at(cx + r * angle.cos(), cy + r * angle.sin())
                    })
                    .collect();
                column_cells.push(curve_of(Polyline::new(corners)?));
            }
            cells.push((column(&base, a), column_cells));
            points.push((column(&base, a), column_points));
        }
        s.set_tree(0, DataTree::from_branches(cells));
        s.set_tree(1, DataTree::from_branches(points));
        Ok(())
    })
}

fn valid_plane(s: &Solve<'_>) -> Result<Plane, NodeError> {
    let plane = *s.item::<Plane>(0)?;
    if plane.is_valid() {
        Ok(plane)
    } else {
        Err(NodeError("plane P is not valid".into()))
    }
}

fn positive(x: f64, what: &str) -> Result<f64, NodeError> {
    if x.is_finite() && x > 0.0 {
        Ok(x)
    } else {
        Err(NodeError(format!(
            "{what} must be a number above 0, not {x}"
        )))
    }
}

/// The extents Ex and Ey (inputs `x` and `y`), each at least 1, with the grid's point count
/// (`(Ex + extra)·(Ey + extra)`) within [`MAX_GRID_POINTS`].
fn extents(s: &Solve<'_>, x: usize, y: usize, extra: usize) -> Result<(usize, usize), NodeError> {
    let one = |input: usize, what: &str| -> Result<usize, NodeError> {
        let n = *s.item::<i64>(input)?;
        usize::try_from(n)
            .ok()
            .filter(|&n| n >= 1)
            .ok_or_else(|| NodeError(format!("extent {what} must be at least 1, not {n}")))
    };
    let (ex, ey) = (one(x, "Ex")?, one(y, "Ey")?);
    let count = (ex.saturating_add(extra)).saturating_mul(ey.saturating_add(extra));
    if count > MAX_GRID_POINTS {
        return Err(NodeError(format!(
            "a grid of {ex} by {ey} cells has {count} points, above the limit of \
             {MAX_GRID_POINTS}"
        )));
    }
    Ok((ex, ey))
}

/// The path the columns are appended to: the iteration's path and its index.
fn column_base(s: &Solve<'_>) -> TreePath {
    let index = u32::try_from(s.index().unwrap_or(0)).unwrap_or(u32::MAX);
    s.path().with_appended(index)
}

fn column(base: &TreePath, a: usize) -> TreePath {
    base.with_appended(u32::try_from(a).unwrap_or(u32::MAX))
}

fn rectangular_grid(
    s: &mut Solve<'_>,
    plane: &Plane,
    sx: f64,
    sy: f64,
    ex: usize,
    ey: usize,
) -> Result<(), NodeError> {
    let at = |a: usize, b: usize| {
        plane.origin + plane.x_axis * (sx * a as f64) + plane.y_axis * (sy * b as f64)
    };
    let base = column_base(s);
    let mut points = Vec::with_capacity(ex + 1);
    for a in 0..=ex {
        let mut column_points = Branch::new(DataType::Point);
        for b in 0..=ey {
            column_points.push(at(a, b));
        }
        points.push((column(&base, a), column_points));
    }
    let mut cells = Vec::with_capacity(ex);
    for a in 0..ex {
        let mut column_cells = Branch::new(DataType::Curve);
        for b in 0..ey {
            let corners = vec![
                at(a, b),
                at(a + 1, b),
                at(a + 1, b + 1),
                at(a, b + 1),
                at(a, b),
            ];
            column_cells.push(curve_of(Polyline::new(corners)?));
        }
        cells.push((column(&base, a), column_cells));
    }
    s.set_tree(0, DataTree::from_branches(cells));
    s.set_tree(1, DataTree::from_branches(points));
    Ok(())
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Curve, Vector3};
    use locus_runtime::{NodeCall, NodeCallResult};

    use super::*;
    use crate::test_support::{assert_error, points};

    fn item<T: locus_runtime::Item>(x: T) -> DataTree {
        DataTree::from_item(x)
    }

    /// The paths of a tree and the points of each branch.
    fn columns(tree: &DataTree) -> Vec<(String, Vec<Point3>)> {
        tree.branches()
            .iter()
            .map(|(p, b)| {
                let mut one = DataTree::new();
                one.insert(p.clone(), b.clone());
                (p.to_string(), points(&one))
            })
            .collect()
    }

    /// The corners of cell `b` of column `a`.
    fn corners(r: &NodeCallResult, a: usize, b: usize) -> Vec<Point3> {
        let column = &r.outputs[0].branches()[a].1;
        let curve = column
            .get::<locus_runtime::Shared<Curve>>(b)
            .expect("a curve");
        match curve.as_ref() {
            Curve::Polyline { polyline, .. } => polyline.points().to_vec(),
            other => panic!("not a polyline: {other:?}"),
        }
    }

    fn close(a: Point3, b: Point3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn square_grid_columns_and_corners() {
        let node = square();
        let r = NodeCall::new(&node)
            .skip_input()
            .input(item(2.0))
            .input(item(3_i64))
            .input(item(2_i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let points = columns(&r.outputs[1]);
        let paths: Vec<&str> = points.iter().map(|(p, _)| p.as_str()).collect();
        assert_eq!(paths, ["{0;0;0}", "{0;0;1}", "{0;0;2}", "{0;0;3}"]);
        assert_eq!(points[2].1.len(), 3);
        assert_eq!(points[2].1[1], Point3::new(4.0, 2.0, 0.0));
        let cells = &r.outputs[0];
        assert_eq!(cells.branch_count(), 3);
        assert_eq!(cells.branches()[1].0.to_string(), "{0;0;1}");
        assert_eq!(cells.branches()[1].1.len(), 2);
        let c = corners(&r, 1, 1);
        let expected = [(2.0, 2.0), (4.0, 2.0), (4.0, 4.0), (2.0, 4.0), (2.0, 2.0)];
        assert_eq!(c.len(), 5);
        for (p, (x, y)) in c.iter().zip(expected) {
            assert_eq!(*p, Point3::new(x, y, 0.0));
        }
    }

    #[test]
    fn rectangular_grid_on_a_turned_plane() {
        let plane = Plane::from_frame(Point3::new(1.0, 1.0, 1.0), Vector3::Y, -Vector3::X).unwrap();
        let node = rectangular();
        let r = NodeCall::new(&node)
            .input(item(plane))
            .input(item(2.0))
            .input(item(0.5))
            .input(item(1_i64))
            .input(item(1_i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let points = columns(&r.outputs[1]);
        assert_eq!(points.len(), 2);
        // (a, b) = (1, 1): 2 along the plane's x (world +Y), 0.5 along its y (world -X).
        assert!(close(points[1].1[1], Point3::new(0.5, 3.0, 1.0)));
    }

    #[test]
    fn hexagonal_grid_centres_touch_and_cells_are_regular() {
        let node = hexagonal();
        let r = NodeCall::new(&node)
            .skip_input()
            .skip_input()
            .input(item(3_i64))
            .input(item(2_i64))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let points = columns(&r.outputs[1]);
        assert_eq!(points.len(), 3);
        let s3 = 3.0_f64.sqrt();
        // Column 1 is half a cell up: (1.5, √3/2), then √3 above it.
        assert!(close(points[1].1[0], Point3::new(1.5, s3 / 2.0, 0.0)));
        assert!(close(points[1].1[1], Point3::new(1.5, 1.5 * s3, 0.0)));
        // Column 2 is level with column 0 again.
        assert!(close(points[2].1[0], Point3::new(3.0, 0.0, 0.0)));
        // Neighbouring centres are √3 apart (the hexagons share a side).
        assert!(((points[1].1[0] - points[0].1[0]).length() - s3).abs() < 1e-12);
        let cell = corners(&r, 0, 0);
        assert_eq!(cell.len(), 7);
        assert!(close(cell[0], Point3::new(1.0, 0.0, 0.0)));
        assert!(close(cell[1], Point3::new(0.5, s3 / 2.0, 0.0)));
        assert!(close(cell[6], cell[0]));
        for w in cell.windows(2) {
            assert!(((w[1] - w[0]).length() - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn bad_extents_sizes_and_huge_grids_are_errors() {
        let node = square();
        let call = |size: f64, ex: i64, ey: i64| {
            NodeCall::new(&node)
                .skip_input()
                .input(item(size))
                .input(item(ex))
                .input(item(ey))
                .run()
        };
        assert_error(&call(1.0, 0, 5), "extent Ex must be at least 1, not 0");
        assert_error(&call(1.0, 5, -2), "extent Ey must be at least 1, not -2");
        assert_error(&call(0.0, 5, 5), "size S must be a number above 0, not 0");
        assert_error(&call(f64::NAN, 5, 5), "size S must be a number above 0");
        let huge = call(1.0, 100_000, 100_000);
        assert_error(&huge, "above the limit of 10000000");
        assert_eq!(huge.outputs[1].item_count(), 0);
    }
}
