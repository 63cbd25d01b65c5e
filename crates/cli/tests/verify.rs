//! `statecheck verify` on models whose answers were derived by hand (see the comments in
//! `tests/verify/*.sc`). Every counterexample produced is replayed through `statecheck sim`
//! and must stop at the same property and tick. Results must not depend on the thread count.

use serde_json::Value;
use std::path::PathBuf;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn model(name: &str) -> String {
    format!("{}/../../tests/verify/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("statecheck-verify-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// Run `verify --json` with a cex dir; replay every counterexample; return (exit, JSON).
fn verify(file: &str, system: &str, extra: &[&str], threads: &str) -> (i32, Value) {
    let dir = temp_dir(&format!(
        "{system}-{threads}-{}",
        extra.join("_").replace(['-', ' '], "")
    ));
    let out = Command::new(BIN)
        .args([
            "verify",
            &model(file),
            "--engine",
            "explicit",
            "--system",
            system,
            "--json",
            "--threads",
            threads,
            "--cex-dir",
        ])
        .arg(&dir)
        .args(extra)
        .output()
        .expect("statecheck runs");
    let code = out.status.code().unwrap_or(-1);
    let v: Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("not JSON ({e}): {}", String::from_utf8_lossy(&out.stdout)));
    for r in v["results"].as_array().expect("results") {
        if let Some(path) = r["counterexample"].as_str() {
            replay(file, system, path, r);
        }
    }
    (code, v)
}

/// Replay a counterexample through the simulator and check where it stops.
fn replay(file: &str, system: &str, path: &str, r: &Value) {
    let out = Command::new(BIN)
        .args([
            "sim",
            &model(file),
            "--system",
            system,
            "--scenario",
            path,
            "--json",
        ])
        .output()
        .expect("sim runs");
    let code = out.status.code().unwrap_or(-1);
    let sim: Value = serde_json::from_slice(&out.stdout).expect("sim JSON");
    let name = r["property"].as_str().expect("name");
    let tick = r["depth"].as_u64().expect("depth") - 1;
    match r["kind"].as_str() {
        Some("reachable") => {
            assert_eq!(code, 0, "witness replay of {name}");
            assert_eq!(
                sim["reached"][name].as_u64(),
                Some(tick),
                "witness of {name} reaches at tick {tick}"
            );
        }
        Some("builtin") => {
            assert_eq!(code, 1, "a run-time error replays with exit 1 ({name})");
            assert_eq!(sim["result"]["property"].as_str(), Some(name));
            assert_eq!(sim["result"]["tick"].as_u64(), Some(tick));
        }
        _ => {
            assert_eq!(code, 4, "violation replays with exit 4 ({name})");
            assert_eq!(sim["result"]["property"].as_str(), Some(name));
            assert_eq!(sim["result"]["tick"].as_u64(), Some(tick));
        }
    }
}

fn result<'a>(v: &'a Value, name: &str) -> &'a Value {
    v["results"]
        .as_array()
        .and_then(|a| a.iter().find(|r| r["property"] == name))
        .unwrap_or_else(|| panic!("no result for {name}: {v}"))
}

/// (verdict, depth) of a property.
fn verdict(v: &Value, name: &str) -> (String, u64) {
    let r = result(v, name);
    (
        r["verdict"].as_str().unwrap_or("").to_string(),
        r["depth"].as_u64().unwrap_or(u64::MAX),
    )
}

fn stat(v: &Value, key: &str) -> u64 {
    v["stats"][key]
        .as_u64()
        .unwrap_or_else(|| panic!("stats.{key} in {v}"))
}

