//! Surface › Analysis and Util: taking B-reps apart and joining them. Deconstruct Brep, Brep
//! Edges, Brep Join, and Singular Points (the book's singularity tutorial as a node).
//!
//! A B-rep ([`Brep`]) is Rhino's boundary representation: faces on NURBS surfaces bounded by
//! trims, joined along edges that meet at vertices. Edges come out as curves: a straight edge of
//! degree 1 between two points as a line curve (as Rhino's box edges are), any other edge as
//! its NURBS curve. Area and Volume are in [`super::brep_analysis`].

use locus_kernel::{Brep, Curve, EdgeKind, Line, NurbsCurve, TrimKind};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Shared, Solve, Value};

/// Id of [`deconstruct_brep`].
pub const DECONSTRUCT_BREP: &str = "surface.deconstruct_brep";
/// Id of [`brep_edges`].
pub const BREP_EDGES: &str = "surface.brep_edges";
/// Id of [`brep_join`].
pub const BREP_JOIN: &str = "surface.brep_join";
/// Id of [`singular_points`].
pub const SINGULAR_POINTS: &str = "surface.singular_points";

/// The distance within which Brep Join joins edges: 0.001 model units, the absolute
/// tolerance of Rhino's default document templates, which Grasshopper's Brep Join uses (it
/// has no tolerance input of its own).
pub const JOIN_TOLERANCE: f64 = 0.001;

/// Registers the B-rep nodes of this file.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        deconstruct_brep(),
        brep_edges(),
        brep_join(),
        singular_points(),
    ] {
        registry.register(t);
    }
}

pub(crate) fn surface_node(id: &str, name: &str, nickname: &str, subcategory: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Surface").subcategory(subcategory)
}

/// The Brep input every node here starts with.
fn brep_input(what: &str) -> Port {
    Port::new("Brep", "B", DataType::Brep).doc(&format!(
        "The B-rep {what}. Boxes and surfaces are taken as B-reps (six faces, one face)."
    ))
}

/// The B-rep on item input `input`, with an error for a non-finite one.
pub(crate) fn brep_item(s: &Solve<'_>, input: usize) -> Result<Shared<Brep>, NodeError> {
    let brep = s.item::<Shared<Brep>>(input)?.clone();
    let finite = brep.vertices().iter().all(|v| v.point.is_finite())
        && brep.faces().iter().all(|f| f.surface.is_finite());
    if !finite {
        return Err("the brep has a coordinate that is not finite".into());
    }
    Ok(brep)
}

/// An edge curve as a curve value: a line for a straight two-point edge, else the NURBS curve.
pub fn edge_curve(curve: &NurbsCurve) -> Value {
    let straight = curve.degree() == 1 && curve.point_count() == 2 && !curve.is_rational();
    let c = if straight {
        Curve::Line {
            line: Line::new(curve.start_point(), curve.end_point()),
            domain: curve.domain(),
        }
    } else {
        Curve::Nurbs(curve.clone())
    };
    Value::Curve(Shared::new(c))
}

/// Deconstruct Brep \[DeBrep\]: the faces, edges and vertices of a B-rep.
pub fn deconstruct_brep() -> NodeType {
    surface_node(DECONSTRUCT_BREP, "Deconstruct Brep", "DeBrep", "Analysis")
        .gh_guid("8d372bdc-9800-45e9-8a26-6e33c5253e21")
        .description(
            "Takes a B-rep apart into its faces, edges and vertices. Each face comes out as a \
             B-rep of its own (Rhino's ExtractFace), with its trims and holes; edges it shared \
             with other faces become naked. Edges come out as curves, in the B-rep's edge \
             order; straight edges as lines. Vertices are points.",
        )
        .input(brep_input("to take apart"))
        .output(
            Port::new("Faces", "F", DataType::Brep)
                .doc("The faces, each a one-face B-rep.")
                .list(),
        )
        .output(
            Port::new("Edges", "E", DataType::Curve)
                .doc("The edges, as curves.")
                .list(),
        )
        .output(
            Port::new("Vertices", "V", DataType::Point)
                .doc("The vertices.")
                .list(),
        )
        .solve(|s| {
            let brep = brep_item(s, 0)?;
            if brep.faces().is_empty() {
                s.warning("the brep has no faces");
            }
            let mut faces = Vec::with_capacity(brep.faces().len());
            for i in 0..brep.faces().len() {
                faces.push(Some(Value::Brep(Shared::new(brep.extract_face(i)?))));
            }
            let edges = brep
                .edges()
                .iter()
                .map(|e| Some(edge_curve(&e.curve)))
                .collect();
            let vertices = brep.vertices().iter().map(|v| v.point).collect();
            s.set_list_values(0, faces);
            s.set_list_values(1, edges);
            s.set_list(2, vertices);
            Ok(())
        })
}

