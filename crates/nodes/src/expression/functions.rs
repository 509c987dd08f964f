//! The built-in functions of the expression language.
//!
//! Names are case-insensitive. Angles are in radians. `if` is not here: the parser compiles
//! it to jumps so that only the chosen branch is evaluated.

use super::{EvalError, Operand};

/// A built-in function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Function {
    /// `abs(x)`: the absolute value; for a vector or point, its length.
    Abs,
    /// `sign(x)`: −1, 0 or 1.
    Sign,
    /// `sqrt(x)`: the square root.
    Sqrt,
    /// `exp(x)`: eˣ.
    Exp,
    /// `ln(x)`: the natural logarithm.
    Ln,
    /// `log(x)`: the base-10 logarithm; `log(x, b)`: the base-b logarithm.
    Log,
    /// `sin(x)`
    Sin,
    /// `cos(x)`
    Cos,
    /// `tan(x)`
    Tan,
    /// `asin(x)`
    Asin,
    /// `acos(x)`
    Acos,
    /// `atan(x)`
    Atan,
    /// `atan2(y, x)`: the angle of the point (x, y), in −π..π.
    Atan2,
    /// `sinh(x)`
    Sinh,
    /// `cosh(x)`
    Cosh,
    /// `tanh(x)`
    Tanh,
    /// `min(a, b, …)`: the smallest argument (NaN if any is NaN).
    Min,
    /// `max(a, b, …)`: the largest argument (NaN if any is NaN).
    Max,
    /// `round(x)`: the nearest whole number, halves away from zero; `round(x, n)`: to n
    /// decimals (0 to 15).
    Round,
    /// `floor(x)`: the largest whole number not above x.
    Floor,
    /// `ceiling(x)` (or `ceil(x)`): the smallest whole number not below x.
    Ceiling,
    /// `trunc(x)`: x with its fraction removed (towards zero).
    Trunc,
    /// `frac(x)`: the fraction, `x − trunc(x)` (it has the sign of x).
    Frac,
    /// `unit(v)`, also written `[v]` as in Grasshopper: the vector (or a point's position
    /// vector) scaled to length 1; a zero vector is an error.
    Unit,
}

/// Every function with its name, for lookup and documentation.
pub const FUNCTIONS: &[(&str, Function)] = &[
    ("abs", Function::Abs),
    ("sign", Function::Sign),
    ("sqrt", Function::Sqrt),
    ("exp", Function::Exp),
    ("ln", Function::Ln),
    ("log", Function::Log),
    ("sin", Function::Sin),
    ("cos", Function::Cos),
    ("tan", Function::Tan),
    ("asin", Function::Asin),
    ("acos", Function::Acos),
    ("atan", Function::Atan),
    ("atan2", Function::Atan2),
    ("sinh", Function::Sinh),
    ("cosh", Function::Cosh),
    ("tanh", Function::Tanh),
    ("min", Function::Min),
    ("max", Function::Max),
    ("round", Function::Round),
    ("floor", Function::Floor),
    ("ceiling", Function::Ceiling),
    ("ceil", Function::Ceiling),
    ("trunc", Function::Trunc),
    ("frac", Function::Frac),
    ("unit", Function::Unit),
];

