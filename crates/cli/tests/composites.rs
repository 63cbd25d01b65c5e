//! Composite components through the binary (docs/components.md): `tests/components/cell.sc`
//! (Cell = ctrl + Storage, Storage = Feeder + Magazine, Feeder = Cylinder + two Sensors)
//! gives the same verdicts, state counts and traces as `cell_flat.sc`, the same system
//! flattened by hand, once each name path's `.` is read as `_`; its traces name signals by
//! their path through the hierarchy.

mod common;

use common::{run, summary_of, Summary};
use serde_json::Value;

const CELL: &str = "tests/components/cell.sc";
const FLAT: &str = "tests/components/cell_flat.sc";

/// (states, transitions, [(property, verdict, tick)]) of `verify --json`, property names with
/// `.` read as `_`.
fn summary(file: &str, engine: &str) -> Summary {
    let (code, out, err) = run(&["verify", "--engine", engine, "--json", file]);
    // `never_empty_extended` is violated: exit 1.
    assert_eq!(code, 1, "{file}: {err}");
    let (states, transitions, rows) = summary_of(&out);
    let rows = rows
        .into_iter()
        .map(|(name, verdict, tick)| (name.replace('.', "_"), verdict, tick))
        .collect();
    (states, transitions, rows)
}

#[test]
fn a_two_level_composite_verifies_like_its_hand_flattened_system() {
    let cell = summary(CELL, "explicit");
    let flat = summary(FLAT, "explicit");
    assert_eq!(cell, flat);
    let verdict = |n: &str| {
        cell.2
            .iter()
            .find(|r| r.0 == n)
            .map(|r| (r.1.as_str(), r.2))
            .unwrap_or(("missing", None))
    };
    // By hand, without `hold`: the storage runs before ctrl, so the cylinder moves one tick
    // after each `go`/`back`: pos 0,1,2,3 in ticks 0-3 (ctrl sees `extended` in tick 3 and
    // pulls), 2,1,0 in ticks 4-6 (ctrl sees `retracted` in tick 6, raises `take`), the
    // magazine takes in tick 7 (count 1, pos 1), pos 2 in tick 8: `half_way` at tick 8.
    // The third cycle empties the magazine (tick 13) and extends again (tick 15).
    assert_eq!(verdict("half_way"), ("reachable", Some(8)));
    assert_eq!(verdict("never_empty_extended"), ("violated", Some(15)));
    // The sensors see one position each: never both on. `empty` is raised one tick after
    // `take`, when ctrl is back in Push, which ignores it: Done is never entered.
    assert_eq!(verdict("storage_feeder_sensors_exclusive").0, "proved");
    assert_eq!(verdict("done").0, "unreachable");
    // The observer reads `storage.magazine` and `storage.feeder.cyl` by path: the magazine is
    // Empty from tick 13 (pos 1), the cylinder goes on 2, 3, 2, 1 and is home (0) in tick 18.
    assert_eq!(verdict("EmptyStaysOut"), ("violated", Some(18)));
    // The composite's inner property keeps its path.
    let (_, out, _) = run(&["verify", "--engine", "explicit", "--json", CELL]);
    assert!(
        out.contains("\"storage.feeder.sensors_exclusive\""),
        "{out}"
    );
}

#[test]
fn the_sat_engines_agree_on_the_composite() {
    let bmc = summary(CELL, "bmc");
    let row = bmc.2.iter().find(|r| r.0 == "never_empty_extended");
    assert_eq!(
        row.map(|r| (r.1.as_str(), r.2)),
        Some(("violated", Some(15)))
    );
    // IC3 and k-induction decide every property as the explicit engine does.
    let verdicts = |s: &Summary| {
        let mut v: Vec<(String, String)> = s.2.iter().map(|r| (r.0.clone(), r.1.clone())).collect();
        v.sort();
        v
    };
    let explicit = verdicts(&summary(CELL, "explicit"));
    for engine in ["ic3", "kind"] {
        assert_eq!(verdicts(&summary(CELL, engine)), explicit, "{engine}");
    }
}

