//! Params › Primitive: Number, Integer, Boolean, Text, File Path, Domain and Domain²
//! parameters.
//!
//! Each has one list-access input and one list output of the same name and nickname; the
//! graph tells them apart by direction (`Num` as an input is the values coming in, `Num` as
//! an output the values going on).

use locus_runtime::{DataType, NodeRegistry, NodeType, Port};

/// Id of [`number`].
pub const NUMBER: &str = "params.number";
/// Id of [`integer`].
pub const INTEGER: &str = "params.integer";
/// Id of [`boolean`].
pub const BOOLEAN: &str = "params.boolean";
/// Id of [`text`].
pub const TEXT: &str = "params.text";
/// Id of [`file_path`].
pub const FILE_PATH: &str = "params.file_path";
/// Id of [`domain`].
pub const DOMAIN: &str = "params.domain";
/// Id of [`domain2`].
pub const DOMAIN2: &str = "params.domain2";

/// Registers the primitive parameters.
pub fn register(registry: &mut NodeRegistry) {
    for t in [
        number(),
        integer(),
        boolean(),
        text(),
        file_path(),
        domain(),
        domain2(),
    ] {
        registry.register(t);
    }
}

/// A parameter node of type `data_type`.
fn parameter(
    id: &str,
    name: &str,
    nickname: &str,
    data_type: DataType,
    description: &str,
    accepts: &str,
) -> NodeType {
    NodeType::new(id, name, nickname, "Params")
        .subcategory("Primitive")
        .description(&format!(
            "{description} A parameter passes its data through unchanged (paths, empty \
             branches and nulls included) after casting every item to its type; a graph uses \
             it to declare a named input. Items that do not cast are errors and become null."
        ))
        .input(Port::new(name, nickname, data_type).list().doc(&format!(
            "The values, given in the graph or wired in: {accepts}. No default; a parameter \
             without data warns that it failed to collect data."
        )))
        .output(
            Port::new(name, nickname, data_type)
                .list()
                .doc("The same values, cast."),
        )
        .solve(|s| {
            if let Some(branch) = s.branch(0) {
                let branch = branch.clone();
                s.set_branch(0, branch);
            }
            Ok(())
        })
}

/// Number \[Num\]: a collection of real numbers.
pub fn number() -> NodeType {
    parameter(
        NUMBER,
        "Number",
        "Num",
        DataType::Number,
        "Contains a collection of floating point numbers.",
        "numbers, integers, booleans (0 or 1), text that reads as a number, or domains",
    )
    .gh_guid("3e8ca6be-fda8-4aaf-b5c0-3c54c8bb7312")
}

/// Integer \[Int\]: a collection of whole numbers.
pub fn integer() -> NodeType {
    parameter(
        INTEGER,
        "Integer",
        "Int",
        DataType::Integer,
        "Contains a collection of integer numbers.",
        "integers, numbers (rounded to the nearest whole number), booleans (0 or 1) or text \
         that reads as a whole number",
    )
    .gh_guid("2e3ab970-8545-46bb-836c-1c11e5610bce")
}

/// Boolean \[Bool\]: a collection of booleans.
pub fn boolean() -> NodeType {
    parameter(
        BOOLEAN,
        "Boolean",
        "Bool",
        DataType::Boolean,
        "Contains a collection of boolean values.",
        "booleans, numbers (0 is false, anything else true) or the text True/False",
    )
    .gh_guid("cb95db89-6165-43b6-9c41-5702bc5bf137")
}

/// Text \[Txt\]: a collection of texts.
pub fn text() -> NodeType {
    parameter(
        TEXT,
        "Text",
        "Txt",
        DataType::Text,
        "Contains a collection of text fragments.",
        "text, or any value, which is written as text",
    )
    .gh_guid("3ede854e-c753-40eb-84cb-b48008f14fd4")
}

/// File Path \[Path\]: a collection of file paths, as text.
pub fn file_path() -> NodeType {
    parameter(
        FILE_PATH,
        "File Path",
        "Path",
        DataType::Text,
        "Contains a collection of file paths, as text: no file is opened or checked (a path \
         from a Grasshopper file names a file on the machine that saved it).",
        "paths as text, or any value, which is written as text",
    )
    .gh_guid("06953bda-1d37-4d58-9b38-4b3c74e54c8f")
}

