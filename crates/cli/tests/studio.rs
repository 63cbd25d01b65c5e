//! The studio runs what `statecheck sim` runs: a session driven through the studio's protocol
//! handler (steps with held and pulsed inputs, random ticks, step back and branch, counter-
//! examples of `statecheck verify --cex-dir` loaded), saved as a scenario, replays under
//! `statecheck sim --scenario --json` to exactly the ticks the page was sent.

use serde_json::{json, Value};
use statecheck_studio::{load, server::handle, session::Session};
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("statecheck-studio-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

fn sim_json(model: &str, system: Option<&str>, scn: &Path) -> Value {
    let mut args = vec![
        "sim",
        model,
        "--scenario",
        scn.to_str().expect("path"),
        "--json",
    ];
    if let Some(s) = system {
        args.extend(["--system", s]);
    }
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(root())
        .args(&args)
        .output()
        .expect("statecheck runs");
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "sim --json: {e}; stderr: {}",
            String::from_utf8_lossy(&out.stderr)
        )
    })
}

/// A studio session on a model, and the records the page holds (what it was sent,
/// truncated on `back` like the page does).
struct Page {
    session: Option<Session>,
    records: Vec<Value>,
    stop: Value,
}

impl Page {
    fn open(model: &str, system: Option<&str>) -> Page {
        let path = root().join(model);
        let loaded = load::load(path.to_str().expect("path"), system)
            .unwrap_or_else(|d| panic!("model checks: {d:?}"));
        Page {
            session: Some(Session::new(loaded)),
            records: Vec::new(),
            stop: Value::Null,
        }
    }

    fn send(&mut self, req: Value) -> Value {
        let r = handle(&mut self.session, &req.to_string());
        assert_ne!(r["type"], "error", "{req} -> {r}");
        if r["type"] == "state" {
            if let Some(t) = r["truncate"].as_u64() {
                self.records.truncate(t as usize);
            }
            self.records
                .extend(r["ticks"].as_array().expect("ticks").iter().cloned());
            self.stop = r["run"]["stop"].clone();
        }
        r
    }

    /// Save the scenario, replay it with `statecheck sim --json`, compare tick by tick.
    fn check_against_sim(&mut self, model: &str, system: Option<&str>, name: &str) -> Value {
        let saved = self.send(json!({"op": "save"}));
        let file = temp(name);
        std::fs::write(&file, saved["text"].as_str().expect("text")).expect("write");
        let sim = sim_json(model, system, &file);
        let ticks = sim["ticks"].as_array().expect("sim ticks");
        assert_eq!(ticks.len(), self.records.len(), "tick count");
        for (page, s) in self.records.iter().zip(ticks) {
            for key in ["tick", "time", "active", "vars", "events"] {
                assert_eq!(page[key], s[key], "tick {}: `{key}` differs", s["tick"]);
            }
        }
        sim
    }
}

#[test]
fn fam_closed_loop_session_replays_in_sim() {
    let model = "examples/fam/fam_system.sc";
    let mut p = Page::open(model, None);
    p.send(json!({"op": "step", "n": 40, "set": {"ctrl.ccm": 1000}}));
    p.send(json!({"op": "step", "n": 1, "pulse": {"fam.stallNow": true}}));
    p.send(json!({"op": "step", "n": 30}));
    // Time travel: back to 20 and branch with other inputs.
    p.send(json!({"op": "back", "tick": 20}));
    p.send(
        json!({"op": "step", "n": 25, "set": {"ctrl.ccm": 500}, "pulse": {"bus.corrupt": true}}),
    );
    p.send(json!({"op": "random", "n": 60, "seed": 7}));
    p.send(json!({"op": "back", "tick": 90}));
    p.send(json!({"op": "forward", "n": 5}));
    // Random inputs under the system's assumes may run out of draws before 60 ticks (sim's
    // generator gives up after MAX_TRIES); the page holds exactly what the server ran.
    let r = p.send(json!({"op": "set", "set": {}}));
    assert_eq!(
        p.records.len() as u64,
        r["run"]["ticks"].as_u64().expect("ticks")
    );
    let sim = p.check_against_sim(model, None, "fam.scn");
    assert_eq!(sim["result"]["status"], "completed");
}

#[test]
fn fam5_random_session_replays_in_sim() {
    let model = "examples/fam/fam_system5.sc";
    let mut p = Page::open(model, None);
    p.send(json!({"op": "random", "n": 120, "seed": 11}));
    p.check_against_sim(model, None, "fam5.scn");
}

#[test]
fn linear_drive_session_replays_in_sim() {
    let model = "examples/linear_drive/linear_drive.sc";
    let mut p = Page::open(model, None);
    p.send(json!({"op": "random", "n": 80, "seed": 3}));
    p.send(json!({"op": "back", "tick": 33}));
    p.send(json!({"op": "random", "n": 40, "seed": 4}));
    p.check_against_sim(model, None, "linear.scn");
}

#[test]
fn a_counterexample_from_verify_replays_to_its_violating_tick() {
    let model = "examples/fam/fam_alone.sc";
    let dir = temp("cex");
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(root())
        .args([
            "verify",
            model,
            "--system",
            "FamAloneSmall",
            "--property",
            "fam_cof_with_notcalib",
            "--cex-dir",
            dir.to_str().expect("path"),
        ])
        .output()
        .expect("verify runs");
    // Exit 1: the property is violated (examples/fam/expected.json: "violated").
    assert_eq!(
        out.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let cex = std::fs::read_to_string(dir.join("fam_cof_with_notcalib.scn")).expect("cex file");
    let mut p = Page::open(model, Some("FamAloneSmall"));
    p.send(json!({"op": "load_scenario", "text": cex}));
    assert_eq!(p.stop["status"], "violated");
    assert_eq!(p.stop["property"], "fam_cof_with_notcalib");
    let sim = p.check_against_sim(model, Some("FamAloneSmall"), "cex_saved.scn");
    assert_eq!(sim["result"]["status"], "violated");
    assert_eq!(p.stop["tick"], sim["result"]["tick"]);
    assert_eq!(p.stop["message"], sim["result"]["message"]);
}