impl Function {
    /// The function called `name`, ignoring case.
    pub fn from_name(name: &str) -> Option<Self> {
        FUNCTIONS
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|&(_, f)| f)
    }

    /// The canonical lower-case name.
    pub fn name(self) -> &'static str {
        FUNCTIONS
            .iter()
            .find(|&&(_, f)| f == self)
            .map_or("?", |&(n, _)| n)
    }

    /// The fewest and most arguments the function takes (`None`: no upper limit).
    pub fn arity(self) -> (usize, Option<usize>) {
        match self {
            Function::Min | Function::Max => (1, None),
            Function::Log | Function::Round => (1, Some(2)),
            Function::Atan2 => (2, Some(2)),
            _ => (1, Some(1)),
        }
    }

    /// Applies the function to its arguments (the parser has checked their number).
    ///
    /// # Errors
    /// [`EvalError::Argument`] when an argument is not a number (or, for `abs`, a vector or
    /// point); [`EvalError::Digits`] for a bad digit count in `round`.
    pub fn apply(self, args: &[Operand]) -> Result<Operand, EvalError> {
        if self == Function::Unit {
            let v = match args {
                [Operand::Vector(v)] => *v,
                [Operand::Point(p)] => p.to_vector(),
                [other, ..] => {
                    return Err(EvalError::VectorArgument {
                        function: self.name(),
                        got: other.kind(),
                    });
                }
                [] => return Err(EvalError::Internal("missing argument")),
            };
            return v
                .try_normalize()
                .map(Operand::Vector)
                .ok_or(EvalError::ZeroVector);
        }
        if self == Function::Abs
            && let [Operand::Vector(v)] = args
        {
            return Ok(Operand::Number(v.length()));
        }
        if self == Function::Abs
            && let [Operand::Point(p)] = args
        {
            return Ok(Operand::Number(p.to_vector().length()));
        }
        let number = |k: usize| -> Result<f64, EvalError> {
            let a = args.get(k).ok_or(EvalError::Internal("missing argument"))?;
            a.as_number().ok_or_else(|| EvalError::Argument {
                function: self.name(),
                got: a.kind(),
            })
        };
        let x = number(0)?;
        let r = match self {
            Function::Abs => x.abs(),
            Function::Sign => {
                if x == 0.0 || x.is_nan() {
                    x
                } else {
                    x.signum()
                }
            }
            Function::Sqrt => x.sqrt(),
            Function::Exp => x.exp(),
            Function::Ln => x.ln(),
            Function::Log => match args.len() {
                1 => x.log10(),
                _ => x.ln() / number(1)?.ln(),
            },
            Function::Sin => x.sin(),
            Function::Cos => x.cos(),
            Function::Tan => x.tan(),
            Function::Asin => x.asin(),
            Function::Acos => x.acos(),
            Function::Atan => x.atan(),
            Function::Atan2 => x.atan2(number(1)?),
            Function::Sinh => x.sinh(),
            Function::Cosh => x.cosh(),
            Function::Tanh => x.tanh(),
            Function::Min | Function::Max => {
                let mut best = x;
                for k in 1..args.len() {
                    let y = number(k)?;
                    if y.is_nan() || best.is_nan() {
                        best = f64::NAN;
                    } else if (self == Function::Min && y < best)
                        || (self == Function::Max && y > best)
                    {
                        best = y;
                    }
                }
                best
            }
            Function::Round => match args.len() {
                1 => x.round(),
                _ => {
                    let digits = number(1)?;
                    if !(0.0..=15.0).contains(&digits) || digits.fract() != 0.0 {
                        return Err(EvalError::Digits(digits));
                    }
                    let scale = 10f64.powi(digits as i32);
                    let scaled = x * scale;
                    if scaled.is_finite() {
                        scaled.round() / scale
                    } else {
                        x
                    }
                }
            },
            Function::Floor => x.floor(),
            Function::Ceiling => x.ceil(),
            Function::Trunc => x.trunc(),
            Function::Frac => x - x.trunc(),
            Function::Unit => unreachable!("handled above"),
        };
        Ok(Operand::Number(r))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn call(f: Function, args: &[f64]) -> f64 {
        let args: Vec<Operand> = args.iter().map(|&x| Operand::Number(x)).collect();
        match f.apply(&args) {
            Ok(Operand::Number(x)) => x,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn names_are_case_insensitive() {
        assert_eq!(Function::from_name("SQRT"), Some(Function::Sqrt));
        assert_eq!(Function::from_name("Ceil"), Some(Function::Ceiling));
        assert_eq!(Function::from_name("nope"), None);
        assert_eq!(Function::Ceiling.name(), "ceiling");
    }

    #[test]
    fn values() {
        assert_eq!(call(Function::Sign, &[-3.0]), -1.0);
        assert_eq!(call(Function::Sign, &[0.0]), 0.0);
        assert_eq!(call(Function::Log, &[1000.0]), 3.0);
        assert!((call(Function::Log, &[8.0, 2.0]) - 3.0).abs() < 1e-15);
        assert_eq!(call(Function::Round, &[2.5]), 3.0);
        assert_eq!(call(Function::Round, &[-2.5]), -3.0);
        assert_eq!(call(Function::Round, &[1.23456, 2.0]), 1.23);
        assert_eq!(call(Function::Frac, &[-2.25]), -0.25);
        assert_eq!(call(Function::Min, &[3.0, -1.0, 2.0]), -1.0);
        assert_eq!(call(Function::Max, &[3.0, -1.0, 2.0]), 3.0);
        assert!(call(Function::Max, &[3.0, f64::NAN]).is_nan());
        assert_eq!(
            call(Function::Atan2, &[1.0, 0.0]),
            std::f64::consts::FRAC_PI_2
        );
        assert!(call(Function::Sqrt, &[-1.0]).is_nan());
    }

    #[test]
    fn abs_of_a_vector_is_its_length() {
        let v = Operand::Vector(locus_kernel::Vector3::new(3.0, 4.0, 0.0));
        assert_eq!(Function::Abs.apply(&[v]), Ok(Operand::Number(5.0)));
    }

    #[test]
    fn unit_scales_vectors_and_points_to_length_one() {
        let v = Operand::Vector(locus_kernel::Vector3::new(3.0, 0.0, 4.0));
        assert_eq!(
            Function::Unit.apply(&[v]),
            Ok(Operand::Vector(locus_kernel::Vector3::new(0.6, 0.0, 0.8)))
        );
        let p = Operand::Point(locus_kernel::Point3::new(0.0, -2.0, 0.0));
        assert_eq!(
            Function::Unit.apply(&[p]),
            Ok(Operand::Vector(locus_kernel::Vector3::new(0.0, -1.0, 0.0)))
        );
        let zero = Operand::Vector(locus_kernel::Vector3::ZERO);
        assert_eq!(Function::Unit.apply(&[zero]), Err(EvalError::ZeroVector));
        assert_eq!(
            Function::Unit
                .apply(&[Operand::Number(2.0)])
                .unwrap_err()
                .to_string(),
            "unit needs a Vector or a Point, not a Number"
        );
    }

    #[test]
    fn bad_arguments_are_errors() {
        let v = Operand::Vector(locus_kernel::Vector3::X);
        assert_eq!(
            Function::Sqrt.apply(&[v]).unwrap_err().to_string(),
            "sqrt needs a Number, not a Vector"
        );
        assert!(
            Function::Round
                .apply(&[Operand::Number(1.0), Operand::Number(-1.0)])
                .is_err()
        );
    }
}
