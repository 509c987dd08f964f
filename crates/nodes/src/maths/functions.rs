//! Maths › Polynomials, Trig and Util, functions of one number: Square, Square Root, Cube,
//! Cube Root, the powers of 2, 10 and e, the logarithms, the trigonometric functions and their
//! inverses, Golden Ratio, Epsilon and Extremes.
//!
//! Each is a plain function of its item, lifted over typed columns. As everywhere in Maths, a
//! result that is not a finite number (the square root or logarithm of a negative number,
//! `asin(2)`, an overflow) is written as NaN with a warning naming the function and its
//! argument, and the item is kept.

use locus_runtime::{DataType, ItemReport, NodeRegistry, NodeType, Port};

use super::invalid_number_warning;

/// Id of [`square`].
pub const SQUARE: &str = "maths.square";
/// Id of [`square_root`].
pub const SQUARE_ROOT: &str = "maths.square_root";
/// Id of [`cube`].
pub const CUBE: &str = "maths.cube";
/// Id of [`cube_root`].
pub const CUBE_ROOT: &str = "maths.cube_root";
/// Id of [`power_of_2`].
pub const POWER_OF_2: &str = "maths.power_of_2";
/// Id of [`power_of_10`].
pub const POWER_OF_10: &str = "maths.power_of_10";
/// Id of [`power_of_e`].
pub const POWER_OF_E: &str = "maths.power_of_e";
/// Id of [`logarithm`].
pub const LOGARITHM: &str = "maths.logarithm";
/// Id of [`natural_logarithm`].
pub const NATURAL_LOGARITHM: &str = "maths.natural_logarithm";
/// Id of [`log_n`].
pub const LOG_N: &str = "maths.log_n";
/// Id of [`sine`].
pub const SINE: &str = "maths.sine";
/// Id of [`cosine`].
pub const COSINE: &str = "maths.cosine";
/// Id of [`tangent`].
pub const TANGENT: &str = "maths.tangent";
/// Id of [`arc_sine`].
pub const ARC_SINE: &str = "maths.arc_sine";
/// Id of [`arc_cosine`].
pub const ARC_COSINE: &str = "maths.arc_cosine";
/// Id of [`arc_tangent`].
pub const ARC_TANGENT: &str = "maths.arc_tangent";
/// Id of [`secant`].
pub const SECANT: &str = "maths.secant";
/// Id of [`cosecant`].
pub const COSECANT: &str = "maths.cosecant";
/// Id of [`cotangent`].
pub const COTANGENT: &str = "maths.cotangent";
/// Id of [`sinc`].
pub const SINC: &str = "maths.sinc";
/// Id of [`golden_ratio`].
pub const GOLDEN_RATIO: &str = "maths.golden_ratio";
/// Id of [`epsilon`].
pub const EPSILON: &str = "maths.epsilon";
/// Id of [`extremes`].
pub const EXTREMES: &str = "maths.extremes";

/// The golden ratio φ = (1 + √5) / 2, the nearest double.
pub const PHI: f64 = 1.618_033_988_749_895;

/// Registers the functions of one number, Golden Ratio, Epsilon and Extremes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        square(),
        square_root(),
        cube(),
        cube_root(),
        power_of_2(),
        power_of_10(),
        power_of_e(),
        logarithm(),
        natural_logarithm(),
        log_n(),
        sine(),
        cosine(),
        tangent(),
        arc_sine(),
        arc_cosine(),
        arc_tangent(),
        secant(),
        cosecant(),
        cotangent(),
        sinc(),
        golden_ratio(),
        epsilon(),
        extremes(),
    ] {
        registry.register(t);
    }
}

/// `y`, or NaN with a warning when it is not finite.
fn finite(y: f64, report: &mut ItemReport, why: impl FnOnce() -> String) -> f64 {
    if y.is_finite() {
        y
    } else {
        report.warning(invalid_number_warning(&why()));
        f64::NAN
    }
}

/// What a function of one number looks like to its node.
struct Function {
    id: &'static str,
    name: &'static str,
    nickname: &'static str,
    subcategory: &'static str,
    guid: &'static str,
    description: &'static str,
    /// The result in words, for the output's doc ("x²").
    result: &'static str,
    /// The function's name in warnings ("the square root").
    what: &'static str,
    f: fn(f64) -> f64,
}

