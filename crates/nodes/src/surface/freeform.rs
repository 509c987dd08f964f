//! Surface › Freeform: Surface From Points, the book's NURBS surface from a grid of points.
//!
//! The points come as one flat list: point `k` is grid point `(i, j) = (k / V, k % V)`, with
//! `U` points along `u` and `V = |P| / U` along `v`, so `v` varies fastest, as in RhinoCommon's `NurbsSurface.CreateFromPoints(points, uCount, vCount, …)` and
//! as Grasshopper's Square Grid lists its points column by column.
//!
//! Without interpolation the points are the control points of a clamped surface of degree
//! `min(3, count − 1)` in each direction, with uniform knots of spacing 1 (openNURBS's
//! `ON_MakeClampedUniformKnotVector`): the surface passes through the four corner points only.
//! With interpolation the surface passes through every point: global tensor-product
//! interpolation (The NURBS Book, §9.2.5, A9.4) with averaged chord-length parameters
//! normalized to `0` to `1` in each direction and knots by averaging. Rhino's
//! `CreateThroughPoints` may choose other parameters and knots (not verified), so the
//! interpolating surface passes through the same points but may differ between them.

use locus_kernel::basis::{MAX_ORDER, basis_functions, span_index};
use locus_kernel::{Brep, NurbsSurface, Point3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared};

use crate::curve::{curve_input, point_list};

/// Id of [`surface_from_points`].
pub const SURFACE_FROM_POINTS: &str = "surface.surface_from_points";
/// Id of [`four_point_surface`].
pub const FOUR_POINT_SURFACE: &str = "surface.four_point_surface";
/// Id of [`edge_surface`].
pub const EDGE_SURFACE: &str = "surface.edge_surface";

/// The distance within which Edge Surface chains its curves: 0.001 model units, Rhino's
/// default document tolerance.
pub const EDGE_CHAIN_TOLERANCE: f64 = 0.001;

/// The degree Surface From Points uses where there are enough points.
const PREFERRED_DEGREE: usize = 3;

/// Registers the freeform nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(surface_from_points());
    registry.register(four_point_surface());
    registry.register(edge_surface());
}

/// Edge Surface \[EdgeSrf\]: the Coons patch of two, three or four edge curves.
pub fn edge_surface() -> NodeType {
    let edge = |name: &str, nick: &str, doc: &str| Port::new(name, nick, DataType::Curve).doc(doc);
    NodeType::new(EDGE_SURFACE, "Edge Surface", "EdgeSrf", "Surface")
        .gh_guid("36132830-e2ef-4476-8ea1-6a43922344f0")
        .subcategory("Freeform")
        .description(
            "Creates a surface from two, three or four edge curves that form a closed loop \
             (in any order and direction; ends meeting within 0.001): the bilinearly blended \
             Coons patch, which passes exactly through every edge, as a one-face B-rep. With \
             three curves one side collapses to a point, with two curves two sides do. The \
             degrees and knots are the edges' (opposite edges made compatible); u runs along \
             curve A, both directions on 0 to 1. Rational edges (arcs) need equal end weights, \
             as Rhino's arcs have.",
        )
        .input(edge("Curve A", "A", "First edge curve."))
        .input(edge("Curve B", "B", "Second edge curve."))
        .input(edge("Curve C", "C", "Optional third edge curve.").optional())
        .input(edge("Curve D", "D", "Optional fourth edge curve.").optional())
        .output(
            Port::new("Surface", "S", DataType::Brep).doc("The edge surface, a one-face B-rep."),
        )
        .solve(|s| {
            let mut edges = vec![curve_input(s, 0)?.to_nurbs(), curve_input(s, 1)?.to_nurbs()];
            for input in [2, 3] {
                if s.value(input).is_some() {
                    edges.push(curve_input(s, input)?.to_nurbs());
                }
            }
            let surface = NurbsSurface::from_edges(&edges, EDGE_CHAIN_TOLERANCE)?;
            s.set(0, Shared::new(Brep::from_surface(surface)?));
            Ok(())
        })
}

