//! `verify --symmetry` end to end: the state counts of `tests/verify/symmetry.sc` derived by
//! hand in the model, equal verdicts with and without it, every counterexample replayed by
//! `sim` to its own violation, and W0317 naming the property that breaks the symmetry. On the
//! SAT engines: one member per family checked (the others' rows name it in `symmetry_of`),
//! the others' counterexamples (its run with two elements exchanged) replayed to their own
//! member, proofs for every member, and the same verdicts as without symmetry.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn statecheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("statecheck runs")
}

/// `verify TARGET… --engine explicit --json --threads 1 EXTRA…`, which must exit 1 (every
/// model here violates a property): its JSON and its standard error.
fn explicit(target: &[&str], extra: &[&str]) -> (serde_json::Value, String) {
    let mut args = vec!["verify"];
    args.extend(target);
    args.extend(["--engine", "explicit", "--json", "--threads", "1"]);
    args.extend(extra);
    let out = statecheck(&args);
    assert_eq!(out.status.code(), Some(1), "{target:?} {extra:?}");
    let v = serde_json::from_slice(&out.stdout).expect("json");
    (v, String::from_utf8_lossy(&out.stderr).into_owned())
}

fn verify(system: &str, extra: &[&str]) -> (serde_json::Value, String) {
    explicit(&["tests/verify/symmetry.sc", "--system", system], extra)
}

