//! The JSON form of values, data trees and messages, as `locus run --format json` prints them
//! and `locus serve`'s `/v1/run` answers (`docs/json-output.md` documents every shape).
//!
//! The form is written once, here, as [`serde::Serialize`] wrappers over borrowed runtime
//! values: [`ValueJson`], [`TreeJson`] and [`MessageJson`]. They go straight into any serde
//! serializer, so a host can stream a whole answer to a writer
//! (`serde_json::to_writer(out, &TreeJson(&tree))`) without building a document first, or turn
//! them into a `serde_json::Value` with `serde_json::to_value`.
//!
//! Numbers: `-0` is written as `0`, and NaN and the infinities (which JSON cannot hold) as
//! `null`; their nodes report them as messages.
//!
//! ```
//! use locus_runtime::{DataTree, TreeJson};
//! use locus_kernel::Point3;
//!
//! let tree = DataTree::from_list(vec![Point3::new(1.0, 2.0, -0.0)]);
//! let text = serde_json::to_string(&TreeJson(&tree)).unwrap();
//! assert_eq!(text, r#"{"{0}":[{"point":[1.0,2.0,0.0]}]}"#);
//! ```

use locus_kernel::{Brep, Color, Interval, LoopKind, NurbsSurface, Plane, Point3, Vector3};
use serde::ser::{Serialize, SerializeMap, SerializeSeq, Serializer};

use crate::{DataTree, Message, Value};

/// One item in locus's JSON form: a number, integer, boolean or string as itself, anything
/// else as a one-key object naming its kind (`{"point": [x, y, z]}`).
#[derive(Clone, Copy, Debug)]
pub struct ValueJson<'a>(pub &'a Value);

/// A data tree as a JSON object `{"{0;1}": [item, …], …}`, branches in path order, null items
/// as `null`.
#[derive(Clone, Copy, Debug)]
pub struct TreeJson<'a>(pub &'a DataTree);

/// A runtime message as `{"node", "level", "path", "index", "text"}` (`path` and `index` are
/// `null` when the message does not come from one iteration).
#[derive(Clone, Copy, Debug)]
pub struct MessageJson<'a>(pub &'a Message);

/// A number as JSON writes it: `-0` as `0`, NaN and the infinities as `null`.
#[derive(Clone, Copy, Debug)]
struct Num(f64);

impl Serialize for Num {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let x = self.0;
        if x.is_finite() {
            s.serialize_f64(if x == 0.0 { 0.0 } else { x })
        } else {
            s.serialize_none()
        }
    }
}

/// `[x, y, z]`.
struct Xyz(f64, f64, f64);

impl Serialize for Xyz {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        [Num(self.0), Num(self.1), Num(self.2)].serialize(s)
    }
}

fn point(p: Point3) -> Xyz {
    Xyz(p.x, p.y, p.z)
}

fn vector(v: Vector3) -> Xyz {
    Xyz(v.x, v.y, v.z)
}

/// `[t0, t1]`.
fn interval(i: Interval) -> [Num; 2] {
    [Num(i.t0), Num(i.t1)]
}

/// A list of numbers.
struct Nums<'a>(&'a [f64]);

impl Serialize for Nums<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.0.iter().map(|&x| Num(x)))
    }
}

/// A list of points.
struct Points<'a>(&'a [Point3]);

impl Serialize for Points<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.0.iter().map(|&p| point(p)))
    }
}

/// `{"origin", "x", "y", "z"}`.
struct PlaneJson<'a>(&'a Plane);

impl Serialize for PlaneJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let p = self.0;
        let mut m = s.serialize_map(Some(4))?;
        m.serialize_entry("origin", &point(p.origin))?;
        m.serialize_entry("x", &vector(p.x_axis))?;
        m.serialize_entry("y", &vector(p.y_axis))?;
        m.serialize_entry("z", &vector(p.z_axis))?;
        m.end()
    }
}

/// `[r, g, b, a]`, each 0 to 255.
fn colour(c: Color) -> [u8; 4] {
    [c.r, c.g, c.b, c.a]
}

/// `{"degree": [du, dv], "count": [nu, nv], "points", "weights", "knots_u", "knots_v"}`.
struct SurfaceJson<'a>(&'a NurbsSurface);

impl Serialize for SurfaceJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let f = self.0;
        let mut m = s.serialize_map(Some(6))?;
        m.serialize_entry("degree", &[f.degree_u(), f.degree_v()])?;
        m.serialize_entry("count", &[f.count_u(), f.count_v()])?;
        m.serialize_entry("points", &Points(f.points()))?;
        m.serialize_entry("weights", &Nums(f.weights()))?;
        m.serialize_entry("knots_u", &Nums(f.knots_u()))?;
        m.serialize_entry("knots_v", &Nums(f.knots_v()))?;
        m.end()
    }
}

