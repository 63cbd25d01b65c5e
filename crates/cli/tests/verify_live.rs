//! `statecheck verify` as it runs: rows printed the moment each verdict is decided
//! (`--json-lines`), Ctrl-C and the time limit keeping the rows decided so far, per-property
//! budgets, and the memory limit. The model is `tests/verify/hard.sc`: `fast` is violated at
//! tick 3 (a counterexample of 4 ticks, derived by hand in the file) and `commutes`, which
//! holds, is out of reach of every engine within seconds.
//!
//! No assertion here is about wall-clock speed: the tests check the order of the lines and
//! that the process is still running when the first row arrives. Figures are printed by
//! `crates/verify/benches/auto_vs_single.sh` and `crates/verify/benches/limits.sh`.

use serde_json::Value;
use std::io::{BufRead, BufReader};
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn hard() -> String {
    format!("{}/../../tests/verify/hard.sc", env!("CARGO_MANIFEST_DIR"))
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("statecheck-live-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn spawn(args: &[&str]) -> Child {
    Command::new(BIN)
        .arg("verify")
        .arg(hard())
        .args(["--system", "Hard", "--json-lines"])
        .args(["--property", "commutes", "--property", "fast"])
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("statecheck runs")
}

fn parse(line: &str) -> Value {
    serde_json::from_str(line).unwrap_or_else(|e| panic!("not JSON ({e}): {line}"))
}

/// The rows of a finished run by property name, and the final line.
fn rest(lines: impl Iterator<Item = std::io::Result<String>>) -> (Vec<Value>, Value) {
    let mut all: Vec<Value> = lines.map(|l| parse(&l.expect("line"))).collect();
    let last = all.pop().expect("a stats line");
    (all, last)
}

fn row<'a>(rows: &'a [Value], name: &str) -> &'a Value {
    rows.iter()
        .find(|r| r["property"] == name)
        .unwrap_or_else(|| panic!("no row for `{name}` in {rows:?}"))
}

#[test]
fn the_first_verdict_is_printed_while_the_run_goes_on() {
    let mut child = spawn(&["--engine", "auto", "--timeout", "8"]);
    let out = child.stdout.take().expect("stdout");
    let mut lines = BufReader::new(out).lines();
    let first = parse(&lines.next().expect("a first line").expect("line"));
    // The row of `fast` arrives while the process is still working on `commutes`.
    let running = child.try_wait().expect("try_wait").is_none();
    assert_eq!(first["property"], "fast", "{first}");
    assert_eq!(first["verdict"], "violated", "{first}");
    assert_eq!(first["depth"], 4, "{first}");
    assert!(running, "the first row came only when the run had ended");
    let (rows, last) = rest(lines);
    let status = child.wait().expect("wait");
    assert_eq!(rows.len(), 1, "{rows:?}");
    assert_eq!(rows[0]["property"], "commutes");
    assert_eq!(rows[0]["verdict"], "unknown");
    assert_eq!(rows[0]["reason"], "time limit");
    assert!(last.get("stats").is_some(), "{last}");
    // A violation outranks an unknown: exit 1.
    assert_eq!(status.code(), Some(1));
}

#[test]
fn an_interrupt_keeps_the_decided_rows_and_their_counterexamples() {
    let dir = temp_dir("sigint");
    let d = dir.to_string_lossy().to_string();
    let mut child = spawn(&["--engine", "auto", "--cex-dir", &d]);
    let out = child.stdout.take().expect("stdout");
    let mut lines = BufReader::new(out).lines();
    let first = parse(&lines.next().expect("a first line").expect("line"));
    assert_eq!(first["property"], "fast", "{first}");
    assert!(
        dir.join("fast.scn").exists(),
        "the counterexample is written when its row is printed"
    );
    let st = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(st.success());
    let (rows, last) = rest(lines);
    let status = child.wait().expect("wait");
    assert_eq!(row(&rows, "commutes")["verdict"], "unknown");
    assert_eq!(row(&rows, "commutes")["reason"], "interrupted");
    assert!(last.get("stats").is_some(), "{last}");
    assert_eq!(status.code(), Some(1), "fast is violated");
}

#[test]
fn an_interrupted_run_with_nothing_violated_exits_3() {
    let mut child = Command::new(BIN)
        .arg("verify")
        .arg(hard())
        .args(["--system", "Hard", "--json-lines", "--property", "commutes"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("statecheck runs");
    // Wait until the run has started (the engines announce nothing on stdout): the SAT
    // engines need a moment, and the signal must come after the handler is installed.
    let err = child.stderr.take().expect("stderr");
    std::thread::sleep(std::time::Duration::from_millis(1500));
    let st = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(st.success());
    let out = child.stdout.take().expect("stdout");
    let (rows, _) = rest(BufReader::new(out).lines());
    drop(err);
    let status = child.wait().expect("wait");
    assert_eq!(row(&rows, "commutes")["verdict"], "unknown");
    assert_eq!(row(&rows, "commutes")["reason"], "interrupted");
    assert_eq!(status.code(), Some(3));
}

/// One engine alone, `commutes` first in its order: with a budget per property, `fast`
/// behind it is still decided.
#[test]
fn a_hard_property_does_not_starve_the_easy_one_behind_it() {
    for engine in ["ic3", "kind"] {
        let child = spawn(&["--engine", engine, "--property-timeout", "1"]);
        let out = child.wait_with_output().expect("wait");
        let text = String::from_utf8_lossy(&out.stdout);
        let (rows, _) = rest(text.lines().map(|l| Ok(l.to_string())));
        assert_eq!(
            row(&rows, "fast")["verdict"],
            "violated",
            "{engine}: {text}"
        );
        assert_eq!(row(&rows, "fast")["depth"], 4, "{engine}: {text}");
        assert_eq!(row(&rows, "commutes")["verdict"], "unknown", "{engine}");
        assert_eq!(
            row(&rows, "commutes")["reason"],
            "property time limit",
            "{engine}"
        );
        assert_eq!(out.status.code(), Some(1), "{engine}");
    }
}

/// Without a per-property budget, the total is shared out: the first pass gives each
/// property a second, so `fast` is decided although `commutes` comes first.
#[test]
fn the_total_time_is_shared_between_the_properties() {
    let child = spawn(&["--engine", "kind", "--timeout", "4"]);
    let out = child.wait_with_output().expect("wait");
    let text = String::from_utf8_lossy(&out.stdout);
    let (rows, _) = rest(text.lines().map(|l| Ok(l.to_string())));
    assert_eq!(row(&rows, "fast")["verdict"], "violated", "{text}");
    assert_eq!(row(&rows, "commutes")["verdict"], "unknown", "{text}");
    assert_eq!(row(&rows, "commutes")["reason"], "time limit", "{text}");
}

/// `--json` is one object at the end, with the same fields as before streaming existed.
#[test]
fn json_is_one_object_with_the_contract_fields() {
    let out = Command::new(BIN)
        .arg("verify")
        .arg(hard())
        .args(["--system", "Hard", "--json", "--timeout", "3"])
        .args(["--property", "commutes", "--property", "fast"])
        .output()
        .expect("runs");
    let v: Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    for r in v["results"].as_array().expect("results") {
        for f in [
            "property",
            "kind",
            "verdict",
            "engine",
            "depth",
            "states",
            "transitions",
            "time_s",
            "counterexample",
        ] {
            assert!(r.get(f).is_some(), "missing `{f}` in {r}");
        }
    }
    assert!(v["stats"].get("peak_rss_bytes").is_some());
}
