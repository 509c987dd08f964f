//! A script node's settings, read once per node: its code, each input's access and type hint,
//! whether it runs as GhPython does, and its time limit.
//!
//! Access and hints are given per input name as `name: value` entries separated by commas,
//! semicolons or new lines (`"pts: list, grid: tree"`, `"x: Point3d; n: int"`); inputs left out
//! are item access without a hint. Every name must be one of the node's inputs, so a typo is a
//! check error with the file position rather than a silently ignored entry.

use std::time::Duration;

use locus_runtime::{Access, DataType, NodeConfig, NodeError, Value};

/// The time limit of one call of a script when the node gives none.
pub const DEFAULT_TIME_LIMIT_SECONDS: f64 = 10.0;

/// The longest time limit a node may give (a day).
pub const MAX_TIME_LIMIT_SECONDS: f64 = 86_400.0;

/// One input as the script sees it.
#[derive(Clone, Debug, PartialEq)]
pub struct InputSpec {
    /// The variable name.
    pub name: String,
    /// Item, list or tree access.
    pub access: Access,
    /// The type the input's items are cast to (`Generic`: as they come).
    pub data_type: DataType,
    /// The type hint as written (canonical spelling), empty for none.
    pub hint: String,
}

/// Everything about a script node that its settings and input names say.
#[derive(Clone, Debug, PartialEq)]
pub struct ScriptSpec {
    /// The script.
    pub code: String,
    /// The inputs, in port order.
    pub inputs: Vec<InputSpec>,
    /// Whether inputs arrive as the GhPython compatibility layer's Rhino types.
    pub ghpython: bool,
    /// The time limit of one call.
    pub time_limit: Duration,
}

/// GhPython's type hints (the names Grasshopper shows) and the locus type each casts to.
/// `ghdoc Object` and the other untyped hints leave items as they are.
pub const GHPYTHON_HINTS: &[(&str, DataType)] = &[
    ("ghdoc Object", DataType::Generic),
    ("System.Object", DataType::Generic),
    ("GeometryBase", DataType::Generic),
    ("bool", DataType::Boolean),
    ("int", DataType::Integer),
    ("float", DataType::Number),
    ("str", DataType::Text),
    ("Color", DataType::Colour),
    ("Point3d", DataType::Point),
    ("Vector3d", DataType::Vector),
    ("Plane", DataType::Plane),
    ("Interval", DataType::Domain),
    ("Box", DataType::Box),
    ("Transform", DataType::Transform),
    ("Line", DataType::Line),
    ("Circle", DataType::Circle),
    ("Arc", DataType::Arc),
    ("Polyline", DataType::Curve),
    ("Rectangle3d", DataType::Curve),
    ("Curve", DataType::Curve),
    ("Surface", DataType::Surface),
    ("Brep", DataType::Brep),
    ("Mesh", DataType::Mesh),
];

/// The type a hint casts to, and its canonical spelling: a GhPython hint (`Point3d`, `float`,
/// `ghdoc Object`…) or a locus type name (`Point`, `Number`…), ignoring case.
pub fn hint_type(hint: &str) -> Option<(DataType, String)> {
    let hint = hint.trim();
    if let Some((name, t)) = GHPYTHON_HINTS
        .iter()
        .find(|(name, _)| name.eq_ignore_ascii_case(hint))
    {
        return Some((*t, (*name).to_owned()));
    }
    DataType::from_name(hint).map(|t| (t, t.name().to_owned()))
}

/// The `name: value` entries of a setting, in order.
fn entries(text: &str) -> Result<Vec<(String, String)>, String> {
    text.split([',', ';', '\n'])
        .map(str::trim)
        .filter(|e| !e.is_empty())
        .map(|e| match e.split_once([':', '=']) {
            Some((name, value)) => Ok((name.trim().to_owned(), value.trim().to_owned())),
            None => Err(format!("expected `input: value`, found {e:?}")),
        })
        .collect()
}

