//! The view a solve function has of one iteration: typed inputs, outputs and messages.
//!
//! The runtime calls a node's solve function once per iteration (see `iterate`). Inputs are
//! already collected, modified and cast to the ports' types, so reading an item is an index
//! into a typed slice; outputs are pushed straight into typed columns.

use std::any::Any;

use crate::NodeError;
use crate::{Access, Branch, DataTree, Item, Level, Port, Prepared, TreePath, Value};

/// Where one input's data is for the current iteration.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Cursor<'a> {
    /// An item-access input: the branch and the item index (`None` when the branch is empty or
    /// missing).
    Item(Option<&'a Branch>, Option<usize>),
    /// A list-access input: the branch (`None` when missing).
    List(Option<&'a Branch>),
    /// A tree-access input.
    Tree(&'a DataTree),
}

/// What a solve call wrote to one output.
#[derive(Debug)]
pub(crate) struct OutputSink {
    pub(crate) access: Access,
    pub(crate) data_type: crate::DataType,
    /// Pieces of the output tree in the order they were produced; equal paths concatenate.
    pub(crate) pieces: Vec<(TreePath, Branch)>,
    /// Whether the current iteration set this output.
    pub(crate) set: bool,
    /// An upper bound of the items and branches set as lists and trees so far (for the item
    /// budget; item outputs are counted before the node runs).
    pub(crate) listed: usize,
    /// Nothing reads this output: what the node sets is dropped.
    pub(crate) skip: bool,
}

/// The context of one iteration: what the node reads and writes.
pub struct Solve<'a> {
    pub(crate) ports: &'a [Port],
    pub(crate) output_ports: &'a [Port],
    pub(crate) cursors: &'a [Cursor<'a>],
    pub(crate) sinks: &'a mut [OutputSink],
    pub(crate) messages: &'a mut Vec<(Level, Option<TreePath>, Option<usize>, String)>,
    pub(crate) settings: &'a [(String, Value)],
    pub(crate) prepared: Option<&'a Prepared>,
    pub(crate) path: &'a TreePath,
    pub(crate) index: Option<usize>,
    /// Whether list outputs get the iteration index appended to their path.
    pub(crate) append_index: bool,
}

impl std::fmt::Debug for Solve<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Solve")
            .field("path", &self.path)
            .field("index", &self.index)
            .finish_non_exhaustive()
    }
}

/// The items of a list-access input: typed, with nulls.
#[derive(Clone, Copy, Debug)]
pub struct ListView<'a, T> {
    items: &'a [T],
    branch: Option<&'a Branch>,
}

impl<'a, T: Item> ListView<'a, T> {
    /// The number of items, nulls included.
    pub fn len(&self) -> usize {
        self.items.len()
    }

    /// Whether the list has no items.
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// The item at `index`, `None` when null or past the end.
    pub fn get(&self, index: usize) -> Option<&'a T> {
        match self.branch {
            Some(b) if !b.is_null(index) => self.items.get(index),
            _ => None,
        }
    }

    /// The items in order, `None` for nulls.
    pub fn iter(&self) -> impl Iterator<Item = Option<&'a T>> + 'a {
        let branch = self.branch;
        self.items
            .iter()
            .enumerate()
            .map(move |(i, x)| match branch {
                Some(b) if b.is_null(i) => None,
                _ => Some(x),
            })
    }

    /// The non-null items in order.
    pub fn present(&self) -> impl Iterator<Item = &'a T> + 'a {
        self.iter().flatten()
    }

    /// The items as one slice when none is null.
    pub fn as_slice(&self) -> Option<&'a [T]> {
        match self.branch {
            Some(b) if b.has_nulls() => None,
            _ => Some(self.items),
        }
    }

    /// The branch the items come from, if any.
    pub fn branch(&self) -> Option<&'a Branch> {
        self.branch
    }
}

impl<'a> Solve<'a> {
    fn port_name(&self, input: usize) -> &str {
        self.ports.get(input).map_or("?", |p| p.nickname.as_str())
    }

