//! A Grasshopper definition as its objects: what the chunk model says about each component,
//! parameter and widget (type, names, ports, wires, persistent data, modifiers), before any
//! mapping onto locus nodes.

use crate::archive::{Chunk, Value};
use crate::error::ArchiveError;
use crate::limits::Limits;

/// A definition read from an archive.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GhDocument {
    /// The definition's name (`DefinitionProperties/Name`), often the file name.
    pub name: String,
    /// Its description.
    pub description: String,
    /// The objects, in file order.
    pub objects: Vec<GhObject>,
    /// The plugin libraries the file lists (`GHALibraries`).
    pub libraries: Vec<Library>,
}

/// A plugin library of `GHALibraries`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Library {
    /// The library's GUID (what an object's `Lib` item holds).
    pub id: String,
    /// Its name.
    pub name: String,
    /// Its author.
    pub author: String,
    /// Its version.
    pub version: String,
}

/// One object of a definition: a component, a floating parameter, a widget, a group, …
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GhObject {
    /// The object's index in `DefinitionObjects`.
    pub index: usize,
    /// The type GUID (lower case): what kind of object it is.
    pub type_guid: String,
    /// The type name the file gives (`Number Slider`).
    pub type_name: String,
    /// The plugin library, when the object comes from one.
    pub library: Option<String>,
    /// The instance GUID.
    pub instance: String,
    /// The user-visible name.
    pub name: String,
    /// The nickname.
    pub nickname: String,
    /// Whether the object is disabled (`Locked`).
    pub disabled: bool,
    /// The inputs (a floating parameter has one: itself).
    pub inputs: Vec<GhParam>,
    /// The outputs (a floating parameter has one: itself).
    pub outputs: Vec<GhParam>,
    /// Whether the object is a floating parameter (its container is the parameter).
    pub floating: bool,
    /// The object's `Container` chunk, for type-specific data (slider, panel, formula).
    pub container: Chunk,
}

/// One parameter: an input or output of a component, or a floating parameter.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GhParam {
    /// The parameter's instance GUID (what `Source` items of receivers hold).
    pub instance: String,
    /// Its name (`Radius`).
    pub name: String,
    /// Its nickname (`R`).
    pub nickname: String,
    /// The instance GUIDs of the outputs (or floating parameters) wired into it, in order.
    pub sources: Vec<String>,
    /// Persistent data (values typed in), when present.
    pub persistent: Option<GhTree>,
    /// The input modifiers set on it.
    pub modifiers: Vec<GhModifier>,
    /// An input expression (`InternalExpression`): the importer puts an Expression node in
    /// front of the input.
    pub expression: Option<String>,
    /// Items that reference Rhino document geometry (`RefID`, `ReferenceData`) or hold
    /// internalised openNURBS geometry (`ON_Data`) that could not be read: their kinds.
    pub foreign_data: Vec<String>,
    /// A script component's parameter: its access (`ScriptParamAccess`: 0 item, 1 list,
    /// 2 tree).
    pub script_access: Option<i64>,
    /// A script component's parameter: its type hint (`TypeHintID`), lower-case.
    pub type_hint: Option<String>,
}

/// Grasshopper's input modifiers, as the file stores them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GhModifier {
    /// `Mapping` 1.
    Flatten,
    /// `Mapping` 2.
    Graft,
    /// `SimplifyData`.
    Simplify,
    /// `ReverseData`.
    Reverse,
    /// `InvertBooleans`.
    Invert,
    /// `UseDegrees`.
    Degrees,
    /// `Reparameterize`.
    Reparameterize,
}

/// Persistent data: branches with their paths and items.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GhTree {
    /// `(path indices, items)` per branch, in file order.
    pub branches: Vec<(Vec<i64>, Vec<GhItem>)>,
}

