//! The Workpiece Distribution Station (issue 18; examples/wds/, docs/case-studies/wds.md).
//!
//! Every expectation comes from examples/wds/expected.json, whose verdicts and ticks are
//! derived by hand in examples/wds/README.md:
//! - the configuration matrix of wds.sc and the orderings of orderings.sc, verdict by verdict
//!   (`verify --all-configs --json`, explicit engine);
//! - the collision exists only for a light workpiece followed by a heavy one: every other
//!   ordering forced in orderings.sc has no counterexample;
//! - the collision counterexamples replayed by `sim`: the Feeder enters its area 95 ticks
//!   (118.75 s) after the heavy workpiece becomes available;
//! - BMC agrees with the explicit engine on every ordering: the same shortest collision, and
//!   no violation within the explicit engine's whole exploration depth where it proved.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn wds(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/wds")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

fn expected() -> Value {
    let text = std::fs::read_to_string(wds("expected.json")).expect("expected.json");
    serde_json::from_str(&text).expect("expected.json is JSON")
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("statecheck-wds-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Runs the binary; returns (exit code, stdout parsed as JSON).
fn run_json(args: &[&str]) -> (i32, Value) {
    let out = Command::new(BIN)
        .args(args)
        .output()
        .expect("statecheck runs");
    let v: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "{args:?}: not JSON ({e}): {} {}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    });
    (out.status.code().unwrap_or(-1), v)
}

/// `verify FILE --all-configs --engine explicit --json` against expected.json's verdicts.
fn check_matrix(file: &str) -> Value {
    let exp = expected();
    let want = &exp[file];
    let (code, got) = run_json(&[
        "verify",
        &wds(file),
        "--all-configs",
        "--engine",
        "explicit",
        "--json",
    ]);
    assert_eq!(got["system"], want["system"], "{file}: system");
    let want_cfgs = want["configurations"].as_object().expect("configurations");
    let got_cfgs = got["configurations"].as_array().expect("configurations");
    let names: Vec<&str> = got_cfgs
        .iter()
        .map(|c| c["configuration"].as_str().expect("name"))
        .collect();
    let want_names: Vec<&str> = want_cfgs.keys().map(String::as_str).collect();
    let mut sorted = names.clone();
    sorted.sort_unstable();
    let mut want_sorted = want_names.clone();
    want_sorted.sort_unstable();
    assert_eq!(sorted, want_sorted, "{file}: configurations");
    let mut any_violated = false;
    for c in got_cfgs {
        let name = c["configuration"].as_str().expect("name");
        let verdicts = want_cfgs[name].as_object().expect("verdicts");
        let results = c["results"].as_array().expect("results");
        assert_eq!(
            results.len(),
            verdicts.len(),
            "{file} {name}: the properties reported: {results:?}"
        );
        for r in results {
            let prop = r["property"].as_str().expect("property");
            let verdict = r["verdict"].as_str().expect("verdict");
            assert_eq!(
                Some(verdict),
                verdicts.get(prop).and_then(Value::as_str),
                "{file} {name} {prop}"
            );
            any_violated |= verdict == "violated";
        }
    }
    assert_eq!(code, if any_violated { 1 } else { 0 }, "{file}: exit code");
    got
}

#[test]
fn configuration_matrix_matches_expected() {
    check_matrix("wds.sc");
}

#[test]
fn only_light_then_heavy_collides() {
    let got = check_matrix("orderings.sc");
    // The same fact stated directly: among the forced orderings, a collision counterexample
    // exists exactly for light-then-heavy, with either Transfer.
    for c in got["configurations"].as_array().expect("configurations") {
        let name = c["configuration"].as_str().expect("name");
        let collision = c["results"]
            .as_array()
            .expect("results")
            .iter()
            .find(|r| r["property"] == "no_collision")
            .expect("no_collision row");
        let violated = collision["verdict"] == "violated";
        assert_eq!(violated, name.starts_with("lh_"), "{name}: {collision}");
    }
}

/// The first tick whose events include `event`, at or after `from`.
fn first_event(ticks: &[Value], event: &str, from: u64) -> Option<u64> {
    ticks.iter().find_map(|t| {
        let tick = t["tick"].as_u64()?;
        let has = t["events"].as_array()?.iter().any(|e| e == event);
        (tick >= from && has).then_some(tick)
    })
}

#[test]
fn collision_is_95_ticks_after_the_heavy_workpiece_is_available() {
    let exp = expected();
    let col = &exp["collision"];
    let tick_s = col["tick_s"].as_f64().expect("tick_s");
    let after = col["after_available_ticks"].as_u64().expect("ticks");
    // 95 ticks of 1.25 s: the paper's 118.75 s = 95 % / 0.8 %/s.
    assert_eq!(
        after as f64 * tick_s,
        col["after_available_s"].as_f64().expect("s")
    );
    let runs = col["runs"].as_object().expect("runs");
    assert_eq!(runs.len(), 4);
    for (key, want) in runs {
        let (file, config) = key.split_once(':').expect("FILE:CONFIG");
        let dir = temp_dir(config);
        let dir_s = dir.to_string_lossy().into_owned();
        let (code, v) = run_json(&[
            "verify",
            &wds(file),
            "--config",
            config,
            "--engine",
            "explicit",
            "--property",
            "no_collision",
            "--cex-dir",
            &dir_s,
            "--json",
        ]);
        assert_eq!(code, 1, "{key}: {v}");
        let row = &v["results"][0];
        assert_eq!(row["verdict"], "violated", "{key}: {row}");
        assert_eq!(row["depth"], want["depth"], "{key}: {row}");
        let scenario = dir.join("no_collision.scn");
        assert!(scenario.exists(), "{key}: no counterexample written");
        let (code, trace) = run_json(&[
            "sim",
            &wds(file),
            "--config",
            config,
            "--scenario",
            &scenario.to_string_lossy(),
            "--json",
        ]);
        assert_eq!(code, 4, "{key}: the replay stops at the violation");
        assert_eq!(trace["result"]["property"], "no_collision", "{key}");
        let collision = trace["result"]["tick"].as_u64().expect("tick");
        assert_eq!(
            collision,
            want["collision"].as_u64().expect("collision"),
            "{key}"
        );
        let ticks = trace["ticks"].as_array().expect("ticks");
        let taken = first_event(ticks, "s.tx.tr.took", 0).expect("the first workpiece taken");
        assert_eq!(taken, want["taken"].as_u64().expect("taken"), "{key}");
        let available = ticks
            .iter()
            .filter(|t| t["tick"].as_u64() > Some(taken))
            .find(|t| t["vars"]["s.st.mag.present"] == true)
            .and_then(|t| t["tick"].as_u64())
            .expect("the second workpiece available");
        assert_eq!(
            available,
            want["available"].as_u64().expect("available"),
            "{key}"
        );
        assert_eq!(collision - available, after, "{key}");
        // The heavy one: the workpiece the Feeder pushes when it enters its area.
        let last = ticks.last().expect("ticks");
        assert_eq!(last["vars"]["s.st.f.wp"], "HEAVY", "{key}");
        assert_eq!(last["vars"]["s.st.f.pos"], 95, "{key}");
        assert!(last["vars"]["s.tx.tr.pos"].as_u64() <= Some(5), "{key}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}

#[test]
fn bmc_agrees_with_the_explicit_engine_on_every_ordering() {
    let (_, explicit) = run_json(&[
        "verify",
        &wds("orderings.sc"),
        "--all-configs",
        "--engine",
        "explicit",
        "--property",
        "no_collision",
        "--json",
    ]);
    for c in explicit["configurations"]
        .as_array()
        .expect("configurations")
    {
        let name = c["configuration"].as_str().expect("name");
        let row = &c["results"][0];
        let depth = row["depth"].as_u64().expect("depth");
        // With START pinned and both workpieces fixed, each configuration has one run; the
        // explicit engine's depth is the tick from which nothing new is reached. BMC one tick
        // deeper either finds the same shortest collision or sees every reachable state.
        let bound = (depth + 1).to_string();
        let (_, bmc) = run_json(&[
            "verify",
            &wds("orderings.sc"),
            "--config",
            name,
            "--engine",
            "bmc",
            "--depth",
            &bound,
            "--property",
            "no_collision",
            "--json",
        ]);
        let b = &bmc["results"][0];
        if row["verdict"] == "violated" {
            assert_eq!(b["verdict"], "violated", "{name}: {b}");
            assert_eq!(b["depth"], row["depth"], "{name}: {b}");
        } else {
            assert_eq!(row["verdict"], "proved", "{name}: {row}");
            assert_eq!(b["verdict"], "bounded", "{name}: {b}");
            assert!(b["depth"].as_u64() > Some(depth), "{name}: {b}");
        }
    }
}

/// `analyse` on the hybrid Feeder and along the checked-in collision (README.md, "The motion,
/// discretized by the checker" and "The first collision"): pushing a heavy workpiece at
/// 0.8 %/s from 0 reaches 95 % at 95 / 0.8 = 118.75 s = 95 ticks of 1.25 s; along
/// collision_faulty_L.scn (START in tick 1, the heavy workpiece available in tick A = 65) the
/// Feeder enters 95 % in PushingHeavy at (65 + 95) × 1.25 s = 200 s, tick 160, and the
/// discretized model reaches it in the same tick (`exact`).
#[test]
fn analyse_reports_the_collision_zone_entry_exactly() {
    let (code, readings) = run_json(&["analyse", &wds("feeder.sc"), "--json"]);
    assert_eq!(code, 0, "{readings}");
    assert_eq!(readings["tick_seconds"], "1.25");
    let heavy = readings["variables"][0]["modes"]
        .as_array()
        .expect("modes")
        .iter()
        .find(|m| m["state"] == "PushingHeavy")
        .expect("PushingHeavy");
    assert_eq!(heavy["from"], 0);
    let at95 = heavy["readings"]
        .as_array()
        .expect("readings")
        .iter()
        .find(|r| r["point"] == 95)
        .expect("95");
    assert_eq!(
        (&at95["seconds"], &at95["ticks"]),
        (&"118.75".into(), &"95".into())
    );

    let (code, run) = run_json(&[
        "analyse",
        &wds("wds.sc"),
        "--system",
        "WDS:faulty_L_sensor",
        "--scenario",
        &wds("collision_faulty_L.scn"),
        "--json",
    ]);
    assert_eq!(code, 0, "{run}");
    let events = run["events"].as_array().expect("events");
    let enter = events
        .iter()
        .find(|e| e["instance"] == "s.st.f" && e["state"] == "PushingHeavy" && e["point"] == 95)
        .expect("the Feeder enters its area with the heavy workpiece");
    assert_eq!(enter["seconds"], "200", "{enter}");
    assert_eq!(enter["model_tick"], 160, "{enter}");
    assert_eq!(enter["status"], "exact", "{enter}");
    // Every critical point of the run is reached at a tick of the discretized model.
    assert!(events.iter().all(|e| e["status"] == "exact"), "{events:?}");
}
