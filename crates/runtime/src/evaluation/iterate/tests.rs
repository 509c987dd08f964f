//! The worked examples E1–E14 of the Grasshopper semantics reference, §2.5.

use super::*;
use crate::DataType;

/// Parses a number tree written `{0;1}:[1, null, 3] {0;2}:[]`.
fn tree(text: &str) -> DataTree {
    let mut t = DataTree::new();
    let mut rest = text.trim();
    while !rest.is_empty() {
        let close = rest.find('}').unwrap();
        let path: TreePath = rest[..=close].parse().unwrap();
        let after = rest[close + 1..].trim_start().strip_prefix(':').unwrap();
        let end = after.find(']').unwrap();
        let items = &after.trim_start()[1..after.trim_start().find(']').unwrap()];
        let mut b = Branch::new(DataType::Number);
        for item in items.split(',').map(str::trim).filter(|s| !s.is_empty()) {
            if item == "null" {
                b.push_null();
            } else {
                b.push(item.parse::<f64>().unwrap());
            }
        }
        t.insert(path, b);
        rest = after[end + 1..].trim_start();
    }
    t
}

fn show(t: &DataTree) -> String {
    let mut parts = Vec::new();
    for (p, b) in t.branches() {
        let items: Vec<String> = b
            .values()
            .map(|v| match v {
                Some(Value::Number(x)) => format!("{x}"),
                Some(other) => format!("{other:?}"),
                None => "null".to_owned(),
            })
            .collect();
        parts.push(format!("{p}:[{}]", items.join(",")));
    }
    parts.join(" ")
}

fn addition() -> NodeType {
    NodeType::new("test.add", "Addition", "A+B", "Maths")
        .input(Port::new("A", "A", DataType::Number))
        .input(Port::new("B", "B", DataType::Number))
        .output(Port::new("Result", "R", DataType::Number))
        .solve(|s| {
            let a = *s.item::<f64>(0)?;
            let b = *s.item::<f64>(1)?;
            s.set(0, a + b);
            Ok(())
        })
}

fn run(node: &NodeType, matching: Matching, principal: Option<usize>, inputs: &[&str]) -> String {
    let trees: Vec<DataTree> = inputs.iter().map(|s| tree(s)).collect();
    let refs: Vec<&DataTree> = trees.iter().collect();
    let id = NodeId::from("n");
    let r = NodeRun {
        node_id: &id,
        node_type: node,
        inputs: &node.inputs,
        settings: &[],
        matching,
        principal,
        prepared: None,
        wanted: &[],
        budget: &crate::limits::Budget::default(),
    };
    let serial = run_node(&r, &refs, false);
    let parallel = run_node(&r, &refs, true);
    assert_eq!(serial.outputs, parallel.outputs);
    show(&serial.outputs[0])
}

#[test]
fn e1_longest_list_repeats_the_last_item() {
    let out = run(
        &addition(),
        Matching::Longest,
        None,
        &["{0}:[1,2,3]", "{0}:[10,20]"],
    );
    assert_eq!(out, "{0}:[11,22,23]");
}

#[test]
fn e2_shortest_list_drops_extra_items() {
    let out = run(
        &addition(),
        Matching::Shortest,
        None,
        &["{0}:[1,2,3]", "{0}:[10,20]"],
    );
    assert_eq!(out, "{0}:[11,22]");
}

#[test]
fn e3_cross_reference_first_input_fastest() {
    let out = run(
        &addition(),
        Matching::Cross,
        None,
        &["{0}:[1,2]", "{0}:[10,20,30]"],
    );
    assert_eq!(out, "{0}:[11,12,21,22,31,32]");
}

#[test]
fn e4_list_reused_for_every_branch() {
    let out = run(
        &addition(),
        Matching::Longest,
        None,
        &["{0}:[1,2]", "{0;0}:[10,20,30] {0;1}:[40]"],
    );
    assert_eq!(out, "{0;0}:[11,22,32] {0;1}:[41,42]");
}

