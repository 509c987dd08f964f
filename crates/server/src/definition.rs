//! The one place definitions are read: bytes in (from `algo` or a file under `--definitions`),
//! a checked [`Definition`] out.
//!
//! RON graphs are read by the runtime. Grasshopper files (`.gh` binary archives and `.ghx` XML)
//! are recognised here and will be read by the `locus-ghx` crate when it is part of the
//! workspace; until then they are refused with a clear message. Everything else in the server
//! sees only [`Definition`], so a new format plugs in here alone.

use base64::Engine as _;
use locus_runtime::{Access, DataTree, DataType, Document, NodeRegistry, Plan, Severity, Value};
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
    /// The name callers use (`ParamName`).
    pub name: String,
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
    /// The name answers use (`ParamName`).
    pub name: String,
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
    /// Problems checking found that do not stop it from running.
    pub warnings: Vec<String>,
}

/// Why bytes are not a definition this server can run.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum DefinitionError {
    /// The format is recognised but not readable by this build.
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
/// [`DefinitionError::Unsupported`] for Grasshopper files (until `locus-ghx` is wired in) and
/// text that is not UTF-8; [`DefinitionError::Invalid`] with every error found.
pub fn load(
    bytes: &[u8],
    pointer: String,
    registry: &NodeRegistry,
) -> Result<Definition, DefinitionError> {
    let format = Format::sniff(bytes);
    match format {
        Format::Ron => {}
        Format::Ghx | Format::Gh => {
            return Err(DefinitionError::Unsupported(format!(
                "Grasshopper {} files cannot be read by this build yet; send a locus graph (RON)",
                if format == Format::Gh { ".gh" } else { ".ghx" }
            )));
        }
    }
    let text = std::str::from_utf8(trim_bom(bytes))
        .map_err(|e| DefinitionError::Unsupported(format!("the definition is not UTF-8: {e}")))?;
    let doc = Document::parse(text).map_err(diagnostics)?;
    let description = doc.graph().description.clone();
    let checked = doc.check(registry).map_err(diagnostics)?;
    let warnings = checked.warnings.iter().map(ToString::to_string).collect();
    let plan = checked.plan;
    let inputs = plan
        .inputs
        .iter()
        .map(|(name, node, port)| {
            let input = &plan.nodes[*node].inputs[*port];
            InputInfo {
                name: name.clone(),
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
    let outputs = plan
        .outputs
        .iter()
        .map(|(name, node, port)| OutputInfo {
            name: name.clone(),
            data_type: plan.nodes[*node].node_type.outputs[*port].data_type,
        })
        .collect();
    Ok(Definition {
        pointer,
        format,
        plan,
        description,
        inputs,
        outputs,
        warnings,
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
