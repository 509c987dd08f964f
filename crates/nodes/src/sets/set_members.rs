//! Sets › Sets, finding and replacing members: Member Index, Replace Members, Find similar
//! member, Delete Consecutive and Key/Value Search.
//!
//! Members are compared as in [`super::set_ops`] ([`MemberKey`]: by type and value, numbers
//! and integers by numeric value). Find similar member measures closeness: numbers by their
//! difference, points by their distance, anything else by the edit (Levenshtein) distance of
//! the items' text forms.

use std::collections::HashMap;

use locus_runtime::{
    Branch, DataType, NodeError, NodeRegistry, NodeType, Port, Value, format_value,
};

use super::set_ops::{Keys, MemberKey, list_of};

/// Id of [`member_index`].
pub const MEMBER_INDEX: &str = "sets.member_index";
/// Id of [`replace_members`].
pub const REPLACE_MEMBERS: &str = "sets.replace_members";
/// Id of [`find_similar_member`].
pub const FIND_SIMILAR_MEMBER: &str = "sets.find_similar_member";
/// Id of [`delete_consecutive`].
pub const DELETE_CONSECUTIVE: &str = "sets.delete_consecutive";
/// Id of [`key_value_search`].
pub const KEY_VALUE_SEARCH: &str = "sets.key_value_search";

/// The most edit-distance cells (characters of one text times characters of the other,
/// summed over the members compared) Find similar member computes for one item of D.
pub const MAX_EDIT_CELLS: usize = 100_000_000;

/// Registers the member nodes.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        member_index(),
        replace_members(),
        find_similar_member(),
        delete_consecutive(),
        key_value_search(),
    ] {
        registry.register(t);
    }
}

fn sets_node(id: &str, name: &str, nickname: &str) -> NodeType {
    NodeType::new(id, name, nickname, "Sets").subcategory("Sets")
}

fn set_port(name: &str, nickname: &str, doc: &str) -> Port {
    Port::new(name, nickname, DataType::Generic).list().doc(doc)
}

fn count(n: usize) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}

/// Member Index \[MIndex\]: where a member occurs in a set.
pub fn member_index() -> NodeType {
    sets_node(MEMBER_INDEX, "Member Index", "MIndex")
        .gh_guid("3ff27857-b988-417a-b495-b24c733dbd00")
        .description(
            "Finds the occurrences of a member in a set: the index of every item equal to M (by \
             type and value; numbers and integers by numeric value) and how many there are. A \
             member that does not occur gives no indices and a count of 0.",
        )
        .input(set_port("Set", "S", "The set to search, of any type."))
        .input(Port::new("Member", "M", DataType::Generic).doc("The member to search for."))
        .output(
            Port::new("Index", "I", DataType::Integer)
                .list()
                .doc("The indices of the items equal to M."),
        )
        .output(Port::new("Count", "N", DataType::Integer).doc("The number of occurrences of M."))
        .solve(|s| {
            let set = list_of(s, 0);
            let member = s
                .value(1)
                .ok_or_else(|| NodeError("input M has no member".to_owned()))?;
            let mut keys = Keys::default();
            let wanted = keys.key(&member)?;
            let ks = keys.of_branch(&set)?;
            let found: Vec<i64> = ks
                .iter()
                .enumerate()
                .filter(|(_, k)| k.as_ref() == Some(&wanted))
                .map(|(i, _)| count(i))
                .collect();
            let n = count(found.len());
            s.set_list(0, found);
            s.set(1, n);
            Ok(())
        })
}

/// Replace Members \[Replace\]: every occurrence of some members replaced by others.
pub fn replace_members() -> NodeType {
    sets_node(REPLACE_MEMBERS, "Replace Members", "Replace")
        .gh_guid("bafac914-ede4-4a59-a7b2-cc41bc3de961")
        .description(
            "Replaces members in a set: every item equal to the k-th item of F becomes the k-th \
             item of R (the first match in F wins). Without replacements the found items are \
             removed. R must have as many items as F, or none; other counts are an error. \
             Null items are kept.",
        )
        .input(set_port("Set", "S", "The set to operate on, of any type."))
        .input(set_port("Find", "F", "The members to replace."))
        .input(
            set_port(
                "Replace",
                "R",
                "The members to replace them with; optional.",
            )
            .optional(),
        )
        .output(set_port(
            "Result",
            "R",
            "The set with the members replaced.",
        ))
        .solve(|s| {
            let (set, find, replace) = (list_of(s, 0), list_of(s, 1), list_of(s, 2));
            if !replace.is_empty() && replace.len() != find.len() {
                return Err(NodeError(format!(
                    "F has {} items but R has {}: give one replacement for each, or none",
                    find.len(),
                    replace.len()
                )));
            }
            let mut keys = Keys::default();
            let mut table: HashMap<MemberKey, usize> = HashMap::new();
            for (k, key) in keys.of_branch(&find)?.into_iter().enumerate() {
                if let Some(key) = key {
                    table.entry(key).or_insert(k);
                }
            }
            let mut out = Branch::new(DataType::Generic);
            for (i, key) in keys.of_branch(&set)?.into_iter().enumerate() {
                match key.and_then(|k| table.get(&k).copied()) {
                    None => out.extend_range(&set, i..i + 1),
                    Some(k) if !replace.is_empty() => out.extend_range(&replace, k..k + 1),
                    Some(_) => {}
                }
            }
            s.set_branch(0, out.narrowed());
            Ok(())
        })
}

