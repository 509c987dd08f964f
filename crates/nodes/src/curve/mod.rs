//! Curve: Grasshopper's Curve tab — primitives (Line, Circle, Arc), splines (PolyLine, Bézier
//! Span, NURBS curves, Interpolate, Knot Vector), analysis (evaluation, curvature, domains,
//! lengths, closest points, continuity), division (Divide Curve, Divide Length, Shatter) and
//! utilities (Flip Curve, Split Curve) and editing (Join Curves, Explode, Offset Curve).
//!
//! Curves flow as `Value::Curve`; lines, circles and arcs also have their own value types, which
//! the nodes that build them output (as Grasshopper's Line gives a line). Every port that takes a
//! curve accepts lines, circles and arcs too (see [`curve_input`]).
//!
//! Parameters are curve parameters in the curve's own domain, as in Grasshopper: a line from the
//! Line node has the domain `[0, length]`, a polyline `[0, n − 1]`, a circle `[0, 2π]`, an arc its
//! angle interval. Tangents are unit vectors.

pub mod analysis;
pub mod dash;
pub mod deconstruct_arc;
pub mod derivatives;
pub mod division;
pub mod edit;
pub mod extend;
pub mod frames;
pub mod point_on_curve;
pub mod primitive;
pub mod primitive_more;
pub mod primitive_rect;
pub mod regions;
pub mod spline;
pub mod util;

use locus_kernel::basis::MAX_DEGREE;
use locus_kernel::{Curve, KnotStyle, Point3};
use locus_runtime::{NodeError, NodeRegistry, Shared, Solve, Value};

/// Registers every Curve node type.
pub fn register(registry: &mut NodeRegistry) {
    primitive::register(registry);
    spline::register(registry);
    analysis::register(registry);
    division::register(registry);
    util::register(registry);
    primitive_more::register(registry);
    primitive_rect::register(registry);
    edit::register(registry);
    frames::register(registry);
    extend::register(registry);
    regions::register(registry);
    derivatives::register(registry);
    deconstruct_arc::register(registry);
    dash::register(registry);
    point_on_curve::register(registry);
}

/// The curve a value stands for: a curve as it is, a line, circle or arc as the same curve
/// (with its usual domain); `None` for other values.
pub fn curve_from_value(value: &Value) -> Option<Shared<Curve>> {
    match value {
        Value::Curve(c) => Some(c.clone()),
        Value::Line(l) => Some(Shared::new(Curve::from(*l))),
        Value::Circle(c) => Some(Shared::new(Curve::from(*c))),
        Value::Arc(a) => Some(Shared::new(Curve::from(*a))),
        _ => None,
    }
}

/// The nickname of input `input`, for messages.
pub(crate) fn input_name(s: &Solve<'_>, input: usize) -> String {
    s.input_port(input)
        .map_or_else(|| format!("#{input}"), |p| p.nickname.clone())
}

/// The curve on item input `input`: a curve, or a line, circle or arc taken as a curve.
///
/// # Errors
/// When the input has no item, holds another type, or holds a line, circle or arc that is not
/// valid (non-finite, zero radius).
pub(crate) fn curve_input(s: &Solve<'_>, input: usize) -> Result<Shared<Curve>, NodeError> {
    let curve = match s.item_opt::<Shared<Curve>>(input) {
        Some(c) => c.clone(),
        None => {
            let Some(value) = s.value(input) else {
                return Err(format!("input {} has no curve", input_name(s, input)).into());
            };
            curve_from_value(&value).ok_or_else(|| {
                format!(
                    "input {}: a {} is not a curve",
                    input_name(s, input),
                    value.data_type()
                )
            })?
        }
    };
    valid_curve(&curve, &input_name(s, input))?;
    Ok(curve)
}

/// Checks that a curve arriving on the input named `input` is valid, as [`curve_input`] does.
///
/// # Errors
/// When it is a line, circle, arc or polyline that is not valid (non-finite, zero radius).
pub(crate) fn valid_curve(curve: &Curve, input: &str) -> Result<(), NodeError> {
    // NURBS curves are valid by construction; the other kinds carry raw fields.
    if !matches!(curve, Curve::Nurbs(_)) && !curve.is_valid() {
        return Err(format!("input {input}: the curve is not valid").into());
    }
    Ok(())
}

/// The points of list input `input`, nulls left out (with a warning).
pub(crate) fn point_list(s: &mut Solve<'_>, input: usize) -> Result<Vec<Point3>, NodeError> {
    let list = s.list::<Point3>(input)?;
    let points: Vec<Point3> = list.present().copied().collect();
    let nulls = list.len() - points.len();
    if nulls > 0 {
        s.warning(format!(
            "input {}: {nulls} null item(s) left out",
            input_name(s, input)
        ));
    }
    Ok(points)
}

/// The numbers of list input `input`, nulls left out (with a warning).
pub(crate) fn number_list(s: &mut Solve<'_>, input: usize) -> Result<Vec<f64>, NodeError> {
    let list = s.list::<f64>(input)?;
    let numbers: Vec<f64> = list.present().copied().collect();
    let nulls = list.len() - numbers.len();
    if nulls > 0 {
        s.warning(format!(
            "input {}: {nulls} null item(s) left out",
            input_name(s, input)
        ));
    }
    Ok(numbers)
}

/// A curve degree from an integer input: from 1 to the kernel's maximum.
pub(crate) fn degree_from(degree: i64) -> Result<usize, NodeError> {
    if degree < 1 || degree > MAX_DEGREE as i64 {
        return Err(format!("degree {degree} is not between 1 and {MAX_DEGREE}").into());
    }
    Ok(degree as usize)
}

/// Grasshopper's knot style number: 0 uniform, 1 chord, 2 square root of chord.
pub(crate) fn knot_style_from(style: i64) -> Result<KnotStyle, NodeError> {
    match style {
        0 => Ok(KnotStyle::Uniform),
        1 => Ok(KnotStyle::Chord),
        2 => Ok(KnotStyle::ChordSquareRoot),
        _ => Err(format!(
            "knot style {style} is not 0 (uniform), 1 (chord) or 2 (square root of chord)"
        )
        .into()),
    }
}

/// Checks that a parameter is a finite number.
pub(crate) fn finite_parameter(t: f64, name: &str) -> Result<f64, NodeError> {
    if t.is_finite() {
        Ok(t)
    } else {
        Err(format!("parameter {name} is {t}, not a finite number").into())
    }
}

/// Writes a new curve with its length and domain to outputs `first`, `first + 1`,
/// `first + 2` (the Curve, Length, Domain outputs of Grasshopper's spline components).
pub(crate) fn set_curve_length_domain(s: &mut Solve<'_>, first: usize, curve: Curve) {
    let length = curve.length();
    let domain = curve.domain();
    s.set(first, Shared::new(curve));
    s.set(first + 1, length);
    s.set(first + 2, domain);
}

#[cfg(test)]
pub(crate) mod test_support {
    //! Helpers for curve node tests: the crate's [`crate::test_support`] and curve trees.

    use locus_kernel::{Curve, Point3};
    use locus_runtime::{DataTree, Shared};

    pub(crate) use crate::test_support::*;

    /// A tree of one curve item.
    pub(crate) fn curve_tree(curve: impl Into<Curve>) -> DataTree {
        DataTree::from_item(Shared::new(curve.into()))
    }

    /// `p` and `q` agree to `tol`.
    pub(crate) fn close(p: Point3, q: Point3, tol: f64) -> bool {
        p.distance(q) <= tol
    }
}
