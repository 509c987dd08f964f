//! A host embedding locus: load the book's tangent-spheres graph with the whole node library,
//! set its named inputs, evaluate, read outputs and messages, change an input and evaluate
//! again (only the nodes downstream of it run).
//!
//! ```sh
//! cargo run --example host
//! ```

use locus_runtime::{DataTree, Evaluator, NodeRegistry};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);

    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("graphs/tangent_spheres.ron");
    let mut graph = Evaluator::from_file(&path, &registry)?;

    // Named inputs take data trees, or literal text read as the graph file writes values.
    graph.set_input_text("B", "(10, 0, 0)")?;
    graph.set_input("t", DataTree::from_list(vec![0.25, 0.5]))?;
    graph.evaluate();
    for name in ["D", "r1", "r2"] {
        let tree = graph.output(name).expect("a named output of the graph");
        println!("{name} = {}", tree.to_text());
    }

    // A changed input re-runs only what depends on it.
    graph.set_input_text("t", "0.75")?;
    graph.evaluate();
    let ran: Vec<&str> = graph.last_run().iter().map(|id| id.0.as_str()).collect();
    println!("after t changed, these nodes ran again: {}", ran.join(", "));
    println!("r1 = {}", graph.output("r1").expect("r1").to_text());

    // Every message names its node and, for a failed iteration, the path and item index.
    for message in graph.messages() {
        println!("{message}");
    }
    Ok(())
}
