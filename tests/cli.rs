//! The `locus` command: output, exit codes and error messages.

use std::process::{Command, Output};

fn locus(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_locus"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the locus binary runs")
}

/// What `locus test` runs here: `graphs/`, without the Python script graphs
/// (`graphs/python/`) when no Python with the `locus` package is at hand (`$LOCUS_PYTHON`, else
/// `python3`); `tests/graphs.rs` checks that those fail only for that reason, and
/// `.ci/steps/50-python.sh` runs them with the package installed.
fn graph_paths() -> Vec<String> {
    let python = std::env::var("LOCUS_PYTHON").unwrap_or_else(|_| "python3".to_owned());
    let has_locus = Command::new(python)
        .args(["-c", "import locus"])
        .output()
        .is_ok_and(|o| o.status.success());
    if has_locus {
        return vec!["graphs".to_owned()];
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("graphs");
    let mut paths: Vec<String> = std::fs::read_dir(&root)
        .expect("graphs/ is readable")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "ron"))
        .map(|p| format!("graphs/{}", p.file_name().unwrap().to_string_lossy()))
        .collect();
    paths.sort();
    paths
}

fn locus_test_graphs() -> Output {
    let paths = graph_paths();
    let mut args = vec!["test"];
    args.extend(paths.iter().map(String::as_str));
    locus(&args)
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
    let o = locus_test_graphs();
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
    let o = locus_test_graphs();
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

/// A graph with one Series of `count` numbers, named `outputs` times (s0, s1, …).
fn series_graph(name: &str, count: usize, outputs: usize) -> std::path::PathBuf {
    let named: Vec<String> = (0..outputs).map(|k| format!("\"s{k}\": \"s.S\"")).collect();
    let text = format!(
        "(format: 1, nodes: [(id: \"s\", type: \"sets.series\", values: {{\"C\": {count}}})], \
         outputs: {{{}}})",
        named.join(", ")
    );
    temp_graph(name, &text)
}

#[test]
fn run_limits_end_in_exit_code_5_with_the_limit_named() {
    let text = r#"(format: 1, nodes: [
        (id: "s", type: "sets.series", values: {"C": 10000}),
        (id: "x", type: "maths.addition", matching: cross),
    ], wires: [("s.S", "x.A"), ("s.S", "x.B")], outputs: {"r": "x.R"})"#;
    let path = temp_graph("cross.ron", text);
    let started = std::time::Instant::now();
    let o = locus(&["run", path.to_str().unwrap()]);
    assert!(started.elapsed() < std::time::Duration::from_secs(20));
    assert_eq!(o.status.code(), Some(5), "{}", stderr(&o));
    assert!(
        stderr(&o).contains(
            "locus: limit: node \"x\": cross reference of 10000 (A) × 10000 (B) items at {0;0} \
             gives 100000000 iterations"
        ),
        "{}",
        stderr(&o)
    );
    // A smaller budget from the command line.
    let path = series_graph("series.ron", 1000, 1);
    let o = locus(&["run", path.to_str().unwrap(), "--max-items", "100"]);
    assert_eq!(o.status.code(), Some(5), "{}", stderr(&o));
    assert!(stderr(&o).contains("above the limit of 100 items per output"));
}

