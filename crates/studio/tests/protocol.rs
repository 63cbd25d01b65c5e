//! The WebSocket protocol of `statecheck serve`: stepping, inputs, time travel, scenarios,
//! and every kind of bad request (each answered with an error, the session kept).

mod common;
use common::*;
use futures_util::SinkExt;
use serde_json::{json, Value};
use tokio_tungstenite::tungstenite::Message;

const FAM: &str = "examples/fam/fam_system.sc";

/// The FAM's configuration before any input changes, read off the chart's `initial` lines
/// (fam.sc: stallHandler noStall, failureMonitor monitoring, failureHandler noFailure,
/// moveHandler stopped, calibHandler calibrated); regions are not listed, as in `sim --json`.
fn fam_initial() -> Value {
    json!([
        "stallHandler.noStall",
        "failureMonitor.monitoring",
        "failureHandler.noFailure",
        "moveHandler.stopped",
        "calibHandler.calibrated"
    ])
}

/// Ask the page's server to verify with `engine` and wait for the run's end: the
/// `verify_done` message, with every result.
async fn verify_on_the_page(ws: &mut Ws, engine: &str) -> Value {
    let started = call(ws, json!({"op": "verify", "engine": engine})).await;
    assert_eq!(started["type"], "verify_started", "{started}");
    loop {
        let m = next(ws).await;
        if m["type"] == "verify_done" {
            break m;
        }
    }
}

/// The result of property `name` in a `verify_done` message.
fn result_row(done: &Value, name: &str) -> Value {
    done["results"]
        .as_array()
        .expect("results")
        .iter()
        .find(|r| r["name"] == name)
        .cloned()
        .unwrap_or_else(|| panic!("no result for {name}: {done}"))
}

/// A model file `name` with `text` in a directory of its own, `tag` and the process's id.
fn temp_model(tag: &str, name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let model = dir.join(name);
    std::fs::write(&model, text).expect("write");
    model
}

