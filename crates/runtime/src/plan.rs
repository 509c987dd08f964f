//! The checked, resolved form of a graph that the evaluator runs.

use std::sync::Arc;

use crate::{DataTree, Matching, Modifier, NodeId, NodeType, Port, Value};

/// A graph that passed checking: every id, port and value resolved, nodes in evaluation order.
#[derive(Clone, Debug)]
pub struct Plan {
    /// The nodes, in the graph file's order; indices into this vector identify nodes.
    pub nodes: Vec<PlanNode>,
    /// Node indices in topological order (sources before the nodes they feed), ties broken by
    /// file order.
    pub order: Vec<usize>,
    /// Named inputs: name → (node index, input index).
    pub inputs: Vec<(String, usize, usize)>,
    /// Named outputs: name → (node index, output index).
    pub outputs: Vec<(String, usize, usize)>,
}

/// One node of a [`Plan`].
#[derive(Clone, Debug)]
pub struct PlanNode {
    /// The node's id in the graph.
    pub id: NodeId,
    /// The node's type.
    pub node_type: Arc<NodeType>,
    /// The node's input ports (variable inputs resolved).
    pub inputs: Vec<PlanInput>,
    /// Per output, its modifiers in application order (applied to the output's tree when the
    /// node has run); empty, or shorter than the outputs, for outputs without modifiers.
    pub output_modifiers: Vec<Vec<Modifier>>,
    /// The node's settings with defaults filled in.
    pub settings: Vec<(String, Value)>,
    /// How item inputs are matched.
    pub matching: Matching,
    /// A disabled node outputs nothing.
    pub disabled: bool,
}

/// One input of a [`PlanNode`].
#[derive(Clone, Debug)]
pub struct PlanInput {
    /// The port.
    pub port: Port,
    /// The outputs wired into it, as (node index, output index), in wire order.
    pub sources: Vec<(usize, usize)>,
    /// The value given in the graph (persistent data), used when no wire is connected; else
    /// the port's default, if any.
    pub value: Option<DataTree>,
    /// The modifiers, in application order.
    pub modifiers: Vec<Modifier>,
}

impl PlanNode {
    /// The modifiers of output `k`, in application order (none for most outputs).
    pub fn output_modifiers(&self, k: usize) -> &[Modifier] {
        self.output_modifiers.get(k).map_or(&[], Vec::as_slice)
    }

    /// The index of the input marked principal, if any.
    pub fn principal_input(&self) -> Option<usize> {
        self.inputs
            .iter()
            .position(|i| i.modifiers.contains(&Modifier::Principal))
    }
}