/// Run on 1 and 2 threads, with native successors, and without the input abstraction
/// (`--no-input-reduction`); the verdicts, depths and counts must be identical (and every
/// counterexample of each run replays).
fn both(file: &str, system: &str, extra: &[&str]) -> (i32, Value) {
    let (c1, v1) = verify(file, system, extra, "1");
    let full_args: Vec<&str> = extra
        .iter()
        .copied()
        .chain(["--no-input-reduction"])
        .collect();
    let (c0, v0) = verify(file, system, &full_args, "1");
    assert_eq!(c0, c1, "exit code independent of the input abstraction");
    let (c2, v2) = verify(file, system, extra, "2");
    let native_args: Vec<&str> = extra
        .iter()
        .copied()
        .chain(["--backend", "native"])
        .collect();
    let (c3, v3) = verify(file, system, &native_args, "2");
    assert_eq!(c1, c2, "exit code independent of threads");
    assert_eq!(c2, c3, "exit code independent of the backend");
    assert_eq!(v3["stats"]["backend"], "native", "{}", v3["stats"]);
    for key in ["states", "transitions", "depth", "dead"] {
        assert_eq!(
            v0["stats"][key], v1["stats"][key],
            "stats.{key} independent of the input abstraction"
        );
        assert_eq!(
            v1["stats"][key], v2["stats"][key],
            "stats.{key} independent of threads"
        );
        assert_eq!(
            v2["stats"][key], v3["stats"][key],
            "stats.{key} independent of the backend"
        );
    }
    let strip = |v: &Value| -> Vec<(Value, Value, Value)> {
        v["results"]
            .as_array()
            .map(|a| {
                a.iter()
                    .map(|r| {
                        (
                            r["property"].clone(),
                            r["verdict"].clone(),
                            r["depth"].clone(),
                        )
                    })
                    .collect()
            })
            .unwrap_or_default()
    };
    assert_eq!(
        strip(&v0),
        strip(&v1),
        "results independent of the input abstraction"
    );
    assert_eq!(strip(&v1), strip(&v2), "results independent of threads");
    assert_eq!(strip(&v2), strip(&v3), "results independent of the backend");
    (c2, v2)
}

#[test]
fn counter_shortest_violation_and_exact_counts() {
    let (code, v) = both("counter.sc", "Counting", &[]);
    assert_eq!(code, 1);
    assert_eq!(verdict(&v, "below5"), ("violated".into(), 6));
    assert_eq!(verdict(&v, "never_above9").0, "proved");
    assert_eq!(verdict(&v, "no_range_overflow").0, "proved");
    assert_eq!(
        (
            stat(&v, "states"),
            stat(&v, "transitions"),
            stat(&v, "depth")
        ),
        (11, 11, 10)
    );
    assert_eq!(v["stats"]["dead"], serde_json::json!([]));
    assert!(result(&v, "below5")["counterexample"].is_string());
}

#[test]
fn reachable_witness_and_unreachable() {
    let (code, v) = both("counter.sc", "Reaching", &[]);
    assert_eq!(code, 1, "an unreachable target exits 1");
    assert_eq!(verdict(&v, "reach9"), ("reachable".into(), 10));
    assert_eq!(verdict(&v, "reach_neg").0, "unreachable");
    let (code, v) = both("counter.sc", "Reaching", &["--property", "reach9"]);
    assert_eq!(code, 0, "only the reachable one: exit 0");
    assert_eq!(v["results"].as_array().map(Vec::len), Some(1));
}

#[test]
fn observer_violation() {
    let (code, v) = both("counter.sc", "Observed", &[]);
    assert_eq!(code, 1);
    assert_eq!(verdict(&v, "over6"), ("violated".into(), 8));
    assert_eq!(stat(&v, "states"), 11);
}

#[test]
fn toggle_counts_and_assume_changes_the_verdict() {
    let (code, v) = both("toggle.sc", "Free", &[]);
    assert_eq!(code, 1);
    assert_eq!(verdict(&v, "stays_off"), ("violated".into(), 2));
    assert_eq!(
        (
            stat(&v, "states"),
            stat(&v, "transitions"),
            stat(&v, "depth")
        ),
        (3, 6, 2)
    );
    let (code, v) = both("toggle.sc", "Frozen", &[]);
    assert_eq!(code, 0);
    assert_eq!(verdict(&v, "stays_off").0, "proved");
    assert_eq!((stat(&v, "states"), stat(&v, "transitions")), (2, 2));
    // Dead design: On is never entered, neither transition fires.
    let dead: Vec<String> = v["stats"]["dead"]
        .as_array()
        .map(|a| {
            a.iter()
                .map(|d| {
                    format!(
                        "{} {}",
                        d["kind"].as_str().unwrap_or(""),
                        d["label"].as_str().unwrap_or("")
                    )
                })
                .collect()
        })
        .unwrap_or_default();
    assert_eq!(
        dead,
        vec!["state On", "transition Off -> On", "transition On -> Off"]
    );
}

