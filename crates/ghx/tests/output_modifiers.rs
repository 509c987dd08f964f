//! Output modifiers in real definitions: Grasshopper stores them on a component's output
//! parameters exactly as on inputs (`Mapping`, `SimplifyData`, `ReverseData`, …); the importer
//! puts them on the node's `output_modifiers` and the writer puts them back.

use locus_ghx::{Limits, export_ghx, import};
use locus_runtime::{Modifier, NodeRegistry};

fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    r
}

#[test]
fn output_modifiers_are_written_back() {
    let registry = registry();
    let text = r#"(format: 1, nodes: [
  (id: "s", type: "sets.series", output_modifiers: {"S": [graft, reverse]}),
  (id: "b", type: "maths.larger_than", values: {"B": 1.0}, output_modifiers: {">": [invert]}),
], wires: [("s.S", "b.A")])"#;
    let graph = locus_runtime::Graph::from_ron(text).unwrap();
    let (ghx, warnings) = export_ghx(&graph, &registry).unwrap();
    assert!(warnings.is_empty(), "{warnings:?}");
    assert!(ghx.contains(r#"<item name="Mapping" type_name="gh_int32" type_code="3">2</item>"#));
    let back = import(ghx.as_bytes(), &registry, &Limits::default()).unwrap();
    let mods: Vec<_> = back
        .graph
        .nodes
        .iter()
        .map(|n| n.output_modifiers.clone())
        .collect();
    assert_eq!(
        mods,
        [
            vec![("S".to_owned(), vec![Modifier::Graft, Modifier::Reverse])],
            vec![(">".to_owned(), vec![Modifier::Invert])],
        ]
    );
}

/// Every (file, node type, output, modifiers) of the definitions in tests/data.
fn corpus_output_modifiers() -> Vec<(String, String, String, Vec<Modifier>)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data");
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .filter(|f| f.ends_with(".ghx") || f.ends_with(".gh"))
        .collect();
    files.sort();
    let registry = registry();
    let mut found = Vec::new();
    for f in files {
        let bytes = std::fs::read(dir.join(&f)).unwrap();
        let imported = import(&bytes, &registry, &Limits::default()).unwrap();
        for node in &imported.graph.nodes {
            for (port, mods) in &node.output_modifiers {
                found.push((
                    f.clone(),
                    node.node_type.clone(),
                    port.clone(),
                    mods.clone(),
                ));
            }
        }
    }
    found
}

#[test]
fn every_output_modifier_of_the_corpus_is_imported() {
    // Read off the files' param_output / OutputParam chunks (Mapping 1 = flatten, 2 = graft;
    // SimplifyData, ReverseData): Square Grid's points flattened, Explode's segments grafted,
    // as the tutorials use them. BranchNodeRnd's Quadrangulate (M, flatten) is not a locus
    // node, so it has no output to carry the modifier.
    use Modifier::{Flatten, Graft, Reverse, Simplify};
    let expected = [
        (
            "mcneel-compute__hops_definitions_SpikeyThing.gh",
            "sets.shift_paths",
            "D",
            Graft,
        ),
        (
            "mcneel-compute__hops_definitions_dresser3.gh",
            "surface.box_2pt",
            "B",
            Flatten,
        ),
        (
            "mcneel-compute__hops_definitions_srf_kmeans.gh",
            "mesh.mesh_colours",
            "M",
            Flatten,
        ),
        (
            "mcneel-compute__hops_definitions_srf_kmeans.gh",
            "sets.text_join",
            "R",
            Flatten,
        ),
        (
            "mcneel-samples__BranchNodeRnd.ghx",
            "curve.explode",
            "S",
            Graft,
        ),
        (
            "mcneel-samples__BranchNodeRnd.ghx",
            "curve.explode",
            "S",
            Graft,
        ),
        (
            "runxel__attractor_1_point.ghx",
            "vector.distance",
            "D",
            Flatten,
        ),
        (
            "runxel__attractor_2_linear.ghx",
            "vector.grid_hexagonal",
            "P",
            Simplify,
        ),
        (
            "runxel__circle_size_gradient.ghx",
            "vector.grid_square",
            "P",
            Flatten,
        ),
        (
            "runxel__datatree_list_shifting.ghx",
            "sets.char_sequence",
            "S",
            Graft,
        ),
        (
            "runxel__datatree_list_shifting.ghx",
            "sets.concatenate",
            "R",
            Simplify,
        ),
        (
            "runxel__datatree_list_shifting.ghx",
            "sets.shift_list",
            "L",
            Simplify,
        ),
        (
            "runxel__datatree_selecting_items.ghx",
            "vector.grid_square",
            "P",
            Simplify,
        ),
        (
            "runxel__rotate_by_length.ghx",
            "vector.construct_point",
            "Pt",
            Reverse,
        ),
    ];
    let mut found = corpus_output_modifiers();
    found.sort_by(|a, b| (&a.0, &a.1).cmp(&(&b.0, &b.1)));
    let expected: Vec<_> = expected
        .into_iter()
        .map(|(f, t, p, m)| (f.to_owned(), t.to_owned(), p.to_owned(), vec![m]))
        .collect();
    assert_eq!(found, expected);
}

#[test]
fn output_modifiers_of_floating_parameters_and_script_outputs_round_trip() {
    let registry = registry();
    // A floating parameter has one set of modifiers in Grasshopper: output modifiers are
    // written as its modifiers and read back as input modifiers (the same tree comes out).
    let text = r#"(format: 1, nodes: [
  (id: "n", type: "params.number", values: {"Num": [1.0, 2.0]}, output_modifiers: {"Num": [graft]}),
  (id: "both", type: "params.number", modifiers: {"Num": [reverse]}, output_modifiers: {"Num": [graft]}),
  (id: "py", type: "script.python", inputs: ["x"], outputs: ["a", "b"],
   settings: {"code": "a = x\nb = x"}, output_modifiers: {"b": [flatten, reverse]}),
], wires: [("n.Num", "py.x")])"#;
    let graph = locus_runtime::Graph::from_ron(text).unwrap();
    let (ghx, warnings) = export_ghx(&graph, &registry).unwrap();
    let about_modifiers: Vec<String> = warnings
        .iter()
        .map(ToString::to_string)
        .filter(|w| w.contains("modifiers"))
        .collect();
    assert_eq!(
        about_modifiers,
        [
            "node \"both\": a floating parameter keeps one set of modifiers; its output modifiers \
          are not written"
        ]
    );
    let back = import(ghx.as_bytes(), &registry, &Limits::default()).unwrap();
    let node = |id: &str| back.graph.nodes.iter().find(|n| n.id.0 == id).unwrap();
    assert_eq!(
        node("n").modifiers,
        [("Num".to_owned(), vec![Modifier::Graft])]
    );
    assert!(node("n").output_modifiers.is_empty());
    assert_eq!(
        node("both").modifiers,
        [("Num".to_owned(), vec![Modifier::Reverse])]
    );
    assert_eq!(
        node("py").output_modifiers,
        [("b".to_owned(), vec![Modifier::Flatten, Modifier::Reverse])]
    );
}
