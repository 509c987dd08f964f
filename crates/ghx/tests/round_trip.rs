//! ghx → RON → ghx → RON gives the same graph (the canonical RON, without the provenance
//! comments, which name the Grasshopper objects of each file).

use locus_ghx::{Limits, export_ghx, import};
use locus_runtime::{Document, NodeRegistry, write_graph};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    r
}

/// The graph with its wires in the order of their targets: only the order of the wires into
/// one input means something (Grasshopper merges them in that order), and an input
/// expression's Expression node is wired in the first import before the file's wires, in the
/// second as one of them.
fn by_target(graph: &locus_runtime::Graph) -> locus_runtime::Graph {
    let mut graph = graph.clone();
    let order: Vec<_> = graph.nodes.iter().map(|n| n.id.clone()).collect();
    let rank = |id: &locus_runtime::NodeId| order.iter().position(|n| n == id);
    graph
        .wires
        .sort_by_key(|w| (rank(&w.to.node), w.to.port.clone()));
    graph
}

#[test]
fn import_export_import_is_stable_for_every_file() {
    let registry = registry();
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| locus_ghx::is_grasshopper_path(p))
        .collect();
    files.sort();
    for f in files {
        let first = import(&std::fs::read(&f).unwrap(), &registry, &Limits::default()).unwrap();
        let ron1 = write_graph(&by_target(&first.graph));
        let (ghx, _warnings) =
            export_ghx(&first.graph, &registry).unwrap_or_else(|e| panic!("{}: {e}", f.display()));
        // The written file is a GH_IO archive this crate reads back.
        let second = import(ghx.as_bytes(), &registry, &Limits::default())
            .unwrap_or_else(|e| panic!("{}: {e}\n{ghx}", f.display()));
        let ron2 = write_graph(&by_target(&second.graph));
        assert_eq!(ron1, ron2, "{}", f.display());
        assert!(second.report.runs_whole(), "{}", f.display());
        // And the RON of the second import checks like the first.
        let checks =
            |text: &str| Document::parse(text).and_then(|d| d.check(&registry).map(|_| ()));
        assert_eq!(
            checks(&ron1).is_ok(),
            checks(&ron2).is_ok(),
            "{}",
            f.display()
        );
    }
}

/// The values of a graph's outputs, evaluated.
fn outputs(graph: &locus_runtime::Graph, registry: &NodeRegistry) -> Vec<(String, Vec<String>)> {
    let checked = locus_runtime::check(graph, registry)
        .unwrap_or_else(|d| panic!("{d:#?}\n{}", write_graph(graph)));
    let mut e = locus_runtime::Evaluator::new(checked.plan);
    e.evaluate();
    graph
        .outputs
        .iter()
        .map(|o| {
            let values = e
                .output(&o.name)
                .map(|t| t.values().map(|v| format!("{v:?}")).collect())
                .unwrap_or_default();
            (o.name.clone(), values)
        })
        .collect()
}

