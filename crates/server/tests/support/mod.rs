//! What the server's integration tests share: a server on a free loopback port, raw HTTP
//! requests and readers of Compute answers.
#![allow(dead_code, reason = "each test file uses a part of these helpers")]

use std::io::{Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::path::PathBuf;
use std::time::Duration;

use base64::Engine as _;
use locus_runtime::NodeRegistry;
use locus_server::{Config, Server};
use serde_json::{Value as Json, json};

pub fn registry() -> NodeRegistry {
    let mut r = NodeRegistry::new();
    locus_nodes::register(&mut r);
    r
}

pub fn definitions() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/definitions")
}

pub fn text(name: &str) -> String {
    std::fs::read_to_string(definitions().join(name)).unwrap()
}

pub fn algo(name: &str) -> String {
    base64::engine::general_purpose::STANDARD.encode(text(name))
}

pub fn config() -> Config {
    Config {
        bind: "127.0.0.1:0".parse().unwrap(),
        workers: 2,
        definitions: Some(definitions()),
        ..Config::default()
    }
}

pub fn start(config: Config) -> Server {
    Server::start(config, registry()).unwrap()
}

pub struct Response {
    pub status: u16,
    pub headers: Vec<(String, String)>,
    pub body: Vec<u8>,
}

impl Response {
    pub fn json(&self) -> Json {
        serde_json::from_slice(&self.body)
            .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(&self.body)))
    }

    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(name))
            .map(|(_, v)| v.as_str())
    }

    /// The error body's kind and message, checking its shape and status.
    pub fn error(&self, status: u16) -> (String, String) {
        assert_eq!(
            self.status,
            status,
            "{}",
            String::from_utf8_lossy(&self.body)
        );
        let j = self.json();
        assert_eq!(j["error"]["status"], json!(status));
        (
            j["error"]["kind"].as_str().unwrap().to_owned(),
            j["error"]["message"].as_str().unwrap().to_owned(),
        )
    }
}

/// Sends raw bytes and reads the answer to the end (the request asks to close).
pub fn raw(addr: SocketAddr, bytes: &[u8]) -> Response {
    let mut s = TcpStream::connect(addr).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
    s.write_all(bytes).unwrap();
    let mut buf = Vec::new();
    let _ = s.read_to_end(&mut buf);
    let mut headers = [httparse::EMPTY_HEADER; 32];
    let mut r = httparse::Response::new(&mut headers);
    let n = match r.parse(&buf).unwrap() {
        httparse::Status::Complete(n) => n,
        httparse::Status::Partial => panic!("partial answer: {}", String::from_utf8_lossy(&buf)),
    };
    Response {
        status: r.code.unwrap(),
        headers: r
            .headers
            .iter()
            .map(|h| {
                (
                    h.name.to_owned(),
                    String::from_utf8_lossy(h.value).into_owned(),
                )
            })
            .collect(),
        body: buf[n..].to_vec(),
    }
}

pub fn send(addr: SocketAddr, method: &str, path: &str, headers: &[&str], body: &[u8]) -> Response {
    let mut req = format!(
        "{method} {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\nContent-Length: {}\r\n",
        body.len()
    );
    for h in headers {
        req.push_str(h);
        req.push_str("\r\n");
    }
    req.push_str("\r\n");
    let mut bytes = req.into_bytes();
    bytes.extend_from_slice(body);
    raw(addr, &bytes)
}

pub fn post(addr: SocketAddr, path: &str, body: &Json) -> Response {
    send(
        addr,
        "POST",
        path,
        &["Content-Type: application/json"],
        body.to_string().as_bytes(),
    )
}

pub fn item_data(answer: &Json, output: &str) -> Vec<(String, String)> {
    let v = answer["values"]
        .as_array()
        .unwrap()
        .iter()
        .find(|v| v["ParamName"] == output)
        .unwrap_or_else(|| panic!("no output {output}: {answer}"));
    v["InnerTree"]
        .as_object()
        .unwrap()
        .values()
        .flat_map(|b| b.as_array().unwrap().clone())
        .map(|i| {
            (
                i["type"].as_str().unwrap().to_owned(),
                i["data"].as_str().unwrap().to_owned(),
            )
        })
        .collect()
}
