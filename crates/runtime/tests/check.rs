//! Checking: one small graph per kind of fault, each giving its message at its place, and the
//! plan of a graph that passes.

mod common;

use locus_runtime::{
    DataTree, DataType, Diagnostic, Graph, Modifier, Severity, TreePath, Value, check, check_text,
};

/// Every diagnostic of a graph that fails checking, printed as the CLI prints them.
fn errors(text: &str) -> Vec<String> {
    match check_text(text, &common::registry()) {
        Ok(c) => panic!("checking passed with warnings {:?}", strings(&c.warnings)),
        Err(d) => d
            .iter()
            .map(|d| d.display_in("g.ron").to_string())
            .collect(),
    }
}

/// The warnings of a graph that passes checking.
fn warnings(text: &str) -> Vec<String> {
    match check_text(text, &common::registry()) {
        Ok(c) => c
            .warnings
            .iter()
            .map(|d| d.display_in("g.ron").to_string())
            .collect(),
        Err(d) => panic!("checking failed: {:?}", strings(&d)),
    }
}

fn strings(d: &[Diagnostic]) -> Vec<String> {
    d.iter().map(ToString::to_string).collect()
}

#[test]
fn unknown_node_type_suggests_close_ids() {
    let text = "(format: 1, nodes: [\n  (id: \"d1\", type: \"vector.dot\"),\n])";
    assert_eq!(
        errors(text),
        [
            "g.ron:2:20: error: unknown node type \"vector.dot\" on node \"d1\" (did you mean \
          \"vector.dot_product\"?)"
        ]
    );
    let far = "(format: 1, nodes: [(id: \"x\", type: \"nothing.like.it\")])";
    assert_eq!(
        errors(far),
        ["g.ron:1:37: error: unknown node type \"nothing.like.it\" on node \"x\""]
    );
}

#[test]
fn a_display_name_as_node_type_suggests_the_id() {
    let text = "(format: 1, nodes: [(id: \"d\", type: \"Dot Product\")])";
    assert_eq!(
        errors(text),
        [
            "g.ron:1:37: error: unknown node type \"Dot Product\" on node \"d\" (did you mean \
          \"vector.dot_product\"?)"
        ]
    );
}

#[test]
fn unknown_ports_list_the_valid_ones() {
    let text = r#"(format: 1, nodes: [
  (id: "d", type: "vector.dot_product", values: {"A": (1, 0, 0), "C": (0, 1, 0)}),
  (id: "n", type: "params.number"),
  (id: "v", type: "params.vector"),
], wires: [("d.X", "n.N"), ("v.V", "d.Vector B")])"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:2:66: error: unknown input \"C\" on node \"d\" (vector.dot_product has \
             inputs \"A\", \"B\")",
            "g.ron:5:13: error: unknown output \"X\" on node \"d\" (vector.dot_product has \
             outputs \"D\")",
        ]
    );
}

#[test]
fn duplicate_and_invalid_node_ids() {
    let text = r#"(format: 1, nodes: [
  (id: "a", type: "params.number"),
  (id: "a", type: "params.number"),
  (id: "b.c", type: "params.number"),
  (id: "", type: "params.number"),
])"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:3:8: error: duplicate node id \"a\" (first used on line 2)",
            "g.ron:4:8: error: invalid node id \"b.c\" (ids are non-empty and have no dots, \
             slashes, quotes or spaces; a slash separates a sub-graph's id from its nodes' ids)",
            "g.ron:5:8: error: invalid node id \"\" (ids are non-empty and have no dots, \
             slashes, quotes or spaces; a slash separates a sub-graph's id from its nodes' ids)",
        ]
    );
}

#[test]
fn wires_need_a_cast() {
    let text = r#"(format: 1, nodes: [
  (id: "b", type: "params.boolean"),
  (id: "d", type: "vector.dot_product", values: {"B": (0, 0, 1)}),
], wires: [
  ("b.B", "d.A"),
])"#;
    assert_eq!(
        errors(text),
        ["g.ron:5:4: error: wire \"b.B\" → \"d.A\" has no cast from Boolean to Vector"]
    );
}

#[test]
fn wires_go_from_outputs_to_inputs() {
    let text = r#"(format: 1, nodes: [
  (id: "p", type: "params.vector"),
  (id: "d", type: "vector.dot_product", values: {"A": (1, 0, 0), "B": (0, 1, 0)}),
  (id: "n", type: "params.number"),
], wires: [
  ("p.V", "d.D"),
  ("d.A", "n.N"),
])"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:6:11: error: the end of wire \"p.V\" → \"d.D\" must be an input, but \"d.D\" \
             is an output",
            "g.ron:7:4: error: the start of wire \"d.A\" → \"n.N\" must be an output, but \
             \"d.A\" is an input",
        ]
    );
}