#[test]
fn e5_collision_offset_when_principal_runs_out() {
    let out = run(
        &addition(),
        Matching::Longest,
        None,
        &["{0;0}:[1] {0;1}:[2]", "{0;0}:[10] {0;1}:[20] {0;2}:[30]"],
    );
    assert_eq!(out, "{0;0}:[11] {0;1}:[22] {0;2}:[32]");
}

#[test]
fn e6_branches_paired_by_position() {
    let out = run(
        &addition(),
        Matching::Longest,
        None,
        &["{1}:[1] {5}:[2]", "{0}:[10] {1}:[20] {2}:[30]"],
    );
    assert_eq!(out, "{1}:[11] {5}:[22] {6}:[32]");
}

fn divide_like() -> NodeType {
    NodeType::new("test.divide", "Divide", "Div", "Curve")
        .input(Port::new("Curve", "C", DataType::Number))
        .input(Port::new("Count", "N", DataType::Number))
        .output(Port::new("Points", "P", DataType::Number).list())
        .solve(|s| {
            let c = *s.item::<f64>(0)?;
            let n = *s.item::<f64>(1)? as usize;
            s.set_list(0, (0..=n).map(|i| c + i as f64).collect());
            Ok(())
        })
}

#[test]
fn e7_list_output_per_item_gets_an_index() {
    let out = run(
        &divide_like(),
        Matching::Longest,
        None,
        &["{0}:[0,10,20]", "{0}:[2]"],
    );
    assert_eq!(out, "{0;0}:[0,1,2] {0;1}:[10,11,12] {0;2}:[20,21,22]");
}

#[test]
fn e8_appended_index_is_per_branch() {
    let out = run(
        &divide_like(),
        Matching::Longest,
        None,
        &["{0;0}:[0,10] {0;1}:[20]", "{0}:[1]"],
    );
    assert_eq!(out, "{0;0;0}:[0,1] {0;0;1}:[10,11] {0;1;0}:[20,21]");
}

fn sum_list() -> NodeType {
    NodeType::new("test.sum", "Sum", "Sum", "Maths")
        .input(Port::new("Values", "V", DataType::Number).list())
        .output(Port::new("Sum", "S", DataType::Number))
        .solve(|s| {
            let total = s.list::<f64>(0)?.present().sum::<f64>();
            s.set(0, total);
            Ok(())
        })
}

fn reverse_list() -> NodeType {
    NodeType::new("test.reverse", "Reverse", "Rev", "Sets")
        .input(Port::new("List", "L", DataType::Number).list())
        .output(Port::new("List", "L", DataType::Number).list())
        .solve(|s| {
            let mut v: Vec<f64> = s.list::<f64>(0)?.present().copied().collect();
            v.reverse();
            s.set_list(0, v);
            Ok(())
        })
}

#[test]
fn e9_list_input_item_output_one_call_per_branch() {
    let out = run(
        &sum_list(),
        Matching::Longest,
        None,
        &["{0;0}:[1,2,3] {0;1}:[4,5]"],
    );
    assert_eq!(out, "{0;0}:[6] {0;1}:[9]");
}

#[test]
fn e10_list_outputs_keep_the_path_without_item_inputs() {
    let out = run(
        &reverse_list(),
        Matching::Longest,
        None,
        &["{0;0}:[1,2,3] {0;1}:[4,5]"],
    );
    assert_eq!(out, "{0;0}:[3,2,1] {0;1}:[5,4]");
}

#[test]
fn e11_null_in_null_out() {
    let out = run(
        &addition(),
        Matching::Longest,
        None,
        &["{0}:[1,null,3]", "{0}:[10]"],
    );
    assert_eq!(out, "{0}:[11,null,13]");
}

#[test]
fn e12_empty_branch_in_empty_branch_out() {
    let out = run(
        &addition(),
        Matching::Longest,
        None,
        &["{0}:[1] {1}:[]", "{0}:[10] {1}:[20]"],
    );
    assert_eq!(out, "{0}:[11] {1}:[]");
}

