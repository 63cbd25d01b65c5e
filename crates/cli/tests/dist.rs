//! `statecheck verify --workers` (the distributed explicit search, docs/distributed.md): two
//! processes of one worker on loopback and one process of two workers give the verdicts,
//! depths and state and transition counts of the single-process explicit engine, and their
//! counterexamples replay in `statecheck sim`. Counts on the counter model are derived by hand;
//! on the examples they are compared with the single-process run.

use serde_json::Value;
use std::path::PathBuf;
use std::process::{Command, Output};

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn path(rel: &str) -> String {
    format!("{}/../../{rel}", env!("CARGO_MANIFEST_DIR"))
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("statecheck-dist-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Two loopback addresses with ports free at the time of asking.
fn free_ports() -> [String; 2] {
    let a = std::net::TcpListener::bind("127.0.0.1:0").expect("bind");
    let b = std::net::TcpListener::bind("127.0.0.1:0").expect("bind");
    let addr = |l: &std::net::TcpListener| l.local_addr().expect("addr").to_string();
    [addr(&a), addr(&b)]
}

fn json(out: &Output) -> Value {
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "not JSON ({e}): {}\n{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    })
}

/// The single-process explicit engine on one thread: (exit code, JSON).
fn single(model: &str, extra: &[&str]) -> (i32, Value) {
    let out = Command::new(BIN)
        .args([
            "verify",
            &path(model),
            "--engine",
            "explicit",
            "--threads",
            "1",
        ])
        .args(["--backend", "interpreter", "--json"])
        .args(extra)
        .output()
        .expect("statecheck runs");
    (out.status.code().unwrap_or(-1), json(&out))
}

/// One process of two workers; counterexamples written to (and replayed from) a directory.
fn two_workers(model: &str, extra: &[&str], tag: &str) -> (i32, Value) {
    let dir = temp_dir(tag);
    let out = Command::new(BIN)
        .args([
            "verify",
            &path(model),
            "--workers",
            "2",
            "--json",
            "--cex-dir",
        ])
        .arg(&dir)
        .args(extra)
        .output()
        .expect("statecheck runs");
    let v = json(&out);
    replay_all(model, extra, &v);
    (out.status.code().unwrap_or(-1), v)
}

/// Two processes of one worker each on loopback: both reports, and process 0's exit code.
fn two_processes(model: &str, extra: &[&str], tag: &str) -> (i32, Value, Value) {
    let dir = temp_dir(tag);
    let hosts = dir.join("hosts");
    let [a, b] = free_ports();
    std::fs::write(&hosts, format!("{a}\n{b}\n")).expect("host file");
    let run = |i: &str| {
        let mut c = Command::new(BIN);
        c.args(["verify", &path(model), "--workers", "1", "--hosts"])
            .arg(&hosts)
            .args(["--process", i, "--json", "--timeout", "120", "--cex-dir"])
            .arg(dir.join(format!("cex{i}")))
            .args(extra)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped());
        c.spawn().expect("statecheck starts")
    };
    let p1 = run("1");
    let p0 = run("0");
    let o0 = p0.wait_with_output().expect("process 0 ends");
    let o1 = p1.wait_with_output().expect("process 1 ends");
    let (v0, v1) = (json(&o0), json(&o1));
    replay_all(model, extra, &v0);
    assert_eq!(o0.status.code(), o1.status.code(), "both processes agree");
    (o0.status.code().unwrap_or(-1), v0, v1)
}

/// The `--system` of `extra`, if any.
fn system(extra: &[&str]) -> Vec<String> {
    extra
        .windows(2)
        .find(|w| w[0] == "--system")
        .map(|w| vec!["--system".to_string(), w[1].to_string()])
        .unwrap_or_default()
}

/// Replay every counterexample of a report in the simulator: it must stop at the same
/// property and tick.
fn replay_all(model: &str, extra: &[&str], v: &Value) {
    for r in v["results"].as_array().expect("results") {
        let Some(scn) = r["counterexample"].as_str() else {
            continue;
        };
        let out = Command::new(BIN)
            .args(["sim", &path(model), "--scenario", scn, "--json"])
            .args(system(extra))
            .output()
            .expect("sim runs");
        let code = out.status.code().unwrap_or(-1);
        let sim = json(&out);
        let name = r["property"].as_str().expect("name");
        let tick = r["depth"].as_u64().expect("depth") - 1;
        match r["kind"].as_str() {
            Some("reachable") => {
                assert_eq!(code, 0, "witness replay of {name}");
                assert_eq!(sim["reached"][name].as_u64(), Some(tick), "{name}");
            }
            Some("builtin") => {
                assert_eq!(code, 1, "run-time error replay of {name}");
                assert_eq!(sim["result"]["property"].as_str(), Some(name));
                assert_eq!(sim["result"]["tick"].as_u64(), Some(tick));
            }
            _ => {
                assert_eq!(code, 4, "violation replay of {name}");
                assert_eq!(sim["result"]["property"].as_str(), Some(name));
                assert_eq!(sim["result"]["tick"].as_u64(), Some(tick));
            }
        }
    }
}

/// (property, verdict, depth) of every result.
fn rows(v: &Value) -> Vec<(Value, Value, Value)> {
    v["results"]
        .as_array()
        .expect("results")
        .iter()
        .map(|r| {
            (
                r["property"].clone(),
                r["verdict"].clone(),
                r["depth"].clone(),
            )
        })
        .collect()
}

fn counts(v: &Value) -> (Value, Value, Value) {
    let s = &v["stats"];
    (
        s["states"].clone(),
        s["transitions"].clone(),
        s["depth"].clone(),
    )
}

/// Each counterexample present in the distributed run.
fn every_finding_has_a_counterexample(v: &Value) {
    for r in v["results"].as_array().expect("results") {
        if r["verdict"] == "violated" || r["verdict"] == "reachable" {
            assert!(r["counterexample"].is_string(), "{r}");
        }
    }
}

/// Same verdicts, depths and counts as the single-process engine, on both layouts.
fn same_as_single(model: &str, extra: &[&str], tag: &str) -> Value {
    let (c, s) = single(model, extra);
    let (c2, w2) = two_workers(model, extra, &format!("{tag}-w"));
    let (c3, p0, p1) = two_processes(model, extra, &format!("{tag}-p"));
    for (what, code, v) in [("1x2", c2, &w2), ("2x1", c3, &p0), ("2x1 p1", c3, &p1)] {
        assert_eq!(code, c, "{what}: exit code");
        assert_eq!(rows(v), rows(&s), "{what}: verdicts and depths");
        assert_eq!(counts(v), counts(&s), "{what}: states, transitions, depth");
    }
    every_finding_has_a_counterexample(&w2);
    every_finding_has_a_counterexample(&p0);
    let d = &p0["stats"]["distributed"];
    assert_eq!(
        (d["workers"].as_u64(), d["processes"].as_u64()),
        (Some(2), Some(2))
    );
    let per_worker: u64 = d["worker_states"]
        .as_array()
        .expect("worker_states")
        .iter()
        .filter_map(Value::as_u64)
        .sum();
    assert_eq!(
        Some(per_worker),
        s["stats"]["states"].as_u64(),
        "states partitioned"
    );
    assert!(
        d["exchange_bytes"].as_u64() > Some(0),
        "successors crossed processes: {d}"
    );
    p0
}

#[test]
fn counter_counts_and_shortest_violation_on_every_layout() {
    // tests/verify/counter.sc, system Counting (derived there): `inc` increments c up to 9, so
    // 11 states (the pre-start state, c = 0..9), one transition each (11), depth 10; `below5`
    // fails when c reaches 5, after 6 ticks.
    let extra = ["--system", "Counting"];
    let v = same_as_single("tests/verify/counter.sc", &extra, "counter");
    assert_eq!(counts(&v), (11.into(), 11.into(), 10.into()));
    let below5 = &v["results"][0];
    assert_eq!(
        (&below5["property"], &below5["depth"]),
        (&"below5".into(), &6.into())
    );
    assert_eq!(below5["verdict"], "violated");
}

#[test]
fn fam_alone_as_single_process() {
    // Many input vectors per tick: a wrong input position or a parent link taken in the wrong
    // round would make a counterexample that does not replay (`replay_all`).
    same_as_single("examples/fam/fam_alone.sc", &[], "fam");
}

#[test]
fn linear_drive_as_single_process_bounded() {
    // Ten ticks of the linear drive (the whole space takes long in a test); the temporal
    // `respond ... within` rows are bounded properties, checked like invariants.
    same_as_single(
        "examples/linear_drive/linear_drive.sc",
        &["--depth", "10"],
        "drive",
    );
}

#[test]
fn limits_give_unknown_with_partial_statistics() {
    // 5 states at most: the counter's run stops (11 states) with `unknown` and exit 3.
    let extra = ["--system", "Counting", "--max-states", "5"];
    let (code, v, _) = two_processes("tests/verify/counter.sc", &extra, "limit");
    assert_eq!(code, 3, "{v}");
    assert_eq!(v["stats"]["limit"]["kind"], "states");
    assert_eq!(v["stats"]["complete"], false);
    // The FAM alone needs MiBs; 64 KiB per process stops it, never an abort.
    let extra = ["--max-memory", "64K"];
    let (code, v, _) = two_processes("examples/fam/fam_alone.sc", &extra, "mem");
    assert_eq!(code, 3, "{v}");
    assert_eq!(v["stats"]["limit"]["kind"], "memory");
    assert!(
        v["stats"]["states"].as_u64() < Some(66_889),
        "{}",
        v["stats"]
    );
}

#[test]
fn temporal_properties_are_unknown_with_the_reason() {
    let model = "examples/linear_drive/liveness/linear_drive_live.sc";
    let out = Command::new(BIN)
        .args([
            "verify",
            &path(model),
            "--workers",
            "2",
            "--json",
            "--depth",
            "3",
        ])
        .output()
        .expect("statecheck runs");
    let v = json(&out);
    let temporal: Vec<&Value> = v["results"]
        .as_array()
        .expect("results")
        .iter()
        .filter(|r| ["ltl", "ctl", "nonblocking"].contains(&r["kind"].as_str().unwrap_or("")))
        .collect();
    assert!(!temporal.is_empty(), "{v}");
    for r in temporal {
        assert_eq!(r["verdict"], "unknown");
        assert!(
            r["reason"]
                .as_str()
                .is_some_and(|x| x.contains("--workers")),
            "{r}"
        );
    }
}

#[test]
fn bad_host_files_are_usage_errors() {
    let dir = temp_dir("hosts");
    let hosts = dir.join("hosts");
    std::fs::write(&hosts, "localhost\n").expect("host file");
    let out = Command::new(BIN)
        .args([
            "verify",
            &path("tests/verify/counter.sc"),
            "--workers",
            "1",
            "--hosts",
        ])
        .arg(&hosts)
        .args(["--process", "0", "--system", "Counting"])
        .output()
        .expect("statecheck runs");
    assert_ne!(out.status.code(), Some(0));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("host:port"), "{err}");
}