fn text_setting<'a>(config: &'a NodeConfig<'_>, name: &str) -> Result<&'a str, NodeError> {
    match config.setting(name) {
        Some(Value::Text(t)) => Ok(t),
        None => Ok(""),
        Some(other) => Err(NodeError(format!(
            "the {name} setting must be a Text, not a {}",
            other.data_type()
        ))),
    }
}

impl ScriptSpec {
    /// Reads a node's settings against its input names.
    ///
    /// # Errors
    /// A setting of the wrong type, an entry naming no input or naming one twice, an unknown
    /// access or type hint, or a time limit that is not a positive number of seconds up to a
    /// day.
    pub fn from_config(config: &NodeConfig<'_>) -> Result<Self, NodeError> {
        let code = text_setting(config, "code")?.to_owned();
        let mut inputs: Vec<InputSpec> = config
            .inputs
            .iter()
            .map(|p| InputSpec {
                name: p.nickname.clone(),
                access: Access::Item,
                data_type: DataType::Generic,
                hint: String::new(),
            })
            .collect();
        let mut seen = Vec::new();
        for (setting, apply) in [
            (
                "access",
                apply_access as fn(&mut InputSpec, &str) -> Result<(), String>,
            ),
            ("hints", apply_hint),
        ] {
            seen.clear();
            let text = text_setting(config, setting)?;
            for (name, value) in entries(text).map_err(|e| NodeError(format!("{setting}: {e}")))? {
                let Some(input) = inputs.iter_mut().find(|i| i.name == name) else {
                    let names: Vec<&str> =
                        config.inputs.iter().map(|p| p.nickname.as_str()).collect();
                    return Err(NodeError(format!(
                        "{setting}: the node has no input {name:?} (its inputs are {})",
                        if names.is_empty() {
                            "none".to_owned()
                        } else {
                            names.join(", ")
                        }
                    )));
                };
                if seen.contains(&name) {
                    return Err(NodeError(format!(
                        "{setting}: input {name:?} is given twice"
                    )));
                }
                apply(input, &value).map_err(|e| NodeError(format!("{setting}: {e}")))?;
                seen.push(name);
            }
        }
        let seconds = match config.setting("timeout") {
            Some(Value::Number(x)) => *x,
            Some(Value::Integer(i)) => *i as f64,
            None => DEFAULT_TIME_LIMIT_SECONDS,
            Some(other) => {
                return Err(NodeError(format!(
                    "the timeout setting must be a Number of seconds, not a {}",
                    other.data_type()
                )));
            }
        };
        if !(seconds > 0.0 && seconds <= MAX_TIME_LIMIT_SECONDS) {
            return Err(NodeError(format!(
                "the timeout must be more than 0 and at most {MAX_TIME_LIMIT_SECONDS} seconds, \
                 got {seconds}"
            )));
        }
        let ghpython = match config.setting("ghpython") {
            Some(Value::Boolean(b)) => *b,
            None => false,
            Some(other) => {
                return Err(NodeError(format!(
                    "the ghpython setting must be a Boolean, not a {}",
                    other.data_type()
                )));
            }
        };
        Ok(Self {
            code,
            inputs,
            ghpython,
            time_limit: Duration::from_secs_f64(seconds),
        })
    }
}

fn apply_access(input: &mut InputSpec, value: &str) -> Result<(), String> {
    input.access = match value.to_ascii_lowercase().as_str() {
        "item" => Access::Item,
        "list" => Access::List,
        "tree" => Access::Tree,
        _ => {
            return Err(format!(
                "input {:?}: access must be item, list or tree, not {value:?}",
                input.name
            ));
        }
    };
    Ok(())
}

