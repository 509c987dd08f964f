//! A bounded loopback load test of a running `locus serve`.
//!
//! `cargo run --release -p locus-server --example loadtest -- URL PID SECONDS CLIENTS [MIX]`
//!
//! CLIENTS connections (HTTP/1.1 keep-alive) send requests for SECONDS. MIX is `mixed` (the
//! default: 80% good tangent-spheres solves with a random t, checked against the expected
//! point; 10% malformed JSON, expected 400; 10% over the item limit, expected 413 — start the
//! server with `--max-items 1000`) or `good` (good solves only). It prints throughput, p50/p99
//! latency of good requests and the server's RSS (from /proc/PID/status) before and after, and
//! exits 1 if any good request failed or the RSS grew by more than 64 MiB.

use std::time::{Duration, Instant};

use base64::Engine as _;
use http_body_util::{BodyExt as _, Full};
use hyper::body::Bytes;
use serde_json::{Value as Json, json};

const RSS_GROWTH_BOUND_KIB: u64 = 64 * 1024;

#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Good,
    Bad,
    Limit,
}

#[derive(Default)]
struct Tally {
    good_latencies: Vec<Duration>,
    good_failed: u64,
    bad_ok: u64,
    bad_wrong: u64,
    limit_ok: u64,
    limit_wrong: u64,
    connect_errors: u64,
}

fn rss_kib(pid: u32) -> u64 {
    std::fs::read_to_string(format!("/proc/{pid}/status"))
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("VmRSS:"))
                .and_then(|l| l.split_whitespace().nth(1).and_then(|n| n.parse().ok()))
        })
        .unwrap_or(0)
}

fn good_body(algo: &str, t: f64) -> String {
    json!({"algo": algo, "values": [{"ParamName": "t", "InnerTree": {"0": [{"data": t}]}}]})
        .to_string()
}

fn limit_body(algo: &str) -> String {
    let items: Vec<Json> = (0..1001)
        .map(|i| json!({"data": f64::from(i) / 1001.0}))
        .collect();
    json!({"algo": algo, "values": [{"ParamName": "t", "InnerTree": {"0": items}}]}).to_string()
}

fn check_good(body: &[u8], t: f64) -> bool {
    let Ok(a) = serde_json::from_slice::<Json>(body) else {
        return false;
    };
    let Some(d) = a["values"]
        .as_array()
        .and_then(|v| v.iter().find(|v| v["ParamName"] == "D"))
        .and_then(|v| v["InnerTree"]["{0}"][0]["data"].as_str())
        .and_then(|s| serde_json::from_str::<Json>(s).ok())
    else {
        return false;
    };
    let close = |k: &str, want: f64| d[k].as_f64().is_some_and(|x| (x - want).abs() < 1e-9);
    close("X", 8.0 * t) && close("Y", 6.0 * t) && close("Z", 0.0)
}

async fn client(addr: String, algo: String, until: Instant, seed: u64, mixed: bool) -> Tally {
    let mut tally = Tally::default();
    let mut rng = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    let limit = limit_body(&algo);
    let mut sender = None;
    let mut n = 0u64;
    while Instant::now() < until {
        if sender.is_none() {
            match tokio::net::TcpStream::connect(&addr).await {
                Ok(stream) => {
                    let io = hyper_util::rt::TokioIo::new(stream);
                    match hyper::client::conn::http1::handshake(io).await {
                        Ok((s, conn)) => {
                            tokio::spawn(conn);
                            sender = Some(s);
                        }
                        Err(_) => {
                            tally.connect_errors += 1;
                            continue;
                        }
                    }
                }
                Err(_) => {
                    tally.connect_errors += 1;
                    tokio::time::sleep(Duration::from_millis(10)).await;
                    continue;
                }
            }
        }
        let Some(s) = sender.as_mut() else { continue };
        n += 1;
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        let kind = match (mixed, n % 10) {
            (true, 3) => Kind::Bad,
            (true, 7) => Kind::Limit,
            _ => Kind::Good,
        };
        let t = (rng % 1000) as f64 / 1000.0;
        let body = match kind {
            Kind::Good => good_body(&algo, t),
            Kind::Bad => "{\"algo\": \"x\", \"values\": [".to_owned(),
            Kind::Limit => limit.clone(),
        };
        let req = hyper::Request::post("/grasshopper")
            .header("host", addr.as_str())
            .header("content-type", "application/json")
            .body(Full::new(Bytes::from(body)))
            .unwrap_or_else(|_| unreachable!("a valid request"));
        let start = Instant::now();
        let result = async {
            let res = s.send_request(req).await?;
            let status = res.status().as_u16();
            let bytes = res.into_body().collect().await?.to_bytes();
            Ok::<_, hyper::Error>((status, bytes))
        }
        .await;
        let elapsed = start.elapsed();
        match (kind, result) {
            (Kind::Good, Ok((200, b))) if check_good(&b, t) => tally.good_latencies.push(elapsed),
            (Kind::Good, _) => {
                tally.good_failed += 1;
                sender = None;
            }
            (Kind::Bad, Ok((400, _))) => tally.bad_ok += 1,
            (Kind::Limit, Ok((413, _))) => tally.limit_ok += 1,
            (Kind::Bad, _) => tally.bad_wrong += 1,
            (Kind::Limit, _) => tally.limit_wrong += 1,
        }
    }
    tally
}

