//! Node types: what a node is called, which ports it has and how it computes.
//!
//! A node type is declared once, with a builder:
//!
//! ```
//! use locus_runtime::{Access, DataType, NodeType, Port};
//! let dot = NodeType::new("vector.dot_product", "Dot Product", "DProd", "Vector")
//!     .description("Computes the dot product of two vectors.")
//!     .input(Port::new("Vector A", "A", DataType::Vector).doc("The first vector."))
//!     .input(Port::new("Vector B", "B", DataType::Vector).doc("The second vector."))
//!     .output(Port::new("Dot product", "D", DataType::Number).doc("A·B."))
//!     .solve(|s| {
//!         let a: locus_kernel::Vector3 = *s.item(0)?;
//!         let b: locus_kernel::Vector3 = *s.item(1)?;
//!         s.set(0, a.dot(b));
//!         Ok(())
//!     });
//! assert_eq!(dot.inputs.len(), 2);
//! ```

use std::any::Any;
use std::fmt;
use std::sync::Arc;

use crate::{DataType, Item, Solve, Value};

/// How a port receives its data in one call of the node's solve function
/// (Grasshopper's `GH_ParamAccess`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Access {
    /// One item per call; the runtime iterates over items with the node's [`Matching`].
    Item,
    /// One whole branch per call.
    List,
    /// The whole tree in one call.
    Tree,
}

impl Access {
    /// The lower-case name used in docs and the CLI (`item`, `list`, `tree`).
    pub fn name(self) -> &'static str {
        match self {
            Access::Item => "item",
            Access::List => "list",
            Access::Tree => "tree",
        }
    }
}

/// How item-access inputs of different lengths are paired (Grasshopper's data matching).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Matching {
    /// Shorter lists repeat their last item (the default).
    #[default]
    Longest,
    /// Stop at the end of the shortest list.
    Shortest,
    /// Every combination; the first input varies fastest.
    Cross,
}

/// A declared input or output of a node type.
#[derive(Clone, Debug, PartialEq)]
pub struct Port {
    /// Grasshopper's full port name, such as `Point A`.
    pub name: String,
    /// Grasshopper's nickname, such as `A`: the identifier used in graph files.
    pub nickname: String,
    /// What the port means, with units and default, for the node catalogue.
    pub description: String,
    /// The type items are cast to on the way in (inputs) or that the node writes (outputs).
    pub data_type: DataType,
    /// Item, list or tree access.
    pub access: Access,
    /// Whether an input may be left without data (the node still runs).
    pub optional: bool,
    /// The value an unconnected input takes when the graph gives none.
    pub default: Option<Value>,
    /// A static constraint on the items of literal values given to this input (a radius is
    /// positive), checked before the graph runs; see [`Port::constraint`].
    pub constraint: Option<ValueConstraint>,
}

/// A check of one item of a literal value, known before running: `Err` says why the item is
/// not acceptable (`radius -1 is not positive`). Wired data is checked by the node as it runs.
#[derive(Clone)]
pub struct ValueConstraint(pub Arc<ConstraintFn>);

/// The function behind a [`ValueConstraint`].
pub type ConstraintFn = dyn Fn(&Value) -> Result<(), String> + Send + Sync;

impl ValueConstraint {
    /// Checks one item.
    ///
    /// # Errors
    /// Why the item does not meet the constraint.
    pub fn check(&self, value: &Value) -> Result<(), String> {
        (self.0)(value)
    }
}

impl fmt::Debug for ValueConstraint {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("ValueConstraint")
    }
}

