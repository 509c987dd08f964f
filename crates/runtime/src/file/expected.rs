//! Expected outputs as `locus test` reads and writes them: literal trees whose items are values,
//! or, for B-reps (which have no literal form), a summary of what can be checked.
//!
//! A B-rep item is expected as
//!
//! ```ron
//! Brep(faces: 6, edges: 12, vertices: 8, area: 52.0, volume: 24.0,
//!      bbox: ((0.0, 0.0, 0.0), (2.0, 3.0, 4.0)))
//! ```
//!
//! Counts compare exactly; area, volume and the corners of the tight bounding box within
//! [`BREP_SUMMARY_TOLERANCE`] (relative). `volume` is left out for an open B-rep (it encloses
//! none) and `area` for a B-rep without area; an expectation that has them fails on a B-rep that
//! does not. Every other item is an ordinary literal read against the output's type, so a
//! Generic output may mix both.

use locus_kernel::{BoundingBox, Brep, Point3};

use crate::file::literal::{LiteralError, error, item_node, parse_item};
use crate::file::syntax::{self, Kind, Node};
use crate::{DataTree, DataType, Literal, TreePath, Value};

/// The relative tolerance for the area, volume and bounding box of a B-rep summary: 1e-6.
///
/// Area and volume come from numerical integration over the faces and the bounding box from
/// sampled extremes of trimmed faces, so their last digits depend on quadrature and sampling
/// details that are not part of the result a user compares; counts are compared exactly.
pub const BREP_SUMMARY_TOLERANCE: f64 = 1e-6;

/// What a regression test checks of a B-rep: its topology counts, area, volume and bounding box.
#[derive(Clone, Debug, PartialEq)]
pub struct BrepSummary {
    /// The number of faces.
    pub faces: usize,
    /// The number of edges.
    pub edges: usize,
    /// The number of vertices.
    pub vertices: usize,
    /// The total area, when the B-rep has one.
    pub area: Option<f64>,
    /// The enclosed volume, for a closed B-rep.
    pub volume: Option<f64>,
    /// The tight axis-aligned bounding box.
    pub bbox: BoundingBox,
}

impl BrepSummary {
    /// The summary of a B-rep.
    pub fn of(brep: &Brep) -> Self {
        Self {
            faces: brep.faces().len(),
            edges: brep.edges().len(),
            vertices: brep.vertices().len(),
            area: brep.area().ok(),
            volume: if brep.is_solid() {
                brep.volume().ok()
            } else {
                None
            },
            bbox: brep.bounding_box(),
        }
    }

    /// The differences from an expected summary (`area: expected 52, got 51.9`); empty when
    /// they agree within [`BREP_SUMMARY_TOLERANCE`].
    pub fn differences(&self, expected: &BrepSummary) -> Vec<String> {
        let mut out = Vec::new();
        for (what, got, want) in [
            ("faces", self.faces, expected.faces),
            ("edges", self.edges, expected.edges),
            ("vertices", self.vertices, expected.vertices),
        ] {
            if got != want {
                out.push(format!("{what}: expected {want}, got {got}"));
            }
        }
        for (what, got, want) in [
            ("area", self.area, expected.area),
            ("volume", self.volume, expected.volume),
        ] {
            match (got, want) {
                (Some(g), Some(w)) if !near(g, w) => {
                    out.push(format!("{what}: expected {w}, got {g}"));
                }
                (None, Some(w)) => out.push(format!("{what}: expected {w}, got none")),
                (Some(g), None) => out.push(format!("{what}: expected none, got {g}")),
                _ => {}
            }
        }
        let corners = |b: &BoundingBox| [b.min.to_array(), b.max.to_array()].concat();
        if !corners(&self.bbox)
            .iter()
            .zip(corners(&expected.bbox))
            .all(|(g, w)| near(*g, w))
        {
            out.push(format!(
                "bbox: expected {}, got {}",
                bbox_text(&expected.bbox),
                bbox_text(&self.bbox)
            ));
        }
        out
    }

