//! Maths › Domain: two-dimensional domains (Domain², a u and a v interval) and the division of
//! domains into equal parts.
//!
//! Grasshopper's Divide Domain² with Isotrim is the usual way to cut a surface into panels:
//! the parts come u-major, every v part of the first u part first.

use locus_kernel::{Interval, UvInterval};
use locus_runtime::{DataType, NodeError, NodeRegistry, NodeType, Port};

/// Id of [`divide_domain`].
pub const DIVIDE_DOMAIN: &str = "maths.divide_domain";
/// Id of [`construct_domain2`].
pub const CONSTRUCT_DOMAIN2: &str = "maths.construct_domain2";
/// Id of [`construct_domain2_numbers`].
pub const CONSTRUCT_DOMAIN2_NUMBERS: &str = "maths.construct_domain2_numbers";
/// Id of [`deconstruct_domain2_numbers`].
pub const DECONSTRUCT_DOMAIN2_NUMBERS: &str = "maths.deconstruct_domain2_numbers";
/// Id of [`divide_domain2`].
pub const DIVIDE_DOMAIN2: &str = "maths.divide_domain2";

/// The most parts one division makes (for Divide Domain², U Count × V Count).
pub const MAX_DOMAIN_PARTS: u64 = 10_000_000;

/// Registers the Domain² nodes and Divide Domain.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        divide_domain(),
        construct_domain2(),
        construct_domain2_numbers(),
        deconstruct_domain2_numbers(),
        divide_domain2(),
    ] {
        registry.register(t);
    }
}

/// A count of parts on input `input`: 0 or more (0 makes no parts).
fn part_count(n: i64, input: &str) -> Result<usize, NodeError> {
    if n < 0 {
        return Err(format!("input {input}: the count must not be negative, got {n}").into());
    }
    usize::try_from(n)
        .ok()
        .filter(|&c| c as u64 <= MAX_DOMAIN_PARTS)
        .ok_or_else(|| format!("input {input}: at most {MAX_DOMAIN_PARTS} parts, got {n}").into())
}

fn unit_domain_port(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Domain)
        .default_value(Interval::UNIT)
        .doc(doc)
}

fn number_port(name: &str, nickname: &str, default: f64, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Number)
        .default_value(default)
        .doc(doc)
}

/// Divide Domain \[Div\]: equal parts of a domain.
pub fn divide_domain() -> NodeType {
    NodeType::new(DIVIDE_DOMAIN, "Divide Domain", "Div", "Maths")
        .gh_guid("75ef4190-91a2-42d9-a245-32a7162b0384")
        .subcategory("Domain")
        .description(
            "Divides a domain into Count equal parts, in order. Neighbouring parts share their \
             bounds exactly and the last part ends exactly on the domain's end; a decreasing \
             domain gives decreasing parts. A count of 0 gives an empty list.",
        )
        .input(
            Port::new("Domain", "I", DataType::Domain)
                .doc("The domain to divide (numbers cast as 0 to x)."),
        )
        .input(
            Port::new("Count", "C", DataType::Integer)
                .default_value(10_i64)
                .doc("Number of parts, 0 or more. Default 10."),
        )
        .output(
            Port::new("Segments", "S", DataType::Domain)
                .list()
                .doc("The parts, one list per domain."),
        )
        .solve(|s| {
            let d = *s.item::<Interval>(0)?;
            let n = part_count(*s.item::<i64>(1)?, "C")?;
            if !d.is_finite() {
                return Err(
                    format!("input I: the domain {} to {} is not finite", d.t0, d.t1).into(),
                );
            }
            s.set_list(0, d.divide(n));
            Ok(())
        })
}

/// Construct Domain² \[Dom²\]: a two-dimensional domain from a u and a v domain.
pub fn construct_domain2() -> NodeType {
    NodeType::new(CONSTRUCT_DOMAIN2, "Construct Domain²", "Dom²", "Maths")
        .gh_guid("8555a743-36c1-42b8-abcc-06d9cb94519f")
        .subcategory("Domain")
        .description(
            "Creates a two-dimensional domain from its u and v domains, kept as given \
             (decreasing domains stay decreasing).",
        )
        .input(unit_domain_port(
            "Domain U",
            "U",
            "The domain in u; default 0 to 1.",
        ))
        .input(unit_domain_port(
            "Domain V",
            "V",
            "The domain in v; default 0 to 1.",
        ))
        .output(Port::new("2D Domain", "I²", DataType::Domain2).doc("The domain U × V."))
        .solve(|s| {
            let u = *s.item::<Interval>(0)?;
            let v = *s.item::<Interval>(1)?;
            s.set(0, UvInterval::new(u, v));
            Ok(())
        })
}