impl PartialEq for ValueConstraint {
    /// Constraints are equal when they are the same function.
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Port {
    /// An item-access, required port without default.
    pub fn new(name: &str, nickname: &str, data_type: DataType) -> Self {
        Self {
            name: name.to_owned(),
            nickname: nickname.to_owned(),
            description: String::new(),
            data_type,
            access: Access::Item,
            optional: false,
            default: None,
            constraint: None,
        }
    }

    /// Declares a static constraint on the items of literal values given to this input:
    /// checking reports an item that fails it as a bad value, naming the node, port and item,
    /// before anything runs.
    pub fn constraint(
        mut self,
        check: impl Fn(&Value) -> Result<(), String> + Send + Sync + 'static,
    ) -> Self {
        self.constraint = Some(ValueConstraint(Arc::new(check)));
        self
    }

    /// Sets the description.
    pub fn doc(mut self, description: &str) -> Self {
        self.description = description.to_owned();
        self
    }

    /// Makes the port list access.
    pub fn list(mut self) -> Self {
        self.access = Access::List;
        self
    }

    /// Makes the port tree access.
    pub fn tree(mut self) -> Self {
        self.access = Access::Tree;
        self
    }

    /// Makes the input optional.
    pub fn optional(mut self) -> Self {
        self.optional = true;
        self
    }

    /// Gives the input a default value (used when it has neither wire nor value).
    pub fn default_value(mut self, value: impl Item) -> Self {
        self.default = Some(value.into_value());
        self
    }

    /// Whether `id` names this port: the nickname (exactly) or the full name (ignoring case).
    pub fn is_named(&self, id: &str) -> bool {
        self.nickname == id || self.name.eq_ignore_ascii_case(id)
    }
}

/// The template for the inputs of a node with a variable number of inputs (Expression's
/// variables, Merge's streams). A graph names the inputs of each such node.
#[derive(Clone, Debug, PartialEq)]
pub struct VariableInputs {
    /// The port every variable input is made from; its name and nickname are replaced.
    pub template: Port,
    /// The input names a new node starts with, such as `["x", "y"]`.
    pub default_names: Vec<String>,
}

/// The template for the outputs of a node with a variable number of outputs (a script's
/// results). A graph names the outputs of each such node.
#[derive(Clone, Debug, PartialEq)]
pub struct VariableOutputs {
    /// The port every variable output is made from; its name and nickname are replaced.
    pub template: Port,
    /// The outputs that keep their declaration whatever the graph names (a script's `out`,
    /// which carries what it printed), and stay first.
    pub fixed: Vec<Port>,
    /// The output names a new node starts with, after the fixed ones.
    pub default_names: Vec<String>,
}

/// A node-level setting that is not a port, such as the Expression node's formula.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    /// The name used in graph files (`expression`).
    pub name: String,
    /// What it means.
    pub description: String,
    /// The type of its value.
    pub data_type: DataType,
    /// The value when the graph gives none.
    pub default: Option<Value>,
}

/// Why one call of a solve function failed. The runtime adds the node, tree path and item
/// index to the message and leaves a null (or empty branch) in the outputs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NodeError(pub String);

impl fmt::Display for NodeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for NodeError {}

impl From<String> for NodeError {
    fn from(s: String) -> Self {
        Self(s)
    }
}

impl From<&str> for NodeError {
    fn from(s: &str) -> Self {
        Self(s.to_owned())
    }
}

impl From<locus_kernel::Error> for NodeError {
    fn from(e: locus_kernel::Error) -> Self {
        Self(e.to_string())
    }
}

/// The function that computes a node: called once per iteration (item and list access) or
/// once per evaluation (tree access only).
pub type SolveFn = Arc<dyn Fn(&mut Solve<'_>) -> Result<(), NodeError> + Send + Sync>;

/// Prepared per-node state, computed once per evaluation from the node's settings (for example
/// a parsed formula), and shared by every iteration.
pub type Prepared = Arc<dyn Any + Send + Sync>;

/// The function that prepares per-node state from settings and input names.
pub type PrepareFn = Arc<dyn Fn(&NodeConfig<'_>) -> Result<Prepared, NodeError> + Send + Sync>;

/// What a prepare function sees of a node instance.
#[derive(Debug)]
pub struct NodeConfig<'a> {
    /// The node's settings, with defaults filled in.
    pub settings: &'a [(String, Value)],
    /// The node's input ports (after variable inputs are resolved).
    pub inputs: &'a [Port],
}

impl NodeConfig<'_> {
    /// The value of a setting.
    pub fn setting(&self, name: &str) -> Option<&Value> {
        self.settings
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v)
    }
}

