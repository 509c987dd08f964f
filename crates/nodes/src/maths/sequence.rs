//! Number sequences: Range and Series.
//!
//! Grasshopper files these under Sets › Sequence, so their category is `Sets` and their ids
//! are `sets.range` and `sets.series`; they live with the Maths nodes because they are
//! arithmetic on numbers.

use locus_kernel::Interval;
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port, Solve};

use super::invalid_number_warning;

/// Id of [`range`].
pub const RANGE: &str = "sets.range";
/// Id of [`series`].
pub const SERIES: &str = "sets.series";

/// The longest list Range and Series make (ten million numbers, 80 MB), so that a typo in a
/// count is an error on the node rather than an exhausted machine.
pub const MAX_SEQUENCE_LENGTH: usize = 10_000_000;

/// Registers the sequence nodes.
pub fn register(registry: &mut NodeRegistry) {
    registry.register(range());
    registry.register(series());
}

/// Range \[Range\]: `N + 1` numbers evenly spaced over a domain, ends included.
pub fn range() -> NodeType {
    NodeType::new(RANGE, "Range", "Range", "Sets")
        .gh_guid("9445ca40-cc73-4861-a455-146308676855")
        .subcategory("Sequence")
        .description(
            "Divides a domain into N equal steps and lists the N + 1 numbers from its start to \
             its end (both included).",
        )
        .input(
            Port::new("Domain", "D", DataType::Domain)
                .doc("The domain to divide; default 0 to 1 (a number x is read as 0 to x).")
                .default_value(Interval::UNIT),
        )
        .input(
            Port::new("Steps", "N", DataType::Integer)
                .doc(&format!(
                    "The number of steps, 1 to {MAX_SEQUENCE_LENGTH}; default 10."
                ))
                .default_value(10_i64),
        )
        .output(
            Port::new("Range", "R", DataType::Number)
                .list()
                .doc("The N + 1 numbers."),
        )
        .solve(|s| {
            let domain = *s.item::<Interval>(0)?;
            let steps = *s.item::<i64>(1)?;
            let n = checked_length(steps, 1, "steps")?;
            let values = (0..=n)
                .map(|i| domain.parameter_at(i as f64 / n as f64))
                .collect();
            set_numbers(s, values, || {
                format!("the domain {} to {} is not finite", domain.t0, domain.t1)
            });
            Ok(())
        })
}

/// Series \[Series\]: `C` numbers from `S` in steps of `N`.
pub fn series() -> NodeType {
    NodeType::new(SERIES, "Series", "Series", "Sets")
        .gh_guid("e64c5fb1-845c-4ab1-8911-5f338516ba67")
        .subcategory("Sequence")
        .description("Lists C numbers starting at S and increasing by N each time.")
        .input(
            Port::new("Start", "S", DataType::Number)
                .doc("The first number of the series; default 0.")
                .default_value(0.0),
        )
        .input(
            Port::new("Step", "N", DataType::Number)
                .doc("The difference between successive numbers; default 1.")
                .default_value(1.0),
        )
        .input(
            Port::new("Count", "C", DataType::Integer)
                .doc(&format!(
                    "The number of values, 0 to {MAX_SEQUENCE_LENGTH}; default 10."
                ))
                .default_value(10_i64),
        )
        .output(
            Port::new("Series", "S", DataType::Number)
                .list()
                .doc("The numbers S, S + N, S + 2N, …"),
        )
        .solve(|s| {
            let start = *s.item::<f64>(0)?;
            let step = *s.item::<f64>(1)?;
            let count = checked_length(*s.item::<i64>(2)?, 0, "count")?;
            let values = (0..count).map(|i| start + i as f64 * step).collect();
            set_numbers(s, values, || {
                format!("start {start} and step {step} give numbers that are not finite")
            });
            Ok(())
        })
}