#[test]
fn wires_name_existing_nodes() {
    let text = r#"(format: 1, nodes: [(id: "n", type: "params.number")], wires: [("m.N", "n.N")])"#;
    assert_eq!(
        errors(text),
        ["g.ron:1:65: error: unknown node \"m\" in the start of wire \"m.N\" → \"n.N\""]
    );
}

#[test]
fn required_inputs_need_data() {
    let text = r#"(format: 1, nodes: [
  (id: "add", type: "math.addition"),
])"#;
    assert_eq!(
        errors(text),
        ["g.ron:2:8: error: input \"A\" of node \"add\" has no wire, no value and no default"]
    );
}

#[test]
fn values_must_parse_as_the_port_type() {
    let text = r#"(format: 1, nodes: [
  (id: "d", type: "vector.dot_product", values: {"A": "abc", "B": (1, x, 3)}),
  (id: "i", type: "params.integer", values: {"I": [1, 2.5]}),
  (id: "t", type: "params.number", values: {"N": {"{0;a}": [1]}}),
])"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:2:55: error: bad value for input \"A\" of node \"d\": expected a vector (x, \
             y, z), found \"abc\"",
            "g.ron:2:71: error: bad value for input \"B\" of node \"d\": expected a number in a \
             vector (x, y, z), found x",
            "g.ron:3:55: error: bad value for input \"I\" of node \"i\": expected an integer, \
             found 2.5",
            "g.ron:4:51: error: bad value for input \"N\" of node \"t\": invalid tree path \
             `{0;a}`: indices must be non-negative integers",
        ]
    );
}

#[test]
fn settings_must_exist_and_parse() {
    let text = r#"(format: 1, nodes: [
  (id: "e", type: "math.expression", settings: {"formula": "x", "precision": "six"}),
  (id: "n", type: "params.number", settings: {"x": 1}),
], inputs: {"x": "e.x", "y": "e.y"})"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:2:49: error: unknown setting \"formula\" on node \"e\" (settings: \
             \"expression\", \"precision\")",
            "g.ron:2:78: error: bad value for setting \"precision\" of node \"e\": expected an \
             integer, found \"six\"",
            "g.ron:3:47: error: unknown setting \"x\" on node \"n\" (it has no settings)",
            "g.ron:4:13: warning: named input \"x\" sets input \"x\" of node \"e\", which has no \
             value until a host sets it",
            "g.ron:4:25: warning: named input \"y\" sets input \"y\" of node \"e\", which has no \
             value until a host sets it",
        ]
    );
}

#[test]
fn modifiers_must_fit_the_port_type() {
    let text = r#"(format: 1, nodes: [
  (id: "r", type: "vector.rotate", values: {"V": (1, 0, 0), "A": 90},
   modifiers: {"V": [invert], "A": [degrees], "X": [degrees, reparameterize]}),
  (id: "a", type: "math.addition", values: {"A": 1}, modifiers: {"A": [reparameterize]}),
  (id: "n", type: "logic.not", values: {"A": true}, modifiers: {"A": [invert, reverse]}),
])"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:3:22: error: modifier invert does not apply to input \"V\" of node \"r\", \
             which is of type Vector (it applies to Boolean inputs)",
            "g.ron:3:53: error: modifier degrees does not apply to input \"X\" of node \"r\", \
             which is of type Vector (it applies to Number inputs)",
            "g.ron:3:62: error: modifier reparameterize does not apply to input \"X\" of node \
             \"r\", which is of type Vector (it applies to Curve and Surface inputs)",
            "g.ron:4:72: error: modifier reparameterize does not apply to input \"A\" of node \
             \"a\", which is of type Number (it applies to Curve and Surface inputs)",
        ]
    );
}

#[test]
fn structural_modifiers_exclude_each_other_and_one_input_is_principal() {
    let text = r#"(format: 1, nodes: [
  (id: "a", type: "math.addition", values: {"A": 1},
   modifiers: {"A": [flatten, graft, principal], "B": [simplify, principal]}),
])"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:2:8: error: node \"a\" has more than one principal input (\"A\", \"B\")",
            "g.ron:3:31: error: modifiers flatten and graft exclude each other on input \"A\" of \
             node \"a\"",
        ]
    );
}

