//! The graph document: nodes, wires, values, named inputs and outputs, as stored in a file.
//!
//! This is the *unchecked* form: ids and port names are plain strings as the user wrote them,
//! and values are literal texts that are only interpreted once the port's type is known.
//! Checking (see `check`) turns a [`Graph`] into a list of diagnostics or a runnable plan.

use crate::{Level, Matching, Message};

/// The version of the graph file format written by this build.
pub const FORMAT_VERSION: u32 = 1;

/// A node-graph document.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Graph {
    /// The format version the file declares.
    pub format: u32,
    /// A short name.
    pub name: String,
    /// What the graph computes, for users.
    pub description: String,
    /// The nodes, in file order (which is also the tie-break order of evaluation).
    pub nodes: Vec<GraphNode>,
    /// The wires, in file order (several wires into one input are merged in this order).
    pub wires: Vec<Wire>,
    /// Named inputs: setting one replaces the value of a node's input.
    pub inputs: Vec<GraphInput>,
    /// Named outputs: the data of a node's output.
    pub outputs: Vec<GraphOutput>,
    /// Expected output trees for regression tests (`locus test`), by output name.
    pub expected: Vec<(String, Literal)>,
    /// Runtime messages a regression test expects (`locus test` fails a graph whose run
    /// reports an error that none of these declares, and one whose run lacks one of these).
    pub expected_messages: Vec<ExpectedMessage>,
}

/// A runtime message a graph declares as expected: the node, the level and a text pattern.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExpectedMessage {
    /// The node that reports it.
    pub node: NodeId,
    /// Its level.
    pub level: Level,
    /// A pattern the message's text contains; `*` stands for any run of characters.
    pub text: String,
}

impl ExpectedMessage {
    /// Whether `message` is this one: same node and level, and the text matches the pattern.
    pub fn matches(&self, message: &Message) -> bool {
        message.node == self.node
            && message.level == self.level
            && text_matches(&self.text, &message.text)
    }
}

/// Whether `text` contains `pattern`, where `*` in the pattern stands for any run of
/// characters (so `"radius * is not positive"` matches `"circle radius -1 is not positive"`).
pub fn text_matches(pattern: &str, text: &str) -> bool {
    let mut rest = text;
    let mut pieces = pattern.split('*').filter(|p| !p.is_empty());
    // The first piece may start anywhere, and so may every later one after its predecessor:
    // the pattern is unanchored at both ends.
    pieces.all(|piece| match rest.find(piece) {
        Some(at) => {
            rest = &rest[at + piece.len()..];
            true
        }
        None => false,
    })
}

/// The id of a node in a graph: unique, stable and readable (`sphere_1`).
#[derive(Clone, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct NodeId(pub String);

impl std::fmt::Display for NodeId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl From<&str> for NodeId {
    fn from(s: &str) -> Self {
        Self(s.to_owned())
    }
}

/// A value as written in a graph file: RON text interpreted against the port's type when the
/// graph is checked (`0.5`, `(1, 2, 3)`, `[1, 2, 3]`, `{"{0;1}": [1, 2]}`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Literal(pub String);

/// A port modifier of an input (Grasshopper's right-click modifiers).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Modifier {
    /// All items on one branch `{0}`.
    Flatten,
    /// Every item on its own branch.
    Graft,
    /// Remove path indices shared by all branches.
    Simplify,
    /// Reverse the items of every branch.
    Reverse,
    /// This input decides the output paths.
    Principal,
    /// Negate booleans.
    Invert,
    /// The angle is given in degrees.
    Degrees,
    /// Reparameterize curves and surfaces to the domain 0 to 1.
    Reparameterize,
}

impl Modifier {
    /// Every modifier, in the order they are applied: structure first (flatten, graft,
    /// simplify), then reverse, then per-item changes (invert, degrees, reparameterize).
    pub const ALL: [Modifier; 8] = [
        Modifier::Flatten,
        Modifier::Graft,
        Modifier::Simplify,
        Modifier::Reverse,
        Modifier::Principal,
        Modifier::Invert,
        Modifier::Degrees,
        Modifier::Reparameterize,
    ];

    /// Whether the modifier can be set on an output (Grasshopper's output parameters have
    /// every modifier but principal, which chooses among inputs, and degrees, which says what
    /// unit an input's angles are in).
    pub fn applies_to_outputs(self) -> bool {
        !matches!(self, Modifier::Principal | Modifier::Degrees)
    }

