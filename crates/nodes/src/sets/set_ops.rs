//! Sets › Sets, the set algebra: Create Set, Set Union, Set Intersection, Set Difference,
//! Set Difference (S) (the symmetric difference), Set Majority, Disjoint and SubSet.
//!
//! A set is a list whose members are compared by type and value ([`MemberKey`]): numbers and
//! integers by their numeric value (so the integer 2 and the number 2.0 are one member, which
//! locus needs because integer literals are integers, while Grasshopper's parameters would
//! have made both numbers), booleans, texts (case-sensitive), points, vectors, domains and
//! colours by their exact values, other geometry by exact equality. Null items are not
//! members: the algebra skips them. Outputs keep the type of their input lists
//! ([`Branch::gather`]). Orders follow Grasshopper's: Union lists A's members and then B's
//! new ones; Intersection lists B's members that are in A, in B's order; Difference keeps A's
//! items (duplicates included) that are not in B.

use std::collections::HashMap;

use locus_runtime::{Branch, DataType, NodeError, NodeRegistry, NodeType, Port, Solve, Value};

/// Id of [`create_set`].
pub const CREATE_SET: &str = "sets.create_set";
/// Id of [`set_union`].
pub const SET_UNION: &str = "sets.set_union";
/// Id of [`set_intersection`].
pub const SET_INTERSECTION: &str = "sets.set_intersection";
/// Id of [`set_difference`].
pub const SET_DIFFERENCE: &str = "sets.set_difference";
/// Id of [`symmetric_difference`].
pub const SYMMETRIC_DIFFERENCE: &str = "sets.symmetric_difference";
/// Id of [`set_majority`].
pub const SET_MAJORITY: &str = "sets.set_majority";
/// Id of [`disjoint`].
pub const DISJOINT: &str = "sets.disjoint";
/// Id of [`subset`].
pub const SUBSET: &str = "sets.subset";

/// The most distinct members of a type without a hash key (curves, surfaces, planes, …) one
/// set may hold: they are compared one by one, so this bounds the work at about 10⁸
/// comparisons.
pub const MAX_PLAIN_MEMBERS: usize = 10_000;

/// Registers the set algebra nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        create_set(),
        set_union(),
        set_intersection(),
        set_difference(),
        symmetric_difference(),
        set_majority(),
        disjoint(),
        subset(),
    ] {
        registry.register(t);
    }
}

/// The identity of a set member: equal keys are one member.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub(crate) enum MemberKey {
    /// An integer, or a number with an integer value in the `i64` range.
    Integer(i64),
    /// Any other number, by its bits (`-0.0` is `0`, every NaN one member).
    Number(u64),
    Boolean(bool),
    Text(String),
    /// A point, vector, domain or colour: its type and the bits of its coordinates.
    Coordinates(DataType, [u64; 4]),
    /// An item of another type: the index of the first equal item met.
    Plain(usize),
}

/// The bits of a number for a key: `-0.0` as `0.0`, every NaN as one NaN.
fn bits(x: f64) -> u64 {
    if x.is_nan() {
        f64::NAN.to_bits()
    } else if x == 0.0 {
        0
    } else {
        x.to_bits()
    }
}

/// Gives members their keys; items without a hash key are compared with the earlier ones.
#[derive(Default)]
pub(crate) struct Keys {
    plain: Vec<Value>,
}

impl Keys {
    /// The key of an item.
    pub(crate) fn key(&mut self, value: &Value) -> Result<MemberKey, NodeError> {
        Ok(match value {
            Value::Integer(i) => MemberKey::Integer(*i),
            Value::Number(x) => number_key(*x),
            Value::Boolean(b) => MemberKey::Boolean(*b),
            Value::Text(t) => MemberKey::Text(t.clone()),
            Value::Point(p) => {
                MemberKey::Coordinates(DataType::Point, [bits(p.x), bits(p.y), bits(p.z), 0])
            }
            Value::Vector(v) => {
                MemberKey::Coordinates(DataType::Vector, [bits(v.x), bits(v.y), bits(v.z), 0])
            }
            Value::Domain(d) => {
                MemberKey::Coordinates(DataType::Domain, [bits(d.t0), bits(d.t1), 0, 0])
            }
            other => match self.plain.iter().position(|p| p == other) {
                Some(k) => MemberKey::Plain(k),
                None => {
                    if self.plain.len() >= MAX_PLAIN_MEMBERS {
                        return Err(NodeError(format!(
                            "a set of {} items holds more than {MAX_PLAIN_MEMBERS} distinct \
                             members, the most locus compares one by one",
                            other.data_type()
                        )));
                    }
                    self.plain.push(other.clone());
                    MemberKey::Plain(self.plain.len() - 1)
                }
            },
        })
    }

