//! Maths › Script: the Expression and Evaluate nodes.
//!
//! Both evaluate a formula of the expression language ([`crate::expression`], described in
//! `docs/expression.md`) once per item. Expression takes the formula as its `expression`
//! setting and parses it once per node; a formula that does not parse is one error on the
//! node, naming the column of the fault. Evaluate takes the formula as its first input `F`,
//! so it may change from item to item; parsed formulas are cached per node.
//!
//! The variables are the node's inputs, named by the graph (`x` and `y` by default), item
//! access, generic data. They are optional: a variable the formula does not use may be left
//! unconnected. A variable the formula uses that has no data at all is an error on the item;
//! one whose item is null (or whose branch is empty) gives a null result, as everywhere in
//! Grasshopper.

use std::sync::{Arc, RwLock};

use locus_kernel::{Point3, Vector3};
use locus_runtime::{
    DataType, NodeConfig, NodeError, NodeRegistry, NodeType, Port, Prepared, Solve, Value,
    format_value,
};

use super::set_operand;
use crate::expression::{EvalError, Operand, ParseError, Program};

/// Id of [`expression`].
pub const EXPRESSION: &str = "maths.expression";
/// Id of [`evaluate`].
pub const EVALUATE: &str = "maths.evaluate";

/// The formula a new Expression node starts with.
pub const DEFAULT_EXPRESSION: &str = "x + y";

/// How many distinct formulas an Evaluate node keeps parsed.
const FORMULA_CACHE_SIZE: usize = 32;

/// Registers the script nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(expression());
    registry.register(evaluate());
}

fn variable_template() -> Port {
    Port::new("Variable", "x", DataType::Generic)
        .optional()
        .doc(
            "A variable of the formula, named by the input's name (ignoring case): a number, \
         integer, boolean, text, point or vector. May be left unconnected if the formula \
         does not use it.",
        )
}

/// Expression \[Expression\]: a formula of the inputs, given as the `expression` setting.
pub fn expression() -> NodeType {
    NodeType::new(EXPRESSION, "Expression", "Expression", "Maths")
        .gh_guid("9df5e896-552d-4c8c-b9ca-4fc147ffa022")
        .subcategory("Script")
        .description(
            "Evaluates a formula, such as `A + t*(B-A)`, for every item of its inputs. The \
             inputs are the formula's variables (x and y by default; the graph may name more). \
             The formula knows + - * / % ^, comparisons, and/or/xor/not, the usual functions \
             (sqrt, sin, min, round, if, …), pi and e, and computes with numbers, points, \
             vectors, booleans and text (see docs/expression.md). A formula that does not \
             parse is an error on the node naming the column of the fault; an invalid numeric \
             result (such as a division by zero) is NaN with a warning, and the item is kept.",
        )
        .variable_inputs(variable_template(), &["x", "y"])
        .output(
            Port::new("Result", "R", DataType::Generic)
                .doc("The value of the formula: a number, boolean, text, point or vector."),
        )
        .setting(
            "expression",
            DataType::Text,
            Some(Value::Text(DEFAULT_EXPRESSION.to_owned())),
            "The formula, in terms of the input names; default `x + y`.",
        )
        .prepare(|config| {
            let source = match config.setting("expression") {
                Some(Value::Text(t)) => t.as_str(),
                Some(other) => {
                    return Err(NodeError(format!(
                        "the expression setting must be a Text, not a {}",
                        other.data_type()
                    )));
                }
                None => return Err(NodeError("the node has no expression".to_owned())),
            };
            let names = variable_names(config, 0)?;
            let program = Program::compile(source, &names)?;
            Ok(Arc::new(program) as Prepared)
        })
        .solve(|s| {
            let program = s
                .prepared::<Program>()
                .ok_or_else(|| NodeError("internal: the expression was not prepared".to_owned()))?;
            run(s, program, 0)
        })
}

/// A formula and what parsing it gave.
type CachedFormula = (String, Result<Arc<Program>, ParseError>);

/// The prepared state of an Evaluate node: its variable names and the formulas seen so far.
#[derive(Debug)]
struct EvaluateState {
    names: Vec<String>,
    cache: RwLock<Vec<CachedFormula>>,
}