/// Sub-graphs nested two deep export as clusters in clusters: the file reads back into the
/// same sub-graphs, which compute what the original computes, and a second round gives the
/// same RON. Inside, the boundary objects are Grasshopper's Cluster Input and Output.
#[test]
fn nested_sub_graphs_round_trip_as_clusters() {
    let registry = registry();
    let text = r#"(
        format: 1,
        name: "nested",
        nodes: [
            (id: "n", type: "params.number", values: {"Num": [1, 2]}),
            (id: "outer", type: "graph", graph: (
                format: 1,
                name: "outer",
                nodes: [
                    (id: "inner", type: "graph", graph: (
                        format: 1,
                        name: "inner",
                        nodes: [(id: "add", type: "maths.addition", values: {"B": 5})],
                        inputs: {"a": "add.A"},
                        outputs: {"s": "add.R"},
                    )),
                    (id: "triple", type: "maths.multiplication", values: {"B": 3}),
                ],
                wires: [("inner.s", "triple.A")],
                inputs: {"v": "inner.a"},
                outputs: {"w": "triple.R", "s": "inner.s"},
            )),
        ],
        wires: [("n.Num", "outer.v")],
        outputs: {"w": "outer.w", "s": "outer.s"},
    )"#;
    let original = Document::parse(text).unwrap().graph().clone();
    let expected = outputs(&original, &registry);
    assert_eq!(
        expected,
        [
            (
                "w".to_owned(),
                vec![
                    "Some(Number(18.0))".to_owned(),
                    "Some(Number(21.0))".to_owned()
                ]
            ),
            (
                "s".to_owned(),
                vec![
                    "Some(Number(6.0))".to_owned(),
                    "Some(Number(7.0))".to_owned()
                ]
            ),
        ]
    );
    let (ghx, warnings) = export_ghx(&original, &registry).unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    let first = import(ghx.as_bytes(), &registry, &Limits::default()).unwrap();
    assert!(first.report.runs_whole(), "{:#?}", first.report.diagnostics);
    assert_eq!(outputs(&first.graph, &registry), expected);
    let (ghx2, _) = export_ghx(&first.graph, &registry).unwrap();
    let second = import(ghx2.as_bytes(), &registry, &Limits::default()).unwrap();
    assert_eq!(
        write_graph(&by_target(&first.graph)),
        write_graph(&by_target(&second.graph))
    );
    // The outer cluster's document holds a cluster of its own, and both hold Grasshopper's
    // boundary objects.
    let limits = Limits::default();
    let root = locus_ghx::read_archive(ghx.as_bytes(), &limits).unwrap();
    let doc = locus_ghx::read_document(&root).unwrap();
    let cluster_document = |o: &locus_ghx::GhObject, depth: usize| {
        assert_eq!(o.type_guid, "f31d8d7a-7536-4ac8-9c96-fde6ecda4d0a");
        let Some(locus_ghx::Value::Bytes(b)) =
            o.container.item("ClusterDocument").map(|i| &i.value)
        else {
            panic!("a cluster document: {o:?}");
        };
        locus_ghx::read_cluster(b, &limits, depth).unwrap()
    };
    let outer = doc.objects.iter().find(|o| o.nickname == "outer").unwrap();
    let outer_doc = cluster_document(outer, 1);
    let types = |d: &locus_ghx::GhDocument| -> Vec<String> {
        d.objects.iter().map(|o| o.type_name.clone()).collect()
    };
    let outer_types = types(&outer_doc);
    assert_eq!(
        outer_types
            .iter()
            .filter(|t| *t == "Cluster Input" || *t == "Cluster Output")
            .count(),
        3,
        "{outer_types:?}"
    );
    let inner = outer_doc
        .objects
        .iter()
        .find(|o| o.nickname == "inner")
        .unwrap();
    let inner_types = types(&cluster_document(inner, 2));
    assert!(
        inner_types.contains(&"Cluster Input".to_owned())
            && inner_types.contains(&"Cluster Output".to_owned()),
        "{inner_types:?}"
    );
}

/// The parameter types (`InputId` / `OutputId`) by component in a file's archive (the node
/// type a component's GUID maps to, so that old and new GUIDs of a component are one).
fn param_ids(
    root: &locus_ghx::Chunk,
    registry: &NodeRegistry,
) -> std::collections::BTreeSet<(String, String, String)> {
    let mut out = std::collections::BTreeSet::new();
    let doc = locus_ghx::read_document(root).unwrap();
    for o in &doc.objects {
        let Some(data) = o.container.chunk("ParameterData") else {
            continue;
        };
        for item in &data.items {
            if let ("InputId" | "OutputId", locus_ghx::Value::Guid(g)) =
                (item.name.as_str(), &item.value)
            {
                let component = registry
                    .by_gh_guid(&o.type_guid)
                    .map_or_else(|| o.type_guid.clone(), |t| t.id.clone());
                out.insert((component, item.name.clone(), g.clone()));
            }
        }
    }
    out
}