    /// The keys of a branch's items, `None` for nulls.
    pub(crate) fn of_branch(
        &mut self,
        branch: &Branch,
    ) -> Result<Vec<Option<MemberKey>>, NodeError> {
        branch
            .values()
            .map(|v| v.map(|v| self.key(&v)).transpose())
            .collect()
    }
}

/// The key of a number: integral numbers are integers, so that 2 and 2.0 are one member.
fn number_key(x: f64) -> MemberKey {
    const I64_END: f64 = 9_223_372_036_854_775_808.0;
    if x.fract() == 0.0 && (-I64_END..I64_END).contains(&x) {
        MemberKey::Integer(x as i64)
    } else {
        MemberKey::Number(bits(x))
    }
}

fn sets_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("Sets")
}

fn set_port(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Generic).list().doc(doc)
}

/// A list input's branch (empty when the input has none).
pub(crate) fn list_of(s: &Solve<'_>, input: usize) -> Branch {
    s.branch(input)
        .cloned()
        .unwrap_or_else(|| Branch::new(DataType::Generic))
}

/// The indices of the first occurrence of each member of `keys`, in order, skipping members
/// already in `seen` (and adding the new ones to it).
fn first_occurrences(
    keys: &[Option<MemberKey>],
    seen: &mut HashMap<MemberKey, usize>,
) -> Vec<usize> {
    let mut out = Vec::new();
    for (i, k) in keys.iter().enumerate() {
        if let Some(k) = k
            && !seen.contains_key(k)
        {
            seen.insert(k.clone(), seen.len());
            out.push(i);
        }
    }
    out
}

/// The set of keys of a list.
fn key_set(keys: &[Option<MemberKey>]) -> std::collections::HashSet<&MemberKey> {
    keys.iter().flatten().collect()
}

/// Two branches of one output joined: typed when both have one type.
fn joined(mut a: Branch, b: &Branch) -> Branch {
    a.extend(b);
    a.narrowed()
}

/// Create Set \[CSet\]: the distinct members of a list, and where each item went.
pub fn create_set() -> NodeType {
    sets_node(CREATE_SET, "Create Set", "CSet")
        .gh_guid("98c3c63a-e78a-43ea-a111-514fcf312c95")
        .gh_guid("2cb4bf85-a282-464c-b42c-8e735d2a0a74")
        .description(
            "Creates the valid set of a list: its distinct members, in the order they first \
             appear, and a map giving for each item of the list the index of its member in the \
             set. Null items are not members: they are left out of the set and their map entry \
             is null.",
        )
        .input(set_port("List", "L", "The list of items, of any type."))
        .output(set_port(
            "Set",
            "S",
            "The distinct members of L, in order of appearance.",
        ))
        .output(
            Port::new("Map", "M", DataType::Integer)
                .list()
                .doc("For each item of L, the index of its member in S (null for a null item)."),
        )
        .solve(|s| {
            let list = list_of(s, 0);
            let mut keys = Keys::default();
            let ks = keys.of_branch(&list)?;
            let mut seen = HashMap::new();
            let firsts = first_occurrences(&ks, &mut seen);
            let map: Vec<Option<Value>> = ks
                .iter()
                .map(|k| {
                    k.as_ref()
                        .map(|k| Value::Integer(i64::try_from(seen[k]).unwrap_or(i64::MAX)))
                })
                .collect();
            s.set_branch(0, list.gather(firsts.into_iter().map(Some)));
            let mut m = Branch::new(DataType::Integer);
            for v in map {
                m.push_option(v);
            }
            s.set_branch(1, m);
            Ok(())
        })
}

