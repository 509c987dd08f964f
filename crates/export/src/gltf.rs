//! glTF 2.0 export (`.glb` binary and `.gltf` with an embedded buffer), written with the
//! `gltf` crate's JSON model so that the document's schema is the crate's, not ours.
//!
//! Layout: one root node [`ROOT_NODE_NAME`] (`locus-root`; the scene is [`SCENE_NAME`],
//! `locus`, and a lookup by name must find the node, not the scene), one child node per output,
//! one child per branch (named by its path, `{0;1}`), one child per item (named `output {0;1}[2]`) holding a mesh whose primitives
//! are the item's triangles (with normals and colours), line strips and points. Every item node
//! carries `{"output", "path", "index", "value"}` in its `extras`.
//!
//! Coordinates: locus is Z-up, glTF is Y-up; a locus point `(x, y, z)` is written as glTF
//! `(x, z, −y)` (as Rhino's glTF exporter does). Vertices are stored as `f32` relative to the
//! centre of the scene's bounding box, which the root node's translation restores, so that
//! geometry far from the origin keeps its precision. glTF has no units: the model units go in
//! the scene's `extras` with the bounding box.

use std::collections::BTreeMap;

use gltf::json::{self, validation::Checked::Valid, validation::USize64};
use locus_kernel::{Color, Mesh, Point3, Vector3};
use serde_json::json;

/// The name of the glTF scene.
pub const SCENE_NAME: &str = "locus";

/// The name of the root node, the parent of one node per output. It differs from
/// [`SCENE_NAME`] so that a lookup by name (three.js's `getObjectByName`, which looks at the
/// scene first) finds the node.
pub const ROOT_NODE_NAME: &str = "locus-root";

use crate::ExportError;
use crate::scene::{Scene, SceneObject};

/// What the exported file says about the model.
#[derive(Clone, Debug, PartialEq)]
pub struct GltfOptions {
    /// The model's units, written into the scene's extras (`"units"`).
    pub units: String,
}

impl Default for GltfOptions {
    fn default() -> Self {
        Self {
            units: "model units".to_owned(),
        }
    }
}

/// The default colour of meshes without colours of their own (light grey).
pub const DEFAULT_MESH_COLOR: Color = Color::rgb(200, 200, 200);
/// The colour of curves and points (dark grey).
pub const DEFAULT_WIRE_COLOR: Color = Color::rgb(40, 40, 40);

fn to_gltf(p: Point3, origin: Point3) -> [f32; 3] {
    let d = p - origin;
    [d.x as f32, d.z as f32, -d.y as f32]
}

fn vec_to_gltf(v: Vector3) -> [f32; 3] {
    [v.x as f32, v.z as f32, -v.y as f32]
}

/// A branch's path and the nodes of its items.
type BranchNodes = (String, Vec<json::Index<json::Node>>);

/// How an accessor's elements are laid out.
#[derive(Clone, Copy)]
struct Layout {
    component: json::accessor::ComponentType,
    type_: json::accessor::Type,
    target: json::buffer::Target,
    normalized: bool,
}

const VEC3_F32: Layout = Layout {
    component: json::accessor::ComponentType::F32,
    type_: json::accessor::Type::Vec3,
    target: json::buffer::Target::ArrayBuffer,
    normalized: false,
};
const COLOUR_U8: Layout = Layout {
    component: json::accessor::ComponentType::U8,
    type_: json::accessor::Type::Vec4,
    target: json::buffer::Target::ArrayBuffer,
    normalized: true,
};
const INDEX_U32: Layout = Layout {
    component: json::accessor::ComponentType::U32,
    type_: json::accessor::Type::Scalar,
    target: json::buffer::Target::ElementArrayBuffer,
    normalized: false,
};

/// The glTF document under construction with its binary buffer.
struct Builder {
    root: json::Root,
    bin: Vec<u8>,
    origin: Point3,
    materials: BTreeMap<(u32, bool), json::Index<json::Material>>,
}