#[test]
fn symmetry_stores_orbits_and_its_counterexamples_replay() {
    let (full, _) = verify("Counters", &["--no-symmetry"]);
    let (plain, _) = verify("Counters", &[]);
    let dir = std::env::temp_dir().join(format!("statecheck-symmetry-{}", std::process::id()));
    let d = dir.to_string_lossy().into_owned();
    let (red, _) = verify("Counters", &["--symmetry", "--cex-dir", &d]);
    assert_eq!(full["stats"]["states"], 28);
    assert_eq!(plain["stats"]["states"], 28, "off by default");
    assert_eq!(red["stats"]["states"], 11);
    assert_eq!(red["stats"]["symmetry"], true);
    let verdicts = |v: &serde_json::Value| -> Vec<(String, String, u64)> {
        v["results"]
            .as_array()
            .expect("results")
            .iter()
            .map(|r| {
                (
                    r["property"].as_str().unwrap_or("").to_string(),
                    r["verdict"].as_str().unwrap_or("").to_string(),
                    r["depth"].as_u64().unwrap_or(0),
                )
            })
            .collect()
    };
    assert_eq!(verdicts(&full), verdicts(&red));
    for i in 0..3 {
        let name = format!("a[{i}].below");
        // (`--cex-dir` writes `a[0].below` as `a_0__below.scn`.)
        let scn = dir.join(format!("a_{i}__below.scn"));
        let scn = scn.to_string_lossy().into_owned();
        let out = statecheck(&[
            "sim",
            "tests/verify/symmetry.sc",
            "--system",
            "Counters",
            "--scenario",
            &scn,
            "--json",
        ]);
        // Ticks count from 0: the third tick is tick 2, where element i's counter is 2 (sim
        // stops at the first violation it sees, which may be another element's in the same
        // tick: a run that moves two counters together violates both).
        assert_eq!(out.status.code(), Some(4), "{name}");
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("sim json");
        let ticks = v["ticks"].as_array().expect("ticks");
        let last = ticks.last().expect("a tick");
        assert_eq!(last["tick"], 2, "{name}");
        assert_eq!(last["vars"][format!("a[{i}].c")], 2, "{name}: {v}");
        assert_eq!(v["result"]["status"], "violated", "{name}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn workers_with_timers_and_monitors_keep_their_verdicts() {
    let (full, _) = verify("Workers", &["--no-symmetry"]);
    let dir = std::env::temp_dir().join(format!("statecheck-symmetry-w-{}", std::process::id()));
    let d = dir.to_string_lossy().into_owned();
    let (red, _) = verify("Workers", &["--symmetry", "--cex-dir", &d]);
    assert_eq!(red["stats"]["symmetry"], true);
    assert!(red["stats"]["states"].as_u64() < full["stats"]["states"].as_u64());
    let rows = |v: &serde_json::Value| -> Vec<String> {
        let mut r: Vec<String> = v["results"]
            .as_array()
            .expect("results")
            .iter()
            .map(|r| format!("{} {} {}", r["property"], r["verdict"], r["depth"]))
            .collect();
        r.sort();
        r
    };
    assert_eq!(rows(&full), rows(&red));
    for i in 0..3 {
        let scn = dir.join(format!("w_{i}__done.scn"));
        let out = statecheck(&[
            "sim",
            "tests/verify/symmetry.sc",
            "--system",
            "Workers",
            "--scenario",
            &scn.to_string_lossy(),
            "-q",
        ]);
        assert_eq!(out.status.code(), Some(4), "w[{i}].done");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(&format!("`w[{i}].done` violated")), "{err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_property_naming_one_element_is_diagnosed() {
    let (v, err) = verify("Named", &["--symmetry"]);
    assert!(err.contains("W0317") && err.contains("`first`"), "{err}");
    assert_eq!(v["stats"]["symmetry"], false);
    assert_eq!(v["stats"]["states"], 28);
}

/// `verify tests/verify/symmetry.sc --system SYSTEM --engine ENGINE --json` with `extra`; the
/// exit code must be 0 or 1 (all hold, or some violated).
fn verify_sat(system: &str, engine: &str, extra: &[&str]) -> serde_json::Value {
    let mut args = vec![
        "verify",
        "tests/verify/symmetry.sc",
        "--system",
        system,
        "--engine",
        engine,
        "--json",
    ];
    args.extend(extra);
    let out = statecheck(&args);
    assert!(
        matches!(out.status.code(), Some(0 | 1)),
        "{system} {engine} {extra:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("json")
}

fn results(v: &serde_json::Value) -> &Vec<serde_json::Value> {
    v["results"].as_array().expect("results")
}

/// Per row: property, verdict, depth.
fn verdicts(v: &serde_json::Value) -> Vec<(String, String, u64)> {
    results(v)
        .iter()
        .map(|r| {
            (
                r["property"].as_str().unwrap_or("").to_string(),
                r["verdict"].as_str().unwrap_or("").to_string(),
                r["depth"].as_u64().unwrap_or(u64::MAX),
            )
        })
        .collect()
}

/// Per row: the member it was answered from (`symmetry_of`), if any.
fn symmetry_of(v: &serde_json::Value) -> Vec<Option<String>> {
    results(v)
        .iter()
        .map(|r| r["symmetry_of"].as_str().map(str::to_string))
        .collect()
}

/// `sim --json` of a written counterexample or witness: exit code, last tick, the value of
/// `var` at the last tick, and the property `sim` stopped at (empty when none).
fn replay(system: &str, scn: &Path, var: &str) -> (Option<i32>, u64, i64, String) {
    let out = statecheck(&[
        "sim",
        "tests/verify/symmetry.sc",
        "--system",
        system,
        "--scenario",
        &scn.to_string_lossy(),
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("sim json");
    let ticks = v["ticks"].as_array().expect("ticks");
    let last = ticks.last().expect("a tick");
    (
        out.status.code(),
        last["tick"].as_u64().unwrap_or(u64::MAX),
        last["vars"][var].as_i64().unwrap_or(-1),
        v["result"]["property"].as_str().unwrap_or("").to_string(),
    )
}

/// `Counters` on BMC, k-induction and IC3 with `--symmetry`: by hand (the model's comments),
/// every `a[k].below` is violated with 3 ticks (tick 0 starts, element k's `inc` at ticks 1
/// and 2 makes its counter 2 at tick 2), as without symmetry. Only `a[0].below` is given to
/// the engine: `a[1].below` and `a[2].below` name it in `symmetry_of` (without symmetry no row
/// does). Each written counterexample replays in `sim`: minimised, it stops at its own member
/// at tick 2; as the engine gave it (`--no-minimise`: `a[0].below`'s run with elements 0 and k
/// exchanged, which may move other counters too), its last tick is 2 with element k's counter
/// at 2.
#[test]
fn sat_engines_check_one_member_per_family_and_counterexamples_replay() {
    for engine in ["bmc", "kind", "ic3"] {
        let full = verify_sat("Counters", engine, &["--depth", "10"]);
        for minimise in [true, false] {
            let dir = std::env::temp_dir().join(format!(
                "statecheck-symmetry-{engine}-{minimise}-{}",
                std::process::id()
            ));
            let d = dir.to_string_lossy().into_owned();
            let mut extra = vec!["--depth", "10", "--symmetry", "--cex-dir", &d];
            if !minimise {
                extra.push("--no-minimise");
            }
            let red = verify_sat("Counters", engine, &extra);
            assert_eq!(verdicts(&full), verdicts(&red), "{engine}");
            assert_eq!(
                symmetry_of(&red)[..3],
                [None, Some("a[0].below".into()), Some("a[0].below".into())],
                "{engine}"
            );
            assert!(symmetry_of(&full).iter().all(Option::is_none), "{engine}");
            for k in 0..3 {
                let name = format!("a[{k}].below");
                let row = &results(&red)[k];
                assert_eq!(row["property"], name.as_str());
                assert_eq!(
                    (
                        row["verdict"].as_str(),
                        row["depth"].as_u64(),
                        row["tick"].as_u64()
                    ),
                    (Some("violated"), Some(3), Some(2)),
                    "{engine} {name}"
                );
                assert!(row.get("replay_note").is_none(), "{engine} {name}: {row}");
                let (code, tick, c, stopped) = replay(
                    "Counters",
                    &dir.join(format!("a_{k}__below.scn")),
                    &format!("a[{k}].c"),
                );
                assert_eq!(
                    (code, tick, c),
                    (Some(4), 2, 2),
                    "{engine} {name} {minimise}"
                );
                if minimise {
                    assert_eq!(stopped, name, "{engine}");
                }
            }
            let _ = std::fs::remove_dir_all(&dir);
        }
    }
}

/// `Pairs` (four elements): by hand (the model's comments) `p[k].same` (x == y, inductive)
/// is proved for every k by k-induction, IC3 and CEGAR, and `bounded` at the depth given by
/// BMC, with and without symmetry; `p[k].full` (x == 3) is reachable with 4 ticks, and each
/// member's witness replays to its own element's `x` at 3 at tick 3.
#[test]
fn sat_engines_prove_a_family_for_every_member() {
    for engine in ["bmc", "kind", "ic3", "cegar"] {
        let dir = std::env::temp_dir().join(format!(
            "statecheck-symmetry-pairs-{engine}-{}",
            std::process::id()
        ));
        let d = dir.to_string_lossy().into_owned();
        let full = verify_sat("Pairs", engine, &["--depth", "6"]);
        let red = verify_sat(
            "Pairs",
            engine,
            &["--depth", "6", "--symmetry", "--cex-dir", &d],
        );
        let held = if engine == "bmc" { "bounded" } else { "proved" };
        for v in [&full, &red] {
            let rows = verdicts(v);
            for k in 0..4 {
                let same = rows.iter().find(|r| r.0 == format!("p[{k}].same"));
                assert_eq!(same.map(|r| r.1.as_str()), Some(held), "{engine} {k}");
                let full = rows.iter().find(|r| r.0 == format!("p[{k}].full"));
                assert_eq!(
                    full.map(|r| (r.1.as_str(), r.2)),
                    Some(("reachable", 4)),
                    "{engine} {k}"
                );
            }
        }
        assert_eq!(verdicts(&full), verdicts(&red), "{engine}");
        let of = symmetry_of(&red);
        assert_eq!(
            of.iter().filter(|o| o.is_some()).count(),
            6,
            "{engine}: {of:?}"
        );
        for k in 0..4 {
            // A witness is no violation: `sim` runs it to the end (exit 0), tick 3, where
            // element k's `x` is 3.
            let (code, tick, x, _) = replay(
                "Pairs",
                &dir.join(format!("p_{k}__full.scn")),
                &format!("p[{k}].x"),
            );
            assert_eq!((code, tick, x), (Some(0), 3, 3), "{engine} p[{k}].full");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}

/// Every system of `tests/verify/symmetry.sc` (the symmetric `Counters`, `Workers` and
/// `Pairs`; `Named`, whose property breaks the symmetry; `Interleaved`, which the step test
/// rejects) on every SAT engine and `auto`:
/// the verdicts and depths with `--symmetry` are those without (under `auto` the verdicts
/// only: the depth of a proof depends on which engine answers first).
#[test]
fn sat_verdicts_with_symmetry_equal_those_without() {
    for system in ["Counters", "Workers", "Pairs", "Named", "Interleaved"] {
        for engine in ["bmc", "kind", "ic3", "cegar", "auto"] {
            let full = verify_sat(system, engine, &["--depth", "8"]);
            let red = verify_sat(system, engine, &["--depth", "8", "--symmetry"]);
            let (mut a, mut b) = (verdicts(&full), verdicts(&red));
            if engine == "auto" {
                for r in a.iter_mut().chain(b.iter_mut()) {
                    r.2 = 0;
                }
            }
            assert_eq!(a, b, "{system} {engine}");
            let reduced = symmetry_of(&red).iter().filter(|o| o.is_some()).count();
            if system == "Named" || system == "Interleaved" {
                assert_eq!(reduced, 0, "{system} {engine}");
            } else if engine != "auto" {
                assert!(reduced > 0, "{system} {engine}");
            }
        }
    }
}

/// `Interleaved`: the detection accepts the array, but the scheduler input names elements by
/// index, so exchanging two elements does not commute with the step; the SAT engines' test of
/// the step finds it (in the first random runs: any tick whose scheduled unit is one of the
/// exchanged elements) and checks every member itself, saying why in `stats.symmetry_note`.
#[test]
fn sat_engines_test_the_symmetry_on_the_step_before_using_it() {
    for engine in ["kind", "ic3"] {
        let v = verify_sat("Interleaved", engine, &["--symmetry"]);
        assert!(symmetry_of(&v).iter().all(Option::is_none), "{engine}");
        let note = v["stats"]["symmetry_note"].as_str().unwrap_or("");
        assert!(
            note.contains("symmetry reduction off: the step does not treat the elements alike"),
            "{engine}: {note}"
        );
    }
}

/// The explicit engine with `--symmetry` and one member of a family selected
/// (`--property a[2].below`): a member alone is not invariant under the permutations (a
/// canonical state may put the violating element elsewhere), so the reduction is off, with a
/// note, and the search is the full one — 28 states, as without symmetry (the model's
/// comment) — and its counterexample replays to `a[2].below` itself (element 2's counter at 2
/// at tick 2). Before, the reduction stayed on and the counterexample decided `a[0].below`.
#[test]
fn explicit_symmetry_is_off_when_only_some_members_of_a_family_are_checked() {
    let dir = std::env::temp_dir().join(format!(
        "statecheck-symmetry-partial-{}",
        std::process::id()
    ));
    let d = dir.to_string_lossy().into_owned();
    let (v, _) = verify(
        "Counters",
        &["--symmetry", "--property", "a[2].below", "--cex-dir", &d],
    );
    assert_eq!(v["stats"]["symmetry"], false, "{v}");
    assert_eq!(v["stats"]["states"], 28, "{v}");
    let note = v["stats"]["symmetry_note"].as_str().unwrap_or("");
    assert!(note.contains("a[2].below"), "{note}");
    let rows = results(&v);
    assert_eq!(rows.len(), 1);
    assert_eq!(rows[0]["verdict"], "violated");
    assert_eq!(rows[0]["depth"], 3);
    let (code, tick, value, prop) = replay("Counters", &dir.join("a_2__below.scn"), "a[2].c");
    assert_eq!(
        (code, tick, value, prop.as_str()),
        (Some(4), 2, 2, "a[2].below")
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// One configuration of a matrix: its name, states stored and (property, verdict, depth) rows.
type ConfigRow = (String, u64, Vec<(String, String, u64)>);

/// `--all-configs --symmetry`: each configuration stores its own orbits (counts derived by
/// hand in `tests/verify/symmetry_configs.sc`), with the verdicts of the full search.
#[test]
fn every_configuration_of_a_matrix_is_reduced_by_its_own_symmetry() {
    let matrix = |extra: &[&str]| -> Vec<ConfigRow> {
        // `thirds` violates `below`: the matrix exits 1.
        let (v, _) = explicit(
            &["tests/verify/symmetry_configs.sc", "--all-configs"],
            extra,
        );
        v["configurations"]
            .as_array()
            .expect("configurations")
            .iter()
            .map(|c| {
                (
                    c["configuration"].as_str().unwrap_or("").to_string(),
                    c["states"].as_u64().unwrap_or(0),
                    verdicts(c),
                )
            })
            .collect()
    };
    let full = matrix(&[]);
    let red = matrix(&["--symmetry"]);
    let counts = |m: &[ConfigRow]| -> Vec<(String, u64)> {
        m.iter().map(|(c, s, _)| (c.clone(), *s)).collect()
    };
    assert_eq!(
        counts(&full),
        [("thirds".to_string(), 28), ("halves".to_string(), 9)]
    );
    assert_eq!(
        counts(&red),
        [("thirds".to_string(), 11), ("halves".to_string(), 5)]
    );
    for ((_, _, f), (c, _, r)) in full.iter().zip(&red) {
        assert_eq!(f, r, "{c}");
    }
    let below: Vec<&str> = red[0]
        .2
        .iter()
        .map(|(_, v, _)| v.as_str())
        .take(3)
        .collect();
    assert_eq!(below, ["violated"; 3]);
    assert!(
        red[1].2.iter().all(|(_, v, _)| v == "proved"),
        "{:?}",
        red[1]
    );
}

/// The distributed search does not reduce: `--symmetry` with `--workers` says so and stores
/// the full search's 28 states (derived in `tests/verify/symmetry.sc`).
#[test]
fn the_distributed_search_warns_that_it_does_not_reduce() {
    let (v, stderr) = verify("Counters", &["--symmetry", "--workers", "1"]);
    assert!(
        stderr.contains("--workers explores without symmetry reduction"),
        "{stderr}"
    );
    assert_eq!(v["stats"]["states"], 28, "{v}");
}
