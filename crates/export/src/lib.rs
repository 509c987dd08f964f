//! What a graph makes, as files and pictures: glTF 2.0 (`.glb`, `.gltf`), Wavefront OBJ,
//! binary STL, SVG plan drawings and PNG pictures drawn in pure Rust.
//!
//! Every format reads a [`Scene`]: the named outputs of an evaluation, turned into meshes,
//! polylines and points once (through the kernel's tessellation: curves as polylines, surfaces and B-reps as meshes),
//! each item remembering its output, tree path and index.
//!
//! ```
//! use locus_export::{Format, Scene, Tessellation, export};
//! use locus_kernel::Point3;
//! use locus_runtime::DataTree;
//!
//! let mut scene = Scene::new();
//! let points = DataTree::from_list(vec![Point3::ORIGIN, Point3::new(1.0, 2.0, 0.0)]);
//! scene.add_output("P", &points, &Tessellation::default());
//! let glb = export(&scene, Format::Glb, &Default::default()).unwrap();
//! assert_eq!(&glb[..4], b"glTF");
//! ```

mod gltf;
mod obj;
mod raster;
mod scene;
mod stl;
mod svg;
mod tessellate;
mod view;
mod viewer;

use std::path::Path;

pub use crate::gltf::{
    DEFAULT_MESH_COLOR, DEFAULT_WIRE_COLOR, GltfOptions, ROOT_NODE_NAME, SCENE_NAME, to_glb,
    to_gltf_text,
};
pub use crate::obj::to_obj;
pub use crate::raster::{MAX_PICTURE_SIDE, PictureOptions, drawn_extent, render, render_png};
pub use crate::scene::{Scene, SceneObject};
pub use crate::stl::to_stl;
pub use crate::svg::to_svg;
pub use crate::tessellate::Tessellation;
pub use crate::view::View;
pub use crate::viewer::{to_html, to_live_html};

/// Why an export failed.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// A file name whose extension names no format.
    #[error("cannot tell the format of `{0}`: use .glb, .gltf, .obj, .stl, .svg or .png")]
    UnknownFormat(String),
    /// The data is too large for the format.
    #[error("{bytes} bytes of geometry are more than glTF's 4 GiB buffer can hold")]
    TooLarge {
        /// The size of the buffer.
        bytes: usize,
    },
    /// The format's writer failed.
    #[error("cannot write the file: {0}")]
    Format(String),
    /// A picture could not be drawn.
    #[error("cannot draw the picture: {0}")]
    Picture(String),
}

/// The file formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Binary glTF 2.0.
    Glb,
    /// Text glTF 2.0 with the buffer embedded.
    Gltf,
    /// Wavefront OBJ.
    Obj,
    /// Binary STL (meshes only).
    Stl,
    /// An SVG drawing from the view of [`ExportOptions::view`] (plan by default).
    Svg,
    /// A PNG picture.
    Png,
}

impl Format {
    /// The format named by a file's extension.
    ///
    /// # Errors
    /// [`ExportError::UnknownFormat`].
    pub fn from_path(path: &Path) -> Result<Self, ExportError> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .unwrap_or("")
            .to_ascii_lowercase();
        Ok(match ext.as_str() {
            "glb" => Format::Glb,
            "gltf" => Format::Gltf,
            "obj" => Format::Obj,
            "stl" => Format::Stl,
            "svg" => Format::Svg,
            "png" => Format::Png,
            _ => return Err(ExportError::UnknownFormat(path.display().to_string())),
        })
    }
}

/// Options of every format.
#[derive(Clone, Debug, PartialEq)]
pub struct ExportOptions {
    /// glTF's options.
    pub gltf: GltfOptions,
    /// The view of SVG drawings (plan by default).
    pub view: View,
    /// The picture's options (PNG).
    pub picture: PictureOptions,
}

impl Default for ExportOptions {
    fn default() -> Self {
        Self {
            gltf: GltfOptions::default(),
            view: View::Top,
            picture: PictureOptions::default(),
        }
    }
}

/// The scene in a format, as bytes.
///
/// # Errors
/// As the format's writer.
pub fn export(
    scene: &Scene,
    format: Format,
    options: &ExportOptions,
) -> Result<Vec<u8>, ExportError> {
    Ok(match format {
        Format::Glb => to_glb(scene, &options.gltf)?,
        Format::Gltf => to_gltf_text(scene, &options.gltf)?.into_bytes(),
        Format::Obj => to_obj(scene).into_bytes(),
        Format::Stl => to_stl(scene),
        Format::Svg => to_svg(scene, options.view).into_bytes(),
        Format::Png => render_png(scene, &options.picture)?,
    })
}