    /// The summary's literal syntax, `Brep(faces: …, …)`.
    pub(crate) fn node(&self) -> Node {
        let number = |x: f64| Node::new(Kind::Number(format!("{x:?}")));
        let count = |n: usize| Node::new(Kind::Number(n.to_string()));
        let point = |p: Point3| Node::new(Kind::Tuple(None, p.to_array().map(number).to_vec()));
        let mut fields = vec![
            field("faces", count(self.faces)),
            field("edges", count(self.edges)),
            field("vertices", count(self.vertices)),
        ];
        if let Some(a) = self.area {
            fields.push(field("area", number(a)));
        }
        if let Some(v) = self.volume {
            fields.push(field("volume", number(v)));
        }
        fields.push(field(
            "bbox",
            Node::new(Kind::Tuple(
                None,
                vec![point(self.bbox.min), point(self.bbox.max)],
            )),
        ));
        Node::new(Kind::Struct(Some("Brep".to_owned()), fields))
    }
}

fn field(name: &str, value: Node) -> syntax::Field {
    syntax::Field {
        name: name.to_owned(),
        name_span: 0..0,
        value,
    }
}

fn near(a: f64, b: f64) -> bool {
    a == b || (a - b).abs() <= BREP_SUMMARY_TOLERANCE * 1f64.max(a.abs()).max(b.abs())
}

fn bbox_text(b: &BoundingBox) -> String {
    let p = |p: Point3| format!("({}, {}, {})", p.x, p.y, p.z);
    format!("({}, {})", p(b.min), p(b.max))
}

/// One expected item.
#[derive(Clone, Debug, PartialEq)]
pub enum ExpectedItem {
    /// A value, compared as [`crate::values_agree`] does.
    Value(Value),
    /// A B-rep, compared by its summary.
    Brep(BrepSummary),
}

/// An expected output tree: branches of expected items (`None` for a null).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ExpectedTree {
    /// The branches in path order.
    pub branches: Vec<(TreePath, Vec<Option<ExpectedItem>>)>,
}

impl ExpectedTree {
    /// Reads an expected value written for an output of type `data_type`.
    ///
    /// # Errors
    /// A [`LiteralError`] as for any literal, or for a malformed B-rep summary.
    pub fn parse(literal: &Literal, data_type: DataType) -> Result<Self, LiteralError> {
        let node = syntax::parse(&literal.0).map_err(|e| LiteralError {
            message: e.message,
            span: e.offset..e.offset,
        })?;
        Self::from_node(&node, data_type)
    }

    /// Reads an expected value from its syntax (the shapes of [`crate::parse_literal`]).
    pub(crate) fn from_node(node: &Node, data_type: DataType) -> Result<Self, LiteralError> {
        let items = |items: &[Node]| -> Result<Vec<Option<ExpectedItem>>, LiteralError> {
            items.iter().map(|n| expected_item(n, data_type)).collect()
        };
        let mut branches = Vec::new();
        match &node.kind {
            Kind::Map(entries) => {
                for (key, value) in entries {
                    let Kind::Str(text) = &key.kind else {
                        return error(
                            key,
                            format!(
                                "expected a tree path in quotes such as \"{{0;1}}\", found {}",
                                key.describe()
                            ),
                        );
                    };
                    let path: TreePath = text.parse().or_else(|e| error(key, format!("{e}")))?;
                    if branches.iter().any(|(p, _)| *p == path) {
                        return error(key, format!("duplicate path {path}"));
                    }
                    let Kind::List(list) = &value.kind else {
                        return error(
                            value,
                            format!(
                                "expected the list of items of branch {path}, found {}",
                                value.describe()
                            ),
                        );
                    };
                    branches.push((path, items(list)?));
                }
                branches.sort_by(|a, b| a.0.cmp(&b.0));
            }
            Kind::List(list) => branches.push((TreePath::zero(), items(list)?)),
            _ => branches.push((TreePath::zero(), items(std::slice::from_ref(node))?)),
        }
        Ok(Self { branches })
    }
}

/// Whether a syntax node is a B-rep summary, `Brep(faces: …)`.
pub(crate) fn is_brep_summary(node: &Node) -> bool {
    matches!(&node.kind, Kind::Struct(Some(tag), fields)
        if tag == "Brep" && fields.iter().any(|f| f.name == "faces"))
}

fn expected_item(node: &Node, data_type: DataType) -> Result<Option<ExpectedItem>, LiteralError> {
    if is_brep_summary(node) {
        if !matches!(data_type, DataType::Brep | DataType::Generic) {
            return error(
                node,
                format!("a B-rep summary for an output of type {}", data_type.name()),
            );
        }
        return brep_summary(node).map(|s| Some(ExpectedItem::Brep(s)));
    }
    Ok(parse_item(node, data_type)?.map(ExpectedItem::Value))
}