/// A node type: identity, documentation, ports and behaviour.
#[derive(Clone)]
pub struct NodeType {
    /// The stable identifier used in graph files, `category.name` (`vector.dot_product`).
    pub id: String,
    /// Grasshopper's display name (`Dot Product`).
    pub name: String,
    /// Grasshopper's nickname (`DProd`).
    pub nickname: String,
    /// The category (`Vector`), as in Grasshopper's tabs.
    pub category: String,
    /// The subcategory (`Vector`, `Point`, …), as in Grasshopper's panels.
    pub subcategory: String,
    /// What the node does, for users.
    pub description: String,
    /// The type GUIDs of the Grasshopper components this node type stands for, lower-case
    /// (old and new versions of a component share its name but not its GUID). Empty when the
    /// node has no Grasshopper counterpart: it is then not importable from Grasshopper files.
    pub gh_guids: Vec<String>,
    /// The inputs, in order.
    pub inputs: Vec<Port>,
    /// The outputs, in order.
    pub outputs: Vec<Port>,
    /// Present when the inputs are variable; `inputs` then holds the default set.
    pub variable_inputs: Option<VariableInputs>,
    /// Present when the outputs are variable; `outputs` then holds the default set.
    pub variable_outputs: Option<VariableOutputs>,
    /// Node-level settings.
    pub settings: Vec<Setting>,
    /// The solve function.
    pub solve: SolveFn,
    /// The optional prepare function. Checking runs it too (it sees only settings and input
    /// names, which are known before running), so a failure is a check error with the file
    /// position rather than a runtime message.
    pub prepare: Option<PrepareFn>,
    /// The item function behind `solve`, when the type was declared with `lift1`/`lift2`/
    /// `lift3`: the runtime runs it as a loop over typed columns.
    pub(crate) lift: Option<crate::evaluation::lift::Lift>,
    /// Loops over typed columns for data of concrete types on generic ports, tried in order
    /// before the solve function (`fast_path2`).
    pub(crate) fast_paths: Vec<crate::evaluation::lift::Lift>,
}

impl fmt::Debug for NodeType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("NodeType")
            .field("id", &self.id)
            .field("name", &self.name)
            .field("inputs", &self.inputs)
            .field("outputs", &self.outputs)
            .finish_non_exhaustive()
    }
}

impl NodeType {
    /// A node type with no ports that does nothing; add ports and a solve function with the
    /// builder methods.
    pub fn new(id: &str, name: &str, nickname: &str, category: &str) -> Self {
        Self {
            id: id.to_owned(),
            name: name.to_owned(),
            nickname: nickname.to_owned(),
            category: category.to_owned(),
            subcategory: String::new(),
            description: String::new(),
            gh_guids: Vec::new(),
            inputs: Vec::new(),
            outputs: Vec::new(),
            variable_inputs: None,
            variable_outputs: None,
            settings: Vec::new(),
            solve: Arc::new(|_| Ok(())),
            prepare: None,
            lift: None,
            fast_paths: Vec::new(),
        }
    }

    /// Sets the subcategory.
    pub fn subcategory(mut self, subcategory: &str) -> Self {
        self.subcategory = subcategory.to_owned();
        self
    }

    /// Sets the description.
    pub fn description(mut self, description: &str) -> Self {
        self.description = description.to_owned();
        self
    }

    /// Declares a Grasshopper component type GUID this node type stands for (repeat for old and
    /// new versions of the component). Stored lower-case.
    pub fn gh_guid(mut self, guid: &str) -> Self {
        self.gh_guids.push(guid.trim().to_ascii_lowercase());
        self
    }

    /// Adds an input.
    pub fn input(mut self, port: Port) -> Self {
        self.inputs.push(port);
        self
    }