fn unary(d: Function) -> NodeType {
    let Function {
        what, f, result, ..
    } = d;
    NodeType::new(d.id, d.name, d.nickname, "Maths")
        .subcategory(d.subcategory)
        .gh_guid(d.guid)
        .description(d.description)
        .input(Port::new("Value", "x", DataType::Number).doc("The input value."))
        .output(Port::new("Result", "y", DataType::Number).doc(result))
        .lift1_with(move |x: &f64, report| {
            let x = *x;
            Ok((finite(f(x), report, || format!("{what} of {x}")),))
        })
}

/// Square \[Sqr\]: x².
pub fn square() -> NodeType {
    unary(Function {
        id: SQUARE,
        name: "Square",
        nickname: "Sqr",
        subcategory: "Polynomials",
        guid: "2280dde4-9fa2-4b4a-ae2f-37d554861367",
        description: "Computes the square of a value, x · x.",
        result: "x², NaN with a warning when it overflows.",
        what: "the square",
        f: |x| x * x,
    })
}

/// Square Root \[Sqrt\]: √x.
pub fn square_root() -> NodeType {
    unary(Function {
        id: SQUARE_ROOT,
        name: "Square Root",
        nickname: "Sqrt",
        subcategory: "Polynomials",
        guid: "ad476cb7-b6d1-41c8-986b-0df243a64146",
        description: "Computes the square root of a value. A negative value has no real square \
                      root: NaN with a warning.",
        result: "√x.",
        what: "the square root",
        f: f64::sqrt,
    })
}

/// Cube \[Cube\]: x³.
pub fn cube() -> NodeType {
    unary(Function {
        id: CUBE,
        name: "Cube",
        nickname: "Cube",
        subcategory: "Polynomials",
        guid: "7e3185eb-a38c-4949-bcf2-0e80dee3a344",
        description: "Computes the cube of a value, x · x · x.",
        result: "x³, NaN with a warning when it overflows.",
        what: "the cube",
        f: |x| x * x * x,
    })
}

/// Cube Root \[Cbrt\]: ∛x.
pub fn cube_root() -> NodeType {
    unary(Function {
        id: CUBE_ROOT,
        name: "Cube Root",
        nickname: "Cbrt",
        subcategory: "Polynomials",
        guid: "5b0be57a-31f5-4446-a11a-ae0d348bca90",
        description: "Computes the cube root of a value; a negative value has a negative cube \
                      root (∛−8 = −2).",
        result: "∛x.",
        what: "the cube root",
        f: f64::cbrt,
    })
}

/// Power of 2 \[2º\]: 2^x.
pub fn power_of_2() -> NodeType {
    unary(Function {
        id: POWER_OF_2,
        name: "Power of 2",
        nickname: "2º",
        subcategory: "Polynomials",
        guid: "7a1e5fd7-b7da-4244-a261-f1da66614992",
        description: "Raises 2 to the power of x.",
        result: "2^x, NaN with a warning when it overflows.",
        what: "2 to the power",
        f: f64::exp2,
    })
}

/// Power of 10 \[10º\]: 10^x.
pub fn power_of_10() -> NodeType {
    unary(Function {
        id: POWER_OF_10,
        name: "Power of 10",
        nickname: "10º",
        subcategory: "Polynomials",
        guid: "2ebb82ef-1f90-4ac9-9a71-1fe0f4ef7044",
        description: "Raises 10 to the power of x.",
        result: "10^x, NaN with a warning when it overflows.",
        what: "10 to the power",
        f: |x| 10_f64.powf(x),
    })
}

/// Power of E \[Eº\]: e^x.
pub fn power_of_e() -> NodeType {
    unary(Function {
        id: POWER_OF_E,
        name: "Power of E",
        nickname: "Eº",
        subcategory: "Polynomials",
        guid: "c717f26f-e4a0-475c-8e1c-b8f77af1bc99",
        description: "Raises e (Euler's number) to the power of x.",
        result: "e^x, NaN with a warning when it overflows.",
        what: "e to the power",
        f: f64::exp,
    })
}

