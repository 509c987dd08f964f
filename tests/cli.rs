//! The `locus` command: output, exit codes and error messages.

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

fn temp_graph(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("locus-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("the graph is written");
    path
}

#[test]
fn run_prints_outputs_in_grasshopper_notation() {
    let o = locus(&["run", "graphs/maths_range_remap.ron", "--set", "N=2"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(
        out.contains("range:\n  {0;0} (3 items)\n    0. 0\n    1. 5\n    2. 10\n"),
        "{out}"
    );
}

#[test]
fn run_json_has_outputs_and_messages() {
    let o = locus(&[
        "run",
        "graphs/maths_range_remap.ron",
        "--format",
        "json",
        "--threads",
        "1",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("valid JSON");
    assert_eq!(v["outputs"]["range"]["{0;0}"][1], serde_json::json!(2.5));
    assert!(v["messages"].as_array().is_some_and(Vec::is_empty));
}

#[test]
fn bad_command_lines_exit_with_2() {
    let o = locus(&["run", "graphs/maths_range_remap.ron", "--set", "nope=1"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--set: unknown input \"nope\" (the graph's inputs are: N)"));
    let o = locus(&["run", "graphs/maths_range_remap.ron", "--set", "N=abc"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("--set: bad value for input \"N\": "),
        "{}",
        stderr(&o)
    );
    assert_eq!(locus(&["frobnicate"]).status.code(), Some(2));
    assert_eq!(locus(&["describe", "no.such_node"]).status.code(), Some(2));
}

#[test]
fn graphs_that_do_not_check_exit_with_3_and_name_the_place() {
    let path = temp_graph(
        "bad.ron",
        "(\n    format: 1,\n    nodes: [\n        (id: \"a\", type: \"maths.additon\"),\n    ],\n)\n",
    );
    let p = path.to_str().expect("a UTF-8 path");
    let o = locus(&["check", p]);
    assert_eq!(o.status.code(), Some(3));
    let err = stderr(&o);
    assert!(err.contains("bad.ron:4:"), "{err}");
    assert!(err.contains("maths.addition"), "a did-you-mean hint: {err}");
    assert_eq!(locus(&["run", p]).status.code(), Some(3));
    assert_eq!(locus(&["run", "does-not-exist.ron"]).status.code(), Some(3));
}

#[test]
fn node_errors_exit_with_1() {
    let path = temp_graph(
        "errors.ron",
        r#"(
    format: 1,
    nodes: [
        (id: "t", type: "params.text", values: {"Txt": ["1", "abc"]}),
        (id: "add", type: "maths.addition", values: {"B": 1.0}),
    ],
    wires: [
        ("t.Txt", "add.A"),
    ],
    outputs: {
        "sum": "add.R",
    },
)
"#,
    );
    let o = locus(&["run", path.to_str().expect("a UTF-8 path")]);
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), stderr(&o));
    assert!(
        stdout(&o).contains("error: node \"add\" at {0}[1]:"),
        "{}",
        stdout(&o)
    );
}

#[test]
fn test_reports_pass_and_fail_with_differences() {
    let o = locus(&["test", "graphs"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).contains(" passed, 0 failed"));
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("graphs/maths_range_remap.ron"),
    )
    .expect("the graph is readable")
    .replace("[0.0, 2.5, 5.0, 7.5, 10.0]", "[0.0, 2.5, 5.0, 7.5, 11.0]");
    let path = temp_graph("wrong.ron", &text);
    let o = locus(&["test", path.to_str().expect("a UTF-8 path")]);
    assert_eq!(o.status.code(), Some(4));
    let out = stdout(&o);
    assert!(out.contains("FAILED"), "{out}");
    assert!(
        out.contains("range {0;0}[4]: expected Number 11, got Number 10"),
        "{out}"
    );
}

#[test]
fn nodes_and_describe_show_the_catalogue() {
    let o = locus(&["nodes", "maths"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).contains("maths.addition"));
    let o = locus(&["describe", "maths.addition"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).contains("Addition [A+B]"));
    let o = locus(&["dot", "graphs/maths_range_remap.ron"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(stdout(&o).starts_with("digraph"));
}

#[test]
fn the_readme_example_prints_what_the_readme_shows() {
    let o = locus(&[
        "run",
        "graphs/tangent_spheres.ron",
        "--set",
        "t=0.5",
        "--set",
        "B=(10, 0, 0)",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    for shown in [
        "D:\n  {0} (1 item)\n    0. {5, 0, 0}\n",
        "C1:\n  {0} (1 item)\n    0. {2.5, 0, 0}\n",
        "r1:\n  {0} (1 item)\n    0. 2.5\n",
        "S1:\n  {0} (1 item)\n    0. NURBS Surface (degree 2×2, 9×5 points)\n",
    ] {
        assert!(out.contains(shown), "missing {shown:?} in\n{out}");
    }
}

#[test]
fn every_graph_passes_locus_test() {
    let o = locus(&["test", "graphs"]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), stderr(&o));
    assert!(stdout(&o).contains(" 0 failed"), "{}", stdout(&o));
}

#[test]
fn json_breps_carry_their_faces_edges_and_vertices() {
    let o = locus(&["run", "graphs/surface_singularity.ron", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("valid JSON");
    assert_eq!(
        v["outputs"]["singular_points"]["{0;0}"][1],
        serde_json::json!({"point": [0.0, 0.0, 2.0]})
    );
    // The exploded box's moved faces: six one-face B-reps, each a planar surface bounded by
    // one outer loop of four edges between four vertices.
    let o = locus(&["run", "graphs/exploded_box.ron", "--format", "json"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("valid JSON");
    let faces = v["outputs"]["faces"]["{0;0}"]
        .as_array()
        .expect("a list of faces");
    assert_eq!(faces.len(), 6);
    for face in faces {
        let brep = &face["brep"];
        assert_eq!(brep["faces"].as_array().map(Vec::len), Some(1));
        assert_eq!(
            brep["faces"][0]["surface"]["degree"],
            serde_json::json!([1, 1])
        );
        let loops = brep["faces"][0]["loops"].as_array().expect("loops");
        assert_eq!(loops.len(), 1);
        assert_eq!(loops[0]["outer"], serde_json::json!(true));
        assert_eq!(loops[0]["edges"].as_array().map(Vec::len), Some(4));
        assert_eq!(brep["edges"].as_array().map(Vec::len), Some(4));
        assert_eq!(brep["vertices"].as_array().map(Vec::len), Some(4));
    }
}
