//! One node as a Grasshopper object: its component or parameter chunk, its parameters with
//! their wires, modifiers and persistent data.

use super::*;

pub(super) fn write_object(
    o: &mut Out,
    index: usize,
    p: &Ports<'_>,
    sources: &HashMap<(String, String), Vec<String>>,
    pos: (f32, f32),
    warnings: &mut Vec<ExportWarning>,
) {
    let id = &p.node.id.0;
    o.chunk_start("Object", Some(index));
    items_and_chunks(
        o,
        |o| {
            let (guid, name) = match p.gh_type {
                Some((guid, name)) => (guid, name),
                None => (p.node_type.gh_guids[0].as_str(), p.node_type.name.as_str()),
            };
            o.item("GUID", None, 9, guid);
            o.item("Name", None, 10, name);
            2
        },
        |o| {
            o.chunk_start("Container", None);
            if is_param(p.node_type) {
                let port = &p.inputs[0];
                let srcs = sources.get(&(id.clone(), port.nickname.clone()));
                let nickname = p.nickname.as_deref().unwrap_or(id);
                let (xml, n, persistent) =
                    param_items(p, port, &object_guid(id), nickname, srcs, warnings);
                items_and_chunks(
                    o,
                    |o| {
                        o.w.get_mut().extend_from_slice(&xml);
                        n
                    },
                    |o| {
                        attributes(o, pos);
                        if let Some(f) = persistent {
                            f(o);
                            2
                        } else {
                            1
                        }
                    },
                );
            } else {
                let variable = p.node_type.variable_inputs.is_some()
                    || p.node_type.variable_outputs.is_some()
                    || p.cluster.is_some();
                items_and_chunks(
                    o,
                    |o| {
                        let mut n = 0;
                        if let Some((_, lit)) =
                            p.node.settings.iter().find(|(k, _)| k == "expression")
                            && let Ok(tree) = parse_literal(&lit.0, DataType::Text)
                            && let Some(Some(Value::Text(t))) = tree.values().next()
                        {
                            o.item("Expression", None, 10, &t);
                            n += 1;
                        }
                        if p.node_type.id == script::PYTHON {
                            o.item("CodeInput", None, 10, &script::code(p.node));
                            n += 1;
                        }
                        if let Some(c) = &p.cluster {
                            o.bytes_item("ClusterDocument", &c.document);
                            n += 1;
                        }
                        o.item("InstanceGuid", None, 9, &object_guid(id));
                        o.item("Name", None, 10, &p.node_type.name);
                        o.item("NickName", None, 10, id);
                        n += 3;
                        if p.node.disabled {
                            o.item("Locked", None, 1, "true");
                            n += 1;
                        }
                        n
                    },
                    |o| {
                        attributes(o, pos);
                        let mut chunks = 1;
                        if let Some(c) = &p.cluster {
                            cluster::write_param_map(o, &c.map);
                            chunks += 1;
                        }
                        if p.node_type.id == "display.gradient" {
                            chunks += gradient::write(o, p.node, warnings);
                        }
                        let write_ports =
                            |o: &mut Out,
                             in_name: &str,
                             out_name: &str,
                             warnings: &mut Vec<ExportWarning>| {
                                for (k, port) in p.inputs.iter().enumerate() {
                                    o.chunk_start(in_name, Some(k));
                                    let srcs = sources.get(&(id.clone(), port.nickname.clone()));
                                    let guid = input_guid(id, &port.nickname);
                                    let (xml, n, persistent) =
                                        param_items(p, port, &guid, &port.nickname, srcs, warnings);
                                    items_and_chunks(
                                        o,
                                        |o| {
                                            o.w.get_mut().extend_from_slice(&xml);
                                            let mut n = n;
                                            if p.node_type.id == script::PYTHON {
                                                let (access, hint) =
                                                    script::input_items(p.node, &port.nickname);
                                                o.item("ScriptParamAccess", None, 3, &access);
                                                o.item("TypeHintID", None, 9, hint);
                                                n += 2;
                                            }
                                            n
                                        },
                                        |o| {
                                            if let Some(f) = persistent {
                                                f(o);
                                                1
                                            } else {
                                                0
                                            }
                                        },
                                    );
                                    o.end("chunk");
                                }
                                for (k, port) in p.outputs.iter().enumerate() {
                                    o.chunk_start(out_name, Some(k));
                                    items_and_chunks(
                                        o,
                                        |o| {
                                            o.item(
                                                "InstanceGuid",
                                                None,
                                                9,
                                                &output_guid(id, &port.nickname),
                                            );
                                            o.item("Name", None, 10, &port.name);
                                            o.item("NickName", None, 10, &port.nickname);
                                            let modifiers = p
                                                .node
                                                .output_modifiers
                                                .iter()
                                                .find(|(k, _)| port.is_named(k))
                                                .map_or(&[][..], |(_, m)| m.as_slice());
                                            let n = write_modifiers(o, modifiers);
                                            o.item("SourceCount", None, 3, "0");
                                            4 + n
                                        },
                                        |_| 0,
                                    );
                                    o.end("chunk");
                                }
                            };
                        if variable {
                            o.chunk_start("ParameterData", None);
                            items_and_chunks(
                                o,
                                |o| {
                                    o.item("InputCount", None, 3, &p.inputs.len().to_string());
                                    for (k, id) in p.param_ids.0.iter().enumerate() {
                                        o.item("InputId", Some(k), 9, id);
                                    }
                                    o.item("OutputCount", None, 3, &p.outputs.len().to_string());
                                    for (k, id) in p.param_ids.1.iter().enumerate() {
                                        o.item("OutputId", Some(k), 9, id);
                                    }
                                    2 + p.param_ids.0.len() + p.param_ids.1.len()
                                },
                                |o| {
                                    write_ports(o, "InputParam", "OutputParam", warnings);
                                    p.inputs.len() + p.outputs.len()
                                },
                            );
                            o.end("chunk");
                            chunks += 1;
                        } else {
                            write_ports(o, "param_input", "param_output", warnings);
                            chunks += p.inputs.len() + p.outputs.len();
                        }
                        chunks
                    },
                );
            }
            o.end("chunk");
            1
        },
    );
    o.end("chunk");
}

