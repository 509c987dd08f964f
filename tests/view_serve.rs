//! `locus view --serve`: the page is served on loopback, numbered by generation, evaluated again
//! when the graph file changes (a broken file gives a page that lists the problems and stays
//! live), and the server stops cleanly.

use std::io::{BufRead as _, BufReader, Read as _, Write as _};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// How long the test waits for the server to notice a change (it polls every 250 ms).
const CHANGE_DEADLINE: Duration = Duration::from_secs(30);

fn points_graph(points: &[(i32, i32)]) -> String {
    let list: Vec<String> = points
        .iter()
        .map(|(x, y)| format!("({x}, {y}, 0)"))
        .collect();
    format!(
        "(\n    format: 1,\n    name: \"live\",\n    nodes: [\n        (id: \"p\", type: \"params.point\", values: {{\"Pt\": [{}]}}),\n    ],\n    wires: [],\n    outputs: {{\"P\": \"p.Pt\"}},\n)\n",
        list.join(", ")
    )
}

/// The status and body of `GET path` (parsed with httparse).
fn get(addr: &str, path: &str) -> (u16, String) {
    let mut stream = TcpStream::connect(addr).expect("the server accepts");
    stream
        .set_read_timeout(Some(Duration::from_secs(30)))
        .unwrap();
    write!(
        stream,
        "GET {path} HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut raw = Vec::new();
    stream.read_to_end(&mut raw).expect("a whole answer");
    let mut headers = [httparse::EMPTY_HEADER; 32];
    let mut response = httparse::Response::new(&mut headers);
    let httparse::Status::Complete(head) = response.parse(&raw).expect("an HTTP answer") else {
        panic!("a truncated answer");
    };
    let cache = response
        .headers
        .iter()
        .find(|h| h.name.eq_ignore_ascii_case("cache-control"))
        .map(|h| String::from_utf8_lossy(h.value).into_owned());
    assert_eq!(cache.as_deref(), Some("no-store"), "{path} is never cached");
    (
        response.code.expect("a status"),
        String::from_utf8_lossy(&raw[head..]).into_owned(),
    )
}

struct Served {
    child: Child,
    addr: String,
}

impl Drop for Served {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

fn serve(graph: &Path) -> Served {
    let mut child = Command::new(env!("CARGO_BIN_EXE_locus"))
        .args(["view", "--serve", "--port", "0", "--quiet"])
        .arg(graph)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("locus runs");
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .expect("the address is printed");
    let addr = line
        .trim()
        .strip_prefix("http://")
        .and_then(|a| a.strip_suffix('/'))
        .unwrap_or_else(|| panic!("an address, got {line:?}"))
        .to_owned();
    assert!(addr.starts_with("127.0.0.1:"), "loopback only: {addr}");
    Served { child, addr }
}

fn generation(addr: &str) -> u64 {
    let (status, body) = get(addr, "/generation");
    assert_eq!(status, 200);
    body.trim().parse().expect("a number")
}

fn wait_for_generation(addr: &str, after: u64) -> u64 {
    let start = Instant::now();
    loop {
        let g = generation(addr);
        if g > after {
            return g;
        }
        assert!(
            start.elapsed() < CHANGE_DEADLINE,
            "the change was not noticed"
        );
        std::thread::sleep(Duration::from_millis(100));
    }
}

fn temp_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("locus-view-serve-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn the_page_follows_the_graph_file() {
    let graph = temp_dir().join("live.ron");
    std::fs::write(&graph, points_graph(&[(0, 0), (1, 0)])).unwrap();
    let served = serve(&graph);
    let addr = served.addr.as_str();

    assert_eq!(generation(addr), 1);
    let (status, page) = get(addr, "/");
    assert_eq!(status, 200);
    assert!(page.contains("\"live\":{\"generation\":1}"), "a live page");
    assert!(page.contains("<title>live — locus</title>"));
    assert!(page.contains("\"messages\":[]"));

    // A broken file: the page lists the problem, with file, line and column.
    std::fs::write(&graph, "(format: 1, nodes: [").unwrap();
    let g = wait_for_generation(addr, 1);
    let (_, page) = get(addr, "/");
    assert!(page.contains(&format!("\"live\":{{\"generation\":{g}}}")));
    assert!(
        page.contains("\"level\":\"error\""),
        "the problem is listed"
    );
    assert!(page.contains("live.ron:1:"), "with its place in the file");

    // Fixed, with a third point: the scene is back.
    std::fs::write(&graph, points_graph(&[(0, 0), (1, 0), (2, 0)])).unwrap();
    let fixed = wait_for_generation(addr, g);
    let (_, page) = get(addr, "/");
    assert!(page.contains(&format!("\"live\":{{\"generation\":{fixed}}}")));
    assert!(page.contains("\"messages\":[]"), "no problems any more");

    // Unknown paths are not found; the server still answers afterwards.
    let mut stream = TcpStream::connect(addr).unwrap();
    write!(
        stream,
        "GET /nothing HTTP/1.1\r\nHost: {addr}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    let mut answer = String::new();
    stream.read_to_string(&mut answer).unwrap();
    assert!(answer.starts_with("HTTP/1.1 404"), "{answer}");
    assert_eq!(generation(addr), fixed, "nothing changed meanwhile");
}

#[test]
fn a_missing_file_or_a_taken_port_is_refused() {
    let o = Command::new(env!("CARGO_BIN_EXE_locus"))
        .args(["view", "--serve", "--port", "0", "-o", "x.html", "g.ron"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "--serve writes no file");

    let graph = temp_dir().join("taken.ron");
    std::fs::write(&graph, points_graph(&[(0, 0)])).unwrap();
    let first = serve(&graph);
    let port = first.addr.rsplit(':').next().unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_locus"))
        .args(["view", "--serve", "--quiet", "--port", port])
        .arg(&graph)
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains(&format!("cannot serve on 127.0.0.1:{port}")),
        "{err}"
    );
}
