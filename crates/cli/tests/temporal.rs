//! Temporal properties (`ltl`, `ctl`, `nonblocking`, unbounded `respond`, `fair`) on
//! `tests/verify/temporal.sc`, whose verdicts are derived by hand in its comments. Every lasso
//! counterexample is replayed with `statecheck sim` (which evaluates the formula on the lasso
//! independently of the checker's automaton) and must exit 4.

use serde_json::Value;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn model() -> String {
    format!(
        "{}/../../tests/verify/temporal.sc",
        env!("CARGO_MANIFEST_DIR")
    )
}

/// `verify --json` of one system; every lasso replayed. Returns name -> verdict.
fn verify(system: &str) -> Vec<(String, String)> {
    let dir = std::env::temp_dir().join(format!(
        "statecheck-temporal-{}-{system}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(BIN)
        .args([
            "verify",
            &model(),
            "--system",
            system,
            "--json",
            "--cex-dir",
        ])
        .arg(&dir)
        .output()
        .expect("statecheck runs");
    let v: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(&out.stdout)));
    let mut verdicts = Vec::new();
    for r in v["results"].as_array().expect("results") {
        let name = r["property"].as_str().unwrap_or("").to_string();
        if r["kind"] == "ltl" || r["kind"] == "respond" {
            if let Some(path) = r["counterexample"].as_str() {
                let k = r["loop_start"].as_u64().expect("a lasso has a loop start");
                let text = std::fs::read_to_string(path).expect("scenario written");
                assert!(text.contains("loop:"), "{name}: {text}");
                let depth = r["depth"].as_u64().unwrap_or(0);
                assert!(k >= 1 && k < depth, "{name}: loop start {k}, {depth} ticks");
                let sim = Command::new(BIN)
                    .args([
                        "sim",
                        &model(),
                        "--system",
                        system,
                        "--scenario",
                        path,
                        "--quiet",
                    ])
                    .output()
                    .expect("sim runs");
                assert_eq!(
                    sim.status.code(),
                    Some(4),
                    "{name}: {}",
                    String::from_utf8_lossy(&sim.stderr)
                );
            }
        }
        verdicts.push((name, r["verdict"].as_str().unwrap_or("").to_string()));
    }
    verdicts
}

fn check(system: &str, expect: &[(&str, &str)]) {
    let got = verify(system);
    for (name, verdict) in expect {
        let v = got.iter().find(|(n, _)| n == name).map(|(_, v)| v.as_str());
        assert_eq!(v, Some(*verdict), "{system}.{name}: {got:?}");
    }
}

#[test]
fn free_counter() {
    check(
        "Free",
        &[
            ("reaches3", "violated"),
            ("bounded", "proved"),
            ("gf_zero", "violated"),
            ("resets", "proved"),
            ("can_reach3", "proved"),
            ("ax_one", "violated"),
            ("eg_low", "proved"),
            ("zero", "proved"),
            ("deadlock_free", "proved"),
        ],
    );
}

#[test]
fn deadlock() {
    check(
        "Deadlock",
        &[
            ("never2", "proved"),
            ("reaches2", "violated"),
            ("deadlock_free", "violated"),
        ],
    );
    // The shortest scenario into the deadlock: tick 0, inc, inc.
    let out = Command::new(BIN)
        .args([
            "verify",
            &model(),
            "--system",
            "Deadlock",
            "--json",
            "--property",
            "deadlock_free",
        ])
        .output()
        .expect("statecheck runs");
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let r = &v["results"][0];
    assert_eq!(r["property"], "deadlock_free");
    assert_eq!(r["depth"], 3);
    assert_eq!(out.status.code(), Some(1));
}

#[test]
fn justice() {
    check("FairInc", &[("reaches3", "violated"), ("gf_inc", "proved")]);
    check("NoReset", &[("reaches3", "proved"), ("stays3", "proved")]);
}

#[test]
fn compassion() {
    check(
        "Compassion",
        &[("past_one", "proved"), ("reaches2", "violated")],
    );
    check("NoCompassion", &[("past_one", "violated")]);
}

#[test]
fn a_scenario_that_is_not_a_lasso_is_refused() {
    // inc in the loop: n goes 1 -> 2, so the state at the loop start does not recur.
    let dir = std::env::temp_dir().join(format!("statecheck-temporal-bad-{}", std::process::id()));
    let _ = std::fs::create_dir_all(&dir);
    let f = dir.join("bad.scn");
    std::fs::write(&f, "-\nc.inc\nloop:\nc.inc\n").expect("write");
    let sim = Command::new(BIN)
        .args(["sim", &model(), "--system", "Free", "--scenario"])
        .arg(&f)
        .output()
        .expect("sim runs");
    assert_eq!(sim.status.code(), Some(1));
    // A loop without events keeps n = 0: it replays, and violates `reaches3` (declared first).
    std::fs::write(&f, "-\nloop:\n-\n").expect("write");
    let sim = Command::new(BIN)
        .args(["sim", &model(), "--system", "Free", "--scenario"])
        .arg(&f)
        .output()
        .expect("sim runs");
    assert_eq!(sim.status.code(), Some(4));
    assert!(
        String::from_utf8_lossy(&sim.stdout).contains("reaches3")
            || String::from_utf8_lossy(&sim.stderr).contains("reaches3")
    );
}

/// examples/linear_drive/liveness/linear_drive_live.sc: its charts are linear_drive.sc's,
/// imported (it declares none of its own); after Run the drive reaches both ends unless Halt
/// comes (§2.1, Modelica paper), and the property without the Halt escape is violated (Run,
/// then Halt).
#[test]
fn linear_drive_liveness() {
    let root = format!("{}/../..", env!("CARGO_MANIFEST_DIR"));
    let live = std::fs::read_to_string(format!(
        "{root}/examples/linear_drive/liveness/linear_drive_live.sc"
    ))
    .expect("example");
    assert!(
        live.contains("import \"../linear_drive.sc\" { Controller, Drive };"),
        "the charts come from linear_drive.sc"
    );
    assert!(
        !live
            .lines()
            .any(|l| l.starts_with("chart ") || l.starts_with("plant chart ")),
        "no chart of its own: they would be copies"
    );
    let out = Command::new(BIN)
        .args([
            "verify",
            &format!("{root}/examples/linear_drive/liveness/linear_drive_live.sc"),
            "--json",
        ])
        .output()
        .expect("statecheck runs");
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let verdict = |n: &str| {
        v["results"]
            .as_array()
            .and_then(|a| a.iter().find(|r| r["property"] == n))
            .map(|r| r["verdict"].as_str().unwrap_or("").to_string())
    };
    assert_eq!(verdict("run_reaches_left").as_deref(), Some("proved"));
    assert_eq!(verdict("run_reaches_right").as_deref(), Some("proved"));
    assert_eq!(
        verdict("run_reaches_left_always").as_deref(),
        Some("violated")
    );
    assert_eq!(verdict("can_stop").as_deref(), Some("proved"));
    assert_eq!(verdict("can_run").as_deref(), Some("proved"));
    assert_eq!(verdict("deadlock_free").as_deref(), Some("proved"));
}