/// Brep Edges \[Edges\]: the edges of a B-rep sorted by how many faces meet there.
pub fn brep_edges() -> NodeType {
    surface_node(BREP_EDGES, "Brep Edges", "Edges", "Analysis")
        .gh_guid("0148a65d-6f42-414a-9db7-9a9b2eb78437")
        .description(
            "Sorts the edges of a B-rep by how many faces meet at them: naked edges are used \
             by one face (the open border of a surface or polysurface), interior edges by two \
             (where faces are joined, or the seam of a closed face such as a cylinder's), \
             non-manifold edges by three or more. A closed solid has no naked edges. Edges \
             come out as curves, in the B-rep's edge order.",
        )
        .input(brep_input("whose edges to sort"))
        .output(
            Port::new("Naked", "En", DataType::Curve)
                .doc("The naked edges, used by one face.")
                .list(),
        )
        .output(
            Port::new("Interior", "Ei", DataType::Curve)
                .doc("The interior edges, used by two faces (or twice by one).")
                .list(),
        )
        .output(
            Port::new("Non-Manifold", "Em", DataType::Curve)
                .doc("The non-manifold edges, used by three or more faces.")
                .list(),
        )
        .solve(|s| {
            let brep = brep_item(s, 0)?;
            for (output, kind) in [
                (0, EdgeKind::Naked),
                (1, EdgeKind::Interior),
                (2, EdgeKind::NonManifold),
            ] {
                let curves = brep
                    .edges_of_kind(kind)
                    .into_iter()
                    .map(|e| Some(edge_curve(&brep.edges()[e].curve)))
                    .collect();
                s.set_list_values(output, curves);
            }
            Ok(())
        })
}

/// Brep Join \[Join\]: joins B-reps along coincident edges.
pub fn brep_join() -> NodeType {
    surface_node(BREP_JOIN, "Brep Join", "Join", "Util")
        .gh_guid("1addcc85-b04e-46e6-bd4a-6f6c93bf7efd")
        .description(
            "Joins B-reps into polysurfaces where their naked edges coincide (within 0.001 \
             model units, Rhino's default document tolerance): the edges become one edge \
             shared by both faces. The result has as few B-reps as the edges allow, one per \
             connected group of faces, each with its faces turned to agree (and outwards when \
             it is closed). Edges must match end to end; an edge along part of another is not \
             split to fit. Null items are skipped with a warning.",
        )
        .input(
            Port::new("Breps", "B", DataType::Brep)
                .doc("The B-reps to join (a list).")
                .list(),
        )
        .output(
            Port::new("Breps", "B", DataType::Brep)
                .doc("The joined B-reps.")
                .list(),
        )
        .output(
            Port::new("Closed", "C", DataType::Boolean)
                .doc("For each joined B-rep, whether it is closed (a solid: no naked edges).")
                .list(),
        )
        .solve(|s| {
            let list = s.list::<Shared<Brep>>(0)?;
            let breps: Vec<Brep> = list.present().map(|b| (**b).clone()).collect();
            let nulls = list.len() - breps.len();
            if nulls > 0 {
                s.warning(format!("input B: {nulls} null item(s) left out"));
            }
            let empty = breps.iter().filter(|b| b.faces().is_empty()).count();
            if empty > 0 {
                s.warning(format!("input B: {empty} brep(s) without faces left out"));
            }
            let joined = Brep::join(&breps, JOIN_TOLERANCE)?;
            let closed: Vec<bool> = joined.iter().map(Brep::is_solid).collect();
            s.set_list(0, joined.into_iter().map(Shared::new).collect());
            s.set_list(1, closed);
            Ok(())
        })
}

