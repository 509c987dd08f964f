//! The one place definitions are read: bytes in (from `algo` or a file under `--definitions`),
//! a checked [`Definition`] out.
//!
//! RON graphs are read by the runtime; Grasshopper files (`.gh` binary archives and `.ghx` XML)
//! are imported by `locus-ghx` onto a graph first. Everything else in the server sees only
//! [`Definition`], so a new format plugs in here alone.
//!
//! A definition's inputs and outputs carry two names: the graph's own (what `/v1/run` uses) and
//! Rhino.Compute's (what `/grasshopper` and `/io` use, `compute_name`). For a RON graph they are
//! the same. For a Grasshopper file Compute's name is the whole nickname of the `RH_IN:`/
//! `RH_OUT:` group (`RH_IN:radius`), or a Hops Get parameter's nickname
//! ([`locus_ghx::ComputeName`]); graph inputs Compute would not see (a slider outside any
//! `RH_IN` group) have none.

use base64::Engine as _;
use locus_runtime::{
    Access, DataTree, DataType, Document, Level, NodeRegistry, Plan, Severity, Value,
};
use md5::{Digest as _, Md5};

/// The kinds of file a definition can come in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// A locus graph (RON text).
    Ron,
    /// A Grasshopper XML file.
    Ghx,
    /// A Grasshopper binary file.
    Gh,
}

impl Format {
    /// Guesses the format from the first bytes: `.ghx` is XML, `.gh` a binary GH_IO archive
    /// (never valid UTF-8 text in practice), anything else RON.
    pub fn sniff(bytes: &[u8]) -> Self {
        let text = trim_bom(bytes);
        let start = text
            .iter()
            .position(|b| !b.is_ascii_whitespace())
            .unwrap_or(text.len());
        if text[start..].starts_with(b"<") {
            Format::Ghx
        } else if std::str::from_utf8(text).is_err() {
            Format::Gh
        } else {
            Format::Ron
        }
    }
}

/// A named input of a definition, as `/io` describes it and solves read it.
#[derive(Clone, Debug)]
pub struct InputInfo {
    /// The graph's name of the input (what `/v1/run` and the evaluator use).
    pub name: String,
    /// The name Compute clients use (`ParamName`), if Compute would see the input.
    pub compute_name: Option<String>,
    /// The y position on the Grasshopper canvas (`/io` sorts by it); 0 for RON graphs.
    pub canvas_y: f64,
    /// The type the input's port takes.
    pub data_type: DataType,
    /// How the port reads its data.
    pub access: Access,
    /// The port's description.
    pub description: String,
    /// The value the definition gives the input when a request sends none.
    pub default: Option<DataTree>,
    /// Whether the port may be left without data.
    pub optional: bool,
}

/// A named output of a definition.
#[derive(Clone, Debug)]
pub struct OutputInfo {
    /// The graph's name of the output.
    pub name: String,
    /// The name Compute answers use (`ParamName`), if Compute would see the output.
    pub compute_name: Option<String>,
    /// The y position on the Grasshopper canvas (`/io` sorts by it); 0 for RON graphs.
    pub canvas_y: f64,
    /// The type of the port's items.
    pub data_type: DataType,
}

/// A definition read and checked once, shared by every request that names it.
#[derive(Clone, Debug)]
pub struct Definition {
    /// Rhino.Compute's cache key: `md5_` and the MD5 of the base64 text of the definition.
    pub pointer: String,
    /// The format it came in.
    pub format: Format,
    /// The checked graph the evaluators run.
    pub plan: Plan,
    /// What the definition computes.
    pub description: String,
    /// The named inputs, in the definition's order.
    pub inputs: Vec<InputInfo>,
    /// The named outputs, in the definition's order.
    pub outputs: Vec<OutputInfo>,
    /// Problems that do not stop it from running: checking's warnings, and for Grasshopper
    /// files the importer's warnings (a dropped modifier, a wire that does not cast, …).
    pub warnings: Vec<String>,
    /// Errors that do not stop the rest from running, reported with every solve as Compute
    /// does: objects of a Grasshopper file that cannot run (scripts, plugins, components
    /// without a locus node) and Compute names used twice (the first one wins).
    pub errors: Vec<String>,
}

/// Why bytes are not a definition this server can run.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DefinitionError {
    /// The bytes do not read in the format they were recognised as (RON that is not UTF-8, a
    /// Grasshopper archive that does not read).
    #[error("{0}")]
    Unsupported(String),
    /// The definition does not read or check: every error with its line and column.
    #[error("the definition does not check: {}", .0.join("; "))]
    Invalid(Vec<String>),
}

/// The pointer of a definition whose base64 text (as a client sends it in `algo`) is `algo`.
pub fn pointer_of_algo(algo: &str) -> String {
    let digest = Md5::digest(algo.as_bytes());
    let mut pointer = String::with_capacity(4 + 32);
    pointer.push_str("md5_");
    for b in digest {
        pointer.push_str(&format!("{b:02X}"));
    }
    pointer
}

/// The pointer of a definition read from bytes (a file): the pointer of the `algo` a client
/// would send for it (base64 of the bytes, any BOM dropped).
pub fn pointer_of_bytes(bytes: &[u8]) -> String {
    pointer_of_algo(&base64::engine::general_purpose::STANDARD.encode(trim_bom(bytes)))
}

fn trim_bom(bytes: &[u8]) -> &[u8] {
    bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes)
}

