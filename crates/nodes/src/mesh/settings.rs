//! Mesh › Util: meshing settings for Mesh Brep, Grasshopper's Settings (Custom), Settings
//! (Speed) and Settings (Quality).
//!
//! locus has no Meshing Parameters value yet, so a setting travels as a text of the kernel's
//! four limits, `max_angle=…; max_chord_deviation=…; max_edge_length=…; min_edge_length=…`
//! (the angle in radians, lengths in model units, 0 for no limit), which [`parse_settings`]
//! reads back. Grasshopper's custom settings have more knobs (jagged seams, simple planes,
//! aspect ratio, initial grid) that the kernel's tessellation does not use.

use locus_kernel::MeshingParameters;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::mesh_node;

/// Id of [`settings_custom`].
pub const SETTINGS_CUSTOM: &str = "mesh.settings_custom";
/// Id of [`settings_speed`].
pub const SETTINGS_SPEED: &str = "mesh.settings_speed";
/// Id of [`settings_quality`].
pub const SETTINGS_QUALITY: &str = "mesh.settings_quality";

/// The density of Settings (Speed): the coarsest preset (maximum angle 20°).
pub const SPEED_DENSITY: f64 = 0.0;
/// The density of Settings (Quality): the finest preset (maximum angle 1°).
pub const QUALITY_DENSITY: f64 = 1.0;

/// Registers the three settings nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(settings_custom());
    registry.register(settings_speed());
    registry.register(settings_quality());
}

/// The text of meshing parameters.
pub fn settings_text(p: &MeshingParameters) -> String {
    format!(
        "max_angle={}; max_chord_deviation={}; max_edge_length={}; min_edge_length={}",
        p.max_angle, p.max_chord_deviation, p.max_edge_length, p.min_edge_length
    )
}

/// The meshing parameters a settings text names (keys left out keep the default), checked.
///
/// # Errors
/// A message naming an unknown key, a value that is not a number, or a limit the kernel
/// refuses.
pub fn parse_settings(text: &str) -> Result<MeshingParameters, String> {
    let mut p = MeshingParameters::default();
    for part in text.split(';').map(str::trim).filter(|s| !s.is_empty()) {
        let (key, value) = part
            .split_once('=')
            .ok_or_else(|| format!("meshing setting {part:?} is not key=value"))?;
        let value: f64 = value.trim().parse().map_err(|_| {
            format!(
                "meshing setting {}: {:?} is not a number",
                key.trim(),
                value.trim()
            )
        })?;
        match key.trim() {
            "max_angle" => p.max_angle = value,
            "max_chord_deviation" => p.max_chord_deviation = value,
            "max_edge_length" => p.max_edge_length = value,
            "min_edge_length" => p.min_edge_length = value,
            other => {
                return Err(format!(
                    "unknown meshing setting {other:?}: the settings are max_angle, \
                     max_chord_deviation, max_edge_length and min_edge_length"
                ));
            }
        }
    }
    p.validate().map_err(|e| e.to_string())?;
    Ok(p)
}

/// The Settings output every settings node has.
fn settings_output() -> Port {
    Port::new("Settings", "S", DataType::Text).doc(
        "The meshing settings, as the text max_angle=…; max_chord_deviation=…; \
         max_edge_length=…; min_edge_length=… (locus has no Meshing Parameters value yet).",
    )
}

/// Settings (Custom) \[Custom\]: meshing settings from the kernel's four limits.
pub fn settings_custom() -> NodeType {
    let d = MeshingParameters::default();
    mesh_node(SETTINGS_CUSTOM, "Settings (Custom)", "Custom", "Util")
        .description(
            "Represents custom meshing settings for Mesh Brep: the largest angle between the \
             normals of neighbouring vertices, the largest distance from a face to the \
             surface, and the longest and shortest edges (0 for no limit). At least one of \
             the first three must limit the mesh. Its Grasshopper GUID is not in the \
             project's table, so files cannot name it yet; Grasshopper's other knobs, such as \
             jagged seams and simple planes, are not used by locus's tessellation.",
        )
        .input(
            Port::new("Max Angle", "A", DataType::Number)
                .default_value(d.max_angle)
                .doc("The largest angle between neighbouring normals, in radians (default 3.5°)."),
        )
        .input(
            Port::new("Tolerance", "T", DataType::Number)
                .default_value(d.max_chord_deviation)
                .doc("The largest distance from a face to the surface; 0 for no limit."),
        )
        .input(
            Port::new("Max Edge", "E+", DataType::Number)
                .default_value(d.max_edge_length)
                .doc("The longest edge; 0 for no limit."),
        )
        .input(
            Port::new("Min Edge", "E-", DataType::Number)
                .default_value(d.min_edge_length)
                .doc("The shortest edge the mesh refines to (default 1e-4)."),
        )
        .output(settings_output())
        .solve(|s| {
            let p = MeshingParameters {
                max_angle: *s.item::<f64>(0)?,
                max_chord_deviation: *s.item::<f64>(1)?,
                max_edge_length: *s.item::<f64>(2)?,
                min_edge_length: *s.item::<f64>(3)?,
            };
            p.validate()?;
            s.set(0, settings_text(&p));
            Ok(())
        })
}