/// Set Union \[SUnion\]: the members of either set.
pub fn set_union() -> NodeType {
    sets_node(SET_UNION, "Set Union", "SUnion")
        .gh_guid("8eed5d78-7810-4ba1-968e-8a1f1db98e39")
        .gh_guid("ab34845d-4ab9-4ff4-8870-eedd0c5594cb")
        .description(
            "Creates the union of two sets: every distinct member of A, in order of \
             appearance, then every member of B that is not in A. Null items are skipped.",
        )
        .input(set_port("Set A", "A", "The first set; optional.").optional())
        .input(set_port("Set B", "B", "The second set; optional.").optional())
        .output(set_port("Union", "U", "The members of A or B."))
        .solve(|s| {
            let (a, b) = (list_of(s, 0), list_of(s, 1));
            let mut keys = Keys::default();
            let (ka, kb) = (keys.of_branch(&a)?, keys.of_branch(&b)?);
            let mut seen = HashMap::new();
            let from_a = a.gather(first_occurrences(&ka, &mut seen).into_iter().map(Some));
            let from_b = b.gather(first_occurrences(&kb, &mut seen).into_iter().map(Some));
            s.set_branch(0, joined(from_a, &from_b));
            Ok(())
        })
}

/// Set Intersection \[Intersection\]: the members of both sets.
pub fn set_intersection() -> NodeType {
    sets_node(SET_INTERSECTION, "Set Intersection", "Intersection")
        .gh_guid("82f19c48-9e73-43a4-ae6c-3a8368099b08")
        .gh_guid("8a55f680-cf53-4634-a486-b828de92b71d")
        .description(
            "Creates the intersection of two sets: the distinct members of B that are also in \
             A, in B's order ([1, 2, 2, 3, 5] and [5, 3, 3, 7] give [5, 3]). Null items are \
             skipped; an empty set gives an empty intersection.",
        )
        .input(set_port("Set A", "A", "The first set; optional.").optional())
        .input(set_port("Set B", "B", "The second set; optional.").optional())
        .output(set_port("Union", "U", "The members of both A and B."))
        .solve(|s| {
            let (a, b) = (list_of(s, 0), list_of(s, 1));
            let mut keys = Keys::default();
            let (ka, kb) = (keys.of_branch(&a)?, keys.of_branch(&b)?);
            let in_a = key_set(&ka);
            let mut seen = HashMap::new();
            let picks: Vec<usize> = first_occurrences(&kb, &mut seen)
                .into_iter()
                .filter(|&i| kb[i].as_ref().is_some_and(|k| in_a.contains(k)))
                .collect();
            s.set_branch(0, b.gather(picks.into_iter().map(Some)));
            Ok(())
        })
}

/// The indices of the items of `keys` whose member is not in `other`.
fn not_in(keys: &[Option<MemberKey>], other: &[Option<MemberKey>]) -> Vec<usize> {
    let other = key_set(other);
    keys.iter()
        .enumerate()
        .filter_map(|(i, k)| k.as_ref().filter(|k| !other.contains(k)).map(|_| i))
        .collect()
}

/// Set Difference \[Difference\]: the items of A that are not in B.
pub fn set_difference() -> NodeType {
    sets_node(SET_DIFFERENCE, "Set Difference", "Difference")
        .gh_guid("e3b1a10c-4d49-4140-b8e6-0b5732a26c31")
        .description(
            "Creates the difference of two sets: the items of A whose member is not in B, in \
             A's order, duplicates kept ([1, 2, 2, 3, 5] minus [5, 3, 7] is [1, 2, 2]). Null \
             items are skipped.",
        )
        .input(set_port("Set A", "A", "The set to subtract from."))
        .input(set_port("Set B", "B", "The set to subtract; optional.").optional())
        .output(set_port("Union", "U", "The items of A that are not in B."))
        .solve(|s| {
            let (a, b) = (list_of(s, 0), list_of(s, 1));
            let mut keys = Keys::default();
            let (ka, kb) = (keys.of_branch(&a)?, keys.of_branch(&b)?);
            s.set_branch(0, a.gather(not_in(&ka, &kb).into_iter().map(Some)));
            Ok(())
        })
}

