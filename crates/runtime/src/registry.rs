//! The registry of node types a graph may use.

use std::collections::HashMap;

use crate::NodeType;

/// The node types known to a host, by id. Built explicitly (there is no global registry):
/// `let mut r = NodeRegistry::new(); locus_nodes::register(&mut r);`.
#[derive(Debug, Default, Clone)]
pub struct NodeRegistry {
    types: Vec<NodeType>,
    by_id: HashMap<String, usize>,
    by_gh_guid: HashMap<String, usize>,
}

impl NodeRegistry {
    /// An empty registry.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a node type, replacing any type with the same id.
    pub fn register(&mut self, node_type: NodeType) {
        let index = match self.by_id.get(&node_type.id) {
            Some(&i) => {
                self.by_gh_guid.retain(|_, j| *j != i);
                i
            }
            None => {
                self.by_id.insert(node_type.id.clone(), self.types.len());
                self.types.len()
            }
        };
        for guid in &node_type.gh_guids {
            self.by_gh_guid.insert(guid.clone(), index);
        }
        if index == self.types.len() {
            self.types.push(node_type);
        } else {
            self.types[index] = node_type;
        }
    }

    /// The node type that stands for the Grasshopper component with this type GUID (any case).
    pub fn by_gh_guid(&self, guid: &str) -> Option<&NodeType> {
        self.by_gh_guid
            .get(&guid.trim().to_ascii_lowercase())
            .map(|&i| &self.types[i])
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_node_types_by_grasshopper_guid_in_any_case() {
        let mut registry = NodeRegistry::new();
        registry.register(
            NodeType::new("maths.a", "A", "A", "Maths")
                .gh_guid("A0D62394-A118-422D-ABB3-6AF115C75B25")
                .gh_guid("9c85271f-89fa-4e9f-9f4a-d75802120ccc"),
        );
        let a = registry.by_gh_guid("a0d62394-a118-422d-abb3-6af115c75b25");
        assert_eq!(a.map(|t| t.id.as_str()), Some("maths.a"));
        let old = registry.by_gh_guid(" 9C85271F-89FA-4E9F-9F4A-D75802120CCC ");
        assert_eq!(old.map(|t| t.id.as_str()), Some("maths.a"));
        assert!(
            registry
                .by_gh_guid("00000000-0000-0000-0000-000000000000")
                .is_none()
        );
        // Replacing a type drops the GUIDs it no longer declares.
        registry.register(
            NodeType::new("maths.a", "A", "A", "Maths")
                .gh_guid("9c85271f-89fa-4e9f-9f4a-d75802120ccc"),
        );
        assert!(
            registry
                .by_gh_guid("a0d62394-a118-422d-abb3-6af115c75b25")
                .is_none()
        );
        assert_eq!(registry.len(), 1);
    }
}
