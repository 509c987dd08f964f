//! Params › Input › Graph Mapper: numbers mapped through a graph.
//!
//! Grasshopper's Graph Mapper is a canvas widget whose graph is edited with grips. Here the
//! graph is given by settings: its type, the X and Y domains, and the type's parameters as a
//! list of numbers. Each graph `g` is defined on the unit square; an input `x` is normalised
//! to `u = (x − X.t0) / (X.t1 − X.t0)`, clamped to 0 to 1, and the output is
//! `Y.t0 + g(u)·(Y.t1 − Y.t0)`.

use std::sync::Arc;

use locus_kernel::Interval;
use locus_runtime::{
    DataType, NodeConfig, NodeError, NodeRegistry, NodeType, Port, Prepared, Value,
};

/// Id of [`graph_mapper`].
pub const GRAPH_MAPPER: &str = "params.graph_mapper";

/// Bisection steps when a Bézier graph is solved for its parameter (2⁻⁶⁰ of the unit).
const BEZIER_STEPS: usize = 60;

/// Registers the Graph Mapper.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(graph_mapper());
}

/// A graph on the unit square.
#[derive(Clone, Debug, PartialEq)]
pub enum Graph {
    /// `g(u) = a + (b − a)·u`: the line from `(0, a)` to `(1, b)`.
    Linear {
        /// The value at 0.
        a: f64,
        /// The value at 1.
        b: f64,
    },
    /// `g(u) = k + c·(u − h)²`: a parabola with its vertex at `(h, k)`.
    Parabola {
        /// The vertex abscissa.
        h: f64,
        /// The vertex ordinate.
        k: f64,
        /// The curvature factor.
        c: f64,
    },
    /// `g(u) = m + a·sin(2π·f·u + φ)`.
    Sine {
        /// The amplitude.
        a: f64,
        /// The frequency, in periods over the unit.
        f: f64,
        /// The phase, in radians.
        phase: f64,
        /// The mean value.
        m: f64,
    },
    /// The cubic Bézier from `(0, 0)` through controls `p1`, `p2` to `(1, 1)`, as a function
    /// of its x coordinate.
    Bezier {
        /// The first control point.
        p1: (f64, f64),
        /// The second control point.
        p2: (f64, f64),
    },
}

impl Graph {
    /// The graph of a type name with parameters (empty for the defaults).
    ///
    /// # Errors
    /// An unknown type, a wrong number of parameters, a parameter that is not finite, or a
    /// Bézier control whose x is outside 0 to 1 (its graph would not be a function).
    pub fn new(kind: &str, p: &[f64]) -> Result<Self, String> {
        if p.iter().any(|x| !x.is_finite()) {
            return Err("the graph parameters must be finite numbers".to_owned());
        }
        let want = |n: usize, defaults: &[f64]| -> Result<Vec<f64>, String> {
            match p.len() {
                0 => Ok(defaults.to_vec()),
                k if k == n => Ok(p.to_vec()),
                k => Err(format!("a {kind} graph takes {n} parameters, not {k}")),
            }
        };
        Ok(match kind.trim().to_ascii_lowercase().as_str() {
            "linear" => {
                let v = want(2, &[0.0, 1.0])?;
                Graph::Linear { a: v[0], b: v[1] }
            }
            "parabola" => {
                let v = want(3, &[0.5, 1.0, -4.0])?;
                Graph::Parabola {
                    h: v[0],
                    k: v[1],
                    c: v[2],
                }
            }
            "sine" => {
                let v = want(4, &[0.5, 1.0, 0.0, 0.5])?;
                Graph::Sine {
                    a: v[0],
                    f: v[1],
                    phase: v[2],
                    m: v[3],
                }
            }
            "bezier" => {
                let v = want(4, &[0.5, 0.0, 0.5, 1.0])?;
                if !(0.0..=1.0).contains(&v[0]) || !(0.0..=1.0).contains(&v[2]) {
                    return Err(
                        "the x of the Bézier controls must be in 0 to 1, so that the graph is a \
                         function"
                            .to_owned(),
                    );
                }
                Graph::Bezier {
                    p1: (v[0], v[1]),
                    p2: (v[2], v[3]),
                }
            }
            other => {
                return Err(format!(
                    "unknown graph type {other:?}: use linear, parabola, sine or bezier"
                ));
            }
        })
    }