/// One item of persistent data.
#[derive(Clone, Debug, PartialEq)]
pub enum GhItem {
    /// A number.
    Number(f64),
    /// An integer.
    Integer(i64),
    /// A boolean.
    Boolean(bool),
    /// A text.
    Text(String),
    /// A point.
    Point([f64; 3]),
    /// A vector.
    Vector([f64; 3]),
    /// A plane: origin, x axis, y axis.
    Plane([f64; 9]),
    /// An interval.
    Domain([f64; 2]),
    /// A two-dimensional interval: u start, u end, v start, v end.
    Domain2([f64; 4]),
    /// A colour (alpha, red, green, blue).
    Colour([u8; 4]),
    /// A mesh face: vertex indices `A`, `B`, `C`, `D` (a triangle repeats `C` as `D`).
    MeshFace([i64; 4]),
    /// Internalised geometry (`ON_Data`), read into a curve, surface, B-rep or mesh; or why it
    /// could not be read.
    Geometry(Result<locus_runtime::Value, String>),
    /// Something that is not a simple value (a reference): its item name.
    Other(String),
}

/// Reads the definition in an archive's root chunk.
pub fn read_document(root: &Chunk) -> Result<GhDocument, ArchiveError> {
    // A file's definition is the chunk `Definition`; a cluster's document is the root itself.
    let own = root.chunk("DefinitionObjects").is_some().then_some(root);
    let def = root
        .chunk("Definition")
        .or(own)
        .ok_or_else(|| ArchiveError::Bad {
            path: root.name.clone(),
            reason: "no Definition chunk: not a Grasshopper definition".to_owned(),
        })?;
    let mut doc = GhDocument::default();
    if let Some(props) = def.chunk("DefinitionProperties") {
        doc.name = props.str("Name").unwrap_or_default().to_owned();
        doc.description = props.str("Description").unwrap_or_default().to_owned();
    }
    if let Some(libs) = def.chunk("GHALibraries") {
        for lib in libs.chunks_named("Library") {
            doc.libraries.push(Library {
                id: lib.str("Id").unwrap_or_default().to_owned(),
                name: lib.str("Name").unwrap_or_default().to_owned(),
                author: lib.str("Author").unwrap_or_default().to_owned(),
                version: lib.str("Version").unwrap_or_default().to_owned(),
            });
        }
    }
    let Some(objects) = def.chunk("DefinitionObjects") else {
        return Ok(doc);
    };
    for (index, chunk) in objects.chunks_named("Object").enumerate() {
        doc.objects.push(read_object(index, chunk));
    }
    Ok(doc)
}

/// Reads the definition inside a cluster's `ClusterDocument` bytes (`cluster_depth` is the
/// depth of that cluster, 1 for a cluster in a file).
pub fn read_cluster(
    bytes: &[u8],
    limits: &Limits,
    cluster_depth: usize,
) -> Result<GhDocument, ArchiveError> {
    if cluster_depth > limits.max_cluster_depth {
        return Err(ArchiveError::TooDeep {
            path: format!("cluster at depth {cluster_depth}"),
            limit: limits.max_cluster_depth,
        });
    }
    let root = crate::binary::read_compressed(bytes, limits, cluster_depth)?;
    read_document(&root)
}

fn read_object(index: usize, chunk: &Chunk) -> GhObject {
    let container = chunk.chunk("Container").cloned().unwrap_or_default();
    let mut object = GhObject {
        index,
        type_guid: chunk.str("GUID").unwrap_or_default().to_ascii_lowercase(),
        type_name: chunk.str("Name").unwrap_or_default().to_owned(),
        library: chunk.str("Lib").map(str::to_ascii_lowercase),
        instance: container.str("InstanceGuid").unwrap_or_default().to_owned(),
        name: container.str("Name").unwrap_or_default().to_owned(),
        nickname: container.str("NickName").unwrap_or_default().to_owned(),
        disabled: container.bool("Locked").unwrap_or(false),
        ..GhObject::default()
    };
    let data = container.chunk("ParameterData");
    let inputs: Vec<&Chunk> = match data {
        Some(d) => d.chunks_named("InputParam").collect(),
        None => container.chunks_named("param_input").collect(),
    };
    let outputs: Vec<&Chunk> = match data {
        Some(d) => d.chunks_named("OutputParam").collect(),
        None => container.chunks_named("param_output").collect(),
    };
    if inputs.is_empty() && outputs.is_empty() && container.item("SourceCount").is_some() {
        // A floating parameter: the container is the parameter, both input and output.
        object.floating = true;
        let param = read_param(&container);
        object.inputs.push(param.clone());
        object.outputs.push(param);
    } else {
        object.inputs = sorted(inputs).into_iter().map(read_param).collect();
        object.outputs = sorted(outputs).into_iter().map(read_param).collect();
    }
    object.container = container;
    object
}

