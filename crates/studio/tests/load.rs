//! Load: 50 concurrent sessions on 127.0.0.1 stepping the FAM closed loop (bounded: 120
//! requests each), every reply checked against the same requests answered by one in-process
//! session; the server's resident memory is printed before and after. Not timed.

mod common;
use common::*;
use serde_json::{json, Value};
use statecheck_studio::{load, server::handle, session::Session};

const SESSIONS: usize = 50;
const REQUESTS: usize = 120;

/// Request `k` of every session: the CCM set to full opening, a stall pulsed now and then,
/// a step back every 40 requests.
fn request(k: usize) -> Value {
    match k {
        0 => json!({"op": "step", "n": 1, "set": {"ctrl.ccm": 1000}}),
        k if k % 40 == 39 => json!({"op": "back", "tick": (k / 2) as u64}),
        k if k % 17 == 0 => json!({"op": "step", "n": 1, "pulse": {"fam.stallNow": true}}),
        k if k % 25 == 0 => {
            json!({"op": "step", "n": 3, "set": {"ctrl.ccm": if k % 50 == 0 { 500 } else { 1000 }}})
        }
        _ => json!({"op": "step", "n": 1}),
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn fifty_sessions_step_the_closed_loop() {
    let model = repo("examples/fam/fam_system.sc");
    // The reference: the same requests answered without the network.
    let loaded = load::load(&model, None).expect("model checks");
    let mut one = Some(Session::new(loaded));
    let expected: Vec<Value> = (0..REQUESTS)
        .map(|k| {
            let mut r = handle(&mut one, &request(k).to_string());
            r["id"] = Value::Null;
            r
        })
        .collect();
    assert!(
        expected.iter().all(|r| r["type"] == "state"),
        "the reference run has no errors"
    );

    let h = start(&model);
    let rss0 = statecheck_studio::server::rss_bytes().unwrap_or(0);
    let expected = std::sync::Arc::new(expected);
    let mut tasks = Vec::new();
    for s in 0..SESSIONS {
        let expected = std::sync::Arc::clone(&expected);
        let (ws, _) = connect(&h).await;
        tasks.push(tokio::spawn(async move {
            let mut ws = ws;
            for (k, want) in expected.iter().enumerate() {
                let mut got = call(&mut ws, request(k)).await;
                got["id"] = Value::Null;
                assert_eq!(&got, want, "session {s}, request {k}");
            }
            expected.len()
        }));
    }
    let mut replies = 0;
    for t in tasks {
        replies += t.await.expect("session task");
    }
    let rss1 = statecheck_studio::server::rss_bytes().unwrap_or(0);
    assert_eq!(replies, SESSIONS * REQUESTS);
    println!(
        "{SESSIONS} sessions x {REQUESTS} requests: all {replies} replies correct; resident memory {:.1} MB before, {:.1} MB after (test process and server)",
        rss0 as f64 / 1e6,
        rss1 as f64 / 1e6
    );
    h.stop();
}
