//! Vector › Point: Point Polar (a point from angles and a distance), Closest Point (the point of
//! a cloud nearest another) and Cull Duplicates (points that coincide within a tolerance).
//!
//! *Cull Duplicates* groups the points in list order: the first point not yet in a group
//! starts one and takes every later point not yet in a group within the tolerance of it (a
//! distance up to and including T). Each group becomes one point, by the `mode` setting, as
//! Grasshopper's component offers: `average` (the default, as in Grasshopper) writes the
//! average of the group, `leave` its first point, `cull` drops every group of more than one
//! point. *Indices* is the index of the point written, or −1 for an average of several
//! points; *Valence* is the number of points in the group. Candidates are found through a hash
//! grid of cells of size T, so that a long list costs about one pass.

use std::collections::HashMap;

use locus_kernel::{Plane, Point3, Vector3};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Value};

use super::{finite_number, finite_point};

/// Id of [`point_polar`].
pub const POINT_POLAR: &str = "vector.point_polar";
/// Id of [`closest_point`].
pub const CLOSEST_POINT: &str = "vector.closest_point";
/// Id of [`cull_duplicates`].
pub const CULL_DUPLICATES: &str = "vector.cull_duplicates";

/// Registers the nodes of this module.
pub fn register(registry: &mut NodeRegistry) {
    for t in [point_polar(), closest_point(), cull_duplicates()] {
        registry.register(t);
    }
}

fn point_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Vector").subcategory("Point")
}

/// The point at angles `xy` (in the plane, from its x axis towards its y axis) and `z`
/// (elevation above the plane, towards its normal) and distance `d` from the plane's origin.
pub fn polar_point(plane: &Plane, xy: f64, z: f64, d: f64) -> Point3 {
    let (sxy, cxy) = xy.sin_cos();
    let (sz, cz) = z.sin_cos();
    plane.origin + (plane.x_axis * (cxy * cz) + plane.y_axis * (sxy * cz) + plane.z_axis * sz) * d
}

/// Point Polar \[Point Polar\]: a point from polar coordinates.
pub fn point_polar() -> NodeType {
    point_node(POINT_POLAR, "Point Polar", "Point Polar")
        .gh_guid("a435f5c8-28a2-43e8-a52a-0b6e73c2e300")
        .description(
            "Creates a point from polar {φ, θ, offset} coordinates on a plane: the direction \
             at the angle xy from the plane's x axis towards its y axis, raised by the angle z \
             towards its normal, at the distance d from its origin.",
        )
        .input(
            Port::new("Plane", "P", DataType::Plane)
                .doc("The base plane; default World XY.")
                .default_value(Plane::WORLD_XY),
        )
        .input(
            Port::new("xy angle", "xy", DataType::Number)
                .doc("The angle in the plane, in radians, from the x axis; default 0.")
                .default_value(0.0),
        )
        .input(
            Port::new("z angle", "z", DataType::Number)
                .doc("The elevation above the plane, in radians; default 0.")
                .default_value(0.0),
        )
        .input(
            Port::new("Offset", "d", DataType::Number)
                .doc("The distance from the plane's origin; default 1.")
                .default_value(1.0),
        )
        .output(Port::new("Point", "Pt", DataType::Point).doc("The point."))
        .solve(|s| {
            let plane = *s.item::<Plane>(0)?;
            if !plane.is_valid() {
                return Err("plane P is not valid".into());
            }
            let xy = finite_number(*s.item::<f64>(1)?, "xy angle")?;
            let z = finite_number(*s.item::<f64>(2)?, "z angle")?;
            let d = finite_number(*s.item::<f64>(3)?, "offset d")?;
            let p = finite_point(polar_point(&plane, xy, z, d), "the point")?;
            s.set(0, p);
            Ok(())
        })
}

