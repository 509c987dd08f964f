//! Property: a graph whose sub-graphs nest in any arrangement (chains of operators and
//! sub-graphs, a Data parameter or an operator's port as a sub-graph's boundary, extra named
//! outputs, inner values as defaults) is written as a `.ghx` with clusters, read back, and
//! computes exactly what the original computes.

use locus_ghx::{Limits, export_ghx, import};
use locus_runtime::{Document, Evaluator, Graph, NodeRegistry, check};
use proptest::prelude::*;

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    r
}

/// One stage of a chain: an operator with a constant, or a sub-graph.
#[derive(Clone, Debug)]
enum Stage {
    /// Addition (`false`) or Multiplication (`true`) by the constant.
    Op(bool, i8),
    /// A sub-graph running a chain, its input set on a Data parameter (`true`) or on the
    /// first operator's port, with its last value as output `r` and, if `mid` is set, its
    /// first stage's value as output `mid` too; if `fresh` is set, nothing is wired into it,
    /// so that its inner values are its defaults.
    Sub {
        data_boundary: bool,
        mid: bool,
        fresh: bool,
        chain: Vec<Stage>,
    },
}

fn stage() -> impl Strategy<Value = Stage> {
    let op = (any::<bool>(), -5i8..6).prop_map(|(m, c)| Stage::Op(m, c));
    op.prop_recursive(3, 16, 4, |inner| {
        (
            any::<bool>(),
            any::<bool>(),
            prop::bool::weighted(0.25),
            prop::collection::vec(inner, 1..4),
        )
            .prop_map(|(data_boundary, mid, fresh, chain)| Stage::Sub {
                data_boundary,
                mid,
                fresh,
                chain,
            })
    })
}

/// The RON of a chain's nodes and wires, fed from `from` (a `node.port`); returns the port
/// of the chain's last value and of its first stage's value.
fn chain_ron(
    chain: &[Stage],
    from: Option<String>,
    prefix: &str,
    nodes: &mut Vec<String>,
    wires: &mut Vec<String>,
) -> (Option<String>, Option<String>) {
    let mut last = from;
    let mut first_value = None;
    for (k, s) in chain.iter().enumerate() {
        let id = format!("{prefix}s{k}");
        let mut wired = true;
        let (input, output) = match s {
            Stage::Op(multiply, c) => {
                let t = if *multiply {
                    "maths.multiplication"
                } else {
                    "maths.addition"
                };
                // Without a wire, A keeps its own value (the default of a sub-graph input).
                nodes.push(format!(
                    r#"(id: "{id}", type: "{t}", values: {{"A": 7, "B": {c}}})"#
                ));
                (format!("{id}.A"), format!("{id}.R"))
            }
            Stage::Sub {
                data_boundary,
                mid,
                fresh,
                chain,
            } => {
                wired = !fresh;
                let mut inner_nodes = Vec::new();
                let mut inner_wires = Vec::new();
                let (target, start) = if *data_boundary {
                    inner_nodes.push(r#"(id: "in", type: "params.data")"#.to_owned());
                    ("in.Data".to_owned(), Some("in.Data".to_owned()))
                } else {
                    (String::new(), None)
                };
                let (end, first) = chain_ron(chain, start, "", &mut inner_nodes, &mut inner_wires);
                // The input is the Data parameter, or the first operator's A (a chain that
                // starts with a sub-graph gets a Data parameter all the same).
                let target = if *data_boundary {
                    target
                } else {
                    match &chain[0] {
                        Stage::Op(..) => "s0.A".to_owned(),
                        Stage::Sub { .. } => "s0.a".to_owned(),
                    }
                };
                let mut outputs = format!(r#""r": "{}""#, end.unwrap_or_default());
                if *mid && let Some(first) = first {
                    outputs.push_str(&format!(r#", "mid": "{first}""#));
                }
                nodes.push(format!(
                    r#"(id: "{id}", type: "graph", graph: (format: 1, name: "{id}",
                        nodes: [{}], wires: [{}], inputs: {{"a": "{target}"}},
                        outputs: {{{outputs}}}))"#,
                    inner_nodes.join(", "),
                    inner_wires.join(", "),
                ));
                (format!("{id}.a"), format!("{id}.r"))
            }
        };
        if let Some(from) = &last
            && wired
        {
            wires.push(format!(r#"("{from}", "{input}")"#));
        }
        if first_value.is_none() {
            first_value = Some(output.clone());
        }
        last = Some(output);
    }
    (last, first_value)
}

fn graph_of(chain: &[Stage], xs: &[i8]) -> Graph {
    let mut nodes = vec![format!(
        r#"(id: "x", type: "params.number", values: {{"Num": {xs:?}}})"#
    )];
    let mut wires = Vec::new();
    let (end, _) = chain_ron(chain, Some("x.Num".to_owned()), "", &mut nodes, &mut wires);
    let text = format!(
        r#"(format: 1, name: "chain", nodes: [{}], wires: [{}], outputs: {{"y": "{}"}})"#,
        nodes.join(", "),
        wires.join(", "),
        end.unwrap_or_default()
    );
    Document::parse(&text)
        .unwrap_or_else(|e| panic!("{e:?}\n{text}"))
        .graph()
        .clone()
}

/// Output `y`, item by item, as bits (the same operations in the same order give the same
/// bits).
fn run(graph: &Graph, registry: &NodeRegistry) -> Vec<Option<u64>> {
    let checked = check(graph, registry)
        .unwrap_or_else(|d| panic!("{d:#?}\n{}", locus_runtime::write_graph(graph)));
    let mut e = Evaluator::new(checked.plan);
    e.evaluate();
    e.output("y")
        .map(|t| {
            t.values()
                .map(|v| match v {
                    Some(locus_runtime::Value::Number(x)) => Some(x.to_bits()),
                    _ => None,
                })
                .collect()
        })
        .unwrap_or_default()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn nested_sub_graphs_compute_the_same_through_a_ghx(
        chain in prop::collection::vec(stage(), 1..4),
        xs in prop::collection::vec(-9i8..10, 1..4),
    ) {
        let registry = registry();
        let original = graph_of(&chain, &xs);
        // A sub-graph with nothing wired in needs a value for its input: one that starts
        // with a Data parameter has none, and such a graph does not check.
        prop_assume!(check(&original, &registry).is_ok());
        let expected = run(&original, &registry);
        let (ghx, warnings) = export_ghx(&original, &registry)
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(warnings.is_empty(), "{:?}", warnings);
        let back = import(ghx.as_bytes(), &registry, &Limits::default())
            .map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(back.report.runs_whole(), "{:#?}", back.report.diagnostics);
        prop_assert_eq!(run(&back.graph, &registry), expected);
    }
}