/// The Levenshtein distance of two texts, in characters, its table taken from `budget`
/// cells; `Err` when the budget does not hold the table.
pub(crate) fn edit_distance(a: &str, b: &str, budget: &mut usize) -> Result<usize, NodeError> {
    let a: Vec<char> = a.chars().collect();
    let b: Vec<char> = b.chars().collect();
    let cells = a.len().saturating_mul(b.len());
    if cells > *budget {
        return Err(NodeError(format!(
            "texts of {} and {} characters are too long to compare: the comparisons would take \
             more than {MAX_EDIT_CELLS} cells",
            a.len(),
            b.len()
        )));
    }
    *budget -= cells;
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let above = row[j + 1];
            row[j + 1] = if ca == cb {
                diagonal
            } else {
                1 + diagonal.min(above).min(row[j])
            };
            diagonal = above;
        }
    }
    Ok(row[b.len()])
}

/// How far apart two items are for Find similar member (smaller is more similar).
fn dissimilarity(a: &Value, b: &Value, budget: &mut usize) -> Result<f64, NodeError> {
    let number = |v: &Value| match v {
        Value::Number(x) => Some(*x),
        Value::Integer(i) => Some(*i as f64),
        _ => None,
    };
    if let (Some(x), Some(y)) = (number(a), number(b)) {
        let d = (x - y).abs();
        return Ok(if d.is_nan() { f64::INFINITY } else { d });
    }
    if let (Value::Point(p), Value::Point(q)) = (a, b) {
        let d = p.distance(*q);
        return Ok(if d.is_nan() { f64::INFINITY } else { d });
    }
    Ok(edit_distance(&format_value(a), &format_value(b), budget)? as f64)
}

/// Find similar member \[FSim\]: the member of a set closest to some data.
pub fn find_similar_member() -> NodeType {
    sets_node(FIND_SIMILAR_MEMBER, "Find similar member", "FSim")
        .gh_guid("b4d4235f-14ff-4d4e-a29a-b358dcd2baf4")
        .description(
            "Finds the member of a set most similar to D: for numbers the one with the smallest \
             difference, for points the nearest, for anything else (or mixed types) the one \
             whose text form is the fewest edits (Levenshtein distance) away. Ties go to the \
             first; null members are skipped; a set without members gives nulls and a warning.",
        )
        .input(Port::new("Data", "D", DataType::Generic).doc("The data to search for."))
        .input(set_port("Set", "S", "The set to search, of any type."))
        .output(Port::new("Hit", "H", DataType::Generic).doc("The member of S closest to D."))
        .output(Port::new("Index", "i", DataType::Integer).doc("The index of H in S."))
        .solve(|s| {
            let data = s
                .value(0)
                .ok_or_else(|| NodeError("input D has no data".to_owned()))?;
            let set = list_of(s, 1);
            let mut best: Option<(f64, usize)> = None;
            let mut budget = MAX_EDIT_CELLS;
            for (i, v) in set.values().enumerate() {
                let Some(v) = v else { continue };
                let d = dissimilarity(&data, &v, &mut budget)?;
                if best.is_none_or(|(b, _)| d < b) {
                    best = Some((d, i));
                }
            }
            match best {
                Some((_, i)) => {
                    s.set_value(0, set.value(i));
                    s.set(1, count(i));
                }
                None => {
                    s.warning("the set has no members to compare with");
                    s.set_value(0, None);
                    s.set_value(1, None);
                }
            }
            Ok(())
        })
}