    /// The name used in graph files (`flatten`, `graft`, …).
    pub fn name(self) -> &'static str {
        match self {
            Modifier::Flatten => "flatten",
            Modifier::Graft => "graft",
            Modifier::Simplify => "simplify",
            Modifier::Reverse => "reverse",
            Modifier::Principal => "principal",
            Modifier::Invert => "invert",
            Modifier::Degrees => "degrees",
            Modifier::Reparameterize => "reparameterize",
        }
    }

    /// The modifier with this name.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }
}

/// One node of a graph.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GraphNode {
    /// The node's id.
    pub id: NodeId,
    /// The node type's id (`vector.dot_product`).
    pub node_type: String,
    /// For node types with variable inputs: the names of this node's inputs.
    pub input_names: Option<Vec<String>>,
    /// For node types with variable outputs: the names of this node's outputs (after the
    /// type's fixed outputs).
    pub output_names: Option<Vec<String>>,
    /// Values of unconnected inputs, by port name (Grasshopper's persistent data).
    pub values: Vec<(String, Literal)>,
    /// Node-level settings by name (the Expression node's formula).
    pub settings: Vec<(String, Literal)>,
    /// Input modifiers, by port name.
    pub modifiers: Vec<(String, Vec<Modifier>)>,
    /// Output modifiers, by port name: applied to the output's tree when the node has run, so
    /// that every wire and named output reading it sees the modified tree.
    pub output_modifiers: Vec<(String, Vec<Modifier>)>,
    /// How item inputs are matched.
    pub matching: Matching,
    /// A disabled node outputs nothing.
    pub disabled: bool,
    /// For a sub-graph node (type [`SUBGRAPH_TYPE`]): the graph it runs.
    pub subgraph: Option<SubGraph>,
}

/// The node type of sub-graph nodes: a node of this type runs another graph, whose named
/// inputs and outputs are its ports (`docs/graph-format.md`, "Sub-graphs").
pub const SUBGRAPH_TYPE: &str = "graph";

/// The body of a sub-graph node.
#[derive(Clone, Debug, PartialEq)]
pub enum SubGraph {
    /// A graph file, relative to the directory of the file that includes it (`path:`).
    Path(String),
    /// A graph written inside the node (`graph: (…)`).
    Inline(Box<Graph>),
}

/// A reference to a port of a node: `node.port` in files.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash)]
pub struct PortRef {
    /// The node id.
    pub node: NodeId,
    /// The port's nickname or name.
    pub port: String,
}

impl std::fmt::Display for PortRef {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}.{}", self.node, self.port)
    }
}

/// A wire from an output to an input.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Wire {
    /// The output the data comes from.
    pub from: PortRef,
    /// The input it goes to.
    pub to: PortRef,
}

/// A named graph input: setting it replaces the value of input `port` of `node`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GraphInput {
    /// The name hosts and `--set` use.
    pub name: String,
    /// The input it sets.
    pub target: PortRef,
}

/// A named graph output: the data of output `port` of `node`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GraphOutput {
    /// The name hosts and the CLI print.
    pub name: String,
    /// The output it reads.
    pub source: PortRef,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn patterns_match_substrings_with_wildcards() {
        assert!(text_matches("radius", "circle radius -1 is not positive"));
        assert!(text_matches(
            "radius * positive",
            "circle radius -1 is not positive"
        ));
        assert!(text_matches("", "anything"));
        assert!(text_matches("*", ""));
        assert!(!text_matches(
            "positive * radius",
            "circle radius -1 is not positive"
        ));
        assert!(!text_matches(
            "radius 2",
            "circle radius -1 is not positive"
        ));
        assert!(text_matches("a*a", "aa"));
        assert!(!text_matches("a*a", "a"));
    }

    #[test]
    fn expected_messages_match_node_level_and_text() {
        let expected = ExpectedMessage {
            node: "d".into(),
            level: Level::Error,
            text: "by zero".to_owned(),
        };
        let mut m = Message {
            node: "d".into(),
            level: Level::Error,
            path: None,
            index: None,
            text: "division by zero".to_owned(),
        };
        assert!(expected.matches(&m));
        m.level = Level::Warning;
        assert!(!expected.matches(&m));
        m.level = Level::Error;
        m.node = "e".into();
        assert!(!expected.matches(&m));
    }
}