#[test]
fn bounded_response() {
    let (code, v) = both("respond.sc", "Prompt", &[]);
    assert_eq!(code, 0);
    assert_eq!(verdict(&v, "work_done").0, "proved");
    let (code, v) = both("respond.sc", "Slow", &[]);
    assert_eq!(code, 1);
    assert_eq!(verdict(&v, "work_done"), ("violated".into(), 4));
    let (code, v) = both("respond.sc", "Eager", &[]);
    assert_eq!(code, 1);
    assert_eq!(verdict(&v, "req_done"), ("violated".into(), 4));
}

#[test]
fn runtime_errors_are_builtin_violations() {
    let (code, v) = both("runtime.sc", "Divide", &[]);
    assert_eq!(code, 1);
    assert_eq!(verdict(&v, "no_division_by_zero"), ("violated".into(), 2));
    assert_eq!(verdict(&v, "no_range_overflow").0, "proved");
    // Pre-start, q = 0, then q in {12, 6, 4}: 5 states, 4 vectors each.
    assert_eq!((stat(&v, "states"), stat(&v, "transitions")), (5, 20));
    let (code, v) = both("runtime.sc", "SafeDivide", &[]);
    assert_eq!(code, 0);
    assert_eq!(verdict(&v, "no_division_by_zero").0, "proved");
    let (code, v) = both("runtime.sc", "Add", &[]);
    assert_eq!(code, 1);
    assert_eq!(verdict(&v, "no_range_overflow"), ("violated".into(), 3));
}

#[test]
fn depth_bound_and_limits() {
    let (code, v) = both("counter.sc", "Counting", &["--depth", "3"]);
    assert_eq!(code, 0, "bounded is not a failure");
    assert_eq!(verdict(&v, "below5"), ("bounded".into(), 3));
    let (code, v) = both("counter.sc", "Counting", &["--depth", "6"]);
    assert_eq!(code, 1);
    assert_eq!(verdict(&v, "below5"), ("violated".into(), 6));
    let (code, v) = both("counter.sc", "Counting", &["--max-states", "3"]);
    assert_eq!(code, 3);
    assert_eq!(verdict(&v, "never_above9").0, "unknown");
    assert_eq!(v["stats"]["limit"]["kind"], "states");
    let (code, v) = verify("counter.sc", "Counting", &["--max-memory", "1K"], "2");
    assert_eq!(code, 3);
    assert_eq!(v["stats"]["limit"]["kind"], "memory");
}

#[test]
fn wide_inputs_are_refused_and_assumes_narrow_them() {
    let (code, v) = verify("wide.sc", "Wide", &[], "2");
    assert_eq!(code, 3);
    assert_eq!(v["stats"]["limit"]["kind"], "branching");
    assert_eq!(stat(&v, "branching"), 4096 * 4096);
    let (code, v) = both("wide.sc", "Restricted", &[]);
    assert_eq!(code, 0);
    assert_eq!(
        (
            stat(&v, "branching"),
            stat(&v, "branching_after_assumes"),
            stat(&v, "states")
        ),
        (4096, 3, 4)
    );
}

#[test]
fn usage_errors_exit_2() {
    let run = |args: &[&str]| {
        Command::new(BIN)
            .arg("verify")
            .args(args)
            .output()
            .expect("runs")
            .status
            .code()
    };
    assert_eq!(
        run(&[
            &model("counter.sc"),
            "--system",
            "Counting",
            "--property",
            "nope"
        ]),
        Some(2)
    );
    assert_eq!(
        run(&[
            &model("counter.sc"),
            "--system",
            "Counting",
            "--max-memory",
            "lots"
        ]),
        Some(2)
    );
    assert_eq!(
        run(&[&model("counter.sc"), "--system", "Counting", "--vcd"]),
        Some(2)
    );
}

#[test]
fn text_output_shows_the_counterexample_table() {
    let out = Command::new(BIN)
        .args([
            "verify",
            &model("counter.sc"),
            "--engine",
            "explicit",
            "--system",
            "Counting",
        ])
        .output()
        .expect("runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text.contains("below5") && text.contains("violated"),
        "{text}"
    );
    assert!(text.contains("counterexample for `below5`"), "{text}");
    assert!(text.contains("c=5"), "{text}");
}
