//! The exchange form of values between the engine and a script worker process.
//!
//! Values cross the process boundary as bytes, written and read by this module on both sides
//! (the engine, and the worker through the `locus` Python package, which links this crate), so
//! that both agree by construction. Every form is exact: numbers are their `f64` bits, and
//! what is read back goes through the same validating constructors as a graph file's values.
//!
//! | item | bytes after its tag |
//! | --- | --- |
//! | null | nothing |
//! | Number, Integer | 8 bytes, little-endian |
//! | Boolean | 1 byte |
//! | Text | its UTF-8 bytes, with their count |
//! | Point, Vector | x, y, z |
//! | Surface | degrees, counts, points, weights and knots, through `NurbsSurface::from_flat` |
//! | Brep | vertices, edges, trims, loops and faces, through `Brep::from_parts` |
//! | any other type | its name and the graph format's literal text of the item (planes, boxes, lines, circles, arcs, curves of every kind, meshes, colours…), read back against that type |
//!
//! Counts are `u32`. A [`Decoder`] never trusts them: a count larger than the bytes left is an
//! error before anything is allocated, so a truncated or corrupt message is an error, never a
//! panic or an unbounded allocation.

use locus_kernel::{
    Brep, BrepEdge, BrepFace, BrepLoop, BrepTrim, BrepVertex, LoopKind, NurbsCurve, NurbsSurface,
    Point3, TrimKind, Vector3,
};
use locus_runtime::{Branch, DataTree, DataType, Literal, Shared, TreePath, Value};

/// Why bytes could not be read as values.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DecodeError(pub String);

impl std::fmt::Display for DecodeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for DecodeError {}

const NULL: u8 = 0;
const NUMBER: u8 = 1;
const INTEGER: u8 = 2;
const BOOLEAN: u8 = 3;
const TEXT: u8 = 4;
const POINT: u8 = 5;
const VECTOR: u8 = 6;
const SURFACE: u8 = 7;
const BREP: u8 = 8;
const LITERAL: u8 = 9;

/// Writes values and the plain parts of messages into a byte buffer.
#[derive(Clone, Debug, Default)]
pub struct Encoder {
    buf: Vec<u8>,
}

impl Encoder {
    /// An empty buffer.
    pub fn new() -> Self {
        Self::default()
    }

    /// The bytes written so far.
    pub fn into_bytes(self) -> Vec<u8> {
        self.buf
    }

    /// Writes one byte.
    pub fn u8(&mut self, x: u8) {
        self.buf.push(x);
    }

    /// Writes a boolean as one byte.
    pub fn bool(&mut self, x: bool) {
        self.buf.push(u8::from(x));
    }

    /// Writes a count or an index. Counts above `u32::MAX` cannot occur: the runtime's item
    /// budget is far below it, and the value is saturated rather than wrapped.
    pub fn count(&mut self, n: usize) {
        let n = u32::try_from(n).unwrap_or(u32::MAX);
        self.buf.extend_from_slice(&n.to_le_bytes());
    }

    /// Writes a number.
    pub fn f64(&mut self, x: f64) {
        self.buf.extend_from_slice(&x.to_le_bytes());
    }

    /// Writes an integer.
    pub fn i64(&mut self, x: i64) {
        self.buf.extend_from_slice(&x.to_le_bytes());
    }

    /// Writes a text.
    pub fn str(&mut self, s: &str) {
        self.count(s.len());
        self.buf.extend_from_slice(s.as_bytes());
    }

    fn xyz(&mut self, c: [f64; 3]) {
        for x in c {
            self.f64(x);
        }
    }

    fn f64s(&mut self, xs: &[f64]) {
        self.count(xs.len());
        for &x in xs {
            self.f64(x);
        }
    }

    fn points(&mut self, ps: &[Point3]) {
        self.count(ps.len());
        for p in ps {
            self.xyz(p.to_array());
        }
    }

