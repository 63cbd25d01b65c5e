//! `statecheck sim` outputs: the JSON contract, CSV, VCD (read back by an independent VCD
//! parser), random runs that replay from their saved scenario, coverage and DOT, and the
//! run-time error report.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn statecheck(args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(root())
        .env("NO_COLOR", "1")
        .args(args)
        .output()
        .expect("statecheck runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    out
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("statecheck-sim-outputs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

const ORDER: &str = "tests/semantics/order.sc";
const ORDER_SCN: &str = "tests/semantics/order.scn";

#[test]
fn json_trace_follows_the_contract() {
    let out = statecheck(&["sim", ORDER, "--scenario", ORDER_SCN, "--json"]);
    assert_eq!(out.status.code(), Some(0));
    let v: Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    let ticks = v["ticks"].as_array().expect("ticks array");
    // order.scn has 6 lines, one tick each.
    assert_eq!(ticks.len(), 6);
    for (k, t) in ticks.iter().enumerate() {
        assert_eq!(t["tick"], k);
        assert!(t["active"]["Order"].is_array());
        assert!(t["vars"]["Order.log"].is_i64());
        assert!(t["events"].is_array());
    }
    // Tick 1 (hand-derived in order.scn): event e, A1 -> B, log 536; composites are listed too.
    assert_eq!(ticks[1]["events"], serde_json::json!(["Order.e"]));
    assert_eq!(ticks[1]["active"]["Order"], serde_json::json!(["B"]));
    assert_eq!(
        ticks[0]["active"]["Order"],
        serde_json::json!(["A", "A.A1"])
    );
    assert_eq!(ticks[1]["vars"]["Order.log"], 536);
    assert_eq!(v["result"]["status"], "completed");
}

#[test]
fn json_shows_bools_and_enums_by_name() {
    let out = statecheck(&[
        "sim",
        "examples/linear_drive/linear_drive.sc",
        "--random",
        "3",
        "--seed",
        "1",
        "--json",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let t0 = &v["ticks"][0]["vars"];
    assert_eq!(t0["ctrl.dir"], "Left", "enums are written as their literal");
    assert!(t0["ctrl.U"].is_i64());
}

#[test]
fn csv_has_a_header_and_one_row_per_tick() {
    let out = statecheck(&["sim", ORDER, "--scenario", ORDER_SCN, "--csv"]);
    let text = String::from_utf8(out.stdout).expect("utf-8");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "tick,Order.active,Order.log,events");
    assert_eq!(lines.len(), 7);
    assert_eq!(lines[2], "1,B,536,Order.e");
}

#[test]
fn vcd_is_read_back_by_an_independent_parser() {
    let file = temp("order.vcd");
    let f = file.to_str().expect("utf-8 path");
    let out = statecheck(&["sim", ORDER, "--scenario", ORDER_SCN, "--vcd", f, "--quiet"]);
    assert_eq!(out.status.code(), Some(0));
    let text = std::fs::read(&file).expect("vcd written");
    let mut parser = vcd::Parser::new(&text[..]);
    let header = parser.parse_header().expect("valid VCD header");
    // The state wire for Order's A.A1 lives in scopes Order / states / A.
    let var = header
        .find_var(&["Order", "states", "A", "A1"])
        .expect("state A.A1 has a signal");
    assert_eq!(var.size, 1);
    let log = header
        .find_var(&["Order", "log"])
        .expect("variable log has a signal");
    let mut log_values = Vec::new();
    let mut a1_high_at = Vec::new();
    let mut now = 0;
    for cmd in parser {
        match cmd.expect("valid VCD body") {
            vcd::Command::Timestamp(t) => now = t,
            vcd::Command::ChangeVector(id, v) if id == log.code => {
                let bits: String = v
                    .iter()
                    .map(|b| if b == vcd::Value::V1 { '1' } else { '0' })
                    .collect();
                log_values.push(i64::from_str_radix(&bits, 2).expect("binary"));
            }
            vcd::Command::ChangeScalar(id, v) if id == var.code && v == vcd::Value::V1 => {
                a1_high_at.push(now)
            }
            _ => {}
        }
    }
    // The log values of order.scn's hand-derived trace, each written when it changes.
    assert_eq!(log_values, vec![124, 536, 724, 53824, 0]);
    // A.A1 is active from tick 0, inactive in tick 1 (B), active again from tick 2.
    assert_eq!(a1_high_at, vec![0, 2]);
}

#[test]
fn a_random_run_replays_from_its_saved_scenario() {
    let saved = temp("random.scn");
    let s = saved.to_str().expect("utf-8 path");
    let model = "examples/linear_drive/linear_drive.sc";
    let a = statecheck(&[
        "sim",
        model,
        "--random",
        "300",
        "--seed",
        "42",
        "--save-scenario",
        s,
        "--json",
    ]);
    let b = statecheck(&["sim", model, "--scenario", s, "--json"]);
    let (va, vb): (Value, Value) = (
        serde_json::from_slice(&a.stdout).expect("JSON"),
        serde_json::from_slice(&b.stdout).expect("JSON"),
    );
    assert_eq!(
        va["ticks"], vb["ticks"],
        "the replay must reproduce the random run tick by tick"
    );
    let c = statecheck(&["sim", model, "--random", "300", "--seed", "42", "--json"]);
    assert_eq!(a.stdout, c.stdout, "the same seed gives the same run");
}

#[test]
fn coverage_counts_and_draws_them() {
    let cov = temp("cov.json");
    let c = cov.to_str().expect("utf-8 path");
    let out = statecheck(&[
        "sim",
        ORDER,
        "--scenario",
        ORDER_SCN,
        "--coverage",
        c,
        "--quiet",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let v: Value =
        serde_json::from_str(&std::fs::read_to_string(&cov).expect("written")).expect("JSON");
    // order.sc has states A, A.A1, B (3) and transitions A->A (f), A1->B, B->A.A1 (3).
    // The scenario enters A and A1 three times each (ticks 0, 2, 3) ... and B once:
    // A: 0, 2, 3 (self-transition re-enters), 4 (again) = 4; A1 likewise 4; B 1.
    assert_eq!(v["states"]["total"], 3);
    assert_eq!(v["states"]["covered"], 3);
    assert_eq!(v["transitions"]["total"], 3);
    assert_eq!(v["transitions"]["covered"], 3);
    let count = |label: &str| {
        v["items"]
            .as_array()
            .expect("items")
            .iter()
            .find(|i| i["label"] == label)
            .map(|i| i["count"].as_u64())
    };
    assert_eq!(count("A"), Some(Some(4)));
    assert_eq!(count("B"), Some(Some(1)));
    assert_eq!(count("A -> A"), Some(Some(2)));
    let dot = statecheck(&["dot", ORDER, "--coverage", c]);
    let text = String::from_utf8(dot.stdout).expect("utf-8");
    assert!(text.starts_with("digraph"));
    assert!(text.contains("×4"), "entry counts are drawn: {text}");
}

#[test]
fn a_run_time_error_names_tick_instance_state_and_place() {
    let out = statecheck(&[
        "sim",
        "tests/semantics/runtime.sc",
        "--scenario",
        "tests/semantics/runtime.scn",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("tick 3"), "{err}");
    assert!(err.contains("instance Runtime, state A"), "{err}");
    assert!(err.contains("tests/semantics/runtime.sc:6:"), "{err}");
}

#[test]
fn usage_errors_exit_2() {
    assert_eq!(
        statecheck(&["sim", ORDER]).status.code(),
        Some(2),
        "no scenario and no --random"
    );
    assert_eq!(
        statecheck(&["sim", ORDER, "--random", "3", "--system", "Nope"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        statecheck(&["sim", "no/such/file.sc", "--random", "3"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(statecheck(&["frobnicate"]).status.code(), Some(2));
}

#[test]
fn scenario_errors_point_at_line_and_column() {
    let bad = temp("bad.scn");
    std::fs::write(&bad, "-\ne\nlog = 3\nnope = 1\n").expect("write");
    let out = statecheck(&["sim", ORDER, "--scenario", bad.to_str().expect("utf-8")]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(":3:1"), "log is not an input: {err}");
    assert!(err.contains("not a free input"), "{err}");
    assert!(err.contains(":4:1"), "nope is unknown: {err}");
}