fn sorted(mut chunks: Vec<&Chunk>) -> Vec<&Chunk> {
    chunks.sort_by_key(|c| c.index.unwrap_or(i32::MAX));
    chunks
}

fn read_param(chunk: &Chunk) -> GhParam {
    let mut param = GhParam {
        instance: chunk.str("InstanceGuid").unwrap_or_default().to_owned(),
        name: chunk.str("Name").unwrap_or_default().to_owned(),
        nickname: chunk.str("NickName").unwrap_or_default().to_owned(),
        ..GhParam::default()
    };
    let mut sources: Vec<(i32, String)> = chunk
        .items_named("Source")
        .filter_map(|i| Some((i.index.unwrap_or(0), i.value.as_str()?.to_owned())))
        .collect();
    sources.sort_by_key(|(i, _)| *i);
    param.sources = sources.into_iter().map(|(_, s)| s).collect();
    match chunk.i64("Mapping") {
        Some(1) => param.modifiers.push(GhModifier::Flatten),
        Some(2) => param.modifiers.push(GhModifier::Graft),
        _ => {}
    }
    for (name, m) in [
        ("SimplifyData", GhModifier::Simplify),
        ("ReverseData", GhModifier::Reverse),
        ("InvertBooleans", GhModifier::Invert),
        ("UseDegrees", GhModifier::Degrees),
        ("Reparameterize", GhModifier::Reparameterize),
    ] {
        if chunk.bool(name) == Some(true) {
            param.modifiers.push(m);
        }
    }
    param.script_access = chunk.i64("ScriptParamAccess");
    param.type_hint = chunk.str("TypeHintID").map(str::to_ascii_lowercase);
    param.expression = chunk
        .str("InternalExpression")
        .filter(|e| !e.trim().is_empty())
        .map(str::to_owned);
    // Internalised items carry a nil `RefID` beside their `ON_Data`: only a real GUID
    // references the Rhino document.
    if contains_item(chunk, &|i| {
        i.name == "RefID" && i.value.as_str().is_some_and(|g| !is_nil_guid(g))
    }) {
        param.foreign_data.push("RefID".to_owned());
    }
    if contains_named(chunk, "ReferenceData") {
        param.foreign_data.push("ReferenceData".to_owned());
    }
    if let Some(data) = chunk.chunk("PersistentData") {
        let tree = read_tree(data);
        if tree
            .branches
            .iter()
            .flat_map(|(_, items)| items)
            .any(|i| matches!(i, GhItem::Geometry(Err(_))))
        {
            param.foreign_data.push("ON_Data".to_owned());
        }
        param.persistent = Some(tree);
    }
    param
}

/// Whether an item that passes `test` occurs anywhere below `chunk`.
fn contains_item(chunk: &Chunk, test: &dyn Fn(&crate::archive::Item) -> bool) -> bool {
    chunk.items.iter().any(test) || chunk.chunks.iter().any(|c| contains_item(c, test))
}

/// `00000000-0000-0000-0000-000000000000`, in any spelling.
fn is_nil_guid(g: &str) -> bool {
    g.chars()
        .all(|c| c == '0' || c == '-' || c == '{' || c == '}')
        && g.contains('0')
}