    /// Writes one item, `None` for a null.
    ///
    /// # Errors
    /// When the value has no exchange form (every value type has one today; a type added to
    /// the runtime without a literal form would be reported here rather than lost).
    pub fn item(&mut self, value: Option<&Value>) -> Result<(), String> {
        let Some(value) = value else {
            self.u8(NULL);
            return Ok(());
        };
        match value {
            Value::Number(x) => {
                self.u8(NUMBER);
                self.f64(*x);
            }
            Value::Integer(i) => {
                self.u8(INTEGER);
                self.i64(*i);
            }
            Value::Boolean(b) => {
                self.u8(BOOLEAN);
                self.bool(*b);
            }
            Value::Text(t) => {
                self.u8(TEXT);
                self.str(t);
            }
            Value::Point(p) => {
                self.u8(POINT);
                self.xyz(p.to_array());
            }
            Value::Vector(v) => {
                self.u8(VECTOR);
                self.xyz(v.to_array());
            }
            Value::Surface(s) => {
                self.u8(SURFACE);
                self.surface(s);
            }
            Value::Brep(b) => {
                self.u8(BREP);
                self.brep(b);
            }
            other => {
                let literal = Literal::from_value(other).map_err(|e| e.message)?;
                self.u8(LITERAL);
                self.str(other.data_type().name());
                self.str(&literal.0);
            }
        }
        Ok(())
    }

    /// Writes a list of items (a branch).
    ///
    /// # Errors
    /// As [`Encoder::item`].
    pub fn branch(&mut self, branch: &Branch) -> Result<(), String> {
        self.count(branch.len());
        for v in branch.values() {
            self.item(v.as_ref())?;
        }
        Ok(())
    }

    /// Writes a list of items given as values.
    ///
    /// # Errors
    /// As [`Encoder::item`].
    pub fn items(&mut self, items: &[Option<Value>]) -> Result<(), String> {
        self.count(items.len());
        for v in items {
            self.item(v.as_ref())?;
        }
        Ok(())
    }

    /// Writes a tree path.
    pub fn path(&mut self, path: &TreePath) {
        self.count(path.len());
        for &i in path.indices() {
            self.buf.extend_from_slice(&i.to_le_bytes());
        }
    }

    /// Writes a data tree: its branches in path order.
    ///
    /// # Errors
    /// As [`Encoder::item`].
    pub fn tree(&mut self, tree: &DataTree) -> Result<(), String> {
        self.count(tree.branch_count());
        for (path, branch) in tree.branches() {
            self.path(path);
            self.branch(branch)?;
        }
        Ok(())
    }

    fn nurbs_curve(&mut self, c: &NurbsCurve) {
        self.count(c.degree());
        self.points(c.points());
        self.f64s(c.weights());
        self.f64s(c.knots());
    }

    fn surface(&mut self, s: &NurbsSurface) {
        self.count(s.degree_u());
        self.count(s.degree_v());
        self.count(s.count_u());
        self.count(s.count_v());
        self.points(s.points());
        self.f64s(s.weights());
        self.f64s(s.knots_u());
        self.f64s(s.knots_v());
    }

    fn brep(&mut self, b: &Brep) {
        self.count(b.vertices().len());
        for v in b.vertices() {
            self.xyz(v.point.to_array());
        }
        self.count(b.edges().len());
        for e in b.edges() {
            self.nurbs_curve(&e.curve);
            self.count(e.vertices[0]);
            self.count(e.vertices[1]);
        }
        self.count(b.trims().len());
        for t in b.trims() {
            self.nurbs_curve(&t.curve);
            match t.edge {
                Some(e) => {
                    self.u8(1);
                    self.count(e);
                }
                None => self.u8(0),
            }
            self.bool(t.reversed);
            self.count(t.loop_index);
            self.count(t.vertices[0]);
            self.count(t.vertices[1]);
        }
        self.count(b.loops().len());
        for l in b.loops() {
            self.count(l.face);
            self.bool(l.kind == LoopKind::Outer);
            self.count(l.trims.len());
            for &t in &l.trims {
                self.count(t);
            }
        }
        self.count(b.faces().len());
        for f in b.faces() {
            self.surface(&f.surface);
            self.count(f.loops.len());
            for &l in &f.loops {
                self.count(l);
            }
            self.bool(f.reversed);
        }
    }
}

/// Reads what an [`Encoder`] wrote, checking every count against the bytes left.
#[derive(Clone, Debug)]
pub struct Decoder<'a> {
    data: &'a [u8],
    pos: usize,
}

impl<'a> Decoder<'a> {
    /// A decoder at the start of `data`.
    pub fn new(data: &'a [u8]) -> Self {
        Self { data, pos: 0 }
    }

