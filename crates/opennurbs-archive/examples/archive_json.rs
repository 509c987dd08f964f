//! Encodes and decodes CommonObject JSON from the command line, for the rhino3dm end-to-end
//! tests (`crates/opennurbs-archive/e2e/`).
//!
//! Reads a JSON list of requests on standard input and writes the list of answers:
//! - `{"op": "encode", "geometry": DESCRIPTION}` → `{"encoded": COMMON_OBJECT_JSON}`
//! - `{"op": "decode", "encoded": COMMON_OBJECT_JSON}` → `{"geometry": DESCRIPTION}`
//!
//! A request that fails answers `{"error": "..."}`. DESCRIPTION is the plain form of
//! `tests/common/describe.rs`.

#[path = "../tests/common/describe.rs"]
mod describe;

use serde_json::{Value, json};

fn answer(req: &Value) -> Value {
    match req["op"].as_str() {
        Some("encode") => match describe::build(&req["geometry"]) {
            Ok(g) => match locus_opennurbs_archive::encode_json(&g) {
                Ok(enc) => json!({ "encoded": enc }),
                Err(e) => json!({ "error": e.to_string() }),
            },
            Err(e) => json!({ "error": e }),
        },
        Some("decode") => match locus_opennurbs_archive::decode_json(&req["encoded"]) {
            Ok(g) => json!({ "geometry": describe::describe(&g), "type": g.rhino_type_name() }),
            Err(e) => json!({ "error": e.to_string() }),
        },
        _ => json!({ "error": "op must be encode or decode" }),
    }
}

fn main() {
    let input: Value = match serde_json::from_reader(std::io::stdin().lock()) {
        Ok(v) => v,
        Err(e) => {
            eprintln!("archive_json: standard input is not JSON: {e}");
            std::process::exit(2);
        }
    };
    let answers: Vec<Value> = match &input {
        Value::Array(reqs) => reqs.iter().map(answer).collect(),
        one => vec![answer(one)],
    };
    println!("{}", Value::Array(answers));
}
