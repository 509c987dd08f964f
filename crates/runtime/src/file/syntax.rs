//! A RON reader that keeps the position of every value, and a canonical RON printer.
//!
//! Graph files and literal values are RON. The `ron` crate reads RON into serde types but
//! forgets where each value was written, and checking a graph needs those positions to point
//! at the node id, port name or value at fault. This module reads the subset of RON that
//! graph files use into a small syntax tree ([`Node`]) whose every value carries its byte
//! span, and prints such trees back in one canonical layout.
//!
//! The subset: numbers (`1`, `-2.5`, `1e-7`, `inf`, `NaN`), strings (`"a\"b"`, raw
//! `r#"…"#`), `true` and `false`, identifiers (`graft`, `XY`, `null`), tuples `(a, b)`,
//! unnamed and named structs `(x: 1)` and `Curve(degree: 3)`, named tuples `Vector(1, 2, 3)`,
//! lists `[a, b]` and maps `{"k": v}`, with `//` and nested `/* */` comments and optional
//! trailing commas. Characters (`'a'`), byte strings and `#![enable(…)]` extensions are not
//! used by graph files and are rejected with a message.

use std::fmt::Write as _;
use std::ops::Range;

/// How deeply values may nest before the reader gives up (protects the stack).
const MAX_DEPTH: usize = 128;

/// The width the pretty printer fills before it breaks a value over several lines.
pub(crate) const LINE_WIDTH: usize = 100;

/// One RON value with its byte span in the text it was read from.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Node {
    /// What the value is.
    pub kind: Kind,
    /// Where it was written (byte offsets).
    pub span: Range<usize>,
}

/// The kinds of RON values.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Kind {
    /// A number, as written (`-2.5`, `1e-7`, `inf`).
    Number(String),
    /// A string, escapes resolved.
    Str(String),
    /// `true` or `false`.
    Bool(bool),
    /// A bare identifier (`graft`, `XY`, `null`).
    Ident(String),
    /// A tuple `(a, b)`, the unit `()`, or a named tuple `Vector(1, 2, 3)`.
    Tuple(Option<String>, Vec<Node>),
    /// A struct `(x: 1, y: 2)` or a named struct `Curve(degree: 3)`.
    Struct(Option<String>, Vec<Field>),
    /// A list `[a, b]`.
    List(Vec<Node>),
    /// A map `{k: v}`.
    Map(Vec<(Node, Node)>),
    /// Text printed as is: a literal that is not valid RON, kept by the writer so that
    /// nothing is lost (the file then fails to load, pointing at it).
    Raw(String),
}

/// One field of a struct.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Field {
    /// The field name.
    pub name: String,
    /// Where the name was written.
    pub name_span: Range<usize>,
    /// The value.
    pub value: Node,
}

/// A syntax error: a message and the byte offset where reading stopped.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct SyntaxError {
    /// What was expected or found.
    pub message: String,
    /// The byte offset of the fault.
    pub offset: usize,
}

impl Node {
    /// A short description of the value for messages: the text of scalars, the shape of
    /// compound values (`a list of 3 items`).
    pub fn describe(&self) -> String {
        fn items(n: usize) -> String {
            if n == 1 {
                "1 item".to_owned()
            } else {
                format!("{n} items")
            }
        }
        match &self.kind {
            Kind::Number(n) => n.clone(),
            Kind::Str(s) => quote(s),
            Kind::Bool(b) => b.to_string(),
            Kind::Ident(i) => i.clone(),
            Kind::Tuple(None, v) if v.is_empty() => "()".to_owned(),
            Kind::Tuple(None, v) => format!("a tuple of {}", items(v.len())),
            Kind::Tuple(Some(name), _) | Kind::Struct(Some(name), _) => format!("{name}(…)"),
            Kind::Struct(None, _) => "a struct".to_owned(),
            Kind::List(v) => format!("a list of {}", items(v.len())),
            Kind::Map(v) => format!("a map of {}", items(v.len())),
            Kind::Raw(text) => text.clone(),
        }
    }

    /// The value as compact canonical RON on one line.
    pub fn to_compact(&self) -> String {
        let mut out = String::new();
        write_compact(self, &mut out);
        out
    }

    /// Builds a node without a source position (for printing).
    pub fn new(kind: Kind) -> Self {
        Self { kind, span: 0..0 }
    }
}