    /// Whether every byte has been read.
    pub fn is_at_end(&self) -> bool {
        self.pos >= self.data.len()
    }

    fn error<T>(&self, what: &str) -> Result<T, DecodeError> {
        Err(DecodeError(format!("{what} at byte {}", self.pos)))
    }

    fn take(&mut self, n: usize) -> Result<&'a [u8], DecodeError> {
        match self.pos.checked_add(n) {
            Some(end) if end <= self.data.len() => {
                let bytes = &self.data[self.pos..end];
                self.pos = end;
                Ok(bytes)
            }
            _ => self.error("the message ends early"),
        }
    }

    fn array<const N: usize>(&mut self) -> Result<[u8; N], DecodeError> {
        let bytes = self.take(N)?;
        let mut out = [0; N];
        out.copy_from_slice(bytes);
        Ok(out)
    }

    /// Reads one byte.
    ///
    /// # Errors
    /// When the message ends.
    pub fn u8(&mut self) -> Result<u8, DecodeError> {
        Ok(self.array::<1>()?[0])
    }

    /// Reads a boolean.
    ///
    /// # Errors
    /// When the message ends or the byte is neither 0 nor 1.
    pub fn bool(&mut self) -> Result<bool, DecodeError> {
        match self.u8()? {
            0 => Ok(false),
            1 => Ok(true),
            _ => self.error("a boolean is neither 0 nor 1"),
        }
    }

    /// Reads an index (not checked against anything).
    ///
    /// # Errors
    /// When the message ends.
    pub fn index(&mut self) -> Result<usize, DecodeError> {
        Ok(u32::from_le_bytes(self.array::<4>()?) as usize)
    }

    /// Reads the count of things that follow, each at least `min_size` bytes long: a count
    /// that the bytes left cannot hold is an error.
    ///
    /// # Errors
    /// When the message ends or the count is too large.
    pub fn count(&mut self, min_size: usize) -> Result<usize, DecodeError> {
        let n = self.index()?;
        let left = self.data.len() - self.pos;
        if n.saturating_mul(min_size.max(1)) > left {
            return self.error(&format!("a count of {n} is more than the message holds"));
        }
        Ok(n)
    }

    /// Reads a number.
    ///
    /// # Errors
    /// When the message ends.
    pub fn f64(&mut self) -> Result<f64, DecodeError> {
        Ok(f64::from_le_bytes(self.array::<8>()?))
    }

    /// Reads an integer.
    ///
    /// # Errors
    /// When the message ends.
    pub fn i64(&mut self) -> Result<i64, DecodeError> {
        Ok(i64::from_le_bytes(self.array::<8>()?))
    }

    /// Reads a text.
    ///
    /// # Errors
    /// When the message ends or the text is not UTF-8.
    pub fn str(&mut self) -> Result<String, DecodeError> {
        let n = self.count(1)?;
        let bytes = self.take(n)?;
        match std::str::from_utf8(bytes) {
            Ok(s) => Ok(s.to_owned()),
            Err(_) => self.error("a text is not UTF-8"),
        }
    }

    fn xyz(&mut self) -> Result<[f64; 3], DecodeError> {
        Ok([self.f64()?, self.f64()?, self.f64()?])
    }

    fn f64s(&mut self) -> Result<Vec<f64>, DecodeError> {
        let n = self.count(8)?;
        (0..n).map(|_| self.f64()).collect()
    }

    fn points(&mut self) -> Result<Vec<Point3>, DecodeError> {
        let n = self.count(24)?;
        (0..n)
            .map(|_| Ok(Point3::from_array(self.xyz()?)))
            .collect()
    }

    fn indices(&mut self) -> Result<Vec<usize>, DecodeError> {
        let n = self.count(4)?;
        (0..n).map(|_| self.index()).collect()
    }

    /// Reads one item (`None` for a null).
    ///
    /// # Errors
    /// When the bytes are not an item, or the item is not valid (a curve with a bad knot
    /// vector, a B-rep whose topology does not hold): the kernel's reason.
    pub fn item(&mut self) -> Result<Option<Value>, DecodeError> {
        let value = match self.u8()? {
            NULL => return Ok(None),
            NUMBER => Value::Number(self.f64()?),
            INTEGER => Value::Integer(self.i64()?),
            BOOLEAN => Value::Boolean(self.bool()?),
            TEXT => Value::Text(self.str()?),
            POINT => Value::Point(Point3::from_array(self.xyz()?)),
            VECTOR => {
                let [x, y, z] = self.xyz()?;
                Value::Vector(Vector3::new(x, y, z))
            }
            SURFACE => Value::Surface(Shared::new(self.surface()?)),
            BREP => Value::Brep(Shared::new(self.brep()?)),
            LITERAL => {
                let name = self.str()?;
                let text = self.str()?;
                let Some(data_type) = DataType::from_name(&name) else {
                    return self.error(&format!("unknown value type {name:?}"));
                };
                match Literal(text).parse_value(data_type) {
                    Ok(v) => v,
                    Err(e) => return self.error(&format!("invalid {name}: {}", e.message)),
                }
            }
            tag => return self.error(&format!("unknown item tag {tag}")),
        };
        Ok(Some(value))
    }

    /// Reads a list of items.
    ///
    /// # Errors
    /// As [`Decoder::item`].
    pub fn items(&mut self) -> Result<Vec<Option<Value>>, DecodeError> {
        let n = self.count(1)?;
        (0..n).map(|_| self.item()).collect()
    }

    /// Reads a list of items as a branch (typed when all its items have one type).
    ///
    /// # Errors
    /// As [`Decoder::item`].
    pub fn branch(&mut self) -> Result<Branch, DecodeError> {
        let mut b = Branch::new(DataType::Generic);
        for v in self.items()? {
            b.push_option(v);
        }
        Ok(b.narrowed())
    }

    /// Reads a tree path.
    ///
    /// # Errors
    /// When the message ends.
    pub fn path(&mut self) -> Result<TreePath, DecodeError> {
        let n = self.count(4)?;
        let indices = (0..n)
            .map(|_| Ok(u32::from_le_bytes(self.array::<4>()?)))
            .collect::<Result<Vec<u32>, DecodeError>>()?;
        Ok(TreePath::new(indices))
    }

    /// Reads a data tree (branches with equal paths are joined).
    ///
    /// # Errors
    /// As [`Decoder::item`].
    pub fn tree(&mut self) -> Result<DataTree, DecodeError> {
        let n = self.count(5)?;
        let mut tree = DataTree::new();
        for _ in 0..n {
            let path = self.path()?;
            let branch = self.branch()?;
            tree.append(path, &branch);
        }
        Ok(tree.narrowed())
    }

    fn kernel<T>(&self, what: &str, r: locus_kernel::Result<T>) -> Result<T, DecodeError> {
        match r {
            Ok(x) => Ok(x),
            Err(e) => self.error(&format!("invalid {what}: {e}")),
        }
    }

    fn nurbs_curve(&mut self) -> Result<NurbsCurve, DecodeError> {
        let degree = self.index()?;
        let points = self.points()?;
        let weights = self.f64s()?;
        let knots = self.f64s()?;
        let curve = NurbsCurve::new(degree, points, weights, knots);
        self.kernel("curve", curve)
    }

    fn surface(&mut self) -> Result<NurbsSurface, DecodeError> {
        let degrees = [self.index()?, self.index()?];
        let counts = [self.index()?, self.index()?];
        let points = self.points()?;
        let weights = self.f64s()?;
        let knots = [self.f64s()?, self.f64s()?];
        let surface = NurbsSurface::from_flat(degrees, counts, points, weights, knots);
        self.kernel("surface", surface)
    }

    fn brep(&mut self) -> Result<Brep, DecodeError> {
        let n = self.count(24)?;
        let vertices = (0..n)
            .map(|_| {
                Ok(BrepVertex {
                    point: Point3::from_array(self.xyz()?),
                    edges: Vec::new(),
                })
            })
            .collect::<Result<Vec<_>, DecodeError>>()?;
        let n = self.count(20)?;
        let edges = (0..n)
            .map(|_| {
                Ok(BrepEdge {
                    curve: self.nurbs_curve()?,
                    vertices: [self.index()?, self.index()?],
                    trims: Vec::new(),
                })
            })
            .collect::<Result<Vec<_>, DecodeError>>()?;
        let n = self.count(26)?;
        let trims = (0..n)
            .map(|_| {
                let curve = self.nurbs_curve()?;
                let edge = match self.bool()? {
                    true => Some(self.index()?),
                    false => None,
                };
                Ok(BrepTrim {
                    curve,
                    edge,
                    reversed: self.bool()?,
                    kind: TrimKind::Boundary,
                    loop_index: self.index()?,
                    vertices: [self.index()?, self.index()?],
                })
            })
            .collect::<Result<Vec<_>, DecodeError>>()?;
        let n = self.count(9)?;
        let loops = (0..n)
            .map(|_| {
                Ok(BrepLoop {
                    face: self.index()?,
                    kind: if self.bool()? {
                        LoopKind::Outer
                    } else {
                        LoopKind::Inner
                    },
                    trims: self.indices()?,
                })
            })
            .collect::<Result<Vec<_>, DecodeError>>()?;
        let n = self.count(33)?;
        let faces = (0..n)
            .map(|_| {
                Ok(BrepFace {
                    surface: self.surface()?,
                    loops: self.indices()?,
                    reversed: self.bool()?,
                })
            })
            .collect::<Result<Vec<_>, DecodeError>>()?;
        let brep = Brep::from_parts(vertices, edges, trims, loops, faces);
        self.kernel("B-rep", brep)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_kernel::{
        Arc, Circle, Color, Curve, Interval, Line, Mesh, MeshFace, OrientedBox, Plane, Sphere,
        Transform,
    };

    fn round_trip(value: Value) {
        let mut e = Encoder::new();
        e.item(Some(&value)).unwrap();
        let bytes = e.into_bytes();
        let mut d = Decoder::new(&bytes);
        let back = d.item().unwrap().unwrap();
        assert!(d.is_at_end());
        assert_eq!(back, value, "{value:?}");
    }

    fn every_type() -> Vec<Value> {
        let plane = Plane::from_frame(
            Point3::new(1.0, 2.0, 3.0),
            Vector3::new(1.0, 1.0, 0.0),
            Vector3::new(0.0, 1.0, 1.0),
        )
        .unwrap();
        let nurbs = NurbsCurve::new(
            2,
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 2.0, 0.1),
                Point3::new(3.0, -1.0, 0.0),
            ],
            vec![1.0, 0.7, 1.0],
            vec![0.0, 0.0, 1.0, 1.0],
        )
        .unwrap();
        let sphere =
            Brep::from_sphere(&Sphere::new(Point3::new(0.0, 0.0, 1.0), 1.5).unwrap()).unwrap();
        let box_ = OrientedBox::new(
            plane,
            Interval::new(0.0, 1.0),
            Interval::new(-1.0, 2.0),
            Interval::new(0.5, 0.75),
        );
        let cube = Brep::from_box(&box_).unwrap();
        let mesh = Mesh::new(
            vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.0, 0.0, 0.0),
                Point3::new(1.0, 1.0, 0.0),
                Point3::new(0.0, 1.0, 0.5),
            ],
            vec![MeshFace {
                vertices: [0, 1, 2, 3],
            }],
        )
        .unwrap();
        vec![
            Value::Number(0.1 + 0.2),
            Value::Number(-0.0),
            Value::Number(f64::NAN.copysign(1.0)),
            Value::Integer(i64::MIN),
            Value::Boolean(true),
            Value::Text("ünïcode \"quoted\"\nline".to_owned()),
            Value::Point(Point3::new(1.0 / 3.0, -2.5, 1e300)),
            Value::Vector(Vector3::new(0.0, -1e-300, 7.0)),
            Value::Plane(plane),
            Value::Domain(Interval::new(2.0, -1.0)),
            Value::Domain2(locus_kernel::UvInterval::new(
                Interval::new(2.0, -1.0),
                Interval::new(0.1, 0.7),
            )),
            Value::Transform(Transform::from_rows([
                [1.0, 2.0, 3.0, 4.0],
                [0.5, 0.25, 0.125, 0.0],
                [0.0, 0.0, 1.0, -9.0],
                [0.0, 0.0, 0.0, 1.0],
            ])),
            Value::Line(Line::new(Point3::ORIGIN, Point3::new(1.0, 2.0, 3.0))),
            Value::Circle(Circle { plane, radius: 2.5 }),
            Value::Arc(Arc {
                circle: Circle { plane, radius: 1.5 },
                angle: Interval::new(0.25, 2.0),
            }),
            Value::Curve(Shared::new(Curve::Nurbs(nurbs))),
            Value::Curve(Shared::new(Curve::from(Line::new(
                Point3::ORIGIN,
                Point3::new(0.0, 0.0, 4.0),
            )))),
            Value::Surface(Shared::new(sphere.faces()[0].surface.clone())),
            Value::Brep(Shared::new(sphere)),
            Value::Brep(Shared::new(cube)),
            Value::Box(box_),
            Value::Mesh(Shared::new(mesh)),
            Value::Colour(Color {
                r: 1,
                g: 2,
                b: 3,
                a: 4,
            }),
        ]
    }

    #[test]
    fn every_value_type_round_trips_exactly() {
        for value in every_type() {
            if let Value::Number(x) = value
                && x.is_nan()
            {
                let mut e = Encoder::new();
                e.item(Some(&value)).unwrap();
                let bytes = e.into_bytes();
                let back = Decoder::new(&bytes).item().unwrap();
                assert!(matches!(back, Some(Value::Number(y)) if y.is_nan()));
                continue;
            }
            round_trip(value);
        }
    }

    #[test]
    fn every_data_type_has_an_exchange_form() {
        let covered: std::collections::BTreeSet<DataType> =
            every_type().iter().map(Value::data_type).collect();
        let missing: Vec<DataType> = DataType::ALL
            .iter()
            .copied()
            .filter(|t| *t != DataType::Generic && !covered.contains(t))
            .collect();
        assert!(missing.is_empty(), "not tested: {missing:?}");
    }

    #[test]
    fn trees_round_trip_with_paths_and_nulls() {
        let mut tree = DataTree::new();
        let mut b = Branch::new(DataType::Generic);
        b.push_value(Value::Number(1.0));
        b.push_null();
        b.push_value(Value::Text("a".to_owned()));
        tree.insert(TreePath::new(vec![0, 2]), b);
        tree.insert(TreePath::new(vec![1]), Branch::from_items(vec![1.0, 2.0]));
        let mut e = Encoder::new();
        e.tree(&tree).unwrap();
        let bytes = e.into_bytes();
        let back = Decoder::new(&bytes).tree().unwrap();
        assert_eq!(back, tree.narrowed());
    }

    #[test]
    fn truncated_or_corrupt_bytes_are_errors_not_panics() {
        let mut e = Encoder::new();
        for v in every_type() {
            e.item(Some(&v)).unwrap();
        }
        let bytes = e.into_bytes();
        // Every prefix, and every single-byte corruption of a stride of positions.
        for end in 0..bytes.len() {
            let mut d = Decoder::new(&bytes[..end]);
            while !d.is_at_end() {
                if d.item().is_err() {
                    break;
                }
            }
        }
        for at in (0..bytes.len()).step_by(7) {
            let mut corrupt = bytes.clone();
            corrupt[at] ^= 0xa5;
            let mut d = Decoder::new(&corrupt);
            while !d.is_at_end() {
                if d.item().is_err() {
                    break;
                }
            }
        }
    }

    #[test]
    fn huge_counts_are_refused_before_allocating() {
        let mut bytes = vec![TEXT];
        bytes.extend_from_slice(&u32::MAX.to_le_bytes());
        let err = Decoder::new(&bytes).item().unwrap_err();
        assert!(err.0.contains("more than the message holds"), "{err}");
        let mut bytes = vec![BREP];
        bytes.extend_from_slice(&(1u32 << 30).to_le_bytes());
        assert!(Decoder::new(&bytes).item().is_err());
    }

    #[test]
    fn invalid_geometry_is_refused_with_the_kernel_reason() {
        // A degree-2 curve with two points and too few knots.
        let mut e = Encoder::new();
        e.u8(BREP);
        e.count(0);
        e.count(1);
        e.count(2);
        e.points(&[Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0)]);
        e.f64s(&[1.0, 1.0]);
        e.f64s(&[0.0]);
        e.count(0);
        e.count(0);
        let bytes = e.into_bytes();
        let err = Decoder::new(&bytes).item().unwrap_err();
        assert!(err.0.contains("invalid curve"), "{err}");
    }
}