const SUMMARY_FIELDS: &[&str] = &["faces", "edges", "vertices", "area", "volume", "bbox"];

fn brep_summary(node: &Node) -> Result<BrepSummary, LiteralError> {
    let Kind::Struct(_, fields) = &node.kind else {
        return error(node, "expected a B-rep summary Brep(faces: …)".to_owned());
    };
    for (i, f) in fields.iter().enumerate() {
        if !SUMMARY_FIELDS.contains(&f.name.as_str()) {
            return error(
                &f.value,
                format!(
                    "unknown field {} of a B-rep summary (its fields are: {})",
                    f.name,
                    SUMMARY_FIELDS.join(", ")
                ),
            );
        }
        if fields[..i].iter().any(|g| g.name == f.name) {
            return error(
                &f.value,
                format!("repeated field {} of a B-rep summary", f.name),
            );
        }
    }
    let get = |name: &str| fields.iter().find(|f| f.name == name).map(|f| &f.value);
    let count = |name: &str| -> Result<usize, LiteralError> {
        let Some(v) = get(name) else {
            return error(node, format!("a B-rep summary needs the field {name}"));
        };
        match &v.kind {
            Kind::Number(n) => n
                .parse()
                .or_else(|_| error(v, format!("expected a count for {name}, found {n}"))),
            _ => error(
                v,
                format!("expected a count for {name}, found {}", v.describe()),
            ),
        }
    };
    let number = |v: &Node| -> Result<f64, LiteralError> {
        match &v.kind {
            Kind::Number(n) => match crate::parse_number(n) {
                Some(x) => Ok(x),
                None => error(v, format!("expected a number, found {n}")),
            },
            _ => error(v, format!("expected a number, found {}", v.describe())),
        }
    };
    let point = |v: &Node| -> Result<Point3, LiteralError> {
        match &v.kind {
            Kind::Tuple(None, xs) if xs.len() == 3 => Ok(Point3::new(
                number(&xs[0])?,
                number(&xs[1])?,
                number(&xs[2])?,
            )),
            _ => error(
                v,
                format!("expected a point (x, y, z), found {}", v.describe()),
            ),
        }
    };
    let bbox = match get("bbox") {
        None => return error(node, "a B-rep summary needs the field bbox".to_owned()),
        Some(v) => match &v.kind {
            Kind::Tuple(None, corners) if corners.len() == 2 => BoundingBox {
                min: point(&corners[0])?,
                max: point(&corners[1])?,
            },
            _ => {
                return error(
                    v,
                    format!(
                        "expected a bounding box ((x, y, z), (x, y, z)), found {}",
                        v.describe()
                    ),
                );
            }
        },
    };
    Ok(BrepSummary {
        faces: count("faces")?,
        edges: count("edges")?,
        vertices: count("vertices")?,
        area: get("area").map(number).transpose()?,
        volume: get("volume").map(number).transpose()?,
        bbox,
    })
}

/// The expectation literal of an output tree: [`Literal::from_tree`], except that B-reps are
/// written as their summaries.
///
/// # Errors
/// A [`LiteralError`] for a value type that has neither a literal nor a summary form.
pub fn expectation_literal(tree: &DataTree) -> Result<Literal, LiteralError> {
    Ok(Literal(expectation_node(tree)?.to_compact()))
}

