//! The XML form of a GH_IO archive (`.ghx`), read with roxmltree.
//!
//! ```xml
//! <Archive name="Root">
//!   <items count="1"><item name="ArchiveVersion" type_name="gh_version" type_code="80">…</item></items>
//!   <chunks count="2"><chunk name="Definition">…</chunk></chunks>
//! </Archive>
//! ```
//!
//! Simple values are the element's text; composite ones are child elements (`<X>`, `<Y>`,
//! `<Z>` of a point, `<ARGB>a;r;g;b</ARGB>` of a colour, `<stream>` base64 of a byte array).

use base64::Engine as _;
use roxmltree::{Document, Node, ParsingOptions};

use crate::archive::{Chunk, Item, Value};
use crate::error::ArchiveError;
use crate::limits::Limits;

/// Reads a `.ghx` file's bytes.
pub fn read_xml(bytes: &[u8], limits: &Limits) -> Result<Chunk, ArchiveError> {
    if bytes.len() > limits.max_file_bytes {
        return Err(ArchiveError::FileTooLarge {
            size: bytes.len(),
            limit: limits.max_file_bytes,
        });
    }
    let bytes = bytes.strip_prefix(&[0xEF, 0xBB, 0xBF]).unwrap_or(bytes);
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let (line, column) = position_of_byte(bytes, e.valid_up_to());
        ArchiveError::Xml {
            line,
            column,
            reason: "the file is not UTF-8".to_owned(),
        }
    })?;
    let options = ParsingOptions {
        allow_dtd: false,
        nodes_limit: u32::try_from(limits.max_entries.saturating_mul(4)).unwrap_or(u32::MAX),
        ..ParsingOptions::default()
    };
    let doc = Document::parse_with_options(text, options).map_err(|e| {
        let pos = e.pos();
        ArchiveError::Xml {
            line: pos.row,
            column: pos.col,
            reason: e.to_string(),
        }
    })?;
    let root = doc.root_element();
    let reader = XmlReader { doc: &doc, limits };
    if root.tag_name().name() != "Archive" {
        return Err(reader.error(root, "not a Grasshopper archive (no <Archive> element)"));
    }
    let mut entries = 0;
    reader.chunk(root, 0, &mut entries)
}

fn position_of_byte(bytes: &[u8], at: usize) -> (u32, u32) {
    let before = &bytes[..at.min(bytes.len())];
    let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
    let column = before.iter().rev().take_while(|&&b| b != b'\n').count() + 1;
    (line as u32, column as u32)
}

struct XmlReader<'a, 'input> {
    doc: &'a Document<'input>,
    limits: &'a Limits,
}

fn elements<'a, 'input>(node: Node<'a, 'input>) -> impl Iterator<Item = Node<'a, 'input>> {
    node.children().filter(|n| n.is_element())
}

fn child<'a, 'input>(node: Node<'a, 'input>, name: &str) -> Option<Node<'a, 'input>> {
    elements(node).find(|n| n.tag_name().name() == name)
}

impl XmlReader<'_, '_> {
    fn error(&self, node: Node<'_, '_>, reason: impl Into<String>) -> ArchiveError {
        let pos = self.doc.text_pos_at(node.range().start);
        ArchiveError::Xml {
            line: pos.row,
            column: pos.col,
            reason: reason.into(),
        }
    }

    fn chunk(
        &self,
        node: Node<'_, '_>,
        depth: usize,
        entries: &mut usize,
    ) -> Result<Chunk, ArchiveError> {
        if depth >= self.limits.max_depth {
            return Err(self.error(
                node,
                format!(
                    "chunks nest deeper than the limit of {}",
                    self.limits.max_depth
                ),
            ));
        }
        self.count(node, entries)?;
        let name = node.attribute("name").unwrap_or_default().to_owned();
        let index = self.index(node)?;
        let mut chunk = Chunk {
            name,
            index,
            items: Vec::new(),
            chunks: Vec::new(),
        };
        for part in elements(node) {
            match part.tag_name().name() {
                "items" => {
                    for item in elements(part).filter(|n| n.tag_name().name() == "item") {
                        self.count(item, entries)?;
                        chunk.items.push(self.item(item)?);
                    }
                }
                "chunks" => {
                    for c in elements(part).filter(|n| n.tag_name().name() == "chunk") {
                        chunk.chunks.push(self.chunk(c, depth + 1, entries)?);
                    }
                }
                _ => {}
            }
        }
        Ok(chunk)
    }

    fn count(&self, node: Node<'_, '_>, entries: &mut usize) -> Result<(), ArchiveError> {
        *entries += 1;
        if *entries > self.limits.max_entries {
            return Err(self.error(
                node,
                format!(
                    "more chunks and items than the limit of {}",
                    self.limits.max_entries
                ),
            ));
        }
        Ok(())
    }

    fn index(&self, node: Node<'_, '_>) -> Result<Option<i32>, ArchiveError> {
        match node.attribute("index") {
            None => Ok(None),
            Some(text) => text
                .trim()
                .parse::<i32>()
                .map(Some)
                .map_err(|_| self.error(node, format!("bad index \"{text}\""))),
        }
    }

