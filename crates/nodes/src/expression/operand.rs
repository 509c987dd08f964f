//! The values an expression computes with, and the arithmetic on them.
//!
//! The same arithmetic backs the operator nodes (Addition, Multiplication, …), so that `x + y`
//! in an Expression and an Addition node always agree. The rules, chosen to match
//! Grasshopper where it is known and to be unsurprising where it is not:
//!
//! | operation | result |
//! | --- | --- |
//! | number ± number, × ÷ % ^ | number (IEEE arithmetic) |
//! | vector ± vector | vector |
//! | point + vector, vector + point, point − vector | point |
//! | point − point | vector from the second point to the first |
//! | point + point | point (component sum, so `(A + B) / 2` is the midpoint) |
//! | vector − point | vector (component difference) |
//! | vector × number, number × vector, vector ÷ number | vector |
//! | point × number, number × point, point ÷ number | point (component scaling) |
//! | vector or point × vector or point | number: the dot product |
//! | −vector, −point | negated components |
//!
//! Booleans take part in arithmetic as 0 and 1. Text takes part only in `=`, `!=` and `&`
//! (concatenation). Anything else is an [`EvalError`].

use std::fmt;
use std::sync::Arc;

use locus_kernel::{Point3, Vector3};
use locus_runtime::{DataType, Value, format_number, format_value, parse_number};

use super::EvalError;

/// One value inside an expression.
#[derive(Clone, Debug, PartialEq)]
pub enum Operand {
    /// A real number. Integers are read as numbers.
    Number(f64),
    /// A boolean.
    Boolean(bool),
    /// A text.
    Text(Arc<str>),
    /// A point.
    Point(Point3),
    /// A vector.
    Vector(Vector3),
}

/// The binary operators of the expression language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    /// `+`
    Add,
    /// `-`
    Subtract,
    /// `*`
    Multiply,
    /// `/`
    Divide,
    /// `%`: the remainder of a truncated division (its sign is the dividend's).
    Modulus,
    /// `^`
    Power,
    /// `&`: text concatenation.
    Concatenate,
    /// `<`
    Less,
    /// `<=`
    LessEqual,
    /// `>`
    Greater,
    /// `>=`
    GreaterEqual,
    /// `=`
    Equal,
    /// `!=`
    NotEqual,
    /// `and`
    And,
    /// `or`
    Or,
    /// `xor`
    Xor,
}