#[test]
fn output_modifiers_name_outputs_and_fit_their_type() {
    let text = r#"(format: 1, nodes: [
  (id: "v", type: "vector.two_pt", values: {"A": (0, 0, 0), "B": (1, 0, 0)},
   output_modifiers: {"V": [principal, degrees, graft], "U": [flatten], "L": [invert]}),
  (id: "n", type: "logic.not", values: {"A": true},
   output_modifiers: {"R": [invert, simplify, graft], "R": [reverse]}),
])"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:3:29: error: modifier principal does not apply to output \"V\" of node \"v\" \
             (it applies to inputs only)",
            "g.ron:3:40: error: modifier degrees does not apply to output \"V\" of node \"v\" (it \
             applies to inputs only)",
            "g.ron:3:57: error: unknown output \"U\" on node \"v\" (vector.two_pt has outputs \"V\", \
             \"L\")",
            "g.ron:3:79: error: modifier invert does not apply to output \"L\" of node \"v\", which \
             is of type Number (it applies to Boolean outputs)",
            "g.ron:5:47: error: modifiers simplify and graft exclude each other on output \"R\" of \
             node \"n\"",
            "g.ron:5:55: error: modifiers of output \"R\" of node \"n\" are given twice",
        ]
    );
}

#[test]
fn output_modifiers_go_into_the_plan_in_application_order() {
    let text = r#"(format: 1, nodes: [
  (id: "v", type: "vector.two_pt", values: {"A": (0, 0, 0), "B": (1, 0, 0)},
   output_modifiers: {"Length": [reverse, flatten]}),
  (id: "n", type: "logic.not", values: {"A": true}, output_modifiers: {"R": [invert]}),
  (id: "plain", type: "logic.not", values: {"A": true}),
])"#;
    let plan = check_text(text, &common::registry()).unwrap().plan;
    assert_eq!(plan.nodes[0].output_modifiers(0), []);
    assert_eq!(
        plan.nodes[0].output_modifiers(1),
        [Modifier::Flatten, Modifier::Reverse]
    );
    assert_eq!(plan.nodes[1].output_modifiers(0), [Modifier::Invert]);
    assert!(plan.nodes[2].output_modifiers.is_empty());
}

#[test]
fn cycles_name_their_nodes() {
    let text = r#"(format: 1, nodes: [
  (id: "start", type: "params.number", values: {"N": 1}),
  (id: "a", type: "math.addition"),
  (id: "b", type: "math.addition"),
  (id: "c", type: "math.addition"),
  (id: "self", type: "math.addition"),
], wires: [
  ("start.N", "a.A"),
  ("a.R", "b.A"),
  ("b.R", "c.A"),
  ("c.R", "a.B"),
  ("self.R", "self.A"),
])"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:3:8: error: wires form a cycle: \"a\" → \"b\" → \"c\" → \"a\"",
            "g.ron:6:8: error: wires form a cycle: \"self\" → \"self\"",
        ]
    );
}

#[test]
fn named_inputs_and_outputs_are_unique_and_resolve() {
    let text = r#"(format: 1, nodes: [
  (id: "n", type: "params.number", values: {"N": 1}),
  (id: "d", type: "vector.dot_product", values: {"A": (1, 0, 0), "B": (0, 1, 0)}),
],
inputs: {"x": "n.N", "x": "n.N", "y": "m.N", "z": "d.D"},
outputs: {"r": "d.D", "r": "n.N", "s": "d.Z", "t": "d.A"})"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:5:22: error: duplicate named input \"x\"",
            "g.ron:5:39: error: unknown node \"m\" in named input \"y\"",
            "g.ron:5:51: error: named input \"z\" must be an input, but \"d.D\" is an output",
            "g.ron:6:23: error: duplicate named output \"r\"",
            "g.ron:6:40: error: unknown output \"Z\" on node \"d\" (vector.dot_product has \
             outputs \"D\")",
            "g.ron:6:52: error: named output \"t\" must be an output, but \"d.A\" is an input",
        ]
    );
}

#[test]
fn expected_values_need_a_named_output_of_their_type() {
    let text = r#"(format: 1, nodes: [
  (id: "n", type: "params.number", values: {"N": 1}),
],
outputs: {"n": "n.N"},
expected: {"n": [1.0, "two"], "m": 3})"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:5:23: error: bad expected value for output \"n\": expected a number, found \
             \"two\"",
            "g.ron:5:31: error: expected value for unknown output \"m\" (outputs: \"n\")",
        ]
    );
}

#[test]
fn variable_input_names_only_where_the_type_has_them() {
    let text = r#"(format: 1, nodes: [
  (id: "n", type: "params.number", inputs: ["a"]),
  (id: "e", type: "math.expression", inputs: ["a", "b", "a", " "], values: {"a": 1, "b": 2}),
])"#;
    assert_eq!(
        errors(text),
        [
            "g.ron:2:45: error: node type \"params.number\" has fixed inputs, so `inputs` cannot \
             be given on node \"n\"",
            "g.ron:3:57: error: duplicate input name \"a\" on node \"e\"",
            "g.ron:3:62: error: empty input name on node \"e\"",
        ]
    );
}

