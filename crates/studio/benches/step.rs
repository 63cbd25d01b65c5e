//! Step round trips of the studio on master + 5 FAMs (`examples/fam/fam_system5.sc`): one
//! session over a loopback WebSocket, a request of one tick, its full reply (active states,
//! values, coverage) parsed; prints the median and p99. Also the time to serve the page and
//! its assets and to receive the model description. Run:
//! `cargo bench -p statecheck-studio --bench step`.

use futures_util::{SinkExt, StreamExt};
use serde_json::{json, Value};
use statecheck_studio::{spawn, Config};
use std::io::{Read, Write};
use std::time::{Duration, Instant};
use tokio_tungstenite::tungstenite::Message;

const STEPS: usize = 2000;

fn http_get(addr: std::net::SocketAddr, path: &str) -> usize {
    let mut s = std::net::TcpStream::connect(addr).expect("connect");
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{}\r\nConnection: close\r\n\r\n",
        addr.port()
    )
    .expect("write");
    let mut out = Vec::new();
    s.read_to_end(&mut out).expect("read");
    out.len()
}

fn pct(sorted: &[Duration], p: f64) -> f64 {
    let k = ((sorted.len() as f64 - 1.0) * p).round() as usize;
    sorted[k].as_secs_f64() * 1e3
}

fn main() {
    let model = format!(
        "{}/../../examples/fam/fam_system5.sc",
        env!("CARGO_MANIFEST_DIR")
    );
    let h = spawn(Config {
        path: model,
        system: None,
        bind: "127.0.0.1".parse().expect("address"),
        port: 0,
        token: Some("bench".into()),
        lib: Vec::new(),
    })
    .expect("server");
    let addr = h.addr;
    let t = Instant::now();
    let mut bytes = 0;
    for p in [
        "/?token=bench",
        "/style.css",
        "/elk.js",
        "/chart.js",
        "/wave.js",
        "/app.js",
    ] {
        bytes += http_get(addr, p);
    }
    println!(
        "page and assets: {bytes} bytes served in {:.1} ms",
        t.elapsed().as_secs_f64() * 1e3
    );
    let rt = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()
        .expect("runtime");
    rt.block_on(async move {
        let t = Instant::now();
        let url = format!("ws://127.0.0.1:{}/ws?token=bench", addr.port());
        let (mut ws, _) = tokio_tungstenite::connect_async(url).await.expect("connect");
        let mut first = None;
        // The model description and the initial state.
        for _ in 0..2 {
            if let Some(Ok(Message::Text(m))) = ws.next().await {
                first.get_or_insert(m.len());
            }
        }
        println!(
            "session open (model description {} bytes + initial state): {:.1} ms",
            first.unwrap_or(0),
            t.elapsed().as_secs_f64() * 1e3
        );
        let mut times = Vec::with_capacity(STEPS);
        for k in 0..STEPS {
            let req = if k == 0 {
                json!({"op": "step", "n": 1, "set": {"env.ccmSel": 2}})
            } else if k % 50 == 0 {
                json!({"op": "back", "tick": (k / 2) as u64})
            } else {
                json!({"op": "step", "n": 1})
            };
            let t = Instant::now();
            ws.send(Message::text(req.to_string())).await.expect("send");
            let reply = loop {
                if let Some(Ok(Message::Text(m))) = ws.next().await {
                    break m;
                }
            };
            let v: Value = serde_json::from_str(reply.as_str()).expect("json");
            times.push(t.elapsed());
            assert_ne!(v["type"], "error", "{v}");
        }
        times.sort();
        println!(
            "step round trip on fam_system5 ({STEPS} requests): median {:.3} ms, p99 {:.3} ms, max {:.3} ms",
            pct(&times, 0.5),
            pct(&times, 0.99),
            pct(&times, 1.0)
        );
    });
    h.stop();
}
