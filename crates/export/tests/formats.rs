//! Every format on real graphs: the tutorial graphs evaluated with the node library, exported,
//! and read back by independent readers (the `gltf` crate's reader for glTF; our own parse of
//! the simple OBJ/STL layouts) with the right counts and bounding boxes.

use std::path::Path;

use locus_export::{
    ExportOptions, Format, PictureOptions, Scene, Tessellation, View, drawn_extent, export, render,
};
use locus_kernel::{BoundingBox, Color, Point3};
use locus_runtime::{Evaluator, NodeRegistry};

fn scene_of(graph: &str) -> Scene {
    scene_with(graph, false)
}

/// The scene of a graph's named outputs, or (`preview`) of every node's outputs as
/// `locus render --preview` draws them.
fn scene_with(graph: &str, preview: bool) -> Scene {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../graphs")
        .join(graph);
    let mut evaluator = Evaluator::from_file(&path, &registry).expect("graph loads");
    if preview {
        evaluator.keep_all_outputs();
    }
    evaluator.evaluate();
    let mut scene = Scene::new();
    if preview {
        for (node, output, tree) in evaluator.node_outputs() {
            scene.add_output(&format!("{node}.{output}"), tree, &Tessellation::default());
        }
    } else {
        for (name, tree) in evaluator.outputs() {
            scene.add_output(name, tree, &Tessellation::default());
        }
    }
    assert!(scene.skipped.is_empty(), "{:?}", scene.skipped);
    scene
}

/// Reads a .glb back with the `gltf` crate: (triangle vertices, line vertices, points, bbox in
/// locus coordinates), undoing the Y-up conversion and the root translation.
fn read_glb(bytes: &[u8]) -> (usize, usize, usize, BoundingBox, Vec<serde_json::Value>) {
    let gltf = gltf::Gltf::from_slice(bytes).expect("valid glTF");
    let blob = gltf.blob.clone().expect("a BIN chunk");
    let root = gltf
        .document
        .nodes()
        .find(|n| n.name() == Some(locus_export::ROOT_NODE_NAME))
        .unwrap();
    let t = root.transform().decomposed().0;
    let origin = Point3::new(f64::from(t[0]), -f64::from(t[2]), f64::from(t[1]));
    let (mut tri, mut line, mut pts) = (0, 0, 0);
    let mut bbox = BoundingBox::EMPTY;
    let mut extras = Vec::new();
    for node in gltf.document.nodes() {
        if let Some(mesh) = node.mesh() {
            extras.push(serde_json::from_str(node.extras().as_ref().unwrap().get()).unwrap());
            for primitive in mesh.primitives() {
                let reader = primitive.reader(|_| Some(&blob));
                let positions: Vec<[f32; 3]> = reader.read_positions().unwrap().collect();
                for p in &positions {
                    let q = Point3::new(f64::from(p[0]), -f64::from(p[2]), f64::from(p[1]));
                    bbox.include_point(origin + (q - Point3::ORIGIN));
                }
                match primitive.mode() {
                    gltf::mesh::Mode::Triangles => {
                        let indices: Vec<u32> = reader.read_indices().unwrap().into_u32().collect();
                        assert!(indices.iter().all(|&i| (i as usize) < positions.len()));
                        assert!(reader.read_normals().is_some());
                        tri += indices.len();
                    }
                    gltf::mesh::Mode::LineStrip => line += positions.len(),
                    gltf::mesh::Mode::Points => pts += positions.len(),
                    other => panic!("unexpected mode {other:?}"),
                }
            }
        }
    }
    (tri, line, pts, bbox, extras)
}

fn close(a: &BoundingBox, b: &BoundingBox, tol: f64) -> bool {
    (a.min - b.min).length() <= tol && (a.max - b.max).length() <= tol
}

#[test]
fn glb_of_the_exploded_box_reads_back_with_counts_and_bounds() {
    let scene = scene_of("exploded_box.ron");
    let glb = export(&scene, Format::Glb, &ExportOptions::default()).unwrap();
    let (tri, line, pts, bbox, extras) = read_glb(&glb);
    assert_eq!(tri, 3 * scene.triangle_count());
    let lines: usize = scene
        .objects
        .iter()
        .flat_map(|o| &o.lines)
        .map(Vec::len)
        .sum();
    let points: usize = scene.objects.iter().map(|o| o.points.len()).sum();
    assert_eq!((line, pts), (lines, points));
    assert!(
        close(&bbox, &scene.bounding_box(), 1e-4),
        "{bbox:?} vs {:?}",
        scene.bounding_box()
    );
    // Every item node names its output, path and index.
    assert_eq!(extras.len(), scene.objects.len());
    for (e, o) in extras.iter().zip(&scene.objects) {
        assert_eq!(e["output"], o.output.as_str());
        assert_eq!(e["path"], o.path.to_string().as_str());
        assert_eq!(e["index"], o.index);
    }
}

