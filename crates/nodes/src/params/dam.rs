//! Data Dam: Grasshopper's valve that holds data back until the user releases it (or a delay
//! passes), so that a slow part of a definition does not recompute on every slider move.
//!
//! locus evaluates a graph in one pass with nobody at a canvas to release anything, so a dam
//! passes each input's tree to the output of the same position at once, unchanged. The delay
//! a file stores is not read.

use locus_runtime::{DataType, NodeType, Port};

/// Id of [`data_dam`].
pub const DATA_DAM: &str = "params.data_dam";

/// Registers Data Dam.
pub fn register(registry: &mut locus_runtime::NodeRegistry) {
    registry.register(data_dam());
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