impl Builder {
    fn view(
        &mut self,
        bytes: &[u8],
        target: Option<json::buffer::Target>,
    ) -> json::Index<json::buffer::View> {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        let offset = self.bin.len();
        self.bin.extend_from_slice(bytes);
        self.root.push(json::buffer::View {
            buffer: json::Index::new(0),
            byte_length: USize64::from(bytes.len()),
            byte_offset: Some(USize64::from(offset)),
            byte_stride: None,
            extensions: None,
            extras: Default::default(),
            name: None,
            target: target.map(Valid),
        })
    }

    fn accessor(
        &mut self,
        bytes: &[u8],
        count: usize,
        layout: Layout,
        bounds: Option<([f32; 3], [f32; 3])>,
    ) -> json::Index<json::Accessor> {
        let view = self.view(bytes, Some(layout.target));
        self.root.push(json::Accessor {
            buffer_view: Some(view),
            byte_offset: None,
            count: USize64::from(count),
            component_type: Valid(json::accessor::GenericComponentType(layout.component)),
            extensions: None,
            extras: Default::default(),
            type_: Valid(layout.type_),
            min: bounds.map(|b| json!(b.0)),
            max: bounds.map(|b| json!(b.1)),
            name: None,
            normalized: layout.normalized,
            sparse: None,
        })
    }

    fn positions(&mut self, points: &[Point3]) -> json::Index<json::Accessor> {
        let mut bytes = Vec::with_capacity(points.len() * 12);
        let (mut lo, mut hi) = ([f32::MAX; 3], [f32::MIN; 3]);
        for &p in points {
            let q = to_gltf(p, self.origin);
            for k in 0..3 {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
                bytes.extend_from_slice(&q[k].to_le_bytes());
            }
        }
        self.accessor(&bytes, points.len(), VEC3_F32, Some((lo, hi)))
    }

    fn material(&mut self, color: Color, unlit_wire: bool) -> json::Index<json::Material> {
        if let Some(&m) = self.materials.get(&(color.to_argb(), unlit_wire)) {
            return m;
        }
        let c = |v: u8| f32::from(v) / 255.0;
        let material = json::Material {
            alpha_cutoff: None,
            alpha_mode: Valid(if color.a == 255 {
                json::material::AlphaMode::Opaque
            } else {
                json::material::AlphaMode::Blend
            }),
            double_sided: true,
            name: Some(if unlit_wire {
                "wire".into()
            } else {
                "surface".into()
            }),
            pbr_metallic_roughness: json::material::PbrMetallicRoughness {
                base_color_factor: json::material::PbrBaseColorFactor([
                    c(color.r),
                    c(color.g),
                    c(color.b),
                    c(color.a),
                ]),
                metallic_factor: json::material::StrengthFactor(0.0),
                roughness_factor: json::material::StrengthFactor(0.9),
                ..Default::default()
            },
            ..Default::default()
        };
        let index = self.root.push(material);
        self.materials.insert((color.to_argb(), unlit_wire), index);
        index
    }