impl BinaryOp {
    /// The operator as written in a formula.
    pub fn symbol(self) -> &'static str {
        match self {
            BinaryOp::Add => "+",
            BinaryOp::Subtract => "-",
            BinaryOp::Multiply => "*",
            BinaryOp::Divide => "/",
            BinaryOp::Modulus => "%",
            BinaryOp::Power => "^",
            BinaryOp::Concatenate => "&",
            BinaryOp::Less => "<",
            BinaryOp::LessEqual => "<=",
            BinaryOp::Greater => ">",
            BinaryOp::GreaterEqual => ">=",
            BinaryOp::Equal => "=",
            BinaryOp::NotEqual => "!=",
            BinaryOp::And => "and",
            BinaryOp::Or => "or",
            BinaryOp::Xor => "xor",
        }
    }

    /// Applies the operator.
    ///
    /// # Errors
    /// [`EvalError::Binary`] when the operator does not apply to these kinds of operand,
    /// [`EvalError::NotBoolean`] for a logical operator on a non-boolean.
    pub fn apply(self, a: &Operand, b: &Operand) -> Result<Operand, EvalError> {
        if let (Operand::Number(x), Operand::Number(y)) = (a, b)
            && let Some(r) = self.apply_numbers(*x, *y)
        {
            return Ok(r);
        }
        match self {
            BinaryOp::Add => add(a, b),
            BinaryOp::Subtract => subtract(a, b),
            BinaryOp::Multiply => multiply(a, b),
            BinaryOp::Divide => divide(a, b),
            BinaryOp::Modulus => numbers(self, a, b, |x, y| x % y),
            BinaryOp::Power => numbers(self, a, b, f64::powf),
            BinaryOp::Concatenate => Ok(Operand::Text(Arc::from(format!("{a}{b}").as_str()))),
            BinaryOp::Less => compare(self, a, b, |x, y| x < y),
            BinaryOp::LessEqual => compare(self, a, b, |x, y| x <= y),
            BinaryOp::Greater => compare(self, a, b, |x, y| x > y),
            BinaryOp::GreaterEqual => compare(self, a, b, |x, y| x >= y),
            BinaryOp::Equal => equal(a, b).map(Operand::Boolean),
            BinaryOp::NotEqual => equal(a, b).map(|e| Operand::Boolean(!e)),
            BinaryOp::And => Ok(Operand::Boolean(a.truth()? && b.truth()?)),
            BinaryOp::Or => Ok(Operand::Boolean(a.truth()? || b.truth()?)),
            BinaryOp::Xor => Ok(Operand::Boolean(a.truth()? != b.truth()?)),
        }
    }

    /// The fast path for two numbers (`None` for the logical operators, which check NaN).
    #[inline]
    fn apply_numbers(self, x: f64, y: f64) -> Option<Operand> {
        Some(match self {
            BinaryOp::Add => Operand::Number(x + y),
            BinaryOp::Subtract => Operand::Number(x - y),
            BinaryOp::Multiply => Operand::Number(x * y),
            BinaryOp::Divide => Operand::Number(x / y),
            BinaryOp::Modulus => Operand::Number(x % y),
            BinaryOp::Power => Operand::Number(x.powf(y)),
            BinaryOp::Less => Operand::Boolean(x < y),
            BinaryOp::LessEqual => Operand::Boolean(x <= y),
            BinaryOp::Greater => Operand::Boolean(x > y),
            BinaryOp::GreaterEqual => Operand::Boolean(x >= y),
            BinaryOp::Equal => Operand::Boolean(x == y),
            BinaryOp::NotEqual => Operand::Boolean(x != y),
            BinaryOp::Concatenate | BinaryOp::And | BinaryOp::Or | BinaryOp::Xor => return None,
        })
    }

    fn error(self, a: &Operand, b: &Operand) -> EvalError {
        EvalError::Binary {
            op: self.symbol(),
            left: a.kind(),
            right: b.kind(),
        }
    }
}

/// The prefix and postfix operators of the expression language.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    /// `-x`
    Negate,
    /// `+x`
    Plus,
    /// `not x`
    Not,
    /// `x²`: `x * x` (a vector's is its dot product with itself).
    Squared,
    /// `x³`: `x * x * x`.
    Cubed,
    /// `x°`: degrees to radians, `x × π / 180`.
    Radians,
    /// `n!`: the factorial of a whole number from 0 up (NaN for any other number; infinite,
    /// so NaN with a warning, above 170).
    Factorial,
}

/// The largest whole number whose factorial is finite in double precision.
const MAX_FACTORIAL: f64 = 170.0;

