//! The evaluator's tables of every node's ports, wires and outputs, each one flat array.
//!
//! Running a node reads its input ports, the outputs wired into it, whether a graph input
//! sets it and which of its outputs are wanted, and writes its outputs. Kept per node (a
//! vector each), every one of those is a separate heap block, and a graph too large for the
//! caches pays a cache miss for each of them on every node: a chain of 100,000 nodes cost
//! twice as much per node as one of 1,000 (issue 16, part 3). Here each is one array in node
//! order, so the nodes of a chain read neighbouring memory, which the processor fetches ahead.

use std::ops::Range;

use crate::{Plan, Port};

/// The flat tables of one plan (see the module docs).
#[derive(Debug)]
pub(super) struct Layout {
    /// Every node's input ports (as the solve function sees them), node after node: node `i`'s
    /// are `ports[port_start[i]..port_start[i + 1]]`.
    ports: Vec<Port>,
    port_start: Vec<usize>,
    /// For each input of each node (indexed as `ports`), the graph input that can set it.
    input_slot: Vec<Option<usize>>,
    /// The outputs wired into each input (indexed as `ports`), as (node, output) in wire
    /// order: input `j`'s are `sources[source_start[j]..source_start[j + 1]]`.
    sources: Vec<(usize, usize)>,
    source_start: Vec<usize>,
    /// Node `i`'s outputs are entries `out_start[i]..out_start[i + 1]` of the output tables.
    out_start: Vec<usize>,
    /// For each output (indexed as the output tables), whether a wire or a named output reads
    /// it (the others are computed only when a host asks for them).
    pub(super) wanted: Vec<bool>,
}

impl Layout {
    pub(super) fn new(plan: &Plan) -> Self {
        let n = plan.nodes.len();
        let mut ports = Vec::new();
        let mut port_start = Vec::with_capacity(n + 1);
        let mut sources = Vec::new();
        let mut source_start = Vec::new();
        let mut out_start = Vec::with_capacity(n + 1);
        let mut outputs = 0;
        for node in &plan.nodes {
            port_start.push(ports.len());
            out_start.push(outputs);
            outputs += node.node_type.outputs.len();
            for input in &node.inputs {
                ports.push(input.port.clone());
                source_start.push(sources.len());
                sources.extend_from_slice(&input.sources);
            }
        }
        port_start.push(ports.len());
        source_start.push(sources.len());
        out_start.push(outputs);
        let mut layout = Self {
            input_slot: vec![None; ports.len()],
            ports,
            port_start,
            sources,
            source_start,
            out_start,
            wanted: vec![false; outputs],
        };
        for (slot, &(_, node, port)) in plan.inputs.iter().enumerate() {
            if let Some(entry) = layout
                .input_index(node, port)
                .and_then(|j| layout.input_slot.get_mut(j))
            {
                // The first graph input naming a port wins.
                entry.get_or_insert(slot);
            }
        }
        let read = layout
            .sources
            .iter()
            .copied()
            .chain(plan.outputs.iter().map(|&(_, node, output)| (node, output)));
        let wanted: Vec<usize> = read
            .filter_map(|(node, output)| layout.output_index(node, output))
            .collect();
        for k in wanted {
            layout.wanted[k] = true;
        }
        layout
    }

    /// The flat index of input `k` of node `i`, if it has one.
    fn input_index(&self, i: usize, k: usize) -> Option<usize> {
        let start = *self.port_start.get(i)?;
        let end = *self.port_start.get(i + 1)?;
        Some(start + k).filter(|&j| j < end)
    }

    /// The input ports of node `i`.
    pub(super) fn ports(&self, i: usize) -> &[Port] {
        &self.ports[self.port_start[i]..self.port_start[i + 1]]
    }

    /// The graph input that can set input `k` of node `i`, if any.
    pub(super) fn input_slot(&self, i: usize, k: usize) -> Option<usize> {
        self.input_index(i, k).and_then(|j| self.input_slot[j])
    }

    /// The outputs wired into input `k` of node `i`, in wire order.
    pub(super) fn sources(&self, i: usize, k: usize) -> &[(usize, usize)] {
        self.input_index(i, k).map_or(&[], |j| {
            &self.sources[self.source_start[j]..self.source_start[j + 1]]
        })
    }

    /// Where node `i`'s outputs are in the output tables.
    pub(super) fn outputs(&self, i: usize) -> Range<usize> {
        self.out_start[i]..self.out_start[i + 1]
    }

    /// The index of output `k` of node `i` in the output tables, if it has one.
    pub(super) fn output_index(&self, i: usize, k: usize) -> Option<usize> {
        let start = *self.out_start.get(i)?;
        let end = *self.out_start.get(i + 1)?;
        Some(start + k).filter(|&j| j < end)
    }

    /// Which outputs of node `i` are wanted.
    pub(super) fn wanted(&self, i: usize) -> &[bool] {
        &self.wanted[self.outputs(i)]
    }
}
