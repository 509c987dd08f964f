//! Running a compiled formula.
//!
//! A [`Program`] is a flat list of stack operations (postfix order) with jumps for `if`. It is
//! evaluated on a stack that is allocated once per thread and reused, so evaluating a formula
//! for each item of a long list allocates nothing (text operands aside).

use std::cell::RefCell;
use std::fmt;

use super::{BinaryOp, EvalError, Function, Operand, UnaryOp};

/// A component of a point or vector, read with `.x`, `.y` or `.z`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Axis {
    X,
    Y,
    Z,
}

/// One stack operation.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Op {
    /// Pushes a constant.
    Push(Operand),
    /// Pushes variable `i`.
    Load(usize),
    /// Replaces the top with the operator applied to it.
    Unary(UnaryOp),
    /// Replaces the two top operands (left below right) with the result.
    Binary(BinaryOp),
    /// Replaces the top `n` operands with the function of them.
    Call(Function, usize),
    /// Replaces a point or vector with one of its components.
    Member(Axis),
    /// Pops a condition and jumps to the op at the index when it is false.
    JumpUnless(usize),
    /// Jumps to the op at the index.
    Jump(usize),
}

/// A parsed formula, ready to evaluate any number of times.
///
/// ```
/// use locus_nodes::expression::{Operand, Program};
/// let program = Program::compile("x^2 + y", &["x", "y"]).unwrap();
/// let vars = [Operand::Number(3.0), Operand::Number(1.0)];
/// let out = program.evaluate(|i| Ok(vars[i].clone())).unwrap();
/// assert_eq!(out.value, Operand::Number(10.0));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    source: String,
    variables: Vec<String>,
    ops: Vec<Op>,
    columns: Vec<usize>,
    max_stack: usize,
}

/// What evaluating a formula gave.
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation {
    /// The result. Numbers that are infinite or NaN have been replaced by NaN.
    pub value: Operand,
    /// Why the result (or a value on the way to it) is not a valid number, if it is not.
    pub warning: Option<String>,
}

/// An evaluation error with the column of the operation that failed.
#[derive(Clone, Debug, PartialEq)]
pub struct EvalFailure {
    /// What went wrong.
    pub error: EvalError,
    /// The 1-based character column of the failing operator, function or name.
    pub column: usize,
}

impl fmt::Display for EvalFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} at column {}", self.error, self.column)
    }
}

impl std::error::Error for EvalFailure {}

thread_local! {
    /// The evaluation stack of this thread, reused between evaluations.
    static STACK: RefCell<Vec<Operand>> = const { RefCell::new(Vec::new()) };
}

impl Program {
    pub(crate) fn new(
        source: &str,
        variables: &[&str],
        ops: Vec<Op>,
        columns: Vec<usize>,
        max_stack: usize,
    ) -> Self {
        Self {
            source: source.to_owned(),
            variables: variables.iter().map(|v| (*v).to_owned()).collect(),
            ops,
            columns,
            max_stack,
        }
    }

    /// Parses `source`; names in it refer to `variables` (ignoring case), which variables
    /// are numbered by their position in that list.
    ///
    /// # Errors
    /// A [`ParseError`](super::ParseError) naming the fault and its column.
    pub fn compile(source: &str, variables: &[&str]) -> Result<Self, super::ParseError> {
        super::parser::compile(source, variables)
    }

    /// The formula as written.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// The variable names the formula was compiled with.
    pub fn variables(&self) -> &[String] {
        &self.variables
    }

    /// Whether the formula reads variable `index`.
    pub fn uses_variable(&self, index: usize) -> bool {
        self.ops.contains(&Op::Load(index))
    }

    /// The deepest the evaluation stack gets.
    pub fn max_stack(&self) -> usize {
        self.max_stack
    }