/// Logarithm \[Log\]: log₁₀ x.
pub fn logarithm() -> NodeType {
    unary(Function {
        id: LOGARITHM,
        name: "Logarithm",
        nickname: "Log",
        subcategory: "Polynomials",
        guid: "27d6f724-a701-4585-992f-3897488abf08",
        description: "Computes the base-10 logarithm of a value. Zero and negative values have \
                      no finite logarithm: NaN with a warning.",
        result: "log₁₀ x.",
        what: "the base-10 logarithm",
        f: f64::log10,
    })
}

/// Natural logarithm \[Ln\]: ln x.
pub fn natural_logarithm() -> NodeType {
    unary(Function {
        id: NATURAL_LOGARITHM,
        name: "Natural logarithm",
        nickname: "Ln",
        subcategory: "Polynomials",
        guid: "23afc7aa-2d2f-4ae7-b876-bf366246b826",
        description: "Computes the natural (base-e) logarithm of a value. Zero and negative \
                      values have no finite logarithm: NaN with a warning.",
        result: "ln x.",
        what: "the natural logarithm",
        f: f64::ln,
    })
}

/// Log N \[LogN\]: the base-B logarithm of a number.
pub fn log_n() -> NodeType {
    NodeType::new(LOG_N, "Log N", "LogN", "Maths")
        .subcategory("Polynomials")
        .gh_guid("7ab8d289-26a2-4dd4-b4ad-df5b477999d8")
        .description(
            "Computes the base-B logarithm of a number, ln V / ln B. A value or base that gives \
             no finite logarithm (zero, a negative number, base 1) gives NaN with a warning.",
        )
        .input(Port::new("Number", "V", DataType::Number).doc("The value."))
        .input(Port::new("Base", "B", DataType::Number).doc("The logarithm base."))
        .output(Port::new("Result", "R", DataType::Number).doc("log_B V."))
        .lift2_with(|v: &f64, b: &f64, report| {
            let (v, b) = (*v, *b);
            Ok((finite(v.ln() / b.ln(), report, || {
                format!("the base-{b} logarithm of {v}")
            }),))
        })
}

/// The trigonometric functions, in radians.
fn trig(d: Function) -> NodeType {
    unary(Function {
        subcategory: "Trig",
        ..d
    })
}

/// Sine \[Sin\]: sin x.
pub fn sine() -> NodeType {
    trig(Function {
        id: SINE,
        name: "Sine",
        nickname: "Sin",
        subcategory: "",
        guid: "7663efbb-d9b8-4c6a-a0da-c3750a7bbe77",
        description: "Computes the sine of an angle in radians.",
        result: "sin x.",
        what: "the sine",
        f: f64::sin,
    })
}

/// Cosine \[Cos\]: cos x.
pub fn cosine() -> NodeType {
    trig(Function {
        id: COSINE,
        name: "Cosine",
        nickname: "Cos",
        subcategory: "",
        guid: "d2d2a900-780c-4d58-9a35-1f9d8d35df6f",
        description: "Computes the cosine of an angle in radians.",
        result: "cos x.",
        what: "the cosine",
        f: f64::cos,
    })
}

/// Tangent \[Tan\]: tan x.
pub fn tangent() -> NodeType {
    trig(Function {
        id: TANGENT,
        name: "Tangent",
        nickname: "Tan",
        subcategory: "",
        guid: "0f31784f-7177-4104-8500-1f4f4a306df4",
        description: "Computes the tangent of an angle in radians (at π/2 the double nearest \
                      to it gives a large finite number, 1.633e16, as in .NET).",
        result: "tan x.",
        what: "the tangent",
        f: f64::tan,
    })
}

/// ArcSine \[ASin\]: asin x.
pub fn arc_sine() -> NodeType {
    trig(Function {
        id: ARC_SINE,
        name: "ArcSine",
        nickname: "ASin",
        subcategory: "",
        guid: "cc15ba56-fae7-4f05-b599-cb7c43b60e11",
        description: "Computes the angle, in radians from −π/2 to π/2, whose sine is x. Values \
                      outside −1 to 1 have none: NaN with a warning.",
        result: "asin x, in radians.",
        what: "the arc sine",
        f: f64::asin,
    })
}