/// The index of the point of `cloud` nearest to `p` (the first of equally near ones) and its
/// distance; `None` when no point of the cloud has a finite distance.
pub fn nearest(p: Point3, cloud: &[Option<&Point3>]) -> Option<(usize, f64)> {
    let mut best: Option<(usize, f64)> = None;
    for (i, q) in cloud.iter().enumerate() {
        let Some(q) = q else { continue };
        let d2 = (**q - p).length_squared();
        if d2.is_finite() && best.is_none_or(|(_, b)| d2 < b) {
            best = Some((i, d2));
        }
    }
    best.map(|(i, d2)| (i, d2.sqrt()))
}

/// Closest Point \[CP\]: the point of a cloud nearest a point.
pub fn closest_point() -> NodeType {
    point_node(CLOSEST_POINT, "Closest Point", "CP")
        .gh_guid("571ca323-6e55-425a-bf9e-ee103c7ba4b9")
        .description(
            "Finds the point of a cloud closest to a point, with its index in the cloud and \
             its distance; of equally close points the first is taken. Nulls and points that \
             are not finite in the cloud are skipped; a cloud with no usable point is an \
             error.",
        )
        .input(Port::new("Point", "P", DataType::Point).doc("The point to search from."))
        .input(
            Port::new("Cloud", "C", DataType::Point)
                .list()
                .doc("The cloud of points to search."),
        )
        .output(
            Port::new("Closest Point", "P", DataType::Point).doc("The point of C closest to P."),
        )
        .output(Port::new("CP Index", "i", DataType::Integer).doc("Its index in the cloud."))
        .output(Port::new("Distance", "D", DataType::Number).doc("Its distance from P."))
        .solve(|s| {
            let p = finite_point(*s.item::<Point3>(0)?, "point P")?;
            let cloud: Vec<Option<&Point3>> = s.list::<Point3>(1)?.iter().collect();
            let (i, d) = nearest(p, &cloud).ok_or_else(|| {
                NodeError("cloud C has no point with a finite distance to P".into())
            })?;
            let q = *cloud[i].expect("nearest returns a present point");
            s.set(0, q);
            s.set(1, i as i64);
            s.set(2, d);
            Ok(())
        })
}

/// What Cull Duplicates writes for a group of coincident points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CullMode {
    /// The average of the group.
    Average,
    /// The first point of the group.
    LeaveOne,
    /// Nothing for a group of more than one point.
    CullAll,
}

/// The groups of `points` (indices, in list order) within `tolerance` of their first point,
/// grouped as the module documentation says. Points that are not finite form groups of their
/// own.
pub fn duplicate_groups(points: &[Point3], tolerance: f64) -> Vec<Vec<usize>> {
    let cell = |p: &Point3| -> Option<[i64; 3]> {
        if !p.is_finite() {
            return None;
        }
        let c = |x: f64| {
            if tolerance > 0.0 {
                (x / tolerance).floor() as i64
            } else {
                0
            }
        };
        Some([c(p.x), c(p.y), c(p.z)])
    };
    let mut grid: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    let cells: Vec<Option<[i64; 3]>> = points.iter().map(cell).collect();
    for (i, c) in cells.iter().enumerate() {
        if let Some(c) = c {
            grid.entry(*c).or_default().push(i);
        }
    }
    let mut taken = vec![false; points.len()];
    let mut groups = Vec::new();
    for i in 0..points.len() {
        if taken[i] {
            continue;
        }
        taken[i] = true;
        let mut group = vec![i];
        if let Some(c) = cells[i] {
            let mut found = Vec::new();
            for dx in -1..=1_i64 {
                for dy in -1..=1_i64 {
                    for dz in -1..=1_i64 {
                        let key = [
                            c[0].saturating_add(dx),
                            c[1].saturating_add(dy),
                            c[2].saturating_add(dz),
                        ];
                        let Some(members) = grid.get(&key) else {
                            continue;
                        };
                        found.extend(
                            members.iter().copied().filter(|&j| {
                                !taken[j] && points[j].distance(points[i]) <= tolerance
                            }),
                        );
                    }
                }
            }
            found.sort_unstable();
            found.dedup();
            for &j in &found {
                taken[j] = true;
            }
            group.extend(found);
        }
        groups.push(group);
    }
    groups
}

