//! Input expressions (`InternalExpression` on a component's input): Grasshopper applies the
//! formula to every item the input collects, as `x`. The importer puts an Expression node in
//! front of the input; these tests write a definition with `locus export-ghx`'s writer, give
//! one input an expression as Grasshopper stores it, and run the import.

use locus_ghx::{Limits, export_ghx, import};
use locus_runtime::{Evaluator, Graph, NodeRegistry, check};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    r
}

/// The ghx of `ron` with `expression` on the input nicknamed `port` (the first such input).
fn with_expression(ron: &str, port: &str, expression: &str) -> String {
    let graph = Graph::from_ron(ron).unwrap();
    let (ghx, warnings) = export_ghx(&graph, &registry()).unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    let nickname =
        format!(r#"<item name="NickName" type_name="gh_string" type_code="10">{port}</item>"#);
    let at = ghx
        .match_indices(&nickname)
        .map(|(k, _)| k)
        .find(|&k| {
            let open = ["param_input", "InputParam"]
                .iter()
                .filter_map(|c| ghx[..k].rfind(&format!("<chunk name=\"{c}\"")))
                .max();
            open > ghx[..k].rfind("</chunk>")
        })
        .unwrap_or_else(|| panic!("no input {port} in\n{ghx}"));
    let item = format!(
        r#"<item name="InternalExpression" type_name="gh_string" type_code="10">{expression}</item>"#
    );
    format!("{}{item}{}", &ghx[..at], &ghx[at..])
}

/// Imports `ghx`, runs it, and gives the named output `name` as text, with the report.
fn run(ghx: &str, name: &str) -> (String, String) {
    let registry = registry();
    let imported = import(ghx.as_bytes(), &registry, &Limits::default()).unwrap();
    let report = format!("{:?}", imported.report.diagnostics);
    let checked = check(&imported.graph, &registry).unwrap_or_else(|e| panic!("{e:?}"));
    let mut evaluator = Evaluator::new(checked.plan.clone());
    evaluator.evaluate();
    let out = evaluator
        .output(name)
        .unwrap_or_else(|| panic!("no output {name}"))
        .to_string();
    (out, report)
}

/// A branch of numbers as the tree's text shows it.
fn numbers(path: &str, items: &[f64]) -> String {
    let mut s = format!("{path} ({} items)\n", items.len());
    for (k, x) in items.iter().enumerate() {
        s.push_str(&format!("  [{k}] Number({x:?})\n"));
    }
    s
}

#[test]
fn an_input_expression_applies_to_typed_in_data() {
    let ron = r#"(format: 1, nodes: [
  (id: "s", type: "sets.series", values: {"S": 0.0, "N": 1.0, "C": 3}),
], outputs: {"series": "s.S"})"#;
    let (plain, _) = run(&with_expression(ron, "N", "x"), "series");
    assert_eq!(
        plain,
        numbers("{0;0}", &[0.0, 1.0, 2.0]),
        "`x` changes nothing"
    );
    let (out, report) = run(&with_expression(ron, "N", "x * 2.5"), "series");
    assert_eq!(out, numbers("{0;0}", &[0.0, 2.5, 5.0]));
    assert!(!report.contains("expression"), "{report}");
}

#[test]
fn an_input_expression_applies_to_wired_data_and_keeps_the_paths() {
    let ron = r#"(format: 1, nodes: [
  (id: "r", type: "sets.range", values: {"D": (0.0, 4.0), "N": 4}),
  (id: "m", type: "maths.multiplication", values: {"B": 1.0}, modifiers: {"A": [graft]}),
], wires: [("r.R", "m.A")], outputs: {"product": "m.R"})"#;
    let (out, _) = run(&with_expression(ron, "A", "-x/2"), "product");
    let grafted: String = [-0.0, -0.5, -1.0, -1.5, -2.0]
        .iter()
        .enumerate()
        .map(|(k, x)| numbers(&format!("{{0;0;{k}}}"), &[*x]))
        .collect();
    assert_eq!(out, grafted);
}

#[test]
fn an_unreadable_input_expression_is_left_out_with_a_warning() {
    let ron = r#"(format: 1, nodes: [
  (id: "s", type: "sets.series", values: {"S": 0.0, "N": 1.0, "C": 3}),
], outputs: {"series": "s.S"})"#;
    let (out, report) = run(&with_expression(ron, "N", "x @ x"), "series");
    assert_eq!(out, numbers("{0;0}", &[0.0, 1.0, 2.0]));
    assert!(report.contains("unsupported-input-expression"), "{report}");
}