    fn mesh_primitive(&mut self, mesh: &Mesh, color: Option<Color>) -> json::mesh::Primitive {
        let mut attributes = BTreeMap::new();
        attributes.insert(
            Valid(json::mesh::Semantic::Positions),
            self.positions(mesh.vertices()),
        );
        let normals = match mesh.normals() {
            Some(n) => n.to_vec(),
            None => mesh
                .clone()
                .with_computed_normals()
                .normals()
                .unwrap_or_default()
                .to_vec(),
        };
        let mut bytes = Vec::with_capacity(normals.len() * 12);
        for n in &normals {
            for x in vec_to_gltf(*n) {
                bytes.extend_from_slice(&x.to_le_bytes());
            }
        }
        let normal_accessor = self.accessor(&bytes, normals.len(), VEC3_F32, None);
        attributes.insert(Valid(json::mesh::Semantic::Normals), normal_accessor);
        if let Some(colors) = mesh.colors() {
            let bytes: Vec<u8> = colors.iter().flat_map(|c| [c.r, c.g, c.b, c.a]).collect();
            let colour_accessor = self.accessor(&bytes, colors.len(), COLOUR_U8, None);
            attributes.insert(Valid(json::mesh::Semantic::Colors(0)), colour_accessor);
        }
        let mut bytes = Vec::with_capacity(mesh.triangle_count() * 12);
        for t in mesh.triangles() {
            for v in t {
                bytes.extend_from_slice(&v.to_le_bytes());
            }
        }
        let indices = self.accessor(&bytes, mesh.triangle_count() * 3, INDEX_U32, None);
        // With vertex colours the material is white so that the colours show as they are.
        let base = if mesh.colors().is_some() {
            Color::WHITE
        } else {
            color.unwrap_or(DEFAULT_MESH_COLOR)
        };
        json::mesh::Primitive {
            attributes,
            extensions: None,
            extras: Default::default(),
            indices: Some(indices),
            material: Some(self.material(base, false)),
            mode: Valid(json::mesh::Mode::Triangles),
            targets: None,
        }
    }

    fn wire_primitive(
        &mut self,
        points: &[Point3],
        mode: json::mesh::Mode,
        color: Option<Color>,
    ) -> json::mesh::Primitive {
        let mut attributes = BTreeMap::new();
        attributes.insert(
            Valid(json::mesh::Semantic::Positions),
            self.positions(points),
        );
        json::mesh::Primitive {
            attributes,
            extensions: None,
            extras: Default::default(),
            indices: None,
            material: Some(self.material(color.unwrap_or(DEFAULT_WIRE_COLOR), true)),
            mode: Valid(mode),
            targets: None,
        }
    }

    fn object_node(&mut self, object: &SceneObject) -> json::Index<json::Node> {
        let mut primitives = Vec::new();
        if let Some(mesh) = object.mesh.as_ref().filter(|m| !m.is_empty()) {
            primitives.push(self.mesh_primitive(mesh, object.color));
        }
        for line in object.lines.iter().filter(|l| l.len() >= 2) {
            primitives.push(self.wire_primitive(line, json::mesh::Mode::LineStrip, object.color));
        }
        if !object.points.is_empty() {
            primitives.push(self.wire_primitive(
                &object.points,
                json::mesh::Mode::Points,
                object.color,
            ));
        }
        let mesh = (!primitives.is_empty()).then(|| {
            self.root.push(json::Mesh {
                extensions: None,
                extras: Default::default(),
                name: Some(object.name()),
                primitives,
                weights: None,
            })
        });
        let extras = json!({
            "output": object.output,
            "path": object.path.to_string(),
            "index": object.index,
            "value": object.label,
        });
        self.root.push(json::Node {
            mesh,
            name: Some(object.name()),
            extras: Some(serde_json::value::to_raw_value(&extras).expect("extras are JSON")),
            ..Default::default()
        })
    }
}

