//! `locus test`, `locus test --bless` and `locus fmt`: regression tests that cannot lie.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn locus(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_locus"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the locus binary runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A fresh folder for one test.
fn folder(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("locus-regression-{}-{test}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    dir
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the graph is written");
    path
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).expect("readable")
}

fn s(p: &Path) -> &str {
    p.to_str().expect("a UTF-8 path")
}

/// A graph whose second addition fails ("abc" is not a number), with `tail` before the `)`.
fn failing_graph(tail: &str) -> String {
    format!(
        r#"(
    format: 1,
    nodes: [
        (id: "t", type: "params.text", values: {{"Txt": ["1", "abc"]}}),
        (id: "add", type: "maths.addition", values: {{"B": 1.0}}),
    ],
    wires: [
        ("t.Txt", "add.A"),
    ],
    outputs: {{
        "sum": "add.R",
    }},
    expected: {{
        "sum": [2.0, null],
    }},
{tail})
"#
    )
}

#[test]
fn an_undeclared_error_fails_the_test_and_a_declared_one_passes() {
    let dir = folder("declared");
    let bad = write(&dir, "undeclared.ron", &failing_graph(""));
    let o = locus(&["test", s(&bad)]);
    assert_eq!(o.status.code(), Some(4), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("error: node \"add\" at {0}[1]:")
            && stdout(&o).contains("(not declared in expected_messages)"),
        "{}",
        stdout(&o)
    );

    let declared =
        "    expected_messages: [\n        (node: \"add\", level: error, text: \"abc\"),\n    ],\n";
    let good = write(&dir, "declared.ron", &failing_graph(declared));
    let o = locus(&["test", s(&good)]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));

    // A declared message that is not reported fails too.
    let never = declared.replace("\"abc\"", "\"division by * zero\"");
    let wrong = write(&dir, "never.ron", &failing_graph(&never));
    let o = locus(&["test", s(&wrong)]);
    assert_eq!(o.status.code(), Some(4), "{}", stdout(&o));
    assert!(
        stdout(&o).contains(
            "expected error on node \"add\" matching \"division by * zero\" was not reported"
        ),
        "{}",
        stdout(&o)
    );

    // An expected message must name a node of the graph.
    let unknown = declared.replace("node: \"add\"", "node: \"nope\"");
    let unknown = write(&dir, "unknown.ron", &failing_graph(&unknown));
    let o = locus(&["check", s(&unknown)]);
    assert_eq!(o.status.code(), Some(3));
    assert!(
        stderr(&o).contains("unknown.ron:17:")
            && stderr(&o).contains("expected message for unknown node \"nope\""),
        "{}",
        stderr(&o)
    );
}