    /// The graph's value at `u` (clamped to 0 to 1).
    pub fn eval(&self, u: f64) -> f64 {
        let u = u.clamp(0.0, 1.0);
        match *self {
            Graph::Linear { a, b } => a + (b - a) * u,
            Graph::Parabola { h, k, c } => k + c * (u - h) * (u - h),
            Graph::Sine { a, f, phase, m } => m + a * (std::f64::consts::TAU * f * u + phase).sin(),
            Graph::Bezier { p1, p2 } => {
                let cubic = |t: f64, a: f64, b: f64| {
                    let s = 1.0 - t;
                    3.0 * s * s * t * a + 3.0 * s * t * t * b + t * t * t
                };
                // x(t) runs from 0 to 1 and, with controls in 0 to 1, never decreases, so
                // bisection finds the t with x(t) = u.
                let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
                for _ in 0..BEZIER_STEPS {
                    let mid = 0.5 * (lo + hi);
                    if cubic(mid, p1.0, p2.0) < u {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                cubic(0.5 * (lo + hi), p1.1, p2.1)
            }
        }
    }
}

/// What Graph Mapper prepares from its settings.
#[derive(Debug)]
struct Mapping {
    graph: Graph,
    x: Interval,
    y: Interval,
}

fn domain_setting(config: &NodeConfig<'_>, name: &str) -> Result<Interval, NodeError> {
    match config.setting(name) {
        Some(Value::Domain(d)) if d.is_finite() => Ok(*d),
        Some(Value::Domain(d)) => Err(NodeError(format!(
            "setting {name}: the domain {} to {} is not finite",
            d.t0, d.t1
        ))),
        Some(other) => Err(NodeError(format!(
            "setting {name} must be a Domain, not a {}",
            other.data_type()
        ))),
        None => Ok(Interval::UNIT),
    }
}

fn prepare(config: &NodeConfig<'_>) -> Result<Prepared, NodeError> {
    let kind = match config.setting("graph") {
        Some(Value::Text(t)) => t.clone(),
        _ => "linear".to_owned(),
    };
    let params: Vec<f64> = match config.setting("parameters") {
        Some(Value::Text(t)) if !t.trim().is_empty() => t
            .split(',')
            .map(|x| {
                locus_runtime::parse_number(x.trim())
                    .ok_or_else(|| NodeError(format!("graph parameter {x:?} is not a number")))
            })
            .collect::<Result<_, _>>()?,
        _ => Vec::new(),
    };
    let graph = Graph::new(&kind, &params).map_err(NodeError)?;
    let x = domain_setting(config, "x_domain")?;
    if x.length() == 0.0 {
        return Err(NodeError("setting x_domain has zero length".into()));
    }
    Ok(Arc::new(Mapping {
        graph,
        x,
        y: domain_setting(config, "y_domain")?,
    }) as Prepared)
}

/// Graph Mapper \[Graph\]: numbers mapped through a graph.
pub fn graph_mapper() -> NodeType {
    NodeType::new(GRAPH_MAPPER, "Graph Mapper", "Graph", "Params")
        .subcategory("Input")
        .gh_guid("bc984576-7aa6-491f-a91d-e444c33675a7")
        .description(
            "Maps numbers through a graph on the unit square: x is normalised to u in the X \
             domain (clamped to 0 to 1) and the result is Y.t0 + g(u)·(Y.t1 − Y.t0). Graphs \
             (the graph setting, with its parameters as comma-separated numbers): linear \
             a, b: a + (b − a)u (default 0, 1); parabola h, k, c: k + c(u − h)² (default \
             0.5, 1, −4: an arch from 0 up to 1 and back); sine a, f, φ, m: m + a·sin(2πfu + φ) \
             (default 0.5, 1, 0, 0.5); bezier x1, y1, x2, y2: the cubic Bézier from (0, 0) \
             through the controls to (1, 1) as a function of x, controls' x in 0 to 1 \
             (default 0.5, 0, 0.5, 1: an ease-in-out). The grip editing of Grasshopper's \
             widget becomes these parameters.",
        )
        .input(Port::new("Numbers", "x", DataType::Number).doc("The numbers to map."))
        .output(Port::new("Numbers", "y", DataType::Number).doc("The mapped numbers."))
        .setting(
            "graph",
            DataType::Text,
            Some(Value::Text("linear".into())),
            "The graph type: linear, parabola, sine or bezier; default linear.",
        )
        .setting(
            "parameters",
            DataType::Text,
            Some(Value::Text(String::new())),
            "The graph's parameters, comma-separated numbers (see the description); empty for \
             the type's defaults.",
        )
        .setting(
            "x_domain",
            DataType::Domain,
            Some(Value::Domain(Interval::UNIT)),
            "The domain of the input numbers; default 0 to 1.",
        )
        .setting(
            "y_domain",
            DataType::Domain,
            Some(Value::Domain(Interval::UNIT)),
            "The domain the graph's 0 to 1 is scaled to; default 0 to 1.",
        )
        .prepare(prepare)
        .solve(|s| {
            let m = s
                .prepared::<Mapping>()
                .ok_or_else(|| NodeError("internal: the graph was not prepared".into()))?;
            let x = *s.item::<f64>(0)?;
            if x.is_nan() {
                return Err(NodeError("the number is NaN".into()));
            }
            let u = (x - m.x.t0) / (m.x.t1 - m.x.t0);
            let y = m.y.t0 + m.graph.eval(u) * (m.y.t1 - m.y.t0);
            s.set(0, y);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::sets::test_support::messages;
    use crate::test_support::numbers;

    fn map(graph: &str, params: &str, xs: Vec<f64>) -> Vec<f64> {
        let r = NodeCall::new(&graph_mapper())
            .input(DataTree::from_list(xs))
            .setting("graph", Value::Text(graph.into()))
            .setting("parameters", Value::Text(params.into()))
            .run();
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        numbers(&r.outputs[0])
    }

    fn close(a: &[f64], b: &[f64]) -> bool {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12)
    }

    #[test]
    fn linear_parabola_and_sine_graphs() {
        assert_eq!(
            map("linear", "", vec![0.0, 0.25, 1.0, 2.0, -1.0]),
            [0.0, 0.25, 1.0, 1.0, 0.0]
        );
        assert_eq!(map("linear", "1, 0", vec![0.25]), [0.75]);
        assert!(close(
            &map("parabola", "", vec![0.0, 0.5, 0.75]),
            &[0.0, 1.0, 0.75]
        ));
        assert!(close(
            &map("sine", "", vec![0.0, 0.25, 0.75]),
            &[0.5, 1.0, 0.0]
        ));
    }

    #[test]
    fn bezier_graph_is_an_ease_in_out() {
        let y = map("bezier", "", vec![0.0, 0.5, 1.0, 0.1, 0.9]);
        assert!(close(&y[..3], &[0.0, 0.5, 1.0]), "{y:?}");
        assert!(y[3] < 0.1 && y[4] > 0.9, "{y:?}");
        // The straight Bézier is the diagonal.
        let y = map(
            "bezier",
            "0.3333333333333333, 0.3333333333333333, 0.6666666666666666, 0.6666666666666666",
            vec![0.2, 0.7],
        );
        assert!(close(&y, &[0.2, 0.7]), "{y:?}");
    }

    #[test]
    fn domains_scale_the_graph() {
        let r = NodeCall::new(&graph_mapper())
            .input(DataTree::from_list(vec![10.0, 15.0, 20.0]))
            .setting("x_domain", Value::Domain(Interval::new(10.0, 20.0)))
            .setting("y_domain", Value::Domain(Interval::new(0.0, 100.0)))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [0.0, 50.0, 100.0]);
    }

    #[test]
    fn bad_settings_and_inputs_are_errors() {
        for (graph, params) in [
            ("spline", ""),
            ("linear", "1"),
            ("linear", "a, b"),
            ("bezier", "2, 0, 0.5, 1"),
            ("sine", "1, 1, 1, NaN"),
        ] {
            let r = NodeCall::new(&graph_mapper())
                .input(DataTree::from_item(0.5))
                .setting("graph", Value::Text(graph.into()))
                .setting("parameters", Value::Text(params.into()))
                .run();
            assert!(!messages(&r, Level::Error).is_empty(), "{graph} {params}");
        }
        let r = NodeCall::new(&graph_mapper())
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_eq!(messages(&r, Level::Error), ["the number is NaN"]);
    }
}