    /// Evaluates the formula; `load(i)` gives the value of variable `i` and is called only
    /// for variables the evaluation reaches (the branch of an `if` not taken is skipped).
    ///
    /// A number that is infinite or NaN, whether a variable's value or an intermediate result,
    /// makes the evaluation succeed with a [`warning`](Evaluation::warning) naming the first
    /// such value; the result's invalid numbers become NaN.
    ///
    /// # Errors
    /// An [`EvalFailure`] when an operator or function meets operands it does not apply to, or
    /// when `load` fails.
    pub fn evaluate(
        &self,
        mut load: impl FnMut(usize) -> Result<Operand, EvalError>,
    ) -> Result<Evaluation, EvalFailure> {
        STACK.with(|cell| match cell.try_borrow_mut() {
            Ok(mut stack) => {
                stack.clear();
                stack.reserve(self.max_stack);
                let r = self.run(&mut stack, &mut load);
                stack.clear();
                r
            }
            // Only reachable if `load` itself evaluates a formula; use a fresh stack then.
            Err(_) => self.run(&mut Vec::with_capacity(self.max_stack), &mut load),
        })
    }

    fn run(
        &self,
        stack: &mut Vec<Operand>,
        load: &mut impl FnMut(usize) -> Result<Operand, EvalError>,
    ) -> Result<Evaluation, EvalFailure> {
        let mut warning: Option<String> = None;
        let mut pc = 0;
        while let Some(op) = self.ops.get(pc) {
            let column = self.columns.get(pc).copied().unwrap_or(0);
            let fail = |error| EvalFailure { error, column };
            let underflow = || fail(EvalError::Internal("stack underflow"));
            pc += 1;
            match op {
                Op::Push(x) => stack.push(x.clone()),
                Op::Load(i) => {
                    let x = load(*i).map_err(fail)?;
                    if warning.is_none() && !x.is_finite() {
                        let name = self.variables.get(*i).map_or("?", String::as_str);
                        warning = Some(format!("input {name} is {x}"));
                    }
                    stack.push(x);
                }
                Op::Unary(u) => {
                    let a = stack.pop().ok_or_else(underflow)?;
                    let r = u.apply(&a).map_err(fail)?;
                    if warning.is_none() && !r.is_finite() && a.is_finite() {
                        warning = Some(if u.is_postfix() {
                            format!("{a}{} is {r}", u.symbol())
                        } else {
                            format!("{}{a} is {r}", u.symbol())
                        });
                    }
                    stack.push(r);
                }
                Op::Binary(b) => {
                    let rhs = stack.pop().ok_or_else(underflow)?;
                    let lhs = stack.pop().ok_or_else(underflow)?;
                    let r = b.apply(&lhs, &rhs).map_err(fail)?;
                    if warning.is_none() && !r.is_finite() && lhs.is_finite() && rhs.is_finite() {
                        warning = Some(binary_warning(*b, &lhs, &rhs));
                    }
                    stack.push(r);
                }
                Op::Call(f, n) => {
                    let start = stack.len().checked_sub(*n).ok_or_else(underflow)?;
                    let r = f.apply(&stack[start..]).map_err(fail)?;
                    if warning.is_none()
                        && !r.is_finite()
                        && stack[start..].iter().all(Operand::is_finite)
                    {
                        let args: Vec<String> =
                            stack[start..].iter().map(ToString::to_string).collect();
                        warning = Some(format!("{}({}) is {r}", f.name(), args.join(", ")));
                    }
                    stack.truncate(start);
                    stack.push(r);
                }
                Op::Member(axis) => {
                    let a = stack.pop().ok_or_else(underflow)?;
                    let v = match &a {
                        Operand::Point(p) => p.to_vector(),
                        Operand::Vector(v) => *v,
                        other => return Err(fail(EvalError::Member(other.kind()))),
                    };
                    stack.push(Operand::Number(match axis {
                        Axis::X => v.x,
                        Axis::Y => v.y,
                        Axis::Z => v.z,
                    }));
                }
                Op::JumpUnless(target) => {
                    let c = stack.pop().ok_or_else(underflow)?;
                    if !c.truth().map_err(fail)? {
                        pc = *target;
                    }
                }
                Op::Jump(target) => pc = *target,
            }
        }
        let value = stack.pop().ok_or(EvalFailure {
            error: EvalError::Internal("the formula left no value"),
            column: 0,
        })?;
        if warning.is_none() && !value.is_finite() {
            warning = Some(format!("the result is {value}"));
        }
        Ok(Evaluation {
            value: value.with_invalid_as_nan(),
            warning,
        })
    }
}