/// `{"faces", "edges", "vertices"}`: each face its untrimmed surface, whether its outward side
/// is against the surface normal, and its loops (the outer one first) as the edges their trims
/// run along (`null` for a trim without an edge: a singular side, such as a sphere's pole).
struct BrepJson<'a>(&'a Brep);

impl Serialize for BrepJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        struct Face<'a>(&'a Brep, usize);
        impl Serialize for Face<'_> {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let (b, face) = (self.0, &self.0.faces()[self.1]);
                let mut m = s.serialize_map(Some(3))?;
                m.serialize_entry("surface", &SurfaceJson(&face.surface))?;
                m.serialize_entry("reversed", &face.reversed)?;
                m.serialize_entry("loops", &Loops(b, &face.loops))?;
                m.end()
            }
        }
        struct Loops<'a>(&'a Brep, &'a [usize]);
        impl Serialize for Loops<'_> {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let b = self.0;
                let mut seq = s.serialize_seq(Some(self.1.len()))?;
                for &l in self.1 {
                    let lp = &b.loops()[l];
                    seq.serialize_element(&Loop(b, lp.kind == LoopKind::Outer, &lp.trims))?;
                }
                seq.end()
            }
        }
        struct Loop<'a>(&'a Brep, bool, &'a [usize]);
        impl Serialize for Loop<'_> {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let trims = self.0.trims();
                let mut m = s.serialize_map(Some(2))?;
                m.serialize_entry("outer", &self.1)?;
                let edges: Vec<Option<usize>> = self.2.iter().map(|&t| trims[t].edge).collect();
                m.serialize_entry("edges", &edges)?;
                m.end()
            }
        }
        struct Edge<'a>(&'a locus_kernel::BrepEdge);
        impl Serialize for Edge<'_> {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let c = &self.0.curve;
                let mut m = s.serialize_map(Some(5))?;
                m.serialize_entry("degree", &c.degree())?;
                m.serialize_entry("points", &Points(c.points()))?;
                m.serialize_entry("weights", &Nums(c.weights()))?;
                m.serialize_entry("knots", &Nums(c.knots()))?;
                m.serialize_entry("vertices", &self.0.vertices)?;
                m.end()
            }
        }
        let b = self.0;
        let mut m = s.serialize_map(Some(3))?;
        m.serialize_entry(
            "faces",
            &Seq((0..b.faces().len()).map(|k| Face(b, k)).collect()),
        )?;
        m.serialize_entry("edges", &Seq(b.edges().iter().map(Edge).collect()))?;
        m.serialize_entry(
            "vertices",
            &Seq(b.vertices().iter().map(|v| point(v.point)).collect()),
        )?;
        m.end()
    }
}

/// A list of serializable parts.
struct Seq<T>(Vec<T>);

impl<T: Serialize> Serialize for Seq<T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(&self.0)
    }
}

/// A one-key object `{key: value}`.
fn tagged<S: Serializer, T: Serialize + ?Sized>(
    s: S,
    key: &str,
    value: &T,
) -> Result<S::Ok, S::Error> {
    let mut m = s.serialize_map(Some(1))?;
    m.serialize_entry(key, value)?;
    m.end()
}

