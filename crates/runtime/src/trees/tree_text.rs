//! Data trees written on one line in Grasshopper's path notation:
//! `{0;0}:[1, 2, 3] {0;1}:[4, null]`.
//!
//! Each branch is its path, a colon and its items in square brackets; branches are separated by
//! white space and printed in path order. Items are written per type: numbers as
//! [`format_number`](crate::file::value_text::format_number) prints them (`0.5`, `1E+15`, `NaN`),
//! integers in decimal, booleans `true`/`false`, text in double quotes with `\"`, `\\`, `\n`,
//! `\r`, `\t` and `\u{..}` escapes, points and vectors `{1, 2, 3}`, domains `0 To 1`, and `null`
//! for a null item. An empty branch is `{0}:[]` and an empty tree is the empty string. The
//! notation is described in `docs/data-trees.md`.

use std::collections::BTreeSet;
use std::fmt;

use locus_kernel::{Interval, Point3, Vector3};

use crate::file::value_text::{
    format_plane, format_transform, parse_number, write_number, write_quoted,
};
use crate::{Branch, DataTree, DataType, TreePath, Value};

/// Why a tree could not be read from text: the column (in characters, from 1) and the problem.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("invalid tree text at column {column}: {message}")]
pub struct TreeTextError {
    /// The column where the problem was found, counted in characters from 1.
    pub column: usize,
    /// What is wrong.
    pub message: String,
}

impl DataTree {
    /// The tree in one-line Grasshopper notation, such as `{0;0}:[1, 2, 3] {0;1}:[4]`.
    ///
    /// Items of any type are printed; trees of numbers, integers, booleans, text, points,
    /// vectors and domains read back with [`DataTree::parse_text`] given their type. Planes and
    /// transforms are printed for reading only.
    pub fn to_text(&self) -> String {
        let mut out = String::new();
        for (b, (path, branch)) in self.branches().iter().enumerate() {
            if b > 0 {
                out.push(' ');
            }
            out.push_str(&path.to_string());
            out.push_str(":[");
            for i in 0..branch.len() {
                if i > 0 {
                    out.push_str(", ");
                }
                match branch.value(i) {
                    None => out.push_str("null"),
                    Some(v) => write_item(&mut out, &v),
                }
            }
            out.push(']');
        }
        out
    }

    /// A tree of numbers from one-line notation: `DataTree::from_text("{0}:[1, null, 3]")`.
    ///
    /// # Errors
    /// [`TreeTextError`] with the column of the first problem.
    pub fn from_text(text: &str) -> Result<DataTree, TreeTextError> {
        Self::parse_text(text, DataType::Number)
    }

    /// A tree of items of type `data_type` from one-line notation.
    ///
    /// With `Generic`, each item's type is read from its spelling: quoted text, `true`/`false`,
    /// `{x, y, z}` points, `a To b` domains, and other numbers as `Number`.
    ///
    /// # Errors
    /// [`TreeTextError`] with the column of the first problem: bad paths, duplicate paths,
    /// items that are not of the type, missing brackets or commas. Planes and transforms cannot
    /// be read.
    pub fn parse_text(text: &str, data_type: DataType) -> Result<DataTree, TreeTextError> {
        Parser {
            text,
            pos: 0,
            data_type,
        }
        .tree()
    }
}

fn write_item(out: &mut String, value: &Value) {
    match value {
        Value::Number(x) => write_number(out, *x),
        Value::Integer(i) => out.push_str(&i.to_string()),
        Value::Boolean(b) => out.push_str(if *b { "true" } else { "false" }),
        Value::Text(t) => write_quoted(out, t),
        Value::Point(p) => write_xyz(out, p.x, p.y, p.z),
        Value::Vector(v) => write_xyz(out, v.x, v.y, v.z),
        Value::Domain(d) => {
            write_number(out, d.t0);
            out.push_str(" To ");
            write_number(out, d.t1);
        }
        Value::Plane(p) => out.push_str(&format_plane(p)),
        Value::Transform(t) => out.push_str(&format_transform(t)),
        other => write_quoted(out, &crate::file::value_text::format_value(other)),
    }
}

fn write_xyz(out: &mut String, x: f64, y: f64, z: f64) {
    out.push('{');
    write_number(out, x);
    out.push_str(", ");
    write_number(out, y);
    out.push_str(", ");
    write_number(out, z);
    out.push('}');
}

struct Parser<'a> {
    text: &'a str,
    /// Byte offset of the next character.
    pos: usize,
    data_type: DataType,
}

