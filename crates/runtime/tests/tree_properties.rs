//! Property tests of data tree operations, tree notation, path mapping and casting.

use locus_kernel::{Interval, Point3};
use locus_runtime::{
    Branch, DataTree, DataType, GraftMode, PathMapper, SimplifyMode, TreePath, Value, cast_branch,
    cast_value, format_number, parse_number,
};
use proptest::prelude::*;

/// A branch of numbers and nulls.
fn number_branch() -> impl Strategy<Value = Vec<Option<f64>>> {
    prop::collection::vec(prop::option::weighted(0.85, -1e6_f64..1e6), 0..6)
}

fn build(branches: Vec<(Vec<u32>, Vec<Option<f64>>)>) -> DataTree {
    let mut tree = DataTree::new();
    for (path, items) in branches {
        let mut b = Branch::new(DataType::Number);
        for item in items {
            match item {
                Some(x) => b.push(x),
                None => b.push_null(),
            }
        }
        tree.insert(TreePath::new(path), b);
    }
    tree
}

/// Trees whose paths have 1 to 4 small indices (so that paths share indices often).
fn any_tree() -> impl Strategy<Value = DataTree> {
    prop::collection::vec(
        (prop::collection::vec(0_u32..3, 1..5), number_branch()),
        0..8,
    )
    .prop_map(build)
}

/// Trees whose paths all have `depth` indices.
fn uniform_tree() -> impl Strategy<Value = DataTree> {
    (1_usize..4).prop_flat_map(|depth| {
        prop::collection::vec(
            (prop::collection::vec(0_u32..3, depth), number_branch()),
            0..8,
        )
        .prop_map(build)
    })
}

/// Items in order, as text so that nulls and values compare simply.
fn items(tree: &DataTree) -> Vec<String> {
    tree.values()
        .map(|v| match v {
            Some(Value::Number(x)) => format_number(x),
            Some(other) => format!("{other:?}"),
            None => "null".to_owned(),
        })
        .collect()
}

fn sorted(mut v: Vec<String>) -> Vec<String> {
    v.sort();
    v
}

fn any_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        any::<f64>().prop_map(Value::Number),
        any::<i64>().prop_map(Value::Integer),
        any::<bool>().prop_map(Value::Boolean),
        "[ -~]{0,12}".prop_map(Value::Text),
        (-1e3_f64..1e3, -1e3_f64..1e3, -1e3_f64..1e3)
            .prop_map(|(x, y, z)| Value::Point(Point3::new(x, y, z))),
        (-1e3_f64..1e3, -1e3_f64..1e3).prop_map(|(a, b)| Value::Domain(Interval::new(a, b))),
    ]
}

