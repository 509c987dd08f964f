//! Sets › Text: Concatenate, Text Split, Text Join, Text Length, Replace Text, Text Case,
//! Match Text and Format.
//!
//! Texts are Rust strings (UTF-8); lengths and cases are Unicode's. Where .NET (which
//! Grasshopper is built on) differs, the node's description says so: .NET counts UTF-16 code
//! units, so a character outside the Basic Multilingual Plane (an emoji) has length 2 there
//! and 1 here. Format implements .NET's composite formatting for the common format strings
//! ([`format`] lists them) in the invariant culture.

use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Value, format_value};

/// Id of [`concatenate`].
pub const CONCATENATE: &str = "sets.concatenate";
/// Id of [`text_split`].
pub const TEXT_SPLIT: &str = "sets.text_split";
/// Id of [`text_join`].
pub const TEXT_JOIN: &str = "sets.text_join";
/// Id of [`text_length`].
pub const TEXT_LENGTH: &str = "sets.text_length";
/// Id of [`replace_text`].
pub const REPLACE_TEXT: &str = "sets.replace_text";
/// Id of [`text_case`].
pub const TEXT_CASE: &str = "sets.text_case";
/// Id of [`match_text`].
pub const MATCH_TEXT: &str = "sets.match_text";
/// Id of [`format`].
pub const FORMAT: &str = "sets.format";

/// The largest compiled regular expression Match Text accepts (bytes of the compiled program),
/// so that a hostile pattern cannot exhaust memory.
pub const MAX_REGEX_SIZE: usize = 1 << 20;

/// The widest field a Format placeholder may ask for (`{0,100000}`), and the most digits.
pub const MAX_FORMAT_WIDTH: usize = 10_000;

/// Registers the text nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        concatenate(),
        text_split(),
        text_join(),
        text_length(),
        replace_text(),
        text_case(),
        match_text(),
        format(),
    ] {
        registry.register(t);
    }
}

fn text_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("Text")
}

fn text_in(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Text).doc(doc)
}

/// Concatenate \[Concat\]: text fragments joined end to end.
pub fn concatenate() -> NodeType {
    text_node(CONCATENATE, "Concatenate", "Concat")
        .gh_guid("2013e425-8713-42e2-a661-b57e78840337")
        .description(
            "Joins text fragments end to end, in input order. A fragment without data (or a \
             null) adds nothing. The graph may name more inputs (C, D, …).",
        )
        .variable_inputs(
            Port::new("Fragment", "A", DataType::Text)
                .optional()
                .doc("A fragment of text; any value is written as text; optional."),
            &["A", "B"],
        )
        .output(Port::new("Result", "R", DataType::Text).doc("The fragments joined."))
        .solve(|s| {
            let mut out = String::new();
            for k in 0..s.input_count() {
                if let Some(t) = s.item_opt::<String>(k) {
                    out.push_str(t);
                }
            }
            s.set(0, out);
            Ok(())
        })
}

/// Text Split \[Split\]: a text cut at separator characters.
pub fn text_split() -> NodeType {
    text_node(TEXT_SPLIT, "Text Split", "Split")
        .gh_guid("04887d01-504c-480e-b2a2-01ea19cc5922")
        .description(
            "Splits a text into fragments at every occurrence of any of the separator \
             characters, as .NET's String.Split(char[]) does: empty fragments between \
             adjacent separators are kept (\"a,,b\" split at \",\" is a, \"\", b). Without \
             separators (an empty C) the text is split at white space.",
        )
        .input(text_in("Text", "T", "The text to split."))
        .input(
            text_in(
                "Separators",
                "C",
                "The separator characters, each one a separator; default a space.",
            )
            .default_value(" ".to_owned()),
        )
        .output(
            Port::new("Result", "R", DataType::Text)
                .list()
                .doc("The fragments, in order."),
        )
        .solve(|s| {
            let text = s.item::<String>(0)?.clone();
            let seps: Vec<char> = s.item::<String>(1)?.chars().collect();
            let parts: Vec<String> = if seps.is_empty() {
                text.split(char::is_whitespace).map(str::to_owned).collect()
            } else {
                text.split(|c| seps.contains(&c))
                    .map(str::to_owned)
                    .collect()
            };
            s.set_list(0, parts);
            Ok(())
        })
}

