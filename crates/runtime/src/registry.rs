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

    /// Registered ids close to `id`, for "did you mean" hints, at most three, best first:
    /// - the ids of types whose display name or nickname is `id` in any case, or whose name
    ///   with spaces as underscores is the part of the id after the category (`"Divide Curve"`
    ///   → `curve.divide_curve`);
    /// - ids within an edit distance of 3, closest first;
    /// - ids that start with `id` (`vector.dot` → `vector.dot_product`) or whose part after
    ///   the category is `id` (`dot_product` → `vector.dot_product`), in registration order.
    pub fn suggestions(&self, id: &str) -> Vec<&str> {
        const MAX: usize = 3;
        let wanted = id.trim();
        if wanted.is_empty() {
            return Vec::new();
        }
        let snake = wanted.to_lowercase().replace([' ', '-'], "_");
        let tail = |t: &NodeType| t.id.rsplit('.').next().unwrap_or(&t.id).to_owned();
        let named = self.types.iter().filter(|t| {
            t.name.eq_ignore_ascii_case(wanted)
                || t.nickname == wanted
                || tail(t).eq_ignore_ascii_case(&snake)
        });
        let mut scored: Vec<(usize, &NodeType)> = self
            .types
            .iter()
            .map(|t| (edit_distance(&t.id, wanted), t))
            .filter(|(d, _)| *d <= 3)
            .collect();
        scored.sort_by(|a, b| a.0.cmp(&b.0).then_with(|| a.1.id.cmp(&b.1.id)));
        let prefixed = self
            .types
            .iter()
            .filter(|t| t.id.starts_with(wanted) || tail(t) == wanted);
        let mut out: Vec<&str> = Vec::new();
        for t in named
            .chain(scored.into_iter().map(|(_, t)| t))
            .chain(prefixed)
        {
            if out.len() == MAX {
                break;
            }
            if !out.contains(&t.id.as_str()) {
                out.push(&t.id);
            }
        }
        out
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

    fn registry() -> NodeRegistry {
        let mut registry = NodeRegistry::new();
        for (id, name, nick) in [
            ("vector.dot_product", "Dot Product", "Dot"),
            ("curve.divide_curve", "Divide Curve", "Divide"),
            ("maths.addition", "Addition", "A+B"),
        ] {
            registry.register(NodeType::new(id, name, nick, "Test"));
        }
        registry
    }

    #[test]
    fn suggests_close_ids_then_prefixes() {
        let r = registry();
        assert_eq!(r.suggestions("maths.additon"), ["maths.addition"]);
        assert_eq!(r.suggestions("vector.dot"), ["vector.dot_product"]);
        assert_eq!(r.suggestions("dot_product"), ["vector.dot_product"]);
        assert!(r.suggestions("surface.loft").is_empty());
        assert!(r.suggestions("").is_empty());
    }

    #[test]
    fn suggests_the_id_for_a_display_name_or_nickname() {
        let r = registry();
        assert_eq!(r.suggestions("Divide Curve"), ["curve.divide_curve"]);
        assert_eq!(r.suggestions("divide curve"), ["curve.divide_curve"]);
        assert_eq!(r.suggestions("A+B"), ["maths.addition"]);
        assert_eq!(r.suggestions("Dot Product"), ["vector.dot_product"]);
    }
}