/// Whether a chunk or item with this name occurs anywhere below `chunk`.
fn contains_named(chunk: &Chunk, name: &str) -> bool {
    chunk.items.iter().any(|i| i.name == name)
        || chunk
            .chunks
            .iter()
            .any(|c| c.name == name || contains_named(c, name))
}

fn read_tree(data: &Chunk) -> GhTree {
    let mut branches: Vec<&Chunk> = data.chunks_named("Branch").collect();
    branches.sort_by_key(|c| c.index.unwrap_or(i32::MAX));
    let mut tree = GhTree::default();
    for branch in branches {
        let path = branch
            .str("Path")
            .map(parse_path)
            .unwrap_or_else(|| vec![0]);
        let mut items: Vec<&Chunk> = branch.chunks_named("Item").collect();
        items.sort_by_key(|c| c.index.unwrap_or(i32::MAX));
        let items = items.into_iter().map(read_item).collect();
        tree.branches.push((path, items));
    }
    tree
}

/// `{0;1}` → `[0, 1]` (unreadable indices are dropped; an empty path is `{0}`).
fn parse_path(text: &str) -> Vec<i64> {
    let inner = text.trim().trim_start_matches('{').trim_end_matches('}');
    let path: Vec<i64> = inner
        .split(';')
        .filter_map(|p| p.trim().parse().ok())
        .collect();
    if path.is_empty() { vec![0] } else { path }
}

/// A Mesh Face item (`GH_MeshFace`): the integers `A`, `B`, `C` and `D`, and nothing else.
fn mesh_face(chunk: &Chunk) -> Option<[i64; 4]> {
    if chunk.items.len() != 4 || !chunk.chunks.is_empty() {
        return None;
    }
    let index = |name: &str| match chunk.item(name).map(|i| &i.value) {
        Some(Value::Int32(i)) => Some(i64::from(*i)),
        _ => None,
    };
    Some([index("A")?, index("B")?, index("C")?, index("D")?])
}

/// A Loft Options item (`GH_LoftOptions`: `LoftType`, `Closed`, `Adjust`, `LoftSimp`, …) as
/// the words Loft's O input reads: the type (Rhino's numbers 0 normal, 1 loose, 2 tight,
/// 3 straight, 4 developable, 5 uniform), `closed`, `adjust`, and `rebuild` or `refit` when the
/// sections are simplified (which Loft refuses with a message, as it does developable).
fn loft_options(chunk: &Chunk) -> Option<GhItem> {
    let int = |name: &str| match chunk.item(name).map(|i| &i.value) {
        Some(Value::Int32(i)) => Some(*i),
        _ => None,
    };
    let kind = int("LoftType")?;
    let closed = chunk.bool("Closed")?;
    let adjust = chunk.bool("Adjust").unwrap_or(false);
    let mut words = vec![match kind {
        0 => "normal".to_owned(),
        1 => "loose".to_owned(),
        2 => "tight".to_owned(),
        3 => "straight".to_owned(),
        4 => "developable".to_owned(),
        5 => "uniform".to_owned(),
        other => format!("type{other}"),
    }];
    if closed {
        words.push("closed".to_owned());
    }
    if adjust {
        words.push("adjust".to_owned());
    }
    match int("LoftSimp") {
        Some(1) => words.push("rebuild".to_owned()),
        Some(2) => words.push("refit".to_owned()),
        _ => {}
    }
    Some(GhItem::Text(words.join(" ")))
}