/// ArcCosine \[ACos\]: acos x.
pub fn arc_cosine() -> NodeType {
    trig(Function {
        id: ARC_COSINE,
        name: "ArcCosine",
        nickname: "ACos",
        subcategory: "",
        guid: "49584390-d541-41f7-b5f6-1f9515ac0f73",
        description: "Computes the angle, in radians from 0 to π, whose cosine is x. Values \
                      outside −1 to 1 have none: NaN with a warning.",
        result: "acos x, in radians.",
        what: "the arc cosine",
        f: f64::acos,
    })
}

/// ArcTangent \[ATan\]: atan x.
pub fn arc_tangent() -> NodeType {
    trig(Function {
        id: ARC_TANGENT,
        name: "ArcTangent",
        nickname: "ATan",
        subcategory: "",
        guid: "b4647919-d041-419e-99f5-fa0dc0ddb8b6",
        description: "Computes the angle, in radians from −π/2 to π/2, whose tangent is x.",
        result: "atan x, in radians.",
        what: "the arc tangent",
        f: f64::atan,
    })
}

/// Secant \[Sec\]: 1 / cos x.
pub fn secant() -> NodeType {
    trig(Function {
        id: SECANT,
        name: "Secant",
        nickname: "Sec",
        subcategory: "",
        guid: "60103def-1bb7-4700-b294-3a89100525c4",
        description: "Computes the secant of an angle in radians, the reciprocal of its cosine.",
        result: "1 / cos x.",
        what: "the secant",
        f: |x| 1.0 / x.cos(),
    })
}

/// CoSecant \[Csc\]: 1 / sin x.
pub fn cosecant() -> NodeType {
    trig(Function {
        id: COSECANT,
        name: "CoSecant",
        nickname: "Csc",
        subcategory: "",
        guid: "d222500b-dfd5-45e0-933e-eabefd07cbfa",
        description: "Computes the co-secant of an angle in radians, the reciprocal of its sine; \
                      at 0 it is infinite: NaN with a warning.",
        result: "1 / sin x.",
        what: "the co-secant",
        f: |x| 1.0 / x.sin(),
    })
}

/// CoTangent \[Cot\]: 1 / tan x.
pub fn cotangent() -> NodeType {
    trig(Function {
        id: COTANGENT,
        name: "CoTangent",
        nickname: "Cot",
        subcategory: "",
        guid: "1f602c33-f38e-4f47-898b-359f0a4de3c2",
        description: "Computes the co-tangent of an angle in radians, the reciprocal of its \
                      tangent; at 0 it is infinite: NaN with a warning.",
        result: "1 / tan x.",
        what: "the co-tangent",
        f: |x| 1.0 / x.tan(),
    })
}

/// Sinc \[Sinc\]: sin x / x.
pub fn sinc() -> NodeType {
    trig(Function {
        id: SINC,
        name: "Sinc",
        nickname: "Sinc",
        subcategory: "",
        guid: "a2d9503d-a83c-4d71-81e0-02af8d09cd0c",
        description: "Computes the sinc (sinus cardinalis) of a value, sin x / x, which is 1 at \
                      x = 0.",
        result: "sin x / x.",
        what: "the sinc",
        f: |x| if x == 0.0 { 1.0 } else { x.sin() / x },
    })
}

/// A factor times a constant (Golden Ratio, Epsilon).
fn constant(
    id: &str,
    name: &str,
    nickname: &str,
    guid: &str,
    description: &str,
    value: f64,
) -> NodeType {
    NodeType::new(id, name, nickname, "Maths")
        .subcategory("Util")
        .gh_guid(guid)
        .description(description)
        .input(
            Port::new("Factor", "N", DataType::Number)
                .doc("The factor to multiply the constant by; default 1.")
                .default_value(1.0),
        )
        .output(Port::new("Output", "y", DataType::Number).doc("N times the constant."))
        .lift1_with(move |n: &f64, report| {
            let n = *n;
            Ok((finite(n * value, report, || format!("{n} times {value}")),))
        })
}

/// Golden Ratio \[Phi\]: a multiple of φ.
pub fn golden_ratio() -> NodeType {
    constant(
        GOLDEN_RATIO,
        "Golden Ratio",
        "Phi",
        "cb22d3ed-93d8-4629-bdf2-c0c7c25afd2c",
        "Returns N times the golden ratio φ = (1 + √5) / 2 = 1.618033988749895 (the nearest \
         double).",
        PHI,
    )
}