impl UnaryOp {
    /// The operator as written in a formula (before the operand, or after it when
    /// [`is_postfix`](Self::is_postfix)).
    pub fn symbol(self) -> &'static str {
        match self {
            UnaryOp::Negate => "-",
            UnaryOp::Plus => "+",
            UnaryOp::Not => "not ",
            UnaryOp::Squared => "²",
            UnaryOp::Cubed => "³",
            UnaryOp::Radians => "°",
            UnaryOp::Factorial => "!",
        }
    }

    /// Whether the operator is written after its operand (`x²`, `90°`, `5!`).
    pub fn is_postfix(self) -> bool {
        matches!(
            self,
            UnaryOp::Squared | UnaryOp::Cubed | UnaryOp::Radians | UnaryOp::Factorial
        )
    }

    /// Applies the operator.
    ///
    /// # Errors
    /// [`EvalError::Unary`] for a text (or a boolean under `-`), [`EvalError::NotBoolean`]
    /// for `not` on a non-boolean.
    pub fn apply(self, a: &Operand) -> Result<Operand, EvalError> {
        let unary = |_| EvalError::Unary {
            op: self.symbol(),
            operand: a.kind(),
        };
        match self {
            UnaryOp::Squared => return BinaryOp::Multiply.apply(a, a).map_err(unary),
            UnaryOp::Cubed => {
                let square = BinaryOp::Multiply.apply(a, a).map_err(unary)?;
                return BinaryOp::Multiply.apply(&square, a).map_err(unary);
            }
            _ => {}
        }
        match (self, a.numeric()) {
            (UnaryOp::Radians, Operand::Number(x)) => Ok(Operand::Number(x.to_radians())),
            (UnaryOp::Factorial, Operand::Number(n)) => Ok(Operand::Number(factorial(n))),
            (UnaryOp::Not, _) => Ok(Operand::Boolean(!a.truth()?)),
            (UnaryOp::Negate, Operand::Number(x)) => Ok(Operand::Number(-x)),
            (UnaryOp::Negate, Operand::Vector(v)) => Ok(Operand::Vector(-v)),
            (UnaryOp::Negate, Operand::Point(p)) => {
                Ok(Operand::Point(Point3::new(-p.x, -p.y, -p.z)))
            }
            (UnaryOp::Plus, x @ (Operand::Number(_) | Operand::Vector(_) | Operand::Point(_))) => {
                Ok(x)
            }
            _ => Err(EvalError::Unary {
                op: self.symbol(),
                operand: a.kind(),
            }),
        }
    }
}

/// `n!` for a whole `n` from 0 up, by the product in increasing order (exact up to 22!); NaN for
/// any other number, infinity above [`MAX_FACTORIAL`].
fn factorial(n: f64) -> f64 {
    if !(n >= 0.0 && n.fract() == 0.0) {
        return f64::NAN;
    }
    if n > MAX_FACTORIAL {
        return f64::INFINITY;
    }
    (2..=n as u32).fold(1.0, |p, k| p * f64::from(k))
}