/// Construct Domain² \[Dom²Num\]: a two-dimensional domain from four numbers.
pub fn construct_domain2_numbers() -> NodeType {
    NodeType::new(
        CONSTRUCT_DOMAIN2_NUMBERS,
        "Construct Domain² Numbers",
        "Dom²Num",
        "Maths",
    )
    .gh_guid("9083b87f-a98c-4e41-9591-077ae4220b19")
    .subcategory("Domain")
    .description(
        "Creates a two-dimensional domain from the ends of its u and v domains, in the order \
         given (Grasshopper names this component Construct Domain² too).",
    )
    .input(number_port(
        "U min",
        "U0",
        0.0,
        "The start of the u domain; default 0.",
    ))
    .input(number_port(
        "U max",
        "U1",
        1.0,
        "The end of the u domain; default 1.",
    ))
    .input(number_port(
        "V min",
        "V0",
        0.0,
        "The start of the v domain; default 0.",
    ))
    .input(number_port(
        "V max",
        "V1",
        1.0,
        "The end of the v domain; default 1.",
    ))
    .output(Port::new("2D Domain", "I²", DataType::Domain2).doc("The domain U0 to U1 × V0 to V1."))
    .solve(|s| {
        let [u0, u1, v0, v1] = [0, 1, 2, 3].map(|i| s.item::<f64>(i).copied());
        let d = UvInterval::new(Interval::new(u0?, u1?), Interval::new(v0?, v1?));
        if !d.is_finite() {
            s.warning("the domain has an end that is not a finite number".to_owned());
        }
        s.set(0, d);
        Ok(())
    })
}

/// Deconstruct Domain² \[DeDom2Num\]: the four ends of a two-dimensional domain.
pub fn deconstruct_domain2_numbers() -> NodeType {
    NodeType::new(
        DECONSTRUCT_DOMAIN2_NUMBERS,
        "Deconstruct Domain² Numbers",
        "DeDom2Num",
        "Maths",
    )
    .gh_guid("47c30f9d-b685-4d4d-9b20-5b60e48d5af8")
    .subcategory("Domain")
    .description(
        "Splits a two-dimensional domain into the start and end of its u and v domains, as \
         stored (a decreasing domain's U min is larger than its U max). Grasshopper names this \
         component Deconstruct Domain² too.",
    )
    .input(
        Port::new("Domain", "I", DataType::Domain2)
            .doc("The two-dimensional domain (a surface casts to its domain)."),
    )
    .output(Port::new("U min", "U0", DataType::Number).doc("The start of the u domain."))
    .output(Port::new("U max", "U1", DataType::Number).doc("The end of the u domain."))
    .output(Port::new("V min", "V0", DataType::Number).doc("The start of the v domain."))
    .output(Port::new("V max", "V1", DataType::Number).doc("The end of the v domain."))
    .solve(|s| {
        let d = *s.item::<UvInterval>(0)?;
        for (k, x) in [d.u.t0, d.u.t1, d.v.t0, d.v.t1].into_iter().enumerate() {
            s.set(k, x);
        }
        Ok(())
    })
}