/// Text Join \[Join\]: a list of texts joined with a separator.
pub fn text_join() -> NodeType {
    text_node(TEXT_JOIN, "Text Join", "Join")
        .gh_guid("1274d51a-81e6-4ccf-ad1f-0edf4c769cac")
        .description(
            "Joins a list of texts into one, with the join text between neighbours. Null \
             items are skipped.",
        )
        .input(
            Port::new("Text", "T", DataType::Text)
                .list()
                .doc("The texts to join."),
        )
        .input(
            text_in(
                "Join",
                "J",
                "The text put between neighbours; default none.",
            )
            .optional()
            .default_value(String::new()),
        )
        .output(Port::new("Result", "R", DataType::Text).doc("The joined text."))
        .solve(|s| {
            let texts = s.list::<String>(0)?;
            let join = s.item_opt::<String>(1).cloned().unwrap_or_default();
            let parts: Vec<&str> = texts.present().map(String::as_str).collect();
            s.set(0, parts.join(&join));
            Ok(())
        })
}

/// Text Length \[Len\]: the number of characters of a text.
pub fn text_length() -> NodeType {
    text_node(TEXT_LENGTH, "Text Length", "Len")
        .gh_guid("dca05f6f-e3d9-42e3-b3bb-eb20363fb335")
        .description(
            "Counts the characters of a text (Unicode scalar values; .NET counts UTF-16 code \
             units, so a character beyond U+FFFF, such as an emoji, counts 1 here and 2 in \
             Grasshopper).",
        )
        .input(text_in("Text", "T", "The text to measure."))
        .output(Port::new("Length", "L", DataType::Integer).doc("The number of characters."))
        .lift1(|t: &String| Ok(i64::try_from(t.chars().count()).unwrap_or(i64::MAX)))
}

/// Replace Text \[Rep\]: every occurrence of a fragment replaced.
pub fn replace_text() -> NodeType {
    text_node(REPLACE_TEXT, "Replace Text", "Rep")
        .gh_guid("4df8df00-3635-45bd-95e6-f9206296c110")
        .description(
            "Replaces every occurrence of the fragment F in a text by R (case-sensitive, left \
             to right, without overlaps). An empty or missing F leaves the text unchanged; a \
             missing R deletes the occurrences.",
        )
        .input(text_in("Text", "T", "The text to change."))
        .input(text_in("Find", "F", "The fragment to find; optional.").optional())
        .input(text_in("Replace", "R", "The replacement; optional (nothing).").optional())
        .output(Port::new("Result", "R", DataType::Text).doc("The changed text."))
        .solve(|s| {
            let text = s.item::<String>(0)?;
            let find = s.item_opt::<String>(1).map(String::as_str).unwrap_or("");
            let with = s.item_opt::<String>(2).map(String::as_str).unwrap_or("");
            let out = if find.is_empty() {
                text.clone()
            } else {
                text.replace(find, with)
            };
            s.set(0, out);
            Ok(())
        })
}

/// Text Case \[Case\]: a text in upper and in lower case.
pub fn text_case() -> NodeType {
    text_node(TEXT_CASE, "Text Case", "Case")
        .gh_guid("b1991128-8bf1-4dea-8497-4b7188a64e9d")
        .description(
            "Writes a text in upper case and in lower case, by Unicode's case mappings (the \
             invariant culture; Grasshopper's Culture input is not supported).",
        )
        .input(text_in("Text", "T", "The text."))
        .output(Port::new("Upper Case", "U", DataType::Text).doc("The text in upper case."))
        .output(Port::new("Lower Case", "L", DataType::Text).doc("The text in lower case."))
        .solve(|s| {
            let t = s.item::<String>(0)?;
            let (u, l) = (t.to_uppercase(), t.to_lowercase());
            s.set(0, u);
            s.set(1, l);
            Ok(())
        })
}

