//! The node catalogue as Markdown (`docs/nodes.md` is generated from the library's registry).

use std::fmt::Write as _;

use crate::{NodeRegistry, NodeType, Port, format_value};

fn port_row(out: &mut String, port: &Port) {
    let default = port
        .default
        .as_ref()
        .map(|d| format!("`{}`", format_value(d)))
        .unwrap_or_default();
    let _ = writeln!(
        out,
        "| {} | {} | {} | {}{} | {} | {} |",
        port.name,
        port.nickname,
        port.data_type,
        port.access.name(),
        if port.optional { ", optional" } else { "" },
        default,
        port.description.replace('|', "\\|").replace('\n', " ")
    );
}

fn node_section(out: &mut String, t: &NodeType) {
    let _ = writeln!(out, "### {} [{}]\n", t.name, t.nickname);
    let place = if t.subcategory.is_empty() {
        t.category.clone()
    } else {
        format!("{} › {}", t.category, t.subcategory)
    };
    let _ = writeln!(out, "`{}` — {place}\n", t.id);
    if !t.description.is_empty() {
        let _ = writeln!(out, "{}\n", t.description);
    }
    if t.variable_inputs.is_some() {
        out.push_str("Inputs are variable: a graph names them; the defaults are listed.\n\n");
    }
    if let Some(v) = &t.variable_outputs {
        let fixed: Vec<&str> = v.fixed.iter().map(|p| p.nickname.as_str()).collect();
        if fixed.is_empty() {
            out.push_str("Outputs are variable: a graph names them; the defaults are listed.\n\n");
        } else {
            let _ = writeln!(
                out,
                "Outputs are variable: a graph names them, after {}; the defaults are listed.\n",
                fixed.join(", ")
            );
        }
    }
    out.push_str("| port | nickname | type | access | default | description |\n");
    out.push_str("| --- | --- | --- | --- | --- | --- |\n");
    for p in &t.inputs {
        port_row(out, p);
    }
    for p in &t.outputs {
        let mut p = p.clone();
        p.name = format!("→ {}", p.name);
        port_row(out, &p);
    }
    for s in &t.settings {
        let default = s
            .default
            .as_ref()
            .map(|d| format!("`{}`", format_value(d)))
            .unwrap_or_default();
        let _ = writeln!(
            out,
            "| setting `{}` | | {} | | {} | {} |",
            s.name, s.data_type, default, s.description
        );
    }
    out.push('\n');
}

impl NodeRegistry {
    /// The catalogue of every node type as Markdown: by category and subcategory, each node
    /// with its id, description and a table of ports (inputs, then outputs marked `→`).
    pub fn catalogue_markdown(&self) -> String {
        let mut types: Vec<&NodeType> = self.iter().collect();
        types.sort_by(|a, b| {
            (&a.category, &a.subcategory, &a.name).cmp(&(&b.category, &b.subcategory, &b.name))
        });
        let mut out = String::from(
            "# Node catalogue\n\nGenerated from the registry by `cargo test` \
             (`UPDATE_EXPECT=1 cargo test --test catalogue` rewrites it); do not edit by hand.\n\n",
        );
        let mut category = "";
        for t in types {
            if t.category != category {
                let _ = writeln!(out, "## {}\n", t.category);
                category = &t.category;
            }
            node_section(&mut out, t);
        }
        out
    }
}