#[test]
fn bless_refuses_errors_unless_allowed_and_then_declares_them() {
    let dir = folder("bless-errors");
    let text = failing_graph("").replace("[2.0, null]", "[5.0, null]");
    let path = write(&dir, "g.ron", &text);
    let o = locus(&["test", "--bless", s(&path)]);
    assert_eq!(o.status.code(), Some(4), "{}", stdout(&o));
    assert!(stdout(&o).contains("pass --allow-errors"), "{}", stdout(&o));
    assert_eq!(read(&path), text, "nothing was written");

    let o = locus(&["test", "--bless", "--allow-errors", s(&path)]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    let blessed = read(&path);
    assert!(blessed.contains("\"sum\": [2.0, null],"), "{blessed}");
    assert!(
        blessed.contains("    expected_messages: [\n        (node: \"add\", level: error, text: "),
        "{blessed}"
    );
    let o = locus(&["test", s(&path)]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    // Blessing again changes nothing.
    let o = locus(&["test", "--bless", s(&path)]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).contains("(unchanged)"), "{}", stdout(&o));
    assert_eq!(read(&path), blessed);
}

const COMMENTED: &str = r#"// The header.
(
    format: 1,
    nodes: [
        (id: "n", type: "params.number", values: {"Num": [1, 2.50, 3e0]}),
    ],
    outputs: {
        "a": "n.Num",
    },
    expected: {
        // Worked out by hand.
        "a": [1, /* the middle */ 2.50, 4e0], // the last one is wrong
    },
)
"#;

#[test]
fn bless_keeps_comments_spellings_and_line_endings_and_writes_through_symlinks() {
    let dir = folder("bless-keeps");
    let path = write(&dir, "g.ron", COMMENTED);
    let o = locus(&["test", s(&path)]);
    assert_eq!(o.status.code(), Some(4));
    assert!(
        stdout(&o).contains("a {0}[2]: expected Number 4, got Number 3"),
        "{}",
        stdout(&o)
    );
    let o = locus(&["test", "--bless", s(&path)]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert_eq!(read(&path), COMMENTED.replace("4e0]", "3.0]"));

    // CRLF, through a symlink.
    let crlf = COMMENTED.replace('\n', "\r\n");
    let target = write(&dir, "real.ron", &crlf);
    let link = dir.join("link.ron");
    #[cfg(unix)]
    std::os::unix::fs::symlink(&target, &link).expect("a symlink");
    #[cfg(not(unix))]
    std::fs::copy(&target, &link).expect("a copy");
    let o = locus(&["test", "--bless", s(&link)]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert_eq!(read(&target), crlf.replace("4e0]", "3.0]"));
    #[cfg(unix)]
    assert!(
        std::fs::symlink_metadata(&link)
            .expect("the link")
            .file_type()
            .is_symlink()
    );
    let names: Vec<_> = std::fs::read_dir(&dir)
        .expect("listable")
        .map(|e| e.expect("an entry").file_name())
        .collect();
    assert_eq!(names.len(), 3, "no temporary file is left: {names:?}");
}

#[test]
fn every_brep_output_has_an_expectation_that_can_fail() {
    let text = read(&Path::new(env!("CARGO_MANIFEST_DIR")).join("graphs/exploded_box.ron"));
    assert!(text.contains("Brep(faces: 1, edges: 4, vertices: 4, area: 12.0"));
    let dir = folder("brep");
    let wrong = write(&dir, "g.ron", &text.replacen("area: 12.0", "area: 12.5", 1));
    let o = locus(&["test", s(&wrong)]);
    assert_eq!(o.status.code(), Some(4), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("faces {0;0}[1]: area: expected 12.5, got 1"),
        "{}",
        stdout(&o)
    );
    let wrong = write(&dir, "h.ron", &text.replacen("edges: 4", "edges: 5", 1));
    let o = locus(&["test", s(&wrong)]);
    assert!(
        stdout(&o).contains("faces {0;0}[0]: edges: expected 5, got 4"),
        "{}",
        stdout(&o)
    );
    // An output without an expected value is a failure, not a silent pass.
    let start = text
        .find("        \"faces\": {\"{0;0}\": [")
        .expect("the B-rep expectation");
    let end = start + text[start..].find("]},\n").expect("its end") + 4;
    let unchecked = write(
        &dir,
        "i.ron",
        &format!("{}{}", &text[..start], &text[end..]),
    );
    let o = locus(&["test", s(&unchecked)]);
    assert_eq!(o.status.code(), Some(4), "{}", stdout(&o));
    assert!(
        stdout(&o).contains("faces: no expected value (the output is unchecked)"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn fmt_rewrites_in_canonical_layout_and_check_reports() {
    let dir = folder("fmt");
    let messy = "// keep me\n(format:1,nodes:[(id:\"n\",type:\"params.number\",values:{\"Num\":[1,2.50]})],outputs:{\"a\":\"n.Num\"},expected:{\"a\":[1,2.50]})";
    let path = write(&dir, "g.ron", messy);
    let o = locus(&["fmt", "--check", s(&path)]);
    assert_eq!(o.status.code(), Some(4), "{}", stdout(&o));
    assert!(stdout(&o).contains("would reformat"), "{}", stdout(&o));
    assert_eq!(read(&path), messy);
    let o = locus(&["fmt", s(&path)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let formatted = read(&path);
    assert_eq!(
        formatted,
        "// keep me\n(\n    format: 1,\n    nodes: [\n        (id: \"n\", type: \"params.number\", values: {\"Num\": [1, 2.50]}),\n    ],\n    outputs: {\n        \"a\": \"n.Num\",\n    },\n    expected: {\n        \"a\": [1, 2.50],\n    },\n)\n"
    );
    let o = locus(&["fmt", "--check", s(&path)]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert_eq!(stdout(&o), "");

    // A comment inside the graph would be lost: the file is left alone, with the place.
    let inside = write(&dir, "h.ron", "(\n    format: 1, // why\n)\n");
    let o = locus(&["fmt", s(&inside)]);
    assert_eq!(o.status.code(), Some(3));
    assert!(
        stderr(&o).contains("h.ron:2:16: a comment inside the graph would be lost"),
        "{}",
        stderr(&o)
    );
    assert_eq!(read(&inside), "(\n    format: 1, // why\n)\n");
    let broken = write(&dir, "i.ron", "(format: 1,");
    assert_eq!(locus(&["fmt", s(&broken)]).status.code(), Some(3));
}

#[test]
fn check_reports_what_it_can_know_before_running() {
    let dir = folder("before-run");
    let graph = write(
        &dir,
        "g.ron",
        r#"(
    format: 1,
    nodes: [
        (id: "e", type: "maths.expression", inputs: ["x"], values: {"x": 1}, settings: {"expression": "(x + 1"}),
        (id: "m", type: "sets.path_mapper", values: {"D": [1]}, settings: {"source": "{A;B", "target": "{B;A}"}),
        (id: "c", type: "curve.circle", values: {"R": [2.0, -1.0]}),
        (id: "s", type: "surface.sphere", values: {"R": 0}),
        (id: "fine", type: "curve.circle", values: {"R": 1.5}),
    ],
)
"#,
    );
    let o = locus(&["check", s(&graph)]);
    assert_eq!(o.status.code(), Some(3), "{}", stdout(&o));
    let err = stderr(&o);
    for want in [
        "g.ron:4:",
        "bad value for setting \"expression\" of node \"e\": expected \")\" at column 7",
        "g.ron:5:",
        "of node \"m\"",
        "g.ron:6:",
        "the radius must be a positive number, got -1 (item {0}[1])",
        "g.ron:7:",
        "got 0 (item {0}[0])",
    ] {
        assert!(err.contains(want), "{want}: {err}");
    }
    assert!(!err.contains("\"fine\""), "{err}");
    assert_eq!(err.matches(": error: ").count(), 4, "{err}");
}