/// Why a binary operation on finite operands gave an invalid number (for warnings).
pub(crate) fn binary_warning(op: BinaryOp, lhs: &Operand, rhs: &Operand) -> String {
    let zero_divisor = rhs.as_number() == Some(0.0);
    match op {
        BinaryOp::Divide if zero_divisor => "division by zero".to_owned(),
        BinaryOp::Modulus if zero_divisor => "modulus by zero".to_owned(),
        _ => match op.apply(lhs, rhs) {
            Ok(r) => format!("{lhs} {} {rhs} is {r}", op.symbol()),
            Err(_) => format!("{lhs} {} {rhs} is not a number", op.symbol()),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_kernel::{Point3, Vector3};

    fn eval(source: &str, names: &[&str], values: &[Operand]) -> Evaluation {
        let program = Program::compile(source, names).unwrap();
        program.evaluate(|i| Ok(values[i].clone())).unwrap()
    }

    fn number(source: &str) -> f64 {
        match eval(source, &[], &[]).value {
            Operand::Number(x) => x,
            other => panic!("{source} gave {other:?}"),
        }
    }

    #[test]
    fn precedence_and_associativity() {
        assert_eq!(number("1 + 2 * 3"), 7.0);
        assert_eq!(number("(1 + 2) * 3"), 9.0);
        assert_eq!(number("2 ^ 3 ^ 2"), 512.0);
        assert_eq!(number("-2 ^ 2"), -4.0);
        assert_eq!(number("2 ^ -1"), 0.5);
        assert_eq!(number("10 - 4 - 3"), 3.0);
        assert_eq!(number("12 / 3 / 2"), 2.0);
        assert_eq!(number("7 % 4 * 2"), 6.0);
        assert_eq!(number("--3"), 3.0);
    }

    #[test]
    fn constants_and_case() {
        assert_eq!(number("PI"), std::f64::consts::PI);
        assert_eq!(number("Sin(pi / 2)"), 1.0);
        assert_eq!(number("E"), std::f64::consts::E);
        assert_eq!(number("2*π"), 2.0 * std::f64::consts::PI);
    }

    #[test]
    fn variables_shadow_constants_and_ignore_case() {
        let r = eval(
            "E + X",
            &["e", "x"],
            &[Operand::Number(1.0), Operand::Number(2.0)],
        );
        assert_eq!(r.value, Operand::Number(3.0));
    }

    #[test]
    fn comparisons_and_logic() {
        let b = |s: &str| eval(s, &[], &[]).value;
        assert_eq!(b("1 < 2 and 2 <= 2"), Operand::Boolean(true));
        assert_eq!(b("not 1 > 2"), Operand::Boolean(true));
        assert_eq!(b("1 = 2 or 3 != 3"), Operand::Boolean(false));
        assert_eq!(b("true xor true"), Operand::Boolean(false));
        assert_eq!(b("\"a\" = \"a\""), Operand::Boolean(true));
        assert_eq!(b("\"a\" & 1 + 1"), Operand::Text("a2".into()));
    }

    #[test]
    fn if_only_evaluates_the_chosen_branch() {
        let mut loaded = Vec::new();
        let program = Program::compile("if(x > 0, y, z)", &["x", "y", "z"]).unwrap();
        let values = [
            Operand::Number(1.0),
            Operand::Number(2.0),
            Operand::Number(3.0),
        ];
        let r = program
            .evaluate(|i| {
                loaded.push(i);
                Ok(values[i].clone())
            })
            .unwrap();
        assert_eq!(r.value, Operand::Number(2.0));
        assert_eq!(loaded, [0, 1]);
        assert_eq!(number("if(0, 1/0, 5)"), 5.0);
        assert!(eval("if(1, 1/0, 5)", &[], &[]).warning.is_some());
    }

    #[test]
    fn the_tangent_spheres_point() {
        let a = Operand::Point(Point3::new(0.0, 0.0, 0.0));
        let b = Operand::Point(Point3::new(10.0, 20.0, -4.0));
        let t = Operand::Number(0.25);
        let r = eval("A + t*(B-A)", &["A", "B", "t"], &[a, b, t]);
        assert_eq!(r.value, Operand::Point(Point3::new(2.5, 5.0, -1.0)));
        assert_eq!(r.warning, None);
    }

    #[test]
    fn grasshoppers_curvature_formula_with_dot_and_unit_vector() {
        // runxel's calculate_curvature tutorial: T = [d1], then the curvature vector
        // (d2 − (d2 • T) T) / (d1 • d1). For the parabola (t, t²) at t = 1/2: d1 = (1, 1),
        // d2 = (0, 2), d2 • T = √2, and the curvature vector is ((0, 2) − (1, 1)) / 2.
        let d1 = Operand::Vector(Vector3::new(1.0, 1.0, 0.0));
        let d2 = Operand::Vector(Vector3::new(0.0, 2.0, 0.0));
        let t = eval("[d1]", &["d1"], std::slice::from_ref(&d1)).value;
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let Operand::Vector(unit) = t else {
            panic!("{t:?}")
        };
        assert!(
            (unit - Vector3::new(h, h, 0.0)).length() < 1e-15,
            "{unit:?}"
        );
        let k = eval("(d2-(d2 • T) *T)/(d1•d1)", &["d1", "d2", "T"], &[d1, d2, t]).value;
        let Operand::Vector(k) = k else {
            panic!("{k:?}")
        };
        assert!((k - Vector3::new(-0.5, 0.5, 0.0)).length() < 1e-15, "{k:?}");
        // Brackets bind as parentheses do; a number has no unit vector.
        let v = Operand::Vector(Vector3::new(0.0, 0.0, 2.0));
        let r = eval("[v + v] * 3", &["v"], &[v]).value;
        assert_eq!(r, Operand::Vector(Vector3::new(0.0, 0.0, 3.0)));
        let e = Program::compile("[x]", &["x"])
            .unwrap()
            .evaluate(|_| Ok(Operand::Number(1.0)))
            .unwrap_err();
        assert!(e.to_string().contains("unit needs a Vector"), "{e}");
    }

    #[test]
    fn member_access() {
        let v = Operand::Vector(Vector3::new(1.0, 2.0, 3.0));
        let r = eval("v.Y * 10 + v.z", &["v"], &[v]);
        assert_eq!(r.value, Operand::Number(23.0));
        let e = Program::compile("x.x", &["x"])
            .unwrap()
            .evaluate(|_| Ok(Operand::Number(1.0)))
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            ".x, .y and .z need a Point or a Vector, not a Number at column 2"
        );
    }

    #[test]
    fn invalid_numbers_are_nan_with_a_warning() {
        let r = eval("1/0", &[], &[]);
        assert!(matches!(r.value, Operand::Number(x) if x.is_nan()));
        assert_eq!(r.warning.as_deref(), Some("division by zero"));
        let r = eval("sqrt(-4) + 1", &[], &[]);
        assert_eq!(r.warning.as_deref(), Some("sqrt(-4) is NaN"));
        let r = eval("x * 2", &["x"], &[Operand::Number(f64::INFINITY)]);
        assert_eq!(r.warning.as_deref(), Some("input x is Infinity"));
        let r = eval("10^400", &[], &[]);
        assert_eq!(r.warning.as_deref(), Some("10 ^ 400 is Infinity"));
        let r = eval("min(1/0, 5)", &[], &[]);
        assert_eq!(r.warning.as_deref(), Some("division by zero"));
    }

    /// Grasshopper's postfix operators: `²`, `³`, `°` and `!`, binding tighter than `^` and
    /// the signs.
    #[test]
    fn postfix_squares_cubes_degrees_and_factorials() {
        assert_eq!(number("3²"), 9.0);
        assert_eq!(number("2³"), 8.0);
        assert_eq!(number("-3²"), -9.0);
        assert_eq!(number("2^2²"), 16.0);
        assert_eq!(number("(1 + 2)² + 1"), 10.0);
        assert_eq!(number("180°"), std::f64::consts::PI);
        assert_eq!(number("sin(90°)"), 1.0);
        assert_eq!(number("0!"), 1.0);
        assert_eq!(number("5!"), 120.0);
        assert_eq!(number("3!²"), 36.0);
        assert_eq!(number("22!"), 1_124_000_727_777_607_680_000.0);
        assert_eq!(eval("5 != 4", &[], &[]).value, Operand::Boolean(true));
        // A name followed by ² is the name squared, not a longer name.
        let r = eval(
            "x²+y³",
            &["x", "y"],
            &[Operand::Number(3.0), Operand::Number(2.0)],
        );
        assert_eq!(r.value, Operand::Number(17.0));
        // A vector squared is its dot product with itself; cubed, that times the vector.
        let v = Operand::Vector(Vector3::new(1.0, 2.0, 2.0));
        assert_eq!(
            eval("v²", &["v"], std::slice::from_ref(&v)).value,
            Operand::Number(9.0)
        );
        assert_eq!(
            eval("v³", &["v"], std::slice::from_ref(&v)).value,
            Operand::Vector(Vector3::new(9.0, 18.0, 18.0))
        );
        // Invalid numbers are NaN with a warning naming the operator.
        let r = eval("2.5!", &[], &[]);
        assert!(matches!(r.value, Operand::Number(x) if x.is_nan()));
        assert_eq!(r.warning.as_deref(), Some("2.5! is NaN"));
        let r = eval("171!", &[], &[]);
        assert_eq!(r.warning.as_deref(), Some("171! is Infinity"));
        let r = eval("(-1)!", &[], &[]);
        assert_eq!(r.warning.as_deref(), Some("-1! is NaN"));
        // Degrees and factorials take numbers only.
        let e = Program::compile("v°", &["v"])
            .unwrap()
            .evaluate(|_| Ok(v.clone()))
            .unwrap_err();
        assert_eq!(e.to_string(), "cannot compute °Vector at column 2");
    }

    #[test]
    fn type_errors_name_the_column() {
        let p = Operand::Point(Point3::ORIGIN);
        let e = Program::compile("x * 2 + p", &["x", "p"])
            .unwrap()
            .evaluate(|i| {
                Ok(if i == 0 {
                    Operand::Number(1.0)
                } else {
                    p.clone()
                })
            })
            .unwrap_err();
        assert_eq!(e.to_string(), "cannot compute Number + Point at column 7");
        let e = Program::compile("if(\"a\", 1, 2)", &[])
            .unwrap()
            .evaluate(|_| Ok(Operand::Number(0.0)))
            .unwrap_err();
        assert_eq!(e.to_string(), "expected a Boolean, not a Text at column 1");
    }

    #[test]
    fn load_errors_are_reported() {
        let e = Program::compile("x", &["x"])
            .unwrap()
            .evaluate(|_| Err(EvalError::NoData("x".into())))
            .unwrap_err();
        assert_eq!(e.to_string(), "input x has no data at column 1");
    }
}
