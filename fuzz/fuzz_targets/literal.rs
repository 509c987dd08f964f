//! Literal values read against every port type: reading never panics, and a tree that reads
//! writes back (`Literal::from_tree`) to a literal that reads as an equal tree.
#![no_main]

use libfuzzer_sys::fuzz_target;
use locus_runtime::{COMPARE_TOLERANCE, DataType, Literal, compare_trees, parse_literal};

fuzz_target!(|data: &[u8]| {
    let Some((&selector, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    let data_type = DataType::ALL[usize::from(selector) % DataType::ALL.len()];
    let Ok(tree) = parse_literal(text, data_type) else {
        return;
    };
    let _ = format!("{tree:?}");
    let Ok(written) = Literal::from_tree(&tree) else {
        return; // a type without a literal form (B-reps, meshes)
    };
    let again = written.parse(data_type).unwrap_or_else(|e| {
        panic!("{text:?} as {data_type:?} writes {written} which does not read: {e}")
    });
    let differences = compare_trees(&again, &tree, COMPARE_TOLERANCE, 3);
    assert!(
        differences.is_empty(),
        "{text:?} as {data_type:?} writes {written} which reads differently: {differences:?}"
    );
});
