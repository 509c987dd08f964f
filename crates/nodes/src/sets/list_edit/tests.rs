use locus_runtime::{DataTree, Level, NodeCall};

use super::*;
use crate::sets::test_support::{generic, messages, tree};

fn texts(t: &DataTree) -> Vec<String> {
    t.values()
        .map(|v| match v {
            None => "null".to_owned(),
            Some(Value::Number(x)) => locus_runtime::format_number(x),
            Some(Value::Integer(i)) => i.to_string(),
            Some(Value::Text(t)) => t,
            Some(other) => format!("{other:?}"),
        })
        .collect()
}

#[test]
fn sub_list_takes_a_domain_of_indices() {
    let r = NodeCall::new(&sub_list())
        .input(tree("{0}:[10, 11, 12, 13, 14]"))
        .input(DataTree::from_item(Interval::new(1.0, 3.0)))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["11", "12", "13"]);
    assert_eq!(texts(&r.outputs[1]), ["1", "2", "3"]);
    // Backwards, clipped without wrap.
    let r = NodeCall::new(&sub_list())
        .input(tree("{0}:[10, 11, 12]"))
        .input(DataTree::from_item(Interval::new(5.0, 1.0)))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["12", "11"]);
    // Wrapped.
    let r = NodeCall::new(&sub_list())
        .input(tree("{0}:[10, 11, 12]"))
        .input(DataTree::from_item(Interval::new(2.0, 4.0)))
        .input(DataTree::from_item(true))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["12", "10", "11"]);
}

#[test]
fn sub_list_refuses_huge_or_invalid_domains() {
    let r = NodeCall::new(&sub_list())
        .input(tree("{0}:[1]"))
        .input(DataTree::from_item(Interval::new(0.0, 1e12)))
        .input(DataTree::from_item(true))
        .run();
    assert_eq!(messages(&r, Level::Error).len(), 1);
    let r = NodeCall::new(&sub_list())
        .input(tree("{0}:[1]"))
        .input(DataTree::from_item(Interval::new(f64::NAN, 1.0)))
        .run();
    assert_eq!(messages(&r, Level::Error).len(), 1);
}

#[test]
fn insert_items_inserts_before_original_indices() {
    let r = NodeCall::new(&insert_items())
        .input(generic("{0}:[\"a\", \"b\", \"c\"]"))
        .input(generic("{0}:[\"x\", \"y\", \"z\"]"))
        .input(DataTree::from_list(vec![0_i64, 2, 3]))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["x", "a", "b", "y", "c", "z"]);
    let r = NodeCall::new(&insert_items())
        .input(generic("{0}:[\"a\", \"b\"]"))
        .input(generic("{0}:[\"x\"]"))
        .input(DataTree::from_list(vec![7_i64, -1]))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["a", "b"]);
    assert_eq!(messages(&r, Level::Warning).len(), 1);
    let r = NodeCall::new(&insert_items())
        .input(generic("{0}:[\"a\", \"b\"]"))
        .input(generic("{0}:[\"x\"]"))
        .input(DataTree::from_list(vec![-1_i64]))
        .input(DataTree::from_item(true))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["a", "b", "x"]);
}

#[test]
fn replace_items_replaces_and_wraps() {
    let r = NodeCall::new(&replace_items())
        .input(tree("{0}:[0, 1, 2, 3]"))
        .input(tree("{0}:[10, 20]"))
        .input(DataTree::from_list(vec![1_i64, -1]))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["0", "10", "2", "20"]);
    let r = NodeCall::new(&replace_items())
        .input(tree("{0}:[0, 1]"))
        .input(tree("{0}:[10]"))
        .input(DataTree::from_list(vec![5_i64]))
        .input(DataTree::from_item(false))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["0", "1"]);
    assert_eq!(messages(&r, Level::Warning).len(), 1);
}

#[test]
fn pick_n_choose_picks_by_index_from_the_named_stream() {
    let r = NodeCall::new(&pick_n_choose())
        .input(tree("{0}:[0, 1, 1, 0]"))
        .input(generic("{0}:[\"a0\", \"a1\", \"a2\", \"a3\"]"))
        .input(generic("{0}:[\"b0\", \"b1\", \"b2\"]"))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["a0", "b1", "b2", "a3"]);
    let r = NodeCall::new(&pick_n_choose())
        .input(tree("{0}:[0, 1, 1, 1]"))
        .input(generic("{0}:[\"a0\"]"))
        .input(generic("{0}:[\"b0\", \"b1\", \"b2\"]"))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["a0", "b1", "b2", "null"]);
    let r = NodeCall::new(&pick_n_choose())
        .input(tree("{0}:[2]"))
        .input(generic("{0}:[1]"))
        .input(generic("{0}:[2]"))
        .run();
    assert_eq!(
        messages(&r, Level::Error),
        ["pattern index 2 names no stream (there are 2, 0 to 1)"]
    );
}