proptest! {
    #[test]
    fn flatten_keeps_items_and_order(tree in any_tree()) {
        let mut flat = tree.clone();
        flat.flatten();
        prop_assert_eq!(items(&flat), items(&tree));
        prop_assert_eq!(flat.branch_count(), usize::from(!tree.is_empty()));
    }

    #[test]
    fn graft_then_flatten_keeps_items(tree in any_tree()) {
        let mut t = tree.clone();
        t.graft(GraftMode::ALL);
        prop_assert_eq!(t.item_count(), tree.item_count());
        prop_assert!(t.branches().iter().all(|(_, b)| b.len() <= 1));
        t.flatten();
        prop_assert_eq!(sorted(items(&t)), sorted(items(&tree)));
    }

    #[test]
    fn graft_then_flatten_is_identity_on_uniform_trees(tree in uniform_tree()) {
        let mut t = tree.clone();
        t.graft(GraftMode::ALL);
        t.flatten();
        prop_assert_eq!(items(&t), items(&tree));
    }

    #[test]
    fn graft_without_nulls_drops_exactly_the_nulls(tree in any_tree()) {
        let mut t = tree.clone();
        t.graft(GraftMode::ITEMS_ONLY);
        let nulls = tree.values().filter(Option::is_none).count();
        prop_assert_eq!(t.item_count(), tree.item_count() - nulls);
        prop_assert_eq!(t.branch_count(), t.item_count());
    }

    #[test]
    fn simplify_never_merges_or_reorders(tree in any_tree(), leading in any::<bool>()) {
        let mode = if leading { SimplifyMode::Leading } else { SimplifyMode::All };
        let mut t = tree.clone();
        t.simplify(mode);
        // Merged duplicates would show as fewer branches.
        prop_assert_eq!(t.branch_count(), tree.branch_count());
        prop_assert_eq!(items(&t), items(&tree));
        for ((new, _), (old, _)) in t.branches().iter().zip(tree.branches()) {
            prop_assert!(!new.is_empty() && new.len() <= old.len());
        }
        let mut twice = t.clone();
        twice.simplify(mode);
        prop_assert_eq!(twice, t);
    }

    #[test]
    fn simplify_all_removes_every_shared_position_of_uniform_trees(tree in uniform_tree()) {
        let mut t = tree.clone();
        t.simplify(SimplifyMode::All);
        if t.branch_count() > 1 {
            let first = t.branches()[0].0.indices().to_vec();
            for (k, index) in first.iter().enumerate() {
                prop_assert!(t.paths().any(|p| p.indices()[k] != *index));
            }
        }
    }

    #[test]
    fn reverse_twice_is_identity(tree in any_tree()) {
        let mut t = tree.clone();
        t.reverse_items();
        t.reverse_items();
        prop_assert_eq!(t, tree);
    }

    #[test]
    fn trim_and_shift_keep_items(tree in any_tree(), depth in 0_usize..5, offset in -5_i64..5) {
        let mut trimmed = tree.clone();
        trimmed.trim(depth);
        prop_assert_eq!(sorted(items(&trimmed)), sorted(items(&tree)));
        let mut shifted = tree.clone();
        shifted.shift_paths(offset);
        prop_assert_eq!(sorted(items(&shifted)), sorted(items(&tree)));
        let min_len = tree.paths().map(TreePath::len).min().unwrap_or(0);
        let uniform = tree.paths().all(|p| p.len() == min_len);
        if uniform && offset < 0 && offset.unsigned_abs() < min_len as u64 {
            // Trimming paths of one length to prefixes merges in path order, so item order is
            // kept. (With several lengths a shorter prefix can sort ahead of a longer one.)
            prop_assert_eq!(items(&shifted), items(&tree));
        }
    }

    #[test]
    fn flip_matrix_twice_is_identity_on_full_matrices(rows in 1_usize..5, columns in 1_usize..5, prefix in 0_u32..3) {
        let mut tree = DataTree::new();
        for r in 0..rows {
            let row: Vec<f64> = (0..columns).map(|c| (r * 10 + c) as f64).collect();
            tree.insert(TreePath::from([prefix, r as u32]), Branch::from_items(row));
        }
        let mut t = tree.clone();
        t.flip_matrix().unwrap();
        prop_assert_eq!(t.branch_count(), columns);
        t.flip_matrix().unwrap();
        prop_assert_eq!(t, tree);
    }

    #[test]
    fn flip_matrix_never_panics(tree in any_tree()) {
        let mut t = tree.clone();
        if t.flip_matrix().is_ok() {
            let columns = tree.branches().iter().map(|(_, b)| b.len()).max().unwrap_or(0);
            prop_assert_eq!(t.item_count(), columns * tree.branch_count());
        } else {
            prop_assert_eq!(t, tree);
        }
    }

    #[test]
    fn path_mapper_identity_and_swap(tree in uniform_tree()) {
        let depth = tree.paths().next().map_or(1, TreePath::len);
        let names: Vec<String> = (0..depth).map(|k| format!("v{k}")).collect();
        let source = format!("{{{}}}(i)", names.join(";"));
        let identity = PathMapper::new(&source, &source).unwrap();
        prop_assert_eq!(identity.apply(&tree).unwrap(), tree.clone());
        let mut reversed = names.clone();
        reversed.reverse();
        let swap = PathMapper::new(&source, &format!("{{{}}}(i)", reversed.join(";"))).unwrap();
        let back = swap.apply(&swap.apply(&tree).unwrap()).unwrap();
        prop_assert_eq!(back, tree);
    }

    #[test]
    fn path_mapper_to_one_path_equals_flatten(tree in uniform_tree()) {
        let depth = tree.paths().next().map_or(1, TreePath::len);
        let names: Vec<String> = (0..depth).map(|k| format!("v{k}")).collect();
        let mapper = PathMapper::new(&format!("{{{}}}", names.join(";")), "{0}").unwrap();
        let mut flat = tree.clone();
        flat.flatten();
        prop_assert_eq!(mapper.apply(&tree).unwrap(), flat);
    }

    #[test]
    fn tree_text_round_trips(tree in any_tree()) {
        let text = tree.to_text();
        prop_assert_eq!(DataTree::from_text(&text).unwrap(), tree);
    }

    #[test]
    fn text_trees_round_trip(texts in prop::collection::vec(prop::option::of("\\PC{0,8}"), 0..6)) {
        let mut b = Branch::new(DataType::Text);
        for t in &texts {
            match t {
                Some(t) => b.push(t.clone()),
                None => b.push_null(),
            }
        }
        let mut tree = DataTree::new();
        tree.insert(TreePath::from([1, 2]), b);
        let parsed = DataTree::parse_text(&tree.to_text(), DataType::Text).unwrap();
        prop_assert_eq!(parsed, tree);
    }

    #[test]
    fn tree_text_parsing_never_panics(text in "[{}\\[\\]:;,0-9a-z \"\\\\.+-]{0,40}") {
        for data_type in DataType::ALL {
            let _ = DataTree::parse_text(&text, *data_type);
        }
    }

    #[test]
    fn tree_text_parsing_of_any_text_never_panics(text in "\\PC{0,40}") {
        for data_type in DataType::ALL {
            let _ = DataTree::parse_text(&text, *data_type);
        }
    }

    #[test]
    fn path_mapper_parsing_of_any_text_never_panics(source in "\\PC{0,20}", target in "\\PC{0,20}") {
        let _ = PathMapper::new(&source, &target);
        let _ = PathMapper::parse(&source);
    }

    #[test]
    fn path_mapper_parsing_never_panics(source in "[{}();A-Ci0-9+*/%\\\\ -]{0,16}", target in "[{}();A-Ci0-9+*/%\\\\ -]{0,16}") {
        if let Ok(mapper) = PathMapper::new(&source, &target) {
            let tree = DataTree::from_text("{0;1}:[1, 2] {1;0}:[3]").unwrap();
            let _ = mapper.apply(&tree);
        }
    }

    #[test]
    fn numbers_print_and_parse_back(x in any::<f64>()) {
        let back = parse_number(&format_number(x)).unwrap();
        prop_assert!(back == x || (x.is_nan() && back.is_nan()));
    }

    #[test]
    fn casting_a_branch_keeps_its_length(values in prop::collection::vec(prop::option::of(any_value()), 0..8), to in 0..DataType::ALL.len()) {
        let to = DataType::ALL[to];
        let mut b = Branch::new(DataType::Generic);
        for v in &values {
            b.push_option(v.clone());
        }
        let (cast, errors) = cast_branch(&b, to);
        prop_assert_eq!(cast.len(), values.len());
        for (i, v) in values.iter().enumerate() {
            let failed = errors.iter().any(|(k, _)| *k == i);
            match v {
                None => prop_assert!(cast.is_null(i) && !failed),
                Some(v) => prop_assert_eq!(cast_value(v, to).is_err(), failed),
            }
            prop_assert_eq!(cast.is_null(i), v.is_none() || failed);
        }
    }

    #[test]
    fn typed_number_branches_cast_like_values(xs in prop::collection::vec(any::<f64>(), 0..8), to in 0..DataType::ALL.len()) {
        let to = DataType::ALL[to];
        let b = Branch::from_items(xs.clone());
        let (cast, errors) = cast_branch(&b, to);
        prop_assert_eq!(cast.len(), xs.len());
        for (i, x) in xs.iter().enumerate() {
            match cast_value(&Value::Number(*x), to) {
                Ok(v) => prop_assert_eq!(format!("{:?}", cast.value(i)), format!("{:?}", Some(v))),
                Err(e) => prop_assert!(errors.contains(&(i, e))),
            }
        }
    }
}