/// Grasshopper's Generic Data parameter type (`Param_GenericObject`).
const GENERIC_PARAM: &str = "8ec86459-bf01-4409-baee-174d0d2b13d0";
/// The variable parameter type of the Expression and Evaluate components.
const EXPRESSION_VARIABLE_PARAM: &str = "ba80fd98-91a1-4958-b6a7-a94e40e52bdb";
/// The type of Evaluate's formula input `F`.
const EVALUATE_FORMULA_PARAM: &str = "bc6c097c-6cc2-479c-b5aa-af99fbb72b88";
/// The type of a script component's inputs (`Param_ScriptVariable`).
const SCRIPT_VARIABLE_PARAM: &str = "84fa917c-1ed8-4db3-8be1-7bdc4a6495a2";
/// Grasshopper's Text parameter type (`Param_String`).
const TEXT_PARAM: &str = "3ede854e-c753-40eb-84cb-b48008f14fd4";

/// The parameter types of a component's ports as Grasshopper records them in `ParameterData`
/// (`InputId` / `OutputId`), from which it rebuilds a variable-parameter component's ports when
/// it opens the file: the Expression's, Evaluate's and script components' own types (as the
/// corpus's files hold them), else the floating parameter of the port's data type (Number
/// 3e8ca6be-…, Integer, Text, Point…), else Generic Data.
pub(super) fn param_type_ids(
    registry: &NodeRegistry,
    node_type: &NodeType,
    inputs: &[locus_runtime::Port],
    outputs: &[locus_runtime::Port],
) -> (Vec<String>, Vec<String>) {
    let by_type = |t: DataType| -> String {
        if t == DataType::Generic {
            return GENERIC_PARAM.to_owned();
        }
        registry
            .iter()
            .filter(|n| n.id.starts_with("params.") && n.name == t.name())
            .find(|n| n.outputs.len() == 1 && n.outputs[0].data_type == t)
            .and_then(|n| n.gh_guids.first().cloned())
            .unwrap_or_else(|| GENERIC_PARAM.to_owned())
    };
    let ins = inputs
        .iter()
        .enumerate()
        .map(|(k, p)| match node_type.id.as_str() {
            "maths.expression" => EXPRESSION_VARIABLE_PARAM.to_owned(),
            "maths.evaluate" if k == 0 => EVALUATE_FORMULA_PARAM.to_owned(),
            "maths.evaluate" => EXPRESSION_VARIABLE_PARAM.to_owned(),
            script::PYTHON => SCRIPT_VARIABLE_PARAM.to_owned(),
            _ => by_type(p.data_type),
        })
        .collect();
    let outs = outputs
        .iter()
        .map(|p| match node_type.id.as_str() {
            "maths.expression" | "maths.evaluate" => GENERIC_PARAM.to_owned(),
            script::PYTHON if p.nickname == "out" => TEXT_PARAM.to_owned(),
            script::PYTHON => GENERIC_PARAM.to_owned(),
            _ => by_type(p.data_type),
        })
        .collect();
    (ins, outs)
}

