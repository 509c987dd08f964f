//! The registry of node types a graph may use.

use std::collections::HashMap;

use crate::NodeType;

/// The node types known to a host, by id. Built explicitly (there is no global registry):
/// `let mut r = NodeRegistry::new(); locus_nodes::register(&mut r);`.
#[derive(Debug, Default, Clone)]
pub struct NodeRegistry {
    types: Vec<NodeType>,
    by_id: HashMap<String, usize>,
}

impl NodeRegistry {
    /// An empty registry.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a node type, replacing any type with the same id.
    pub fn register(&mut self, node_type: NodeType) {
        match self.by_id.get(&node_type.id) {
            Some(&i) => self.types[i] = node_type,
            None => {
                self.by_id.insert(node_type.id.clone(), self.types.len());
                self.types.push(node_type);
            }
        }
    }

    /// The node type with this id.
    pub fn get(&self, id: &str) -> Option<&NodeType> {
        self.by_id.get(id).map(|&i| &self.types[i])
    }

    /// Every node type, in registration order.
    pub fn iter(&self) -> impl Iterator<Item = &NodeType> {
        self.types.iter()
    }

    /// The number of node types.
    pub fn len(&self) -> usize {
        self.types.len()
    }

    /// Whether the registry is empty.
    pub fn is_empty(&self) -> bool {
        self.types.is_empty()
    }

    /// Ids close to `id` (same suffix or small edit distance), for "did you mean" hints.
    pub fn suggestions(&self, id: &str) -> Vec<&str> {
        let mut scored: Vec<(usize, &str)> = self
            .types
            .iter()
            .map(|t| (edit_distance(&t.id, id), t.id.as_str()))
            .filter(|(d, _)| *d <= 3)
            .collect();
        scored.sort();
        scored.into_iter().take(3).map(|(_, s)| s).collect()
    }
}

/// The Levenshtein distance between two strings.
pub(crate) fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = if ca == cb {
                prev
            } else {
                1 + prev.min(row[j]).min(row[j + 1])
            };
            prev = cur;
        }
    }
    row[b.len()]
}