/// Delete Consecutive \[DCon\]: runs of equal members reduced to one.
pub fn delete_consecutive() -> NodeType {
    sets_node(DELETE_CONSECUTIVE, "Delete Consecutive", "DCon")
        .gh_guid("190d042c-2270-4bc1-81c0-4f90c170c9c9")
        .description(
            "Deletes consecutive similar members: of every run of equal neighbouring items only \
             the first is kept. With Wrap the last and first items are neighbours too, so a \
             last run equal to the first is removed. Nulls are items here: a run of nulls is \
             one null. Count is the number of items removed.",
        )
        .input(set_port("Set", "S", "The set to operate on, of any type."))
        .input(
            Port::new("Wrap", "W", DataType::Boolean)
                .doc("Whether the last and first members are adjacent; default false.")
                .default_value(false),
        )
        .output(set_port(
            "Set",
            "S",
            "The set without consecutive equal members.",
        ))
        .output(Port::new("Count", "N", DataType::Integer).doc("The number of items removed."))
        .solve(|s| {
            let set = list_of(s, 0);
            let wrap = s.item_opt::<bool>(1).copied().unwrap_or(false);
            let mut keys = Keys::default();
            let ks = keys.of_branch(&set)?;
            let mut kept: Vec<usize> = Vec::new();
            for (i, k) in ks.iter().enumerate() {
                if kept.last().is_none_or(|&j| ks[j] != *k) {
                    kept.push(i);
                }
            }
            if wrap && kept.len() > 1 && ks[kept[0]] == ks[kept[kept.len() - 1]] {
                kept.pop();
            }
            let removed = count(set.len() - kept.len());
            s.set_branch(0, set.gather(kept.into_iter().map(Some)));
            s.set(1, removed);
            Ok(())
        })
}