/// Epsilon \[Eps\]: a multiple of the double-precision machine epsilon.
pub fn epsilon() -> NodeType {
    constant(
        EPSILON,
        "Epsilon",
        "Eps",
        "deadf87d-99a6-4980-90c3-f98350aa6f0f",
        "Returns N times the double-precision machine epsilon, 2⁻⁵² = 2.220446049250313e-16 \
         (the gap between 1 and the next double).",
        f64::EPSILON,
    )
}

/// Extremes \[Extrz\]: the smallest and largest of several numbers.
pub fn extremes() -> NodeType {
    NodeType::new(EXTREMES, "Extremes", "Extrz", "Maths")
        .subcategory("Util")
        .gh_guid("37084b3f-2b66-4f3a-9737-80d0b0b7f0cb")
        .description(
            "Finds the extremes of several values, item by item: the lowest and the highest of \
             the inputs' numbers (nulls skipped; a NaN makes both NaN, with a warning). The \
             graph may name more inputs (C, D, …).",
        )
        .variable_inputs(
            Port::new("Value", "A", DataType::Number)
                .optional()
                .doc("A value for comparison; optional."),
            &["A", "B"],
        )
        .output(
            Port::new("Mininum", "V-", DataType::Number)
                .doc("The lowest of all values (Grasshopper spells the name Mininum)."),
        )
        .output(Port::new("Maximum", "V+", DataType::Number).doc("The highest of all values."))
        .solve(|s| {
            let xs: Vec<f64> = (0..s.input_count())
                .filter_map(|k| s.item_opt::<f64>(k).copied())
                .collect();
            if xs.is_empty() {
                s.warning("no input has a value");
                s.set_value(0, None);
                s.set_value(1, None);
                return Ok(());
            }
            if xs.iter().any(|x| x.is_nan()) {
                s.warning(invalid_number_warning("a value is NaN"));
                s.set(0, f64::NAN);
                s.set(1, f64::NAN);
                return Ok(());
            }
            s.set(0, xs.iter().copied().fold(f64::INFINITY, f64::min));
            s.set(1, xs.iter().copied().fold(f64::NEG_INFINITY, f64::max));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, FRAC_PI_6, PI};

    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::maths::test_support::{assert_clean, messages, numbers};

    fn run(node: &NodeType, xs: Vec<f64>) -> locus_runtime::NodeCallResult {
        NodeCall::new(node).input(DataTree::from_list(xs)).run()
    }

    #[test]
    fn powers_and_roots() {
        assert_eq!(
            numbers(&run(&square(), vec![3.0, -1.5]).outputs[0]),
            [9.0, 2.25]
        );
        assert_eq!(
            numbers(&run(&square_root(), vec![16.0, 2.0]).outputs[0]),
            [4.0, 2_f64.sqrt()]
        );
        assert_eq!(
            numbers(&run(&cube(), vec![2.0, -3.0]).outputs[0]),
            [8.0, -27.0]
        );
        assert_eq!(
            numbers(&run(&cube_root(), vec![27.0, -8.0]).outputs[0]),
            [3.0, -2.0]
        );
        assert_eq!(
            numbers(&run(&power_of_2(), vec![10.0, -1.0]).outputs[0]),
            [1024.0, 0.5]
        );
        assert_eq!(
            numbers(&run(&power_of_10(), vec![3.0]).outputs[0]),
            [1000.0]
        );
        assert_eq!(
            numbers(&run(&power_of_e(), vec![0.0, 1.0]).outputs[0]),
            [1.0, std::f64::consts::E]
        );
    }

    #[test]
    fn logarithms() {
        assert_eq!(
            numbers(&run(&logarithm(), vec![1000.0, 1.0]).outputs[0]),
            [3.0, 0.0]
        );
        assert_eq!(
            numbers(&run(&natural_logarithm(), vec![std::f64::consts::E]).outputs[0]),
            [1.0]
        );
        let r = NodeCall::new(&log_n())
            .input(DataTree::from_list(vec![8.0, 81.0]))
            .input(DataTree::from_list(vec![2.0, 3.0]))
            .run();
        assert_clean(&r);
        let y = numbers(&r.outputs[0]);
        assert!(
            (y[0] - 3.0).abs() < 1e-15 && (y[1] - 4.0).abs() < 1e-15,
            "{y:?}"
        );
    }

    #[test]
    fn invalid_results_are_nan_with_a_warning() {
        let r = run(&square_root(), vec![-4.0, 9.0]);
        let y = numbers(&r.outputs[0]);
        assert!(y[0].is_nan());
        assert_eq!(y[1], 3.0);
        let w = messages(&r, Level::Warning);
        assert_eq!(w.len(), 1);
        assert!(w[0].contains("the square root of -4"), "{w:?}");
        assert_eq!(r.messages[0].index, Some(0));
        for node in [
            logarithm(),
            natural_logarithm(),
            arc_sine(),
            arc_cosine(),
            cosecant(),
        ] {
            let r = run(
                &node,
                vec![if node.id == ARC_SINE || node.id == ARC_COSINE {
                    2.0
                } else {
                    0.0
                }],
            );
            assert!(numbers(&r.outputs[0])[0].is_nan(), "{}", node.id);
            assert_eq!(messages(&r, Level::Warning).len(), 1, "{}", node.id);
        }
        let r = run(&square(), vec![1e200, f64::NAN]);
        assert_eq!(messages(&r, Level::Warning).len(), 2);
    }

    #[test]
    fn trigonometry_in_radians() {
        let s = numbers(&run(&sine(), vec![FRAC_PI_6, FRAC_PI_2]).outputs[0]);
        assert!((s[0] - 0.5).abs() < 1e-15 && s[1] == 1.0, "{s:?}");
        let c = numbers(&run(&cosine(), vec![0.0, PI]).outputs[0]);
        assert_eq!(c, [1.0, -1.0]);
        let t = numbers(&run(&tangent(), vec![FRAC_PI_4]).outputs[0]);
        assert!((t[0] - 1.0).abs() < 1e-15);
        assert_eq!(
            numbers(&run(&arc_sine(), vec![1.0]).outputs[0]),
            [FRAC_PI_2]
        );
        assert_eq!(numbers(&run(&arc_cosine(), vec![-1.0]).outputs[0]), [PI]);
        assert_eq!(
            numbers(&run(&arc_tangent(), vec![1.0]).outputs[0]),
            [FRAC_PI_4]
        );
        assert_eq!(numbers(&run(&secant(), vec![0.0]).outputs[0]), [1.0]);
        let csc = numbers(&run(&cosecant(), vec![FRAC_PI_2]).outputs[0]);
        assert_eq!(csc, [1.0]);
        let cot = numbers(&run(&cotangent(), vec![FRAC_PI_4]).outputs[0]);
        assert!((cot[0] - 1.0).abs() < 1e-15);
        let sc = numbers(&run(&sinc(), vec![0.0, PI / 2.0]).outputs[0]);
        assert_eq!(sc[0], 1.0);
        assert!((sc[1] - 2.0 / PI).abs() < 1e-15, "{sc:?}");
    }

    #[test]
    fn golden_ratio_epsilon_and_extremes() {
        assert_eq!(PHI, (1.0 + 5_f64.sqrt()) / 2.0);
        let r = run(&golden_ratio(), vec![1.0, 2.0]);
        assert_eq!(numbers(&r.outputs[0]), [PHI, 2.0 * PHI]);
        let r = NodeCall::new(&golden_ratio()).run();
        assert_eq!(numbers(&r.outputs[0]), [PHI]);
        let r = run(&epsilon(), vec![1.0]);
        assert_eq!(numbers(&r.outputs[0]), [2.220446049250313e-16]);
        let r = NodeCall::new(&extremes())
            .input(DataTree::from_list(vec![3.0, -1.0]))
            .input(DataTree::from_item(1.0))
            .run();
        assert_clean(&r);
        assert_eq!(numbers(&r.outputs[0]), [1.0, -1.0]);
        assert_eq!(numbers(&r.outputs[1]), [3.0, 1.0]);
        let r = NodeCall::new(&extremes())
            .input_names(&["A", "B", "C"])
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(f64::NAN))
            .input(DataTree::from_item(5.0))
            .run();
        assert!(numbers(&r.outputs[0])[0].is_nan());
        assert_eq!(messages(&r, Level::Warning).len(), 1);
    }
}
