//! `locus view`: one self-contained HTML page that shows a scene in an orbit view (three.js),
//! with a panel of outputs and branches to toggle, the output, path, index and value of a
//! clicked object, and the messages per node.
//!
//! Everything the page needs is inside it: the scene as a base64 `.glb`, the messages as JSON,
//! and the viewer script (`viewer/src/viewer.js` bundled with three.js by `viewer/build.sh` into
//! `viewer/dist/viewer.js`, checked in with three.js's MIT licence), so it opens without a
//! network or a server.

use base64::Engine as _;
use serde_json::Value as Json;

use crate::ExportError;
use crate::gltf::{GltfOptions, to_glb};
use crate::scene::Scene;

/// The bundled viewer script.
const VIEWER_JS: &str = include_str!("../viewer/dist/viewer.js");

const STYLE: &str = "
html, body { margin: 0; height: 100%; font: 13px/1.4 system-ui, sans-serif; color: #222; }
body { display: flex; }
#viewport { flex: 1; position: relative; min-width: 0; }
#viewport canvas { width: 100%; height: 100%; display: block; }
#panel { width: 300px; overflow: auto; border-left: 1px solid #ccc; padding: 8px 12px; background: #fafafa; }
#panel h1 { font-size: 15px; margin: 4px 0 8px; } #panel h2 { font-size: 13px; margin: 12px 0 4px; }
#panel ul { list-style: none; padding-left: 14px; margin: 2px 0; } #outputs { padding-left: 0 !important; }
#selection { background: #fff; border: 1px solid #ddd; padding: 6px; min-height: 2.8em; word-break: break-word; }
#messages li.error { color: #b00020; } #messages li.warning { color: #8a5a00; } #messages li.remark { color: #555; }
";

/// JSON made safe to sit inside a `<script>` element.
fn script_json(value: &Json) -> String {
    serde_json::to_string(value)
        .unwrap_or_else(|_| "null".into())
        .replace('<', "\\u003c")
}

fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// The page for a scene. `messages` is a JSON array of `{level, node, path, index, text}`
/// objects (the shape of `locus run --format json`); `title` names the graph.
///
/// # Errors
/// As [`to_glb`].
pub fn to_html(scene: &Scene, messages: &Json, title: &str) -> Result<String, ExportError> {
    page(scene, messages, title, None)
}

/// The page for a scene served by `locus view --serve`: as [`to_html`], and the page asks its
/// server for the `generation` URL beside it twice a second, reloading (with the camera kept)
/// when the answer is no longer `generation`, the number of the evaluation it shows.
///
/// # Errors
/// As [`to_glb`].
pub fn to_live_html(
    scene: &Scene,
    messages: &Json,
    title: &str,
    generation: u64,
) -> Result<String, ExportError> {
    page(scene, messages, title, Some(generation))
}

fn page(
    scene: &Scene,
    messages: &Json,
    title: &str,
    live: Option<u64>,
) -> Result<String, ExportError> {
    let glb = to_glb(scene, &GltfOptions::default())?;
    let glb = base64::engine::general_purpose::STANDARD.encode(glb);
    let mut data =
        serde_json::json!({ "title": title, "messages": messages, "skipped": scene.skipped });
    if let Some(generation) = live {
        data["live"] = serde_json::json!({ "generation": generation });
    }
    let title = escape_html(title);
    Ok(format!(
        "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\
<link rel=\"icon\" href=\"data:,\">\
<title>{title} — locus</title><style>{STYLE}</style></head>\n<body>\
<div id=\"viewport\"></div>\
<div id=\"panel\"><h1>{title}</h1><h2>Selected</h2><div id=\"selection\"></div>\
<h2>Outputs</h2><ul id=\"outputs\"></ul><h2>Messages</h2><ul id=\"messages\"></ul></div>\n\
<script id=\"locus-data\" type=\"application/json\">{data}</script>\n\
<script id=\"locus-glb\" type=\"application/octet-stream\">{glb}</script>\n\
<script>{VIEWER_JS}</script>\n</body></html>\n",
        data = script_json(&data),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_page_embeds_its_data_safely() {
        let messages = serde_json::json!([{"level": "error", "node": "n", "text": "</script><b>"}]);
        let html = to_html(&Scene::new(), &messages, "a <graph>").unwrap();
        assert!(html.contains("<title>a &lt;graph&gt; — locus</title>"));
        assert_eq!(
            html.matches("</script>").count(),
            3,
            "only the three script elements end"
        );
        assert!(html.contains("\\u003c/script>\\u003cb>"));
        assert!(!html.contains("\"live\":{"), "a written page is not live");
        // No network at view time: the only URL strings are XML namespace names (the headless
        // browser test also fails on any request that is not the page itself).
        let urls = html.matches("\"http").count() + html.matches("'http").count();
        assert_eq!(urls, html.matches("\"http://www.w3.org/").count());
    }

    #[test]
    fn a_live_page_carries_its_generation() {
        let html = to_live_html(&Scene::new(), &serde_json::json!([]), "g", 7).unwrap();
        assert!(html.contains("\"live\":{\"generation\":7}"));
    }
}