/// 4Point Surface \[Srf4Pt\]: the bilinear patch on three or four corners.
pub fn four_point_surface() -> NodeType {
    let corner =
        |name: &str, nick: &str, doc: &str| Port::new(name, nick, DataType::Point).doc(doc);
    NodeType::new(FOUR_POINT_SURFACE, "4Point Surface", "Srf4Pt", "Surface")
        .gh_guid("c77a8b3b-c569-4d81-9b59-1c27299a1c45")
        .subcategory("Freeform")
        .description(
            "Creates the bilinear surface on three or four corner points (Rhino's \
             CreateFromCorners): degree 1 both ways on 0 to 1, A at (0, 0), B at (1, 0), C at \
             (1, 1) and D at (0, 1), straight along every isocurve. Four corners out of one \
             plane give a twisted patch (a hyperbolic paraboloid). Without D the fourth corner \
             is C: the side from C to D collapses and the surface is the triangle A B C. \
             Corners on one line are an error.",
        )
        .input(corner("Corner A", "A", "First corner, at (0, 0)."))
        .input(corner("Corner B", "B", "Second corner, at (1, 0)."))
        .input(corner("Corner C", "C", "Third corner, at (1, 1)."))
        .input(
            corner(
                "Corner D",
                "D",
                "Optional fourth corner, at (0, 1); C when absent.",
            )
            .optional(),
        )
        .output(Port::new("Surface", "S", DataType::Surface).doc("The bilinear surface."))
        .solve(|s| {
            let a = *s.item::<Point3>(0)?;
            let b = *s.item::<Point3>(1)?;
            let c = *s.item::<Point3>(2)?;
            let d = s.item_opt::<Point3>(3).copied().unwrap_or(c);
            let surface = NurbsSurface::from_corners(a, b, c, d).map_err(|e| match e {
                locus_kernel::Error::Degenerate { .. } => {
                    NodeError::from("the corners lie on one line and span no surface")
                }
                other => other.into(),
            })?;
            s.set(0, Shared::new(surface));
            Ok(())
        })
}

/// Surface From Points \[SrfGrid\]: a NURBS surface from a grid of points.
pub fn surface_from_points() -> NodeType {
    NodeType::new(
        SURFACE_FROM_POINTS,
        "Surface From Points",
        "SrfGrid",
        "Surface",
    )
    .gh_guid("4b04a1e1-cddf-405d-a7db-335aaa940541")
    .subcategory("Freeform")
    .description(
        "Creates a NURBS surface from a grid of points given as one list, U Count points \
         along u and the list's length divided by U Count along v (v varying fastest: point k \
         is grid point (k / V, k mod V)). The degree is 3 in each direction, or one less than \
         the number of points there if that is smaller. With Interpolate the surface passes \
         through every point (averaged chord-length parameters, domain 0 to 1 each way); \
         without, the points are its control points (clamped uniform knots, domain 0 to \
         count − degree) and it passes through the corners only. The list's length must be a \
         multiple of U Count with at least two points each way; interpolation also needs \
         neighbouring rows and columns to be apart.",
    )
    .input(
        Port::new("Points", "P", DataType::Point)
            .list()
            .doc("Grid of points, v varying fastest; nulls are left out with a warning."),
    )
    .input(
        Port::new("U Count", "U", DataType::Integer)
            .doc("Number of points in the u direction, at least 2; must divide the point count."),
    )
    .input(
        Port::new("Interpolate", "I", DataType::Boolean)
            .default_value(true)
            .doc("True: the surface goes through the points; false: they are control points. Default true."),
    )
    .output(Port::new("Surface", "S", DataType::Surface).doc("The NURBS surface."))
    .solve(|s| {
        let points = point_list(s, 0)?;
        let u_count = *s.item::<i64>(1)?;
        let interpolate = *s.item::<bool>(2)?;
        let (_, nv) = grid_shape(points.len(), u_count)?;
        if let Some(k) = points.iter().position(|p| !p.is_finite()) {
            return Err(format!("input P: point {k} is not finite").into());
        }
        let grid: Vec<Vec<Point3>> = points.chunks(nv).map(<[Point3]>::to_vec).collect();
        let surface = if interpolate {
            interpolate_grid(&grid)?
        } else {
            control_grid(grid)?
        };
        s.set(0, Shared::new(surface));
        Ok(())
    })
}

/// The `(u, v)` counts of a list of `total` points with `u_count` along u.
fn grid_shape(total: usize, u_count: i64) -> Result<(usize, usize), NodeError> {
    if u_count < 2 {
        return Err(format!("input U: the u count must be at least 2, got {u_count}").into());
    }
    let nu = usize::try_from(u_count).map_err(|_| format!("input U: {u_count} is too large"))?;
    if !total.is_multiple_of(nu) {
        return Err(format!(
            "input P: {total} points do not make a grid of {nu} along u (not a multiple)"
        )
        .into());
    }
    let nv = total / nu;
    if nv < 2 {
        return Err(format!(
            "input P: {total} points with {nu} along u leave fewer than 2 along v"
        )
        .into());
    }
    Ok((nu, nv))
}

fn degree_for(count: usize) -> usize {
    PREFERRED_DEGREE.min(count - 1)
}