/// The scene as a glTF document and its binary buffer.
fn build(scene: &Scene, options: &GltfOptions) -> Result<(json::Root, Vec<u8>), ExportError> {
    let bbox = scene.bounding_box();
    let origin = if bbox.is_empty() {
        Point3::ORIGIN
    } else {
        bbox.center()
    };
    let mut b = Builder {
        root: json::Root::default(),
        bin: Vec::new(),
        origin,
        materials: BTreeMap::new(),
    };
    b.root.asset = json::Asset {
        generator: Some(format!("locus {}", env!("CARGO_PKG_VERSION"))),
        ..Default::default()
    };
    // Outputs in first-seen order, branches in path order within each output.
    let mut outputs: Vec<(String, Vec<BranchNodes>)> = Vec::new();
    for object in &scene.objects {
        let node = b.object_node(object);
        if outputs
            .last()
            .is_none_or(|(name, _)| *name != object.output)
        {
            outputs.push((object.output.clone(), Vec::new()));
        }
        let branches = &mut outputs.last_mut().expect("pushed above").1;
        let path = object.path.to_string();
        if branches.last().is_none_or(|(p, _)| *p != path) {
            branches.push((path, Vec::new()));
        }
        branches.last_mut().expect("pushed above").1.push(node);
    }
    let mut output_nodes = Vec::new();
    for (name, branches) in outputs {
        let children: Vec<_> = branches
            .into_iter()
            .map(|(path, items)| {
                b.root.push(json::Node {
                    name: Some(path.clone()),
                    children: Some(items),
                    extras: Some(
                        serde_json::value::to_raw_value(&json!({"output": name, "path": path}))
                            .expect("JSON"),
                    ),
                    ..Default::default()
                })
            })
            .collect();
        output_nodes.push(b.root.push(json::Node {
            name: Some(name.clone()),
            children: Some(children),
            extras: Some(serde_json::value::to_raw_value(&json!({"output": name})).expect("JSON")),
            ..Default::default()
        }));
    }
    let top = b.root.push(json::Node {
        name: Some(ROOT_NODE_NAME.into()),
        children: (!output_nodes.is_empty()).then_some(output_nodes),
        translation: Some(to_gltf(origin, Point3::ORIGIN)),
        ..Default::default()
    });
    let extras = json!({
        "units": options.units,
        "up": "Z in locus; written Y-up as glTF requires: glTF (x, y, z) = locus (x, z, -y)",
        "bounding_box": if bbox.is_empty() { serde_json::Value::Null } else {
            json!({"min": [bbox.min.x, bbox.min.y, bbox.min.z], "max": [bbox.max.x, bbox.max.y, bbox.max.z]})
        },
        "skipped": scene.skipped,
    });
    let scene_index = b.root.push(json::Scene {
        extensions: None,
        extras: Some(serde_json::value::to_raw_value(&extras).expect("JSON")),
        name: Some(SCENE_NAME.into()),
        nodes: vec![top],
    });
    b.root.scene = Some(scene_index);
    while !b.bin.len().is_multiple_of(4) {
        b.bin.push(0);
    }
    if !b.bin.is_empty() {
        b.root.push(json::Buffer {
            byte_length: USize64::from(b.bin.len()),
            extensions: None,
            extras: Default::default(),
            name: None,
            uri: None,
        });
    }
    Ok((b.root, b.bin))
}

/// The scene as binary glTF (`.glb`).
///
/// # Errors
/// [`ExportError::TooLarge`] when the buffer passes glTF's 4 GiB limit.
pub fn to_glb(scene: &Scene, options: &GltfOptions) -> Result<Vec<u8>, ExportError> {
    let (root, bin) = build(scene, options)?;
    if bin.len() > u32::MAX as usize - 1024 {
        return Err(ExportError::TooLarge { bytes: bin.len() });
    }
    let json = root
        .to_vec()
        .map_err(|e| ExportError::Format(e.to_string()))?;
    let glb = gltf::binary::Glb {
        header: gltf::binary::Header {
            magic: *b"glTF",
            version: 2,
            length: 0,
        },
        json: json.into(),
        bin: (!bin.is_empty()).then_some(bin.into()),
    };
    glb.to_vec().map_err(|e| ExportError::Format(e.to_string()))
}

/// The scene as text glTF (`.gltf`) with its buffer embedded as a base64 data URI.
///
/// # Errors
/// As [`to_glb`].
pub fn to_gltf_text(scene: &Scene, options: &GltfOptions) -> Result<String, ExportError> {
    use base64::Engine as _;
    let (mut root, bin) = build(scene, options)?;
    if let Some(buffer) = root.buffers.first_mut() {
        let data = base64::engine::general_purpose::STANDARD.encode(&bin);
        buffer.uri = Some(format!("data:application/octet-stream;base64,{data}"));
    }
    root.to_string_pretty()
        .map_err(|e| ExportError::Format(e.to_string()))
}