impl<'a> Parser<'a> {
    fn tree(mut self) -> Result<DataTree, TreeTextError> {
        let mut branches = Vec::new();
        let mut seen = BTreeSet::new();
        loop {
            self.skip_space();
            if self.rest().is_empty() {
                break;
            }
            let start = self.pos;
            let path = self.path()?;
            if !seen.insert(path.clone()) {
                return Err(self.error_at(start, format!("duplicate path {path}")));
            }
            self.skip_space();
            self.expect(':')?;
            self.skip_space();
            let branch = self.branch()?;
            branches.push((path, branch));
        }
        Ok(DataTree::from_branches(branches))
    }

    fn path(&mut self) -> Result<TreePath, TreeTextError> {
        if !self.rest().starts_with('{') {
            return Err(self.error("expected a path such as `{0;1}`"));
        }
        let Some(len) = self.rest().find('}') else {
            return Err(self.error("missing `}` after the path"));
        };
        let start = self.pos;
        let text = &self.rest()[..=len];
        let path = text
            .parse::<TreePath>()
            .map_err(|e| self.error_at(start, e.to_string()))?;
        self.pos += len + 1;
        Ok(path)
    }

    fn branch(&mut self) -> Result<Branch, TreeTextError> {
        self.expect('[')?;
        let mut branch = Branch::new(self.data_type);
        self.skip_space();
        if self.eat(']') {
            return Ok(branch);
        }
        loop {
            self.skip_space();
            self.item(&mut branch)?;
            self.skip_space();
            if self.eat(',') {
                continue;
            }
            if self.eat(']') {
                return Ok(branch);
            }
            return Err(self.error("expected `,` or `]`"));
        }
    }

    fn item(&mut self, branch: &mut Branch) -> Result<(), TreeTextError> {
        let start = self.pos;
        if self.peek_word() == "null" {
            self.pos += 4;
            branch.push_null();
            return Ok(());
        }
        match self.data_type {
            DataType::Number => {
                let x = self.number()?;
                branch.push(x);
            }
            DataType::Integer => {
                let word = self.word();
                let i: i64 = word
                    .parse()
                    .map_err(|_| self.error_at(start, format!("`{word}` is not an integer")))?;
                branch.push(i);
            }
            DataType::Boolean => {
                let word = self.word();
                let b = if word.eq_ignore_ascii_case("true") {
                    true
                } else if word.eq_ignore_ascii_case("false") {
                    false
                } else {
                    return Err(self.error_at(start, format!("`{word}` is not a boolean")));
                };
                branch.push(b);
            }
            DataType::Text => {
                let t = self.quoted()?;
                branch.push(t);
            }
            DataType::Point => {
                let [x, y, z] = self.xyz()?;
                branch.push(Point3::new(x, y, z));
            }
            DataType::Vector => {
                let [x, y, z] = self.xyz()?;
                branch.push(Vector3::new(x, y, z));
            }
            DataType::Domain => {
                let d = self.domain()?;
                branch.push(d);
            }
            DataType::Generic => {
                let v = self.any_value()?;
                branch.push_value(v);
            }
            other => {
                return Err(self.error(format!("{other} items cannot be read from tree text")));
            }
        }
        Ok(())
    }

    fn any_value(&mut self) -> Result<Value, TreeTextError> {
        if self.rest().starts_with('"') {
            return self.quoted().map(Value::Text);
        }
        if self.rest().starts_with('{') {
            let [x, y, z] = self.xyz()?;
            return Ok(Value::Point(Point3::new(x, y, z)));
        }
        let word = self.peek_word();
        if word.eq_ignore_ascii_case("true") || word.eq_ignore_ascii_case("false") {
            self.pos += word.len();
            return Ok(Value::Boolean(word.eq_ignore_ascii_case("true")));
        }
        let t0 = self.number()?;
        match self.domain_end()? {
            Some(t1) => Ok(Value::Domain(Interval::new(t0, t1))),
            None => Ok(Value::Number(t0)),
        }
    }

    fn domain(&mut self) -> Result<Interval, TreeTextError> {
        let t0 = self.number()?;
        match self.domain_end()? {
            Some(t1) => Ok(Interval::new(t0, t1)),
            None => Err(self.error("expected `To` and the end of the domain")),
        }
    }

    /// After a number: ` To b` gives `Some(b)`; anything else is left unread.
    fn domain_end(&mut self) -> Result<Option<f64>, TreeTextError> {
        let save = self.pos;
        self.skip_space();
        if self.peek_word().eq_ignore_ascii_case("to") {
            self.pos += 2;
            self.skip_space();
            return self.number().map(Some);
        }
        self.pos = save;
        Ok(None)
    }

