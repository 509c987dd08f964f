//! The parameters that hold data across Grasshopper's solutions: Data Dam, the valve that holds
//! data back until the user releases it (or a delay passes) so that a slow part of a
//! definition does not recompute on every slider move, and Data Recorder, which appends each
//! solution's data to what it recorded before.
//!
//! locus evaluates a graph in one pass with nobody at a canvas, so both pass their data on at
//! once, unchanged: a dam has nothing to wait for (the delay a file stores is not read) and a
//! recorder records the one solution there is (its record limit is not read).

use locus_runtime::{DataType, NodeType, Port};

/// Id of [`data_dam`].
pub const DATA_DAM: &str = "params.data_dam";
/// Id of [`data_recorder`].
pub const DATA_RECORDER: &str = "params.data_recorder";

/// Registers Data Dam and Data Recorder.
pub fn register(registry: &mut locus_runtime::NodeRegistry) {
    registry.register(data_dam());
    registry.register(data_recorder());
}

/// Data Recorder \[Rec\]: the data of the one solution a headless run makes.
pub fn data_recorder() -> NodeType {
    NodeType::new(DATA_RECORDER, "Data Recorder", "Rec", "Params")
        .subcategory("Util")
        .gh_guid("401aa475-997a-4139-991d-f980ffdcf908")
        .description(
            "Records data. In Grasshopper a recorder appends every solution's data to what it \
             recorded before (up to its limit), branch by branch; a headless run makes one \
             solution, so the record is that solution's data: the tree passes through \
             unchanged (paths, empty branches and nulls included).",
        )
        .input(
            Port::new("Data Recorder", "Rec", DataType::Generic)
                .tree()
                .doc("The data to record, of any type."),
        )
        .output(
            Port::new("Data Recorder", "Rec", DataType::Generic)
                .tree()
                .doc("The recorded data: this solution's."),
        )
        .solve(|s| {
            let tree = s.tree(0)?.clone();
            s.set_tree(0, tree);
            Ok(())
        })
}

/// Data Dam \[Dam\]: each input's data passed on to its output.
pub fn data_dam() -> NodeType {
    NodeType::new(DATA_DAM, "Data Dam", "Dam", "Params")
        .subcategory("Util")
        .gh_guid("65283518-ad00-49d3-87fb-f76823ebb162")
        .description(
            "Passes each input's data (the whole tree, any type) to the output of the same \
             position, unchanged. In Grasshopper a dam holds data back until it is released \
             or a delay passes; a headless run has no one to release it and evaluates once, \
             so the data passes at once and the delay is ignored. Inputs and outputs are \
             variable, A, B, … on both sides as Grasshopper names them; an output without an \
             input of its position stays empty, with a warning.",
        )
        .variable_inputs(
            Port::new("Data", "A", DataType::Generic)
                .tree()
                .optional()
                .doc("Data to pass through, of any type (the input at the same position as the output); optional."),
            &["A"],
        )
        .variable_outputs(
            Port::new("Data", "A", DataType::Generic)
                .tree()
                .doc("The data of the input at the same position, unchanged."),
            &["A"],
        )
        .solve(|s| {
            let inputs = s.input_count();
            for k in 0..s.output_count() {
                if k < inputs {
                    let tree = s.tree(k)?.clone();
                    s.set_tree(k, tree);
                } else {
                    s.warning(format!(
                        "output {} has no input at its position (there are {inputs} inputs)",
                        k + 1
                    ));
                }
            }
            Ok(())
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use locus_runtime::{DataTree, NodeCall};

    fn tree(text: &str) -> DataTree {
        DataTree::parse_text(text, DataType::Generic).unwrap()
    }

    #[test]
    fn a_recorder_records_the_one_solution() {
        let a = tree("{0;1}:[1, null] {0;2}:[] {3}:[\"x\"]");
        let out = NodeCall::new(&data_recorder()).input(a.clone()).run();
        assert!(out.messages.is_empty(), "{:?}", out.messages);
        assert_eq!(out.outputs[0].to_text(), a.to_text());
        // Nothing to record: the input warns that it collected no data.
        let out = NodeCall::new(&data_recorder()).skip_input().run();
        assert!(!out.messages.is_empty());
    }

    #[test]
    fn each_input_passes_to_its_output_unchanged() {
        let (a, b) = (tree("{0;1}:[1, null] {0;2}:[]"), tree(r#"{0}:["x", true]"#));
        let node = data_dam();
        let out = NodeCall::new(&node)
            .input_names(&["A", "B"])
            .output_names(&["A", "B"])
            .input(a.clone())
            .input(b.clone())
            .run();
        assert!(out.messages.is_empty(), "{:?}", out.messages);
        assert_eq!(out.outputs[0].to_text(), a.to_text());
        assert_eq!(out.outputs[1].to_text(), b.to_text());
    }

    #[test]
    fn an_output_without_an_input_stays_empty_with_a_warning() {
        let node = data_dam();
        let out = NodeCall::new(&node)
            .input_names(&["A"])
            .output_names(&["A", "B"])
            .input(tree("{0}:[2]"))
            .run();
        assert_eq!(out.outputs[0].to_text(), "{0}:[2]");
        assert_eq!(out.outputs[1].item_count(), 0);
        assert!(
            out.messages.iter().any(|m| m.text.contains("output 2")),
            "{:?}",
            out.messages
        );
    }

    #[test]
    fn nothing_in_is_nothing_out() {
        let node = data_dam();
        let out = NodeCall::new(&node).skip_input().run();
        assert_eq!(out.outputs[0].item_count(), 0);
        assert!(out.messages.is_empty(), "{:?}", out.messages);
    }
}