/// Set Difference (S) \[ExDiff\]: the items in A or in B but not in both.
pub fn symmetric_difference() -> NodeType {
    sets_node(SYMMETRIC_DIFFERENCE, "Set Difference (S)", "ExDiff")
        .gh_guid("d2461702-3164-4894-8c10-ed1fc4b52965")
        .description(
            "Creates the symmetric difference of two sets: the items of A whose member is not \
             in B, then the items of B whose member is not in A, each in its list's order with \
             duplicates kept. Null items are skipped.",
        )
        .input(set_port("Set A", "A", "The first set; optional.").optional())
        .input(set_port("Set B", "B", "The second set; optional.").optional())
        .output(set_port(
            "ExDifference",
            "X",
            "The items of A or B whose member is not in both.",
        ))
        .solve(|s| {
            let (a, b) = (list_of(s, 0), list_of(s, 1));
            let mut keys = Keys::default();
            let (ka, kb) = (keys.of_branch(&a)?, keys.of_branch(&b)?);
            let only_a = a.gather(not_in(&ka, &kb).into_iter().map(Some));
            let only_b = b.gather(not_in(&kb, &ka).into_iter().map(Some));
            s.set_branch(0, joined(only_a, &only_b));
            Ok(())
        })
}

/// Set Majority \[Majority\]: the members in at least two of three sets.
pub fn set_majority() -> NodeType {
    sets_node(SET_MAJORITY, "Set Majority", "Majority")
        .gh_guid("d4136a7b-7422-4660-9404-640474bd2725")
        .description(
            "Determines majority presence amongst three sets: the distinct members that are in \
             at least two of A, B and C, listed as the members of A that are in B, then the new \
             members of B that are in C, then the new members of A that are in C. Null items \
             are skipped.",
        )
        .input(set_port("Set A", "A", "The first set; optional.").optional())
        .input(set_port("Set B", "B", "The second set; optional.").optional())
        .input(set_port("Set C", "C", "The third set; optional.").optional())
        .output(set_port(
            "Result",
            "R",
            "The members that occur in at least two of the sets.",
        ))
        .solve(|s| {
            let (a, b, c) = (list_of(s, 0), list_of(s, 1), list_of(s, 2));
            let mut keys = Keys::default();
            let (ka, kb, kc) = (
                keys.of_branch(&a)?,
                keys.of_branch(&b)?,
                keys.of_branch(&c)?,
            );
            let (in_b, in_c) = (key_set(&kb), key_set(&kc));
            let mut seen = std::collections::HashSet::new();
            let mut pick =
                |ks: &[Option<MemberKey>], other: &std::collections::HashSet<&MemberKey>| {
                    let mut out = Vec::new();
                    for (i, k) in ks.iter().enumerate() {
                        if let Some(k) = k
                            && other.contains(k)
                            && seen.insert(k.clone())
                        {
                            out.push(i);
                        }
                    }
                    out
                };
            let ab = a.gather(pick(&ka, &in_b).into_iter().map(Some));
            let bc = b.gather(pick(&kb, &in_c).into_iter().map(Some));
            let ac = a.gather(pick(&ka, &in_c).into_iter().map(Some));
            s.set_branch(0, joined(joined(ab, &bc), &ac));
            Ok(())
        })
}