    fn number(&mut self) -> Result<f64, TreeTextError> {
        let start = self.pos;
        let word = self.word();
        if word.is_empty() {
            return Err(self.error_at(start, "expected a number".to_owned()));
        }
        parse_number(word).ok_or_else(|| self.error_at(start, format!("`{word}` is not a number")))
    }

    fn xyz(&mut self) -> Result<[f64; 3], TreeTextError> {
        self.expect('{')?;
        let mut xyz = [0.0; 3];
        for (k, c) in xyz.iter_mut().enumerate() {
            self.skip_space();
            *c = self.number()?;
            self.skip_space();
            self.expect(if k < 2 { ',' } else { '}' })?;
        }
        Ok(xyz)
    }

    fn quoted(&mut self) -> Result<String, TreeTextError> {
        let start = self.pos;
        self.expect('"')?;
        let mut out = String::new();
        let text: &'a str = self.text;
        let rest = &text[self.pos..];
        let mut chars = rest.char_indices();
        while let Some((i, c)) = chars.next() {
            match c {
                '"' => {
                    self.pos += i + 1;
                    return Ok(out);
                }
                '\\' => match chars.next() {
                    Some((_, '"')) => out.push('"'),
                    Some((_, '\\')) => out.push('\\'),
                    Some((_, 'n')) => out.push('\n'),
                    Some((_, 'r')) => out.push('\r'),
                    Some((_, 't')) => out.push('\t'),
                    Some((j, 'u')) => {
                        let code = rest[j + 1..]
                            .strip_prefix('{')
                            .and_then(|r| r.split_once('}'))
                            .and_then(|(hex, _)| {
                                u32::from_str_radix(hex, 16).ok().map(|n| (hex, n))
                            })
                            .and_then(|(hex, n)| char::from_u32(n).map(|c| (hex.len(), c)));
                        let Some((hex_len, c)) = code else {
                            return Err(self.error_at(self.pos + j, "bad `\\u{..}` escape".into()));
                        };
                        out.push(c);
                        // Skip `{`, the hex digits and `}`.
                        for _ in 0..hex_len + 2 {
                            chars.next();
                        }
                    }
                    Some((j, other)) => {
                        return Err(
                            self.error_at(self.pos + j, format!("unknown escape `\\{other}`"))
                        );
                    }
                    None => break,
                },
                c => out.push(c),
            }
        }
        Err(self.error_at(start, "unterminated text".to_owned()))
    }

    fn rest(&self) -> &'a str {
        let text: &'a str = self.text;
        &text[self.pos..]
    }

    fn skip_space(&mut self) {
        let rest = self.rest();
        self.pos += rest.len() - rest.trim_start().len();
    }

    /// The run of characters up to white space, `,`, `]`, `}` or the end, without consuming it.
    fn peek_word(&self) -> &'a str {
        let rest = self.rest();
        let end = rest
            .find(|c: char| c.is_whitespace() || matches!(c, ',' | ']' | '}'))
            .unwrap_or(rest.len());
        &rest[..end]
    }

    fn word(&mut self) -> &'a str {
        let word = self.peek_word();
        self.pos += word.len();
        word
    }

    fn eat(&mut self, c: char) -> bool {
        if self.rest().starts_with(c) {
            self.pos += c.len_utf8();
            true
        } else {
            false
        }
    }

    fn expect(&mut self, c: char) -> Result<(), TreeTextError> {
        if self.eat(c) {
            Ok(())
        } else {
            let found = match self.rest().chars().next() {
                Some(f) => format!("`{f}`"),
                None => "the end".to_owned(),
            };
            Err(self.error(format!("expected `{c}`, found {found}")))
        }
    }

    fn error(&self, message: impl Into<String>) -> TreeTextError {
        self.error_at(self.pos, message.into())
    }

    fn error_at(&self, pos: usize, message: String) -> TreeTextError {
        TreeTextError {
            column: self.text[..pos.min(self.text.len())].chars().count() + 1,
            message,
        }
    }
}

/// A tree that displays in one-line notation (see [`DataTree::text`]).
#[derive(Clone, Copy, Debug)]
pub struct TreeText<'a>(&'a DataTree);

impl fmt::Display for TreeText<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0.to_text())
    }
}