/// Clamped uniform knots in Rhino form, spacing 1: `degree` zeros, `1, …, count − degree − 1`,
/// and `degree` times `count − degree`.
fn clamped_uniform_knots(count: usize, degree: usize) -> Vec<f64> {
    let last = (count - degree) as f64;
    let mut knots = vec![0.0; degree];
    knots.extend((1..count - degree).map(|k| k as f64));
    knots.extend(std::iter::repeat_n(last, degree));
    knots
}

/// The surface with the grid as its control points.
fn control_grid(grid: Vec<Vec<Point3>>) -> Result<NurbsSurface, NodeError> {
    let (nu, nv) = (grid.len(), grid[0].len());
    let (p, q) = (degree_for(nu), degree_for(nv));
    Ok(NurbsSurface::non_rational(
        p,
        q,
        grid,
        clamped_uniform_knots(nu, p),
        clamped_uniform_knots(nv, q),
    )?)
}

/// Averaged, normalized chord-length parameters for the `count` points of each of the `lines`
/// (The NURBS Book, A9.3): lines of zero length are left out of the average.
fn averaged_parameters(lines: &[Vec<Point3>], direction: &str) -> Result<Vec<f64>, NodeError> {
    let count = lines[0].len();
    let mut sum = vec![0.0; count];
    let mut used = 0usize;
    for line in lines {
        let chords: Vec<f64> = line.windows(2).map(|w| w[0].distance(w[1])).collect();
        let total: f64 = chords.iter().sum();
        if total <= 0.0 {
            continue;
        }
        used += 1;
        let mut acc = 0.0;
        for (k, c) in chords.iter().enumerate() {
            acc += c;
            sum[k + 1] += acc / total;
        }
    }
    if used == 0 {
        return Err(
            format!("input P: every line of points along {direction} has zero length").into(),
        );
    }
    let mut params: Vec<f64> = sum.iter().map(|x| x / used as f64).collect();
    params[0] = 0.0;
    params[count - 1] = 1.0;
    if params.windows(2).any(|w| w[1] <= w[0]) {
        return Err(format!(
            "input P: neighbouring points along {direction} coincide in every line, so the \
             surface cannot pass through them"
        )
        .into());
    }
    Ok(params)
}

/// Knots in Rhino form by averaging the parameters (The NURBS Book, eq. 9.8).
fn averaged_knots(params: &[f64], degree: usize) -> Vec<f64> {
    let n = params.len() - 1;
    let mut knots = vec![params[0]; degree];
    for j in 1..=n - degree {
        knots.push(params[j..j + degree].iter().sum::<f64>() / degree as f64);
    }
    knots.extend(std::iter::repeat_n(params[n], degree));
    knots
}

/// An LU factorization with partial pivoting of the collocation matrix `A[k][i] = Nᵢ(t_k)`.
struct Collocation {
    lu: Vec<Vec<f64>>,
    pivots: Vec<usize>,
}

impl Collocation {
    fn new(params: &[f64], knots: &[f64], degree: usize) -> Result<Self, NodeError> {
        let n = params.len();
        let mut a = vec![vec![0.0; n]; n];
        let mut basis = [0.0; MAX_ORDER];
        for (k, &t) in params.iter().enumerate() {
            let span = span_index(degree, knots, t);
            basis_functions(degree, knots, span, t, &mut basis);
            let first = span + 1 - degree;
            a[k][first..=first + degree].copy_from_slice(&basis[..=degree]);
        }
        let mut pivots = (0..n).collect::<Vec<_>>();
        for col in 0..n {
            let (best, value) = (col..n)
                .map(|r| (r, a[r][col].abs()))
                .fold((col, -1.0), |acc, x| if x.1 > acc.1 { x } else { acc });
            if value <= 1e-14 {
                return Err("the interpolation system is singular for these points".into());
            }
            a.swap(col, best);
            pivots.swap(col, best);
            let (upper, lower) = a.split_at_mut(col + 1);
            let pivot_row = &upper[col];
            for row in lower {
                let factor = row[col] / pivot_row[col];
                if factor != 0.0 {
                    row[col] = factor;
                    for (x, &p) in row[col + 1..].iter_mut().zip(&pivot_row[col + 1..]) {
                        *x -= factor * p;
                    }
                }
            }
        }
        Ok(Self { lu: a, pivots })
    }