fn apply_hint(input: &mut InputSpec, value: &str) -> Result<(), String> {
    let Some((data_type, hint)) = hint_type(value) else {
        let known: Vec<&str> = GHPYTHON_HINTS.iter().map(|(n, _)| *n).collect();
        return Err(format!(
            "input {:?}: unknown type hint {value:?} (GhPython's hints: {}; or a locus type \
             name such as Point or Number)",
            input.name,
            known.join(", ")
        ));
    };
    input.data_type = data_type;
    input.hint = hint;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_runtime::Port;

    fn spec(settings: &[(&str, Value)], names: &[&str]) -> Result<ScriptSpec, NodeError> {
        let settings: Vec<(String, Value)> = settings
            .iter()
            .map(|(n, v)| ((*n).to_owned(), v.clone()))
            .collect();
        let inputs: Vec<Port> = names
            .iter()
            .map(|n| Port::new(n, n, DataType::Generic).tree())
            .collect();
        ScriptSpec::from_config(&NodeConfig {
            settings: &settings,
            inputs: &inputs,
        })
    }

    fn text(s: &str) -> Value {
        Value::Text(s.to_owned())
    }

    #[test]
    fn access_and_hints_are_read_per_input() {
        let s = spec(
            &[
                ("code", text("a = x")),
                ("access", text("pts: list; t = tree")),
                ("hints", text("pts: Point3d, x: float\nt: ghdoc object")),
                ("timeout", Value::Number(2.5)),
                ("ghpython", Value::Boolean(true)),
            ],
            &["x", "pts", "t"],
        )
        .unwrap();
        assert_eq!(s.code, "a = x");
        assert!(s.ghpython);
        assert_eq!(s.time_limit, Duration::from_millis(2500));
        let got: Vec<(&str, Access, DataType, &str)> = s
            .inputs
            .iter()
            .map(|i| (i.name.as_str(), i.access, i.data_type, i.hint.as_str()))
            .collect();
        assert_eq!(
            got,
            [
                ("x", Access::Item, DataType::Number, "float"),
                ("pts", Access::List, DataType::Point, "Point3d"),
                ("t", Access::Tree, DataType::Generic, "ghdoc Object"),
            ]
        );
    }

    #[test]
    fn locus_type_names_are_hints_too() {
        let s = spec(&[("hints", text("x: curve"))], &["x"]).unwrap();
        assert_eq!(s.inputs[0].data_type, DataType::Curve);
        assert_eq!(s.inputs[0].hint, "Curve");
        let s = spec(&[("hints", text("x: Domain"))], &["x"]).unwrap();
        assert_eq!(s.inputs[0].data_type, DataType::Domain);
    }

    #[test]
    fn defaults_are_item_access_without_hints() {
        let s = spec(&[], &["x", "y"]).unwrap();
        assert!(s.inputs.iter().all(|i| i.access == Access::Item
            && i.data_type == DataType::Generic
            && i.hint.is_empty()));
        assert_eq!(
            s.time_limit,
            Duration::from_secs_f64(DEFAULT_TIME_LIMIT_SECONDS)
        );
        assert!(!s.ghpython);
    }

    #[test]
    fn mistakes_are_errors_naming_the_setting_and_input() {
        let err = |settings: &[(&str, Value)]| spec(settings, &["x", "y"]).unwrap_err().0;
        assert!(
            err(&[("access", text("z: list"))]).contains("no input \"z\" (its inputs are x, y)")
        );
        assert!(err(&[("access", text("x: lists"))]).contains("access must be item, list or tree"));
        assert!(err(&[("access", text("x: list, x: tree"))]).contains("given twice"));
        assert!(err(&[("access", text("x"))]).contains("expected `input: value`"));
        assert!(err(&[("hints", text("x: Point4d"))]).contains("unknown type hint \"Point4d\""));
        assert!(err(&[("timeout", Value::Number(0.0))]).contains("more than 0"));
        assert!(err(&[("timeout", Value::Number(f64::NAN))]).contains("more than 0"));
        assert!(err(&[("timeout", Value::Number(1e9))]).contains("at most"));
        assert!(err(&[("code", Value::Number(1.0))]).contains("code setting must be a Text"));
    }
}
