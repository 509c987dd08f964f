//! The casting table in `docs/casting.md` agrees with `can_cast`.

use locus_runtime::{DataType, can_cast};

#[test]
fn documented_table_matches_can_cast() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/casting.md");
    let doc = std::fs::read_to_string(path).expect("docs/casting.md is readable");
    let table: Vec<&str> = doc
        .lines()
        .skip_while(|l| !l.starts_with("| from \\ to |"))
        .take_while(|l| l.starts_with('|'))
        .collect();
    assert!(!table.is_empty(), "the table is missing");
    let cells = |line: &str| -> Vec<String> {
        line.trim_matches('|')
            .split('|')
            .map(|c| c.trim().to_owned())
            .collect()
    };
    let header = cells(table[0]);
    let targets: Vec<DataType> = header[1..]
        .iter()
        .map(|n| DataType::from_name(n).unwrap_or_else(|| panic!("unknown type {n}")))
        .collect();
    let mut rows_seen = 0;
    for line in &table[2..] {
        let row = cells(line);
        let from =
            DataType::from_name(&row[0]).unwrap_or_else(|| panic!("unknown type {}", row[0]));
        if from == DataType::Generic {
            continue;
        }
        rows_seen += 1;
        for (to, cell) in targets.iter().zip(&row[1..]) {
            if *to == from {
                assert!(cell.is_empty(), "{from} → {to}: the diagonal is left blank");
                continue;
            }
            assert_eq!(
                !cell.is_empty(),
                can_cast(from, *to),
                "docs/casting.md and can_cast disagree on {from} → {to}"
            );
        }
    }
    assert_eq!(
        rows_seen,
        DataType::ALL.len() - 1,
        "a type is missing from the table"
    );
    assert_eq!(
        targets.len(),
        DataType::ALL.len() - 1,
        "a type is missing from the header"
    );
}
