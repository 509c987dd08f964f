//! Script: the Python script node, Grasshopper's GhPython component.
//!
//! A `script.python` node runs a Python script once per iteration of its inputs, as GhPython
//! does: the inputs are the script's variables, named by the graph (`x` and `y` by default),
//! each with item, list or tree access and an optional type hint (the `access` and `hints`
//! settings); what the script assigns to the output names becomes the outputs; what it prints
//! is a remark (and the `out` output); an exception is an error on the item with the last line
//! of its traceback and the line of the script.
//!
//! Scripts run in a separate Python process (a *worker*, [`worker`]), never in the engine's
//! own: a script that loops forever is stopped at its time limit, and one that crashes its
//! interpreter is an error on its item; in both cases the rest of the graph runs. All the
//! iterations of one node evaluation go to the worker in one request ([`protocol`], values in
//! the [`codec`]'s exact form) and come back in order, so a node of a thousand items costs one
//! round trip, not a thousand. The worker is the `locus` Python package
//! (`locus._script_worker` run by `python`), so scripts get the package's geometry classes
//! (`locus.Point3`, `locus.NurbsCurve`, …), or with the `ghpython` setting the Rhino types of
//! its GhPython compatibility layer (`Rhino.Geometry`, `rhinoscriptsyntax`). Without a Python
//! that has the package, the node reports that Python is not available.
//!
//! Scripts run with the rights of the user who runs locus, as in Grasshopper: there is no
//! sandbox. Only run graphs whose scripts you trust.

pub mod codec;
pub mod protocol;
mod run;
pub mod spec;
pub mod worker;

use std::sync::Arc;
use std::time::Duration;

use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Prepared, Value};

pub use run::PRINTED_OUTPUT;
pub use spec::{DEFAULT_TIME_LIMIT_SECONDS, ScriptSpec};
pub use worker::{PYTHON_ENV, PythonConfig, WorkerInfo, WorkerPool};

/// Id of [`python`].
pub const PYTHON: &str = "script.python";

/// The type GUID of Grasshopper's GhPython Script component (IronPython, Rhino 6 to 8), whose
/// script is the item `CodeInput`.
pub const GHPYTHON_GUID: &str = "410755b1-224a-4c1e-a407-bf32fb45ea7e";

/// Registers the script nodes, running scripts with the Python named by `$LOCUS_PYTHON`
/// (else `python3`).
pub fn register(registry: &mut NodeRegistry) {
    registry.register(python(PythonConfig::FromEnvironment));
}

fn variable_template() -> Port {
    Port::new("Variable", "x", DataType::Generic)
        .tree()
        .optional()
        .doc(
            "A variable of the script, named by the input's name. Its access (item, list or \
             tree) and type hint are the node's `access` and `hints` settings: an item input is \
             one value per call, a list input a Python list per call, a tree input a dict of \
             paths. May be left unconnected: the variable is then None.",
        )
}

/// `2.5` for 2.5 seconds.
pub(crate) fn format_seconds(d: Duration) -> String {
    locus_runtime::format_number(d.as_secs_f64())
}

/// Python Script \[Python\]: a Python script run once per iteration, in a worker process
/// started as `config` says.
pub fn python(config: PythonConfig) -> NodeType {
    let pool = Arc::new(WorkerPool::new(config));
    NodeType::new(PYTHON, "Python Script", "Python", "Script")
        .gh_guid(GHPYTHON_GUID)
        .subcategory("Python")
        .description(
            "Runs a Python script for every iteration of its inputs, as Grasshopper's GhPython \
             component does. The inputs are the script's variables (x and y by default; the \
             graph names them), each item, list or tree access with an optional type hint (the \
             access and hints settings); the script assigns its outputs by name (a, by \
             default; the graph names them after out), a list becomes a branch and a dict of paths a \
             tree. What it prints is a \
             remark and the out output; an exception is an error on the item naming the line. \
             Values arrive as the locus package's classes (Point3, NurbsCurve, …), or with \
             ghpython as Rhino.Geometry objects of its compatibility layer. Scripts run in a \
             separate Python process with the package installed ($LOCUS_PYTHON, else python3): \
             a call longer than the time limit is stopped, a crash of Python is an error on \
             the item, and without Python the node reports that Python is not available. \
             Scripts run with your rights (no sandbox): only run scripts you trust.",
        )
        .variable_inputs(variable_template(), &["x", "y"])
        .output(
            Port::new("Output", PRINTED_OUTPUT, DataType::Text)
                .tree()
                .doc("What the script printed, one text per call that printed something."),
        )
        .variable_outputs(
            Port::new("Result", "a", DataType::Generic).tree().doc(
                "The value the script assigns to the output's name: an item per call, a list \
                 as a branch per call, a dict of paths (or a DataTree) as a tree.",
            ),
            &["a"],
        )
        .setting(
            "code",
            DataType::Text,
            Some(Value::Text(String::new())),
            "The Python script (empty: the node does nothing).",
        )
        .setting(
            "access",
            DataType::Text,
            Some(Value::Text(String::new())),
            "Each input's access as `name: item|list|tree` entries (`pts: list, t: tree`); \
             inputs not named are item access.",
        )
        .setting(
            "hints",
            DataType::Text,
            Some(Value::Text(String::new())),
            "Each input's type hint as `name: hint` entries (`x: Point3d, n: int`): GhPython's \
             hints or locus type names; items are cast to it. Inputs not named take items as \
             they come (ghdoc Object).",
        )
        .setting(
            "ghpython",
            DataType::Boolean,
            Some(Value::Boolean(false)),
            "Values arrive as Rhino.Geometry objects of the GhPython compatibility layer \
             (Point3d, NurbsCurve, Brep, …), and `import Rhino` and `import rhinoscriptsyntax` \
             work, as in GhPython.",
        )
        .setting(
            "timeout",
            DataType::Number,
            Some(Value::Number(DEFAULT_TIME_LIMIT_SECONDS)),
            "The time limit of one call of the script, in seconds (default 10): a call that \
             runs longer is an error on its item and is stopped.",
        )
        .prepare(|config| Ok(Arc::new(ScriptSpec::from_config(config)?) as Prepared))
        .solve(move |s| {
            let spec = s
                .prepared::<ScriptSpec>()
                .ok_or_else(|| NodeError("internal: the script was not prepared".to_owned()))?;
            run::run(s, spec, &pool)
        })
}
