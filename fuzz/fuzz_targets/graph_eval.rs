//! Whole-graph evaluation of random well-formed graphs under tight limits: up to eight nodes of
//! any library type, each input wired from an earlier node's output of a type that can be cast
//! to it, given a small literal value, or left to its default; any matching mode and modifier.
//! Checking must accept what it accepts without panicking, and evaluation must finish (small
//! values keep counts small) with outputs and messages identical on one thread and on two.
#![no_main]

use std::sync::OnceLock;

use libfuzzer_sys::fuzz_target;
use locus_runtime::{DataType, Evaluator, NodeRegistry, NodeType, can_cast, check_text};

/// At most this many nodes per graph.
const MAX_NODES: usize = 8;

fn registry() -> &'static (NodeRegistry, Vec<String>) {
    static REGISTRY: OnceLock<(NodeRegistry, Vec<String>)> = OnceLock::new();
    REGISTRY.get_or_init(|| {
        let mut r = NodeRegistry::new();
        locus_nodes::register(&mut r);
        let mut ids: Vec<String> = r.iter().map(|t| t.id.clone()).collect();
        ids.sort();
        (r, ids)
    })
}

/// Bytes read one at a time; zeros once they run out.
struct Bytes<'a>(&'a [u8]);

impl Bytes<'_> {
    fn byte(&mut self) -> u8 {
        match self.0.split_first() {
            Some((&b, rest)) => {
                self.0 = rest;
                b
            }
            None => 0,
        }
    }

    fn pick<'t, T>(&mut self, items: &'t [T]) -> &'t T {
        &items[usize::from(self.byte()) % items.len()]
    }
}

/// A small literal of a type: a few awkward numbers, small counts, degenerate geometry.
fn literal(data_type: DataType, b: &mut Bytes) -> Option<String> {
    let numbers = [
        "0", "1", "-1", "0.5", "3", "-2.5", "1e-12", "NaN", "inf", "7",
    ];
    let n = |b: &mut Bytes| b.pick(&numbers).to_string();
    let point = |b: &mut Bytes| format!("({}, {}, {})", n(b), n(b), n(b));
    let one = |b: &mut Bytes| -> Option<String> {
        Some(match data_type {
            DataType::Number => n(b),
            DataType::Integer => b.pick(&["0", "1", "2", "-1", "5"]).to_string(),
            DataType::Boolean => b.pick(&["true", "false"]).to_string(),
            DataType::Text => b
                .pick(&["\"\"", "\"a\"", "\"{0;1}\"", "\"x+1\""])
                .to_string(),
            DataType::Point | DataType::Vector => point(b),
            DataType::Domain => format!("({}, {})", n(b), n(b)),
            DataType::Plane => b.pick(&["XY", "YZ", "XZ", "ZX"]).to_string(),
            DataType::Line => format!("({}, {})", point(b), point(b)),
            DataType::Circle => format!("(plane: XY, radius: {})", n(b)),
            DataType::Box | DataType::Brep => {
                format!("Box(plane: XY, x: (0, {}), y: (0, 1), z: (0, 1))", n(b))
            }
            DataType::Curve => format!("(degree: 1, points: [{}, {}])", point(b), point(b)),
            DataType::Generic => n(b),
            _ => return None,
        })
    };
    match b.byte() % 4 {
        0 => one(b),
        1 => Some("[]".to_owned()),
        2 => {
            let items: Option<Vec<String>> = (0..b.byte() % 4 + 1).map(|_| one(b)).collect();
            Some(format!("[{}]", items?.join(", ")))
        }
        _ => Some(format!(
            "{{\"{{0;1}}\": [{}], \"{{1}}\": [{}]}}",
            one(b)?,
            one(b)?
        )),
    }
}

/// A graph as RON text.
fn graph(data: &[u8]) -> String {
    let (registry, ids) = registry();
    let mut b = Bytes(data);
    let count = usize::from(b.byte()) % MAX_NODES + 1;
    let mut nodes = Vec::new();
    let mut wires = Vec::new();
    let mut types: Vec<&NodeType> = Vec::new();
    for k in 0..count {
        let id: &String = b.pick(ids);
        let node_type = registry.get(id).expect("a registered type");
        let mut values = Vec::new();
        for port in &node_type.inputs {
            match b.byte() % 4 {
                0 => {}
                1 => {
                    if let Some(text) = literal(port.data_type, &mut b) {
                        values.push(format!("{:?}: {text}", port.nickname));
                    }
                }
                _ if k > 0 => {
                    let from = usize::from(b.byte()) % k;
                    let outputs = &types[from].outputs;
                    if !outputs.is_empty() {
                        let out = b.pick(outputs);
                        if can_cast(out.data_type, port.data_type) {
                            wires.push(format!(
                                "(\"n{from}.{}\", \"n{k}.{}\")",
                                out.nickname, port.nickname
                            ));
                        }
                    }
                }
                _ => {}
            }
        }
        let matching = b.pick(&["", ", matching: shortest", ", matching: cross"]);
        let modifiers = match (node_type.inputs.first(), b.byte() % 5) {
            (Some(p), 1) => format!(", modifiers: {{{:?}: [graft]}}", p.nickname),
            (Some(p), 2) => format!(", modifiers: {{{:?}: [flatten, reverse]}}", p.nickname),
            (Some(p), 3) => format!(", modifiers: {{{:?}: [simplify]}}", p.nickname),
            _ => String::new(),
        };
        nodes.push(format!(
            "(id: \"n{k}\", type: {:?}, values: {{{}}}{matching}{modifiers})",
            node_type.id,
            values.join(", ")
        ));
        types.push(node_type);
    }
    format!(
        "(format: 1, nodes: [{}], wires: [{}])",
        nodes.join(", "),
        wires.join(", ")
    )
}

fn evaluate(checked: &locus_runtime::Checked, threads: usize) -> String {
    let mut ev = Evaluator::new(checked.plan.clone());
    ev.set_threads(threads).expect("a thread pool");
    ev.evaluate();
    let mut dump = String::new();
    for (k, node) in checked.plan.nodes.iter().enumerate() {
        for o in 0..node.node_type.outputs.len() {
            dump.push_str(&format!("{k}.{o}: {:?}\n", ev.node_output_at(k, o)));
        }
    }
    for m in ev.messages() {
        dump.push_str(&format!("{m}\n"));
    }
    dump
}

fuzz_target!(|data: &[u8]| {
    let text = graph(data);
    let (registry, _) = registry();
    let Ok(checked) = check_text(&text, registry) else {
        return;
    };
    let one = evaluate(&checked, 1);
    let two = evaluate(&checked, 2);
    assert!(one == two, "one thread and two differ on {text}");
});