/// The syntax of [`expectation_literal`].
pub(crate) fn expectation_node(tree: &DataTree) -> Result<Node, LiteralError> {
    let has_brep = tree
        .branches()
        .iter()
        .any(|(_, b)| b.values().any(|v| matches!(v, Some(Value::Brep(_)))));
    if !has_brep {
        return crate::file::literal::tree_node(tree);
    }
    let items = |branch: &crate::Branch| -> Result<Vec<Node>, LiteralError> {
        let generic = branch.data_type() == DataType::Generic;
        branch
            .values()
            .map(|v| match v {
                Some(Value::Brep(b)) => Ok(BrepSummary::of(&b).node()),
                Some(v) => item_node(&v, generic),
                None => Ok(Node::new(Kind::Ident("null".to_owned()))),
            })
            .collect()
    };
    let branches = tree.branches();
    if let [(path, branch)] = branches
        && *path == TreePath::zero()
    {
        let mut list = items(branch)?;
        if list.len() == 1 && !branch.is_null(0) {
            return Ok(list.swap_remove(0));
        }
        return Ok(Node::new(Kind::List(list)));
    }
    let mut entries = Vec::with_capacity(branches.len());
    for (path, branch) in branches {
        entries.push((
            Node::new(Kind::Str(path.to_string())),
            Node::new(Kind::List(items(branch)?)),
        ));
    }
    Ok(Node::new(Kind::Map(entries)))
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Interval, OrientedBox, Plane};

    use super::*;
    use crate::Shared;

    fn box_brep(x: f64) -> Shared<Brep> {
        let b = OrientedBox::new(
            Plane::WORLD_XY,
            Interval::new(0.0, x),
            Interval::new(0.0, 3.0),
            Interval::new(0.0, 4.0),
        );
        Shared::new(Brep::from_box(&b).expect("a box B-rep"))
    }

    #[test]
    fn a_box_is_summarised_and_reads_back() {
        let tree = DataTree::from_item(box_brep(2.0));
        let literal = expectation_literal(&tree).expect("a literal");
        assert!(
            literal
                .0
                .starts_with("Brep(faces: 6, edges: 12, vertices: 8, area: 5"),
            "{}",
            literal.0
        );
        assert!(
            literal
                .0
                .ends_with("bbox: ((0.0, 0.0, 0.0), (2.0, 3.0, 4.0)))"),
            "{}",
            literal.0
        );
        let expected = ExpectedTree::parse(&literal, DataType::Brep).expect("reads");
        let Some(ExpectedItem::Brep(summary)) = &expected.branches[0].1[0] else {
            panic!("{expected:?}");
        };
        assert!(
            BrepSummary::of(&box_brep(2.0))
                .differences(summary)
                .is_empty()
        );
        let wider = BrepSummary::of(&box_brep(2.5)).differences(summary);
        assert_eq!(wider.len(), 3, "{wider:?}");
        assert!(wider[0].starts_with("area: expected 5"), "{wider:?}");
    }

    #[test]
    fn malformed_summaries_are_errors() {
        for (text, message) in [
            (
                "Brep(faces: 1, edges: 1, vertices: 1)",
                "needs the field bbox",
            ),
            (
                "Brep(faces: 1, edges: 1, bbox: ((0,0,0),(1,1,1)))",
                "needs the field vertices",
            ),
            (
                "Brep(faces: -1, edges: 1, vertices: 1, bbox: ((0,0,0),(1,1,1)))",
                "expected a count",
            ),
            (
                "Brep(faces: 1, edges: 1, vertices: 1, colour: 2, bbox: ((0,0,0),(1,1,1)))",
                "unknown field colour",
            ),
            (
                "Brep(faces: 1, edges: 1, vertices: 1, bbox: (0, 1))",
                "expected a point",
            ),
            (
                "Brep(faces: 1, edges: 1, vertices: 1, bbox: 3)",
                "expected a bounding box",
            ),
        ] {
            let e = ExpectedTree::parse(&Literal(text.to_owned()), DataType::Brep).unwrap_err();
            assert!(e.message.contains(message), "{text}: {}", e.message);
        }
        let e = ExpectedTree::parse(
            &Literal("Brep(faces: 1, edges: 1, vertices: 1, bbox: ((0,0,0),(1,1,1)))".to_owned()),
            DataType::Number,
        )
        .unwrap_err();
        assert!(e.message.contains("type Number"), "{}", e.message);
    }

    #[test]
    fn generic_trees_mix_values_and_summaries() {
        let mut tree = DataTree::new();
        let mut branch = crate::Branch::new(DataType::Generic);
        branch.push_option(Some(Value::Brep(box_brep(1.0))));
        branch.push_option(Some(Value::Number(2.0)));
        branch.push_option(None);
        tree.insert(TreePath::from([0, 1]), branch);
        let literal = expectation_literal(&tree).expect("a literal");
        assert!(
            literal.0.starts_with("{\"{0;1}\": [Brep(faces: 6"),
            "{}",
            literal.0
        );
        assert!(literal.0.ends_with(", 2.0, null]}"), "{}", literal.0);
        let expected = ExpectedTree::parse(&literal, DataType::Generic).expect("reads");
        assert_eq!(expected.branches[0].1.len(), 3);
        assert_eq!(
            expected.branches[0].1[1],
            Some(ExpectedItem::Value(Value::Number(2.0)))
        );
    }
}