/// Key/Value Search \[KeySearch\]: the value paired with a key.
pub fn key_value_search() -> NodeType {
    sets_node(KEY_VALUE_SEARCH, "Key/Value Search", "KeySearch")
        .gh_guid("1edcc3cf-cf84-41d4-8204-561162cfe510")
        .description(
            "Extracts an item from a collection by a key: the value paired with the first key \
             equal to S (by type and value; numbers and integers by numeric value). K and V \
             must have as many items; a key that is not there gives a null and a warning.",
        )
        .input(set_port("Keys", "K", "The keys, of any type."))
        .input(set_port("Values", "V", "The values, one for each key."))
        .input(Port::new("Search", "S", DataType::Generic).doc("The key to search for."))
        .output(Port::new("Result", "R", DataType::Generic).doc("The value whose key matches S."))
        .solve(|s| {
            let (keys_list, values) = (list_of(s, 0), list_of(s, 1));
            if keys_list.len() != values.len() {
                return Err(NodeError(format!(
                    "K has {} keys but V has {} values: give one value for each key",
                    keys_list.len(),
                    values.len()
                )));
            }
            let search = s
                .value(2)
                .ok_or_else(|| NodeError("input S has no key".to_owned()))?;
            let mut keys = Keys::default();
            let wanted = keys.key(&search)?;
            let ks = keys.of_branch(&keys_list)?;
            match ks.iter().position(|k| k.as_ref() == Some(&wanted)) {
                Some(i) => s.set_value(0, values.value(i)),
                None => {
                    s.warning(format!("no key equals {}", format_value(&search)));
                    s.set_value(0, None);
                }
            }
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use locus_kernel::Point3;
    use locus_runtime::{DataTree, Level, NodeCall};

    use super::*;
    use crate::sets::test_support::{assert_clean, generic, messages, tree};
    use crate::test_support::{all, items, values};

    #[test]
    fn member_index_finds_every_occurrence() {
        let r = NodeCall::new(&member_index())
            .input(tree("{0}:[4, 2, 4, null, 4]"))
            .input(DataTree::from_item(4_i64))
            .run();
        assert_clean(&r);
        assert_eq!(all::<i64>(&r.outputs[0]), [0, 2, 4]);
        assert_eq!(all::<i64>(&r.outputs[1]), [3]);
        let r = NodeCall::new(&member_index())
            .input(generic(r#"{0}:["a", "b"]"#))
            .input(DataTree::from_item("c".to_owned()))
            .run();
        assert!(r.outputs[0].has_no_items());
        assert_eq!(all::<i64>(&r.outputs[1]), [0]);
    }

    #[test]
    fn replace_members_replaces_removes_and_checks_counts() {
        let r = NodeCall::new(&replace_members())
            .input(generic(r#"{0}:["a", "b", "a", null, "c"]"#))
            .input(generic(r#"{0}:["a", "c"]"#))
            .input(generic(r#"{0}:["x", "y"]"#))
            .run();
        assert_clean(&r);
        assert_eq!(
            values(&r.outputs[0]),
            [
                Some(Value::Text("x".into())),
                Some(Value::Text("b".into())),
                Some(Value::Text("x".into())),
                None,
                Some(Value::Text("y".into())),
            ]
        );
        let r = NodeCall::new(&replace_members())
            .input(tree("{0}:[1, 2, 1, 3]"))
            .input(tree("{0}:[1]"))
            .run();
        assert_eq!(all::<f64>(&r.outputs[0]), [2.0, 3.0]);
        let r = NodeCall::new(&replace_members())
            .input(tree("{0}:[1, 2]"))
            .input(tree("{0}:[1, 2]"))
            .input(tree("{0}:[9]"))
            .run();
        let e = messages(&r, Level::Error);
        assert!(
            e.len() == 1 && e[0].contains("F has 2 items but R has 1"),
            "{e:?}"
        );
    }

    #[test]
    fn edit_distance_is_levenshteins() {
        let mut budget = MAX_EDIT_CELLS;
        assert_eq!(edit_distance("kitten", "sitting", &mut budget).unwrap(), 3);
        assert_eq!(edit_distance("", "abc", &mut budget).unwrap(), 3);
        assert_eq!(edit_distance("flaw", "lawn", &mut budget).unwrap(), 2);
        assert_eq!(edit_distance("ÄÖ", "AÖ", &mut budget).unwrap(), 1);
        assert_eq!(budget, MAX_EDIT_CELLS - 42 - 16 - 4);
        let mut small = 10;
        assert!(edit_distance("abcd", "abcd", &mut small).is_err());
    }

    #[test]
    fn find_similar_member_by_difference_distance_and_edits() {
        let r = NodeCall::new(&find_similar_member())
            .input(DataTree::from_item(4.4))
            .input(tree("{0}:[1, 5, 4, 7]"))
            .run();
        assert_clean(&r);
        assert_eq!(all::<f64>(&r.outputs[0]), [4.0]);
        assert_eq!(all::<i64>(&r.outputs[1]), [2]);
        // Ties go to the first.
        let r = NodeCall::new(&find_similar_member())
            .input(DataTree::from_item(3.0))
            .input(tree("{0}:[2, 4]"))
            .run();
        assert_eq!(all::<i64>(&r.outputs[1]), [0]);
        let r = NodeCall::new(&find_similar_member())
            .input(DataTree::from_item(Point3::new(1.0, 1.0, 0.0)))
            .input(DataTree::from_list(vec![
                Point3::new(5.0, 0.0, 0.0),
                Point3::new(0.0, 2.0, 0.0),
            ]))
            .run();
        assert_eq!(all::<i64>(&r.outputs[1]), [1]);
        let r = NodeCall::new(&find_similar_member())
            .input(DataTree::from_item("apple".to_owned()))
            .input(generic(r#"{0}:["maple", "apply", "pear"]"#))
            .run();
        assert_eq!(all::<String>(&r.outputs[0]), ["apply"]);
    }

    #[test]
    fn find_similar_member_in_an_empty_set_warns() {
        let r = NodeCall::new(&find_similar_member())
            .input(DataTree::from_item(1.0))
            .input(tree("{0}:[null, null]"))
            .run();
        assert_eq!(
            messages(&r, Level::Warning),
            ["the set has no members to compare with"]
        );
        assert_eq!(items::<i64>(&r.outputs[1]), [None]);
    }

    #[test]
    fn delete_consecutive_with_and_without_wrap() {
        let r = NodeCall::new(&delete_consecutive())
            .input(tree("{0}:[1, 1, 2, 2, 2, 3, 1, 1]"))
            .run();
        assert_clean(&r);
        assert_eq!(all::<f64>(&r.outputs[0]), [1.0, 2.0, 3.0, 1.0]);
        assert_eq!(all::<i64>(&r.outputs[1]), [4]);
        let r = NodeCall::new(&delete_consecutive())
            .input(tree("{0}:[1, 1, 2, 2, 2, 3, 1, 1]"))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(all::<f64>(&r.outputs[0]), [1.0, 2.0, 3.0]);
        assert_eq!(all::<i64>(&r.outputs[1]), [5]);
        // One member stays even when wrapped onto itself.
        let r = NodeCall::new(&delete_consecutive())
            .input(tree("{0}:[7, 7]"))
            .input(DataTree::from_item(true))
            .run();
        assert_eq!(all::<f64>(&r.outputs[0]), [7.0]);
    }

    #[test]
    fn key_value_search_finds_pairs_and_reports_misses() {
        let r = NodeCall::new(&key_value_search())
            .input(generic(r#"{0}:["a", "b", "c"]"#))
            .input(tree("{0}:[10, 20, 30]"))
            .input(DataTree::from_item("b".to_owned()))
            .run();
        assert_clean(&r);
        assert_eq!(all::<f64>(&r.outputs[0]), [20.0]);
        let r = NodeCall::new(&key_value_search())
            .input(generic(r#"{0}:["a"]"#))
            .input(tree("{0}:[10]"))
            .input(DataTree::from_item("z".to_owned()))
            .run();
        assert_eq!(messages(&r, Level::Warning), ["no key equals z"]);
        let r = NodeCall::new(&key_value_search())
            .input(generic(r#"{0}:["a", "b"]"#))
            .input(tree("{0}:[10]"))
            .input(DataTree::from_item("a".to_owned()))
            .run();
        assert_eq!(messages(&r, Level::Error).len(), 1);
    }
}