impl DataTree {
    /// The tree as a value that displays in one-line notation, for `format!` and `assert!`
    /// messages.
    pub fn text(&self) -> TreeText<'_> {
        TreeText(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_kernel::Plane;

    #[test]
    fn prints_grasshopper_notation() {
        let mut t = DataTree::new();
        t.insert(TreePath::from([0, 1]), Branch::from_items(vec![4.0]));
        t.insert(
            TreePath::from([0, 0]),
            Branch::from_items(vec![1.0, 2.5, 3.0]),
        );
        assert_eq!(t.to_text(), "{0;0}:[1, 2.5, 3] {0;1}:[4]");
        assert_eq!(format!("{}", t.text()), "{0;0}:[1, 2.5, 3] {0;1}:[4]");
        assert_eq!(DataTree::new().to_text(), "");
    }

    #[test]
    fn parses_numbers_with_nulls_and_empty_branches() {
        let t = DataTree::from_text(" {0;1}:[] {0}:[1, null, -3e2]\n{2}:[ NaN ]").unwrap();
        assert_eq!(t.branch_count(), 3);
        assert_eq!(t.to_text(), "{0}:[1, null, -300] {0;1}:[] {2}:[NaN]");
        let b = t.branch(&TreePath::zero()).unwrap();
        assert_eq!(b.data_type(), DataType::Number);
        assert!(b.is_null(1));
        assert_eq!(b.slice::<f64>().map(<[f64]>::len), Some(3));
        assert!(DataTree::from_text("").unwrap().is_empty());
    }

    #[test]
    fn round_trips_every_readable_type() {
        let cases = [
            (DataType::Number, "{0}:[1, 0.1, 1E+20, -Infinity, null]"),
            (
                DataType::Integer,
                "{0;0}:[1, -2, 9223372036854775807] {0;1}:[null]",
            ),
            (DataType::Boolean, "{3}:[true, false, null]"),
            (
                DataType::Text,
                r#"{0}:["a, b", "say \"hi\"", "", "x\ny", "]", "null", null]"#,
            ),
            (DataType::Point, "{0}:[{1, 2, 3}, null, {-0.5, 0, 1E+100}]"),
            (DataType::Vector, "{0}:[{0, 0, 1}]"),
            (DataType::Domain, "{0}:[0 To 1, -2 To 2.5]"),
            (
                DataType::Generic,
                r#"{0}:[1, "1", true, {1, 2, 3}, 0 To 1, null]"#,
            ),
        ];
        for (data_type, text) in cases {
            let t = DataTree::parse_text(text, data_type).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert_eq!(t.to_text(), text);
        }
    }

    #[test]
    fn generic_items_take_their_type_from_their_spelling() {
        let t = DataTree::parse_text(
            r#"{0}:[1, "1", TRUE, {1, 2, 3}, 0 To 1]"#,
            DataType::Generic,
        )
        .unwrap();
        let types: Vec<DataType> = t.values().map(|v| v.unwrap().data_type()).collect();
        assert_eq!(
            types,
            [
                DataType::Number,
                DataType::Text,
                DataType::Boolean,
                DataType::Point,
                DataType::Domain
            ]
        );
    }

    #[test]
    fn reports_problems_with_columns() {
        let cases = [
            ("{0}:[1, x]", 9, "`x` is not a number"),
            ("{0}:[1 2]", 8, "expected `,` or `]`"),
            ("{0}:[1,]", 8, "expected a number"),
            ("{0}[1]", 4, "expected `:`, found `[`"),
            ("{0}:[1", 7, "expected `,` or `]`"),
            (
                "{a}:[1]",
                1,
                "invalid tree path `{a}`: indices must be non-negative integers",
            ),
            ("{0}:[1] {0}:[2]", 9, "duplicate path {0}"),
            ("[1]", 1, "expected a path such as `{0;1}`"),
            ("{0:[1]", 1, "missing `}` after the path"),
        ];
        for (text, column, message) in cases {
            let e = DataTree::from_text(text).unwrap_err();
            assert_eq!((e.column, e.message.as_str()), (column, message), "{text}");
        }
        let e = DataTree::parse_text("{0}:[1.5]", DataType::Integer).unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid tree text at column 6: `1.5` is not an integer"
        );
        let e = DataTree::parse_text(r#"{0}:["abc]"#, DataType::Text).unwrap_err();
        assert_eq!(e.message, "unterminated text");
        let e = DataTree::parse_text("{0}:[0 To]", DataType::Domain).unwrap_err();
        assert_eq!(e.message, "expected a number");
        let e = DataTree::parse_text("{0}:[1]", DataType::Plane).unwrap_err();
        assert_eq!(e.message, "Plane items cannot be read from tree text");
    }

    #[test]
    fn prints_planes_for_reading() {
        let t = DataTree::from_item(Plane::WORLD_XY);
        assert_eq!(t.to_text(), "{0}:[O{0, 0, 0} Z{0, 0, 1}]");
    }

    #[test]
    fn unicode_columns_count_characters() {
        let e = DataTree::parse_text("{0}:[\"é\", é]", DataType::Text).unwrap_err();
        assert_eq!(e.column, 11);
    }
}
