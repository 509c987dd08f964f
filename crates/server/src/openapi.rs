//! The OpenAPI 3 description the server publishes at `/openapi.json` (for clients and fuzzers
//! such as schemathesis).

use serde_json::{Value as Json, json};

/// The OpenAPI document.
pub fn document() -> Json {
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
                "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ComputeRequest"}}}},
                "responses": with_errors(json!({"description": "outputs", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ComputeAnswer"}}}}))
            }},
            "/solve": {"post": {
                "summary": "the same as /grasshopper",
                "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ComputeRequest"}}}},
                "responses": with_errors(json!({"description": "outputs", "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ComputeAnswer"}}}}))
            }},
            "/io": {"post": {
                "summary": "describe a definition's inputs and outputs",
                "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/ComputeRequest"}}}},
                "responses": with_errors(json!({"description": "inputs and outputs", "content": {"application/json": {"schema": {"type": "object"}}}}))
            }},
            "/v1/run": {"post": {
                "summary": "run a graph with locus's JSON (docs/json-output.md)",
                "requestBody": {"required": true, "content": {"application/json": {"schema": {"$ref": "#/components/schemas/RunRequest"}}}},
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