impl Operand {
    /// The name of the operand's kind, as Grasshopper names types (`Number`, `Point`, …).
    pub fn kind(&self) -> &'static str {
        match self {
            Operand::Number(_) => "Number",
            Operand::Boolean(_) => "Boolean",
            Operand::Text(_) => "Text",
            Operand::Point(_) => "Point",
            Operand::Vector(_) => "Vector",
        }
    }

    /// The operand for a runtime value: integers become numbers; domains, planes and
    /// transforms are not expression values.
    ///
    /// # Errors
    /// [`EvalError::Unsupported`] for a value of another type.
    pub fn from_value(value: &Value) -> Result<Self, EvalError> {
        Ok(match value {
            Value::Number(x) => Operand::Number(*x),
            Value::Integer(i) => Operand::Number(*i as f64),
            Value::Boolean(b) => Operand::Boolean(*b),
            Value::Text(t) => Operand::Text(Arc::from(t.as_str())),
            Value::Point(p) => Operand::Point(*p),
            Value::Vector(v) => Operand::Vector(*v),
            other => return Err(EvalError::Unsupported(other.data_type())),
        })
    }

    /// Like [`from_value`](Self::from_value), but reads a text as a number, the way
    /// Grasshopper's operator components treat text (`"2.5"` is 2.5).
    ///
    /// # Errors
    /// [`EvalError::NotANumber`] for a text that is not a number, [`EvalError::Unsupported`]
    /// for a value of an unsupported type.
    pub fn from_value_numeric(value: &Value) -> Result<Self, EvalError> {
        match value {
            Value::Text(t) => parse_number(t)
                .map(Operand::Number)
                .ok_or_else(|| EvalError::NotANumber(t.clone())),
            other => Self::from_value(other),
        }
    }

    /// The operand as a runtime value.
    pub fn into_value(self) -> Value {
        match self {
            Operand::Number(x) => Value::Number(x),
            Operand::Boolean(b) => Value::Boolean(b),
            Operand::Text(t) => Value::Text(t.to_string()),
            Operand::Point(p) => Value::Point(p),
            Operand::Vector(v) => Value::Vector(v),
        }
    }

    /// The runtime type of [`into_value`](Self::into_value).
    pub fn data_type(&self) -> DataType {
        match self {
            Operand::Number(_) => DataType::Number,
            Operand::Boolean(_) => DataType::Boolean,
            Operand::Text(_) => DataType::Text,
            Operand::Point(_) => DataType::Point,
            Operand::Vector(_) => DataType::Vector,
        }
    }

    /// Whether every number in the operand is finite (booleans and text always are).
    pub fn is_finite(&self) -> bool {
        match self {
            Operand::Number(x) => x.is_finite(),
            Operand::Point(p) => p.is_finite(),
            Operand::Vector(v) => v.is_finite(),
            Operand::Boolean(_) | Operand::Text(_) => true,
        }
    }

    /// The operand with every non-finite number (infinity or NaN) replaced by NaN, which is how
    /// an invalid numeric result leaves a node.
    pub fn with_invalid_as_nan(self) -> Self {
        let fix = |x: f64| if x.is_finite() { x } else { f64::NAN };
        match self {
            Operand::Number(x) => Operand::Number(fix(x)),
            Operand::Point(p) => Operand::Point(Point3::new(fix(p.x), fix(p.y), fix(p.z))),
            Operand::Vector(v) => Operand::Vector(Vector3::new(fix(v.x), fix(v.y), fix(v.z))),
            other => other,
        }
    }

    /// The number, if the operand is a number or a boolean (as 0 or 1).
    pub fn as_number(&self) -> Option<f64> {
        match self.numeric() {
            Operand::Number(x) => Some(x),
            _ => None,
        }
    }

    /// The truth of the operand: a boolean, or a number other than 0.
    ///
    /// # Errors
    /// [`EvalError::NotBoolean`] for NaN, a text, a point or a vector.
    pub fn truth(&self) -> Result<bool, EvalError> {
        match self {
            Operand::Boolean(b) => Ok(*b),
            Operand::Number(x) if !x.is_nan() => Ok(*x != 0.0),
            Operand::Number(_) => Err(EvalError::NotBoolean("NaN")),
            other => Err(EvalError::NotBoolean(other.kind())),
        }
    }

    /// The operand with booleans turned into 0 or 1, for arithmetic.
    fn numeric(&self) -> Operand {
        match self {
            Operand::Boolean(b) => Operand::Number(f64::from(u8::from(*b))),
            other => other.clone(),
        }
    }

    /// The components of a point or vector.
    fn components(&self) -> Option<Vector3> {
        match self {
            Operand::Point(p) => Some(p.to_vector()),
            Operand::Vector(v) => Some(*v),
            _ => None,
        }
    }
}

impl fmt::Display for Operand {
    /// Formats the operand as the runtime's cast to text does (and so as Grasshopper prints
    /// values): numbers in the invariant culture with .NET's exponent notation (`0.5`, `1E+15`,
    /// `NaN`, `Infinity`), booleans as `True`/`False`, points and vectors as `{x, y, z}`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Operand::Number(x) => f.write_str(&format_number(*x)),
            Operand::Text(t) => f.write_str(t),
            Operand::Boolean(b) => f.write_str(&format_value(&Value::Boolean(*b))),
            Operand::Point(p) => f.write_str(&format_value(&Value::Point(*p))),
            Operand::Vector(v) => f.write_str(&format_value(&Value::Vector(*v))),
        }
    }
}

fn point(v: Vector3) -> Operand {
    Operand::Point(Point3::from_vector(v))
}

fn add(a: &Operand, b: &Operand) -> Result<Operand, EvalError> {
    use Operand::{Number as N, Point as P, Vector as V};
    Ok(match (a.numeric(), b.numeric()) {
        (N(x), N(y)) => N(x + y),
        (V(u), V(v)) => V(u + v),
        (P(p), V(v)) | (V(v), P(p)) => P(p + v),
        (P(p), P(q)) => point(p.to_vector() + q.to_vector()),
        _ => return Err(BinaryOp::Add.error(a, b)),
    })
}

