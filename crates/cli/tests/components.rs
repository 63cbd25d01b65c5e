//! Parameterised chart types through the binary (docs/components.md): a system of two
//! instances of one parameterised chart gives the same verdicts, state counts and traces as
//! the same system with the arguments substituted by hand (`tests/components/counters*.sc`).

mod common;

use common::{run, summary_of, Summary};
use serde_json::Value;

/// (states, transitions, rows) of `verify --json`.
fn summary(file: &str, engine: &str) -> Summary {
    let (code, out, err) = run(&["verify", "--engine", engine, "--json", file]);
    // `sum` is violated: exit 1.
    assert_eq!(code, 1, "{err}");
    summary_of(&out)
}

#[test]
fn parameterised_counters_match_the_hand_substituted_system() {
    let (states, transitions, results) = summary("tests/components/counters.sc", "explicit");
    // By hand: a.n ranges over 0..=2 and b.n over 1..=3 independently (each steps on its own
    // event while below its maximum): 3 * 3 = 9 started states plus the state before the first
    // tick = 10; every state has 2 events, so 4 input vectors: 40 transitions.
    assert_eq!((states, transitions), (10, 40));
    let verdict = |n: &str| {
        results
            .iter()
            .find(|r| r.0 == n)
            .map(|r| (r.1.as_str(), r.2))
            .unwrap_or(("missing", None))
    };
    // a.n == 2 after two steps of a (ticks 1 and 2); b.n starts at 1 and never decreases;
    // a.n + b.n == 5 needs a.n == 2 and b.n == 3, both two steps away: tick 2.
    assert_eq!(verdict("a_full"), ("reachable", Some(2)));
    assert_eq!(verdict("b_low").0, "proved");
    assert_eq!(verdict("sum"), ("violated", Some(2)));
    assert_eq!(verdict("a.in_range").0, "proved");
    assert_eq!(verdict("b.in_range").0, "proved");
    let flat = summary("tests/components/counters_flat.sc", "explicit");
    assert_eq!((states, transitions, results), flat);
}

#[test]
fn the_sat_engines_agree_on_the_parameterised_counters() {
    let (_, _, results) = summary("tests/components/counters.sc", "bmc");
    let sum = results.iter().find(|r| r.0 == "sum").map(|r| r.1.clone());
    assert_eq!(sum.as_deref(), Some("violated"));
}