type ChunkWriter<'a> = Box<dyn FnOnce(&mut Out) + 'a>;

/// The items of one parameter (floating or a component's port), and its persistent data
/// chunk when it has a value.
fn param_items<'a>(
    p: &Ports<'_>,
    port: &locus_runtime::Port,
    guid: &str,
    nickname: &str,
    srcs: Option<&Vec<String>>,
    warnings: &mut Vec<ExportWarning>,
) -> (Vec<u8>, usize, Option<ChunkWriter<'a>>) {
    let mut buffer = Out {
        w: Writer::new_with_indent(Vec::new(), b' ', 2),
    };
    let o = &mut buffer;
    let mut n = 0;
    o.item("InstanceGuid", None, 9, guid);
    o.item("Name", None, 10, &port.name);
    o.item("NickName", None, 10, nickname);
    n += 3;
    if p.node_type.id == POINT_ON_CURVE {
        let x = p
            .node
            .settings
            .iter()
            .find(|(k, _)| k == "parameter")
            .and_then(|(_, lit)| lit.parse_value(DataType::Number).ok())
            .and_then(|v| match v {
                Value::Number(x) => Some(x),
                _ => None,
            })
            .unwrap_or(0.5);
        o.item("parameter", None, 6, &num(x));
        n += 1;
    }
    if p.node.disabled && is_param(p.node_type) {
        o.item("Locked", None, 1, "true");
        n += 1;
    }
    let mut modifiers = p
        .node
        .modifiers
        .iter()
        .find(|(k, _)| port.is_named(k))
        .map(|(_, m)| m.clone())
        .unwrap_or_default();
    if is_param(p.node_type)
        && let Some((_, output)) = p.node.output_modifiers.iter().find(|(_, m)| !m.is_empty())
    {
        // A floating parameter has one set of modifiers; on a parameter that passes its data
        // through, output modifiers do what the same input modifiers do.
        if modifiers.is_empty() {
            modifiers.clone_from(output);
        } else {
            warnings.push(ExportWarning(format!(
                "node \"{}\": a floating parameter keeps one set of modifiers; its output \
                 modifiers are not written",
                p.node.id
            )));
        }
    }
    if modifiers.contains(&Modifier::Principal) {
        warnings.push(ExportWarning(format!(
            "node \"{}\" input {}: the principal modifier is not written",
            p.node.id, port.nickname
        )));
    }
    n += write_modifiers(o, &modifiers);
    let srcs = srcs.cloned().unwrap_or_default();
    for (k, s) in srcs.iter().enumerate() {
        o.item("Source", Some(k), 9, s);
    }
    o.item("SourceCount", None, 3, &srcs.len().to_string());
    n += srcs.len() + 1;
    let value = p.node.values.iter().find(|(k, _)| port.is_named(k));
    let persistent: Option<ChunkWriter<'a>> = match value {
        Some((_, lit)) if srcs.is_empty() => match parse_literal(&lit.0, port.data_type) {
            Ok(tree) => {
                let mut branches = Vec::new();
                for (path, branch) in tree.branches() {
                    let mut items = Vec::new();
                    for v in branch.values().flatten() {
                        match item_xml(&v) {
                            Some(Ok(x)) => items.push(x),
                            Some(Err(e)) => warnings.push(ExportWarning(format!(
                                "node \"{}\" input {}: a {} value is not written: {e}",
                                p.node.id,
                                port.nickname,
                                v.data_type().name()
                            ))),
                            None => warnings.push(ExportWarning(format!(
                                "node \"{}\" input {}: a {} value is not written",
                                p.node.id,
                                port.nickname,
                                v.data_type().name()
                            ))),
                        }
                    }
                    branches.push((path.to_string(), items));
                }
                Some(Box::new(move |o: &mut Out| write_persistent(o, &branches)))
            }
            Err(e) => {
                warnings.push(ExportWarning(format!(
                    "node \"{}\" input {}: the value does not read: {e}",
                    p.node.id, port.nickname
                )));
                None
            }
        },
        _ => None,
    };
    (buffer.w.into_inner(), n, persistent)
}

