//! SVG export: a parallel view (plan by default) of curves, points and mesh outlines, in model
//! units, for 2-D work and laser cutting.
//!
//! The drawing's `viewBox` is the projected bounding box in model units (with y flipped so
//! that up is up) plus a 2 % margin; strokes do not scale. Meshes are drawn as filled,
//! outlined polygons, curves as polylines, points as small circles. Each item is a `<g>` with
//! `data-output`, `data-path` and `data-index` attributes.

use std::fmt::Write as _;

use crate::scene::Scene;
use crate::view::View;

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The scene drawn from `view` as SVG text.
pub fn to_svg(scene: &Scene, view: View) -> String {
    let mut lo = (f64::INFINITY, f64::INFINITY);
    let mut hi = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    let mut include = |x: f64, y: f64| {
        lo = (lo.0.min(x), lo.1.min(y));
        hi = (hi.0.max(x), hi.1.max(y));
    };
    for o in &scene.objects {
        let mesh_points = o.mesh.iter().flat_map(|m| m.vertices().iter());
        for &p in mesh_points.chain(o.lines.iter().flatten()).chain(&o.points) {
            let (x, y, _) = view.project(p);
            include(x, -y);
        }
    }
    if !lo.0.is_finite() {
        lo = (0.0, 0.0);
        hi = (1.0, 1.0);
    }
    let size = (hi.0 - lo.0).max(hi.1 - lo.1).max(1e-9);
    let margin = 0.02 * size;
    let (x0, y0) = (lo.0 - margin, lo.1 - margin);
    let (w, h) = (hi.0 - lo.0 + 2.0 * margin, hi.1 - lo.1 + 2.0 * margin);
    let dot = 0.004 * size;
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="{x0} {y0} {w} {h}" width="{w}" height="{h}">"#
    );
    let _ = writeln!(out, "<title>locus {view:?} view</title>");
    let _ = writeln!(
        out,
        r#"<g fill="none" stroke="black" stroke-width="1" vector-effect="non-scaling-stroke" stroke-linejoin="round">"#
    );
    for o in &scene.objects {
        let _ = writeln!(
            out,
            r#"<g data-output="{}" data-path="{}" data-index="{}">"#,
            escape(&o.output),
            o.path,
            o.index
        );
        let pt = |p| {
            let (x, y, _) = view.project(p);
            format!("{x},{}", -y)
        };
        if let Some(mesh) = &o.mesh {
            for face in mesh.faces() {
                let points: Vec<String> = face
                    .corners()
                    .iter()
                    .map(|&v| pt(mesh.vertices()[v as usize]))
                    .collect();
                let _ = writeln!(
                    out,
                    r##"<polygon points="{}" fill="#ddd" stroke="#999" vector-effect="non-scaling-stroke"/>"##,
                    points.join(" ")
                );
            }
        }
        for line in &o.lines {
            let points: Vec<String> = line.iter().map(|&p| pt(p)).collect();
            let _ = writeln!(
                out,
                r#"<polyline points="{}" vector-effect="non-scaling-stroke"/>"#,
                points.join(" ")
            );
        }
        for &p in &o.points {
            let (x, y, _) = view.project(p);
            let _ = writeln!(
                out,
                r#"<circle cx="{x}" cy="{}" r="{dot}" fill="black" stroke="none"/>"#,
                -y
            );
        }
        out.push_str("</g>\n");
    }
    out.push_str("</g>\n</svg>\n");
    out
}
