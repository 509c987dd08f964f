//! Grasshopper object types the importer treats specially, by type GUID: widgets, pass-through
//! parameters, display-only objects, canvas furniture, clusters and Hops.
//!
//! Everything else is mapped through the registry (`NodeType::gh_guids`), or reported as
//! unsupported.

/// How the importer treats an object type that is not a plain registry node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Special {
    /// Number Slider: a Number parameter with the slider's value (range and digits kept as
    /// input metadata).
    Slider,
    /// Control Knob: a Number parameter with the knob's value.
    Knob,
    /// MD Slider: a Point parameter at the slider's position mapped onto its domains.
    MdSlider,
    /// Panel: a Text parameter with the panel's text when nothing feeds it; a pass-through
    /// (and a named output) when something does.
    Panel,
    /// Boolean Toggle: a Boolean parameter with the toggle's state.
    Toggle,
    /// Button: a Boolean parameter, false (not pressed).
    Button,
    /// Value List: the selected items' values.
    ValueList,
    /// A parameter that passes its data on unchanged (Data, Relay, Line, Circle, Mesh).
    PassThrough,
    /// Shows data on the canvas or in the viewport only: dropped with a remark.
    Display,
    /// Timer: triggers new solutions on a clock; a headless run solves once, so it is ignored
    /// with a remark.
    Timer,
    /// Canvas furniture (groups, scribbles, sketches): ignored; groups are read for the
    /// `RH_IN:`/`RH_OUT:` names.
    Furniture,
    /// A cluster: its `ClusterDocument` is a nested archive.
    Cluster,
    /// A Hops Get parameter (Get Number, Get Point, …): a named input, as a parameter node of
    /// this type.
    HopsGet(&'static str),
    /// A Hops output (Context Bake, Context Print): a named output, named as Compute names it
    /// after the nickname of the component's input, of the data wired into that input.
    HopsPut,
    /// A Hops call to a remote definition: unsupported.
    HopsCall,
}

/// The group type, whose `ID` items list the grouped objects.
pub const GROUP: &str = "c552a431-af5b-46a9-a8a4-0fcbc27ef596";

/// The cluster type, whose `ClusterDocument` item holds its definition.
pub const CLUSTER: &str = "f31d8d7a-7536-4ac8-9c96-fde6ecda4d0a";

/// The Cluster Input object inside a cluster's document (as the runxel tutorials' cluster
/// holds it): a parameter whose data is what the cluster's input is given.
pub const CLUSTER_INPUT: &str = "448de216-3a12-43cf-a135-e3bfafc87744";

/// The Cluster Output object inside a cluster's document: a parameter whose data is the
/// cluster's output.
pub const CLUSTER_OUTPUT: &str = "a4b285fe-2e13-4204-b65c-189aa6704da5";

