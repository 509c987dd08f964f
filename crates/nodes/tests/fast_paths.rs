//! Property tests: the typed loops of lifted nodes and fast paths give exactly what the general
//! solve function gives (outputs, nulls, messages with path and index) on random trees with
//! nulls, empty branches, non-finite numbers and mixed types, and outputs that no wire reads
//! are the same when they are computed on request.

use std::sync::Arc;

use locus_kernel::{Plane, Point3, Vector3};
use locus_nodes::maths::{comparison, operators};
use locus_nodes::transform::euclidean;
use locus_nodes::vector::{plane, point, vectors};
use locus_runtime::{
    Branch, DataTree, DataType, Evaluator, Matching, NodeCall, NodeId, NodeType, Plan, PlanInput,
    PlanNode, TreePath, Value,
};
use proptest::prelude::*;

fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        8 => -10.0..10.0f64,
        1 => Just(0.0),
        1 => Just(f64::NAN),
        1 => Just(f64::INFINITY),
    ]
}

fn a_point() -> impl Strategy<Value = Point3> {
    (number(), number(), number()).prop_map(|(x, y, z)| Point3::new(x, y, z))
}

/// One item of the given kind, sometimes null, sometimes of another type.
fn item(kind: DataType) -> impl Strategy<Value = Option<Value>> {
    let own: BoxedStrategy<Value> = match kind {
        DataType::Point => a_point().prop_map(Value::Point).boxed(),
        DataType::Vector => a_point().prop_map(|p| Value::Vector(p.to_vector())).boxed(),
        DataType::Boolean => any::<bool>().prop_map(Value::Boolean).boxed(),
        DataType::Plane => a_point()
            .prop_map(|p| {
                Value::Plane(
                    Plane::from_frame(p, Vector3::X, Vector3::Y).unwrap_or(Plane::WORLD_XY),
                )
            })
            .boxed(),
        _ => number().prop_map(Value::Number).boxed(),
    };
    prop_oneof![
        12 => own.prop_map(Some),
        2 => Just(None),
        1 => number().prop_map(|x| Some(Value::Number(x))),
        1 => a_point().prop_map(|p| Some(Value::Point(p))),
        1 => Just(Some(Value::Text("1.5".to_owned()))),
    ]
}

/// A branch: usually of one type (a typed column, which the fast loops take), sometimes
/// mixed, sometimes empty.
fn branch(kind: DataType) -> impl Strategy<Value = Branch> {
    prop::collection::vec(item(kind), 0..6).prop_map(|items| {
        let mut b = Branch::new(DataType::Generic);
        for v in items {
            b.push_option(v);
        }
        b.narrowed()
    })
}

/// A tree of up to three branches `{0}`, `{1}`, `{2}`.
fn tree(kind: DataType) -> impl Strategy<Value = DataTree> {
    prop::collection::vec(branch(kind), 0..4).prop_map(|branches| {
        DataTree::from_branches(
            branches
                .into_iter()
                .enumerate()
                .map(|(i, b)| (TreePath::new(vec![i as u32]), b)),
        )
    })
}

/// One item of the given kind (a single-item tree), as a wire from a number slider would give.
fn one(kind: DataType) -> impl Strategy<Value = DataTree> {
    item(kind).prop_map(|v| v.map_or_else(DataTree::new, DataTree::from_value))
}

fn run(node: &NodeType, inputs: &[DataTree]) -> String {
    let mut call = NodeCall::new(node);
    for input in inputs {
        call = call.input(input.clone());
    }
    let r = call.run();
    format!("{}\n{:?}", items(&r.outputs), r.messages)
}

/// The paths and items of trees as text (Debug text compares NaNs as equal). An empty branch
/// has no items, so the type its column was made with (a generic output's empty branch is
/// generic in the general path) is not compared.
fn items(trees: &[DataTree]) -> String {
    let trees: Vec<Vec<(TreePath, Vec<Option<Value>>)>> = trees
        .iter()
        .map(|t| {
            t.branches()
                .iter()
                .map(|(p, b)| (p.clone(), b.values().collect()))
                .collect()
        })
        .collect();
    format!("{trees:?}")
}

fn same(node: NodeType, inputs: &[DataTree]) -> Result<(), TestCaseError> {
    let general = node.clone().general_only();
    prop_assert_eq!(run(&node, inputs), run(&general, inputs));
    Ok(())
}

