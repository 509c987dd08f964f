//! The command on real Grasshopper definitions: `locus test` with hand-checked expectations,
//! `locus import --report`, `locus check --format json`, `locus export-ghx`.

use std::process::Command;

fn locus(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_locus"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("locus runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The first item of output `label` as `locus run` prints it (without its `0. `).
fn first_item(out: &str, label: &str) -> String {
    let start = out
        .find(&format!("{label}:\n"))
        .unwrap_or_else(|| panic!("{out}"));
    out[start..]
        .lines()
        .nth(2)
        .unwrap_or_default()
        .trim()
        .trim_start_matches("0. ")
        .to_owned()
}

#[test]
fn hand_checked_definitions_pass_locus_test() {
    let (code, out, _) = locus(&["test", "crates/ghx/tests/data"]);
    assert_eq!(code, 0, "{out}");
    let ok = out.lines().filter(|l| l.starts_with("ok ")).count();
    assert!(ok >= 5, "{out}");
    assert!(out.contains(", 0 failed,"), "{out}");
}

#[test]
fn import_report_and_json_check() {
    // The attractor tutorial runs whole (its hexagonal grid and MD Sliders map); the McNeel
    // sample still holds a GhPython script and components locus lacks.
    let whole = "crates/ghx/tests/data/runxel__attractor_2_linear.ghx";
    let (code, out, _) = locus(&["import", whole, "--report"]);
    assert_eq!(code, 0);
    assert!(out.contains("runs whole: yes"), "{out}");
    assert!(out.contains("graph: checks"), "{out}");
    let file = "crates/ghx/tests/data/mcneel-samples__BranchNodeRnd.ghx";
    let (code, out, _) = locus(&["import", file, "--report"]);
    assert_eq!(code, 0);
    assert!(out.contains("objects: "), "{out}");
    assert!(out.contains("runs whole: no"), "{out}");
    let (_, out, _) = locus(&["check", "--format", "json", file]);
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let unsupported = v
        .as_array()
        .unwrap()
        .iter()
        .find(|d| d["code"] == "unsupported-cluster" || d["code"] == "unsupported-script")
        .expect("the sample's script is reported");
    assert_eq!(unsupported["severity"], "error");
    assert!(
        unsupported["gh_instance"]
            .as_str()
            .is_some_and(|s| s.len() == 36)
    );
}

#[test]
fn run_reads_gh_and_export_round_trips() {
    let file = "crates/ghx/tests/data/mcneel-compute__ghhops-server-py_examples_Hops_Example.gh";
    let (code, out, err) = locus(&["run", file, "--set", "Number Slider (3)=2.5"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("Circle (R:2.5 at {0, 0, 0})"), "{out}");
    let dir = std::env::temp_dir().join(format!("locus-ghx-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let ron = dir.join("a.ron");
    let ghx = dir.join("a.ghx");
    let (code, _, err) = locus(&["import", file, "-o", ron.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = locus(&[
        "export-ghx",
        ron.to_str().unwrap(),
        "-o",
        ghx.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let (code, out, err) = locus(&["run", ghx.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("Circle (R:3.6 at {0, 0, 0})"), "{out}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_curvature_tutorial_agrees_with_the_curvature_component() {
    // runxel's calculate_curvature computes the curvature vector from Derivatives with
    // Grasshopper's vector syntax, T = [d1] and (d2-(d2 • T) *T)/(d1•d1) (Panel 1), beside the
    // length of the Curvature component's vector (Panel 2). On the parabola (t, t², 0) at
    // t = 0.5 the curvature vector is (−0.5, 0.5, 0), of length 1/√2.
    let file = "crates/ghx/tests/data/runxel__calculate_curvature.ghx";
    let (code, out, err) = locus(&[
        "run",
        file,
        "--set",
        "Curve=(degree: 2, points: [(0, 0, 0), (0.5, 0, 0), (1, 1, 0)], knots: [0, 0, 1, 1])",
        "--set",
        "t=0.5",
    ]);
    // The whole file runs (its third formula takes the radius from Deconstruct Arc).
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("error"), "{out}");
    let after = |label: &str| format!("0. {}", first_item(&out, label));
    assert_eq!(
        after("Panel 1"),
        "0. {-0.4999999999999999, 0.5000000000000001, 0}"
    );
    assert_eq!(after("Panel 2"), "0. 0.7071067811865476");
}

#[test]
fn the_helix_tutorial_winds_around_its_internalised_curve_and_around_a_line() {
    // runxel's helix_along_curve: 100 segments give 101 perpendicular frames on the curve; a
    // series of (100 + 1) + 1 = 102 angles, stepping 2π·r·(turns / 101) rad (r = 1.795,
    // turns = 8.4808, so 0.94702 rad), is evaluated on circles of radius r around the frames
    // (the last circle repeats), and Interpolate (uniform knots) runs through the 102 points.
    let file = "crates/ghx/tests/data/runxel__helix_along_curve.ghx";
    let value = first_item;
    // On the file's own curve (internalised ON_Data, a Rhino 6 NURBS curve).
    let (code, out, err) = locus(&["run", file]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(value(&out, "interpolate.D"), "0 To 101");
    // On a straight line of length 10 set in its place: consecutive points are 0.1 apart
    // along the line and 0.94702 rad apart around it (the last pair only around it). The
    // interpolated curve is longer than the polyline through its points (100 chords of
    // √((2r·sin(θ/2))² + 0.1²) and one of 2r·sin(θ/2): 165.67) and shorter than the helix
    // through them (arcs of r·θ: 171.98).
    let (code, out, err) = locus(&[
        "run",
        file,
        "--set",
        "Input Curve=(line: ((0, 0, 0), (10, 0, 0)))",
    ]);
    assert_eq!(code, 0, "{err}");
    let theta = 2.0 * std::f64::consts::PI * 1.795 * (8.4808 / 101.0);
    let chord = 2.0 * 1.795 * (theta / 2.0).sin();
    let polyline = 100.0 * (chord * chord + 0.01).sqrt() + chord;
    let arc = 1.795 * theta;
    let helix = 100.0 * (arc * arc + 0.01).sqrt() + arc;
    let length: f64 = value(&out, "interpolate.L").parse().unwrap();
    assert!(
        polyline < length && length < helix,
        "{polyline} < {length} < {helix}"
    );
}

/// Sub-graphs are written as clusters: the graph with a sub-graph from a file and an inline
/// one exports, runs from the `.ghx` with the same outputs as from its RON, and imports,
/// exports and imports again to the same RON.
#[test]
fn sub_graphs_export_as_clusters_and_round_trip() {
    let dir = std::env::temp_dir().join(format!("locus-cluster-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = |name: &str| dir.join(name).to_str().unwrap().to_owned();
    let (code, _, err) = locus(&[
        "export-ghx",
        "graphs/cluster_subgraph.ron",
        "-o",
        &path("a.ghx"),
    ]);
    assert_eq!(code, 0, "{err}");
    let (_, from_ron, _) = locus(&["run", "graphs/cluster_subgraph.ron"]);
    let (code, from_ghx, err) = locus(&["run", &path("a.ghx")]);
    assert_eq!(code, 0, "{err}");
    // The same numbers, in the same outputs (the inner nodes' ids may differ in messages).
    let numbers = |out: &str| -> Vec<String> {
        out.lines()
            .take_while(|l| !l.starts_with("messages:"))
            .map(str::to_owned)
            .collect()
    };
    assert_eq!(numbers(&from_ron), numbers(&from_ghx));
    assert!(from_ghx.contains("doubled:"), "{from_ghx}");
    assert!(from_ghx.contains("0. 26"), "{from_ghx}");
    assert!(from_ghx.contains("the square root of -14"), "{from_ghx}");
    let (code, _, err) = locus(&["import", &path("a.ghx"), "-o", &path("1.ron")]);
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = locus(&["export-ghx", &path("1.ron"), "-o", &path("b.ghx")]);
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = locus(&["import", &path("b.ghx"), "-o", &path("2.ron")]);
    assert_eq!(code, 0, "{err}");
    // The same RON, but for the comments that name the Grasshopper objects (the first file's
    // Cluster Inputs are boundary objects of their own, the second's the Data parameters).
    let graph = |name: &str| -> String {
        std::fs::read_to_string(path(name))
            .unwrap()
            .lines()
            .filter(|l| !l.trim_start().starts_with("//"))
            .collect::<Vec<_>>()
            .join("\n")
    };
    let first = graph("1.ron");
    assert!(first.contains("graph: ("), "{first}");
    assert_eq!(first, graph("2.ron"));
    // Nodes inside a cluster are named in comments after their own objects.
    let text = std::fs::read_to_string(path("2.ron")).unwrap();
    assert!(text.contains("// Multiplication \"scale\""), "{text}");
    std::fs::remove_dir_all(&dir).ok();
}