#[test]
fn e13_item_and_tree_take_the_tree_structure() {
    let out = run(
        &addition(),
        Matching::Longest,
        None,
        &["{0}:[100]", "{0;0}:[1,2] {0;1}:[3]"],
    );
    assert_eq!(out, "{0;0}:[101,102] {0;1}:[103]");
}

#[test]
fn e14_grafted_input_gives_a_table_of_pairs() {
    let out = run(
        &addition(),
        Matching::Longest,
        None,
        &["{0;0}:[1] {0;1}:[2]", "{0}:[10,20,30]"],
    );
    assert_eq!(out, "{0;0}:[11,21,31] {0;1}:[12,22,32]");
}

#[test]
fn marked_principal_decides_the_paths() {
    let out = run(
        &addition(),
        Matching::Longest,
        Some(0),
        &["{0}:[100]", "{0;0}:[1,2] {0;1}:[3]"],
    );
    assert_eq!(out, "{0}:[101,102] {1}:[103]");
}

#[test]
fn failing_iterations_leave_nulls_and_messages() {
    let node = NodeType::new("test.div", "Division", "A/B", "Maths")
        .input(Port::new("A", "A", DataType::Number))
        .input(Port::new("B", "B", DataType::Number))
        .output(Port::new("Result", "R", DataType::Number))
        .solve(|s| {
            let a = *s.item::<f64>(0)?;
            let b = *s.item::<f64>(1)?;
            if b == 0.0 {
                return Err("division by zero".into());
            }
            s.set(0, a / b);
            Ok(())
        });
    let trees = [tree("{0}:[1,2,3]"), tree("{0}:[1,0,3]")];
    let refs: Vec<&DataTree> = trees.iter().collect();
    let id = NodeId::from("div");
    let r = NodeRun {
        node_id: &id,
        node_type: &node,
        inputs: &node.inputs,
        settings: &[],
        matching: Matching::Longest,
        principal: None,
        prepared: None,
        wanted: &[],
        budget: &crate::limits::Budget::default(),
    };
    let out = run_node(&r, &refs, false);
    assert_eq!(show(&out.outputs[0]), "{0}:[1,null,1]");
    assert_eq!(out.messages.len(), 1);
    assert_eq!(
        out.messages[0].to_string(),
        "error: node \"div\" at {0}[1]: division by zero"
    );
}

#[test]
fn large_branches_give_identical_results_in_parallel() {
    let n = 100_000;
    let a: Vec<f64> = (0..n).map(|i| i as f64).collect();
    let trees = [DataTree::from_list(a), DataTree::from_item(0.5)];
    let refs: Vec<&DataTree> = trees.iter().collect();
    let node = addition();
    let id = NodeId::from("n");
    let r = NodeRun {
        node_id: &id,
        node_type: &node,
        inputs: &node.inputs,
        settings: &[],
        matching: Matching::Longest,
        principal: None,
        prepared: None,
        wanted: &[],
        budget: &crate::limits::Budget::default(),
    };
    let serial = run_node(&r, &refs, false);
    let parallel = run_node(&r, &refs, true);
    assert_eq!(serial.outputs, parallel.outputs);
    let out = serial.outputs[0].branch(&TreePath::zero()).unwrap();
    assert_eq!(out.len(), n);
    assert_eq!(out.get::<f64>(n - 1), Some(&(n as f64 - 0.5)));
}

/// `A + Σ L1 + Σ L2 …`: an item input first, then list inputs.
fn item_plus_sums(lists: usize, item_first: bool) -> NodeType {
    let mut node = NodeType::new("test.item_plus_sums", "Item plus sums", "IpS", "Maths");
    let item = Port::new("A", "A", DataType::Number);
    let list = |i: usize| Port::new(&format!("L{i}"), &format!("L{i}"), DataType::Number).list();
    if item_first {
        node = node.input(item.clone());
    }
    for i in 0..lists {
        node = node.input(list(i));
    }
    if !item_first {
        node = node.input(item);
    }
    let a_at = if item_first { 0 } else { lists };
    node.output(Port::new("Result", "R", DataType::Number))
        .solve(move |s| {
            let mut total = *s.item::<f64>(a_at)?;
            for i in (0..=lists).filter(|&i| i != a_at) {
                total += s.list::<f64>(i)?.present().sum::<f64>();
            }
            s.set(0, total);
            Ok(())
        })
}