/// Object types by GUID, with their treatment and a short reason shown in reports.
pub const KNOWN: &[(&str, &str, Special)] = &[
    (
        "57da07bd-ecab-415d-9d86-af36d7073abc",
        "Number Slider",
        Special::Slider,
    ),
    (
        "59e0b89a-e487-49f8-bab8-b5bab16be14c",
        "Panel",
        Special::Panel,
    ),
    (
        "bcac2747-348b-4edd-ae1f-77a782cebbdd",
        "Control Knob",
        Special::Knob,
    ),
    (
        "318dacd7-9073-4ede-b043-a0c132eb77e0",
        "MD Slider",
        Special::MdSlider,
    ),
    (
        "2e78987b-9dfb-42a2-8b76-3923ac8bd91a",
        "Boolean Toggle",
        Special::Toggle,
    ),
    (
        "a8b97322-2d53-47cd-905e-b932c3ccd74e",
        "Button",
        Special::Button,
    ),
    (
        "00027467-0d24-4fa7-b178-8dc0ac5f42ec",
        "Value List",
        Special::ValueList,
    ),
    (
        "8ec86459-bf01-4409-baee-174d0d2b13d0",
        "Data",
        Special::PassThrough,
    ),
    (
        "b6236720-8d88-4289-93c3-ac4c99f9b97b",
        "Relay",
        Special::PassThrough,
    ),
    (
        "8529dbdf-9b6f-42e9-8e1f-c7a2bde56a70",
        "Line",
        Special::PassThrough,
    ),
    (
        "d1028c72-ff86-4057-9eb0-36c687a4d98c",
        "Circle",
        Special::PassThrough,
    ),
    (
        "1e936df3-0eea-4246-8549-514cb8862b7a",
        "Mesh",
        Special::PassThrough,
    ),
    (
        "059b72b0-9bb3-4542-a805-2dcd27493164",
        "Cloud Display",
        Special::Display,
    ),
    (
        "9c53bac0-ba66-40bd-8154-ce9829b9db1a",
        "Colour Swatch",
        Special::Display,
    ),
    (
        "76975309-75a6-446a-afed-f8653720a9f2",
        "Create Material",
        Special::Display,
    ),
    (
        "537b0419-bbc2-4ff4-bf08-afe526367b2c",
        "Custom Preview",
        Special::Display,
    ),
    (
        "72a29b54-2e48-474b-a400-d2124c4edf79",
        "Param Viewer",
        Special::Display,
    ),
    (
        "1f18e802-4ab9-444f-bf3c-3e7e421a2acf",
        "Point List",
        Special::Display,
    ),
    (
        "cc14daa5-911a-4fcc-8b3b-1149bf7f2eeb",
        "Point List",
        Special::Display,
    ),
    (
        "0ad9f1ab-2204-45bb-b282-474469e2fa7b",
        "Point Order",
        Special::Display,
    ),
    (
        "2b69bf71-4e69-43aa-b7be-4f6ce7e45bef",
        "Quick Graph",
        Special::Display,
    ),
    (
        "79747717-1874-4c34-b790-faef53b50569",
        "Symbol (Simple)",
        Special::Display,
    ),
    (
        "62d5ead4-53c4-4d0b-b5ce-6bd6e0850ab8",
        "Symbol Display",
        Special::Display,
    ),
    (
        "3b220754-4114-4170-b6c3-b286b86ed524",
        "Text Tag",
        Special::Display,
    ),
    (
        "5a41528b-12b9-40dc-a3f2-842034d267c4",
        "Text Tag 3D",
        Special::Display,
    ),
    (
        "2a3f7078-2e25-4dd4-96f7-0efb491bd61c",
        "Vector Display",
        Special::Display,
    ),
    (
        "11e95a7b-1e2c-4b66-bd95-fcad51f8662a",
        "Vector Display Ex",
        Special::Display,
    ),
    (
        "5a2b0735-ba98-4b7d-a7d3-c1dfc04475ad",
        "Timer",
        Special::Timer,
    ),
    (GROUP, "Group", Special::Furniture),
    (
        "7f5c6c55-f846-4a08-9c9a-cfdc285cc6fe",
        "Scribble",
        Special::Furniture,
    ),
    (
        "2844fec5-142d-4381-bd5d-4cbcef6d6fed",
        "Sketch",
        Special::Furniture,
    ),
    (
        "f31d8d7a-7536-4ac8-9c96-fde6ecda4d0a",
        "Cluster",
        Special::Cluster,
    ),
    (
        "51ef601d-f86e-4ee4-bcf2-3d459d3e95e9",
        "Get Boolean",
        Special::HopsGet("params.boolean"),
    ),
    (
        "41dd7ba9-1f53-49d9-af42-a9270b0e9454",
        "Get Geometry",
        Special::HopsGet("params.geometry"),
    ),
    (
        "7b36b876-9451-46f5-8220-a200d969cc66",
        "Get Number",
        Special::HopsGet("params.number"),
    ),
    (
        "fed87bdd-8327-49cd-949c-09d70f3c345c",
        "Get String",
        Special::HopsGet("params.text"),
    ),
    (
        "b228887e-0852-4d9f-bd46-2591646e0d7c",
        "Get Integer",
        Special::HopsGet("params.integer"),
    ),
    (
        "997704ba-c1d3-4262-9090-927c81347ce6",
        "Get Point",
        Special::HopsGet("params.point"),
    ),
    (
        "88bd0e1d-363a-469f-9104-57d3aac5d6b8",
        "Get Plane",
        Special::HopsGet("params.plane"),
    ),
    (
        "af519c71-7dc1-4524-b8cc-add5544e2ef6",
        "Get Line",
        Special::HopsGet("params.line"),
    ),
    (
        "e83dd8b2-42aa-41e6-9254-882cddec0a2e",
        "Get File Path",
        Special::HopsGet("params.text"),
    ),
    (
        "ae2531b4-bab2-4bb1-b5bf-f2143d10c132",
        "Context Bake",
        Special::HopsPut,
    ),
    (
        "73215ec5-0eb5-4f85-9e07-b09c4590ce2b",
        "Context Print",
        Special::HopsPut,
    ),
    (
        "c69bb52c-88ba-4640-b69f-188d111029e8",
        "Hops",
        Special::HopsCall,
    ),
];

/// The special treatment of a type GUID, if any.
pub fn special(guid: &str) -> Option<Special> {
    KNOWN
        .iter()
        .find(|(g, _, _)| *g == guid)
        .map(|(_, _, s)| *s)
}