/// `value` as a list length, at least `least` and at most [`MAX_SEQUENCE_LENGTH`].
fn checked_length(value: i64, least: i64, what: &str) -> Result<usize, NodeError> {
    if value < least {
        return Err(NodeError(format!(
            "{what} must be at least {least}, not {value}"
        )));
    }
    match usize::try_from(value) {
        Ok(n) if n <= MAX_SEQUENCE_LENGTH => Ok(n),
        _ => Err(NodeError(format!(
            "{what} must be at most {MAX_SEQUENCE_LENGTH}, not {value}"
        ))),
    }
}

/// Writes a list of numbers to output 0, non-finite ones as NaN with one warning.
fn set_numbers(s: &mut Solve<'_>, mut values: Vec<f64>, why: impl FnOnce() -> String) {
    if values.iter().any(|x| !x.is_finite()) {
        s.warning(invalid_number_warning(&why()));
        for x in &mut values {
            if !x.is_finite() {
                *x = f64::NAN;
            }
        }
    }
    s.set_list(0, values);
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall, TreePath};

    use super::*;
    use crate::maths::test_support::{messages, numbers};

    #[test]
    fn range_defaults_to_eleven_values_from_zero_to_one() {
        let r = NodeCall::new(&range()).run();
        let out = numbers(&r.outputs[0]);
        assert_eq!(out.len(), 11);
        assert_eq!(out[0], 0.0);
        assert_eq!(out[10], 1.0);
        assert!((out[3] - 0.3).abs() < 1e-15);
    }

    #[test]
    fn range_over_a_decreasing_domain_hits_both_ends() {
        let r = NodeCall::new(&range())
            .input(DataTree::from_item(Interval::new(10.0, -2.0)))
            .input(DataTree::from_item(4_i64))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [10.0, 7.0, 4.0, 1.0, -2.0]);
    }

    #[test]
    fn range_gives_one_list_per_item_input() {
        let r = NodeCall::new(&range())
            .skip_input()
            .input(DataTree::from_list(vec![1_i64, 2]))
            .run();
        let paths: Vec<String> = r.outputs[0].paths().map(TreePath::to_string).collect();
        assert_eq!(paths, ["{0;0}", "{0;1}"]);
        assert_eq!(numbers(&r.outputs[0]), [0.0, 1.0, 0.0, 0.5, 1.0]);
    }

    #[test]
    fn range_rejects_bad_step_counts() {
        for (steps, message) in [
            (0, "steps must be at least 1, not 0"),
            (-3, "steps must be at least 1, not -3"),
            (
                i64::MAX,
                "steps must be at most 10000000, not 9223372036854775807",
            ),
        ] {
            let r = NodeCall::new(&range())
                .skip_input()
                .input(DataTree::from_item(steps))
                .run();
            assert_eq!(messages(&r, Level::Error), [message]);
            assert_eq!(r.outputs[0].item_count(), 0);
        }
    }

    #[test]
    fn series_defaults_and_values() {
        let r = NodeCall::new(&series()).run();
        assert_eq!(
            numbers(&r.outputs[0]),
            [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0]
        );
        let r = NodeCall::new(&series())
            .input(DataTree::from_item(1.5))
            .input(DataTree::from_item(-0.5))
            .input(DataTree::from_item(4_i64))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [1.5, 1.0, 0.5, 0.0]);
    }

    #[test]
    fn series_of_zero_is_empty_and_negative_is_an_error() {
        let r = NodeCall::new(&series())
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(0_i64))
            .run();
        assert_eq!(r.outputs[0].item_count(), 0);
        assert!(r.messages.is_empty());
        let r = NodeCall::new(&series())
            .skip_input()
            .skip_input()
            .input(DataTree::from_item(-1_i64))
            .run();
        assert_eq!(
            messages(&r, Level::Error),
            ["count must be at least 0, not -1"]
        );
    }

    #[test]
    fn series_overflow_is_nan_with_one_warning() {
        let r = NodeCall::new(&series())
            .input(DataTree::from_item(f64::MAX))
            .input(DataTree::from_item(f64::MAX))
            .input(DataTree::from_item(3_i64))
            .run();
        let out = numbers(&r.outputs[0]);
        assert_eq!(out[0], f64::MAX);
        assert!(out[1].is_nan() && out[2].is_nan());
        assert_eq!(messages(&r, Level::Warning).len(), 1);
    }
}
