//! Pictures without a browser: a scene drawn into a PNG in pure Rust (tiny-skia), as a shaded
//! parallel view with edges, curves and points.
//!
//! Everything is drawn back to front (the painter's algorithm): triangles, line segments and
//! points are sorted by depth along the view, farthest first, so nearer surfaces hide what is
//! behind them. Triangles are flat-shaded with a light over the viewer's shoulder; curves and
//! edges are drawn a little in front of the surfaces they lie on so that they stay visible.

use locus_kernel::{Color, Point3, Vector3};
use tiny_skia::{FillRule, Paint, PathBuilder, Pixmap, Stroke, Transform as Affine};

use crate::ExportError;
use crate::gltf::{DEFAULT_MESH_COLOR, DEFAULT_WIRE_COLOR};
use crate::scene::Scene;
use crate::view::View;

/// The largest picture side, in pixels.
pub const MAX_PICTURE_SIDE: u32 = 8192;

/// How to draw a picture.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PictureOptions {
    /// The view direction.
    pub view: View,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The background.
    pub background: Color,
}

impl Default for PictureOptions {
    fn default() -> Self {
        Self {
            view: View::Iso,
            width: 800,
            height: 600,
            background: Color::WHITE,
        }
    }
}

/// One thing to draw, with its depth.
enum Primitive {
    Triangle([(f32, f32); 3], Color),
    Segment([(f32, f32); 2], Color),
    Dot((f32, f32), Color),
}