/// Reads and checks a definition. `pointer` is the cache key it will be known by.
///
/// # Errors
/// [`DefinitionError::Unsupported`] for text that is not UTF-8 and Grasshopper files that do
/// not read; [`DefinitionError::Invalid`] with every error found.
pub fn load(
    bytes: &[u8],
    pointer: String,
    registry: &NodeRegistry,
) -> Result<Definition, DefinitionError> {
    let format = Format::sniff(bytes);
    let (checked, description, names, mut warnings, errors) = match format {
        Format::Ron => {
            let text = std::str::from_utf8(trim_bom(bytes)).map_err(|e| {
                DefinitionError::Unsupported(format!("the definition is not UTF-8: {e}"))
            })?;
            let doc = Document::parse(text).map_err(diagnostics)?;
            let description = doc.graph().description.clone();
            let checked = doc.check(registry).map_err(diagnostics)?;
            (checked, description, None, Vec::new(), Vec::new())
        }
        Format::Ghx | Format::Gh => {
            let limits = locus_ghx::Limits {
                max_file_bytes: bytes.len().max(1),
                ..locus_ghx::Limits::default()
            };
            let import = locus_ghx::import(bytes, registry, &limits).map_err(|e| {
                DefinitionError::Unsupported(format!(
                    "the Grasshopper {} file does not read: {e}",
                    if format == Format::Gh { ".gh" } else { ".ghx" }
                ))
            })?;
            let mut warnings = Vec::new();
            let mut errors = Vec::new();
            for d in &import.report.diagnostics {
                match d.severity {
                    Level::Error => errors.push(d.message.clone()),
                    Level::Warning => warnings.push(d.message.clone()),
                    Level::Remark => {}
                }
            }
            let checked = locus_runtime::check(&import.graph, registry).map_err(diagnostics)?;
            let names = (import.compute_inputs, import.compute_outputs);
            (
                checked,
                import.graph.description.clone(),
                Some(names),
                warnings,
                errors,
            )
        }
    };
    warnings.extend(checked.warnings.iter().map(ToString::to_string));
    let plan = checked.plan;
    let mut inputs: Vec<InputInfo> = plan
        .inputs
        .iter()
        .map(|(name, node, port)| {
            let input = &plan.nodes[*node].inputs[*port];
            InputInfo {
                name: name.clone(),
                compute_name: names.is_none().then(|| name.clone()),
                canvas_y: 0.0,
                data_type: input.port.data_type,
                access: input.port.access,
                description: input.port.description.clone(),
                default: input
                    .value
                    .clone()
                    .or_else(|| input.port.default.clone().map(DataTree::from_value)),
                optional: input.port.optional,
            }
        })
        .collect();
    let mut outputs: Vec<OutputInfo> = plan
        .outputs
        .iter()
        .map(|(name, node, port)| OutputInfo {
            name: name.clone(),
            compute_name: names.is_none().then(|| name.clone()),
            canvas_y: 0.0,
            data_type: plan.nodes[*node].node_type.outputs[*port].data_type,
        })
        .collect();
    let mut errors = errors;
    let mut input_order = Vec::new();
    let mut output_order = Vec::new();
    if let Some((compute_inputs, compute_outputs)) = names {
        input_order = compute_inputs.iter().map(|n| n.name.clone()).collect();
        output_order = compute_outputs.iter().map(|n| n.name.clone()).collect();
        let mut named = |list: Vec<locus_ghx::ComputeName>,
                         set: &mut dyn FnMut(&str, &str, f64),
                         what: &str| {
            let mut seen = std::collections::HashSet::new();
            for n in list {
                if !seen.insert(n.name.clone()) {
                    // Compute's own message for this; the first one wins.
                    errors.push(format!(
                        "Multiple {what} parameters with the same name were detected. \
                         Parameter names must be unique. (\"{}\")",
                        n.name
                    ));
                } else {
                    set(&n.graph, &n.name, n.canvas_y);
                }
            }
        };
        named(
            compute_inputs,
            &mut |graph, name, y| {
                if let Some(i) = inputs.iter_mut().find(|i| i.name == graph) {
                    i.compute_name = Some(name.to_owned());
                    i.canvas_y = y;
                }
            },
            "input",
        );
        named(
            compute_outputs,
            &mut |graph, name, y| {
                if let Some(o) = outputs.iter_mut().find(|o| o.name == graph) {
                    o.compute_name = Some(name.to_owned());
                    o.canvas_y = y;
                }
            },
            "output",
        );
    }
    if format != Format::Ron {
        // Compute's order: the order of the objects that name them.
        let rank = |name: &Option<String>, order: &[String]| {
            name.as_ref()
                .and_then(|n| order.iter().position(|o| o == n))
                .unwrap_or(usize::MAX)
        };
        inputs.sort_by_key(|i| rank(&i.compute_name, &input_order));
        outputs.sort_by_key(|o| rank(&o.compute_name, &output_order));
    }
    Ok(Definition {
        pointer,
        format,
        plan,
        description,
        inputs,
        outputs,
        warnings,
        errors,
    })
}

fn diagnostics(d: Vec<locus_runtime::Diagnostic>) -> DefinitionError {
    DefinitionError::Invalid(
        d.iter()
            .filter(|d| d.severity == Severity::Error)
            .map(ToString::to_string)
            .collect(),
    )
}

/// Whether a value type is geometry that Compute sends as openNURBS-archive JSON.
pub fn is_archive_type(data_type: DataType) -> bool {
    matches!(
        data_type,
        DataType::Curve | DataType::Surface | DataType::Brep
    )
}

/// The first item of a tree, if any (for `/io`'s Minimum and Maximum).
pub fn first_item(tree: &DataTree) -> Option<Value> {
    tree.values().flatten().next()
}
