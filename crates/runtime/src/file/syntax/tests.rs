use super::*;

fn compact(text: &str) -> String {
    parse(text).unwrap().to_compact()
}

#[test]
fn reads_every_kind_of_value() {
    assert_eq!(compact("( 1 ,2,3 , )"), "(1, 2, 3)");
    assert_eq!(
        compact("[-2.5e3, +1, .5, inf, -inf, NaN]"),
        "[-2.5e3, +1, .5, inf, -inf, NaN]"
    );
    assert_eq!(
        compact(r#"{"a": true, "b":false}"#),
        r#"{"a": true, "b": false}"#
    );
    assert_eq!(
        compact("Curve(degree: 3, points: [])"),
        "Curve(degree: 3, points: [])"
    );
    assert_eq!(compact("Vector (1, 2, 3)"), "Vector(1, 2, 3)");
    assert_eq!(
        compact("(a: XY, b: null, c: ())"),
        "(a: XY, b: null, c: ())"
    );
    assert_eq!(compact(r##"r#"a "b" c"#"##), r#""a \"b\" c""#);
    assert_eq!(compact("\"\\u{e9}\\n\\t\\\\\""), "\"é\\n\\t\\\\\"");
}

#[test]
fn skips_comments() {
    let text = "// head\n( /* a /* nested */ comment */ x: 1, // tail\n)";
    assert_eq!(compact(text), "(x: 1)");
}

#[test]
fn keeps_spans() {
    let text = r#"(id: "d1", type: "vector.dot")"#;
    let node = parse(text).unwrap();
    let Kind::Struct(None, fields) = node.kind else {
        panic!("not a struct")
    };
    assert_eq!(&text[fields[1].name_span.clone()], "type");
    assert_eq!(&text[fields[1].value.span.clone()], "\"vector.dot\"");
}

#[test]
fn reports_errors_with_offsets() {
    let cases = [
        ("(a: 1", "expected `,` or `)`, found end of file", 5),
        ("[1 2]", "expected `,` or `]`, found `2`", 3),
        ("\"abc", "unterminated string", 0),
        ("(1) x", "unexpected `x` after the end of the value", 4),
        ("'a'", "character literals are not supported", 0),
        ("/* x", "unterminated block comment", 0),
        ("1e", "expected digits in the exponent", 1),
        ("{1 2}", "expected `:` after a map key, found `2`", 3),
        ("\"\\q\"", "unknown escape `\\q` in a string", 1),
    ];
    for (text, message, offset) in cases {
        let e = parse(text).unwrap_err();
        assert_eq!((e.message.as_str(), e.offset), (message, offset), "{text}");
    }
}

#[test]
fn deep_nesting_is_an_error_not_a_stack_overflow() {
    let text = "[".repeat(100_000);
    assert_eq!(
        parse(&text).unwrap_err().message,
        "values are nested too deeply"
    );
}

#[test]
fn strings_round_trip_through_quote() {
    for s in ["", "a\"b\\c", "line\nnext\ttab", "\u{1}", "é ∑ 🙂"] {
        let node = parse(&quote(s)).unwrap();
        assert_eq!(node.kind, Kind::Str(s.to_owned()));
    }
}

#[test]
fn pretty_breaks_long_values() {
    let items: Vec<String> = (0..40).map(|i| format!("{i}.5")).collect();
    let node = parse(&format!("[{}]", items.join(","))).unwrap();
    let mut out = String::new();
    write_pretty(&node, 0, 0, 0, &mut out);
    assert!(out.starts_with("[\n    0.5,\n    1.5,\n"), "{out}");
    assert!(out.ends_with("\n    39.5,\n]"), "{out}");
    assert_eq!(parse(&out).unwrap().to_compact(), node.to_compact());
}

#[test]
fn line_and_column_count_characters() {
    let text = "ab\né x";
    assert_eq!(line_column(text, 0), (1, 1));
    assert_eq!(line_column(text, 3), (2, 1));
    assert_eq!(line_column(text, 6), (2, 3));
    assert_eq!(line_column(text, 99), (2, 4));
    assert_eq!(line_column(text, 2), (1, 3));
    assert_eq!(line_column("", 0), (1, 1));
    assert_eq!(line_column("a\n", 2), (2, 1));
}