#[test]
fn gltf_text_embeds_the_same_buffer() {
    let scene = scene_of("tangent_spheres.ron");
    let text = export(&scene, Format::Gltf, &ExportOptions::default()).unwrap();
    let gltf = gltf::Gltf::from_slice(&text).expect("valid glTF text");
    let uri = match gltf.document.buffers().next().unwrap().source() {
        gltf::buffer::Source::Uri(uri) => uri.to_owned(),
        gltf::buffer::Source::Bin => panic!("the buffer is embedded"),
    };
    assert!(uri.starts_with("data:application/octet-stream;base64,"));
    let glb = export(&scene, Format::Glb, &ExportOptions::default()).unwrap();
    let blob = gltf::Gltf::from_slice(&glb).unwrap().blob.unwrap();
    use base64::Engine as _;
    let data = base64::engine::general_purpose::STANDARD
        .decode(&uri["data:application/octet-stream;base64,".len()..])
        .unwrap();
    assert_eq!(data, blob);
}

#[test]
fn stl_holds_every_triangle_and_obj_every_vertex() {
    let scene = scene_of("exploded_box.ron");
    let stl = export(&scene, Format::Stl, &ExportOptions::default()).unwrap();
    let count = u32::from_le_bytes(stl[80..84].try_into().unwrap()) as usize;
    assert_eq!(count, scene.triangle_count());
    assert_eq!(stl.len(), 84 + 50 * count);
    let obj =
        String::from_utf8(export(&scene, Format::Obj, &ExportOptions::default()).unwrap()).unwrap();
    let vertices = obj.lines().filter(|l| l.starts_with("v ")).count();
    let expected: usize = scene
        .objects
        .iter()
        .map(|o| {
            o.mesh.as_ref().map_or(0, |m| m.vertices().len())
                + o.lines.iter().map(Vec::len).sum::<usize>()
                + o.points.len()
        })
        .sum();
    assert_eq!(vertices, expected);
    // Face indices are 1-based and name existing vertices.
    for l in obj.lines().filter(|l| l.starts_with("f ")) {
        for v in l[2..].split_whitespace() {
            let i: usize = v.split('/').next().unwrap().parse().unwrap();
            assert!((1..=vertices).contains(&i));
        }
    }
}

#[test]
fn svg_is_well_formed_and_holds_every_item() {
    let scene = scene_of("tangent_spheres.ron");
    let svg =
        String::from_utf8(export(&scene, Format::Svg, &ExportOptions::default()).unwrap()).unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert_eq!(svg.matches("data-output=").count(), scene.objects.len());
    assert_eq!(svg.matches("<g").count(), svg.matches("</g>").count());
}

#[test]
fn pictures_of_the_tutorials_are_not_blank_and_fit_the_geometry() {
    let named = [
        "exploded_box.ron",
        "tangent_spheres.ron",
        "multiple_transformations.ron",
        "face_direction.ron",
    ]
    .map(|g| (g, false));
    // Every tutorial as `locus render --preview` draws it (every node's geometry).
    let previews = [
        "exploded_box.ron",
        "tangent_spheres.ron",
        "multiple_transformations.ron",
        "face_direction.ron",
        "curve_continuity_tutorial.ron",
        "surface_singularity.ron",
    ]
    .map(|g| (g, true));
    for (graph, preview) in named.into_iter().chain(previews) {
        let scene = scene_with(graph, preview);
        for view in [View::Top, View::Front, View::Iso] {
            let options = PictureOptions {
                view,
                width: 400,
                height: 300,
                background: Color::WHITE,
            };
            let pixmap = render(&scene, &options).unwrap();
            let (x0, y0, x1, y1) = drawn_extent(&pixmap, Color::WHITE)
                .unwrap_or_else(|| panic!("{graph} {view:?} (preview {preview}) is blank"));
            // The geometry fills 90 % of the tighter side, centred.
            let (w, h) = (f64::from(x1 - x0 + 1), f64::from(y1 - y0 + 1));
            assert!(
                w >= 0.85 * 400.0 || h >= 0.85 * 300.0,
                "{graph} {view:?}: {w}×{h}"
            );
            assert!(
                w <= 0.95 * 400.0 + 4.0 && h <= 0.95 * 300.0 + 4.0,
                "{graph} {view:?}: {w}×{h}"
            );
            let centre = (f64::from(x0 + x1) / 2.0, f64::from(y0 + y1) / 2.0);
            assert!(
                (centre.0 - 200.0).abs() < 8.0 && (centre.1 - 150.0).abs() < 8.0,
                "{graph} {view:?}: {centre:?}"
            );
        }
    }
}

#[test]
fn an_empty_scene_exports_and_draws_nothing() {
    let scene = Scene::new();
    for format in [
        Format::Glb,
        Format::Gltf,
        Format::Obj,
        Format::Stl,
        Format::Svg,
        Format::Png,
    ] {
        export(&scene, format, &ExportOptions::default()).unwrap();
    }
    let pixmap = render(&scene, &PictureOptions::default()).unwrap();
    assert_eq!(drawn_extent(&pixmap, Color::WHITE), None);
    let bad = PictureOptions {
        width: 0,
        ..PictureOptions::default()
    };
    assert!(render(&scene, &bad).is_err());
}