    fn item(&self, node: Node<'_, '_>) -> Result<Item, ArchiveError> {
        let name = node.attribute("name").unwrap_or_default().to_owned();
        let index = self.index(node)?;
        let code_text = node.attribute("type_code").unwrap_or_default();
        let code: u32 = code_text
            .trim()
            .parse()
            .map_err(|_| self.error(node, format!("item {name}: bad type code \"{code_text}\"")))?;
        let value = self
            .value(node, code)
            .map_err(|reason| self.error(node, format!("item {name}: {reason}")))?;
        Ok(Item { name, index, value })
    }

    fn text<'n>(&self, node: Node<'n, '_>) -> Result<&'n str, String> {
        let text = node.text().unwrap_or_default();
        if text.len() > self.limits.max_string_bytes {
            return Err(format!(
                "a text of {} bytes passes the limit of {}",
                text.len(),
                self.limits.max_string_bytes
            ));
        }
        Ok(text)
    }

    fn value(&self, node: Node<'_, '_>, code: u32) -> Result<Value, String> {
        let text = || self.text(node).map(str::trim);
        Ok(match code {
            1 => Value::Bool(parse_bool(text()?)?),
            2 => Value::Byte(parse_int(text()?)?),
            3 => Value::Int32(parse_int(text()?)?),
            4 => Value::Int64(parse_int(text()?)?),
            5 => Value::Single(parse_float(text()?)? as f32),
            6 => Value::Double(parse_float(text()?)?),
            7 => Value::Decimal(parse_float(text()?)?),
            8 => Value::Date(parse_int(text()?)?),
            9 => Value::Guid(parse_guid(text()?)?),
            10 => Value::String(self.text(node)?.to_owned()),
            20 => Value::Bytes(self.base64(node, "stream")?),
            37 => Value::Bitmap(self.base64(node, "bitmap")?),
            21 => Value::Doubles(
                elements(node)
                    .map(|n| self.text(n).and_then(|t| parse_float(t.trim())))
                    .collect::<Result<_, _>>()?,
            ),
            30 => Value::DrawingPoint(self.ints(node, ["X", "Y"])?),
            31 => Value::DrawingPointF(self.floats(node, ["X", "Y"])?.map(|v| v as f32)),
            32 => Value::DrawingSize(self.ints(node, ["W", "H"])?),
            33 => Value::DrawingSizeF(self.floats(node, ["W", "H"])?.map(|v| v as f32)),
            34 => Value::DrawingRectangle(self.ints(node, ["X", "Y", "W", "H"])?),
            35 => {
                Value::DrawingRectangleF(self.floats(node, ["X", "Y", "W", "H"])?.map(|v| v as f32))
            }
            36 => {
                let argb = child(node, "ARGB").ok_or("a colour needs <ARGB>")?;
                let parts: Vec<u8> = self
                    .text(argb)?
                    .split(';')
                    .map(|p| parse_int(p.trim()))
                    .collect::<Result<_, _>>()?;
                let argb: [u8; 4] = parts
                    .try_into()
                    .map_err(|_| "a colour needs four parts a;r;g;b")?;
                Value::Color(argb)
            }
            50 => Value::Point2(self.floats(node, ["X", "Y"])?),
            51 => Value::Point3(self.floats(node, ["X", "Y", "Z"])?),
            52 => Value::Point4(self.floats(node, ["X", "Y", "Z", "W"])?),
            60 => Value::Interval(self.floats(node, ["A", "B"])?),
            61 => Value::Interval2(self.in_order(node)?),
            70 => Value::Line(self.in_order(node)?),
            71 => Value::BoundingBox(self.in_order(node)?),
            72 => Value::Plane(
                self.floats(node, ["Ox", "Oy", "Oz", "Xx", "Xy", "Xz", "Yx", "Yy", "Yz"])?,
            ),
            80 => Value::Version(self.ints(node, ["Major", "Minor", "Revision"])?),
            _ => return Err(format!("unknown type code {code}")),
        })
    }

    fn base64(&self, node: Node<'_, '_>, element: &str) -> Result<Vec<u8>, String> {
        let data = child(node, element).ok_or_else(|| format!("expected <{element}>"))?;
        let text = self.text(data)?;
        let clean: Vec<u8> = text.bytes().filter(|b| !b.is_ascii_whitespace()).collect();
        base64::engine::general_purpose::STANDARD
            .decode(&clean)
            .map_err(|e| format!("bad base64 in <{element}>: {e}"))
    }

    fn floats<const N: usize>(
        &self,
        node: Node<'_, '_>,
        names: [&str; N],
    ) -> Result<[f64; N], String> {
        let mut out = [0.0; N];
        for (v, name) in out.iter_mut().zip(names) {
            let c = child(node, name).ok_or_else(|| format!("expected <{name}>"))?;
            *v = parse_float(self.text(c)?.trim())?;
        }
        Ok(out)
    }