/// Reads one RON value that must fill the whole text (comments and whitespace aside).
pub(crate) fn parse(text: &str) -> Result<Node, SyntaxError> {
    let mut p = Parser { text, pos: 0 };
    p.skip_trivia()?;
    if p.peek() == Some(b'#') {
        return Err(p.error("RON extensions (`#![enable(…)]`) are not supported in graph files"));
    }
    let node = p.value(0)?;
    p.skip_trivia()?;
    if p.pos < text.len() {
        return Err(p.error(&format!(
            "unexpected {} after the end of the value",
            p.describe_here()
        )));
    }
    Ok(node)
}

struct Parser<'a> {
    text: &'a str,
    pos: usize,
}

impl Parser<'_> {
    fn bytes(&self) -> &[u8] {
        self.text.as_bytes()
    }

    fn peek(&self) -> Option<u8> {
        self.bytes().get(self.pos).copied()
    }

    fn peek_at(&self, ahead: usize) -> Option<u8> {
        self.bytes().get(self.pos + ahead).copied()
    }

    fn error(&self, message: &str) -> SyntaxError {
        SyntaxError {
            message: message.to_owned(),
            offset: self.pos,
        }
    }

    /// What stands at the current position, for messages.
    fn describe_here(&self) -> String {
        match self.text[self.pos..].chars().next() {
            None => "end of file".to_owned(),
            Some(c) => format!("`{c}`"),
        }
    }

    fn expected(&self, what: &str) -> SyntaxError {
        self.error(&format!("expected {what}, found {}", self.describe_here()))
    }

    fn skip_trivia(&mut self) -> Result<(), SyntaxError> {
        loop {
            match self.peek() {
                Some(b' ' | b'\t' | b'\n' | b'\r') => self.pos += 1,
                Some(b'/') if self.peek_at(1) == Some(b'/') => {
                    while let Some(c) = self.peek() {
                        if c == b'\n' {
                            break;
                        }
                        self.pos += 1;
                    }
                }
                Some(b'/') if self.peek_at(1) == Some(b'*') => {
                    let start = self.pos;
                    self.pos += 2;
                    let mut depth = 1;
                    while depth > 0 {
                        match (self.peek(), self.peek_at(1)) {
                            (None, _) => {
                                self.pos = start;
                                return Err(self.error("unterminated block comment"));
                            }
                            (Some(b'*'), Some(b'/')) => {
                                depth -= 1;
                                self.pos += 2;
                            }
                            (Some(b'/'), Some(b'*')) => {
                                depth += 1;
                                self.pos += 2;
                            }
                            _ => self.pos += 1,
                        }
                    }
                }
                _ => return Ok(()),
            }
        }
    }

    fn value(&mut self, depth: usize) -> Result<Node, SyntaxError> {
        if depth > MAX_DEPTH {
            return Err(self.error("values are nested too deeply"));
        }
        let start = self.pos;
        let kind = match self.peek() {
            None => return Err(self.expected("a value")),
            Some(b'"') => Kind::Str(self.string()?),
            Some(b'r') if matches!(self.peek_at(1), Some(b'"' | b'#')) => {
                Kind::Str(self.raw_string()?)
            }
            Some(b'0'..=b'9' | b'.' | b'+' | b'-') => Kind::Number(self.number()?),
            Some(b'(') => self.parenthesised(None, depth)?,
            Some(b'[') => Kind::List(self.list(depth)?),
            Some(b'{') => Kind::Map(self.map(depth)?),
            Some(b'\'') => return Err(self.error("character literals are not supported")),
            Some(c) if c == b'_' || c.is_ascii_alphabetic() => {
                let ident = self.ident();
                let mut after = Parser {
                    text: self.text,
                    pos: self.pos,
                };
                after.skip_trivia()?;
                if after.peek() == Some(b'(') {
                    self.pos = after.pos;
                    self.parenthesised(Some(ident), depth)?
                } else {
                    match ident.as_str() {
                        "true" => Kind::Bool(true),
                        "false" => Kind::Bool(false),
                        "inf" | "NaN" => Kind::Number(ident),
                        _ => Kind::Ident(ident),
                    }
                }
            }
            Some(_) => return Err(self.expected("a value")),
        };
        Ok(Node {
            kind,
            span: start..self.pos,
        })
    }

    fn ident(&mut self) -> String {
        let start = self.pos;
        while let Some(c) = self.peek() {
            if c == b'_' || c.is_ascii_alphanumeric() {
                self.pos += 1;
            } else {
                break;
            }
        }
        self.text[start..self.pos].to_owned()
    }

    fn number(&mut self) -> Result<String, SyntaxError> {
        let start = self.pos;
        if matches!(self.peek(), Some(b'+' | b'-')) {
            self.pos += 1;
        }
        if matches!(self.peek(), Some(b'i' | b'N')) {
            let ident = self.ident();
            if ident == "inf" || ident == "NaN" {
                return Ok(self.text[start..self.pos].to_owned());
            }
            self.pos = start;
            return Err(self.error("expected a number"));
        }
        let digits = |p: &mut Self| {
            let s = p.pos;
            while matches!(p.peek(), Some(b'0'..=b'9' | b'_')) {
                p.pos += 1;
            }
            p.pos > s
        };
        let mut any = digits(self);
        if self.peek() == Some(b'.') && !matches!(self.peek_at(1), Some(b'.')) {
            self.pos += 1;
            any |= digits(self);
        }
        if !any {
            self.pos = start;
            return Err(self.expected("a number"));
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            let mark = self.pos;
            self.pos += 1;
            if matches!(self.peek(), Some(b'+' | b'-')) {
                self.pos += 1;
            }
            if !digits(self) {
                self.pos = mark;
                return Err(self.error("expected digits in the exponent"));
            }
        }
        if matches!(self.peek(), Some(c) if c == b'_' || c.is_ascii_alphabetic()) {
            return Err(self.error(&format!("unexpected {} in a number", self.describe_here())));
        }
        Ok(self.text[start..self.pos].to_owned())
    }

    fn string(&mut self) -> Result<String, SyntaxError> {
        let start = self.pos;
        self.pos += 1;
        let mut out = String::new();
        loop {
            let rest = &self.text[self.pos..];
            let Some(c) = rest.chars().next() else {
                self.pos = start;
                return Err(self.error("unterminated string"));
            };
            self.pos += c.len_utf8();
            match c {
                '"' => return self.within_text_limit(start, out),
                '\\' => {
                    let esc_start = self.pos - 1;
                    let Some(e) = self.text[self.pos..].chars().next() else {
                        self.pos = start;
                        return Err(self.error("unterminated string"));
                    };
                    self.pos += e.len_utf8();
                    match e {
                        '"' => out.push('"'),
                        '\\' => out.push('\\'),
                        '/' => out.push('/'),
                        'n' => out.push('\n'),
                        't' => out.push('\t'),
                        'r' => out.push('\r'),
                        '0' => out.push('\0'),
                        'b' => out.push('\u{8}'),
                        'f' => out.push('\u{c}'),
                        'u' => out.push(self.unicode_escape(esc_start)?),
                        _ => {
                            self.pos = esc_start;
                            return Err(self.error(&format!("unknown escape `\\{e}` in a string")));
                        }
                    }
                }
                c => out.push(c),
            }
        }
    }

    /// The string read from `start`, or an error there when it is longer than
    /// [`MAX_TEXT_BYTES`](crate::MAX_TEXT_BYTES) (literal texts, formulas and masks).
    fn within_text_limit(&mut self, start: usize, text: String) -> Result<String, SyntaxError> {
        if text.len() <= crate::MAX_TEXT_BYTES {
            return Ok(text);
        }
        self.pos = start;
        Err(self.error(&format!(
            "the string is too long ({} bytes; the limit is {} bytes)",
            text.len(),
            crate::MAX_TEXT_BYTES
        )))
    }

    /// Reads the `{XXXX}` of a `\u{XXXX}` escape (the `\u` is already consumed).
    fn unicode_escape(&mut self, esc_start: usize) -> Result<char, SyntaxError> {
        let bad = |p: &mut Self| {
            p.pos = esc_start;
            Err(p.error("invalid unicode escape, expected `\\u{…}` with 1 to 6 hex digits"))
        };
        if self.peek() != Some(b'{') {
            return bad(self);
        }
        self.pos += 1;
        let hex_start = self.pos;
        while matches!(self.peek(), Some(c) if c.is_ascii_hexdigit()) {
            self.pos += 1;
        }
        let hex = &self.text[hex_start..self.pos];
        if self.peek() != Some(b'}') || hex.is_empty() || hex.len() > 6 {
            return bad(self);
        }
        self.pos += 1;
        match u32::from_str_radix(hex, 16).ok().and_then(char::from_u32) {
            Some(c) => Ok(c),
            None => bad(self),
        }
    }

    fn raw_string(&mut self) -> Result<String, SyntaxError> {
        let start = self.pos;
        self.pos += 1;
        let mut hashes = 0;
        while self.peek() == Some(b'#') {
            hashes += 1;
            self.pos += 1;
        }
        if self.peek() != Some(b'"') {
            return Err(self.expected("`\"` to open a raw string"));
        }
        self.pos += 1;
        let body = self.pos;
        let closing: String = std::iter::once('"')
            .chain(std::iter::repeat_n('#', hashes))
            .collect();
        match self.text[body..].find(&closing) {
            Some(len) => {
                self.pos = body + len + closing.len();
                self.within_text_limit(start, self.text[body..body + len].to_owned())
            }
            None => {
                self.pos = start;
                Err(self.error("unterminated raw string"))
            }
        }
    }

    /// Reads `( … )`: a tuple, or a struct when the first item is `name:`.
    fn parenthesised(&mut self, name: Option<String>, depth: usize) -> Result<Kind, SyntaxError> {
        self.pos += 1;
        self.skip_trivia()?;
        if self.is_field_start() {
            let mut fields = Vec::new();
            self.sequence(b')', |p| {
                if !p.is_field_start() {
                    return Err(p.expected("a field `name: value`"));
                }
                let name_start = p.pos;
                let field = p.ident();
                let name_span = name_start..p.pos;
                p.skip_trivia()?;
                p.pos += 1; // The colon, seen by `is_field_start`.
                p.skip_trivia()?;
                let value = p.value(depth + 1)?;
                fields.push(Field {
                    name: field,
                    name_span,
                    value,
                });
                Ok(())
            })?;
            Ok(Kind::Struct(name, fields))
        } else {
            let mut items = Vec::new();
            self.sequence(b')', |p| {
                items.push(p.value(depth + 1)?);
                Ok(())
            })?;
            Ok(Kind::Tuple(name, items))
        }
    }

    /// Whether the text at the position is `ident :` (not `ident ::`).
    fn is_field_start(&self) -> bool {
        let mut p = Parser {
            text: self.text,
            pos: self.pos,
        };
        match p.peek() {
            Some(c) if c == b'_' || c.is_ascii_alphabetic() => {}
            _ => return false,
        }
        p.ident();
        if p.skip_trivia().is_err() {
            return false;
        }
        p.peek() == Some(b':') && p.peek_at(1) != Some(b':')
    }

    fn list(&mut self, depth: usize) -> Result<Vec<Node>, SyntaxError> {
        self.pos += 1;
        let mut items = Vec::new();
        self.sequence(b']', |p| {
            items.push(p.value(depth + 1)?);
            Ok(())
        })?;
        Ok(items)
    }

    fn map(&mut self, depth: usize) -> Result<Vec<(Node, Node)>, SyntaxError> {
        self.pos += 1;
        let mut entries = Vec::new();
        self.sequence(b'}', |p| {
            let key = p.value(depth + 1)?;
            p.skip_trivia()?;
            if p.peek() != Some(b':') {
                return Err(p.expected("`:` after a map key"));
            }
            p.pos += 1;
            p.skip_trivia()?;
            let value = p.value(depth + 1)?;
            entries.push((key, value));
            Ok(())
        })?;
        Ok(entries)
    }

    /// Reads comma-separated elements up to `close` (after the opening bracket), allowing a
    /// trailing comma.
    fn sequence(
        &mut self,
        close: u8,
        mut element: impl FnMut(&mut Self) -> Result<(), SyntaxError>,
    ) -> Result<(), SyntaxError> {
        let close_char = close as char;
        loop {
            self.skip_trivia()?;
            if self.peek() == Some(close) {
                self.pos += 1;
                return Ok(());
            }
            element(self)?;
            self.skip_trivia()?;
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(c) if c == close => {
                    self.pos += 1;
                    return Ok(());
                }
                _ => return Err(self.expected(&format!("`,` or `{close_char}`"))),
            }
        }
    }
}

