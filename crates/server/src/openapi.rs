//! The OpenAPI 3 description the server publishes at `/openapi.json` (for clients and fuzzers
//! such as schemathesis).

use base64::Engine as _;
use serde_json::{Value as Json, json};

/// A small graph the examples solve: `sum = x + 1`, so that a fuzzer that starts from the
/// examples reaches the solver with any server, whatever definitions it serves.
const EXAMPLE_GRAPH: &str = r#"(format: 1, nodes: [(id: "a", type: "maths.addition", values: {"B": 1})], inputs: {"x": "a.A"}, outputs: {"sum": "a.R"})"#;

/// The OpenAPI document.
pub fn document() -> Json {
    let algo = base64::engine::general_purpose::STANDARD.encode(EXAMPLE_GRAPH);
    let compute_example = json!({"algo": algo, "values": [
        {"ParamName": "x", "InnerTree": {"{0}": [{"type": "System.Double", "data": "2.5"}]}}]});
    let compute_body = json!({"required": true, "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/ComputeRequest"},
        "example": compute_example}}});
    let run_body = json!({"required": true, "content": {"application/json": {
        "schema": {"$ref": "#/components/schemas/RunRequest"},
        "example": {"graph": EXAMPLE_GRAPH, "inputs": {"x": [1.5, {"point": [1, 2, 3]}]}}}}});
    let error = json!({"description": "an error", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/Error"}}}});
    let errors = json!({
        "400": error, "401": error, "404": error, "413": error, "500": error, "503": error, "504": error,
    });
    let with_errors = |ok: Json| {
        let mut r = errors.clone();
        r["200"] = ok;
        r
    };
    json!({
        "openapi": "3.0.3",
        "info": {
            "title": "locus serve",
            "version": env!("CARGO_PKG_VERSION"),
            "description": "Rhino.Compute-compatible Grasshopper endpoints and locus's own /v1/run. See docs/server.md."
        },
        "paths": {
            "/healthcheck": {"get": {"responses": {"200": {"description": "Healthy", "content": {"text/plain": {"schema": {"type": "string"}}}}}}},
            "/version": {"get": {"responses": {"200": {"description": "versions", "content": {"application/json": {"schema": {"type": "object"}}}}}}},
            "/grasshopper": {"post": {
                "summary": "solve a definition (Rhino.Compute schema)",
                "requestBody": compute_body.clone(),
                "responses": with_errors(json!({"description": "outputs", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ComputeAnswer"}}}}))
            }},
            "/solve": {"post": {
                "summary": "the same as /grasshopper",
                "requestBody": compute_body.clone(),
                "responses": with_errors(json!({"description": "outputs", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ComputeAnswer"}}}}))
            }},
            "/io": {"post": {
                "summary": "describe a definition's inputs and outputs",
                "requestBody": compute_body.clone(),
                "responses": with_errors(json!({"description": "inputs and outputs", "content": {"application/json": {"schema": {"type": "object"}}}}))
            }},
            "/v1/run": {"post": {
                "summary": "run a graph with locus's JSON (docs/json-output.md)",
                "requestBody": run_body,
                "responses": with_errors(json!({"description": "outputs and messages", "content": {"application/json": {"schema": {"type": "object"}}}}))
            }}
        },
        "components": {"schemas": {
            "Error": {"type": "object", "required": ["error"], "properties": {"error": {"type": "object", "properties": {
                "status": {"type": "integer"}, "kind": {"type": "string"}, "message": {"type": "string"}}}}},
            "Item": {"type": "object", "properties": {"type": {"type": "string"}, "data": {}}},
            "Tree": {"type": "object", "properties": {
                "ParamName": {"type": "string"},
                "InnerTree": {"type": "object", "additionalProperties": {"type": "array", "items": {"$ref": "#/components/schemas/Item"}}}}},
            "ComputeRequest": {"type": "object", "properties": {
                "algo": {"type": "string", "description": "base64 of the definition"},
                "pointer": {"type": "string"},
                "values": {"type": "array", "items": {"$ref": "#/components/schemas/Tree"}},
                "absolutetolerance": {"type": "number"},
                "angletolerance": {"type": "number"},
                "modelunits": {"type": "string"},
                "dataversion": {"type": "integer"},
                "cachesolve": {"type": "boolean"},
                "recursionlevel": {"type": "integer"}}},
            "ComputeAnswer": {"type": "object", "properties": {
                "pointer": {"type": "string"},
                "values": {"type": "array", "items": {"$ref": "#/components/schemas/Tree"}},
                "errors": {"type": "array", "items": {"type": "string"}},
                "warnings": {"type": "array", "items": {"type": "string"}}}},
            "RunRequest": {"type": "object", "additionalProperties": false, "properties": {
                "graph": {"type": "string", "description": "RON text"},
                "algo": {"type": "string"},
                "pointer": {"type": "string"},
                "inputs": {"type": "object"},
                "literals": {"type": "object", "additionalProperties": {"type": "string"}}}}
        }}
    })
}