#[test]
fn output_selection_and_truncation() {
    let path = series_graph("two.ron", 3, 2);
    let o = locus(&["run", path.to_str().unwrap(), "--output", "s1"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("s1:\n") && !stdout(&o).contains("s0:"));
    let o = locus(&["run", path.to_str().unwrap(), "--output", "nope"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("unknown output \"nope\" (the graph's outputs are: s0, s1)"));
    // About a gigabyte of text (60 outputs of a million numbers) stops at the byte limit.
    let path = series_graph("huge.ron", 1_000_000, 60);
    let started = std::time::Instant::now();
    let o = locus(&[
        "run",
        path.to_str().unwrap(),
        "--max-output-bytes",
        "20000000",
    ]);
    assert!(started.elapsed() < std::time::Duration::from_secs(60));
    assert_eq!(o.status.code(), Some(5), "{}", stderr(&o));
    assert!(o.stdout.len() < 20_000_000 + 1000, "{}", o.stdout.len());
    assert!(
        stdout(&o).contains("(output truncated: more than 20000000 bytes; see --max-output-bytes)")
    );
    assert!(stderr(&o).contains("locus: limit: the output was truncated at 20000000 bytes"));
    let o = locus(&[
        "run",
        path.to_str().unwrap(),
        "--format",
        "json",
        "--output",
        "s0",
        "--output",
        "s1",
        "--max-output-bytes",
        "100",
    ]);
    assert_eq!(o.status.code(), Some(5), "{}", stderr(&o));
    let doc: serde_json::Value = serde_json::from_slice(&o.stdout).expect("valid JSON");
    assert_eq!(doc["truncated"]["omitted"], serde_json::json!(["s0", "s1"]));
}

#[test]
fn devices_fifos_and_bad_thread_counts_are_refused() {
    let o = locus(&["check", "/dev/zero"]);
    assert_eq!(o.status.code(), Some(3));
    assert!(
        stderr(&o).contains("cannot read /dev/zero: not a regular file"),
        "{}",
        stderr(&o)
    );
    let fifo = std::env::temp_dir().join(format!("locus-cli-fifo-{}", std::process::id()));
    let made = Command::new("mkfifo").arg(&fifo).status();
    if made.is_ok_and(|s| s.success()) {
        let o = locus(&["run", fifo.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(3));
        assert!(stderr(&o).contains("not a regular file"), "{}", stderr(&o));
        std::fs::remove_file(&fifo).ok();
    }
    let path = series_graph("threads.ron", 3, 1);
    assert_eq!(
        locus(&["run", path.to_str().unwrap(), "--threads", "0"])
            .status
            .code(),
        Some(2)
    );
    let o = locus(&["run", path.to_str().unwrap(), "--threads", "100000"]);
    assert_eq!(o.status.code(), Some(0));
    assert!(stderr(&o).contains("--threads 100000 is more than 4 per core; using"));
    let o = locus(&["run", path.to_str().unwrap(), "--timeout", "-1"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn sub_graphs_run_and_report_inner_nodes_by_nested_id() {
    let o = locus(&["run", "graphs/cluster_subgraph.ron", "--set", "x=[4, -3]"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    let all = format!("{out}{}", stderr(&o));
    // y = 3x + 10: 22 and 1; the root of 22, then of 1.
    assert!(out.contains("doubled:"), "{out}");
    assert!(out.contains("44"), "{out}");
    assert!(
        !all.contains("part/root"),
        "no warning for non-negative y: {all}"
    );
    let o = locus(&["run", "graphs/cluster_subgraph.ron"]);
    let all = format!("{}{}", stdout(&o), stderr(&o));
    assert!(all.contains("node \"part/root\""), "{all}");
    // A sub-graph file's problem names the file and the nested node.
    let dir = std::env::temp_dir().join(format!("locus-cli-sub-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("parts")).expect("a temporary folder");
    std::fs::write(
        dir.join("parts/bad.ron"),
        "(\n    format: 1,\n    nodes: [(id: \"a\", type: \"maths.additon\")],\n)\n",
    )
    .expect("written");
    let top = dir.join("top.ron");
    std::fs::write(
        &top,
        r#"(format: 1, nodes: [(id: "c", type: "graph", path: "parts/bad.ron")])"#,
    )
    .expect("written");
    let o = locus(&["check", top.to_str().expect("a UTF-8 path")]);
    assert_eq!(o.status.code(), Some(3));
    let err = stderr(&o);
    assert!(err.contains("parts/bad.ron:3:"), "{err}");
    assert!(err.contains("\"c/a\""), "{err}");
}

#[test]
fn preview_draws_and_exports_every_nodes_geometry() {
    let dir = std::env::temp_dir().join(format!("locus-cli-preview-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    let (named, every, png) = (
        dir.join("named.gltf"),
        dir.join("every.gltf"),
        dir.join("every.png"),
    );
    let path = |p: &std::path::Path| p.to_str().expect("a UTF-8 path").to_owned();
    let graph = "graphs/face_direction.ron";
    let o = locus(&["run", graph, "--export", &path(&named)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = locus(&["run", graph, "--preview", "--export", &path(&every)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // The sphere is no named output: only the preview holds it, named by node and output.
    let named = std::fs::read_to_string(&named).expect("exported");
    let every = std::fs::read_to_string(&every).expect("exported");
    assert!(!named.contains("\"sphere.S\""), "{named}");
    assert!(every.contains("\"sphere.S\""));
    assert!(every.contains("\"closest.P\""));
    let o = locus(&[
        "render",
        graph,
        "--preview",
        "-o",
        &path(&png),
        "--size",
        "64x48",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let bytes = std::fs::read(&png).expect("drawn");
    assert!(bytes.starts_with(b"\x89PNG"), "not a PNG");
    std::fs::remove_dir_all(&dir).ok();
}
