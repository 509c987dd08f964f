//! The closed set of value types that flow through a graph, and their typed column storage.
//!
//! Every value type is declared once, in the `value_types!` invocation below, which generates
//! [`DataType`] (the type tag of a port), [`Value`] (one item of any type, used where types
//! are mixed) and [`Column`] (a contiguous vector of items of one type: the storage of a tree
//! branch), plus an [`Item`] implementation that lets node code read and write typed slices
//! without boxing. Adding a value type is one line there.
//!
//! *Size.* A [`Value`] is 152 bytes, set by its largest variant (a Box: a plane and three
//! intervals; a Transform is 128, an Arc 120, a Plane 96), so generic columns of small items are
//! heavy. Boxing the large variants in `Value` alone would bring it to 56 bytes (a Line) but
//! make every construction `Value::Plane(Box::new(p))` and every by-value match `**p` in node
//! code; it is not done, because typed columns (the storage of every typed port) are unaffected
//! and generic columns are the exception on hot paths. A test pins the size so that a change
//! is deliberate.

use std::fmt;
use std::sync::Arc;

use locus_kernel::{
    Arc as ArcCurve, Brep, Circle, Color, Curve, Interval, Line, Mesh, NurbsSurface, OrientedBox,
    Plane, Point3, Transform, UvInterval, Vector3,
};

/// A Rust type that can be stored as an item of a data tree.
///
/// Implemented for every value type (`f64`, `i64`, `bool`, `String`, `Point3`, …) and for
/// [`Value`] itself, whose column is the generic, mixed-type [`Column::Generic`].
pub trait Item: Clone + Send + Sync + 'static {
    /// The port type this Rust type stands for.
    const TYPE: DataType;
    /// The items of a column, if the column holds this type.
    fn slice(column: &Column) -> Option<&[Self]>;
    /// The vector of a column, if the column holds this type.
    fn vec_mut(column: &mut Column) -> Option<&mut Vec<Self>>;
    /// A column holding these items.
    fn into_column(items: Vec<Self>) -> Column;
    /// The item as a [`Value`].
    fn into_value(self) -> Value;
    /// The item inside a value of exactly this type (no casting).
    fn from_value(value: &Value) -> Option<Self>;
    /// The placeholder stored in a column under a null item.
    fn placeholder() -> Self;
}