impl Serialize for ValueJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self.0 {
            Value::Number(x) => Num(*x).serialize(s),
            Value::Integer(i) => s.serialize_i64(*i),
            Value::Boolean(b) => s.serialize_bool(*b),
            Value::Text(t) => s.serialize_str(t),
            Value::Point(p) => tagged(s, "point", &point(*p)),
            Value::Vector(v) => tagged(s, "vector", &vector(*v)),
            Value::Plane(p) => tagged(s, "plane", &PlaneJson(p)),
            Value::Domain(d) => tagged(s, "domain", &interval(*d)),
            Value::Domain2(d) => {
                struct Domain2Json(locus_kernel::UvInterval);
                impl Serialize for Domain2Json {
                    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                        let mut m = s.serialize_map(Some(2))?;
                        m.serialize_entry("u", &interval(self.0.u))?;
                        m.serialize_entry("v", &interval(self.0.v))?;
                        m.end()
                    }
                }
                tagged(s, "domain2", &Domain2Json(*d))
            }
            Value::Transform(t) => {
                let rows = t.to_rows();
                let rows: Vec<Nums<'_>> = rows.iter().map(|r| Nums(r)).collect();
                tagged(s, "transform", &Seq(rows))
            }
            Value::Box(b) => {
                struct BoxJson<'a>(&'a locus_kernel::OrientedBox);
                impl Serialize for BoxJson<'_> {
                    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                        let b = self.0;
                        let mut m = s.serialize_map(Some(4))?;
                        m.serialize_entry("plane", &PlaneJson(&b.plane))?;
                        m.serialize_entry("x", &interval(b.x))?;
                        m.serialize_entry("y", &interval(b.y))?;
                        m.serialize_entry("z", &interval(b.z))?;
                        m.end()
                    }
                }
                tagged(s, "box", &BoxJson(b))
            }
            Value::Line(l) => tagged(s, "line", &[point(l.from), point(l.to)]),
            Value::Circle(c) => {
                struct CircleJson<'a>(&'a locus_kernel::Circle);
                impl Serialize for CircleJson<'_> {
                    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                        let mut m = s.serialize_map(Some(2))?;
                        m.serialize_entry("plane", &PlaneJson(&self.0.plane))?;
                        m.serialize_entry("radius", &Num(self.0.radius))?;
                        m.end()
                    }
                }
                tagged(s, "circle", &CircleJson(c))
            }
            Value::Arc(a) => {
                struct ArcJson<'a>(&'a locus_kernel::Arc);
                impl Serialize for ArcJson<'_> {
                    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                        let a = self.0;
                        let mut m = s.serialize_map(Some(3))?;
                        m.serialize_entry("plane", &PlaneJson(&a.circle.plane))?;
                        m.serialize_entry("radius", &Num(a.circle.radius))?;
                        m.serialize_entry("angle", &interval(a.angle))?;
                        m.end()
                    }
                }
                tagged(s, "arc", &ArcJson(a))
            }
            Value::Curve(c) => {
                struct CurveJson<'a>(&'a locus_kernel::NurbsCurve, Interval);
                impl Serialize for CurveJson<'_> {
                    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                        let n = self.0;
                        let mut m = s.serialize_map(Some(6))?;
                        m.serialize_entry("degree", &n.degree())?;
                        m.serialize_entry("points", &Points(n.points()))?;
                        m.serialize_entry("weights", &Nums(n.weights()))?;
                        m.serialize_entry("knots", &Nums(n.knots()))?;
                        m.serialize_entry("periodic", &n.is_periodic())?;
                        m.serialize_entry("domain", &interval(self.1))?;
                        m.end()
                    }
                }
                tagged(s, "curve", &CurveJson(&c.to_nurbs(), c.domain()))
            }
            Value::Surface(f) => tagged(s, "surface", &SurfaceJson(f)),
            Value::Brep(b) => tagged(s, "brep", &BrepJson(b)),
            Value::Mesh(mesh) => {
                struct MeshJson<'a>(&'a locus_kernel::Mesh);
                impl Serialize for MeshJson<'_> {
                    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                        let mesh = self.0;
                        let normals = mesh.normals();
                        let colours = mesh.colors();
                        let n = 2 + usize::from(normals.is_some()) + usize::from(colours.is_some());
                        let mut m = s.serialize_map(Some(n))?;
                        m.serialize_entry("vertices", &Points(mesh.vertices()))?;
                        // Faces as three or four vertex indices (a triangle does not repeat
                        // its last).
                        m.serialize_entry(
                            "faces",
                            &Seq(mesh.faces().iter().map(|f| f.corners()).collect()),
                        )?;
                        if let Some(normals) = normals {
                            m.serialize_entry(
                                "normals",
                                &Seq(normals.iter().map(|&v| vector(v)).collect()),
                            )?;
                        }
                        if let Some(colours) = colours {
                            m.serialize_entry(
                                "colours",
                                &Seq(colours.iter().map(|&c| colour(c)).collect()),
                            )?;
                        }
                        m.end()
                    }
                }
                tagged(s, "mesh", &MeshJson(mesh))
            }
            Value::Colour(c) => tagged(s, "colour", &colour(*c)),
        }
    }
}

impl Serialize for TreeJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        struct Items<'a>(&'a crate::Branch);
        impl Serialize for Items<'_> {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let mut seq = s.serialize_seq(Some(self.0.len()))?;
                for item in self.0.values() {
                    seq.serialize_element(&item.as_ref().map(ValueJson))?;
                }
                seq.end()
            }
        }
        let branches = self.0.branches();
        let mut m = s.serialize_map(Some(branches.len()))?;
        for (path, branch) in branches {
            m.serialize_entry(&path.to_string(), &Items(branch))?;
        }
        m.end()
    }
}