/// Whether `text` matches the wildcard `pattern` of Visual Basic's `Like`: `*` any run of
/// characters, `?` one character, `#` one digit, `[abc]`/`[a-z]` one of a set, `[!abc]` one
/// not in it.
fn like(text: &[char], pattern: &[char]) -> Result<bool, NodeError> {
    // Dynamic programming over positions: reachable[i] = the pattern so far can end before
    // text[i]. Bounded by |text| × |pattern| steps.
    let mut reachable = vec![false; text.len() + 1];
    reachable[0] = true;
    let mut p = 0;
    while p < pattern.len() {
        let c = pattern[p];
        let mut next = vec![false; text.len() + 1];
        match c {
            '*' => {
                let mut any = false;
                for i in 0..=text.len() {
                    any |= reachable[i];
                    next[i] = any;
                }
                p += 1;
            }
            '[' => {
                let close = pattern[p + 1..]
                    .iter()
                    .position(|&c| c == ']')
                    .map(|k| p + 1 + k)
                    .ok_or_else(|| NodeError("the pattern has a [ without ]".into()))?;
                let mut set = &pattern[p + 1..close];
                let negate = set.first() == Some(&'!');
                if negate {
                    set = &set[1..];
                }
                let in_set = |ch: char| {
                    let mut k = 0;
                    while k < set.len() {
                        if k + 2 < set.len() && set[k + 1] == '-' {
                            if (set[k]..=set[k + 2]).contains(&ch) {
                                return true;
                            }
                            k += 3;
                        } else {
                            if set[k] == ch {
                                return true;
                            }
                            k += 1;
                        }
                    }
                    false
                };
                for i in 0..text.len() {
                    if reachable[i] && in_set(text[i]) != negate {
                        next[i + 1] = true;
                    }
                }
                p = close + 1;
            }
            _ => {
                for i in 0..text.len() {
                    let ok = match c {
                        '?' => true,
                        '#' => text[i].is_ascii_digit(),
                        c => text[i] == c,
                    };
                    if reachable[i] && ok {
                        next[i + 1] = true;
                    }
                }
                p += 1;
            }
        }
        reachable = next;
    }
    Ok(reachable[text.len()])
}

/// Match Text \[TMatch\]: whether a text matches a wildcard pattern and a regular expression.
pub fn match_text() -> NodeType {
    text_node(MATCH_TEXT, "Match Text", "TMatch")
        .gh_guid("3756c55f-95c3-442c-a027-6b3ab0455a94")
        .description(
            "Tests a text against a wildcard pattern P (the whole text, as Visual Basic's Like: \
             * any characters, ? one character, # one digit, [abc] or [a-z] one of a set, \
             [!abc] one not in it) and a regular expression R (found anywhere in the text, as \
             .NET's Regex.IsMatch; the syntax is the Rust regex crate's, which has no \
             look-around or back-references). The text matches when it matches every one given; \
             with neither, it is an error. Case sensitive unless C is false.",
        )
        .input(text_in("Text", "T", "The text to test."))
        .input(text_in("Pattern", "P", "A wildcard pattern; optional.").optional())
        .input(text_in("RegEx", "R", "A regular expression; optional.").optional())
        .input(
            Port::new("Case", "C", DataType::Boolean)
                .doc("Whether the test is case sensitive; default true.")
                .default_value(true),
        )
        .output(Port::new("Match", "M", DataType::Boolean).doc("True when the text matches."))
        .solve(|s| {
            let text = s.item::<String>(0)?;
            let pattern = s.item_opt::<String>(1);
            let regex = s.item_opt::<String>(2);
            let case = *s.item::<bool>(3)?;
            if pattern.is_none() && regex.is_none() {
                return Err(NodeError(
                    "give a pattern P or a regular expression R".into(),
                ));
            }
            let mut matched = true;
            if let Some(p) = pattern {
                let fold = |t: &str| -> Vec<char> {
                    if case {
                        t.chars().collect()
                    } else {
                        t.to_lowercase().chars().collect()
                    }
                };
                matched &= like(&fold(text), &fold(p))?;
            }
            if let Some(r) = regex {
                let re = regex::RegexBuilder::new(r)
                    .case_insensitive(!case)
                    .size_limit(MAX_REGEX_SIZE)
                    .build()
                    .map_err(|e| NodeError(format!("regular expression R: {e}")))?;
                matched &= re.is_match(text);
            }
            s.set(0, matched);
            Ok(())
        })
}