#[test]
fn a_composite_simulates_like_its_hand_flattened_system_and_names_paths() {
    let dir = std::env::temp_dir().join(format!("statecheck-composites-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    // `hold` is the Storage port left free in Cell: it holds the cylinder and the magazine
    // in the same tick (one free input, read by both).
    let scn = |name: &str, hold: &str| {
        let p = dir.join(name);
        let text = format!("-\n{hold}\n{hold}\n-\n-\n-\n-\n-\n{hold}\n-\n");
        std::fs::write(&p, text).expect("write scenario");
        p.to_string_lossy().into_owned()
    };
    let a = scn("cell.scn", "storage.feeder.cyl.hold");
    let b = scn("flat.scn", "storage_feeder_cyl.hold");
    let (c1, t1, e1) = run(&["sim", CELL, "--scenario", &a, "--csv"]);
    let (c2, t2, e2) = run(&["sim", FLAT, "--scenario", &b, "--csv"]);
    assert_eq!((c1, c2), (0, 0), "{e1}{e2}");
    assert_eq!(t1.replace('.', "_"), t2.replace('.', "_"));
    // Name paths through the hierarchy in the columns.
    let header = t1.lines().next().unwrap_or("");
    for col in [
        "storage.feeder.cyl.pos",
        "storage.magazine.count",
        "ctrl.extended",
    ] {
        assert!(header.split(',').any(|c| c == col), "{header}");
    }
    // By hand: hold in ticks 1 and 2 keeps pos at 0 (tick 0 enters; `go` from tick 0 is
    // held in 1, `go` from 1 in 2), so pos is 1 in tick 3, as in a run without hold at tick 1.
    let col = header
        .split(',')
        .position(|c| c == "storage.feeder.cyl.pos")
        .unwrap_or(0);
    let pos: Vec<&str> = t1
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(col).unwrap_or(""))
        .collect();
    assert_eq!(&pos[..5], ["0", "0", "0", "1", "2"], "{t1}");
    // The VCD nests the path: scope storage, scope feeder, scope cyl.
    let vcd = dir.join("cell.vcd");
    let vcd_s = vcd.to_string_lossy().into_owned();
    let (c3, _, e3) = run(&["sim", CELL, "--scenario", &a, "--vcd", &vcd_s]);
    assert_eq!(c3, 0, "{e3}");
    let text = std::fs::read_to_string(&vcd).expect("vcd written");
    assert!(
        text.contains(
            "$scope module storage $end\n$scope module feeder $end\n$scope module cyl $end"
        ),
        "{text}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_component_runs_alone_with_its_ports_free() {
    let (code, out, err) = run(&["verify", "--engine", "explicit", "--system", "Feeder", CELL]);
    assert_eq!(code, 0, "{out}{err}");
    // By hand: the cylinder's pos 0..3 and the two sensors follow it in the same tick:
    // 4 started states plus the one before the first tick; `sensors_exclusive` holds.
    assert!(out.contains("sensors_exclusive"), "{out}");
    assert!(out.contains("5 states"), "{out}");
}

#[test]
fn formatting_keeps_components() {
    let (code, out, err) = run(&["fmt", "--check", CELL]);
    assert_eq!(code, 0, "{out}{err}");
}

#[test]
fn configurations_swap_a_composite_and_a_slot_inside_one() {
    let (code, out, err) = run(&[
        "verify",
        "--engine",
        "explicit",
        "--all-configs",
        "--json",
        "tests/components/axis_configs.sc",
    ]);
    // `stuck` violates `settles`: exit 1.
    assert_eq!(code, 1, "{out}{err}");
    let v: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"));
    let rows = v["configurations"].as_array().cloned().unwrap_or_default();
    let cell = |config: &str, prop: &str| -> (String, u64) {
        let row = rows
            .iter()
            .find(|r| r["configuration"] == config)
            .unwrap_or_else(|| panic!("no row {config}: {out}"));
        let verdict = row["results"]
            .as_array()
            .and_then(|rs| rs.iter().find(|r| r["property"] == prop))
            .and_then(|r| r["verdict"].as_str())
            .unwrap_or("missing")
            .to_string();
        (verdict, row["states"].as_u64().unwrap_or(0))
    };
    // By hand. normal: the system is closed and deterministic; the cylinder moves one step a
    // tick after each `go`/`back` (pos 0,1,2,3; ctrl pulls in tick 3; 2,1,0; ctrl pushes in
    // tick 6, the state of tick 0 again, the `settles` monitor's age included): the state
    // before the first tick and those of ticks 0..5, 7 states.
    assert_eq!(cell("normal", "pulls"), ("reachable".into(), 7));
    assert_eq!(cell("normal", "settles").0, "proved");
    // stuck: the front sensor never fires; ctrl pushes forever and `go` is never answered.
    assert_eq!(cell("stuck", "pulls").0, "unreachable");
    assert_eq!(cell("stuck", "settles").0, "violated");
    // quick: the toggle is out in tick 1 (ctrl pulls), in again in tick 2 (ctrl pushes: the
    // state of tick 0): 3 states.
    assert_eq!(cell("quick", "pulls"), ("reachable".into(), 3));
    for config in ["normal", "stuck", "quick"] {
        assert_eq!(cell(config, "never_both").0, "proved", "{config}");
    }
}

#[test]
fn synthesis_accepts_a_parameterised_plant_chart() {
    let dir = std::env::temp_dir().join(format!("statecheck-psynth-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let sup = dir.join("sup.sc").to_string_lossy().into_owned();
    let (code, out, err) = run(&[
        "synth",
        "tests/components/synth_params.sc",
        "--system",
        "S",
        "-o",
        &sup,
    ]);
    assert_eq!(code, 0, "{out}{err}");
    // By hand (the file's comment): 2 states, 2 transitions, `start` always allowed.
    let text = format!("{out}{err}");
    assert!(
        text.contains("supervisor: 2 states, 2 transitions"),
        "{text}"
    );
    assert!(text.contains("start: true"), "{text}");
    let (code, out, err) = run(&[
        "verify",
        &sup,
        "--plant",
        "tests/components/synth_params.sc",
        "--plant-system",
        "S",
    ]);
    assert_eq!(code, 0, "{out}{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

const BANK: &str = "tests/components/bank.sc";
const BANK_FLAT: &str = "tests/components/bank_flat.sc";

/// (states, transitions, rows) of `verify --json` for `bank*.sc` (`p_three` is unreachable:
/// exit 1), property names with `.`, `[`, `]` read as `_`.
fn bank_summary(file: &str, engine: &str) -> Summary {
    let (code, out, err) = run(&["verify", "--engine", engine, "--json", file]);
    assert_eq!(code, 1, "{file}: {err}");
    let (states, transitions, rows) = summary_of(&out);
    let mut rows: Vec<_> = rows
        .into_iter()
        .map(|(name, verdict, tick)| (name.replace(['.', '[', ']'], "_"), verdict, tick))
        .collect();
    rows.sort();
    (states, transitions, rows)
}

#[test]
fn a_parameterised_component_and_an_array_of_components_verify_like_the_hand_flattened_system() {
    let bank = bank_summary(BANK, "explicit");
    assert_eq!(bank, bank_summary(BANK_FLAT, "explicit"));
    // By hand (bank.sc's header): 3 * 4 * 4 = 48 started states plus the state before the
    // first tick; 3 free events, so 8 input vectors from each state.
    assert_eq!((bank.0, bank.1), (49, 49 * 8));
    let verdict = |n: &str| {
        bank.2
            .iter()
            .find(|r| r.0 == n)
            .map(|r| (r.1.as_str(), r.2))
            .unwrap_or(("missing", None))
    };
    // Tick 0 enters; `step` in ticks 1, 2, 3 brings cells[1].hi to 3 in tick 3 (Pair(3)),
    // p.hi stops at 2 (Pair(2)), so 3 is unreachable for it.
    assert_eq!(verdict("c1_full"), ("reachable", Some(3)));
    assert_eq!(verdict("p_full"), ("reachable", Some(2)));
    assert_eq!(verdict("p_three").0, "unreachable");
    for p in [
        "p_capped",
        "cells_0__capped",
        "cells_1__capped",
        "lo_follows",
    ] {
        assert_eq!(verdict(p).0, "proved", "{p}");
    }
    // A SAT engine agrees on every verdict.
    let verdicts = |s: &Summary| {
        s.2.iter()
            .map(|r| (r.0.clone(), r.1.clone()))
            .collect::<Vec<_>>()
    };
    assert_eq!(verdicts(&bank_summary(BANK, "ic3")), verdicts(&bank));
}

#[test]
fn an_array_of_components_simulates_by_element_path() {
    let dir = std::env::temp_dir().join(format!("statecheck-bank-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let scn = |name: &str, a: &str, b: &str| {
        let p = dir.join(name);
        std::fs::write(&p, format!("-\n{a}\n-\n{a}\n{b}\n")).expect("write scenario");
        p.to_string_lossy().into_owned()
    };
    let a = scn("bank.scn", "cells[1].lo.step", "p.lo.step");
    let b = scn("flat.scn", "cells_1__lo.step", "p_lo.step");
    let (c1, t1, e1) = run(&["sim", BANK, "--scenario", &a, "--csv"]);
    let (c2, t2, e2) = run(&["sim", BANK_FLAT, "--scenario", &b, "--csv"]);
    assert_eq!((c1, c2), (0, 0), "{e1}{e2}");
    assert_eq!(
        t1.replace(['.', '[', ']'], "_"),
        t2.replace(['.', '[', ']'], "_")
    );
    let header = t1.lines().next().unwrap_or("");
    let col = header
        .split(',')
        .position(|c| c == "cells[1].hi.n")
        .unwrap_or_else(|| panic!("{header}"));
    let n: Vec<&str> = t1
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(col).unwrap_or(""))
        .collect();
    // Steps in ticks 1 and 3: 1 from tick 1, 2 from tick 3.
    assert_eq!(n, ["0", "1", "1", "2", "2"], "{t1}");
    let _ = std::fs::remove_dir_all(&dir);
}

const INTERLEAVED: &str = "tests/components/interleaved.sc";

/// (exit code, states, transitions, verdict of `same`, its tick) of one system of
/// `interleaved.sc` under one engine.
fn same_verdict(system: &str, engine: &str) -> (i32, u64, u64, String, Option<u64>) {
    let (code, out, err) = run(&[
        "verify",
        "--engine",
        engine,
        "--system",
        system,
        "--json",
        INTERLEAVED,
    ]);
    let v: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}{err}"));
    let row = v["results"]
        .as_array()
        .and_then(|a| a.iter().find(|r| r["property"] == "same"))
        .cloned()
        .unwrap_or(Value::Null);
    (
        code,
        v["stats"]["states"].as_u64().unwrap_or(0),
        v["stats"]["transitions"].as_u64().unwrap_or(0),
        row["verdict"].as_str().unwrap_or("missing").to_string(),
        row["tick"].as_u64(),
    )
}

#[test]
fn interleaved_composition_breaks_what_synchronous_composition_keeps() {
    // By hand (interleaved.sc's header): synchronous, 3 states, 3 transitions, `same` holds;
    // interleaved, 5 states, 10 transitions (2 scheduler choices), violated at tick 1 when
    // `a` steps alone.
    let (code, states, transitions, verdict, _) = same_verdict("Sync", "explicit");
    assert_eq!(
        (code, states, transitions, verdict.as_str()),
        (0, 3, 3, "proved")
    );
    let (code, states, transitions, verdict, tick) = same_verdict("Async", "explicit");
    assert_eq!(
        (code, states, transitions, verdict.as_str(), tick),
        (1, 5, 10, "violated", Some(1))
    );
    // A SAT engine: the same violation at the same depth, nothing found synchronously.
    let (code, _, _, verdict, tick) = same_verdict("Async", "bmc");
    assert_eq!((code, verdict.as_str(), tick), (1, "violated", Some(1)));
    let (code, _, _, verdict, _) = same_verdict("Sync", "ic3");
    assert_eq!((code, verdict.as_str()), (0, "proved"));
    // The scheduler is an ordinary input of the trace: b alone in tick 1 keeps y == x
    // (both false), a alone in tick 2 breaks it (exit 4: violated during sim).
    let dir = std::env::temp_dir().join(format!("statecheck-interleaved-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let scn = dir.join("async.scn");
    std::fs::write(&scn, "-\nsched.unit=1\nsched.unit=0\n").expect("write scenario");
    let scn = scn.to_string_lossy().into_owned();
    let (code, csv, err) = run(&[
        "sim",
        INTERLEAVED,
        "--system",
        "Async",
        "--scenario",
        &scn,
        "--csv",
    ]);
    assert_eq!(code, 4, "{err}");
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(
        rows[0],
        "tick,sched.active,a.active,b.active,sched.unit,a.x,b.i,b.y,events"
    );
    assert_eq!(rows[2], "1,Run,S,S,1,false,false,false,");
    assert_eq!(rows[3], "2,Run,S,S,0,true,true,false,");
    let _ = std::fs::remove_dir_all(&dir);
}
