//! Maths: arithmetic and logic operators, domains, number sequences, formulas and functions of
//! one number ([`functions`]: powers, roots, logarithms, trigonometry, Golden Ratio, Epsilon,
//! Extremes) (Grasshopper's Maths tab, plus Range and Series from Sets › Sequence).
//!
//! Numeric results that are not finite (division by zero, `sqrt` of a negative number,
//! overflow) are written as NaN with a warning, and the item is kept so that lists stay
//! aligned, as Grasshopper's number parameter does.

pub mod boolean;
pub mod comparison;
pub mod domain;
pub mod domain2;
pub mod functions;
pub mod mass;
pub mod operators;
pub mod script;
pub mod sequence;
pub mod util;

use locus_runtime::{NodeRegistry, Solve};

use crate::expression::Operand;

/// Registers every Maths node type.
pub fn register(registry: &mut NodeRegistry) {
    operators::register(registry);
    comparison::register(registry);
    boolean::register(registry);
    domain::register(registry);
    domain2::register(registry);
    sequence::register(registry);
    script::register(registry);
    mass::register(registry);
    util::register(registry);
    functions::register(registry);
}

/// The warning for an invalid numeric result, `why` saying what produced it.
pub(crate) fn invalid_number_warning(why: &str) -> String {
    format!("invalid numeric result, kept as NaN: {why}")
}

/// Writes a number to an item output; a non-finite number is written as NaN with a warning
/// built by `why`.
pub(crate) fn set_number(s: &mut Solve<'_>, output: usize, x: f64, why: impl FnOnce() -> String) {
    if x.is_finite() {
        s.set(output, x);
    } else {
        s.warning(invalid_number_warning(&why()));
        s.set(output, f64::NAN);
    }
}

/// Writes an operand to an item output, non-finite numbers in it as NaN. `why` says which
/// invalid number (an input, or an intermediate result) was met on the way, if any: it is
/// reported as a warning even when the result itself is finite (as `vector / ∞` is).
pub(crate) fn set_operand(s: &mut Solve<'_>, output: usize, r: Operand, why: Option<String>) {
    let why = why.or_else(|| (!r.is_finite()).then(|| format!("the result is {r}")));
    if let Some(why) = why {
        s.warning(if r.is_finite() {
            format!("invalid number on the way to the result: {why}")
        } else {
            invalid_number_warning(&why)
        });
    }
    s.set_value(output, Some(r.with_invalid_as_nan().into_value()));
}

#[cfg(test)]
pub(crate) mod test_support {
    //! Helpers for node tests: the crate's [`crate::test_support`].
    pub(crate) use crate::test_support::*;
}