/// A string as a RON string literal, with escapes.
pub(crate) fn quote(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            '\r' => out.push_str("\\r"),
            c if c.is_control() => {
                let _ = write!(out, "\\u{{{:x}}}", c as u32);
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn write_compact(node: &Node, out: &mut String) {
    fn join<T>(out: &mut String, items: &[T], mut item: impl FnMut(&mut String, &T)) {
        for (i, x) in items.iter().enumerate() {
            if i > 0 {
                out.push_str(", ");
            }
            item(out, x);
        }
    }
    match &node.kind {
        Kind::Number(n) => out.push_str(n),
        Kind::Str(s) => out.push_str(&quote(s)),
        Kind::Bool(b) => out.push_str(if *b { "true" } else { "false" }),
        Kind::Ident(i) | Kind::Raw(i) => out.push_str(i),
        Kind::Tuple(name, items) => {
            if let Some(name) = name {
                out.push_str(name);
            }
            out.push('(');
            join(out, items, |o, n| write_compact(n, o));
            out.push(')');
        }
        Kind::Struct(name, fields) => {
            if let Some(name) = name {
                out.push_str(name);
            }
            out.push('(');
            join(out, fields, |o, f| {
                o.push_str(&f.name);
                o.push_str(": ");
                write_compact(&f.value, o);
            });
            out.push(')');
        }
        Kind::List(items) => {
            out.push('[');
            join(out, items, |o, n| write_compact(n, o));
            out.push(']');
        }
        Kind::Map(entries) => {
            out.push('{');
            join(out, entries, |o, (k, v)| {
                write_compact(k, o);
                o.push_str(": ");
                write_compact(v, o);
            });
            out.push('}');
        }
    }
}

/// Writes `node` starting at column `indent` (the caller has written the indentation and
/// `prefix_len` more characters on the line): on one line when it fits in [`LINE_WIDTH`]
/// together with `suffix_len` characters that follow it, otherwise with one element per line,
/// each indented four more spaces and followed by a comma.
pub(crate) fn write_pretty(
    node: &Node,
    indent: usize,
    prefix_len: usize,
    suffix_len: usize,
    out: &mut String,
) {
    let compact = node.to_compact();
    if indent + prefix_len + compact.chars().count() + suffix_len <= LINE_WIDTH
        || !is_compound(node)
    {
        out.push_str(&compact);
        return;
    }
    write_broken(node, indent, out);
}

/// Whether a value has elements that could go on lines of their own.
fn is_compound(node: &Node) -> bool {
    match &node.kind {
        Kind::Tuple(_, v) | Kind::List(v) => !v.is_empty(),
        Kind::Struct(_, v) => !v.is_empty(),
        Kind::Map(v) => !v.is_empty(),
        _ => false,
    }
}

/// Writes a compound value with one element per line.
pub(crate) fn write_broken(node: &Node, indent: usize, out: &mut String) {
    let inner = indent + 4;
    let pad = " ".repeat(inner);
    let line = |out: &mut String, prefix: &str, value: &Node| {
        out.push('\n');
        out.push_str(&pad);
        out.push_str(prefix);
        write_pretty(value, inner, prefix.chars().count(), 1, out);
        out.push(',');
    };
    let close = match &node.kind {
        Kind::Tuple(name, items) => {
            out.push_str(name.as_deref().unwrap_or(""));
            out.push('(');
            for item in items {
                line(out, "", item);
            }
            ')'
        }
        Kind::Struct(name, fields) => {
            out.push_str(name.as_deref().unwrap_or(""));
            out.push('(');
            for f in fields {
                line(out, &format!("{}: ", f.name), &f.value);
            }
            ')'
        }
        Kind::List(items) => {
            out.push('[');
            for item in items {
                line(out, "", item);
            }
            ']'
        }
        Kind::Map(entries) => {
            out.push('{');
            for (k, v) in entries {
                line(out, &format!("{}: ", k.to_compact()), v);
            }
            '}'
        }
        _ => {
            out.push_str(&node.to_compact());
            return;
        }
    };
    out.push('\n');
    out.push_str(&" ".repeat(indent));
    out.push(close);
}

/// The start offsets of the lines of a text, to turn byte offsets into lines and columns in
/// logarithmic time (a file with thousands of diagnostics must not take quadratic time).
#[derive(Clone, Debug, Default)]
pub(crate) struct LineIndex {
    starts: Vec<usize>,
}

impl LineIndex {
    /// Indexes the lines of `text`.
    pub fn new(text: &str) -> Self {
        let starts = std::iter::once(0)
            .chain(text.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        Self { starts }
    }

    /// The 1-based line and column (in characters) of a byte offset in `text`, the text this
    /// index was built from.
    pub fn line_column(&self, text: &str, offset: usize) -> (usize, usize) {
        let mut offset = offset.min(text.len());
        while !text.is_char_boundary(offset) {
            offset -= 1;
        }
        let line = self.starts.partition_point(|&s| s <= offset).max(1);
        let start = self.starts.get(line - 1).copied().unwrap_or(0).min(offset);
        let column = 1 + text[start..offset].chars().count();
        (line, column)
    }
}

/// The 1-based line and column (in characters) of a byte offset in `text`.
#[cfg(test)]
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    LineIndex::new(text).line_column(text, offset)
}

#[cfg(test)]
mod tests;