/// Format \[Format\]: data written into a text with .NET's placeholders.
pub fn format() -> NodeType {
    text_node(FORMAT, "Format", "Format")
        .gh_guid("758d91a0-4aec-47f8-9671-16739a8a2c5d")
        .description(
            "Writes data into a format text with .NET's composite formatting: {k} is the item \
             of data input k, {k,w} pads it to width w (right-aligned; −w left-aligns), \
             {k:f} formats it with the format string f, and {{ and }} are braces. Number \
             formats: N or Nd (thousands separators, d decimals, default 2), Fd (fixed), Ed \
             (exponent, default 6), Pd (percent), Dd (integers, zero-padded to d digits), X \
             (hexadecimal integers), G or R (shortest), and custom formats of 0, #, . and , \
             (\"0.00\", \"#,##0.0\", \"000\"). Other values are written as locus writes them. \
             The first input is the format F, the others the data 0, 1, … (the graph may name \
             more). The invariant culture is used (Grasshopper's Culture input is not \
             supported). An unknown format string or a placeholder without data is an error.",
        )
        .variable_inputs(
            Port::new("Data", "0", DataType::Generic)
                .optional()
                .doc("The first input (F): the format text; the others: the data to insert, of any type; optional."),
            &["F", "0", "1"],
        )
        .output(Port::new("Text", "T", DataType::Text).doc("The formatted text."))
        .solve(|s| {
            let format = match s.value(0) {
                Some(Value::Text(t)) => t,
                Some(other) => format_value(&other),
                None => return Err(NodeError("the format F has no text".into())),
            };
            let data: Vec<Option<Value>> = (1..s.input_count()).map(|k| s.value(k)).collect();
            s.set(0, composite_format(&format, &data)?);
            Ok(())
        })
}

/// .NET's composite formatting of `data` into `format` (see [`format`]).
pub fn composite_format(format: &str, data: &[Option<Value>]) -> Result<String, NodeError> {
    let mut out = String::new();
    let mut chars = format.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '{' if chars.peek() == Some(&'{') => {
                chars.next();
                out.push('{');
            }
            '}' if chars.peek() == Some(&'}') => {
                chars.next();
                out.push('}');
            }
            '}' => return Err(NodeError("the format has a } without {".into())),
            '{' => {
                let mut spec = String::new();
                loop {
                    match chars.next() {
                        Some('}') => break,
                        Some(c) => spec.push(c),
                        None => return Err(NodeError("the format has a { without }".into())),
                    }
                }
                out.push_str(&placeholder(&spec, data)?);
            }
            c => out.push(c),
        }
    }
    Ok(out)
}

/// One placeholder `k[,w][:f]` written out.
fn placeholder(spec: &str, data: &[Option<Value>]) -> Result<String, NodeError> {
    let (head, fmt) = match spec.split_once(':') {
        Some((h, f)) => (h, Some(f)),
        None => (spec, None),
    };
    let (index, width) = match head.split_once(',') {
        Some((i, w)) => (i, Some(w)),
        None => (head, None),
    };
    let bad = || {
        NodeError(format!(
            "placeholder {{{spec}}} is not {{index[,width][:format]}}"
        ))
    };
    let index: usize = index.trim().parse().map_err(|_| bad())?;
    let width: i64 = match width {
        Some(w) => w.trim().parse().map_err(|_| bad())?,
        None => 0,
    };
    if width.unsigned_abs() > MAX_FORMAT_WIDTH as u64 {
        return Err(NodeError(format!(
            "placeholder {{{spec}}}: the width is more than {MAX_FORMAT_WIDTH}"
        )));
    }
    let value = data.get(index).ok_or_else(|| {
        NodeError(format!(
            "placeholder {{{spec}}} names data input {index}, but there are {}",
            data.len()
        ))
    })?;
    let text = match (value, fmt) {
        (None, _) => String::new(),
        (Some(v), None) => plain(v),
        (Some(v), Some(f)) => formatted(v, f)?,
    };
    let pad = usize::try_from(width.unsigned_abs())
        .unwrap_or(0)
        .saturating_sub(text.chars().count());
    Ok(if width >= 0 {
        " ".repeat(pad) + &text
    } else {
        text + &" ".repeat(pad)
    })
}