    #[inline]
    fn cursor(&self, input: usize) -> Result<Cursor<'a>, NodeError> {
        match self.cursors.get(input) {
            Some(c) => Ok(*c),
            None => Err(Self::no_input(input)),
        }
    }

    #[cold]
    #[inline(never)]
    fn no_input(input: usize) -> NodeError {
        NodeError(format!("internal: the node has no input {input}"))
    }

    #[cold]
    #[inline(never)]
    fn no_item(&self, input: usize) -> NodeError {
        NodeError(format!("input {} has no item", self.port_name(input)))
    }

    #[cold]
    #[inline(never)]
    fn wrong_access(&self, input: usize, access: &str) -> NodeError {
        NodeError(format!(
            "internal: input {} is not {access} access",
            self.port_name(input)
        ))
    }

    /// The number of inputs (for nodes with variable inputs).
    pub fn input_count(&self) -> usize {
        self.ports.len()
    }

    /// The declaration of input `input`.
    pub fn input_port(&self, input: usize) -> Option<&Port> {
        self.ports.get(input)
    }

    /// The item of an item-access input.
    ///
    /// # Errors
    /// When the item is null or missing (only possible for optional inputs: the runtime skips
    /// iterations where a required item is missing) or the port holds another type.
    #[inline]
    pub fn item<T: Item>(&self, input: usize) -> Result<&'a T, NodeError> {
        match self.cursor(input)? {
            Cursor::Item(Some(branch), Some(k)) => {
                if branch.is_null(k) {
                    return Err(self.no_item(input));
                }
                match T::slice(branch.column()).and_then(|s| s.get(k)) {
                    Some(item) => Ok(item),
                    None => Err(self.type_error(input, branch, T::TYPE)),
                }
            }
            Cursor::Item(..) => Err(self.no_item(input)),
            _ => Err(self.wrong_access(input, "item")),
        }
    }

    /// The item of an item-access input, or `None` when it is null, missing or of another type.
    #[inline]
    pub fn item_opt<T: Item>(&self, input: usize) -> Option<&'a T> {
        match self.cursors.get(input)? {
            Cursor::Item(Some(branch), Some(k)) => branch.get::<T>(*k),
            _ => None,
        }
    }

    /// The item of an item-access input as a [`Value`] of whatever type it has (for generic
    /// ports), or `None` when null or missing.
    pub fn value(&self, input: usize) -> Option<Value> {
        match self.cursors.get(input)? {
            Cursor::Item(Some(branch), Some(k)) => branch.value(*k),
            _ => None,
        }
    }

    /// The branch of a list-access input as a typed list.
    ///
    /// # Errors
    /// When the port is not list access or holds another type than `T`.
    pub fn list<T: Item>(&self, input: usize) -> Result<ListView<'a, T>, NodeError> {
        match self.cursor(input)? {
            Cursor::List(None) => Ok(ListView {
                items: &[],
                branch: None,
            }),
            Cursor::List(Some(branch)) => {
                if branch.is_empty() {
                    return Ok(ListView {
                        items: &[],
                        branch: Some(branch),
                    });
                }
                match T::slice(branch.column()) {
                    Some(items) => Ok(ListView {
                        items,
                        branch: Some(branch),
                    }),
                    None => Err(self.type_error(input, branch, T::TYPE)),
                }
            }
            _ => Err(NodeError(format!(
                "internal: input {} is not list access",
                self.port_name(input)
            ))),
        }
    }

    /// The branch of a list-access input, whatever its type (for generic ports).
    pub fn branch(&self, input: usize) -> Option<&'a Branch> {
        match self.cursors.get(input)? {
            Cursor::List(b) => *b,
            Cursor::Item(b, _) => *b,
            Cursor::Tree(_) => None,
        }
    }

    /// The whole tree of a tree-access input.
    ///
    /// # Errors
    /// When the port is not tree access.
    pub fn tree(&self, input: usize) -> Result<&'a DataTree, NodeError> {
        match self.cursor(input)? {
            Cursor::Tree(t) => Ok(t),
            _ => Err(NodeError(format!(
                "internal: input {} is not tree access",
                self.port_name(input)
            ))),
        }
    }

    #[cold]
    #[inline(never)]
    fn type_error(&self, input: usize, branch: &Branch, read_as: crate::DataType) -> NodeError {
        NodeError(format!(
            "internal: input {} holds {} items, read as {}",
            self.port_name(input),
            branch.data_type(),
            read_as
        ))
    }

    fn sink(&mut self, output: usize) -> Option<&mut OutputSink> {
        self.sinks.get_mut(output).filter(|s| !s.skip)
    }

    /// Sets the item of an item-access output for this iteration (a second call replaces it).
    #[inline]
    pub fn set<T: Item>(&mut self, output: usize, item: T) {
        let Some(sink) = self.sink(output) else {
            return;
        };
        match sink.access {
            Access::Item => {
                let Some((_, branch)) = sink.pieces.last_mut() else {
                    return;
                };
                if sink.set {
                    replace_last(branch, item.into_value());
                } else {
                    branch.push(item);
                    sink.set = true;
                }
            }
            _ => self.set_list(output, vec![item]),
        }
    }

    /// Sets an output item given as a [`Value`] (for generic outputs); `None` sets a null.
    ///
    /// A generic output collects values in a generic column; when the node has run, each of
    /// its branches whose items all have one type becomes a typed column
    /// ([`Branch::narrowed`](crate::Branch::narrowed)).
    pub fn set_value(&mut self, output: usize, value: Option<Value>) {
        let Some(sink) = self.sink(output) else {
            return;
        };
        match sink.access {
            Access::Item => {
                let Some((_, branch)) = sink.pieces.last_mut() else {
                    return;
                };
                if sink.set {
                    // Replace: rebuild the last item.
                    match value {
                        Some(v) => replace_last(branch, v),
                        None => replace_last_with_null(branch),
                    }
                } else {
                    branch.push_option(value);
                    sink.set = true;
                }
            }
            _ => {
                let mut b = Branch::new(sink.data_type);
                b.push_option(value);
                self.set_branch(output, b);
            }
        }
    }

    /// Sets the list of a list-access output for this iteration.
    pub fn set_list<T: Item>(&mut self, output: usize, items: Vec<T>) {
        self.set_branch(output, Branch::from_items(items));
    }

    /// Sets the list of a list-access output from values, `None` for nulls.
    pub fn set_list_values(&mut self, output: usize, values: Vec<Option<Value>>) {
        let data_type = self.sinks.get(output).map(|s| s.data_type);
        let mut b = Branch::new(data_type.unwrap_or(crate::DataType::Generic));
        for v in values {
            b.push_option(v);
        }
        self.set_branch(output, b);
    }

    /// Sets the list of a list-access output to a prepared branch.
    pub fn set_branch(&mut self, output: usize, branch: Branch) {
        let path = if self.append_index {
            self.path.with_appended(self.index.unwrap_or(0) as u32)
        } else {
            self.path.clone()
        };
        let Some(sink) = self.sink(output) else {
            return;
        };
        if sink.set {
            sink.pieces.pop();
        }
        sink.listed = sink.listed.saturating_add(branch.len() + 1);
        sink.pieces.push((path, branch));
        sink.set = true;
    }

    /// Sets a tree-access output: the tree's branches are merged into the output as they are.
    pub fn set_tree(&mut self, output: usize, tree: DataTree) {
        let Some(sink) = self.sink(output) else {
            return;
        };
        sink.listed = sink
            .listed
            .saturating_add(tree.item_count() + tree.branch_count());
        sink.pieces.extend(tree.into_branches());
        sink.set = true;
    }

    /// Reports a remark for this iteration.
    pub fn remark(&mut self, text: impl Into<String>) {
        self.message(Level::Remark, text.into());
    }

    /// Reports a warning for this iteration.
    pub fn warning(&mut self, text: impl Into<String>) {
        self.message(Level::Warning, text.into());
    }

    /// Reports an error for this iteration (returning `Err` from the solve function does the
    /// same and leaves the outputs not yet set empty).
    pub fn error(&mut self, text: impl Into<String>) {
        self.message(Level::Error, text.into());
    }

    /// Reports a message for a given path and item index rather than this iteration's: for
    /// nodes that solve once over whole trees and iterate themselves (a script node reports
    /// each item's error on that item).
    pub fn message_at(
        &mut self,
        level: Level,
        path: Option<TreePath>,
        index: Option<usize>,
        text: impl Into<String>,
    ) {
        self.messages.push((level, path, index, text.into()));
    }

    fn message(&mut self, level: Level, text: String) {
        self.messages
            .push((level, Some(self.path.clone()), self.index, text));
    }

    /// The value of a node setting (defaults filled in).
    pub fn setting(&self, name: &str) -> Option<&'a Value> {
        self.settings
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v)
    }

    /// The node's prepared state, if its type has a prepare function and it returned a `T`.
    pub fn prepared<T: Any + Send + Sync>(&self) -> Option<&'a T> {
        self.prepared.and_then(|p| p.downcast_ref::<T>())
    }

    /// The output path of this iteration.
    pub fn path(&self) -> &TreePath {
        self.path
    }

    /// The item index of this iteration within its branch (`None` for list-only nodes).
    pub fn index(&self) -> Option<usize> {
        self.index
    }

    /// The declaration of output `output`.
    pub fn output_port(&self, output: usize) -> Option<&Port> {
        self.output_ports.get(output)
    }

    /// How many outputs the node has (a node with variable outputs has those its graph names).
    pub fn output_count(&self) -> usize {
        self.output_ports.len()
    }
}

fn replace_last(branch: &mut Branch, value: Value) {
    let n = branch.len();
    if n == 0 {
        branch.push_value(value);
        return;
    }
    let mut rebuilt = Branch::new(branch.data_type());
    rebuilt.extend_range(branch, 0..n - 1);
    rebuilt.push_value(value);
    *branch = rebuilt;
}

fn replace_last_with_null(branch: &mut Branch) {
    let n = branch.len();
    let mut rebuilt = Branch::new(branch.data_type());
    rebuilt.extend_range(branch, 0..n.saturating_sub(1));
    rebuilt.push_null();
    *branch = rebuilt;
}