    /// Adds an output.
    pub fn output(mut self, port: Port) -> Self {
        self.outputs.push(port);
        self
    }

    /// Makes the inputs variable: each graph node names its inputs, all made from `template`;
    /// `default_names` are the inputs of a node that names none.
    pub fn variable_inputs(mut self, template: Port, default_names: &[&str]) -> Self {
        self.inputs = default_names
            .iter()
            .map(|n| variable_port(&template, n))
            .collect();
        self.variable_inputs = Some(VariableInputs {
            template,
            default_names: default_names.iter().map(|s| (*s).to_owned()).collect(),
        });
        self
    }

    /// Makes the outputs variable: each graph node names its outputs, all made from
    /// `template`, after the `fixed` outputs (which a graph does not name); `default_names` are
    /// the outputs of a node that names none. Outputs added before are the fixed ones.
    pub fn variable_outputs(mut self, template: Port, default_names: &[&str]) -> Self {
        let fixed = std::mem::take(&mut self.outputs);
        self.outputs = fixed.clone();
        self.outputs
            .extend(default_names.iter().map(|n| variable_port(&template, n)));
        self.variable_outputs = Some(VariableOutputs {
            template,
            fixed,
            default_names: default_names.iter().map(|s| (*s).to_owned()).collect(),
        });
        self
    }

    /// Adds a setting.
    pub fn setting(
        mut self,
        name: &str,
        data_type: DataType,
        default: Option<Value>,
        description: &str,
    ) -> Self {
        self.settings.push(Setting {
            name: name.to_owned(),
            description: description.to_owned(),
            data_type,
            default,
        });
        self
    }

    /// Sets the solve function.
    pub fn solve(
        mut self,
        f: impl Fn(&mut Solve<'_>) -> Result<(), NodeError> + Send + Sync + 'static,
    ) -> Self {
        self.solve = Arc::new(f);
        self.lift = None;
        self
    }

    /// Sets the prepare function.
    pub fn prepare(
        mut self,
        f: impl Fn(&NodeConfig<'_>) -> Result<Prepared, NodeError> + Send + Sync + 'static,
    ) -> Self {
        self.prepare = Some(Arc::new(f));
        self
    }

    /// The input ports of a node instance that names `names` as its variable inputs (or the
    /// declared inputs when the type has fixed inputs or `names` is `None`).
    pub fn resolve_inputs(&self, names: Option<&[String]>) -> Vec<Port> {
        match (&self.variable_inputs, names) {
            (Some(var), Some(names)) => names
                .iter()
                .map(|n| variable_port(&var.template, n))
                .collect(),
            _ => self.inputs.clone(),
        }
    }

    /// The output ports of a node instance that names `names` as its variable outputs (the
    /// fixed outputs first), or the declared outputs when the type has fixed outputs or
    /// `names` is `None`.
    pub fn resolve_outputs(&self, names: Option<&[String]>) -> Vec<Port> {
        match (&self.variable_outputs, names) {
            (Some(var), Some(names)) => var
                .fixed
                .iter()
                .cloned()
                .chain(names.iter().map(|n| variable_port(&var.template, n)))
                .collect(),
            _ => self.outputs.clone(),
        }
    }

    /// The index of the input named `id` (nickname or full name).
    pub fn input_index(&self, id: &str) -> Option<usize> {
        self.inputs.iter().position(|p| p.is_named(id))
    }

    /// The index of the output named `id` (nickname or full name).
    pub fn output_index(&self, id: &str) -> Option<usize> {
        self.outputs.iter().position(|p| p.is_named(id))
    }

    /// Whether every input is tree access (or there are no inputs): the node solves once.
    pub fn solves_once(inputs: &[Port]) -> bool {
        inputs.iter().all(|p| p.access == Access::Tree)
    }
}

fn variable_port(template: &Port, name: &str) -> Port {
    let mut p = template.clone();
    p.name = name.to_owned();
    p.nickname = name.to_owned();
    p
}
