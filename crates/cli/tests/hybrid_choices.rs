//! `statecheck analyse --depth N` (docs/hybrid.md): every sequence of discrete choices up to
//! N, with the exact times at which each sensor's zone is entered and left, checked against
//! the times derived by hand in the models' comments (`tests/hybrid/two_speed.sc`,
//! `interrupted.sc`, `feeder_loop.sc`).

use serde_json::Value;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn path(name: &str) -> String {
    format!("{}/../../tests/hybrid/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// `analyse FILE --depth D --json` plus `extra`: (exit code, the JSON).
fn analyse(file: &str, depth: &str, extra: &[&str]) -> (i32, Value) {
    let p = path(file);
    let mut args = vec!["analyse", p.as_str(), "--depth", depth, "--json"];
    args.extend(extra);
    let out = Command::new(BIN)
        .args(&args)
        .output()
        .expect("statecheck runs");
    let text = String::from_utf8_lossy(&out.stdout);
    let v = serde_json::from_str(&text)
        .unwrap_or_else(|e| panic!("{e}: {text}{}", String::from_utf8_lossy(&out.stderr)));
    (out.status.code().unwrap_or(-1), v)
}

/// The choices of a run as `tick:input=value` strings, the inputs each choice changed only.
fn choices(run: &Value) -> Vec<String> {
    let mut out = Vec::new();
    for c in run["choices"].as_array().expect("choices") {
        for k in c["changed"].as_array().expect("changed") {
            let k = k.as_str().unwrap_or("");
            let v = c["inputs"][k].as_str().unwrap_or("");
            out.push(format!("{}:{k}={v}", c["tick"]));
        }
    }
    out
}

/// A zone event: (sensor, event, seconds, expected tick, model tick, on grid).
type Zone = (String, String, String, Option<u64>, Option<u64>, bool);

/// The zone events of a run.
fn zones(run: &Value) -> Vec<Zone> {
    run["zones"]
        .as_array()
        .expect("zones")
        .iter()
        .map(|z| {
            (
                z["sensor"].as_str().unwrap_or("").to_string(),
                z["event"].as_str().unwrap_or("").to_string(),
                z["seconds"].as_str().unwrap_or("").to_string(),
                z["expected_tick"].as_u64(),
                z["model_tick"].as_u64(),
                z["on_grid"].as_bool().unwrap_or(false),
            )
        })
        .collect()
}

fn z(s: &str, e: &str, secs: &str, exp: u64, model: u64) -> Zone {
    (
        s.into(),
        e.into(),
        secs.into(),
        Some(exp),
        Some(model),
        exp == model,
    )
}

#[test]
fn light_then_heavy_collides_118_75_s_after_the_heavy_push() {
    // Depth 3: push, retract, push again (tests/hybrid/two_speed.sc). At each choice the four
    // valuations of (light, heavy): pushing light or heavy first, then at the third choice
    // nothing, heavy or light: 2 × 3 = 6 sequences.
    let (code, v) = analyse("two_speed.sc", "3", &[]);
    assert_eq!(code, 0);
    assert_eq!(v["complete"], true);
    assert_eq!(v["tick_seconds"], "1.25");
    let runs = v["runs"].as_array().expect("runs");
    assert_eq!(runs.len(), 6, "{v:#}");
    let lh = runs
        .iter()
        .find(|r| {
            let c = choices(r);
            c.first().map(String::as_str) == Some("1:feeder.light=true")
                && c.last().map(String::as_str) == Some("62:feeder.heavy=true")
        })
        .expect("light then heavy");
    // Every time from the model's comment; every one is on the grid.
    assert_eq!(
        zones(lh),
        vec![
            z("feeder.at_home", "left", "3.75", 4, 4),
            z("feeder.in_area", "entered", "48.75", 39, 39),
            z("feeder.in_area", "left", "52.5", 43, 43),
            z("feeder.at_home", "entered", "75", 60, 60),
            z("feeder.at_home", "left", "83.75", 68, 68),
            z("feeder.in_area", "entered", "196.25", 157, 157),
        ]
    );
    // The heavy push began at 77.5 s: the area is entered 118.75 s later.
    assert_eq!(lh["switches"][3]["seconds"], "77.5");
    assert_eq!(lh["switches"][3]["state"], "Heavy");
    // The invariant `outside` is violated first by the light push, at tick 39.
    assert_eq!(lh["violations"][0]["tick"], 39);
    let heavy_first = runs
        .iter()
        .find(|r| choices(r).first().map(String::as_str) == Some("1:feeder.heavy=true"))
        .expect("heavy first");
    // Heavy first: at_home left at 1.25 + 6.25 = 7.5 s, the area entered at 120 s.
    assert_eq!(
        zones(heavy_first)[..2],
        [
            z("feeder.at_home", "left", "7.5", 7, 7),
            z("feeder.in_area", "entered", "120", 96, 96),
        ]
    );
}

#[test]
fn an_interrupted_motion_is_reported_off_the_grid() {
    // tests/hybrid/interrupted.sc: go, then at tick 9 go again (or not).
    let (code, v) = analyse("interrupted.sc", "2", &[]);
    assert_eq!(code, 0);
    let runs = v["runs"].as_array().expect("runs");
    // go (tick 1), then go held or withdrawn at tick 9: two sequences.
    assert_eq!(runs.len(), 2);
    assert_eq!(runs[0]["choices"][1]["tick"], 9);
    let resumed = runs
        .iter()
        .find(|r| r["choices"][1]["inputs"]["lin.go"] == "true")
        .unwrap_or_else(|| panic!("{v:#}"));
    // Entered at 12 s continuously; the model's sensor changes only in tick 14.
    let zs = zones(resumed);
    assert_eq!(zs, vec![z("lin.far", "entered", "12", 12, 14)]);
    assert!(!zs[0].5);
    assert!(resumed["zones"][0]["status"]
        .as_str()
        .is_some_and(|s| s.starts_with("model differs")));
}

#[test]
fn the_closed_loop_feeder_retracts_by_itself() {
    // tests/hybrid/feeder_loop.sc and push.scn's derivation: the controller retracts at
    // 52.5 s; at_end is left at 53.75 s, at_home entered at 76.25 s.
    let (_, v) = analyse("feeder_loop.sc", "3", &["--system", "Loop"]);
    let first = &v["runs"][0];
    assert_eq!(choices(first)[0], "1:ctrl.start=true");
    let zs = zones(first);
    assert!(
        zs.contains(&z("feeder.at_end", "entered", "48.75", 39, 39)),
        "{zs:?}"
    );
    assert!(
        zs.contains(&z("feeder.at_end", "left", "53.75", 44, 44)),
        "{zs:?}"
    );
    assert!(
        zs.contains(&z("feeder.at_home", "entered", "76.25", 61, 61)),
        "{zs:?}"
    );
}

#[test]
fn too_many_sequences_are_cut_and_said_so() {
    // With 3 sequences per push cycle at least, depth 12 has more than 5.
    let (code, v) = analyse("two_speed.sc", "12", &["--max-runs", "5"]);
    assert_eq!(code, 3);
    assert_eq!(v["complete"], false);
    assert_eq!(v["runs"].as_array().map(Vec::len), Some(5));
    assert!(v["truncated"]
        .as_str()
        .is_some_and(|t| t.contains("first 5")));
}

#[test]
fn parameterised_copies_are_analysed_with_their_own_speeds() {
    // tests/hybrid/params.sc: Mover(20) at 2 %/s and Mover(8) at 0.8 %/s, both started by
    // the first choice (both `go` in tick 1): at_end (95 %) at 1.25 + 47.5 = 48.75 s (tick 39)
    // for the light one and 1.25 + 118.75 = 120 s (tick 96) for the heavy one; each
    // invariant is first violated then.
    let (_, v) = analyse("params.sc", "2", &[]);
    let runs = v["runs"].as_array().expect("runs");
    let both = runs
        .iter()
        .find(|r| {
            let c = choices(r);
            c.contains(&"1:light.go=true".to_string()) && c.contains(&"1:heavy.go=true".to_string())
        })
        .unwrap_or_else(|| panic!("{v:#}"));
    let zs = zones(both);
    assert_eq!(
        zs[..2],
        [
            z("light.at_end", "entered", "48.75", 39, 39),
            z("heavy.at_end", "entered", "120", 96, 96),
        ]
    );
    let viol: Vec<(String, u64)> = both["violations"]
        .as_array()
        .expect("violations")
        .iter()
        .map(|x| {
            (
                x["property"].as_str().unwrap_or("").to_string(),
                x["tick"].as_u64().unwrap_or(0),
            )
        })
        .collect();
    assert_eq!(
        viol,
        vec![("light_end".to_string(), 39), ("heavy_end".to_string(), 96)]
    );
}
