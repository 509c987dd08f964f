//! Cycles, the topological order, and the plan built from a checked graph.

use super::*;

impl<'a> Checker<'a> {
    pub(super) fn cycles(&mut self) {
        let n = self.graph.nodes.len();
        let mut g: DiGraph<(), ()> = DiGraph::with_capacity(n, self.edges.len());
        for _ in 0..n {
            g.add_node(());
        }
        let mut successors = vec![Vec::new(); n];
        for &(a, b) in &self.edges {
            g.add_edge(NodeIndex::new(a), NodeIndex::new(b), ());
            successors[a].push(b);
        }
        for s in &mut successors {
            s.sort_unstable();
            s.dedup();
        }
        // Kosaraju's algorithm walks with an explicit stack; petgraph's Tarjan recurses once per
        // node of a path and overflowed the stack on a 100,000-node chain.
        let mut components: Vec<Vec<usize>> = petgraph::algo::kosaraju_scc(&g)
            .into_iter()
            .map(|c| {
                let mut c: Vec<usize> = c.into_iter().map(NodeIndex::index).collect();
                c.sort_unstable();
                c
            })
            .filter(|c| c.len() > 1 || successors[c[0]].contains(&c[0]))
            .collect();
        components.sort();
        for component in components {
            let path = shortest_cycle(component[0], &component, &successors);
            let nodes = path
                .iter()
                .map(|&i| self.graph.nodes[i].id.0.clone())
                .collect();
            let at = self.node_offset(component[0]);
            self.error(DiagnosticKind::Cycle { nodes }, at);
        }
    }

    pub(super) fn plan(self, outputs: Vec<Option<(usize, usize)>>) -> Plan {
        let graph = self.graph;
        let mut shared: HashMap<&str, Arc<NodeType>> = HashMap::new();
        let mut nodes = Vec::with_capacity(graph.nodes.len());
        let mut values = self.values;
        let mut sources = self.sources;
        let mut modifiers = self.modifiers;
        for (i, (node, resolved)) in graph.nodes.iter().zip(self.resolved).enumerate() {
            // Checking passed, so every node type is known.
            let Some(r) = resolved else { continue };
            let node_type = if node.output_names.is_some() && r.node_type.variable_outputs.is_some()
            {
                // A node that names its outputs runs a type of its own with those outputs.
                let mut own = r.node_type.clone();
                own.outputs = r.outputs;
                Arc::new(own)
            } else {
                shared
                    .entry(r.node_type.id.as_str())
                    .or_insert_with(|| Arc::new(r.node_type.clone()))
                    .clone()
            };
            let inputs = r
                .inputs
                .into_iter()
                .enumerate()
                .map(|(k, port)| {
                    let value = values[i][k]
                        .take()
                        .or_else(|| port.default.clone().map(DataTree::from_value));
                    PlanInput {
                        port,
                        sources: std::mem::take(&mut sources[i][k]),
                        value,
                        modifiers: std::mem::take(&mut modifiers[i][k]),
                    }
                })
                .collect();
            let settings = node_type
                .settings
                .iter()
                .zip(&self.settings[i])
                .filter_map(|(s, given)| {
                    given
                        .clone()
                        .or_else(|| s.default.clone())
                        .map(|v| (s.name.clone(), v))
                })
                .collect();
            nodes.push(PlanNode {
                id: node.id.clone(),
                node_type,
                inputs,
                settings,
                matching: node.matching,
                disabled: node.disabled,
            });
        }
        let order = topological_order(nodes.len(), &self.edges);
        let inputs = graph
            .inputs
            .iter()
            .enumerate()
            .filter_map(|(n, input)| {
                self.named_targets
                    .iter()
                    .enumerate()
                    .find_map(|(i, targets)| {
                        let k = targets.iter().position(|t| *t == Some(n))?;
                        Some((input.name.clone(), i, k))
                    })
            })
            .collect();
        let outputs = graph
            .outputs
            .iter()
            .zip(outputs)
            .filter_map(|(o, r)| r.map(|(i, k)| (o.name.clone(), i, k)))
            .collect();
        Plan {
            nodes,
            order,
            inputs,
            outputs,
        }
    }
}

/// The shortest cycle through `start` within `component` (breadth-first, successors in index
/// order), as node indices with `start` first and last.
fn shortest_cycle(start: usize, component: &[usize], successors: &[Vec<usize>]) -> Vec<usize> {
    let mut parent: HashMap<usize, usize> = HashMap::new();
    let mut queue = VecDeque::from([start]);
    while let Some(a) = queue.pop_front() {
        for &b in &successors[a] {
            if component.binary_search(&b).is_err() {
                continue;
            }
            if b == start {
                let mut path = vec![start, a];
                let mut c = a;
                while let Some(&p) = parent.get(&c) {
                    path.push(p);
                    c = p;
                }
                path.reverse();
                return path;
            }
            if b != start && !parent.contains_key(&b) {
                parent.insert(b, a);
                queue.push_back(b);
            }
        }
    }
    // Unreachable for a strongly connected component; fall back to listing it.
    let mut path = component.to_vec();
    path.push(start);
    path
}

/// Kahn's algorithm with a min-heap: among the nodes whose sources are all placed, the one
/// earliest in the file goes first. Nodes on cycles (which checking rejects) are left out.
pub(crate) fn topological_order(n: usize, edges: &[(usize, usize)]) -> Vec<usize> {
    let mut successors = vec![Vec::new(); n];
    let mut in_degree = vec![0usize; n];
    for &(a, b) in edges {
        successors[a].push(b);
        in_degree[b] += 1;
    }
    let mut ready: BinaryHeap<Reverse<usize>> =
        (0..n).filter(|&i| in_degree[i] == 0).map(Reverse).collect();
    let mut order = Vec::with_capacity(n);
    while let Some(Reverse(i)) = ready.pop() {
        order.push(i);
        for &b in &successors[i] {
            in_degree[b] -= 1;
            if in_degree[b] == 0 {
                ready.push(Reverse(b));
            }
        }
    }
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn topological_order_breaks_ties_by_file_order() {
        // 3 → 1, 2 → 0; free nodes 4. Ready at start: 2, 3, 4 → take 2, then 0 becomes
        // ready and is earlier than 3.
        let order = topological_order(5, &[(3, 1), (2, 0)]);
        assert_eq!(order, [2, 0, 3, 1, 4]);
    }

    #[test]
    fn shortest_cycle_names_each_node_once() {
        let successors = vec![vec![1], vec![2], vec![0, 1]];
        assert_eq!(shortest_cycle(0, &[0, 1, 2], &successors), [0, 1, 2, 0]);
        let self_loop = vec![vec![0]];
        assert_eq!(shortest_cycle(0, &[0], &self_loop), [0, 0]);
    }
}
