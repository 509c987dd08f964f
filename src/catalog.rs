//! `locus nodes` and `locus describe`: the node catalogue.

use locus_runtime::{NodeRegistry, NodeType, Port};

use crate::{EXIT_USAGE, render};

/// The registry with every node of the library.
pub(crate) fn registry() -> NodeRegistry {
    let mut registry = NodeRegistry::new();
    locus_nodes::register(&mut registry);
    registry
}

/// Prints the catalogue, grouped by category.
pub(crate) fn list(registry: &NodeRegistry, category: Option<&str>) -> u8 {
    let mut types: Vec<&NodeType> = registry
        .iter()
        .filter(|t| category.is_none_or(|c| t.category.eq_ignore_ascii_case(c)))
        .collect();
    if types.is_empty() {
        let mut categories: Vec<&str> = registry.iter().map(|t| t.category.as_str()).collect();
        categories.sort_unstable();
        categories.dedup();
        eprintln!(
            "locus: no category \"{}\" (categories: {})",
            category.unwrap_or_default(),
            categories.join(", ")
        );
        return EXIT_USAGE;
    }
    types.sort_by(|a, b| {
        (&a.category, &a.subcategory, &a.id).cmp(&(&b.category, &b.subcategory, &b.id))
    });
    let width = types.iter().map(|t| t.id.len()).max().unwrap_or(0);
    let mut current = "";
    for t in types {
        if t.category != current {
            out!("{}", t.category);
            current = &t.category;
        }
        out!("  {:width$}  {} [{}]", t.id, t.name, t.nickname);
    }
    0
}

fn find<'r>(registry: &'r NodeRegistry, name: &str) -> Option<&'r NodeType> {
    registry.get(name).or_else(|| {
        registry
            .iter()
            .find(|t| t.name.eq_ignore_ascii_case(name) || t.nickname.eq_ignore_ascii_case(name))
    })
}

fn port_line(port: &Port) -> String {
    let mut line = format!(
        "    {} ({}) {} {}",
        port.name,
        port.nickname,
        port.data_type,
        port.access.name()
    );
    if port.optional {
        line.push_str(", optional");
    }
    if let Some(d) = &port.default {
        line.push_str(&format!(", default {}", render::value_text(d)));
    }
    if !port.description.is_empty() {
        line.push_str(&format!("\n      {}", port.description));
    }
    line
}

/// Prints a node type's documentation and ports.
pub(crate) fn describe(registry: &NodeRegistry, name: &str) -> u8 {
    let Some(t) = find(registry, name) else {
        let hints = registry.suggestions(name);
        if hints.is_empty() {
            eprintln!("locus: no node type \"{name}\" (`locus nodes` lists them)");
        } else {
            eprintln!(
                "locus: no node type \"{name}\" (did you mean {}?)",
                hints.join(", ")
            );
        }
        return EXIT_USAGE;
    };
    out!("{} [{}]  ({})", t.name, t.nickname, t.id);
    let place = if t.subcategory.is_empty() {
        t.category.clone()
    } else {
        format!("{} > {}", t.category, t.subcategory)
    };
    out!("  {place}");
    if !t.description.is_empty() {
        out!("\n  {}", t.description);
    }
    out!("\n  Inputs:");
    if t.variable_inputs.is_some() {
        out!("    (variable: a graph names this node's inputs; these are the defaults)");
    }
    if t.inputs.is_empty() {
        out!("    none");
    }
    for p in &t.inputs {
        out!("{}", port_line(p));
    }
    out!("\n  Outputs:");
    if let Some(v) = &t.variable_outputs {
        let fixed: Vec<&str> = v.fixed.iter().map(|p| p.nickname.as_str()).collect();
        if fixed.is_empty() {
            out!("    (variable: a graph names this node's outputs; these are the defaults)");
        } else {
            out!(
                "    (variable: a graph names this node's outputs after {}; these are the defaults)",
                fixed.join(", ")
            );
        }
    }
    for p in &t.outputs {
        out!("{}", port_line(p));
    }
    if !t.settings.is_empty() {
        out!("\n  Settings:");
        for s in &t.settings {
            let default = s
                .default
                .as_ref()
                .map(|d| format!(", default {}", render::value_text(d)))
                .unwrap_or_default();
            out!(
                "    {} {}{default}\n      {}",
                s.name,
                s.data_type,
                s.description
            );
        }
    }
    0
}
