//! The chunk/item model of a GH_IO archive, shared by the XML (`.ghx`), binary (`.gh`) and
//! nested cluster forms.
//!
//! An archive is a tree of [`Chunk`]s; each chunk has a name, an optional index (`Object
//! index=3`), typed [`Item`]s and child chunks. Readers fill this model; everything that
//! interprets a definition (objects, ports, wires, values) reads only this model.

use crate::error::ArchiveError;
use crate::limits::Limits;

/// One chunk of an archive.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Chunk {
    /// The chunk's name (`Object`, `Container`, `param_input`).
    pub name: String,
    /// The chunk's index when it is one of a numbered series (`Object index=3`).
    pub index: Option<i32>,
    /// The items, in file order.
    pub items: Vec<Item>,
    /// The child chunks, in file order.
    pub chunks: Vec<Chunk>,
}

/// One named, typed value of a chunk.
#[derive(Clone, Debug, PartialEq)]
pub struct Item {
    /// The item's name (`InstanceGuid`, `Source`).
    pub name: String,
    /// The item's index when it is one of a numbered series (`Source index=1`).
    pub index: Option<i32>,
    /// The value.
    pub value: Value,
}

/// The typed value of an item, one variant per GH_IO type (the type codes of the file format
/// are in [`Value::type_code`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// `gh_bool` (1).
    Bool(bool),
    /// `gh_byte` (2).
    Byte(u8),
    /// `gh_int32` (3).
    Int32(i32),
    /// `gh_int64` (4).
    Int64(i64),
    /// `gh_single` (5).
    Single(f32),
    /// `gh_double` (6).
    Double(f64),
    /// `gh_decimal` (7), converted to the nearest double.
    Decimal(f64),
    /// `gh_date` (8): .NET ticks.
    Date(i64),
    /// `gh_guid` (9), lower-case canonical text.
    Guid(String),
    /// `gh_string` (10).
    String(String),
    /// `gh_bytearray` (20).
    Bytes(Vec<u8>),
    /// `gh_doublearray` (21).
    Doubles(Vec<f64>),
    /// `gh_drawing_point` (30).
    DrawingPoint([i32; 2]),
    /// `gh_drawing_pointf` (31).
    DrawingPointF([f32; 2]),
    /// `gh_drawing_size` (32).
    DrawingSize([i32; 2]),
    /// `gh_drawing_sizef` (33).
    DrawingSizeF([f32; 2]),
    /// `gh_drawing_rectangle` (34): x, y, width, height.
    DrawingRectangle([i32; 4]),
    /// `gh_drawing_rectanglef` (35): x, y, width, height.
    DrawingRectangleF([f32; 4]),
    /// `gh_drawing_color` (36): alpha, red, green, blue.
    Color([u8; 4]),
    /// `gh_drawing_bitmap` (37): the encoded image.
    Bitmap(Vec<u8>),
    /// `gh_point2d` (50).
    Point2([f64; 2]),
    /// `gh_point3d` (51), also used for vectors.
    Point3([f64; 3]),
    /// `gh_point4d` (52).
    Point4([f64; 4]),
    /// `gh_interval1d` (60): start, end.
    Interval([f64; 2]),
    /// `gh_interval2d` (61): u start, u end, v start, v end.
    Interval2([f64; 4]),
    /// `gh_line` (70): start, end.
    Line([f64; 6]),
    /// `gh_boundingbox` (71): min, max.
    BoundingBox([f64; 6]),
    /// `gh_plane` (72): origin, x axis, y axis.
    Plane([f64; 9]),
    /// `gh_version` (80): major, minor, revision.
    Version([i32; 3]),
}

impl Value {
    /// The GH_IO type code of this value.
    pub fn type_code(&self) -> u32 {
        match self {
            Value::Bool(_) => 1,
            Value::Byte(_) => 2,
            Value::Int32(_) => 3,
            Value::Int64(_) => 4,
            Value::Single(_) => 5,
            Value::Double(_) => 6,
            Value::Decimal(_) => 7,
            Value::Date(_) => 8,
            Value::Guid(_) => 9,
            Value::String(_) => 10,
            Value::Bytes(_) => 20,
            Value::Doubles(_) => 21,
            Value::DrawingPoint(_) => 30,
            Value::DrawingPointF(_) => 31,
            Value::DrawingSize(_) => 32,
            Value::DrawingSizeF(_) => 33,
            Value::DrawingRectangle(_) => 34,
            Value::DrawingRectangleF(_) => 35,
            Value::Color(_) => 36,
            Value::Bitmap(_) => 37,
            Value::Point2(_) => 50,
            Value::Point3(_) => 51,
            Value::Point4(_) => 52,
            Value::Interval(_) => 60,
            Value::Interval2(_) => 61,
            Value::Line(_) => 70,
            Value::BoundingBox(_) => 71,
            Value::Plane(_) => 72,
            Value::Version(_) => 80,
        }
    }

