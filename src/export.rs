//! `locus run --export FILE` and `locus render`: the geometry of a graph's outputs written as
//! glTF, OBJ, STL, SVG or PNG (crate `locus-export`).

use std::path::{Path, PathBuf};

use locus_export::{ExportOptions, Format, PictureOptions, Scene, Tessellation, View, export};
use locus_runtime::{Evaluator, NodeRegistry};

use crate::graph_file::RunLimits;
use crate::write_file::write_bytes_atomically;

/// The scene of the named outputs of an evaluated graph that `--output` selects, or with
/// `--preview` of every node's outputs, named `node.output`.
pub(crate) fn scene(evaluator: &Evaluator, limits: &RunLimits) -> Scene {
    let mut scene = Scene::new();
    let settings = Tessellation::default();
    if limits.previews_every_node() {
        for (node, output, tree) in evaluator.node_outputs() {
            scene.add_output(&format!("{node}.{output}"), tree, &settings);
        }
        return scene;
    }
    for (name, tree) in evaluator.outputs().filter(|(name, _)| limits.selects(name)) {
        scene.add_output(name, tree, &settings);
    }
    scene
}

/// Writes the outputs of an evaluated graph into each file, in the format its extension names.
///
/// # Errors
/// The first file that could not be written, with the reason.
pub(crate) fn write_files(
    evaluator: &Evaluator,
    limits: &RunLimits,
    files: &[PathBuf],
) -> Result<(), String> {
    if files.is_empty() {
        return Ok(());
    }
    let scene = scene(evaluator, limits);
    for line in &scene.skipped {
        eprintln!("locus: not exported: {line}");
    }
    for file in files {
        write_one(&scene, file, &ExportOptions::default())?;
    }
    Ok(())
}

fn write_one(scene: &Scene, file: &Path, options: &ExportOptions) -> Result<(), String> {
    let format = Format::from_path(file).map_err(|e| e.to_string())?;
    let bytes = export(scene, format, options).map_err(|e| format!("{}: {e}", file.display()))?;
    write_bytes_atomically(file, &bytes)
}

/// Parses `WIDTHxHEIGHT`.
pub(crate) fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let (w, h) = text
        .split_once(['x', 'X', '×'])
        .ok_or_else(|| format!("size `{text}` is not WIDTHxHEIGHT, e.g. 800x600"))?;
    let side = |s: &str| {
        s.trim()
            .parse::<u32>()
            .ok()
            .filter(|&n| (1..=locus_export::MAX_PICTURE_SIDE).contains(&n))
            .ok_or_else(|| {
                format!(
                    "size `{text}`: each side is 1 to {} pixels",
                    locus_export::MAX_PICTURE_SIDE
                )
            })
    };
    Ok((side(w)?, side(h)?))
}

/// The options of `locus render`.
pub(crate) struct RenderArgs<'a> {
    pub(crate) graph: &'a Path,
    pub(crate) sets: &'a [String],
    pub(crate) output: &'a Path,
    pub(crate) view: &'a str,
    pub(crate) size: &'a str,
    pub(crate) threads: Option<usize>,
    pub(crate) limits: &'a RunLimits,
}

/// `locus render`: evaluates a graph and draws its outputs into a picture (PNG) or drawing
/// (SVG, from the same view).
pub(crate) fn render(registry: &NodeRegistry, args: &RenderArgs<'_>) -> u8 {
    let (view, size) = match (args.view.parse::<View>(), parse_size(args.size)) {
        (Ok(v), Ok(s)) => (v, s),
        (Err(e), _) | (_, Err(e)) => {
            eprintln!("locus: {e}");
            return crate::EXIT_USAGE;
        }
    };
    let mut evaluator = match crate::graph_file::prepared(
        registry,
        args.graph,
        args.sets,
        args.threads,
        args.limits,
    ) {
        Ok(e) => e,
        Err(code) => return code,
    };
    evaluator.evaluate();
    for m in evaluator.messages() {
        eprintln!("{m}");
    }
    let scene = scene(&evaluator, args.limits);
    for line in &scene.skipped {
        eprintln!("locus: not drawn: {line}");
    }
    let options = ExportOptions {
        view,
        picture: PictureOptions {
            view,
            width: size.0,
            height: size.1,
            ..PictureOptions::default()
        },
        ..ExportOptions::default()
    };
    match write_one(&scene, args.output, &options) {
        Ok(()) => 0,
        Err(e) => {
            eprintln!("locus: {e}");
            crate::EXIT_EXPORT_FAILED
        }
    }
}

/// `locus view`: evaluates a graph and writes one self-contained HTML page that shows its
/// outputs in an orbit view with their messages; prints the page's path.
pub(crate) fn view(
    registry: &NodeRegistry,
    graph: &Path,
    sets: &[String],
    output: Option<&Path>,
    threads: Option<usize>,
    limits: &RunLimits,
) -> u8 {
    let mut evaluator = match crate::graph_file::prepared(registry, graph, sets, threads, limits) {
        Ok(e) => e,
        Err(code) => return code,
    };
    evaluator.evaluate();
    let scene = scene(&evaluator, limits);
    let messages: Vec<serde_json::Value> = evaluator
        .messages()
        .map(crate::render::message_json)
        .collect();
    let title = graph
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let page = match locus_export::to_html(&scene, &serde_json::Value::Array(messages), &title) {
        Ok(page) => page,
        Err(e) => {
            eprintln!("locus: {e}");
            return crate::EXIT_EXPORT_FAILED;
        }
    };
    let file = output.map_or_else(|| graph.with_extension("html"), Path::to_path_buf);
    match write_bytes_atomically(&file, page.as_bytes()) {
        Ok(()) => {
            println!("{}", file.display());
            0
        }
        Err(e) => {
            eprintln!("locus: {e}");
            crate::EXIT_EXPORT_FAILED
        }
    }
}