/// Cull Duplicates \[CullPt\]: one point for each group of coincident points.
pub fn cull_duplicates() -> NodeType {
    point_node(CULL_DUPLICATES, "Cull Duplicates", "CullPt")
        .gh_guid("6eaffbb2-3392-441a-8556-2dc126aa8910")
        .description(
            "Culls points that coincide within a tolerance: each group of points within T of \
             its first point becomes one point, the group's average (setting mode = \
             \"average\", the default), its first point (\"leave\") or none when the group has \
             more than one point (\"cull\").",
        )
        .input(
            Port::new("Points", "P", DataType::Point)
                .list()
                .doc("The points to cull; nulls are skipped."),
        )
        .input(
            Port::new("Tolerance", "T", DataType::Number)
                .doc("The largest distance at which points coincide, 0 or more; default 0.1.")
                .default_value(0.1),
        )
        .setting(
            "mode",
            DataType::Text,
            Some(Value::Text("average".into())),
            "What a group of coincident points becomes: \"average\" (their average), \
             \"leave\" (the first of them) or \"cull\" (nothing).",
        )
        .output(
            Port::new("Points", "P", DataType::Point)
                .list()
                .doc("One point for each group, in the order of the groups' first points."),
        )
        .output(
            Port::new("Indices", "I", DataType::Integer)
                .list()
                .doc("The index of each point written, or −1 for an average of several points."),
        )
        .output(
            Port::new("Valence", "V", DataType::Integer)
                .list()
                .doc("The number of input points each point written stands for."),
        )
        .solve(|s| {
            let mode = match s.setting("mode") {
                Some(Value::Text(t)) => match t.trim().to_ascii_lowercase().as_str() {
                    "average" | "" => CullMode::Average,
                    "leave" | "leave one" => CullMode::LeaveOne,
                    "cull" | "cull all" => CullMode::CullAll,
                    other => {
                        return Err(NodeError(format!(
                            "setting mode is \"{other}\", not \"average\", \"leave\" or \"cull\""
                        )));
                    }
                },
                _ => CullMode::Average,
            };
            let t = finite_number(*s.item::<f64>(1)?, "tolerance T")?;
            if t < 0.0 {
                return Err(NodeError(format!("tolerance T must be 0 or more, not {t}")));
            }
            let list = s.list::<Point3>(0)?;
            let (indices, points): (Vec<usize>, Vec<Point3>) = list
                .iter()
                .enumerate()
                .filter_map(|(i, p)| p.map(|p| (i, *p)))
                .unzip();
            let mut out = Vec::new();
            let mut out_index = Vec::new();
            let mut valence = Vec::new();
            for group in duplicate_groups(&points, t) {
                let n = group.len();
                let first = indices[group[0]] as i64;
                match (mode, n) {
                    (_, 1) | (CullMode::LeaveOne, _) => {
                        out.push(points[group[0]]);
                        out_index.push(first);
                    }
                    (CullMode::Average, _) => {
                        let sum = group
                            .iter()
                            .fold(Vector3::ZERO, |acc, &k| acc + (points[k] - Point3::ORIGIN));
                        out.push(Point3::ORIGIN + sum / n as f64);
                        out_index.push(-1);
                    }
                    (CullMode::CullAll, _) => continue,
                }
                valence.push(n as i64);
            }
            s.set_list(0, out);
            s.set_list(1, out_index);
            s.set_list(2, valence);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_6};

    use locus_runtime::{DataTree, NodeCall};

    use super::*;
    use crate::test_support::{assert_error, only, points};

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new(x, y, z)
    }

    fn integers(tree: &DataTree) -> Vec<i64> {
        crate::test_support::all(tree)
    }

    #[test]
    fn point_polar_on_the_world_plane() {
        let run = |xy: f64, z: f64, d: f64| {
            let r = NodeCall::new(&point_polar())
                .skip_input()
                .input(DataTree::from_item(xy))
                .input(DataTree::from_item(z))
                .input(DataTree::from_item(d))
                .run();
            only::<Point3>(&r, 0)
        };
        assert!((run(FRAC_PI_2, 0.0, 2.0) - p(0.0, 2.0, 0.0)).length() < 1e-15);
        assert!((run(0.0, FRAC_PI_6, 2.0) - p(3.0_f64.sqrt(), 0.0, 1.0)).length() < 1e-15);
        let r = NodeCall::new(&point_polar())
            .skip_input()
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_error(&r, "xy angle is not a finite number");
    }

    #[test]
    fn closest_point_takes_the_first_of_equals() {
        let cloud =
            DataTree::from_list(vec![p(5.0, 0.0, 0.0), p(0.0, 3.0, 0.0), p(-3.0, 0.0, 0.0)]);
        let r = NodeCall::new(&closest_point())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(cloud)
            .run();
        assert_eq!(only::<Point3>(&r, 0), p(0.0, 3.0, 0.0));
        assert_eq!(only::<i64>(&r, 1), 1);
        assert_eq!(only::<f64>(&r, 2), 3.0);
        let r = NodeCall::new(&closest_point())
            .input(DataTree::from_item(Point3::ORIGIN))
            .input(DataTree::from_list(vec![p(f64::NAN, 0.0, 0.0)]))
            .run();
        assert_error(&r, "cloud C has no point");
    }

    fn cull(mode: &str, pts: Vec<Point3>, t: f64) -> locus_runtime::NodeCallResult {
        NodeCall::new(&cull_duplicates())
            .setting("mode", Value::Text(mode.into()))
            .input(DataTree::from_list(pts))
            .input(DataTree::from_item(t))
            .run()
    }

    fn sample() -> Vec<Point3> {
        vec![
            p(0.0, 0.0, 0.0),
            p(5.0, 0.0, 0.0),
            p(0.05, 0.0, 0.0),
            p(0.0, 0.1, 0.0),
            p(5.0, 0.0, 0.2),
        ]
    }

    #[test]
    fn cull_duplicates_averages_leaves_or_culls() {
        let r = cull("average", sample(), 0.1);
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let pts = points(&r.outputs[0]);
        assert_eq!(pts.len(), 3);
        assert!((pts[0] - p(0.05 / 3.0, 0.1 / 3.0, 0.0)).length() < 1e-15);
        assert_eq!(&pts[1..], [p(5.0, 0.0, 0.0), p(5.0, 0.0, 0.2)]);
        assert_eq!(integers(&r.outputs[1]), [-1, 1, 4]);
        assert_eq!(integers(&r.outputs[2]), [3, 1, 1]);
        let r = cull("leave", sample(), 0.1);
        assert_eq!(points(&r.outputs[0])[0], Point3::ORIGIN);
        assert_eq!(integers(&r.outputs[1]), [0, 1, 4]);
        let r = cull("cull", sample(), 0.1);
        assert_eq!(integers(&r.outputs[1]), [1, 4]);
        assert_eq!(integers(&r.outputs[2]), [1, 1]);
        let r = cull("leave", sample(), 0.0);
        assert_eq!(integers(&r.outputs[2]), [1, 1, 1, 1, 1]);
    }

    #[test]
    fn cull_duplicates_groups_around_the_first_point_only() {
        // 0.08 apart in a chain: 1 is within 0.1 of 0, 2 is not (0.16), so it starts a group.
        let chain = vec![p(0.0, 0.0, 0.0), p(0.08, 0.0, 0.0), p(0.16, 0.0, 0.0)];
        let r = cull("leave", chain, 0.1);
        assert_eq!(integers(&r.outputs[1]), [0, 2]);
    }

    #[test]
    fn cull_duplicates_rejects_bad_tolerances_and_modes() {
        assert_error(
            &cull("average", sample(), -1.0),
            "tolerance T must be 0 or more",
        );
        assert_error(
            &cull("average", sample(), f64::NAN),
            "tolerance T is not a finite",
        );
        assert_error(&cull("merge", sample(), 0.1), "setting mode is \"merge\"");
        let r = cull(
            "average",
            vec![p(f64::NAN, 0.0, 0.0), p(f64::NAN, 0.0, 0.0)],
            0.1,
        );
        assert_eq!(integers(&r.outputs[2]), [1, 1]);
    }
}