    /// Solves `A x = b` for points.
    fn solve(&self, b: &[Point3]) -> Vec<Point3> {
        let n = b.len();
        let mut x: Vec<Point3> = self.pivots.iter().map(|&p| b[p]).collect();
        for r in 0..n {
            let row = &self.lu[r];
            let acc = x[..r]
                .iter()
                .zip(row)
                .fold(x[r].to_vector(), |acc, (xc, &l)| acc - xc.to_vector() * l);
            x[r] = Point3::from_vector(acc);
        }
        for r in (0..n).rev() {
            let row = &self.lu[r];
            let acc = x[r + 1..]
                .iter()
                .zip(&row[r + 1..])
                .fold(x[r].to_vector(), |acc, (xc, &u)| acc - xc.to_vector() * u);
            x[r] = Point3::from_vector(acc / row[r]);
        }
        x
    }
}

/// The surface through every point of the grid (The NURBS Book, A9.4).
fn interpolate_grid(grid: &[Vec<Point3>]) -> Result<NurbsSurface, NodeError> {
    let (nu, nv) = (grid.len(), grid[0].len());
    let (p, q) = (degree_for(nu), degree_for(nv));
    let columns: Vec<Vec<Point3>> = (0..nv)
        .map(|j| (0..nu).map(|i| grid[i][j]).collect())
        .collect();
    let u_params = averaged_parameters(&columns, "u")?;
    let v_params = averaged_parameters(grid, "v")?;
    let (u_knots, v_knots) = (averaged_knots(&u_params, p), averaged_knots(&v_params, q));
    let along_u = Collocation::new(&u_params, &u_knots, p)?;
    let along_v = Collocation::new(&v_params, &v_knots, q)?;
    // Curves through each column along u, then through each row of their control points.
    let r: Vec<Vec<Point3>> = columns.iter().map(|c| along_u.solve(c)).collect();
    let control: Vec<Vec<Point3>> = (0..nu)
        .map(|i| {
            let row: Vec<Point3> = (0..nv).map(|j| r[j][i]).collect();
            along_v.solve(&row)
        })
        .collect();
    Ok(NurbsSurface::non_rational(p, q, control, u_knots, v_knots)?)
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Interval, Vector3};
    use locus_runtime::{DataTree, Level, NodeCall, NodeCallResult, Value};

    use super::*;

    /// A 4 × 5 grid on the saddle z = (x² − y²)/10, column by column (v fastest).
    fn saddle_points() -> Vec<Point3> {
        let mut pts = Vec::new();
        for i in 0..4 {
            for j in 0..5 {
                let (x, y) = (i as f64 * 2.0 - 3.0, j as f64 * 1.5 - 3.0);
                pts.push(Point3::new(x, y, (x * x - y * y) / 10.0));
            }
        }
        pts
    }

    fn run(points: Vec<Point3>, u: i64, interpolate: bool) -> NodeCallResult {
        NodeCall::new(&surface_from_points())
            .input(DataTree::from_list(points))
            .input(DataTree::from_item(u))
            .input(DataTree::from_item(interpolate))
            .run()
    }

    fn surface(r: &NodeCallResult) -> Shared<NurbsSurface> {
        match r.outputs[0].values().next().flatten() {
            Some(Value::Surface(s)) => s,
            other => panic!("no surface: {other:?} {:?}", r.messages),
        }
    }

    fn error(r: &NodeCallResult) -> String {
        r.messages
            .iter()
            .find(|m| m.level == Level::Error)
            .map(|m| m.text.clone())
            .unwrap_or_default()
    }

    #[test]
    fn interpolating_surface_passes_through_every_point() {
        let pts = saddle_points();
        let r = run(pts.clone(), 4, true);
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let s = surface(&r);
        assert_eq!((s.degree_u(), s.degree_v()), (3, 3));
        assert_eq!(
            (s.domain_u(), s.domain_v()),
            (Interval::UNIT, Interval::UNIT)
        );
        // The grid is uniform in x and y, so the parameters are near k/(n − 1); every point
        // is reached by the closest point at distance ~0.
        for p in &pts {
            let cp = s.closest_point(*p).unwrap();
            assert!(cp.distance < 1e-9, "{p:?}: {}", cp.distance);
        }
        // A quadric saddle is reproduced closely between the points too.
        let mid = s.point_at(0.5, 0.5);
        assert!(
            (mid.z - (mid.x * mid.x - mid.y * mid.y) / 10.0).abs() < 2e-2,
            "{mid:?}"
        );
    }

    #[test]
    fn control_point_surface_reaches_the_corners() {
        let pts = saddle_points();
        let r = run(pts.clone(), 4, false);
        let s = surface(&r);
        assert_eq!(s.domain_u(), Interval::new(0.0, 1.0));
        assert_eq!(s.domain_v(), Interval::new(0.0, 2.0));
        assert_eq!(s.points(), &pts[..]);
        assert_eq!(s.point_at(0.0, 0.0), pts[0]);
        assert!(s.point_at(1.0, 2.0).abs_diff_eq(pts[19], 1e-12));
    }

    #[test]
    fn two_by_two_points_make_a_bilinear_patch() {
        let pts = vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 1.0),
        ];
        let s = surface(&run(pts, 2, true));
        assert_eq!((s.degree_u(), s.degree_v()), (1, 1));
        assert!(
            s.point_at(0.5, 0.5)
                .abs_diff_eq(Point3::new(0.5, 0.5, 0.25), 1e-12)
        );
        let n = s.normal_at(0.0, 0.0).unwrap();
        assert!((n - Vector3::Z).length() < 1e-12, "u along x, v along y");
    }

    #[test]
    fn bad_grids_are_errors() {
        assert!(error(&run(saddle_points(), 3, true)).contains("multiple"));
        assert!(error(&run(saddle_points(), 1, true)).contains("input U"));
        assert!(error(&run(saddle_points(), 20, true)).contains("fewer than 2"));
        let mut nan = saddle_points();
        nan[3] = Point3::new(f64::NAN, 0.0, 0.0);
        assert!(error(&run(nan, 4, false)).contains("not finite"));
        let same = vec![Point3::ORIGIN; 4];
        assert!(error(&run(same.clone(), 2, true)).contains("zero length"));
        // As control points, coincident points are allowed (a degenerate surface).
        assert!(
            run(same, 2, false).outputs[0]
                .values()
                .next()
                .flatten()
                .is_some()
        );
    }

    fn corners(points: &[Point3]) -> NodeCallResult {
        let node = four_point_surface();
        let mut call = NodeCall::new(&node);
        for p in points {
            call = call.input(DataTree::from_item(*p));
        }
        call.run()
    }

    #[test]
    fn four_point_surface_on_a_rectangle_and_a_triangle() {
        let (a, b, c, d) = (
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(3.0, 0.0, 0.0),
            Point3::new(3.0, 2.0, 0.0),
            Point3::new(0.0, 2.0, 0.0),
        );
        let r = corners(&[a, b, c, d]);
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let Some(Value::Surface(s)) = r.outputs[0].values().next().flatten() else {
            panic!("no surface")
        };
        assert!((s.area_properties().unwrap().area - 6.0).abs() < 1e-12);
        assert_eq!(s.point_at(1.0, 1.0), c);
        // Without D: the triangle A B C of area 3.
        let r = corners(&[a, b, c]);
        let Some(Value::Surface(t)) = r.outputs[0].values().next().flatten() else {
            panic!("no surface: {:?}", r.messages)
        };
        assert!((t.area_properties().unwrap().area - 3.0).abs() < 1e-12);
    }

    #[test]
    fn four_point_surface_bad_input() {
        let p = |x: f64| Point3::new(x, 0.0, 0.0);
        let r = corners(&[p(0.0), p(1.0), p(2.0), p(3.0)]);
        let e: Vec<&str> = r
            .messages
            .iter()
            .filter(|m| m.level == Level::Error)
            .map(|m| m.text.as_str())
            .collect();
        assert!(e.len() == 1 && e[0].contains("one line"), "{e:?}");
        let r = corners(&[p(0.0), Point3::new(f64::NAN, 0.0, 0.0), p(2.0)]);
        assert!(
            r.messages.iter().any(|m| m.level == Level::Error),
            "{:?}",
            r.messages
        );
    }

    #[test]
    fn edge_surface_of_four_lines() {
        let line =
            |a: Point3, b: Point3| DataTree::from_item(Value::Line(locus_kernel::Line::new(a, b)));
        let (a, b, c, d) = (
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(3.0, 0.0, 0.0),
            Point3::new(3.0, 2.0, 0.0),
            Point3::new(0.0, 2.0, 0.0),
        );
        let r = NodeCall::new(&edge_surface())
            .input(line(a, b))
            .input(line(b, c))
            .input(line(c, d))
            .input(line(d, a))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let Some(Value::Brep(brep)) = r.outputs[0].values().next().flatten() else {
            panic!("no brep")
        };
        assert!((brep.area().unwrap() - 6.0).abs() < 1e-12);
        // Two curves that do not close are an error naming the chain.
        let r = NodeCall::new(&edge_surface())
            .input(line(a, b))
            .input(line(c, d))
            .run();
        let e: Vec<&str> = r
            .messages
            .iter()
            .filter(|m| m.level == Level::Error)
            .map(|m| m.text.as_str())
            .collect();
        assert!(e.len() == 1 && e[0].contains("chain"), "{e:?}");
    }
}