fn main() -> std::process::ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 4 {
        eprintln!("usage: loadtest URL PID SECONDS CLIENTS [mixed|good]");
        return std::process::ExitCode::from(2);
    }
    let addr = args[0]
        .trim_start_matches("http://")
        .trim_end_matches('/')
        .to_owned();
    let pid: u32 = args[1].parse().unwrap_or(0);
    let seconds: f64 = args[2].parse().unwrap_or(5.0);
    let clients: u64 = args[3].parse().unwrap_or(8);
    let mixed = args.get(4).is_none_or(|m| m != "good");
    let graph = include_str!("../tests/definitions/tangent_spheres.ron");
    let algo = base64::engine::general_purpose::STANDARD.encode(graph);

    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .unwrap_or_else(|e| panic!("cannot start tokio: {e}"));
    let rss_before = rss_kib(pid);
    let start = Instant::now();
    let until = start + Duration::from_secs_f64(seconds);
    let tallies: Vec<Tally> = runtime.block_on(async {
        let tasks: Vec<_> = (0..clients)
            .map(|k| tokio::spawn(client(addr.clone(), algo.clone(), until, k + 1, mixed)))
            .collect();
        let mut out = Vec::new();
        for t in tasks {
            out.push(t.await.unwrap_or_default());
        }
        out
    });
    let elapsed = start.elapsed().as_secs_f64();
    let rss_after = rss_kib(pid);
    let mut all = Tally::default();
    for t in tallies {
        all.good_latencies.extend(t.good_latencies);
        all.good_failed += t.good_failed;
        all.bad_ok += t.bad_ok;
        all.bad_wrong += t.bad_wrong;
        all.limit_ok += t.limit_ok;
        all.limit_wrong += t.limit_wrong;
        all.connect_errors += t.connect_errors;
    }
    all.good_latencies.sort_unstable();
    let pct = |p: f64| {
        let l = &all.good_latencies;
        if l.is_empty() {
            return 0.0;
        }
        let i = ((l.len() as f64 - 1.0) * p).round() as usize;
        l[i].as_secs_f64() * 1000.0
    };
    let good = all.good_latencies.len() as u64;
    let total =
        good + all.good_failed + all.bad_ok + all.bad_wrong + all.limit_ok + all.limit_wrong;
    println!(
        "loadtest: {clients} clients, {elapsed:.1} s, {} mix: {total} requests, {:.0} req/s; \
         good {good} ({:.0}/s, p50 {:.2} ms, p99 {:.2} ms, failed {}); bad→400 {} (wrong {}); \
         limit→413 {} (wrong {}); connect errors {}; RSS {} KiB → {} KiB",
        if mixed { "mixed" } else { "good-only" },
        total as f64 / elapsed,
        good as f64 / elapsed,
        pct(0.5),
        pct(0.99),
        all.good_failed,
        all.bad_ok,
        all.bad_wrong,
        all.limit_ok,
        all.limit_wrong,
        all.connect_errors,
        rss_before,
        rss_after,
    );
    let grew = rss_after.saturating_sub(rss_before);
    if all.good_failed > 0 || all.bad_wrong > 0 || all.limit_wrong > 0 || good == 0 {
        eprintln!("loadtest: FAILED: requests did not get their expected answers");
        return std::process::ExitCode::from(1);
    }
    if pid != 0 && grew > RSS_GROWTH_BOUND_KIB {
        eprintln!("loadtest: FAILED: the server's RSS grew by {grew} KiB");
        return std::process::ExitCode::from(1);
    }
    std::process::ExitCode::SUCCESS
}