#[test]
fn cross_reference_steps_list_branches_inside_the_odometer() {
    // Reference §2.2: under cross reference the list input's branch index is a wheel of the
    // odometer, after the item input (the first input turns fastest).
    let inputs = ["{0}:[1,2]", "{0}:[10,20] {1}:[100]"];
    let out = run(&item_plus_sums(1, true), Matching::Cross, None, &inputs);
    assert_eq!(out, "{0}:[31,32,101,102]");
    // Longest list pairs the same branches branch by branch instead.
    let out = run(&item_plus_sums(1, true), Matching::Longest, None, &inputs);
    assert_eq!(out, "{0}:[31,32] {1}:[101,102]");
    // With the list input first, its branch turns fastest.
    let inputs = ["{0}:[10,20] {1}:[100]", "{0}:[1,2]"];
    let out = run(&item_plus_sums(1, false), Matching::Cross, None, &inputs);
    assert_eq!(out, "{0}:[31,101,32,102]");
}

#[test]
fn cross_reference_with_two_list_inputs_crosses_their_branches() {
    let inputs = ["{0}:[0]", "{0}:[1] {1}:[2]", "{0}:[10] {1}:[20]"];
    let out = run(&item_plus_sums(2, true), Matching::Cross, None, &inputs);
    assert_eq!(out, "{0}:[11,12,21,22]");
    // An empty branch of a required list input leaves a null, as an empty item does.
    let inputs = ["{0}:[0]", "{0}:[1] {1}:[]", "{0}:[10]"];
    let out = run(&item_plus_sums(2, true), Matching::Cross, None, &inputs);
    assert_eq!(out, "{0}:[11,null]");
}

/// A list input with data and one optional item input without: the node solves once per
/// branch (the sum of the list, plus the item when present), as a list-only node would.
fn sum_plus_optional() -> NodeType {
    NodeType::new("test.sum_plus", "Sum Plus", "S+", "Maths")
        .input(Port::new("V", "V", DataType::Number).list())
        .input(Port::new("K", "K", DataType::Number).optional())
        .output(Port::new("Result", "R", DataType::Number))
        .solve(|s| {
            let sum: f64 = s.list::<f64>(0)?.present().sum();
            let k = s.item_opt::<f64>(1).copied().unwrap_or(0.0);
            s.set(0, sum + k);
            Ok(())
        })
}

#[test]
fn empty_optional_item_inputs_do_not_stop_a_list_node() {
    let node = sum_plus_optional();
    for matching in [Matching::Longest, Matching::Shortest] {
        assert_eq!(
            run(&node, matching, None, &["{0;0}:[1,2,3] {0;1}:[4,5]", ""]),
            "{0;0}:[6] {0;1}:[9]",
            "{matching:?}"
        );
    }
    // Under cross reference a list input's branches are a wheel of the odometer (§2.2), so
    // both sums land in one branch, as they do when K has data.
    assert_eq!(
        run(&node, Matching::Cross, None, &["{0;0}:[1,2,3] {0;1}:[4,5]", ""]),
        "{0;0}:[6,9]"
    );
    // With the item present, it iterates as before.
    assert_eq!(
        run(
            &node,
            Matching::Longest,
            None,
            &["{0}:[1,2,3]", "{0}:[10,20]"]
        ),
        "{0}:[16,26]"
    );
    // Nothing at all: nothing to solve, an empty branch as before.
    assert_eq!(run(&node, Matching::Longest, None, &["", ""]), "{0}:[]");
}