/// Disjoint \[Disjoint\]: whether two sets share no member.
pub fn disjoint() -> NodeType {
    sets_node(DISJOINT, "Disjoint", "Disjoint")
        .gh_guid("81800098-1060-4e2b-80d4-17f835cc825f")
        .description(
            "Tests whether two sets are disjoint: true when no member of A is in B (an empty \
             set is disjoint from any set). Null items are skipped.",
        )
        .input(set_port("Set A", "A", "The first set; optional.").optional())
        .input(set_port("Set B", "B", "The second set; optional.").optional())
        .output(
            Port::new("Result", "R", DataType::Boolean)
                .doc("True if none of the items of A occur in B."),
        )
        .solve(|s| {
            let (a, b) = (list_of(s, 0), list_of(s, 1));
            let mut keys = Keys::default();
            let (ka, kb) = (keys.of_branch(&a)?, keys.of_branch(&b)?);
            let in_b = key_set(&kb);
            s.set(0, !ka.iter().flatten().any(|k| in_b.contains(k)));
            Ok(())
        })
}

/// SubSet \[SubSet\]: whether every member of B is in A.
pub fn subset() -> NodeType {
    sets_node(SUBSET, "SubSet", "SubSet")
        .gh_guid("4cfc0bb0-0745-4772-a520-39f9bf3d99bc")
        .description(
            "Tests two sets for inclusion: true when every member of B is in A (B is a subset \
             of A; equal sets qualify and an empty B always does). Null items are skipped.",
        )
        .input(set_port("Set A", "A", "The super set; optional.").optional())
        .input(set_port("Set B", "B", "The sub set; optional.").optional())
        .output(
            Port::new("Result", "R", DataType::Boolean)
                .doc("True if all items of B are present in A."),
        )
        .solve(|s| {
            let (a, b) = (list_of(s, 0), list_of(s, 1));
            let mut keys = Keys::default();
            let (ka, kb) = (keys.of_branch(&a)?, keys.of_branch(&b)?);
            let in_a = key_set(&ka);
            s.set(0, kb.iter().flatten().all(|k| in_a.contains(k)));
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::{Line, Point3};
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::sets::test_support::{assert_clean, generic, messages, tree};
    use crate::test_support::{all, booleans, items, values};

    fn run2(node: &NodeType, a: DataTree, b: DataTree) -> locus_runtime::NodeCallResult {
        NodeCall::new(node).input(a).input(b).run()
    }

    #[test]
    fn create_set_lists_distinct_members_and_maps_items() {
        let r = NodeCall::new(&create_set())
            .input(generic(r#"{0}:[1, "a", 2.0, 1, null, "a", 2, true]"#))
            .run();
        assert_clean(&r);
        assert_eq!(
            values(&r.outputs[0]),
            [
                Some(Value::Number(1.0)),
                Some(Value::Text("a".into())),
                Some(Value::Number(2.0)),
                Some(Value::Boolean(true)),
            ]
        );
        assert_eq!(
            items::<i64>(&r.outputs[1]),
            [
                Some(0),
                Some(1),
                Some(2),
                Some(0),
                None,
                Some(1),
                Some(2),
                Some(3)
            ]
        );
        // A typed list stays typed.
        let r = NodeCall::new(&create_set())
            .input(tree("{0}:[3, 1, 3, 1, -0.0, 0.0]"))
            .run();
        assert_eq!(all::<f64>(&r.outputs[0]), [3.0, 1.0, -0.0]);
        assert_eq!(all::<i64>(&r.outputs[1]), [0, 1, 0, 1, 2, 2]);
    }

    #[test]
    fn nan_is_one_member_and_geometry_compares_by_value() {
        let r = NodeCall::new(&create_set())
            .input(DataTree::from_list(vec![f64::NAN, 1.0, f64::NAN]))
            .run();
        assert_eq!(all::<i64>(&r.outputs[1]), [0, 1, 0]);
        let l = |x: f64| Line::new(Point3::ORIGIN, Point3::new(x, 0.0, 0.0));
        let r = NodeCall::new(&create_set())
            .input(DataTree::from_list(vec![l(1.0), l(2.0), l(1.0)]))
            .run();
        assert_eq!(all::<i64>(&r.outputs[1]), [0, 1, 0]);
        assert_eq!(all::<Line>(&r.outputs[0]).len(), 2);
    }

    #[test]
    fn union_intersection_and_differences_follow_grasshoppers_orders() {
        let a = || tree("{0}:[1, 2, 2, 3, 5]");
        let b = || tree("{0}:[5, 3, 3, 7]");
        let r = run2(&set_union(), a(), b());
        assert_eq!(all::<f64>(&r.outputs[0]), [1.0, 2.0, 3.0, 5.0, 7.0]);
        let r = run2(&set_intersection(), a(), b());
        assert_eq!(all::<f64>(&r.outputs[0]), [5.0, 3.0]);
        let r = run2(&set_difference(), a(), tree("{0}:[5, 3, 7]"));
        assert_eq!(all::<f64>(&r.outputs[0]), [1.0, 2.0, 2.0]);
        let r = run2(&symmetric_difference(), a(), b());
        assert_eq!(all::<f64>(&r.outputs[0]), [1.0, 2.0, 2.0, 7.0]);
    }

    #[test]
    fn symmetric_difference_keeps_duplicates_of_both_sides() {
        let r = run2(
            &symmetric_difference(),
            tree("{0}:[1, 1, 2]"),
            tree("{0}:[2, 3, 3]"),
        );
        assert_eq!(all::<f64>(&r.outputs[0]), [1.0, 1.0, 3.0, 3.0]);
    }

    #[test]
    fn mixed_types_are_distinct_members_but_numbers_meet_integers() {
        let mut b = Branch::new(DataType::Generic);
        for v in [
            Value::Integer(1),
            Value::Number(2.0),
            Value::Text("true".into()),
        ] {
            b.push_value(v);
        }
        let r = run2(
            &set_union(),
            generic(r#"{0}:["1", true, 2]"#),
            DataTree::from_branches([(locus_runtime::TreePath::new(vec![0]), b)]),
        );
        assert_eq!(
            values(&r.outputs[0]),
            [
                Some(Value::Text("1".into())),
                Some(Value::Boolean(true)),
                Some(Value::Number(2.0)),
                Some(Value::Integer(1)),
                Some(Value::Text("true".into())),
            ]
        );
    }

    #[test]
    fn majority_disjoint_and_subset() {
        let r = NodeCall::new(&set_majority())
            .input(tree("{0}:[1, 2, 3]"))
            .input(tree("{0}:[3, 4, 5]"))
            .input(tree("{0}:[5, 1, 6]"))
            .run();
        // A∩B = [3]; B∩C adds 5; A∩C adds 1.
        assert_eq!(all::<f64>(&r.outputs[0]), [3.0, 5.0, 1.0]);
        let r = run2(&disjoint(), tree("{0}:[1, 2]"), tree("{0}:[3, 4]"));
        assert_eq!(booleans(&r.outputs[0]), [true]);
        let r = run2(&disjoint(), tree("{0}:[1, 2]"), tree("{0}:[2]"));
        assert_eq!(booleans(&r.outputs[0]), [false]);
        let r = run2(&subset(), tree("{0}:[1, 2, 3]"), tree("{0}:[3, 1, 1]"));
        assert_eq!(booleans(&r.outputs[0]), [true]);
        let r = run2(&subset(), tree("{0}:[1, 2, 3]"), tree("{0}:[4]"));
        assert_eq!(booleans(&r.outputs[0]), [false]);
    }

    #[test]
    fn empty_and_null_sets() {
        // An empty B: nothing to subtract, every set includes it, nothing is shared.
        let empty = || tree("{0}:[]");
        let r = run2(&set_difference(), tree("{0}:[1, null, 2]"), empty());
        assert_eq!(all::<f64>(&r.outputs[0]), [1.0, 2.0]);
        let r = run2(&subset(), tree("{0}:[1]"), empty());
        assert_eq!(booleans(&r.outputs[0]), [true]);
        let r = run2(&disjoint(), empty(), tree("{0}:[1]"));
        assert_eq!(booleans(&r.outputs[0]), [true]);
        let r = run2(&set_intersection(), empty(), tree("{0}:[1]"));
        assert!(r.outputs[0].has_no_items());
        let r = run2(&set_union(), tree("{0}:[null]"), empty());
        assert!(r.outputs[0].has_no_items());
        assert!(messages(&r, Level::Error).is_empty());
    }
}