impl EvaluateState {
    /// The compiled formula for `source`, from the cache or parsed now.
    fn program(&self, source: &str) -> Result<Arc<Program>, ParseError> {
        let cached = |cache: &[CachedFormula]| {
            cache
                .iter()
                .find(|(s, _)| s == source)
                .map(|(_, p)| p.clone())
        };
        let hit = match self.cache.read() {
            Ok(cache) => cached(&cache),
            Err(poisoned) => cached(&poisoned.into_inner()),
        };
        if let Some(p) = hit {
            return p;
        }
        let names: Vec<&str> = self.names.iter().map(String::as_str).collect();
        let compiled = Program::compile(source, &names).map(Arc::new);
        let mut cache = match self.cache.write() {
            Ok(cache) => cache,
            Err(poisoned) => poisoned.into_inner(),
        };
        if cache.len() >= FORMULA_CACHE_SIZE {
            cache.clear();
        }
        cache.push((source.to_owned(), compiled.clone()));
        compiled
    }
}

/// Evaluate \[Eval\]: a formula given as the input F, of the other inputs.
pub fn evaluate() -> NodeType {
    let mut node = NodeType::new(EVALUATE, "Evaluate", "Eval", "Maths")
        .gh_guid("cc2b626f-6eff-4d08-9829-2877560693f4")
        .subcategory("Script")
        .description(
            "Evaluates a formula given as data: the first input F holds the formula (text), \
             the other inputs are its variables (x and y by default; the graph may name more, \
             but the first input must stay F). The formula language is the Expression node's \
             (see docs/expression.md). A formula that does not parse is an error on that item; \
             an invalid numeric result is NaN with a warning, and the item is kept.",
        )
        .variable_inputs(variable_template(), &["F", "x", "y"])
        .output(
            Port::new("Result", "r", DataType::Generic)
                .doc("The value of the formula: a number, boolean, text, point or vector."),
        )
        .prepare(|config| {
            let first = config.inputs.first().map(|p| p.nickname.as_str());
            if !first.is_some_and(|n| n.eq_ignore_ascii_case("F")) {
                return Err(NodeError(
                    "the first input of Evaluate must be the expression F (name the inputs F, \
                     x, y, …)"
                        .to_owned(),
                ));
            }
            let names = variable_names(config, 1)?;
            Ok(Arc::new(EvaluateState {
                names: names.into_iter().map(str::to_owned).collect(),
                cache: RwLock::new(Vec::new()),
            }) as Prepared)
        })
        .solve(|s| {
            let state = s
                .prepared::<EvaluateState>()
                .ok_or_else(|| NodeError("internal: the node was not prepared".to_owned()))?;
            // F is a Text port, so the runtime casts what is wired in; when the graph names
            // the inputs, F is a generic port and other values are written as text here, the
            // same way.
            let source = match s.value(0) {
                Some(Value::Text(t)) => t,
                Some(other) => format_value(&other),
                None => return Ok(()),
            };
            let program = state.program(&source)?;
            run(s, &program, 1)
        });
    node.inputs[0] = Port::new("Expression", "F", DataType::Text)
        .doc("The formula to evaluate, in terms of the other inputs' names.");
    node
}

/// The names of the inputs from `first` on, checked to differ ignoring case.
fn variable_names<'a>(config: &'a NodeConfig<'_>, first: usize) -> Result<Vec<&'a str>, NodeError> {
    let names: Vec<&str> = config
        .inputs
        .iter()
        .skip(first)
        .map(|p| p.nickname.as_str())
        .collect();
    for (i, a) in names.iter().enumerate() {
        if let Some(b) = names[..i]
            .iter()
            .find(|b| b.to_lowercase() == a.to_lowercase())
        {
            return Err(NodeError(format!(
                "the inputs {b} and {a} have the same name (names in a formula ignore case)"
            )));
        }
    }
    Ok(names)
}

/// Evaluates `program` on the current items (variable `i` is input `first + i`) and writes
/// the result to output 0.
fn run(s: &mut Solve<'_>, program: &Program, first: usize) -> Result<(), NodeError> {
    let result = program.evaluate(|i| load(s, first + i));
    match result {
        Ok(evaluation) => {
            set_operand(s, 0, evaluation.value, evaluation.warning);
            Ok(())
        }
        // A null variable leaves a null result, without a message.
        Err(failure) if matches!(failure.error, EvalError::Null(_)) => Ok(()),
        Err(failure) => Err(failure.into()),
    }
}