/// Divide Domain² \[Divide\]: equal parts of a two-dimensional domain.
pub fn divide_domain2() -> NodeType {
    NodeType::new(DIVIDE_DOMAIN2, "Divide Domain²", "Divide", "Maths")
        .gh_guid("75ac008b-1bc2-4edd-b967-667d628b9d24")
        .subcategory("Domain")
        .description(
            "Divides a two-dimensional domain into U Count × V Count equal parts, as one list, \
             u-major: every v part of the first u part, then those of the next. Neighbouring \
             parts share their bounds exactly and the last ones end exactly on the domain's \
             ends. A surface on input I is divided over its own domain (the usual way to \
             panel a surface with Isotrim). A count of 0 gives an empty list.",
        )
        .input(
            Port::new("Domain", "I", DataType::Domain2)
                .doc("The domain to divide; a surface casts to its u and v domains."),
        )
        .input(
            Port::new("U Count", "U", DataType::Integer)
                .default_value(10_i64)
                .doc("Number of parts in u, 0 or more. Default 10."),
        )
        .input(
            Port::new("V Count", "V", DataType::Integer)
                .default_value(10_i64)
                .doc("Number of parts in v, 0 or more. Default 10."),
        )
        .output(
            Port::new("Segments", "S", DataType::Domain2)
                .list()
                .doc("The parts, one list per domain."),
        )
        .solve(|s| {
            let d = *s.item::<UvInterval>(0)?;
            let u = part_count(*s.item::<i64>(1)?, "U")?;
            let v = part_count(*s.item::<i64>(2)?, "V")?;
            if (u as u64).saturating_mul(v as u64) > MAX_DOMAIN_PARTS {
                return Err(format!(
                    "inputs U and V: {u} × {v} parts is more than {MAX_DOMAIN_PARTS}"
                )
                .into());
            }
            if !d.is_finite() {
                return Err("input I: the domain has an end that is not a finite number".into());
            }
            s.set_list(0, d.divide(u, v));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{NurbsSurface, Point3};
    use locus_runtime::{DataTree, Level, NodeCall, Shared, Value};

    use super::*;
    use crate::maths::test_support::{messages, numbers, values};

    fn d2(u0: f64, u1: f64, v0: f64, v1: f64) -> UvInterval {
        UvInterval::new(Interval::new(u0, u1), Interval::new(v0, v1))
    }

    #[test]
    fn divide_domain_parts_end_exactly() {
        let r = NodeCall::new(&divide_domain())
            .input(DataTree::from_item(Interval::new(0.0, 0.7)))
            .input(DataTree::from_item(3_i64))
            .run();
        let parts = values(&r.outputs[0]);
        assert_eq!(parts.len(), 3);
        assert_eq!(
            parts[2],
            Some(Value::Domain(Interval::new(0.7 * 2.0 / 3.0, 0.7)))
        );
        let r = NodeCall::new(&divide_domain())
            .input(DataTree::from_item(5.0))
            .input(DataTree::from_item(0_i64))
            .run();
        assert_eq!(r.outputs[0].item_count(), 0);
        assert!(r.messages.is_empty(), "{:?}", r.messages);
        let r = NodeCall::new(&divide_domain())
            .input(DataTree::from_item(Interval::new(0.0, 1.0)))
            .input(DataTree::from_item(-2_i64))
            .run();
        assert_eq!(
            messages(&r, Level::Error),
            ["input C: the count must not be negative, got -2"]
        );
    }

    #[test]
    fn construct_and_deconstruct_domain2() {
        let r = NodeCall::new(&construct_domain2())
            .input(DataTree::from_item(Interval::new(2.0, 1.0)))
            .run();
        assert_eq!(
            values(&r.outputs[0]),
            [Some(Value::Domain2(d2(2.0, 1.0, 0.0, 1.0)))]
        );
        let r = NodeCall::new(&construct_domain2_numbers())
            .input(DataTree::from_item(1.0))
            .input(DataTree::from_item(2.0))
            .input(DataTree::from_item(3.0))
            .input(DataTree::from_item(4.0))
            .run();
        let Some(Value::Domain2(d)) = values(&r.outputs[0])[0] else {
            panic!("{:?}", r.outputs[0])
        };
        assert_eq!(d, d2(1.0, 2.0, 3.0, 4.0));
        let r = NodeCall::new(&deconstruct_domain2_numbers())
            .input(DataTree::from_item(d))
            .run();
        let ends: Vec<f64> = (0..4).flat_map(|k| numbers(&r.outputs[k])).collect();
        assert_eq!(ends, [1.0, 2.0, 3.0, 4.0]);
    }

    #[test]
    fn divide_domain2_is_u_major_and_takes_a_surface() {
        let r = NodeCall::new(&divide_domain2())
            .input(DataTree::from_item(d2(0.0, 1.0, 0.0, 2.0)))
            .input(DataTree::from_item(2_i64))
            .input(DataTree::from_item(3_i64))
            .run();
        let parts = values(&r.outputs[0]);
        assert_eq!(parts.len(), 6);
        assert_eq!(
            parts[1],
            Some(Value::Domain2(d2(0.0, 0.5, 2.0 / 3.0, 4.0 / 3.0)))
        );
        assert_eq!(parts[5], Some(Value::Domain2(d2(0.5, 1.0, 4.0 / 3.0, 2.0))));
        let plane = NurbsSurface::non_rational(
            1,
            1,
            vec![
                vec![Point3::ORIGIN, Point3::new(0.0, 1.0, 0.0)],
                vec![Point3::new(1.0, 0.0, 0.0), Point3::new(1.0, 1.0, 0.0)],
            ],
            vec![0.0, 4.0],
            vec![-1.0, 1.0],
        )
        .unwrap();
        let r = NodeCall::new(&divide_domain2())
            .input(DataTree::from_item(Shared::new(plane)))
            .input(DataTree::from_item(4_i64))
            .input(DataTree::from_item(1_i64))
            .run();
        let parts = values(&r.outputs[0]);
        assert_eq!(parts[3], Some(Value::Domain2(d2(3.0, 4.0, -1.0, 1.0))));
    }

    #[test]
    fn divide_domain2_refuses_huge_and_negative_counts() {
        let r = NodeCall::new(&divide_domain2())
            .input(DataTree::from_item(d2(0.0, 1.0, 0.0, 1.0)))
            .input(DataTree::from_item(100_000_i64))
            .input(DataTree::from_item(100_000_i64))
            .run();
        assert_eq!(r.outputs[0].item_count(), 0);
        assert!(messages(&r, Level::Error)[0].contains("more than 10000000"));
        let r = NodeCall::new(&divide_domain2())
            .input(DataTree::from_item(d2(0.0, f64::NAN, 0.0, 1.0)))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }
}