/// Settings (Speed) \[Speed\]: coarse meshing settings.
pub fn settings_speed() -> NodeType {
    mesh_node(SETTINGS_SPEED, "Settings (Speed)", "Speed", "Util")
        .description(
            "Represents meshing settings for speed: the coarsest density preset, a maximum \
             angle of 20° between neighbouring normals (in the spirit of Rhino's \
             FastRenderMesh). Its Grasshopper GUID is not in the project's table.",
        )
        .output(settings_output())
        .solve(|s| {
            s.set(
                0,
                settings_text(&MeshingParameters::from_density(SPEED_DENSITY)),
            );
            Ok(())
        })
}

/// Settings (Quality) \[Quality\]: fine meshing settings.
pub fn settings_quality() -> NodeType {
    mesh_node(SETTINGS_QUALITY, "Settings (Quality)", "Quality", "Util")
        .description(
            "Represents meshing settings for quality: the finest density preset, a maximum \
             angle of 1° between neighbouring normals (in the spirit of Rhino's \
             QualityRenderMesh). Its Grasshopper GUID is not in the project's table.",
        )
        .output(settings_output())
        .solve(|s| {
            s.set(
                0,
                settings_text(&MeshingParameters::from_density(QUALITY_DENSITY)),
            );
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{assert_clean, assert_error, only};
    use locus_runtime::{DataTree, NodeCall, Value};

    #[test]
    fn settings_text_round_trips() {
        let p = MeshingParameters::from_density(0.5);
        assert_eq!(parse_settings(&settings_text(&p)), Ok(p));
        assert_eq!(parse_settings(""), Ok(MeshingParameters::default()));
        let p = parse_settings("max_edge_length = 2").unwrap();
        assert_eq!(p.max_edge_length, 2.0);
        assert_eq!(p.max_angle, MeshingParameters::default().max_angle);
        assert!(
            parse_settings("density=1")
                .unwrap_err()
                .contains("unknown meshing setting")
        );
        assert!(
            parse_settings("max_angle=wide")
                .unwrap_err()
                .contains("not a number")
        );
        assert!(
            parse_settings("max_angle")
                .unwrap_err()
                .contains("key=value")
        );
        assert!(
            parse_settings("max_angle=4")
                .unwrap_err()
                .contains("below π")
        );
    }

    #[test]
    fn the_settings_nodes_give_their_limits() {
        let r = NodeCall::new(&settings_speed()).run();
        assert_clean(&r);
        let speed = parse_settings(&only::<String>(&r, 0)).unwrap();
        assert!((speed.max_angle - 20f64.to_radians()).abs() < 1e-15);
        let r = NodeCall::new(&settings_quality()).run();
        let quality = parse_settings(&only::<String>(&r, 0)).unwrap();
        assert!((quality.max_angle - 1f64.to_radians()).abs() < 1e-15);
        let r = NodeCall::new(&settings_custom())
            .input(DataTree::from_value(Value::Number(0.0)))
            .input(DataTree::from_value(Value::Number(0.01)))
            .run();
        assert_clean(&r);
        let custom = parse_settings(&only::<String>(&r, 0)).unwrap();
        assert_eq!(custom.max_angle, 0.0);
        assert_eq!(custom.max_chord_deviation, 0.01);
        let r = NodeCall::new(&settings_custom())
            .input(DataTree::from_value(Value::Number(0.0)))
            .run();
        assert_error(&r, "needs a maximum angle");
    }
}