/// Domain \[Domain\]: a collection of numeric domains.
pub fn domain() -> NodeType {
    parameter(
        DOMAIN,
        "Domain",
        "Domain",
        DataType::Domain,
        "Contains a collection of numeric domains.",
        "domains, numbers (x is the domain 0 to x) or text such as \"0 To 10\"",
    )
    .gh_guid("15b7afe5-d0d0-43e1-b894-34fcfe3be384")
}

/// Domain² \[Domain²\]: a collection of two-dimensional domains.
pub fn domain2() -> NodeType {
    parameter(
        DOMAIN2,
        "Domain²",
        "Domain²",
        DataType::Domain2,
        "Contains a collection of two-dimensional domains (a u and a v domain each).",
        "two-dimensional domains, domains (used for both u and v), numbers (0 to x in both) \
         or surfaces (their domains)",
    )
    .gh_guid("90744326-eb53-4a0e-b7ef-4b45f5473d6e")
}

#[cfg(test)]
mod tests {
    use locus_kernel::Interval;
    use locus_runtime::{Branch, DataTree, Level, NodeCall, TreePath, Value};

    use super::*;

    #[test]
    fn structure_and_nulls_pass_through() {
        let mut with_null = Branch::new(DataType::Number);
        with_null.push(1.0);
        with_null.push_null();
        with_null.push(3.0);
        let input = DataTree::from_branches([
            (TreePath::new(vec![0, 0]), with_null),
            (TreePath::new(vec![0, 1]), Branch::new(DataType::Number)),
            (TreePath::new(vec![0, 2]), Branch::from_items(vec![4.0])),
        ]);
        let r = NodeCall::new(&number()).input(input.clone()).run();
        assert_eq!(r.outputs[0], input);
        assert!(r.messages.is_empty());
    }

    #[test]
    fn every_primitive_passes_its_type() {
        let cases = [
            (integer(), DataTree::from_list(vec![1_i64, -2])),
            (boolean(), DataTree::from_list(vec![true, false])),
            (
                text(),
                DataTree::from_list(vec!["a".to_owned(), String::new()]),
            ),
            (domain(), DataTree::from_item(Interval::new(2.0, 5.0))),
        ];
        for (node, tree) in cases {
            let r = NodeCall::new(&node).input(tree.clone()).run();
            assert_eq!(r.outputs[0], tree, "{}", node.id);
            assert_eq!(node.inputs[0].data_type, node.outputs[0].data_type);
            assert_eq!(node.inputs[0].nickname, node.outputs[0].nickname);
        }
    }

    #[test]
    fn items_are_cast_on_the_way_in() {
        let mixed = DataTree::from_list(vec![
            Value::Text("2.5".to_owned()),
            Value::Integer(3),
            Value::Boolean(true),
        ]);
        let r = NodeCall::new(&number()).input(mixed).run();
        assert_eq!(r.outputs[0], DataTree::from_list(vec![2.5, 3.0, 1.0]));
        let r = NodeCall::new(&boolean())
            .input(DataTree::from_list(vec![0.0, 2.0]))
            .run();
        assert_eq!(r.outputs[0], DataTree::from_list(vec![false, true]));
        let r = NodeCall::new(&domain())
            .input(DataTree::from_item(5.0))
            .run();
        assert_eq!(r.outputs[0], DataTree::from_item(Interval::new(0.0, 5.0)));
    }

    #[test]
    fn a_failed_cast_is_an_error_and_a_null() {
        let r = NodeCall::new(&number())
            .input(DataTree::from_list(vec!["abc".to_owned(), "1".to_owned()]))
            .run();
        let out: Vec<_> = r.outputs[0].values().collect();
        assert_eq!(out, [None, Some(Value::Number(1.0))]);
        assert_eq!(
            r.messages
                .iter()
                .filter(|m| m.level == Level::Error)
                .count(),
            1
        );
    }

    #[test]
    fn a_parameter_without_data_warns() {
        let r = NodeCall::new(&number()).run();
        assert!(r.outputs[0].is_empty());
        let warnings: Vec<&str> = r
            .messages
            .iter()
            .filter(|m| m.level == Level::Warning)
            .map(|m| m.text.as_str())
            .collect();
        assert_eq!(warnings, ["input parameter Num failed to collect data"]);
    }

    #[test]
    fn single_values_stay_single() {
        let r = NodeCall::new(&domain())
            .input(DataTree::from_item(Interval::UNIT))
            .run();
        let out: Vec<_> = r.outputs[0].values().collect();
        assert_eq!(out, [Some(Value::Domain(Interval::UNIT))]);
    }
}