#[test]
fn pick_n_choose_takes_more_streams() {
    let r = NodeCall::new(&pick_n_choose())
        .input_names(&["P", "0", "1", "2"])
        .input(tree("{0}:[2, 0]"))
        .input(generic("{0}:[\"a0\", \"a1\"]"))
        .input(generic("{0}:[\"b0\", \"b1\"]"))
        .input(generic("{0}:[\"c0\", \"c1\"]"))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["c0", "a1"]);
}

#[test]
fn weave_interleaves_until_the_streams_are_used_up() {
    let r = NodeCall::new(&weave())
        .input(tree("{0}:[0, 1]"))
        .input(generic("{0}:[\"a0\", \"a1\", \"a2\"]"))
        .input(generic("{0}:[\"b0\"]"))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["a0", "b0", "a1", "a2"]);
    let r = NodeCall::new(&weave())
        .input(tree("{0}:[0, 0, 1]"))
        .input(generic("{0}:[\"a0\", \"a1\", \"a2\", \"a3\"]"))
        .input(generic("{0}:[\"b0\", \"b1\"]"))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["a0", "a1", "b0", "a2", "a3", "b1"]);
    // A stream the pattern never names is left out with a warning.
    let r = NodeCall::new(&weave())
        .input(tree("{0}:[1]"))
        .input(generic("{0}:[\"a0\"]"))
        .input(generic("{0}:[\"b0\"]"))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["b0"]);
    assert_eq!(messages(&r, Level::Warning).len(), 1);
    let r = NodeCall::new(&weave())
        .input(generic("{0}:[\"x\"]"))
        .input(generic("{0}:[1]"))
        .run();
    assert_eq!(messages(&r, Level::Error).len(), 1);
}

#[test]
fn sift_pattern_keeps_outputs_aligned_with_nulls() {
    let r = NodeCall::new(&sift_pattern())
        .input(tree("{0}:[0, 1, 2, 3, 4]"))
        .input(DataTree::from_list(vec![0_i64, 1, 1]))
        .run();
    assert_eq!(texts(&r.outputs[0]), ["0", "null", "null", "3", "null"]);
    assert_eq!(texts(&r.outputs[1]), ["null", "1", "2", "null", "4"]);
    let r = NodeCall::new(&sift_pattern())
        .input(tree("{0}:[0, 1, 2]"))
        .input(DataTree::from_list(vec![0_i64, 5]))
        .run();
    assert_eq!(texts(&r.outputs[1]), ["null", "null", "null"]);
    assert_eq!(messages(&r, Level::Warning).len(), 1);
}

#[test]
fn cross_reference_modes() {
    let run = |mode: &str| {
        let r = NodeCall::new(&cross_reference())
            .input(tree("{0}:[0, 1, 2]"))
            .input(generic("{0}:[\"a\", \"b\", \"c\"]"))
            .setting("mode", Value::Text(mode.into()))
            .run();
        let a = texts(&r.outputs[0]);
        let b = texts(&r.outputs[1]);
        a.into_iter()
            .zip(b)
            .map(|(a, b)| format!("{a}{b}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    assert_eq!(run("holistic"), "0a 1a 2a 0b 1b 2b 0c 1c 2c");
    assert_eq!(run("diagonal"), "1a 2a 0b 2b 0c 1c");
    assert_eq!(run("coincident"), "0a 1b 2c");
    assert_eq!(run("lower_triangle"), "0a 1a 2a 1b 2b 2c");
    assert_eq!(run("lower_triangle_strict"), "1a 2a 2b");
    assert_eq!(run("upper_triangle"), "0a 0b 1b 0c 1c 2c");
    assert_eq!(run("upper_triangle_strict"), "0b 0c 1c");
    let r = NodeCall::new(&cross_reference())
        .input(tree("{0}:[0]"))
        .input(tree("{0}:[1]"))
        .setting("mode", Value::Text("sideways".into()))
        .run();
    assert_eq!(messages(&r, Level::Error).len(), 1);
}

#[test]
fn null_item_flags_nulls_and_invalid_items() {
    let r = NodeCall::new(&null_item())
        .input(generic("{0}:[1, null, NaN, \"a\"]"))
        .run();
    assert_eq!(
        crate::test_support::booleans(&r.outputs[0]),
        [false, true, false, false]
    );
    assert_eq!(
        crate::test_support::booleans(&r.outputs[1]),
        [false, false, true, false]
    );
    assert_eq!(
        texts(&r.outputs[2]),
        [
            "Valid Number",
            "Null",
            "Invalid: the number NaN is not finite",
            "Valid Text"
        ]
    );
}