fn sorted(v: &Value) -> Vec<String> {
    let mut x: Vec<String> = v
        .as_array()
        .expect("array")
        .iter()
        .map(|s| s.as_str().expect("string").to_string())
        .collect();
    x.sort();
    x
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn hello_describes_the_system_and_steps_run() {
    let h = start(&repo(FAM));
    let (mut ws, hello) = connect(&h).await;
    assert_eq!(hello["type"], "model");
    let m = &hello["model"];
    assert_eq!(m["system"], "FamSystem");
    let names: Vec<&str> = m["instances"]
        .as_array()
        .expect("instances")
        .iter()
        .map(|i| i["name"].as_str().expect("name"))
        .collect();
    // fam_system.sc: `instance tie; bus; port; fam; ctrl` in this order, then the observer
    // instance of the system's observer property `master_failure_sequence`.
    assert_eq!(
        names,
        [
            "tie",
            "bus",
            "port",
            "fam",
            "ctrl",
            "master_failure_sequence"
        ]
    );
    let ccm = m["inputs"]
        .as_array()
        .expect("inputs")
        .iter()
        .find(|i| i["name"] == "ctrl.ccm")
        .expect("ctrl.ccm is a free input");
    // `input ccm: int[0..1000] = 0;`
    assert_eq!(
        (ccm["lo"].as_i64(), ccm["hi"].as_i64(), &ccm["type"]),
        (Some(0), Some(1000), &json!("int"))
    );

    let r = step(&mut ws, 3, json!({"ctrl.ccm": 500}), json!({})).await;
    assert_eq!(r["type"], "state", "{r}");
    let ticks = r["ticks"].as_array().expect("ticks");
    assert_eq!(ticks.len(), 3);
    for (k, t) in ticks.iter().enumerate() {
        assert_eq!(t["tick"], k as u64);
    }
    assert_eq!(sorted(&ticks[0]["active"]["fam"]), sorted(&fam_initial()));
    assert_eq!(ticks[0]["vars"]["ctrl.ccm"], 500);
    assert_eq!(r["run"]["ticks"], 3);
    assert_eq!(r["held"]["ctrl.ccm"], 500);
    h.stop();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn back_and_forward_give_the_same_ticks() {
    let h = start(&repo(FAM));
    let (mut ws, _) = connect(&h).await;
    let first = step(&mut ws, 150, json!({"ctrl.ccm": 1000}), json!({})).await;
    assert_eq!(first["type"], "state", "{first}");
    let orig = first["ticks"].as_array().expect("ticks").clone();
    assert_eq!(orig.len(), 150);
    // Back past two snapshots (every 64 ticks) and forward again.
    let b = call(&mut ws, json!({"op": "back", "tick": 70})).await;
    assert_eq!(
        (
            b["run"]["ticks"].as_u64(),
            b["run"]["future"].as_u64(),
            b["truncate"].as_u64()
        ),
        (Some(70), Some(80), Some(70))
    );
    let f = call(&mut ws, json!({"op": "forward", "n": 80})).await;
    assert_eq!(f["ticks"].as_array().expect("ticks")[..], orig[70..]);
    assert_eq!(f["run"]["future"], 0);
    // Back to 0, then forward everything: the same run, coverage included.
    let cov = f["run"]["coverage"].clone();
    call(&mut ws, json!({"op": "back", "tick": 0})).await;
    let f2 = call(&mut ws, json!({"op": "forward", "n": 1000})).await;
    assert_eq!(f2["ticks"].as_array().expect("ticks")[..], orig[..]);
    assert_eq!(f2["run"]["coverage"], cov);
    // Branching: a new step after a back drops the undone ticks.
    call(&mut ws, json!({"op": "back", "tick": 10})).await;
    let s = step(&mut ws, 1, json!({}), json!({"fam.stallNow": true})).await;
    assert_eq!(
        (s["run"]["ticks"].as_u64(), s["run"]["future"].as_u64()),
        (Some(11), Some(0))
    );
    // `assume ctrl.ccm == 0 || ctrl.ccm == 500 || ctrl.ccm == 1000`: 300 is refused, nothing runs.
    let refused = step(&mut ws, 1, json!({"ctrl.ccm": 300}), json!({})).await;
    assert_eq!(refused["code"], "assume", "{refused}");
    // At most one fault per tick: two at once are refused.
    let two = step(
        &mut ws,
        1,
        json!({}),
        json!({"fam.stallNow": true, "bus.corrupt": true}),
    )
    .await;
    assert_eq!(two["code"], "assume", "{two}");
    let held = call(&mut ws, json!({"op": "set", "set": {}})).await;
    assert_eq!(
        (held["run"]["ticks"].as_u64(), &held["held"]["ctrl.ccm"]),
        (Some(11), &json!(1000))
    );
    let bad = call(&mut ws, json!({"op": "back", "tick": 12})).await;
    assert_eq!(bad["code"], "badtick");
    h.stop();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bad_requests_get_errors_and_the_session_goes_on() {
    let h = start(&repo(FAM));
    let (mut ws, _) = connect(&h).await;
    let cases: Vec<(String, &str)> = vec![
        ("not json".into(), "malformed"),
        ("{\"op\":\"fly\"}".into(), "malformed"),
        ("[1,2,3]".into(), "malformed"),
        (json!({"op": "step", "n": "many"}).to_string(), "malformed"),
        (json!({"op": "step", "n": -1}).to_string(), "malformed"),
        (json!({"op": "step", "extra": 1}).to_string(), "malformed"),
        (
            json!({"op": "step", "set": {"ctrl.nope": 1}}).to_string(),
            "bad_input",
        ),
        (
            json!({"op": "step", "set": {"ctrl.ccm": 1001}}).to_string(),
            "bad_input",
        ),
        (
            json!({"op": "step", "set": {"ctrl.ccm": -1}}).to_string(),
            "bad_input",
        ),
        (
            json!({"op": "step", "set": {"ctrl.ccm": true}}).to_string(),
            "bad_input",
        ),
        (
            json!({"op": "step", "set": {"ctrl.ccm": 1.5}}).to_string(),
            "bad_input",
        ),
        (
            json!({"op": "step", "pulse": {"fam.stallNow": 1}}).to_string(),
            "bad_input",
        ),
        // An output is not an input the page may set.
        (
            json!({"op": "set", "set": {"fam.run": true}}).to_string(),
            "bad_input",
        ),
        (
            json!({"op": "load_scenario", "text": "fam.nope = 3\n"}).to_string(),
            "badscenario",
        ),
        (
            json!({"op": "load_scenario", "text": "- * 999999999\n"}).to_string(),
            "badscenario",
        ),
    ];
    for (text, code) in &cases {
        ws.send(Message::text(text.clone())).await.expect("send");
        let r = next(&mut ws).await;
        assert_eq!(r["type"], "error", "{text} -> {r}");
        assert_eq!(r["code"], *code, "{text} -> {r}");
    }
    // 10 MB in one frame: refused with an error, the session kept.
    let big = format!(
        "{{\"op\":\"load_scenario\",\"text\":\"{}\"}}",
        "x".repeat(10 << 20)
    );
    ws.send(Message::text(big)).await.expect("send");
    let r = next(&mut ws).await;
    assert_eq!(
        (r["type"].as_str(), r["code"].as_str()),
        (Some("error"), Some("too_large"))
    );
    // A binary frame.
    ws.send(Message::binary(vec![1u8, 2, 3]))
        .await
        .expect("send");
    assert_eq!(next(&mut ws).await["code"], "malformed");
    // Still alive, nothing ran.
    let r = step(&mut ws, 2, json!({}), json!({})).await;
    assert_eq!(r["run"]["ticks"], 2, "{r}");
    h.stop();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn other_origins_hosts_and_tokens_are_refused() {
    let h = start(&repo(FAM));
    let port = h.addr.port();
    let own = format!("http://127.0.0.1:{port}");
    assert!(connect_with(&h, TOKEN, Some("http://evil.example"), None)
        .await
        .is_err());
    assert!(connect_with(
        &h,
        TOKEN,
        Some(&format!("http://127.0.0.1:{}", port + 1)),
        None
    )
    .await
    .is_err());
    assert!(connect_with(&h, "wrong", Some(&own), None).await.is_err());
    assert!(connect_with(&h, "", Some(&own), None).await.is_err());
    assert!(
        connect_with(&h, TOKEN, Some(&own), Some(&format!("evil.example:{port}")))
            .await
            .is_err()
    );
    assert!(connect_with(
        &h,
        TOKEN,
        Some(&format!("http://localhost:{port}")),
        Some(&format!("localhost:{port}"))
    )
    .await
    .is_ok());
    // The page itself needs the token and a known Host.
    let get = |path: &str, host: &str| {
        let mut s = std::net::TcpStream::connect(h.addr).expect("connect");
        use std::io::{Read, Write};
        write!(
            s,
            "GET {path} HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n"
        )
        .expect("write");
        let mut out = String::new();
        s.read_to_string(&mut out).expect("read");
        out.lines().next().unwrap_or("").to_string()
    };
    let host = format!("127.0.0.1:{port}");
    assert!(get(&format!("/?token={TOKEN}"), &host).contains("200"));
    assert!(get("/?token=nope", &host).contains("403"));
    assert!(get("/", &host).contains("403"));
    assert!(get(&format!("/?token={TOKEN}"), "attacker.example").contains("403"));
    assert!(get("/elk.js", &host).contains("200"));
    // Still serving.
    let (mut ws, _) = connect(&h).await;
    assert_eq!(
        step(&mut ws, 1, json!({}), json!({})).await["run"]["ticks"],
        1
    );
    h.stop();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_scenario_saved_loads_back_to_the_same_run() {
    let h = start(&repo(FAM));
    let (mut ws, _) = connect(&h).await;
    let a = step(&mut ws, 40, json!({"ctrl.ccm": 1000}), json!({})).await;
    let b = step(&mut ws, 5, json!({}), json!({"fam.stallNow": true})).await;
    let c = step(&mut ws, 30, json!({"ctrl.ccm": 500}), json!({})).await;
    let mut all: Vec<Value> = Vec::new();
    for r in [&a, &b, &c] {
        all.extend(r["ticks"].as_array().expect("ticks").iter().cloned());
    }
    let saved = call(&mut ws, json!({"op": "save"})).await;
    assert_eq!(saved["type"], "scenario");
    let text = saved["text"].as_str().expect("text").to_string();
    let (mut ws2, _) = connect(&h).await;
    let l = call(&mut ws2, json!({"op": "load_scenario", "text": text})).await;
    assert_eq!(l["ticks"].as_array().expect("ticks")[..], all[..]);
    h.stop();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_counterexample_stops_at_its_violating_tick() {
    // examples/fam/scenarios/cof_with_notcalib.scn drives fam_alone.sc's FAM into the state
    // the thesis's `fam_cof_with_notcalib` forbids; sim stops at the violating tick.
    let dir = std::env::temp_dir().join(format!("studio-cex-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    // A one-chart model with an invariant that fails when `n` reaches 3. By hand: tick 0
    // enters A (no `during` in the entering tick), so n is 0, 1, 2, 3 after ticks 0..3 and
    // tick 3 violates; sim stops there with the violating tick in the trace (4 records).
    let model = dir.join("count.sc");
    std::fs::write(
        &model,
        "chart C {\n  input go: bool = false;\n  output n: int[0..9] = 0;\n  initial A;\n  state A { during { if go { n = min(9, n + 1); } } }\n  invariant small: n < 3;\n}\n",
    )
    .expect("write");
    let h = start(model.to_str().expect("path"));
    let (mut ws, hello) = connect(&h).await;
    assert_eq!(hello["type"], "model", "{hello}");
    let l = call(
        &mut ws,
        json!({"op": "load_scenario", "text": "go = true * 5\n"}),
    )
    .await;
    let stop = &l["run"]["stop"];
    assert_eq!(
        (stop["status"].as_str(), stop["tick"].as_u64()),
        (Some("violated"), Some(3)),
        "{l}"
    );
    assert_eq!(stop["message"], "property `small` violated at tick 3");
    assert_eq!(l["ticks"].as_array().expect("ticks").len(), 4);
    // The run is over until a step back.
    assert_eq!(
        step(&mut ws, 1, json!({}), json!({})).await["code"],
        "stopped"
    );
    let b = call(&mut ws, json!({"op": "back", "tick": 3})).await;
    assert!(b["run"]["stop"].is_null());
    let s = step(&mut ws, 1, json!({"C.go": false}), json!({})).await;
    assert_eq!(s["ticks"][0]["vars"]["C.n"], 2, "{s}");
    h.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_page_reloads_and_shows_diagnostics() {
    let dir = std::env::temp_dir().join(format!("studio-reload-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let model = dir.join("m.sc");
    let good = "chart C {\n  input go: bool = false;\n  initial A;\n  state A { on [go] -> B; }\n  state B { }\n}\n";
    std::fs::write(&model, good).expect("write");
    let h = start(model.to_str().expect("path"));
    let (mut ws, hello) = connect(&h).await;
    assert_eq!(hello["type"], "model");
    // Line 4 refers to a state that does not exist.
    std::fs::write(&model, good.replace("-> B;", "-> Nowhere;")).expect("write");
    let d = next(&mut ws).await;
    assert_eq!(d["type"], "diagnostics", "{d}");
    let first = &d["diagnostics"][0];
    assert_eq!(first["line"], 4, "{d}");
    assert!(
        first["message"]
            .as_str()
            .expect("message")
            .contains("Nowhere"),
        "{d}"
    );
    assert_eq!(
        step(&mut ws, 1, json!({}), json!({})).await["code"],
        "no_model"
    );
    std::fs::write(&model, good.replace("state B { }", "state B { }\n")).expect("write");
    let m = next(&mut ws).await;
    assert_eq!(m["type"], "model", "{m}");
    h.stop();
    let _ = std::fs::remove_dir_all(&dir);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn times_come_with_the_ticks_when_the_model_declares_a_tick() {
    // tests/time/station.sc (hand-derived there): ticks of 1.25 s; `start` in tick 1 and a
    // timer of 94 ticks end the stroke in tick 95, at 95 × 1.25 s = 118.75 s, where the
    // invariant `never_at_end` is violated. The run then has 96 ticks: 120.00 s.
    let h = start(&repo("tests/time/station.sc"));
    let (mut ws, hello) = connect(&h).await;
    assert_eq!(hello["type"], "model", "{hello}");
    let scn = std::fs::read_to_string(repo("tests/time/station.scn")).expect("scenario");
    let l = call(&mut ws, json!({"op": "load_scenario", "text": scn})).await;
    let stop = &l["run"]["stop"];
    assert_eq!(stop["tick"], 95, "{l}");
    assert_eq!(stop["time"], json!(118.75));
    assert_eq!(
        stop["message"],
        "property `never_at_end` violated at tick 95 (118.75 s)"
    );
    assert_eq!(l["run"]["time_text"], "120.00");
    let ticks = l["ticks"].as_array().expect("ticks");
    assert_eq!(ticks.len(), 96);
    assert_eq!(
        (&ticks[1]["time"], &ticks[1]["time_text"]),
        (&json!(1.25), &json!("1.25"))
    );
    assert_eq!(
        (&ticks[95]["time"], &ticks[95]["time_text"]),
        (&json!(118.75), &json!("118.75"))
    );
    // Verify from the page: the counterexample is decided at tick 95, 118.75 s.
    let done = verify_on_the_page(&mut ws, "explicit").await;
    let r = result_row(&done, "never_at_end");
    assert_eq!(r["verdict"], "violated");
    assert_eq!(
        (&r["tick"], &r["time_text"]),
        (&json!(95), &json!("118.75"))
    );
    h.stop();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn verify_from_the_page_minimises_the_counterexample() {
    // By hand: tick 0 enters A (no `during`), so `go` must hold in ticks 1, 2 and 3 for n to
    // reach 3 and violate `small` at tick 3; `go` in tick 0 and `x` (read by nothing) never
    // matter. Minimised (as `statecheck verify` does), the scenario keeps every input at its
    // initial value except `go` from tick 1 on: `-`, `C.go = true`, `- * 2`. (The explicit
    // engine's raw trace sets `x`, a choice among equals; the page must not show it.)
    let model = temp_model("studio-minimise", "noise.sc", "chart C {\n  input go: bool = false;\n  input x: int[0..3] = 2;\n  output n: int[0..9] = 0;\n  initial A;\n  state A { during { if go { n = min(9, n + 1); } } }\n  invariant small: n < 3;\n}\n");
    let h = start(model.to_str().expect("path"));
    let (mut ws, hello) = connect(&h).await;
    assert_eq!(hello["type"], "model", "{hello}");
    let done = verify_on_the_page(&mut ws, "explicit").await;
    let r = result_row(&done, "small");
    assert_eq!(
        (&r["verdict"], &r["depth"]),
        (&json!("violated"), &json!(4))
    );
    let text = r["scenario"].as_str().expect("scenario");
    let lines: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(lines, ["-", "C.go = true", "- * 2"], "{text}");
    h.stop();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn cegar_from_the_page_proves_and_refutes() {
    // By hand: `n` counts the ticks with `go` from tick 1 on (tick 0 enters A), saturating at
    // 9, so `small` (n < 3) is violated first at tick 3: a counterexample of 4 ticks; `capped`
    // (n <= 9) holds in every state and needs a proof, which BMC cannot give. The page names
    // the engine `cegar` and every row must say it decided it.
    let model = temp_model("studio-cegar", "count.sc", "chart C {\n  input go: bool = false;\n  output n: int[0..9] = 0;\n  initial A;\n  state A { during { if go { n = min(9, n + 1); } } }\n  invariant small: n < 3;\n  invariant capped: n <= 9;\n}\n");
    let h = start(model.to_str().expect("path"));
    let (mut ws, hello) = connect(&h).await;
    assert_eq!(hello["type"], "model", "{hello}");
    let done = verify_on_the_page(&mut ws, "cegar").await;
    let small = result_row(&done, "small");
    assert_eq!(
        (&small["verdict"], &small["depth"], &small["engine"]),
        (&json!("violated"), &json!(4), &json!("cegar")),
        "{small}"
    );
    assert!(small["scenario"].is_string(), "{small}");
    let capped = result_row(&done, "capped");
    assert_eq!(
        (&capped["verdict"], &capped["engine"]),
        (&json!("proved"), &json!("cegar")),
        "{capped}"
    );
    // A name that is no engine is refused with the list of those that are.
    let bad = call(&mut ws, json!({"op": "verify", "engine": "pdr"})).await;
    assert_eq!(bad["type"], "error", "{bad}");
    let message = bad["message"].as_str().expect("message");
    assert!(message.contains("ic3, cegar"), "{message}");
    h.stop();
}