macro_rules! value_types {
    ($( $(#[$doc:meta])* $variant:ident($ty:ty) = $name:literal, placeholder $placeholder:expr; )*) => {
        /// The type of a port or of a column: one of the value types, or `Generic` for any.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum DataType {
            $( $(#[$doc])* $variant, )*
            /// Any value; a column of this type may mix value types (Grasshopper's Generic Data).
            Generic,
        }

        impl DataType {
            /// Every data type, in declaration order, `Generic` last.
            pub const ALL: &'static [DataType] = &[$(DataType::$variant,)* DataType::Generic];

            /// The user-facing name of the type, as Grasshopper spells it (`Number`, `Point`, …).
            pub fn name(self) -> &'static str {
                match self {
                    $( DataType::$variant => $name, )*
                    DataType::Generic => "Generic",
                }
            }

            /// The type with this name (case-insensitive), as written in graph files.
            pub fn from_name(name: &str) -> Option<Self> {
                Self::ALL.iter().copied().find(|t| t.name().eq_ignore_ascii_case(name))
            }
        }

        /// One item of any value type.
        #[derive(Clone, Debug, PartialEq)]
        pub enum Value {
            $( $(#[$doc])* $variant($ty), )*
        }

        impl Value {
            /// The type of this value.
            pub fn data_type(&self) -> DataType {
                match self {
                    $( Value::$variant(_) => DataType::$variant, )*
                }
            }
        }

        /// The items of one branch, stored contiguously by type.
        #[derive(Clone, Debug, PartialEq)]
        pub enum Column {
            $( $(#[$doc])* $variant(Vec<$ty>), )*
            /// Items of mixed or unknown type.
            Generic(Vec<Value>),
        }

        impl Column {
            /// An empty column of the given type.
            pub fn new(data_type: DataType) -> Self {
                Self::with_capacity(data_type, 0)
            }

            /// An empty column of the given type with room for `capacity` items.
            pub fn with_capacity(data_type: DataType, capacity: usize) -> Self {
                match data_type {
                    $( DataType::$variant => Column::$variant(Vec::with_capacity(capacity)), )*
                    DataType::Generic => Column::Generic(Vec::with_capacity(capacity)),
                }
            }

            /// The type of the column.
            pub fn data_type(&self) -> DataType {
                match self {
                    $( Column::$variant(_) => DataType::$variant, )*
                    Column::Generic(_) => DataType::Generic,
                }
            }

            /// The number of items (null placeholders included).
            pub fn len(&self) -> usize {
                match self {
                    $( Column::$variant(v) => v.len(), )*
                    Column::Generic(v) => v.len(),
                }
            }

            /// Whether the column has no items.
            pub fn is_empty(&self) -> bool {
                self.len() == 0
            }

            /// The item at `index` as a [`Value`] (cloned), or `None` past the end.
            pub fn value(&self, index: usize) -> Option<Value> {
                match self {
                    $( Column::$variant(v) => v.get(index).cloned().map(Value::$variant), )*
                    Column::Generic(v) => v.get(index).cloned(),
                }
            }

            /// Appends a value. A value of another type turns the column generic first.
            pub fn push_value(&mut self, value: Value) {
                match (&mut *self, value) {
                    $( (Column::$variant(v), Value::$variant(x)) => v.push(x), )*
                    (Column::Generic(v), x) => v.push(x),
                    (_, x) => {
                        self.make_generic();
                        if let Column::Generic(v) = self {
                            v.push(x);
                        }
                    }
                }
            }

            /// Appends a null placeholder of the column's type.
            pub fn push_placeholder(&mut self) {
                match self {
                    $( Column::$variant(v) => v.push(<$ty as Item>::placeholder()), )*
                    Column::Generic(v) => v.push(Value::placeholder()),
                }
            }

            /// A generic column whose items (leaving out those `nulls` flags; an empty mask
            /// flags none) are all of one type, as a typed column of that type with
            /// placeholders at the nulls; any other column as it is.
            pub fn narrowed(self, nulls: &[bool]) -> Column {
                let Column::Generic(values) = self else {
                    return self;
                };
                let is_null = |i: usize| !nulls.is_empty() && nulls.get(i).copied().unwrap_or(false);
                let mut common = None;
                for (i, v) in values.iter().enumerate() {
                    if is_null(i) {
                        continue;
                    }
                    match common {
                        None => common = Some(v.data_type()),
                        Some(t) if t == v.data_type() => {}
                        Some(_) => return Column::Generic(values),
                    }
                }
                match common {
                    $( Some(DataType::$variant) => Column::$variant(
                        values
                            .into_iter()
                            .enumerate()
                            .map(|(i, v)| match v {
                                Value::$variant(x) if !is_null(i) => x,
                                _ => <$ty as Item>::placeholder(),
                            })
                            .collect(),
                    ), )*
                    Some(DataType::Generic) | None => Column::Generic(values),
                }
            }

            /// Converts the column to a generic column holding the same items.
            pub fn make_generic(&mut self) {
                let generic = match std::mem::replace(self, Column::Generic(Vec::new())) {
                    $( Column::$variant(v) => v.into_iter().map(Value::$variant).collect(), )*
                    Column::Generic(v) => v,
                };
                *self = Column::Generic(generic);
            }

            /// Appends the items `range` of `other`, which must be of the same type; a column of
            /// another type turns this one generic first.
            pub fn extend_from(&mut self, other: &Column, range: std::ops::Range<usize>) {
                match (&mut *self, other) {
                    $( (Column::$variant(a), Column::$variant(b)) => a.extend_from_slice(&b[range]), )*
                    (Column::Generic(a), Column::Generic(b)) => a.extend_from_slice(&b[range]),
                    _ => {
                        for i in range {
                            if let Some(v) = other.value(i) {
                                self.push_value(v);
                            }
                        }
                    }
                }
            }

            /// Reverses the order of the items.
            pub fn reverse(&mut self) {
                match self {
                    $( Column::$variant(v) => v.reverse(), )*
                    Column::Generic(v) => v.reverse(),
                }
            }

            /// Keeps only the items whose index passes `keep`.
            pub fn retain_indices(&mut self, mut keep: impl FnMut(usize) -> bool) {
                fn retain<T>(v: &mut Vec<T>, keep: &mut impl FnMut(usize) -> bool) {
                    let mut i = 0;
                    v.retain(|_| {
                        let k = keep(i);
                        i += 1;
                        k
                    });
                }
                match self {
                    $( Column::$variant(v) => retain(v, &mut keep), )*
                    Column::Generic(v) => retain(v, &mut keep),
                }
            }
        }

        $(
            impl Item for $ty {
                const TYPE: DataType = DataType::$variant;
                #[inline]
                fn slice(column: &Column) -> Option<&[Self]> {
                    match column {
                        Column::$variant(v) => Some(v),
                        _ => None,
                    }
                }
                #[inline]
                fn vec_mut(column: &mut Column) -> Option<&mut Vec<Self>> {
                    match column {
                        Column::$variant(v) => Some(v),
                        _ => None,
                    }
                }
                fn into_column(items: Vec<Self>) -> Column {
                    Column::$variant(items)
                }
                fn into_value(self) -> Value {
                    Value::$variant(self)
                }
                fn from_value(value: &Value) -> Option<Self> {
                    match value {
                        Value::$variant(x) => Some(x.clone()),
                        #[allow(unreachable_patterns, reason = "generated for every variant")]
                        _ => None,
                    }
                }
                fn placeholder() -> Self {
                    $placeholder
                }
            }
        )*
    };
}

value_types! {
    /// A real number (`f64`).
    Number(f64) = "Number", placeholder 0.0;
    /// A whole number (`i64`).
    Integer(i64) = "Integer", placeholder 0;
    /// A boolean.
    Boolean(bool) = "Boolean", placeholder false;
    /// A text.
    Text(String) = "Text", placeholder String::new();
    /// A point.
    Point(Point3) = "Point", placeholder Point3::ORIGIN;
    /// A vector.
    Vector(Vector3) = "Vector", placeholder Vector3::ZERO;
    /// A plane.
    Plane(Plane) = "Plane", placeholder Plane::WORLD_XY;
    /// A domain (interval of numbers).
    Domain(Interval) = "Domain", placeholder Interval::UNIT;
    /// A two-dimensional domain: a u and a v interval (Grasshopper's Domain²).
    Domain2(UvInterval) = "Domain2", placeholder UvInterval::UNIT;
    /// A 4×4 transformation.
    Transform(Transform) = "Transform", placeholder Transform::IDENTITY;
    /// An oriented box (Grasshopper's Box: a plane and three intervals).
    Box(OrientedBox) = "Box", placeholder OrientedBox::new(
        Plane::WORLD_XY, Interval::UNIT, Interval::UNIT, Interval::UNIT
    );
    /// A line segment.
    Line(Line) = "Line", placeholder Line::new(Point3::ORIGIN, Point3::new(1.0, 0.0, 0.0));
    /// A circle.
    Circle(Circle) = "Circle", placeholder Circle { plane: Plane::WORLD_XY, radius: 1.0 };
    /// A circular arc.
    Arc(ArcCurve) = "Arc", placeholder ArcCurve {
        circle: Circle { plane: Plane::WORLD_XY, radius: 1.0 },
        angle: Interval::new(0.0, std::f64::consts::FRAC_PI_2),
    };
    /// A curve of any kind (line, polyline, circle, arc, NURBS), shared.
    Curve(Shared<Curve>) = "Curve", placeholder placeholder_curve();
    /// A NURBS surface, shared.
    Surface(Shared<NurbsSurface>) = "Surface", placeholder placeholder_surface();
    /// A boundary representation (faces, edges, vertices), shared.
    Brep(Shared<Brep>) = "Brep", placeholder Shared::new(Brep::default());
    /// A polygon mesh of triangles and quads, shared.
    Mesh(Shared<Mesh>) = "Mesh", placeholder Shared::new(Mesh::default());
    /// A colour with alpha (Grasshopper's Colour, `System.Drawing.Color`).
    Colour(Color) = "Colour", placeholder Color::BLACK;
}

/// The curve stored under null curve items: a unit line.
fn placeholder_curve() -> Shared<Curve> {
    static CURVE: std::sync::LazyLock<Shared<Curve>> = std::sync::LazyLock::new(|| {
        Shared::new(Curve::from(Line::new(
            Point3::ORIGIN,
            Point3::new(1.0, 0.0, 0.0),
        )))
    });
    CURVE.clone()
}

/// The surface stored under null surface items: the unit square of the world XY plane.
fn placeholder_surface() -> Shared<NurbsSurface> {
    static SURFACE: std::sync::LazyLock<Shared<NurbsSurface>> = std::sync::LazyLock::new(|| {
        let square = NurbsSurface::from_plane(&Plane::WORLD_XY, Interval::UNIT, Interval::UNIT);
        // The unit square of World XY is valid by construction.
        Shared::new(square.unwrap_or_else(|_| unreachable!("the unit square is a valid surface")))
    });
    SURFACE.clone()
}

impl Value {
    /// The placeholder stored under a null item of a generic column.
    pub fn placeholder() -> Self {
        Value::Boolean(false)
    }

    /// The item as a value of type `T`, if it is exactly of that type.
    pub fn get<T: Item>(&self) -> Option<T> {
        T::from_value(self)
    }
}

impl Item for Value {
    const TYPE: DataType = DataType::Generic;
    #[inline]
    fn slice(column: &Column) -> Option<&[Self]> {
        match column {
            Column::Generic(v) => Some(v),
            _ => None,
        }
    }
    #[inline]
    fn vec_mut(column: &mut Column) -> Option<&mut Vec<Self>> {
        match column {
            Column::Generic(v) => Some(v),
            _ => None,
        }
    }
    fn into_column(items: Vec<Self>) -> Column {
        Column::Generic(items)
    }
    fn into_value(self) -> Value {
        self
    }
    fn from_value(value: &Value) -> Option<Self> {
        Some(value.clone())
    }
    fn placeholder() -> Self {
        Value::placeholder()
    }
}

impl fmt::Display for DataType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Shared ownership for large geometry stored in trees, so that copying a tree copies pointers.
pub type Shared<T> = Arc<T>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pushing_another_type_turns_the_column_generic() {
        let mut c = Column::new(DataType::Number);
        c.push_value(Value::Number(1.0));
        c.push_value(Value::Text("a".into()));
        assert_eq!(c.data_type(), DataType::Generic);
        assert_eq!(c.value(0), Some(Value::Number(1.0)));
        assert_eq!(c.value(1), Some(Value::Text("a".into())));
    }

    #[test]
    fn typed_slices_are_contiguous() {
        let c = f64::into_column(vec![1.0, 2.0]);
        assert_eq!(f64::slice(&c), Some(&[1.0, 2.0][..]));
        assert_eq!(i64::slice(&c), None);
    }

    #[test]
    fn value_size_is_known() {
        assert_eq!(std::mem::size_of::<Value>(), 152);
        assert_eq!(std::mem::size_of::<Column>(), 32);
    }

    #[test]
    fn type_names_round_trip() {
        for &t in DataType::ALL {
            assert_eq!(DataType::from_name(t.name()), Some(t));
        }
    }
}