fn subtract(a: &Operand, b: &Operand) -> Result<Operand, EvalError> {
    use Operand::{Number as N, Point as P, Vector as V};
    Ok(match (a.numeric(), b.numeric()) {
        (N(x), N(y)) => N(x - y),
        (V(u), V(v)) => V(u - v),
        (P(p), P(q)) => V(p - q),
        (P(p), V(v)) => P(p - v),
        (V(v), P(p)) => V(v - p.to_vector()),
        _ => return Err(BinaryOp::Subtract.error(a, b)),
    })
}

fn multiply(a: &Operand, b: &Operand) -> Result<Operand, EvalError> {
    use Operand::{Number as N, Point as P, Vector as V};
    let (a2, b2) = (a.numeric(), b.numeric());
    if let (Some(u), Some(v)) = (a2.components(), b2.components()) {
        return Ok(N(u.dot(v)));
    }
    Ok(match (a2, b2) {
        (N(x), N(y)) => N(x * y),
        (V(v), N(s)) | (N(s), V(v)) => V(v * s),
        (P(p), N(s)) | (N(s), P(p)) => point(p.to_vector() * s),
        _ => return Err(BinaryOp::Multiply.error(a, b)),
    })
}

fn divide(a: &Operand, b: &Operand) -> Result<Operand, EvalError> {
    use Operand::{Number as N, Point as P, Vector as V};
    Ok(match (a.numeric(), b.numeric()) {
        (N(x), N(y)) => N(x / y),
        (V(v), N(s)) => V(v / s),
        (P(p), N(s)) => point(p.to_vector() / s),
        _ => return Err(BinaryOp::Divide.error(a, b)),
    })
}

fn numbers(
    op: BinaryOp,
    a: &Operand,
    b: &Operand,
    f: impl Fn(f64, f64) -> f64,
) -> Result<Operand, EvalError> {
    match (a.as_number(), b.as_number()) {
        (Some(x), Some(y)) => Ok(Operand::Number(f(x, y))),
        _ => Err(op.error(a, b)),
    }
}

fn compare(
    op: BinaryOp,
    a: &Operand,
    b: &Operand,
    f: impl Fn(f64, f64) -> bool,
) -> Result<Operand, EvalError> {
    match (a.as_number(), b.as_number()) {
        (Some(x), Some(y)) => Ok(Operand::Boolean(f(x, y))),
        _ => Err(op.error(a, b)),
    }
}