/// Two item trees, each either a full tree or one item.
fn pair(a: DataType, b: DataType) -> impl Strategy<Value = Vec<DataTree>> {
    (prop_oneof![tree(a), one(a)], prop_oneof![tree(b), one(b)]).prop_map(|(x, y)| vec![x, y])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn move_fast_path_is_the_solve_function(inputs in pair(DataType::Point, DataType::Vector)) {
        same(euclidean::move_geometry(), &inputs)?;
    }

    #[test]
    fn rotate_fast_path_is_the_solve_function(
        mut inputs in pair(DataType::Point, DataType::Number),
        planes in prop_oneof![tree(DataType::Plane), one(DataType::Plane)],
    ) {
        inputs.push(planes);
        same(euclidean::rotate(), &inputs)?;
    }

    #[test]
    fn comparisons_are_the_solve_function(inputs in pair(DataType::Number, DataType::Number)) {
        same(comparison::larger_than(), &inputs)?;
        same(comparison::smaller_than(), &inputs)?;
        same(comparison::equality(), &inputs)?;
    }

    #[test]
    fn addition_fast_path_is_the_solve_function(
        inputs in pair(DataType::Number, DataType::Number),
    ) {
        same(operators::addition(), &inputs)?;
        same(operators::subtraction(), &inputs)?;
    }

    #[test]
    fn vector_nodes_are_the_solve_function(
        mut inputs in pair(DataType::Point, DataType::Point),
        unitize in prop_oneof![tree(DataType::Boolean), one(DataType::Boolean)],
        numbers in prop_oneof![tree(DataType::Number), one(DataType::Number)],
    ) {
        same(point::distance(), &inputs)?;
        same(point::deconstruct_point(), &inputs[..1])?;
        same(vectors::deconstruct_vector(), &inputs[..1])?;
        inputs.push(unitize);
        same(vectors::vector_2pt(), &inputs)?;
        let xyz = [numbers.clone(), inputs[0].clone(), numbers];
        same(vectors::vector_xyz(), &xyz)?;
    }

    #[test]
    fn plane_nodes_are_the_solve_function(
        planes in prop_oneof![tree(DataType::Plane), one(DataType::Plane)],
    ) {
        same(plane::deconstruct_plane(), std::slice::from_ref(&planes))?;
        same(plane::plane_coefficients(), &[planes])?;
    }

    /// Move's transform output, which no wire reads here, is computed on request and equals
    /// the one computed with the geometry.
    #[test]
    fn unread_outputs_are_computed_on_request(
        inputs in pair(DataType::Point, DataType::Vector),
    ) {
        let node = euclidean::move_geometry();
        let mut e = one_node(&node, &inputs, &[0]);
        e.evaluate();
        let all = run(&node, &inputs);
        let late = format!(
            "{}\n{:?}",
            items(&[e.node_output_at(0, 0).clone(), e.node_output_at(0, 1).clone()]),
            e.messages().cloned().collect::<Vec<_>>()
        );
        prop_assert_eq!(late, all);
    }
}

/// A graph of one node whose inputs hold `inputs`, with the outputs `read` as named outputs.
fn one_node(node_type: &NodeType, inputs: &[DataTree], read: &[usize]) -> Evaluator {
    let inputs = node_type
        .resolve_inputs(None)
        .into_iter()
        .enumerate()
        .map(|(k, port)| PlanInput {
            value: inputs
                .get(k)
                .cloned()
                .or_else(|| port.default.clone().map(DataTree::from_value)),
            port,
            sources: Vec::new(),
            modifiers: Vec::new(),
        })
        .collect();
    let plan = Plan {
        nodes: vec![PlanNode {
            id: NodeId::from(node_type.id.as_str()),
            node_type: Arc::new(node_type.clone()),
            inputs,
            output_modifiers: Vec::new(),
            settings: Vec::new(),
            matching: Matching::Longest,
            disabled: false,
        }],
        order: vec![0],
        inputs: Vec::new(),
        outputs: read.iter().map(|&k| (format!("out{k}"), 0, k)).collect(),
    };
    let mut e = Evaluator::new(plan);
    e.set_threads(1).expect("one thread");
    e
}