    fn ints<const N: usize>(
        &self,
        node: Node<'_, '_>,
        names: [&str; N],
    ) -> Result<[i32; N], String> {
        let mut out = [0; N];
        for (v, name) in out.iter_mut().zip(names) {
            let c = child(node, name).ok_or_else(|| format!("expected <{name}>"))?;
            *v = parse_int(self.text(c)?.trim())?;
        }
        Ok(out)
    }

    fn in_order<const N: usize>(&self, node: Node<'_, '_>) -> Result<[f64; N], String> {
        let values: Vec<f64> = elements(node)
            .take(N + 1)
            .map(|n| self.text(n).and_then(|t| parse_float(t.trim())))
            .collect::<Result<_, _>>()?;
        values
            .try_into()
            .map_err(|_| format!("expected {N} numbers"))
    }
}

fn parse_bool(t: &str) -> Result<bool, String> {
    if t.eq_ignore_ascii_case("true") {
        Ok(true)
    } else if t.eq_ignore_ascii_case("false") {
        Ok(false)
    } else {
        Err(format!("expected true or false, found \"{}\"", short(t)))
    }
}

fn parse_int<T: std::str::FromStr>(t: &str) -> Result<T, String> {
    t.parse()
        .map_err(|_| format!("expected an integer, found \"{}\"", short(t)))
}

/// A number as .NET writes it (`6.42`, `1E-05`, `Infinity`, `-Infinity`, `NaN`).
pub(crate) fn parse_float(t: &str) -> Result<f64, String> {
    match t {
        "Infinity" | "∞" => return Ok(f64::INFINITY),
        "-Infinity" | "-∞" => return Ok(f64::NEG_INFINITY),
        _ => {}
    }
    t.parse()
        .map_err(|_| format!("expected a number, found \"{}\"", short(t)))
}

fn parse_guid(t: &str) -> Result<String, String> {
    let t = t.trim_matches(|c| c == '{' || c == '}');
    let ok = t.len() == 36
        && t.char_indices().all(|(i, c)| {
            if matches!(i, 8 | 13 | 18 | 23) {
                c == '-'
            } else {
                c.is_ascii_hexdigit()
            }
        });
    if ok {
        Ok(t.to_ascii_lowercase())
    } else {
        Err(format!("expected a GUID, found \"{}\"", short(t)))
    }
}

/// The start of a text, for messages about it.
fn short(t: &str) -> String {
    let mut s: String = t.chars().take(40).collect();
    if s.len() < t.len() {
        s.push('…');
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<Chunk, ArchiveError> {
        read_xml(text.as_bytes(), &Limits::default())
    }

    #[test]
    fn reads_items_of_every_kind_of_shape() {
        let root = read(
            r#"<?xml version="1.0"?><Archive name="Root"><items count="4">
            <item name="p" type_name="gh_point3d" type_code="51"><X>1</X><Y>2.5</Y><Z>-3</Z></item>
            <item name="c" type_name="gh_drawing_color" type_code="36"><ARGB>255;1;2;3</ARGB></item>
            <item name="g" type_name="gh_guid" type_code="9">E5824402-41F0-49C7-B71E-834DEA734DD7</item>
            <item name="s" index="2" type_name="gh_string" type_code="10"></item>
            </items><chunks count="1"><chunk name="A" index="3"><items count="0" /></chunk></chunks></Archive>"#,
        )
        .unwrap();
        assert_eq!(root.items[0].value, Value::Point3([1.0, 2.5, -3.0]));
        assert_eq!(root.items[1].value, Value::Color([255, 1, 2, 3]));
        assert_eq!(root.str("g"), Some("e5824402-41f0-49c7-b71e-834dea734dd7"));
        assert_eq!(root.items[3].index, Some(2));
        assert_eq!(root.str("s"), Some(""));
        assert_eq!(root.chunks[0].index, Some(3));
    }

    #[test]
    fn bad_values_name_the_item_and_position() {
        let err = read(
            "<Archive name=\"Root\"><items count=\"1\">\n<item name=\"n\" type_code=\"6\">abc</item></items></Archive>",
        )
        .unwrap_err();
        assert_eq!(
            err.to_string(),
            "line 2, column 1: item n: expected a number, found \"abc\""
        );
        let err = read("<Archive><items>").unwrap_err();
        assert!(err.to_string().starts_with("line 1"), "{err}");
        let err = read("<NotAnArchive/>").unwrap_err();
        assert!(
            err.to_string().contains("not a Grasshopper archive"),
            "{err}"
        );
    }

    #[test]
    fn deep_nesting_is_an_error() {
        let mut text = String::from("<Archive name=\"Root\">");
        for _ in 0..100 {
            text.push_str("<chunks><chunk name=\"c\">");
        }
        for _ in 0..100 {
            text.push_str("</chunk></chunks>");
        }
        text.push_str("</Archive>");
        let err = read(&text).unwrap_err();
        assert!(
            err.to_string().contains("deeper than the limit of 64"),
            "{err}"
        );
    }
}