/// A value without a format string: numbers in the shortest round-trip form, text as is.
fn plain(v: &Value) -> String {
    match v {
        Value::Text(t) => t.clone(),
        Value::Boolean(b) => if *b { "True" } else { "False" }.to_owned(),
        other => format_value(other),
    }
}

fn number_of(v: &Value) -> Option<f64> {
    match v {
        Value::Number(x) => Some(*x),
        Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

/// A value with a format string.
fn formatted(v: &Value, f: &str) -> Result<String, NodeError> {
    let Some(x) = number_of(v) else {
        return Ok(plain(v));
    };
    let unknown = || NodeError(format!("unknown number format {f:?}"));
    let mut cs = f.chars();
    let Some(kind) = cs.next() else {
        return Ok(plain(v));
    };
    let rest: String = cs.collect();
    let digits = |default: usize| -> Result<usize, NodeError> {
        if rest.is_empty() {
            return Ok(default);
        }
        let d: usize = rest.parse().map_err(|_| unknown())?;
        if d > MAX_FORMAT_WIDTH {
            return Err(NodeError(format!(
                "format {f:?} asks for more than {MAX_FORMAT_WIDTH} digits"
            )));
        }
        Ok(d)
    };
    if !x.is_finite() {
        return Ok(if x.is_nan() {
            "NaN".to_owned()
        } else if x > 0.0 {
            "Infinity".to_owned()
        } else {
            "-Infinity".to_owned()
        });
    }
    if f.chars().all(|c| matches!(c, '0' | '#' | '.' | ',')) {
        return Ok(custom(x, f));
    }
    Ok(match kind {
        'N' | 'n' => grouped(&format!("{:.*}", digits(2)?, x)),
        'F' | 'f' => format!("{:.*}", digits(2)?, x),
        'E' | 'e' => {
            let s = format!("{:.*e}", digits(6)?, x);
            let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
            let exp: i32 = exp.parse().unwrap_or(0);
            let e = if kind == 'E' { 'E' } else { 'e' };
            format!(
                "{mantissa}{e}{}{:03}",
                if exp < 0 { '-' } else { '+' },
                exp.abs()
            )
        }
        'P' | 'p' => format!("{} %", grouped(&format!("{:.*}", digits(2)?, x * 100.0))),
        'D' | 'd' => {
            let Value::Integer(i) = v else {
                return Err(NodeError(format!("format {f:?} is for integers, not {x}")));
            };
            let body = format!("{:0width$}", i.unsigned_abs(), width = digits(0)?);
            if *i < 0 { format!("-{body}") } else { body }
        }
        'X' | 'x' => {
            let Value::Integer(i) = v else {
                return Err(NodeError(format!("format {f:?} is for integers, not {x}")));
            };
            let s = format!("{:0width$X}", i, width = digits(0)?);
            if kind == 'x' { s.to_lowercase() } else { s }
        }
        'G' | 'g' | 'R' | 'r' if rest.is_empty() => plain(v),
        _ => return Err(unknown()),
    })
}

/// Digits before the decimal point grouped by three with commas.
fn grouped(fixed: &str) -> String {
    let (sign, body) = match fixed.strip_prefix('-') {
        Some(b) => ("-", b),
        None => ("", fixed),
    };
    let (int, frac) = match body.split_once('.') {
        Some((i, f)) => (i, Some(f)),
        None => (body, None),
    };
    let mut g = String::new();
    for (k, c) in int.chars().enumerate() {
        if k > 0 && (int.len() - k) % 3 == 0 {
            g.push(',');
        }
        g.push(c);
    }
    match frac {
        Some(f) => format!("{sign}{g}.{f}"),
        None => format!("{sign}{g}"),
    }
}

/// A custom number format of `0` (a digit always shown), `#` (a digit shown when
/// significant), `.` and `,` (grouping, when between digit places before the point).
fn custom(x: f64, f: &str) -> String {
    let (int_part, frac_part) = match f.split_once('.') {
        Some((i, fr)) => (i, fr),
        None => (f, ""),
    };
    let min_frac = frac_part.chars().filter(|&c| c == '0').count();
    let max_frac = frac_part.chars().filter(|&c| c == '0' || c == '#').count();
    let min_int = int_part.chars().filter(|&c| c == '0').count();
    let group = int_part.contains(',');
    let s = format!("{:.*}", max_frac, x.abs());
    let (int, frac) = s.split_once('.').unwrap_or((&s, ""));
    let mut frac = frac.to_owned();
    while frac.len() > min_frac && frac.ends_with('0') {
        frac.pop();
    }
    let mut int = int.trim_start_matches('0').to_owned();
    while int.len() < min_int {
        int.insert(0, '0');
    }
    if group {
        int = grouped(&int);
    }
    let negative = x < 0.0
        && (int.chars().any(|c| c.is_ascii_digit() && c != '0') || frac.chars().any(|c| c != '0'));
    let mut out = String::new();
    if negative {
        out.push('-');
    }
    out.push_str(&int);
    if !frac.is_empty() {
        out.push('.');
        out.push_str(&frac);
    }
    out
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::sets::test_support::messages;
    use crate::test_support::{all, booleans};

    fn texts(t: &DataTree) -> Vec<String> {
        all(t)
    }

    fn text(t: &str) -> DataTree {
        DataTree::from_item(t.to_owned())
    }

    #[test]
    fn concatenate_joins_fragments_and_skips_missing_ones() {
        let r = NodeCall::new(&concatenate())
            .input(text("ab"))
            .input(text("cd"))
            .run();
        assert_eq!(texts(&r.outputs[0]), ["abcd"]);
        let r = NodeCall::new(&concatenate())
            .input_names(&["A", "B", "C"])
            .input(text("x"))
            .skip_input()
            .input(DataTree::from_item(2.5))
            .run();
        assert_eq!(texts(&r.outputs[0]), ["x2.5"]);
    }

    #[test]
    fn text_split_keeps_empty_fragments() {
        let r = NodeCall::new(&text_split())
            .input(text("a,,b;c"))
            .input(text(",;"))
            .run();
        assert_eq!(texts(&r.outputs[0]), ["a", "", "b", "c"]);
        let r = NodeCall::new(&text_split()).input(text("one two")).run();
        assert_eq!(texts(&r.outputs[0]), ["one", "two"]);
    }

    #[test]
    fn text_join_length_replace_and_case() {
        let r = NodeCall::new(&text_join())
            .input(DataTree::from_list(vec![
                "a".to_owned(),
                "b".into(),
                "c".into(),
            ]))
            .input(text(", "))
            .run();
        assert_eq!(texts(&r.outputs[0]), ["a, b, c"]);
        let r = NodeCall::new(&text_length())
            .input(DataTree::from_list(vec!["".to_owned(), "héllo".into()]))
            .run();
        assert_eq!(all::<i64>(&r.outputs[0]), [0, 5]);
        let r = NodeCall::new(&replace_text())
            .input(text("aXbXc"))
            .input(text("X"))
            .input(text("--"))
            .run();
        assert_eq!(texts(&r.outputs[0]), ["a--b--c"]);
        let r = NodeCall::new(&replace_text())
            .input(text("abc"))
            .input(text(""))
            .run();
        assert_eq!(texts(&r.outputs[0]), ["abc"]);
        let r = NodeCall::new(&text_case()).input(text("Straße")).run();
        assert_eq!(texts(&r.outputs[0]), ["STRASSE"]);
        assert_eq!(texts(&r.outputs[1]), ["straße"]);
    }

    #[test]
    fn match_text_wildcards_and_regex() {
        let m = |t: &str, p: Option<&str>, r: Option<&str>, case: bool| {
            let node = match_text();
            let mut call = NodeCall::new(&node).input(text(t));
            call = match p {
                Some(p) => call.input(text(p)),
                None => call.skip_input(),
            };
            call = match r {
                Some(r) => call.input(text(r)),
                None => call.skip_input(),
            };
            let res = call.input(DataTree::from_item(case)).run();
            booleans(&res.outputs[0]).first().copied()
        };
        assert_eq!(m("Grasshopper", Some("Gr*per"), None, true), Some(true));
        assert_eq!(m("Grasshopper", Some("gr*"), None, true), Some(false));
        assert_eq!(m("Grasshopper", Some("gr*"), None, false), Some(true));
        assert_eq!(m("A1", Some("[A-C]#"), None, true), Some(true));
        assert_eq!(m("D1", Some("[!A-C]?"), None, true), Some(true));
        assert_eq!(m("D1", Some("[A-C]?"), None, true), Some(false));
        assert_eq!(m("panel 12", None, Some(r"\d+$"), true), Some(true));
        assert_eq!(m("panel", Some("p*"), Some(r"\d"), true), Some(false));
    }

    #[test]
    fn match_text_reports_bad_patterns() {
        let r = NodeCall::new(&match_text()).input(text("x")).run();
        assert_eq!(
            messages(&r, Level::Error),
            ["give a pattern P or a regular expression R"]
        );
        let r = NodeCall::new(&match_text())
            .input(text("x"))
            .skip_input()
            .input(text("("))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        let r = NodeCall::new(&match_text())
            .input(text("x"))
            .input(text("[ab"))
            .run();
        assert_eq!(
            messages(&r, Level::Error),
            ["the pattern has a [ without ]"]
        );
        // A pattern that would be exponential for a backtracking matcher is quick.
        let long = "a".repeat(2000);
        let r = NodeCall::new(&match_text())
            .input(text(&long))
            .input(text(&"*a".repeat(200)))
            .run();
        assert_eq!(booleans(&r.outputs[0]), [true]);
    }

    #[test]
    fn composite_format_follows_dot_net() {
        let n = |x: f64| Some(Value::Number(x));
        let i = |x: i64| Some(Value::Integer(x));
        let f = |fmt: &str, data: &[Option<Value>]| composite_format(fmt, data).unwrap();
        assert_eq!(
            f("{0} and {1}", &[n(1.5), Some(Value::Text("b".into()))]),
            "1.5 and b"
        );
        assert_eq!(f("{0:N2}", &[n(1234567.891)]), "1,234,567.89");
        assert_eq!(f("{0:F3}", &[n(-2.5)]), "-2.500");
        assert_eq!(f("{0:E2}", &[n(12345.0)]), "1.23E+004");
        assert_eq!(f("{0:P1}", &[n(0.256)]), "25.6 %");
        assert_eq!(f("{0:D4}", &[i(42)]), "0042");
        assert_eq!(f("{0:X}", &[i(255)]), "FF");
        assert_eq!(f("{0:0.00}", &[n(1.23456)]), "1.23");
        assert_eq!(f("{0:#.##}", &[n(2.5)]), "2.5");
        assert_eq!(f("{0:000}", &[n(7.0)]), "007");
        assert_eq!(f("{0:#,##0.0}", &[n(12345.67)]), "12,345.7");
        assert_eq!(
            f("[{0,5}|{1,-4}]", &[i(42), Some(Value::Text("ab".into()))]),
            "[   42|ab  ]"
        );
        assert_eq!(f("{{{0}}}", &[i(1)]), "{1}");
        assert_eq!(f("{0}", &[Some(Value::Boolean(true))]), "True");
    }

    #[test]
    fn composite_format_rejects_bad_placeholders() {
        for bad in [
            "{0",
            "0}",
            "{x}",
            "{1}",
            "{0:Q}",
            "{0,99999999}",
            "{0:F99999999}",
        ] {
            assert!(
                composite_format(bad, &[Some(Value::Number(1.0))]).is_err(),
                "{bad} should fail"
            );
        }
        let r = NodeCall::new(&format())
            .input(text("{0}:{1}"))
            .input(DataTree::from_item(1.0))
            .input(text("x"))
            .run();
        assert_eq!(texts(&r.outputs[0]), ["1:x"]);
    }
}