#[test]
fn warnings_do_not_stop_the_graph() {
    let text = r#"(format: 1, nodes: [
  (id: "n", type: "params.number", values: {"N": 1}),
  (id: "a", type: "math.addition", values: {"A": 5}),
], wires: [("n.N", "a.A"), ("n.N", "a.A")])"#;
    assert_eq!(
        warnings(text),
        [
            "g.ron:3:45: warning: the value of input \"A\" of node \"a\" is ignored because the \
             input is wired",
            "g.ron:4:29: warning: duplicate wire \"n.N\" → \"a.A\"",
        ]
    );
}

#[test]
fn all_problems_are_reported_at_once_in_file_order() {
    let text = r#"(format: 1, nodes: [
  (id: "p", type: "params.pointt"),
  (id: "d", type: "vector.dot_product", values: {"A": 1}),
  (id: "d", type: "math.addition", values: {"A": 1}),
], wires: [("d.D", "q.A")])"#;
    let all = errors(text);
    assert_eq!(
        all,
        [
            "g.ron:2:19: error: unknown node type \"params.pointt\" on node \"p\" (did you mean \
             \"params.point\"?)",
            "g.ron:3:8: error: input \"B\" of node \"d\" has no wire, no value and no default",
            "g.ron:3:55: error: bad value for input \"A\" of node \"d\": expected a vector (x, y, \
             z), found 1",
            "g.ron:4:8: error: duplicate node id \"d\" (first used on line 3)",
            "g.ron:5:20: error: unknown node \"q\" in the end of wire \"d.D\" → \"q.A\"",
        ]
    );
}

#[test]
fn graphs_checked_without_source_have_no_locations() {
    let graph =
        Graph::from_ron(r#"(format: 1, nodes: [(id: "a", type: "math.addition")])"#).unwrap();
    let d = check(&graph, &common::registry()).unwrap_err();
    assert_eq!(
        strings(&d),
        ["error: input \"A\" of node \"a\" has no wire, no value and no default"]
    );
    assert_eq!(d[0].node(), Some("a"));
    assert_eq!(d[0].port(), Some("A"));
    assert_eq!(d[0].severity, Severity::Error);
}

#[test]
fn a_checked_graph_becomes_a_plan() {
    let text = r#"(format: 1, nodes: [
  (id: "sum", type: "math.addition", modifiers: {"B": [reverse, graft]}),
  (id: "x", type: "params.number", values: {"N": [1, 2]}),
  (id: "free", type: "params.integer"),
  (id: "y", type: "params.number", values: {"N": 3}),
  (id: "e", type: "math.expression", inputs: ["u"], settings: {"expression": "u"}),
], wires: [("y.N", "sum.A"), ("x.N", "sum.A"), ("sum.R", "e.u")],
inputs: {"y": "y.Number"}, outputs: {"out": "e.Result"})"#;
    let checked = check_text(text, &common::registry()).unwrap();
    assert!(checked.warnings.is_empty());
    let plan = checked.plan;
    // Sources first; ties go to the earlier node in the file.
    assert_eq!(plan.order, [1, 2, 3, 0, 4]);
    let sum = &plan.nodes[0];
    assert_eq!(sum.inputs[0].sources, [(3, 0), (1, 0)]);
    assert_eq!(sum.inputs[1].value, Some(DataTree::from_item(0.0)));
    assert_eq!(
        sum.inputs[1].modifiers,
        [Modifier::Graft, Modifier::Reverse]
    );
    assert_eq!(
        plan.nodes[1].inputs[0].value,
        Some(DataTree::from_list(vec![1.0, 2.0]))
    );
    assert_eq!(plan.nodes[2].inputs[0].value, None);
    let e = &plan.nodes[4];
    assert_eq!(e.inputs.len(), 1);
    assert_eq!(e.inputs[0].port.nickname, "u");
    assert_eq!(e.inputs[0].port.data_type, DataType::Generic);
    assert_eq!(
        e.settings,
        [
            ("expression".to_owned(), Value::Text("u".to_owned())),
            ("precision".to_owned(), Value::Integer(6)),
        ]
    );
    assert_eq!(plan.inputs, [("y".to_owned(), 3, 0)]);
    assert_eq!(plan.outputs, [("out".to_owned(), 4, 0)]);
    assert!(std::sync::Arc::ptr_eq(
        &plan.nodes[1].node_type,
        &plan.nodes[3].node_type
    ));
    assert_eq!(
        plan.nodes[1].inputs[0]
            .value
            .as_ref()
            .and_then(|t| t.branch(&TreePath::zero()))
            .map(|b| b.len()),
        Some(2)
    );
}
