//! Maths › Domain: numeric domains (intervals) and remapping numbers between them.
//!
//! A domain runs from its start to its end and may be decreasing (start > end).

use locus_kernel::Interval;
use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

use super::{invalid_number_warning, set_number};

/// Id of [`construct_domain`].
pub const CONSTRUCT_DOMAIN: &str = "maths.construct_domain";
/// Id of [`deconstruct_domain`].
pub const DECONSTRUCT_DOMAIN: &str = "maths.deconstruct_domain";
/// Id of [`remap_numbers`].
pub const REMAP_NUMBERS: &str = "maths.remap_numbers";

/// Registers the domain nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [construct_domain(), deconstruct_domain(), remap_numbers()] {
        registry.register(t);
    }
}

/// Construct Domain \[Dom\]: the domain from A to B.
pub fn construct_domain() -> NodeType {
    NodeType::new(CONSTRUCT_DOMAIN, "Construct Domain", "Dom", "Maths")
        .gh_guid("d1a28e95-cf96-4936-bf34-8bf142d731bf")
        .subcategory("Domain")
        .description(
            "Creates a numeric domain from two numbers. The order is kept: A > B makes a \
             decreasing domain.",
        )
        .input(
            Port::new("Domain start", "A", DataType::Number)
                .doc("The start of the domain; default 0.")
                .default_value(0.0),
        )
        .input(
            Port::new("Domain end", "B", DataType::Number)
                .doc("The end of the domain; default 1.")
                .default_value(1.0),
        )
        .output(Port::new("Domain", "I", DataType::Domain).doc("The domain from A to B."))
        .solve(|s| {
            let a = *s.item::<f64>(0)?;
            let b = *s.item::<f64>(1)?;
            let domain = Interval::new(a, b);
            if !domain.is_finite() {
                s.warning(format!(
                    "the domain {a} to {b} has an end that is not a finite number"
                ));
            }
            s.set(0, domain);
            Ok(())
        })
}

/// Deconstruct Domain \[DeDomain\]: the start and end of a domain.
pub fn deconstruct_domain() -> NodeType {
    NodeType::new(
        DECONSTRUCT_DOMAIN,
        "Deconstruct Domain",
        "DeDomain",
        "Maths",
    )
    .gh_guid("825ea536-aebb-41e9-af32-8baeb2ecb590")
    .subcategory("Domain")
    .description("Splits a numeric domain into its start and end.")
    .input(Port::new("Domain", "I", DataType::Domain).doc("The domain."))
    .output(Port::new("Start", "S", DataType::Number).doc("The start of the domain."))
    .output(Port::new("End", "E", DataType::Number).doc("The end of the domain."))
    .solve(|s| {
        let d = *s.item::<Interval>(0)?;
        s.set(0, d.t0);
        s.set(1, d.t1);
        Ok(())
    })
}

/// Remap Numbers \[ReMap\]: moves a number from a source domain to a target domain.
pub fn remap_numbers() -> NodeType {
    NodeType::new(REMAP_NUMBERS, "Remap Numbers", "ReMap", "Maths")
        .gh_guid("2fcc2743-8339-4cdf-a046-a1f17439191d")
        .subcategory("Domain")
        .description(
            "Remaps a number from a source domain into a target domain, keeping its relative \
             position: the source start maps to the target start and the source end to the \
             target end. Values outside the source domain map outside the target domain \
             (Mapped) or are clipped to it (Clipped). A source domain of zero length gives NaN \
             with a warning.",
        )
        .input(Port::new("Value", "V", DataType::Number).doc("The number to remap."))
        .input(
            Port::new("Source", "S", DataType::Domain)
                .doc("The domain the value is measured in; default 0 to 1.")
                .default_value(Interval::UNIT),
        )
        .input(
            Port::new("Target", "T", DataType::Domain)
                .doc("The domain to map into; default 0 to 1.")
                .default_value(Interval::UNIT),
        )
        .output(Port::new("Mapped", "R", DataType::Number).doc("The remapped number."))
        .output(
            Port::new("Clipped", "C", DataType::Number)
                .doc("The remapped number, limited to the target domain."),
        )
        .solve(|s| {
            let v = *s.item::<f64>(0)?;
            let source = *s.item::<Interval>(1)?;
            let target = *s.item::<Interval>(2)?;
            let t = match source.normalized_parameter_at(v) {
                Ok(t) => t,
                Err(_) => {
                    s.warning(invalid_number_warning(&format!(
                        "the source domain {} to {} has zero length",
                        source.t0, source.t1
                    )));
                    s.set(0, f64::NAN);
                    s.set(1, f64::NAN);
                    return Ok(());
                }
            };
            let mapped = target.parameter_at(t);
            let why = || format!("remapping {v} gave {mapped}");
            set_number(s, 0, mapped, why);
            let clipped = mapped.clamp(target.min(), target.max());
            set_number(s, 1, clipped, why);
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_runtime::{DataTree, Level, NodeCall, Value};

    use super::*;
    use crate::maths::test_support::{messages, numbers, values};

    #[test]
    fn construct_with_defaults_and_values() {
        let r = NodeCall::new(&construct_domain()).run();
        assert_eq!(values(&r.outputs[0]), [Some(Value::Domain(Interval::UNIT))]);
        let r = NodeCall::new(&construct_domain())
            .input(DataTree::from_item(5.0))
            .input(DataTree::from_list(vec![2.0, 8.0]))
            .run();
        assert_eq!(
            values(&r.outputs[0]),
            [
                Some(Value::Domain(Interval::new(5.0, 2.0))),
                Some(Value::Domain(Interval::new(5.0, 8.0)))
            ]
        );
    }

    #[test]
    fn construct_warns_about_non_finite_ends() {
        let r = NodeCall::new(&construct_domain())
            .input(DataTree::from_item(f64::NAN))
            .run();
        assert_eq!(messages(&r, Level::Warning).len(), 1);
        assert_eq!(r.outputs[0].item_count(), 1);
    }

    #[test]
    fn deconstruct() {
        let r = NodeCall::new(&deconstruct_domain())
            .input(DataTree::from_item(Interval::new(3.0, -1.0)))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [3.0]);
        assert_eq!(numbers(&r.outputs[1]), [-1.0]);
    }

    #[test]
    fn remap_and_clip() {
        let r = NodeCall::new(&remap_numbers())
            .input(DataTree::from_list(vec![0.0, 25.0, 100.0, 150.0]))
            .input(DataTree::from_item(Interval::new(0.0, 100.0)))
            .input(DataTree::from_item(Interval::new(10.0, 0.0)))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [10.0, 7.5, 0.0, -5.0]);
        assert_eq!(numbers(&r.outputs[1]), [10.0, 7.5, 0.0, 0.0]);
        assert!(r.messages.is_empty());
    }

    #[test]
    fn remap_defaults_are_the_unit_domain() {
        let r = NodeCall::new(&remap_numbers())
            .input(DataTree::from_item(0.25))
            .run();
        assert_eq!(numbers(&r.outputs[0]), [0.25]);
    }

    #[test]
    fn zero_length_source_is_nan_with_a_warning() {
        let r = NodeCall::new(&remap_numbers())
            .input(DataTree::from_list(vec![1.0, 2.0]))
            .input(DataTree::from_item(Interval::new(3.0, 3.0)))
            .run();
        let out = numbers(&r.outputs[0]);
        assert!(out.len() == 2 && out.iter().all(|x| x.is_nan()));
        assert_eq!(
            messages(&r, Level::Warning)[0],
            "invalid numeric result, kept as NaN: the source domain 3 to 3 has zero length"
        );
    }
}