/// The current item of input `input` as an operand.
fn load(s: &Solve<'_>, input: usize) -> Result<Operand, EvalError> {
    // Typed columns first: reading them copies no `Value`.
    if let Some(x) = s.item_opt::<f64>(input) {
        return Ok(Operand::Number(*x));
    }
    if let Some(p) = s.item_opt::<Point3>(input) {
        return Ok(Operand::Point(*p));
    }
    if let Some(v) = s.item_opt::<Vector3>(input) {
        return Ok(Operand::Vector(*v));
    }
    match s.value(input) {
        Some(v) => Operand::from_value(&v),
        None => {
            let name = s
                .input_port(input)
                .map_or_else(|| "?".to_owned(), |p| p.nickname.clone());
            match s.branch(input) {
                None => Err(EvalError::NoData(name)),
                Some(_) => Err(EvalError::Null(name)),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use locus_runtime::{Branch, DataTree, Level, NodeCall, TreePath};

    use super::*;
    use crate::maths::test_support::{messages, numbers, values};

    fn text(s: &str) -> Value {
        Value::Text(s.to_owned())
    }

    #[test]
    fn default_formula_adds_x_and_y() {
        let r = NodeCall::new(&expression())
            .input(DataTree::from_list(vec![1.0, 2.0]))
            .input(DataTree::from_item(10.0))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [11.0, 12.0]);
    }

    #[test]
    fn tangent_spheres_point_with_named_inputs() {
        let r = NodeCall::new(&expression())
            .input_names(&["A", "B", "t"])
            .setting("expression", text("A + t*(B-A)"))
            .input(DataTree::from_item(Point3::new(0.0, 0.0, 0.0)))
            .input(DataTree::from_item(Point3::new(4.0, 8.0, 2.0)))
            .input(DataTree::from_list(vec![0.0, 0.5, 1.0]))
            .run();
        assert_eq!(
            values(&r.outputs[0]),
            [
                Some(Value::Point(Point3::new(0.0, 0.0, 0.0))),
                Some(Value::Point(Point3::new(2.0, 4.0, 1.0))),
                Some(Value::Point(Point3::new(4.0, 8.0, 2.0))),
            ]
        );
        assert!(r.messages.is_empty());
    }

    #[test]
    fn unused_inputs_may_be_unconnected() {
        let r = NodeCall::new(&expression())
            .setting("expression", text("2 * X"))
            .input(DataTree::from_list(vec![1.0, 2.0]))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [2.0, 4.0]);
        assert!(r.messages.is_empty());
    }

    #[test]
    fn a_used_input_without_data_is_an_error() {
        let r = NodeCall::new(&expression())
            .input(DataTree::from_item(1.0))
            .run();
        assert_eq!(values(&r.outputs[0]), [None]);
        assert_eq!(
            messages(&r, Level::Error),
            ["input y has no data at column 5"]
        );
    }

    #[test]
    fn a_null_input_gives_a_null_result_silently() {
        let mut b = Branch::new(DataType::Number);
        b.push(1.0);
        b.push_null();
        let r = NodeCall::new(&expression())
            .input(DataTree::from_branches([(TreePath::zero(), b)]))
            .input(DataTree::from_item(1.0))
            .run();
        assert_eq!(values(&r.outputs[0]), [Some(Value::Number(2.0)), None]);
        assert!(r.messages.is_empty());
    }

    #[test]
    fn parse_errors_are_one_error_on_the_node() {
        let r = NodeCall::new(&expression())
            .setting("expression", text("(x + 1"))
            .input(DataTree::from_list(vec![1.0, 2.0, 3.0]))
            .run();
        assert_eq!(messages(&r, Level::Error), ["expected \")\" at column 7"]);
        assert_eq!(r.messages.len(), 1);
        assert!(r.outputs[0].is_empty());
        let r = NodeCall::new(&expression())
            .setting("expression", text("x + z"))
            .input(DataTree::from_item(1.0))
            .run();
        assert_eq!(
            messages(&r, Level::Error),
            ["unknown name \"z\" (the variables are x, y) at column 5"]
        );
        let r = NodeCall::new(&expression())
            .setting("expression", Value::Number(1.0))
            .run();
        assert_eq!(
            messages(&r, Level::Error),
            ["the expression setting must be a Text, not a Number"]
        );
    }

    #[test]
    fn names_differing_only_in_case_are_an_error() {
        let r = NodeCall::new(&expression())
            .input_names(&["a", "A"])
            .setting("expression", text("a"))
            .input(DataTree::from_item(1.0))
            .run();
        assert_eq!(
            messages(&r, Level::Error),
            ["the inputs a and A have the same name (names in a formula ignore case)"]
        );
    }

    #[test]
    fn invalid_results_are_nan_with_a_warning_and_kept() {
        let r = NodeCall::new(&expression())
            .setting("expression", text("1 / x"))
            .input(DataTree::from_list(vec![2.0, 0.0, 4.0]))
            .run();
        let out = numbers(&r.outputs[0]);
        assert_eq!(out.len(), 3);
        assert_eq!((out[0], out[2]), (0.5, 0.25));
        assert!(out[1].is_nan());
        assert_eq!(
            messages(&r, Level::Warning),
            ["invalid numeric result, kept as NaN: division by zero"]
        );
        let r = NodeCall::new(&expression())
            .setting("expression", text("min(1/x, 5)"))
            .input(DataTree::from_item(0.0))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [5.0]);
        assert_eq!(
            messages(&r, Level::Warning),
            ["invalid number on the way to the result: division by zero"]
        );
    }

    #[test]
    fn type_errors_are_errors_on_the_item() {
        let r = NodeCall::new(&expression())
            .input(DataTree::from_list(vec![
                Value::Number(1.0),
                Value::Point(Point3::ORIGIN),
            ]))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(values(&r.outputs[0]), [Some(Value::Number(2.0)), None]);
        assert_eq!(
            messages(&r, Level::Error),
            ["cannot compute Point + Boolean at column 3"]
        );
    }

    #[test]
    fn results_of_every_type() {
        let run = |formula: &str| {
            let r = NodeCall::new(&expression())
                .setting("expression", text(formula))
                .input(DataTree::from_item(Vector3::new(1.0, 2.0, 2.0)))
                .input(DataTree::from_item("abc".to_owned()))
                .run();
            values(&r.outputs[0])
        };
        assert_eq!(run("abs(x)"), [Some(Value::Number(3.0))]);
        assert_eq!(
            run("x * 2"),
            [Some(Value::Vector(Vector3::new(2.0, 4.0, 4.0)))]
        );
        assert_eq!(run("y = \"abc\""), [Some(Value::Boolean(true))]);
        assert_eq!(run("y & \"!\""), [Some(text("abc!"))]);
    }

    #[test]
    fn evaluate_takes_the_formula_as_data() {
        let r = NodeCall::new(&evaluate())
            .input(DataTree::from_list(vec![
                "x * y".to_owned(),
                "x - y".to_owned(),
                "x +".to_owned(),
                "x * y".to_owned(),
            ]))
            .input(DataTree::from_item(6.0))
            .input(DataTree::from_item(2.0))
            .run();
        assert_eq!(
            values(&r.outputs[0]),
            [
                Some(Value::Number(12.0)),
                Some(Value::Number(4.0)),
                None,
                Some(Value::Number(12.0))
            ]
        );
        assert_eq!(
            messages(&r, Level::Error),
            ["unexpected end of the expression at column 4"]
        );
    }

    #[test]
    fn evaluate_with_named_inputs() {
        let r = NodeCall::new(&evaluate())
            .input_names(&["F", "a", "b", "c"])
            .input(DataTree::from_item("a*b + c".to_owned()))
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(3.0))
            .input(DataTree::from_item(4.0))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [10.0]);
        let r = NodeCall::new(&evaluate())
            .input_names(&["F", "x"])
            .input(DataTree::from_item(7.0))
            .input(DataTree::from_item(3.0))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [7.0]);
        let r = NodeCall::new(&evaluate())
            .input_names(&["a", "b"])
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(3.0))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
        // A number wired into F is cast to text, as Grasshopper does: the formula "5".
        let r = NodeCall::new(&evaluate())
            .input(DataTree::from_item(5.0))
            .input(DataTree::from_item(3.0))
            .run();
        assert!(messages(&r, Level::Error).is_empty());
        assert_eq!(numbers(&r.outputs[0]), [5.0]);
    }

    #[test]
    fn evaluate_declares_f_as_text() {
        let node = evaluate();
        assert_eq!(node.inputs[0].nickname, "F");
        assert_eq!(node.inputs[0].data_type, DataType::Text);
        assert!(!node.inputs[0].optional);
        assert_eq!(node.inputs[1].nickname, "x");
    }

    #[test]
    fn the_formula_cache_is_bounded_and_correct() {
        let state = EvaluateState {
            names: vec!["x".to_owned()],
            cache: RwLock::new(Vec::new()),
        };
        for k in 0..100 {
            let p = state.program(&format!("x + {k}")).unwrap();
            let r = p.evaluate(|_| Ok(Operand::Number(1.0))).unwrap();
            assert_eq!(r.value, Operand::Number(1.0 + f64::from(k)));
        }
        assert!(state.cache.read().unwrap().len() <= FORMULA_CACHE_SIZE);
        assert!(state.program("x +").is_err());
    }
}