impl Serialize for MessageJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let msg = self.0;
        let mut m = s.serialize_map(Some(5))?;
        m.serialize_entry("node", &msg.node.0)?;
        m.serialize_entry("level", msg.level.name())?;
        m.serialize_entry("path", &msg.path.as_ref().map(ToString::to_string))?;
        m.serialize_entry("index", &msg.index)?;
        m.serialize_entry("text", &msg.text)?;
        m.end()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Branch, DataType, Level, NodeId, TreePath};
    use locus_kernel::{
        Arc, Circle, Curve, Mesh, MeshFace, NurbsCurve, OrientedBox, Sphere, Transform,
    };
    use std::sync::Arc as Shared;

    fn text(v: Value) -> String {
        serde_json::to_string(&ValueJson(&v)).unwrap()
    }

    #[test]
    fn plain_items_and_awkward_numbers() {
        assert_eq!(text(Value::Number(1.5)), "1.5");
        assert_eq!(text(Value::Number(-0.0)), "0.0");
        assert_eq!(text(Value::Number(f64::NAN)), "null");
        assert_eq!(text(Value::Number(f64::NEG_INFINITY)), "null");
        assert_eq!(text(Value::Number(1e-300)), "1e-300");
        assert_eq!(text(Value::Integer(i64::MIN)), "-9223372036854775808");
        assert_eq!(text(Value::Boolean(false)), "false");
        assert_eq!(
            text(Value::Text("a \"q\"\n\u{1b}".into())),
            r#""a \"q\"\n\u001b""#
        );
    }

    #[test]
    fn geometry_items_are_one_key_objects() {
        let plane = Plane::WORLD_XY;
        let xy =
            r#"{"origin":[0.0,0.0,0.0],"x":[1.0,0.0,0.0],"y":[0.0,1.0,0.0],"z":[0.0,0.0,1.0]}"#;
        assert_eq!(
            text(Value::Point(Point3::new(1.0, -0.0, f64::NAN))),
            r#"{"point":[1.0,0.0,null]}"#
        );
        assert_eq!(
            text(Value::Vector(Vector3::new(0.0, 1.0, -2.0))),
            r#"{"vector":[0.0,1.0,-2.0]}"#
        );
        assert_eq!(text(Value::Plane(plane)), format!(r#"{{"plane":{xy}}}"#));
        assert_eq!(
            text(Value::Domain(Interval::new(-1.0, 2.0))),
            r#"{"domain":[-1.0,2.0]}"#
        );
        let circle = Circle::new(plane, 2.0).unwrap();
        assert_eq!(
            text(Value::Circle(circle)),
            format!(r#"{{"circle":{{"plane":{xy},"radius":2.0}}}}"#)
        );
        let arc = Arc::new(circle, Interval::new(0.0, 1.5)).unwrap();
        assert_eq!(
            text(Value::Arc(arc)),
            format!(r#"{{"arc":{{"plane":{xy},"radius":2.0,"angle":[0.0,1.5]}}}}"#)
        );
        let b = OrientedBox::new(
            plane,
            Interval::new(0.0, 1.0),
            Interval::new(0.0, 2.0),
            Interval::new(0.0, 3.0),
        );
        assert_eq!(
            text(Value::Box(b)),
            format!(r#"{{"box":{{"plane":{xy},"x":[0.0,1.0],"y":[0.0,2.0],"z":[0.0,3.0]}}}}"#)
        );
        assert_eq!(
            text(Value::Line(locus_kernel::Line::new(
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0)
            ))),
            r#"{"line":[[0.0,0.0,0.0],[1.0,0.0,0.0]]}"#
        );
        assert_eq!(
            text(Value::Transform(Transform::IDENTITY)),
            r#"{"transform":[[1.0,0.0,0.0,0.0],[0.0,1.0,0.0,0.0],[0.0,0.0,1.0,0.0],[0.0,0.0,0.0,1.0]]}"#
        );
        assert_eq!(
            text(Value::Colour(Color {
                r: 1,
                g: 2,
                b: 3,
                a: 4
            })),
            r#"{"colour":[1,2,3,4]}"#
        );
    }

    #[test]
    fn curves_meshes_and_breps() {
        let nurbs = NurbsCurve::new_non_rational(
            1,
            vec![Point3::ORIGIN, Point3::new(2.0, 0.0, 0.0)],
            vec![0.0, 1.0],
        )
        .unwrap();
        assert_eq!(
            text(Value::Curve(Shared::new(Curve::from(nurbs)))),
            r#"{"curve":{"degree":1,"points":[[0.0,0.0,0.0],[2.0,0.0,0.0]],"weights":[1.0,1.0],"knots":[0.0,1.0],"periodic":false,"domain":[0.0,1.0]}}"#
        );
        let mesh = Mesh::new(
            vec![
                Point3::ORIGIN,
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(0.0, 1.0, 0.0),
            ],
            vec![MeshFace::triangle(0, 1, 2)],
        )
        .unwrap();
        assert_eq!(
            text(Value::Mesh(Shared::new(mesh.clone()))),
            r#"{"mesh":{"vertices":[[0.0,0.0,0.0],[1.0,0.0,0.0],[0.0,1.0,0.0]],"faces":[[0,1,2]]}}"#
        );
        let coloured = mesh
            .with_computed_normals()
            .with_colors(vec![
                Color {
                    r: 9,
                    g: 8,
                    b: 7,
                    a: 255
                };
                3
            ])
            .unwrap();
        let j: serde_json::Value =
            serde_json::from_str(&text(Value::Mesh(Shared::new(coloured)))).unwrap();
        let mut keys: Vec<&String> = j["mesh"].as_object().unwrap().keys().collect();
        keys.sort();
        assert_eq!(keys, ["colours", "faces", "normals", "vertices"]);
        assert_eq!(j["mesh"]["normals"][0], serde_json::json!([0.0, 0.0, 1.0]));
        assert_eq!(j["mesh"]["colours"][2], serde_json::json!([9, 8, 7, 255]));
        // A sphere: one face whose loop has two singular trims (the poles), `null` edges.
        let sphere =
            Brep::from_sphere(&Sphere::new(Point3::new(0.0, 0.0, 1.0), 1.5).unwrap()).unwrap();
        let j: serde_json::Value =
            serde_json::from_str(&text(Value::Brep(Shared::new(sphere.clone())))).unwrap();
        let brep = &j["brep"];
        assert_eq!(
            brep["faces"].as_array().unwrap().len(),
            sphere.faces().len()
        );
        let edges = &brep["faces"][0]["loops"][0]["edges"];
        assert!(
            edges
                .as_array()
                .unwrap()
                .iter()
                .any(serde_json::Value::is_null),
            "{edges}"
        );
        assert_eq!(brep["faces"][0]["loops"][0]["outer"], true);
        assert_eq!(
            brep["vertices"].as_array().unwrap().len(),
            sphere.vertices().len()
        );
        assert_eq!(
            brep["faces"][0]["surface"]["degree"],
            serde_json::json!([2, 2])
        );
    }

    #[test]
    fn trees_and_messages() {
        let mut tree = DataTree::new();
        let mut b = Branch::new(DataType::Number);
        b.push_value(Value::Number(1.0));
        b.push_null();
        tree.insert(TreePath::new(vec![0, 2]), b);
        tree.insert(TreePath::new(vec![1]), Branch::new(DataType::Number));
        assert_eq!(
            serde_json::to_string(&TreeJson(&tree)).unwrap(),
            r#"{"{0;2}":[1.0,null],"{1}":[]}"#
        );
        assert_eq!(
            serde_json::to_string_pretty(&TreeJson(&DataTree::new())).unwrap(),
            "{}"
        );
        let m = Message {
            node: NodeId("n".into()),
            level: Level::Warning,
            path: Some(TreePath::new(vec![0, 1])),
            index: Some(3),
            text: "bad".into(),
        };
        assert_eq!(
            serde_json::to_string(&MessageJson(&m)).unwrap(),
            r#"{"node":"n","level":"warning","path":"{0;1}","index":3,"text":"bad"}"#
        );
        let m = Message {
            path: None,
            index: None,
            ..m
        };
        assert_eq!(
            serde_json::to_string(&MessageJson(&m)).unwrap(),
            r#"{"node":"n","level":"warning","path":null,"index":null,"text":"bad"}"#
        );
    }

    #[test]
    fn streams_into_a_writer_as_it_prints_to_a_string() {
        let tree = DataTree::from_list(vec![1.0, 2.5]);
        let mut out = Vec::new();
        serde_json::to_writer_pretty(&mut out, &TreeJson(&tree)).unwrap();
        assert_eq!(
            String::from_utf8(out).unwrap(),
            serde_json::to_string_pretty(&serde_json::to_value(TreeJson(&tree)).unwrap()).unwrap()
        );
    }
}