/// Grasshopper rebuilds a variable-parameter component's ports from the parameter types in
/// its `ParameterData`: every type the export writes for a component is one Grasshopper wrote
/// for that component in the corpus, and none is missing.
#[test]
fn variable_components_carry_grasshoppers_parameter_types() {
    let registry = registry();
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut seen = std::collections::BTreeSet::new();
    let mut written = std::collections::BTreeSet::new();
    let mut exported_components = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let f = entry.unwrap().path();
        if !locus_ghx::is_grasshopper_path(&f) {
            continue;
        }
        let bytes = std::fs::read(&f).unwrap();
        let root = locus_ghx::read_archive(&bytes, &Limits::default()).unwrap();
        seen.extend(param_ids(&root, &registry));
        let first = import(&bytes, &registry, &Limits::default()).unwrap();
        let (ghx, _) = export_ghx(&first.graph, &registry).unwrap();
        let root = locus_ghx::read_archive(ghx.as_bytes(), &Limits::default()).unwrap();
        let doc = locus_ghx::read_document(&root).unwrap();
        for o in &doc.objects {
            if let Some(data) = o.container.chunk("ParameterData") {
                exported_components += 1;
                let ins = data.items_named("InputId").count();
                let outs = data.items_named("OutputId").count();
                assert_eq!(
                    (ins, outs),
                    (o.inputs.len(), o.outputs.len()),
                    "{}: {}",
                    f.display(),
                    o.type_name
                );
            }
        }
        written.extend(param_ids(&root, &registry));
    }
    assert!(exported_components > 10, "{exported_components}");
    let unknown: Vec<_> = written.difference(&seen).collect();
    assert!(
        unknown.is_empty(),
        "written but never in the corpus: {unknown:#?}"
    );
}

/// Sub-graphs nested deeper than a file read back by locus may hold clusters, and sub-graphs
/// still in files, are errors naming the node, not files that cannot be read.
#[test]
fn too_deep_or_unread_sub_graphs_are_export_errors() {
    let registry = registry();
    let mut text = r#"(format: 1, nodes: [(id: "add", type: "maths.addition")],
        inputs: {"a": "add.A"}, outputs: {"r": "add.R"})"#
        .to_owned();
    for depth in 0..Limits::default().max_cluster_depth + 1 {
        text = format!(
            r#"(format: 1, nodes: [(id: "level{depth}", type: "graph", graph: {text})],
                inputs: {{"a": "level{depth}.a"}}, outputs: {{"r": "level{depth}.r"}})"#
        );
    }
    let graph = Document::parse(&text).unwrap().graph().clone();
    let e = export_ghx(&graph, &registry).unwrap_err().to_string();
    assert!(e.contains("nest more than 8 levels deep"), "{e}");
    let graph =
        Document::parse(r#"(format: 1, nodes: [(id: "part", type: "graph", path: "part.ron")])"#)
            .unwrap()
            .graph()
            .clone();
    let e = export_ghx(&graph, &registry).unwrap_err().to_string();
    assert!(
        e.starts_with("node \"part\": its sub-graph is the file \"part.ron\""),
        "{e}"
    );
}

/// A sub-graph node's input modifiers are its cluster's, and a modifier on the Data parameter
/// that gives a sub-graph's output is its Cluster Output's: both come back, and the graph
/// computes the same tree.
#[test]
fn a_clusters_modifiers_round_trip() {
    let registry = registry();
    let text = r#"(
        format: 1,
        nodes: [
            (id: "n", type: "params.number", values: {"Num": [1, 2, 3]}),
            (id: "twice", type: "graph",
                modifiers: {"x": [reverse]},
                graph: (
                    format: 1,
                    nodes: [
                        (id: "double", type: "maths.multiplication", values: {"B": 2}),
                        (id: "y", type: "params.data", output_modifiers: {"Data": [graft]}),
                    ],
                    wires: [("double.R", "y.Data")],
                    inputs: {"x": "double.A"},
                    outputs: {"y": "y.Data"},
                )),
        ],
        wires: [("n.Num", "twice.x")],
        outputs: {"y": "twice.y"},
    )"#;
    let original = Document::parse(text).unwrap().graph().clone();
    let (ghx, warnings) = export_ghx(&original, &registry).unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    let back = import(ghx.as_bytes(), &registry, &Limits::default()).unwrap();
    let node = back.graph.nodes.iter().find(|n| n.id.0 == "twice").unwrap();
    assert_eq!(node.modifiers, original.nodes[1].modifiers);
    let graft = |g: &locus_runtime::Graph| {
        let tree = |g: &locus_runtime::Graph| {
            let checked = locus_runtime::check(g, &registry).unwrap();
            let mut e = locus_runtime::Evaluator::new(checked.plan);
            e.evaluate();
            e.output("y").map(|t| format!("{t:?}")).unwrap_or_default()
        };
        tree(g)
    };
    let expected = graft(&original);
    assert!(
        expected.contains("[0, 2]") || expected.contains("0;2"),
        "{expected}"
    );
    assert_eq!(graft(&back.graph), expected);
}