/// Exact equality: numbers (and booleans, as 0 and 1) by value, texts character by character
/// (case-sensitive), points and vectors component by component.
fn equal(a: &Operand, b: &Operand) -> Result<bool, EvalError> {
    if let (Operand::Text(s), Operand::Text(t)) = (a, b) {
        return Ok(s == t);
    }
    if let (Some(x), Some(y)) = (a.as_number(), b.as_number()) {
        return Ok(x == y);
    }
    if let (Some(u), Some(v)) = (a.components(), b.components()) {
        return Ok(u == v);
    }
    Err(BinaryOp::Equal.error(a, b))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64, z: f64) -> Operand {
        Operand::Point(Point3::new(x, y, z))
    }

    fn v(x: f64, y: f64, z: f64) -> Operand {
        Operand::Vector(Vector3::new(x, y, z))
    }

    fn n(x: f64) -> Operand {
        Operand::Number(x)
    }

    #[test]
    fn point_and_vector_arithmetic() {
        let a = p(1.0, 2.0, 3.0);
        let b = p(4.0, 6.0, 3.0);
        assert_eq!(BinaryOp::Subtract.apply(&b, &a), Ok(v(3.0, 4.0, 0.0)));
        assert_eq!(
            BinaryOp::Add.apply(&a, &v(1.0, 1.0, 1.0)),
            Ok(p(2.0, 3.0, 4.0))
        );
        assert_eq!(
            BinaryOp::Add.apply(&v(1.0, 1.0, 1.0), &a),
            Ok(p(2.0, 3.0, 4.0))
        );
        assert_eq!(BinaryOp::Add.apply(&a, &b), Ok(p(5.0, 8.0, 6.0)));
        assert_eq!(
            BinaryOp::Multiply.apply(&n(2.0), &v(1.0, 0.0, -1.0)),
            Ok(v(2.0, 0.0, -2.0))
        );
        assert_eq!(
            BinaryOp::Multiply.apply(&v(1.0, 2.0, 3.0), &v(4.0, 5.0, 6.0)),
            Ok(n(32.0))
        );
        assert_eq!(BinaryOp::Divide.apply(&a, &n(2.0)), Ok(p(0.5, 1.0, 1.5)));
        assert_eq!(
            UnaryOp::Negate.apply(&v(1.0, -2.0, 0.0)),
            Ok(v(-1.0, 2.0, -0.0))
        );
    }

    #[test]
    fn booleans_count_as_zero_and_one() {
        let t = Operand::Boolean(true);
        assert_eq!(BinaryOp::Add.apply(&t, &t), Ok(n(2.0)));
        assert_eq!(
            BinaryOp::Equal.apply(&t, &n(1.0)),
            Ok(Operand::Boolean(true))
        );
    }

    #[test]
    fn kind_mismatches_are_errors() {
        let text = Operand::Text(Arc::from("a"));
        let e = BinaryOp::Add.apply(&text, &n(1.0)).unwrap_err();
        assert_eq!(e.to_string(), "cannot compute Text + Number");
        let e = BinaryOp::Divide
            .apply(&n(1.0), &v(1.0, 0.0, 0.0))
            .unwrap_err();
        assert_eq!(e.to_string(), "cannot compute Number / Vector");
        let e = BinaryOp::Less
            .apply(&p(0.0, 0.0, 0.0), &n(1.0))
            .unwrap_err();
        assert_eq!(e.to_string(), "cannot compute Point < Number");
        let e = UnaryOp::Negate.apply(&text).unwrap_err();
        assert_eq!(e.to_string(), "cannot compute -Text");
        assert!(BinaryOp::And.apply(&text, &n(1.0)).is_err());
    }

    #[test]
    fn text_equality_and_concatenation() {
        let a = Operand::Text(Arc::from("abc"));
        let b = Operand::Text(Arc::from("abc"));
        assert_eq!(BinaryOp::Equal.apply(&a, &b), Ok(Operand::Boolean(true)));
        assert_eq!(
            BinaryOp::Concatenate.apply(&a, &n(1.5)),
            Ok(Operand::Text(Arc::from("abc1.5")))
        );
        assert!(BinaryOp::Equal.apply(&a, &n(1.0)).is_err());
    }

    #[test]
    fn modulus_keeps_the_sign_of_the_dividend() {
        assert_eq!(BinaryOp::Modulus.apply(&n(-7.0), &n(3.0)), Ok(n(-1.0)));
        assert_eq!(BinaryOp::Modulus.apply(&n(7.5), &n(2.0)), Ok(n(1.5)));
    }

    #[test]
    fn nan_is_neither_true_nor_false() {
        assert!(n(f64::NAN).truth().is_err());
        assert_eq!(n(2.0).truth(), Ok(true));
    }

    #[test]
    fn invalid_numbers_become_nan() {
        let r = n(f64::INFINITY).with_invalid_as_nan();
        assert!(matches!(r, Operand::Number(x) if x.is_nan()));
        let r = v(1.0, f64::NEG_INFINITY, 0.0).with_invalid_as_nan();
        assert!(matches!(r, Operand::Vector(u) if u.x == 1.0 && u.y.is_nan()));
    }

    #[test]
    fn values_convert_both_ways() {
        assert_eq!(Operand::from_value(&Value::Integer(3)), Ok(n(3.0)));
        assert_eq!(
            Operand::from_value_numeric(&Value::Text(" 2.5 ".into())),
            Ok(n(2.5))
        );
        assert_eq!(
            Operand::from_value_numeric(&Value::Text("abc".into()))
                .unwrap_err()
                .to_string(),
            "cannot read \"abc\" as a number"
        );
        assert!(Operand::from_value(&Value::Domain(locus_kernel::Interval::UNIT)).is_err());
        assert_eq!(
            p(1.0, 2.0, 3.0).into_value(),
            Value::Point(Point3::new(1.0, 2.0, 3.0))
        );
    }
}