    /// The GH_IO type name of a type code (`gh_double`), if the code is known.
    pub fn type_name(code: u32) -> Option<&'static str> {
        Some(match code {
            1 => "gh_bool",
            2 => "gh_byte",
            3 => "gh_int32",
            4 => "gh_int64",
            5 => "gh_single",
            6 => "gh_double",
            7 => "gh_decimal",
            8 => "gh_date",
            9 => "gh_guid",
            10 => "gh_string",
            20 => "gh_bytearray",
            21 => "gh_doublearray",
            30 => "gh_drawing_point",
            31 => "gh_drawing_pointf",
            32 => "gh_drawing_size",
            33 => "gh_drawing_sizef",
            34 => "gh_drawing_rectangle",
            35 => "gh_drawing_rectanglef",
            36 => "gh_drawing_color",
            37 => "gh_drawing_bitmap",
            50 => "gh_point2d",
            51 => "gh_point3d",
            52 => "gh_point4d",
            60 => "gh_interval1d",
            61 => "gh_interval2d",
            70 => "gh_line",
            71 => "gh_boundingbox",
            72 => "gh_plane",
            80 => "gh_version",
            _ => return None,
        })
    }

    /// The value as a number, for the numeric types.
    pub fn as_f64(&self) -> Option<f64> {
        match *self {
            Value::Byte(v) => Some(f64::from(v)),
            Value::Int32(v) => Some(f64::from(v)),
            Value::Int64(v) => Some(v as f64),
            Value::Single(v) => Some(f64::from(v)),
            Value::Double(v) | Value::Decimal(v) => Some(v),
            _ => None,
        }
    }

    /// The value as an integer, for the integer types.
    pub fn as_i64(&self) -> Option<i64> {
        match *self {
            Value::Byte(v) => Some(i64::from(v)),
            Value::Int32(v) => Some(i64::from(v)),
            Value::Int64(v) => Some(v),
            _ => None,
        }
    }

    /// The text of a string or GUID item.
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Value::String(s) | Value::Guid(s) => Some(s),
            _ => None,
        }
    }

    /// The value of a boolean item.
    pub fn as_bool(&self) -> Option<bool> {
        match *self {
            Value::Bool(b) => Some(b),
            _ => None,
        }
    }
}

impl Chunk {
    /// The first child chunk with this name (any index).
    pub fn chunk(&self, name: &str) -> Option<&Chunk> {
        self.chunks.iter().find(|c| c.name == name)
    }

    /// Every child chunk with this name, in file order.
    pub fn chunks_named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Chunk> + 'a {
        self.chunks.iter().filter(move |c| c.name == name)
    }

    /// The first item with this name (any index).
    pub fn item(&self, name: &str) -> Option<&Item> {
        self.items.iter().find(|i| i.name == name)
    }

    /// Every item with this name, in file order.
    pub fn items_named<'a>(&'a self, name: &'a str) -> impl Iterator<Item = &'a Item> + 'a {
        self.items.iter().filter(move |i| i.name == name)
    }

    /// The text of a string or GUID item.
    pub fn str(&self, name: &str) -> Option<&str> {
        self.item(name).and_then(|i| i.value.as_str())
    }

    /// The value of a boolean item.
    pub fn bool(&self, name: &str) -> Option<bool> {
        self.item(name).and_then(|i| i.value.as_bool())
    }

    /// The value of a numeric item.
    pub fn f64(&self, name: &str) -> Option<f64> {
        self.item(name).and_then(|i| i.value.as_f64())
    }

    /// The value of an integer item.
    pub fn i64(&self, name: &str) -> Option<i64> {
        self.item(name).and_then(|i| i.value.as_i64())
    }

    /// The number of chunks in this tree (this one included) and of items in it.
    pub fn counts(&self) -> (usize, usize) {
        let mut chunks = 1;
        let mut items = self.items.len();
        for c in &self.chunks {
            let (a, b) = c.counts();
            chunks += a;
            items += b;
        }
        (chunks, items)
    }
}

/// The form an archive was read from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// XML (`.ghx`).
    Xml,
    /// Binary, raw-deflate-compressed (`.gh`, and clusters inside either).
    Binary,
}

/// Reads an archive from the bytes of a `.gh` or `.ghx` file, telling the form from the
/// content (XML starts with `<`, after an optional byte order mark and white space).
pub fn read_archive(bytes: &[u8], limits: &Limits) -> Result<Chunk, ArchiveError> {
    match detect(bytes) {
        Form::Xml => crate::xml::read_xml(bytes, limits),
        Form::Binary => crate::binary::read_compressed(bytes, limits, 0),
    }
}

/// Which form the bytes are in.
pub fn detect(bytes: &[u8]) -> Form {
    let rest = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF]).unwrap_or(bytes);
    match rest.iter().find(|b| !b.is_ascii_whitespace()) {
        Some(b'<') => Form::Xml,
        _ => Form::Binary,
    }
}