/// The items of a parameter's modifiers (`Mapping`, `SimplifyData`, …), as Grasshopper stores
/// them on inputs and outputs alike; returns how many were written. Principal has no item.
fn write_modifiers(o: &mut Out, modifiers: &[Modifier]) -> usize {
    let mut n = 0;
    for m in modifiers {
        match m {
            Modifier::Flatten => o.item("Mapping", None, 3, "1"),
            Modifier::Graft => o.item("Mapping", None, 3, "2"),
            Modifier::Simplify => o.item("SimplifyData", None, 1, "true"),
            Modifier::Reverse => o.item("ReverseData", None, 1, "true"),
            Modifier::Invert => o.item("InvertBooleans", None, 1, "true"),
            Modifier::Degrees => o.item("UseDegrees", None, 1, "true"),
            Modifier::Reparameterize => o.item("Reparameterize", None, 1, "true"),
            Modifier::Principal => continue,
        }
        n += 1;
    }
    n
}

/// One persistent item: its item name, type code and parts (or text).
type ItemXml = (
    &'static str,
    u32,
    Vec<(&'static str, String)>,
    Option<String>,
);

/// The persistent-data item of one value; geometry is internalised as `ON_Data` (its base64
/// text, type code 20).
fn item_xml(v: &Value) -> Option<Result<ItemXml, String>> {
    if let Some(bytes) = crate::internalised::encode_base64(v) {
        return Some(bytes.map(|b| ("ON_Data", 20, vec![], Some(b))));
    }
    Some(Ok(match v {
        Value::Number(x) => ("number", 6, vec![], Some(num(*x))),
        Value::Integer(i) => ("number", 3, vec![], Some(i.to_string())),
        Value::Boolean(b) => ("boolean", 1, vec![], Some(b.to_string())),
        Value::Text(t) => ("string", 10, vec![], Some(t.clone())),
        Value::Point(p) => (
            "Coordinate",
            51,
            vec![("X", num(p.x)), ("Y", num(p.y)), ("Z", num(p.z))],
            None,
        ),
        Value::Vector(p) => (
            "vector",
            51,
            vec![("X", num(p.x)), ("Y", num(p.y)), ("Z", num(p.z))],
            None,
        ),
        Value::Domain(d) => (
            "Interval",
            60,
            vec![("A", num(d.t0)), ("B", num(d.t1))],
            None,
        ),
        Value::Plane(pl) => (
            "plane",
            72,
            vec![
                ("Ox", num(pl.origin.x)),
                ("Oy", num(pl.origin.y)),
                ("Oz", num(pl.origin.z)),
                ("Xx", num(pl.x_axis.x)),
                ("Xy", num(pl.x_axis.y)),
                ("Xz", num(pl.x_axis.z)),
                ("Yx", num(pl.y_axis.x)),
                ("Yy", num(pl.y_axis.y)),
                ("Yz", num(pl.y_axis.z)),
            ],
            None,
        ),
        _ => return None,
    }))
}

fn write_persistent(o: &mut Out, branches: &[(String, Vec<ItemXml>)]) {
    o.chunk_start("PersistentData", None);
    items_and_chunks(
        o,
        |o| {
            o.item("Count", None, 3, &branches.len().to_string());
            1
        },
        |o| {
            for (b, (path, items)) in branches.iter().enumerate() {
                o.chunk_start("Branch", Some(b));
                items_and_chunks(
                    o,
                    |o| {
                        o.item("Count", None, 3, &items.len().to_string());
                        o.item("Path", None, 10, path);
                        2
                    },
                    |o| {
                        for (k, (name, code, parts, text)) in items.iter().enumerate() {
                            o.chunk_start("Item", Some(k));
                            items_and_chunks(
                                o,
                                |o| match text {
                                    // Internalised geometry: its bytes, and the nil
                                    // document reference Grasshopper writes beside them.
                                    Some(t) if *code == 20 => {
                                        o.bytes_item(name, t);
                                        o.item("RefID", None, 9, NIL_GUID);
                                        2
                                    }
                                    Some(t) => {
                                        o.item(name, None, *code, t);
                                        1
                                    }
                                    None => {
                                        o.item_parts(name, *code, parts);
                                        1
                                    }
                                },
                                |_| 0,
                            );
                            o.end("chunk");
                        }
                        items.len()
                    },
                );
                o.end("chunk");
            }
            branches.len()
        },
    );
    o.end("chunk");
}