/// Singular Points \[Sing\]: the points where a side of a face collapses.
pub fn singular_points() -> NodeType {
    surface_node(SINGULAR_POINTS, "Singular Points", "Sing", "Analysis")
        .description(
            "Finds the singular points of a B-rep, as the book's singularity tutorial does \
             (this is not a stock Grasshopper component): every trim without an edge runs \
             along a side of its face's parameter rectangle that collapses to one point, such \
             as a sphere's poles or a cone's apex. For each such trim, in trim order, the \
             point is the face's surface evaluated at the start of the trim. A B-rep without \
             singular trims (a box, a cylinder) gives an empty list.",
        )
        .input(brep_input("to search"))
        .output(
            Port::new("Points", "P", DataType::Point)
                .doc("The singular points, one per singular trim.")
                .list(),
        )
        .solve(|s| {
            let brep = brep_item(s, 0)?;
            let mut points = Vec::new();
            for t in brep.trims() {
                if t.edge.is_some() || t.kind != TrimKind::Singular {
                    continue;
                }
                let face = &brep.faces()[brep.loops()[t.loop_index].face];
                let uv = t.curve.start_point();
                points.push(face.surface.try_point_at(uv.x, uv.y)?);
            }
            s.set_list(0, points);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use locus_kernel::{
        Cone, Cylinder, Interval, OrientedBox, Plane, Point3, Sphere, Transform, Vector3,
    };
    use locus_runtime::{DataTree, Level, NodeCall, NodeCallResult};

    use super::*;
    use crate::vector::test_support::{assert_clean, items, messages};

    fn oracle_breps() -> serde_json::Value {
        locus_test_data::load_oracle("opennurbs-cases.json")["breps"].clone()
    }

    pub(crate) fn box_brep(size: [f64; 3]) -> Shared<Brep> {
        Shared::new(
            Brep::from_box(&OrientedBox::new(
                Plane::WORLD_XY,
                Interval::new(0.0, size[0]),
                Interval::new(0.0, size[1]),
                Interval::new(0.0, size[2]),
            ))
            .unwrap(),
        )
    }

    fn sphere(r: f64) -> Shared<Brep> {
        Shared::new(Brep::from_sphere(&Sphere::new(Point3::ORIGIN, r).unwrap()).unwrap())
    }

    fn run(node: NodeType, brep: Shared<Brep>) -> NodeCallResult {
        NodeCall::new(&node).input(DataTree::from_item(brep)).run()
    }

    fn counts(r: &NodeCallResult) -> (usize, usize, usize) {
        (
            r.outputs[0].item_count(),
            r.outputs[1].item_count(),
            r.outputs[2].item_count(),
        )
    }

    #[test]
    fn deconstruct_brep_matches_the_opennurbs_topology() {
        for case in oracle_breps().as_array().expect("breps") {
            let name = case["name"].as_str().unwrap();
            let brep = if name.starts_with("box-0,0,0-2,3,4") {
                box_brep([2.0, 3.0, 4.0])
            } else if name == "sphere-r2" {
                sphere(2.0)
            } else {
                panic!("unknown brep case {name}");
            };
            let r = run(deconstruct_brep(), brep);
            assert_clean(&r);
            let want = |k: &str| case[k].as_u64().unwrap() as usize;
            assert_eq!(
                counts(&r),
                (want("faces"), want("edges"), want("vertices")),
                "{name}"
            );
            if let Some(locations) = case["vertex_locations"].as_array() {
                let got: Vec<Point3> = items::<Point3>(&r.outputs[2])
                    .into_iter()
                    .flatten()
                    .collect();
                for (g, w) in got.iter().zip(locations) {
                    let w: Vec<f64> = w
                        .as_array()
                        .unwrap()
                        .iter()
                        .map(|x| x.as_f64().unwrap())
                        .collect();
                    assert!(g.distance(Point3::new(w[0], w[1], w[2])) < 1e-12, "{name}");
                }
            }
        }
    }

    #[test]
    fn deconstructed_faces_and_edges() {
        let r = run(deconstruct_brep(), box_brep([2.0, 3.0, 4.0]));
        let faces = items::<Shared<Brep>>(&r.outputs[0]);
        let areas: Vec<f64> = faces
            .iter()
            .map(|f| f.as_ref().unwrap().area().unwrap())
            .collect();
        // Front and back 2 × 4, right and left 3 × 4, bottom and top 2 × 3.
        for (a, want) in areas.iter().zip([8.0, 12.0, 8.0, 12.0, 6.0, 6.0]) {
            assert!((a - want).abs() < 1e-12, "{areas:?}");
        }
        let edges = items::<Shared<Curve>>(&r.outputs[1]);
        assert!(
            edges
                .iter()
                .all(|e| matches!(**e.as_ref().unwrap(), Curve::Line { .. }))
        );
        let total: f64 = edges.iter().map(|e| e.as_ref().unwrap().length()).sum();
        assert!((total - 4.0 * (2.0 + 3.0 + 4.0)).abs() < 1e-12);
        // A sphere's seam is a NURBS half circle of length πr.
        let r = run(deconstruct_brep(), sphere(2.0));
        let seam = items::<Shared<Curve>>(&r.outputs[1]).remove(0).unwrap();
        assert!(matches!(*seam, Curve::Nurbs(_)));
        assert!((seam.length() - 2.0 * PI).abs() < 1e-9);
    }

    #[test]
    fn deconstruct_bad_input() {
        let r = run(deconstruct_brep(), Shared::new(Brep::default()));
        assert_eq!(counts(&r), (0, 0, 0));
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        let nan = box_brep([1.0, 1.0, 1.0]).transformed(&Transform::translation(Vector3::new(
            f64::NAN,
            0.0,
            0.0,
        )));
        assert!(nan.is_err(), "the kernel refuses to make a NaN brep");
        let r = NodeCall::new(&deconstruct_brep())
            .input(DataTree::from_value(Value::Number(1.0)))
            .run();
        assert!(!r.messages.is_empty());
    }

    #[test]
    fn brep_edges_by_kind() {
        let r = run(brep_edges(), box_brep([1.0, 1.0, 1.0]));
        assert_clean(&r);
        assert_eq!(counts(&r), (0, 12, 0));
        let open = Cylinder::new(Plane::WORLD_XY, 1.0, 2.0).unwrap();
        let tube = Shared::new(Brep::from_cylinder(&open, false).unwrap());
        let r = run(brep_edges(), tube);
        assert_eq!(counts(&r), (2, 1, 0));
        let naked = items::<Shared<Curve>>(&r.outputs[0]);
        assert!((naked[0].as_ref().unwrap().length() - 2.0 * PI).abs() < 1e-9);
        // A square with a square hole: eight naked edges, and its area is 16 − 1.
        let square = [
            Point3::ORIGIN,
            Point3::new(4.0, 0.0, 0.0),
            Point3::new(4.0, 4.0, 0.0),
            Point3::new(0.0, 4.0, 0.0),
        ];
        let hole = vec![
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(2.0, 1.0, 0.0),
            Point3::new(2.0, 2.0, 0.0),
            Point3::new(1.0, 2.0, 0.0),
        ];
        let holed = Shared::new(Brep::from_planar_polylines(&square, &[hole], 1e-9).unwrap());
        assert_eq!(counts(&run(brep_edges(), holed.clone())), (8, 0, 0));
        let r = run(deconstruct_brep(), holed);
        assert_eq!(counts(&r), (1, 8, 8));
        let face = items::<Shared<Brep>>(&r.outputs[0]).remove(0).unwrap();
        assert!((face.area().unwrap() - 15.0).abs() < 1e-12);
        // One face of a box: four naked edges.
        let face = Shared::new(box_brep([1.0, 1.0, 1.0]).extract_face(0).unwrap());
        assert_eq!(counts(&run(brep_edges(), face)), (4, 0, 0));
    }

    fn join(breps: Vec<Shared<Brep>>) -> NodeCallResult {
        NodeCall::new(&brep_join())
            .input(DataTree::from_list(breps))
            .run()
    }

    #[test]
    fn brep_join_rebuilds_an_exploded_box() {
        let b = box_brep([2.0, 3.0, 4.0]);
        let faces: Vec<Shared<Brep>> = (0..6)
            .map(|i| Shared::new(b.extract_face(i).unwrap()))
            .collect();
        let r = join(faces.clone());
        assert_clean(&r);
        let joined = items::<Shared<Brep>>(&r.outputs[0]);
        assert_eq!(joined.len(), 1);
        let j = joined[0].as_ref().unwrap();
        assert_eq!(
            (j.faces().len(), j.edges().len(), j.vertices().len()),
            (6, 12, 8)
        );
        assert!((j.volume().unwrap() - 24.0).abs() < 1e-12);
        assert_eq!(items::<bool>(&r.outputs[1]), vec![Some(true)]);
        // Five faces: one open polysurface with four naked edges.
        let r = join(faces[..5].to_vec());
        assert_eq!(items::<bool>(&r.outputs[1]), vec![Some(false)]);
        // A face moved 0.01 away no longer joins: two pieces.
        let mut moved = faces.clone();
        moved[5] = Shared::new(
            moved[5]
                .transformed(&Transform::translation(Vector3::new(0.0, 0.0, 0.01)))
                .unwrap(),
        );
        let r = join(moved);
        assert_eq!(items::<bool>(&r.outputs[1]), vec![Some(false), Some(false)]);
        // Within the tolerance (0.0005) it does.
        let mut near = faces;
        near[5] = Shared::new(
            near[5]
                .transformed(&Transform::translation(Vector3::new(0.0, 0.0, 0.0005)))
                .unwrap(),
        );
        assert_eq!(items::<bool>(&join(near).outputs[1]), vec![Some(true)]);
    }

    #[test]
    fn brep_join_bad_input() {
        let mut tree = DataTree::new();
        let mut with_null = locus_runtime::Branch::new(DataType::Brep);
        with_null.push(box_brep([1.0, 1.0, 1.0]));
        with_null.push_null();
        with_null.push(Shared::new(Brep::default()));
        tree.insert(locus_runtime::TreePath::zero(), with_null);
        let r = NodeCall::new(&brep_join()).input(tree).run();
        assert_eq!(messages(&r, Level::Warning).len(), 2, "{:?}", r.messages);
        assert_eq!(items::<bool>(&r.outputs[1]), vec![Some(true)]);
        let r = join(Vec::new());
        assert_eq!(r.outputs[0].item_count(), 0);
    }

    #[test]
    fn singular_points_of_spheres_and_cones() {
        let r = run(singular_points(), sphere(2.0));
        assert_clean(&r);
        assert_eq!(
            items::<Point3>(&r.outputs[0]),
            vec![
                Some(Point3::new(0.0, 0.0, -2.0)),
                Some(Point3::new(0.0, 0.0, 2.0))
            ]
        );
        let plane =
            Plane::from_normal(Point3::new(1.0, 2.0, 3.0), Vector3::new(0.0, 1.0, 1.0)).unwrap();
        let cone = Cone::new(plane, 4.0, 1.5).unwrap();
        for capped in [false, true] {
            let b = Shared::new(Brep::from_cone(&cone, capped).unwrap());
            let points = items::<Point3>(&run(singular_points(), b).outputs[0]);
            assert_eq!(points.len(), 1);
            // The apex of Rhino's cone is the origin of its plane.
            assert!(points[0].unwrap().distance(plane.origin) < 1e-12);
        }
        let r = run(singular_points(), box_brep([1.0, 1.0, 1.0]));
        assert_eq!(r.outputs[0].item_count(), 0);
        let cyl = Brep::from_cylinder(&Cylinder::new(plane, 1.0, 1.0).unwrap(), true).unwrap();
        assert_eq!(
            run(singular_points(), Shared::new(cyl)).outputs[0].item_count(),
            0
        );
        let r = NodeCall::new(&singular_points()).run();
        assert!(r.outputs[0].is_empty() || r.outputs[0].item_count() == 0);
    }
}
