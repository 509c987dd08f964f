//! Calling one node directly on input trees, without a graph: for tests and for hosts that
//! want a single component.

use std::sync::Arc;

use crate::{
    DataTree, Evaluator, Matching, Message, NodeId, NodeType, Plan, PlanInput, PlanNode, Value,
};

/// What a node call produced.
#[derive(Clone, Debug, PartialEq)]
pub struct NodeCallResult {
    /// One tree per output port.
    pub outputs: Vec<DataTree>,
    /// The runtime messages.
    pub messages: Vec<Message>,
}

/// A call of one node on given input trees, built step by step.
///
/// ```
/// use locus_runtime::{DataTree, DataType, NodeCall, NodeType, Port};
/// let add = NodeType::new("maths.addition", "Addition", "A+B", "Maths")
///     .input(Port::new("A", "A", DataType::Number))
///     .input(Port::new("B", "B", DataType::Number))
///     .output(Port::new("Result", "R", DataType::Number))
///     .solve(|s| {
///         let (a, b) = (*s.item::<f64>(0)?, *s.item::<f64>(1)?);
///         s.set(0, a + b);
///         Ok(())
///     });
/// let r = NodeCall::new(&add)
///     .input(DataTree::from_list(vec![1.0, 2.0]))
///     .input(DataTree::from_item(10.0))
///     .run();
/// assert_eq!(r.outputs[0], DataTree::from_list(vec![11.0, 12.0]));
/// ```
#[derive(Debug)]
pub struct NodeCall<'a> {
    node_type: &'a NodeType,
    input_names: Option<Vec<String>>,
    output_names: Option<Vec<String>>,
    inputs: Vec<Option<DataTree>>,
    settings: Vec<(String, Value)>,
    matching: Matching,
}

impl<'a> NodeCall<'a> {
    /// A call of `node_type` with no inputs given yet (unset inputs take their defaults).
    pub fn new(node_type: &'a NodeType) -> Self {
        Self {
            node_type,
            input_names: None,
            output_names: None,
            inputs: Vec::new(),
            settings: Vec::new(),
            matching: Matching::Longest,
        }
    }

    /// Gives the next input a tree.
    pub fn input(mut self, tree: DataTree) -> Self {
        self.inputs.push(Some(tree));
        self
    }

    /// Leaves the next input unset (it takes its default, or has no data).
    pub fn skip_input(mut self) -> Self {
        self.inputs.push(None);
        self
    }

    /// Names the inputs of a node type with variable inputs.
    pub fn input_names(mut self, names: &[&str]) -> Self {
        self.input_names = Some(names.iter().map(|s| (*s).to_owned()).collect());
        self
    }

    /// Names the outputs of a node type with variable outputs (after its fixed outputs).
    pub fn output_names(mut self, names: &[&str]) -> Self {
        self.output_names = Some(names.iter().map(|s| (*s).to_owned()).collect());
        self
    }

    /// Sets a node setting.
    pub fn setting(mut self, name: &str, value: Value) -> Self {
        self.settings.retain(|(n, _)| n != name);
        self.settings.push((name.to_owned(), value));
        self
    }

    /// Sets the matching mode.
    pub fn matching(mut self, matching: Matching) -> Self {
        self.matching = matching;
        self
    }

    /// Runs the node (on the calling thread) and returns its outputs and messages.
    pub fn run(self) -> NodeCallResult {
        let ports = self.node_type.resolve_inputs(self.input_names.as_deref());
        let inputs = ports
            .into_iter()
            .enumerate()
            .map(|(k, port)| {
                let value = self
                    .inputs
                    .get(k)
                    .cloned()
                    .flatten()
                    .or_else(|| port.default.clone().map(DataTree::from_value));
                PlanInput {
                    port,
                    sources: Vec::new(),
                    value,
                    modifiers: Vec::new(),
                }
            })
            .collect();
        let mut settings: Vec<(String, Value)> = self
            .node_type
            .settings
            .iter()
            .filter_map(|s| s.default.clone().map(|d| (s.name.clone(), d)))
            .collect();
        for (name, value) in self.settings {
            settings.retain(|(n, _)| *n != name);
            settings.push((name, value));
        }
        let mut node_type = self.node_type.clone();
        node_type.outputs = node_type.resolve_outputs(self.output_names.as_deref());
        let n_outputs = node_type.outputs.len();
        let plan = Plan {
            nodes: vec![PlanNode {
                id: NodeId::from(self.node_type.id.as_str()),
                node_type: Arc::new(node_type),
                inputs,
                settings,
                matching: self.matching,
                disabled: false,
            }],
            order: vec![0],
            inputs: Vec::new(),
            outputs: Vec::new(),
        };
        let mut evaluator = Evaluator::new(plan);
        // A single thread keeps node tests deterministic and free of pool start-up.
        let _ = evaluator.set_threads(1);
        evaluator.keep_all_outputs();
        evaluator.evaluate();
        let outputs = (0..n_outputs)
            .map(|k| evaluator.node_output_at(0, k).clone())
            .collect();
        NodeCallResult {
            outputs,
            messages: evaluator.messages().cloned().collect(),
        }
    }
}