fn read_item(chunk: &Chunk) -> GhItem {
    if let Some(item) = chunk.item("ON_Data") {
        return GhItem::Geometry(match &item.value {
            Value::Bytes(bytes) => crate::internalised::decode(bytes),
            other => Err(format!(
                "an ON_Data item of type {} instead of bytes",
                other.type_code()
            )),
        });
    }
    if chunk.chunk("ON_Data").is_some() {
        return GhItem::Geometry(Err(
            "ON_Data stored as a chunk, which locus does not read".to_owned()
        ));
    }
    if let Some(face) = mesh_face(chunk) {
        return GhItem::MeshFace(face);
    }
    if let Some(options) = loft_options(chunk) {
        return options;
    }
    // Generic data carries a `TypeName` item beside the value; a text carries a `null_string`
    // flag before it.
    let Some(item) = chunk
        .items
        .iter()
        .find(|i| i.name != "TypeName" && i.name != "null_string")
    else {
        return GhItem::Other(
            chunk
                .chunks
                .first()
                .map(|c| c.name.clone())
                .unwrap_or_else(|| "empty".to_owned()),
        );
    };
    match (item.name.as_str(), &item.value) {
        (_, Value::Bool(b)) => GhItem::Boolean(*b),
        ("vector", Value::Point3(p)) => GhItem::Vector(*p),
        (_, Value::Point3(p)) => GhItem::Point(*p),
        (_, Value::Plane(p)) => GhItem::Plane(*p),
        (_, Value::Interval(d)) => GhItem::Domain(*d),
        (_, Value::Interval2(d)) => GhItem::Domain2(*d),
        (_, Value::Color(c)) => GhItem::Colour(*c),
        (_, Value::String(s)) => GhItem::Text(s.clone()),
        (_, Value::Int32(i)) => GhItem::Integer(i64::from(*i)),
        (_, Value::Int64(i)) => GhItem::Integer(*i),
        (_, v) => match v.as_f64() {
            Some(x) => GhItem::Number(x),
            None => GhItem::Other(item.name.clone()),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Limits;
    use crate::xml::read_xml;

    fn item_of(items: &str) -> GhItem {
        let xml = format!(
            r#"<?xml version="1.0"?><Archive name="Root"><items count="0" /><chunks count="1"><chunk name="Item" index="0">{items}</chunk></chunks></Archive>"#
        );
        let root = read_xml(xml.as_bytes(), &Limits::default()).unwrap();
        read_item(&root.chunks[0])
    }

    fn int(name: &str, value: i32) -> String {
        format!(r#"<item name="{name}" type_name="gh_int32" type_code="3">{value}</item>"#)
    }

    #[test]
    fn mesh_faces_typed_into_an_input_are_read_as_faces() {
        let quad = format!(
            r#"<items count="4">{}{}{}{}</items>"#,
            int("A", 0),
            int("B", 1),
            int("C", 2),
            int("D", 3)
        );
        assert_eq!(item_of(&quad), GhItem::MeshFace([0, 1, 2, 3]));
        let triangle = quad.replace(&int("D", 3), &int("D", 2));
        assert_eq!(item_of(&triangle), GhItem::MeshFace([0, 1, 2, 2]));
        // Three integers are not a face: the first is read as before.
        let three = format!(
            r#"<items count="3">{}{}{}</items>"#,
            int("A", 4),
            int("B", 1),
            int("C", 2)
        );
        assert_eq!(item_of(&three), GhItem::Integer(4));
    }

    fn boolean(name: &str, value: bool) -> String {
        format!(r#"<item name="{name}" type_name="gh_bool" type_code="1">{value}</item>"#)
    }

    #[test]
    fn loft_options_typed_into_an_input_are_read_as_loft_words() {
        // As runxel's simple_triangulation stores them (a GH_LoftOptions item).
        let options = |adjust: bool, closed: bool, kind: i32, simplify: i32| {
            item_of(&format!(
                r#"<items count="7">{}{}{}{}{}{}<item name="Refit" type_name="gh_double" type_code="6">0.01</item></items>"#,
                boolean("Adjust", adjust),
                boolean("Closed", closed),
                int("LoftEnds", 0),
                int("LoftSimp", simplify),
                int("LoftType", kind),
                int("Rebuild", 10),
            ))
        };
        assert_eq!(
            options(false, false, 0, 0),
            GhItem::Text("normal".to_owned())
        );
        assert_eq!(
            options(true, true, 3, 0),
            GhItem::Text("straight closed adjust".to_owned())
        );
        assert_eq!(
            options(false, false, 4, 1),
            GhItem::Text("developable rebuild".to_owned())
        );
    }
}