#[test]
fn a_parameterised_chart_simulates_like_its_hand_written_copy() {
    let scenario = "-\na.step\nb.step\na.step, b.step\n";
    let dir = std::env::temp_dir().join(format!("statecheck-components-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let scn = dir.join("steps.scn");
    std::fs::write(&scn, scenario).expect("write scenario");
    let scn = scn.to_string_lossy().into_owned();
    let (c1, t1, e1) = run(&["sim", "tests/components/counters.sc", "--scenario", &scn]);
    let (c2, t2, e2) = run(&[
        "sim",
        "tests/components/counters_flat.sc",
        "--scenario",
        &scn,
    ]);
    // At tick 3 a.n + b.n = 5 breaks `sum`: exit 4 (a property violated during sim).
    assert_eq!((c1, c2), (4, 4), "{e1}{e2}");
    assert!(e1.contains("`sum` violated at tick 3"), "{e1}");
    assert_eq!(t1, t2);
    // By hand: tick 0 enters the charts (a.n = 0, b.n = 1); a steps in ticks 1 and 3
    // (0 -> 1 -> 2), b in ticks 2 and 3 (1 -> 2 -> 3).
    assert!(t1.contains("a.n=2") && t1.contains("b.n=3"), "{t1}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn formatting_keeps_parameters_and_arguments() {
    let (code, out, err) = run(&["fmt", "--check", "tests/components/counters.sc"]);
    assert_eq!(code, 0, "{out}{err}");
}

/// One configuration's row: its name, (property, verdict) pairs, and its state count.
type ConfigRow = (String, Vec<(String, String)>, u64);

/// `--all-configs --json` on tests/components/sensors.sc: the exit code and the rows.
fn matrix() -> (i32, Vec<ConfigRow>) {
    let (code, out, err) = run(&[
        "verify",
        "--engine",
        "explicit",
        "--all-configs",
        "--json",
        "tests/components/sensors.sc",
    ]);
    let v: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}{err}"));
    let rows = v["configurations"]
        .as_array()
        .map(|a| {
            a.iter()
                .map(|c| {
                    let cells = c["results"]
                        .as_array()
                        .map(|rs| {
                            rs.iter()
                                .map(|r| {
                                    (
                                        r["property"].as_str().unwrap_or("?").to_string(),
                                        r["verdict"].as_str().unwrap_or("?").to_string(),
                                    )
                                })
                                .collect()
                        })
                        .unwrap_or_default();
                    (
                        c["configuration"].as_str().unwrap_or("?").to_string(),
                        cells,
                        c["states"].as_u64().unwrap_or(0),
                    )
                })
                .collect()
        })
        .unwrap_or_default();
    (code, rows)
}

#[test]
fn all_configs_prints_the_hand_derived_matrix() {
    let (code, rows) = matrix();
    // By hand (sensors.sc): with `ideal` present == (raw > 3) in every tick, so the alarm
    // follows the reading; `faulty` (raw = 4, stuck) and `sensitive` (threshold 0, raw = 1)
    // break it in tick 0. The alarm can be on in all three. Every configuration has 3 states:
    // before the first tick, and (present, alarm) in {(false, false), (true, true)}.
    assert_eq!(code, 1, "a configuration violates a property");
    let want = [
        ("ideal", "proved"),
        ("faulty", "violated"),
        ("sensitive", "violated"),
    ];
    assert_eq!(rows.len(), want.len(), "{rows:?}");
    for ((config, follows), (name, cells, states)) in want.iter().zip(&rows) {
        assert_eq!(name, config);
        let verdict = |p: &str| {
            cells
                .iter()
                .find(|c| c.0 == p)
                .map(|c| c.1.clone())
                .unwrap_or_default()
        };
        assert_eq!(verdict("alarm_follows"), *follows, "{config}");
        assert_eq!(verdict("alarm_on"), "reachable", "{config}");
        assert_eq!(*states, 3, "{config}");
    }
}

#[test]
fn config_selects_one_configuration() {
    let one = |config: &str| {
        let (code, out, err) = run(&[
            "verify",
            "--engine",
            "explicit",
            "--json",
            "--config",
            config,
            "tests/components/sensors.sc",
        ]);
        let v: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}{err}"));
        (code, v["stats"]["transitions"].as_u64().unwrap_or(0))
    };
    // 3 states each; `ideal` has the 10 values of raw per tick, `faulty` also `stuck`: 20.
    assert_eq!(one("ideal"), (0, 30));
    assert_eq!(one("faulty"), (1, 60));
    // The counterexample says which configuration it belongs to.
    let (_, text, _) = run(&[
        "verify",
        "--engine",
        "explicit",
        "--config",
        "faulty",
        "tests/components/sensors.sc",
    ]);
    assert!(
        text.contains("counterexample for `alarm_follows` in configuration `faulty`"),
        "{text}"
    );
    let (code, _, err) = run(&["verify", "--config", "nope", "tests/components/sensors.sc"]);
    assert_eq!(code, 2);
    assert!(
        err.contains("has no configuration `nope`") && err.contains("ideal, faulty, sensitive"),
        "{err}"
    );
}

#[test]
fn the_plain_system_is_its_first_configuration() {
    let (_, a, _) = run(&[
        "verify",
        "--engine",
        "explicit",
        "--json",
        "tests/components/sensors.sc",
    ]);
    let (_, b, _) = run(&[
        "verify",
        "--engine",
        "explicit",
        "--json",
        "--config",
        "ideal",
        "tests/components/sensors.sc",
    ]);
    let strip = |s: &str| -> Value {
        let mut v: Value = serde_json::from_str(s).unwrap_or(Value::Null);
        // Times and memory differ from run to run.
        v["stats"] = Value::Null;
        if let Some(rs) = v["results"].as_array_mut() {
            for r in rs {
                r["time_s"] = Value::Null;
            }
        }
        v
    };
    assert_eq!(strip(&a), strip(&b));
    assert_ne!(strip(&a), Value::Null);
}

#[test]
fn dead_design_in_an_imported_file_names_that_file_and_line() {
    let (code, out, err) = run(&[
        "verify",
        "--engine",
        "explicit",
        "--json",
        "tests/components/dead_imported.sc",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"));
    // By hand (tests/components/lib/latch.sc): `state Never;` is line 8, `Never` at column 9;
    // the transition `on [false] -> Never;` of line 7 starts at column 14.
    let dead: Vec<(String, String, u64, u64)> = v["stats"]["dead"]
        .as_array()
        .map(|a| {
            a.iter()
                .map(|d| {
                    (
                        d["label"].as_str().unwrap_or("?").to_string(),
                        d["file"].as_str().unwrap_or("?").to_string(),
                        d["line"].as_u64().unwrap_or(0),
                        d["col"].as_u64().unwrap_or(0),
                    )
                })
                .collect()
        })
        .unwrap_or_default();
    let lib = "tests/components/lib/latch.sc".to_string();
    assert_eq!(
        dead,
        vec![
            ("Never".to_string(), lib.clone(), 8, 9),
            ("On -> Never".to_string(), lib, 7, 14),
        ]
    );
    let (_, text, _) = run(&[
        "verify",
        "--engine",
        "explicit",
        "tests/components/dead_imported.sc",
    ]);
    assert!(
        text.contains("l: Never (tests/components/lib/latch.sc:8:9)"),
        "{text}"
    );
}

#[test]
fn sim_runs_a_configuration() {
    let dir =
        std::env::temp_dir().join(format!("statecheck-components-sim-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let scn = dir.join("one.scn");
    std::fs::write(&scn, "-\ns.raw = 1\n").expect("write scenario");
    let scn = scn.to_string_lossy().into_owned();
    let sim = |config: &str| {
        run(&[
            "sim",
            "tests/components/sensors.sc",
            "--config",
            config,
            "--scenario",
            &scn,
        ])
    };
    // By hand: raw = 1 in tick 1. `sensitive` (threshold 0) reports it present, so the alarm
    // goes on while raw > 3 is false: `alarm_follows` is violated in tick 1 (exit 4); `ideal`
    // (threshold 3) does not.
    let (code, out, err) = sim("sensitive");
    assert_eq!(code, 4, "{out}{err}");
    assert!(err.contains("`alarm_follows` violated at tick 1"), "{err}");
    let (code, out, err) = sim("ideal");
    assert_eq!(code, 0, "{out}{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