/// The scene drawn as an RGBA picture.
///
/// # Errors
/// [`ExportError::Picture`] for a size of zero or above [`MAX_PICTURE_SIDE`].
pub fn render(scene: &Scene, options: &PictureOptions) -> Result<Pixmap, ExportError> {
    let (w, h) = (options.width, options.height);
    if w == 0 || h == 0 || w > MAX_PICTURE_SIDE || h > MAX_PICTURE_SIDE {
        return Err(ExportError::Picture(format!(
            "picture size {w}×{h} is outside 1–{MAX_PICTURE_SIDE} pixels a side"
        )));
    }
    let mut pixmap =
        Pixmap::new(w, h).ok_or_else(|| ExportError::Picture("cannot allocate".into()))?;
    let bg = options.background;
    pixmap.fill(tiny_skia::Color::from_rgba8(bg.r, bg.g, bg.b, bg.a));
    let view = options.view;
    let (_, _, forward) = view.axes();

    // Fit the projected geometry into the picture with a 5 % margin.
    let (mut lo, mut hi) = (
        (f64::INFINITY, f64::INFINITY),
        (f64::NEG_INFINITY, f64::NEG_INFINITY),
    );
    let (mut near, mut far) = (f64::INFINITY, f64::NEG_INFINITY);
    for object in &scene.objects {
        let mesh_points = object.mesh.iter().flat_map(|m| m.vertices().iter());
        for &p in mesh_points
            .chain(object.lines.iter().flatten())
            .chain(&object.points)
        {
            let (x, y, d) = view.project(p);
            lo = (lo.0.min(x), lo.1.min(y));
            hi = (hi.0.max(x), hi.1.max(y));
            near = near.min(d);
            far = far.max(d);
        }
    }
    if !(lo.0.is_finite() && hi.0.is_finite()) {
        return Ok(pixmap);
    }
    let span = ((hi.0 - lo.0) / f64::from(w))
        .max((hi.1 - lo.1) / f64::from(h))
        .max(1e-300);
    let scale = 0.9 / span;
    let centre = (0.5 * (lo.0 + hi.0), 0.5 * (lo.1 + hi.1));
    let to_screen = |p: Point3| {
        let (x, y, d) = view.project(p);
        let sx = f64::from(w) * 0.5 + (x - centre.0) * scale;
        let sy = f64::from(h) * 0.5 - (y - centre.1) * scale;
        ((sx as f32, sy as f32), d)
    };
    // Lines are pulled towards the viewer by a small fraction of the depth range.
    let bias = 1e-3 * (far - near).max(1e-12);
    let light = (-forward + Vector3::new(0.2, 0.3, 0.4)).normalize_or_zero();

    let mut primitives: Vec<(f64, Primitive)> = Vec::new();
    for object in &scene.objects {
        if let Some(mesh) = &object.mesh {
            let v = mesh.vertices();
            let base = object.color.unwrap_or(DEFAULT_MESH_COLOR);
            for t in mesh.triangles() {
                let [p, q, r] = t.map(|i| v[i as usize]);
                let Ok(n) = (q - p).cross(r - p).unitize() else {
                    continue;
                };
                let shade = 0.35 + 0.65 * n.dot(light).abs();
                let colour = match mesh.colors() {
                    Some(c) => c[t[0] as usize],
                    None => base,
                };
                let s = |c: u8| (f64::from(c) * shade).round().clamp(0.0, 255.0) as u8;
                let shaded = Color::rgba(s(colour.r), s(colour.g), s(colour.b), colour.a);
                let (a, da) = to_screen(p);
                let (b, db) = to_screen(q);
                let (c, dc) = to_screen(r);
                primitives.push(((da + db + dc) / 3.0, Primitive::Triangle([a, b, c], shaded)));
            }
        }
        let wire = object.color.unwrap_or(DEFAULT_WIRE_COLOR);
        let edge = if object.mesh.is_some() {
            Color::rgb(60, 60, 60)
        } else {
            wire
        };
        for line in &object.lines {
            for s in line.windows(2) {
                let (a, da) = to_screen(s[0]);
                let (b, db) = to_screen(s[1]);
                primitives.push((0.5 * (da + db) - bias, Primitive::Segment([a, b], edge)));
            }
        }
        for &p in &object.points {
            let (a, d) = to_screen(p);
            primitives.push((d - 2.0 * bias, Primitive::Dot(a, wire)));
        }
    }
    // Farthest first; ties keep scene order (a stable sort), so pictures are deterministic.
    primitives.sort_by(|a, b| b.0.total_cmp(&a.0));

    let mut paint = Paint::default();
    let stroke = Stroke {
        width: 1.2,
        ..Stroke::default()
    };
    let dot_radius = (f64::from(w.min(h)) / 200.0).clamp(1.5, 6.0) as f32;
    for (_, primitive) in &primitives {
        match primitive {
            Primitive::Triangle([a, b, c], colour) => {
                let mut pb = PathBuilder::new();
                pb.move_to(a.0, a.1);
                pb.line_to(b.0, b.1);
                pb.line_to(c.0, c.1);
                pb.close();
                let Some(path) = pb.finish() else { continue };
                paint.set_color_rgba8(colour.r, colour.g, colour.b, colour.a);
                // No anti-aliasing inside meshes: it would show the seams between triangles.
                paint.anti_alias = false;
                pixmap.fill_path(&path, &paint, FillRule::Winding, Affine::identity(), None);
                // A hairline of the same colour closes the gaps the rasteriser leaves.
                pixmap.stroke_path(
                    &path,
                    &paint,
                    &Stroke {
                        width: 0.5,
                        ..Stroke::default()
                    },
                    Affine::identity(),
                    None,
                );
            }
            Primitive::Segment([a, b], colour) => {
                let mut pb = PathBuilder::new();
                pb.move_to(a.0, a.1);
                pb.line_to(b.0, b.1);
                let Some(path) = pb.finish() else { continue };
                paint.set_color_rgba8(colour.r, colour.g, colour.b, colour.a);
                paint.anti_alias = true;
                pixmap.stroke_path(&path, &paint, &stroke, Affine::identity(), None);
            }
            Primitive::Dot(a, colour) => {
                let Some(path) = PathBuilder::from_circle(a.0, a.1, dot_radius) else {
                    continue;
                };
                paint.set_color_rgba8(colour.r, colour.g, colour.b, colour.a);
                paint.anti_alias = true;
                pixmap.fill_path(&path, &paint, FillRule::Winding, Affine::identity(), None);
            }
        }
    }
    Ok(pixmap)
}

/// The scene drawn as PNG bytes.
///
/// # Errors
/// As [`render`], or when PNG encoding fails.
pub fn render_png(scene: &Scene, options: &PictureOptions) -> Result<Vec<u8>, ExportError> {
    render(scene, options)?
        .encode_png()
        .map_err(|e| ExportError::Picture(e.to_string()))
}

/// The bounding box, in pixels, of the pixels that differ from the background:
/// `(min_x, min_y, max_x, max_y)`, or `None` for a blank picture.
pub fn drawn_extent(pixmap: &Pixmap, background: Color) -> Option<(u32, u32, u32, u32)> {
    let bg = [background.r, background.g, background.b, background.a];
    let mut extent: Option<(u32, u32, u32, u32)> = None;
    for (i, px) in pixmap.pixels().iter().enumerate() {
        let c = px.demultiply();
        if [c.red(), c.green(), c.blue(), c.alpha()] != bg {
            let (x, y) = (i as u32 % pixmap.width(), i as u32 / pixmap.width());
            extent = Some(match extent {
                None => (x, y, x, y),
                Some((a, b, c, d)) => (a.min(x), b.min(y), c.max(x), d.max(y)),
            });
        }
    }
    extent
}
