//! The FAM case study (issue 4; examples/fam/, docs/case-studies/fam.md).
//!
//! - the LIN encoder against byte vectors computed by hand (below);
//! - the verification table: `statecheck verify <file> --json` against examples/fam/expected.json
//!   (the thesis's verdicts, ch. 5), every counterexample replayed with `statecheck sim`;
//! - the validation scenarios of fam.sc against the traces derived by hand in their comments.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn fam_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fam")
}

fn fam(name: &str) -> String {
    fam_dir().join(name).to_string_lossy().into_owned()
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("statecheck-fam-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// `statecheck sim --json`; returns (exit code, JSON).
fn sim(file: &str, system: &str, scenario: &Path) -> (i32, Value) {
    let out = Command::new(BIN)
        .args(["sim", &fam(file), "--system", system, "--scenario"])
        .arg(scenario)
        .arg("--json")
        .output()
        .expect("sim runs");
    let v: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "sim {file}: not JSON ({e}): {} {}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    });
    (out.status.code().unwrap_or(-1), v)
}

// ---------------------------------------------------------------------------------------
// LIN encoder (App. A, Tables C.1, C.5). Hand computation, tick by tick:
//
// tick 1  id 0x00: ID5..ID0 = 000000. P0 = 0^0^0^0 = 0, P1 = !(0^0^0^0) = 1 -> 0x80.
// tick 2  id 0x31 (response ID of slave 0: length 11, ID0 = 1) = 110001:
//         P0 = ID0^ID1^ID2^ID4 = 1^0^0^1 = 0; P1 = !(ID1^ID3^ID4^ID5) = !(0^0^1^1) = 1 -> 0xB1.
// tick 3  id 0x02 (request ID of slave 1) = 000010: P0 = 0^1^0^0 = 1; P1 = !(1^0^0^0) = 0
//         -> 0x40 | 0x02 = 0x42.
// tick 4  id 0x39 (response ID of slave 4) = 111001: P0 = 1^0^0^1 = 0;
//         P1 = !(0^1^1^1) = 0 -> 0x39.
// ticks 1..4: request STOP_STALL, no swap, target 0: DB1 = 0, DB2 = 0, sum 0, checksum 0xFF.
//         The response with everything 0: DB1..DB8 = 00 00 FF FF 00 FF FF FF; 0x00 + 0xFF =
//         0xFF, 0xFF + 0xFF = 0x1FE -> carry -> 0xFF, ... sum 0xFF, checksum 0x00.
// tick 5  NORMAL_RUN (0b010), no swap, target 4090 = 0xFFA: DB1 = 010 0 1111 = 0x4F,
//         DB2 = 0xFA; 0x4F + 0xFA = 0x149 -> 0x49 + 1 = 0x4A; checksum 0xFF - 0x4A = 0xB5.
// tick 6  FAILURE_RUN (0b100), swap, target 5: DB1 = 100 1 0000 = 0x90, DB2 = 0x05;
//         sum 0x95, checksum 0x6A.
// tick 7  response: notCalib, DIR, RUN, position 4092 = 0xFFC, failures EPM|FBF = 0x24:
//         DB1 = 1 0 1 1 1111 = 0xBF, DB2 = 0xFC, DB5 = 0x24. Sum over BF FC FF FF 24 FF FF FF:
//         0xBF + 0xFC = 0x1BB -> 0xBC; + 0xFF -> 0x1BB -> 0xBC (twice); + 0x24 = 0xE0;
//         + 0xFF three times -> 0xE0; checksum 0xFF - 0xE0 = 0x1F.
const LIN_SCENARIO: &str = "-
id = 0
id = 49
id = 2
id = 57
mode = NORMAL_RUN, target = 4090
mode = FAILURE_RUN, swap = true, target = 5
mode = STOP_STALL, swap = false, target = 0, notCalib = true, dir = true, run = true, pos = 4092, fail = 36
";

#[test]
fn lin_encoder_matches_hand_computed_vectors() {
    let dir = temp_dir("lin");
    let scn = dir.join("lin.scn");
    std::fs::write(&scn, LIN_SCENARIO).expect("write");
    let (code, v) = sim("lin_vectors.sc", "LinVectors", &scn);
    assert_eq!(code, 0, "{v}");
    let ticks = v["ticks"].as_array().expect("ticks");
    let get =
        |t: usize, name: &str| -> Value { ticks[t]["vars"][format!("LinVectors.{name}")].clone() };
    let int = |t: usize, name: &str| get(t, name).as_i64().expect(name);
    // ident fields
    for (t, want) in [(1, 0x80), (2, 0xB1), (3, 0x42), (4, 0x39)] {
        assert_eq!(int(t, "ident"), want, "ident field at tick {t}");
        assert_eq!(get(t, "identOk"), Value::Bool(true));
    }
    // request frames: (tick, DB1, DB2, checksum)
    for (t, d1, d2, ck) in [
        (1, 0x00, 0x00, 0xFF),
        (5, 0x4F, 0xFA, 0xB5),
        (6, 0x90, 0x05, 0x6A),
    ] {
        assert_eq!(
            (int(t, "rq1"), int(t, "rq2"), int(t, "rqCk")),
            (d1, d2, ck),
            "request frame at tick {t}"
        );
        assert_eq!(
            get(t, "rqSumOk"),
            Value::Bool(true),
            "checksum adds to 0xFF"
        );
        assert_eq!(
            get(t, "rqCorruptOk"),
            Value::Bool(false),
            "a flipped bit is detected"
        );
    }
    // decoding gives the fields back
    assert_eq!(get(5, "decMode"), Value::from("NORMAL_RUN"));
    assert_eq!(int(5, "decTarget"), 4090);
    assert_eq!(get(6, "decMode"), Value::from("FAILURE_RUN"));
    assert_eq!(get(6, "decSwap"), Value::Bool(true));
    assert_eq!(int(6, "decTarget"), 5);
    // response frames
    assert_eq!(
        (int(1, "rs1"), int(1, "rs2"), int(1, "rs5"), int(1, "rsCk")),
        (0, 0, 0, 0x00)
    );
    assert_eq!(
        (int(7, "rs1"), int(7, "rs2"), int(7, "rs5"), int(7, "rsCk")),
        (0xBF, 0xFC, 0x24, 0x1F)
    );
    for t in [1, 7] {
        assert_eq!(
            get(t, "rsSumOk"),
            Value::Bool(true),
            "response check at tick {t}"
        );
    }
}

// ---------------------------------------------------------------------------------------
// The verification table.

fn expected() -> Value {
    let text = std::fs::read_to_string(fam("expected.json")).expect("expected.json");
    serde_json::from_str(&text).expect("expected.json parses")
}

/// Replay a counterexample or witness with `statecheck sim` and check where it stops.
fn replay(file: &str, system: &str, r: &Value) {
    let Some(path) = r["counterexample"].as_str() else {
        return;
    };
    let (code, sim) = sim(file, system, Path::new(path));
    let name = r["property"].as_str().expect("name");
    let tick = r["depth"].as_u64().expect("depth") - 1;
    match r["kind"].as_str() {
        Some("reachable") => {
            assert_eq!(code, 0, "witness replay of {name}");
            assert_eq!(
                sim["reached"][name].as_u64(),
                Some(tick),
                "{name} reached at {tick}"
            );
        }
        Some("builtin") => {
            assert_eq!(code, 1, "run-time error replays with exit 1 ({name})");
        }
        _ => {
            assert_eq!(
                code, 4,
                "violation of {name} replays with exit 4: {}",
                sim["result"]
            );
            assert_eq!(sim["result"]["property"].as_str(), Some(name));
            assert_eq!(sim["result"]["tick"].as_u64(), Some(tick));
        }
    }
}

/// Verify one file of expected.json's "runs" and compare every listed verdict.
fn check_run(key: &str) {
    let exp = expected();
    let run = &exp["runs"][key];
    let file = run["file"].as_str().unwrap_or(key);
    let system = run["system"].as_str().expect("system");
    let dir = temp_dir(&key.replace(['.', ',', ' '], "_"));
    let mut cmd = Command::new(BIN);
    cmd.args([
        "verify",
        &fam(file),
        "--system",
        system,
        "--json",
        "--cex-dir",
    ])
    .arg(&dir);
    if let Some(depth) = run["depth"].as_u64() {
        cmd.args(["--depth", &depth.to_string()]);
    }
    let engine = run["engine"].as_str();
    match engine {
        Some(e) => cmd.args(["--engine", e, "--timeout", "120"]),
        None => cmd.args(["--engine", "explicit"]),
    };
    if let Some(props) = run["properties"].as_array() {
        for p in props {
            cmd.args(["--property", p.as_str().expect("name")]);
        }
    }
    let out = cmd.output().expect("verify runs");
    let v: Value = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "verify {file}: not JSON ({e}): {}",
            String::from_utf8_lossy(&out.stderr)
        )
    });
    // "complete" is the explicit engine's exhaustion; a symbolic verdict is definitive alone.
    assert!(
        engine.is_some()
            || v["stats"]["complete"].as_bool() == Some(true)
            || run["complete"] == Value::Bool(false),
        "{file}: exploration incomplete: {}",
        v["stats"]
    );
    let results = v["results"].as_array().expect("results");
    let verdicts = run["verdicts"].as_object().expect("verdicts");
    for (name, want) in verdicts {
        let r = results
            .iter()
            .find(|r| r["property"] == name.as_str())
            .unwrap_or_else(|| panic!("{file}: no result for {name}"));
        assert_eq!(
            r["verdict"].as_str(),
            want.as_str(),
            "{file}: verdict of {name}: {r}"
        );
        replay(file, system, r);
    }
}

#[test]
fn fam_alone_reproduces_the_thesis_table() {
    check_run("fam_alone.sc");
}

/// The open-loop table with every input free (no `assume`, targetPos over 0..4095): IC3.
#[test]
fn fam_open_loop_decided_by_ic3() {
    check_run("fam.sc");
}

/// Master + 1 FAM with the SAT engines racing: the thesis's proved safety properties proved.
#[test]
fn closed_loop_proofs_by_auto() {
    check_run("fam_system.sc, auto");
}

#[test]
fn closed_loop_master_and_one_fam() {
    check_run("fam_system.sc");
}

#[test]
fn bug_modulus_is_found() {
    check_run("bug_modulus.sc");
}

#[test]
fn bug_short_timeout_is_found() {
    check_run("bug_short_timeout.sc");
}

#[test]
fn every_contract_property_has_a_thesis_verdict() {
    // docs: ../shared/design/case-studies.md — the names are a contract.
    let names = [
        "fam_stall_running_possible",
        "fam_stall_blocks_run",
        "fam_failure_running_possible",
        "fam_failure_blocks_run",
        "fam_cof_with_notcalib",
        "fam_actualpos_in_range",
        "master_no_normal_run_on_failure",
        "master_failure_before_stall",
        "master_outputs_in_range",
        "master_target_outside_ends_only_calibrating",
        "master_failure_sequence",
    ];
    let exp = expected();
    for n in names {
        assert!(
            exp["thesis"][n].is_string(),
            "expected.json: thesis verdict of {n}"
        );
        assert!(
            exp["runs"]["fam_system.sc"]["verdicts"][n].is_string(),
            "fam_system.sc states {n}"
        );
    }
}

// ---------------------------------------------------------------------------------------
// Validation scenarios (thesis ch. 4) on the FAM alone. Each check is taken from the trace
// derived by hand in the scenario's comments (tick, variable, value) or (tick, active state).

enum Want {
    Var(&'static str, i64),
    Bool(&'static str, bool),
    Active(&'static str),
}
use Want::{Active, Bool, Var};

fn check_scenario(name: &str, wants: &[(usize, Want)]) -> Value {
    let scn = fam_dir().join("scenarios").join(format!("{name}.scn"));
    let (_, v) = sim("fam.sc", "FamAlone", &scn);
    let ticks = v["ticks"].as_array().expect("ticks");
    for (t, want) in wants {
        let tick = ticks
            .get(*t)
            .unwrap_or_else(|| panic!("{name}: no tick {t} ({})", v["result"]));
        match want {
            Var(var, x) => assert_eq!(
                tick["vars"][format!("fam.{var}")].as_i64(),
                Some(*x),
                "{name}: fam.{var} at tick {t}"
            ),
            Bool(var, x) => assert_eq!(
                tick["vars"][format!("fam.{var}")].as_bool(),
                Some(*x),
                "{name}: fam.{var} at tick {t}"
            ),
            Active(state) => assert!(
                tick["active"]["fam"]
                    .as_array()
                    .is_some_and(|a| a.iter().any(|s| s == state)),
                "{name}: {state} active at tick {t}: {}",
                tick["active"]
            ),
        }
    }
    v
}

#[test]
fn scenario_normal_run() {
    check_scenario(
        "normal_run",
        &[
            (0, Var("actualPos", 2048)),
            (1, Active("moveHandler.running")),
            (1, Var("actualPos", 2048)),
            (2, Var("actualPos", 2049)),
            (11, Var("actualPos", 2058)),
            (12, Active("moveHandler.stopped")),
            (13, Bool("dir", true)),
            (14, Var("actualPos", 2055)),
            (113, Var("actualPos", 1758)),
            (114, Bool("dir", true)),
            (115, Bool("dir", false)),
            (120, Var("actualPos", 1763)),
            (121, Bool("run", false)),
        ],
    );
}

#[test]
fn scenario_stall_ack() {
    let v = check_scenario(
        "stall_ack",
        &[
            (30, Var("actualPos", 2077)),
            (31, Bool("stall", true)),
            (31, Active("moveHandler.stopped")),
            (31, Bool("notCalib", false)),
            (34, Active("moveHandler.stopped")),
            (35, Bool("stall", false)),
            (36, Active("moveHandler.running")),
            (107, Var("actualPos", 2148)),
            (108, Active("moveHandler.stopped")),
            (130, Var("actualPos", 2127)),
            (131, Bool("stall", true)),
            (132, Active("stallHandler.stallMode")),
            (132, Active("moveHandler.running")),
            (159, Var("actualPos", 2100)),
            (160, Bool("stall", true)),
            (161, Bool("stall", false)),
        ],
    );
    assert_eq!(
        v["reached"]["fam_stall_running_possible"].as_u64(),
        Some(132)
    );
}

#[test]
fn scenario_lost_calibration() {
    check_scenario(
        "lost_calibration",
        &[
            (5, Var("actualPos", 2052)),
            (6, Bool("stall", true)),
            (6, Bool("notCalib", true)),
            (6, Var("failureReg", 0)),
            (8, Bool("stall", false)),
            (8, Bool("notCalib", true)),
            (9, Bool("notCalib", false)),
            (10, Active("moveHandler.running")),
            (11, Var("actualPos", 2053)),
            (12, Var("actualPos", 2054)),
            (13, Active("moveHandler.stopped")),
            (13, Var("actualPos", 2054)),
        ],
    );
}

#[test]
fn scenario_failure_fbf() {
    check_scenario(
        "failure_fbf",
        &[
            (10, Var("actualPos", 2057)),
            (11, Var("failureReg", 4)),
            (11, Active("failureHandler.failure")),
            (11, Bool("run", false)),
            (11, Bool("notCalib", true)),
            (13, Var("failureReg", 4)),
            (13, Active("moveHandler.stopped")),
            (14, Var("failureReg", 0)),
            (14, Active("failureHandler.noFailure")),
            (14, Bool("notCalib", true)),
            (16, Bool("notCalib", false)),
            (17, Active("moveHandler.running")),
            (108, Var("actualPos", 2148)),
            (109, Active("moveHandler.stopped")),
        ],
    );
}

#[test]
fn scenario_failure_hsl_permanent() {
    let v = check_scenario(
        "failure_hsl_permanent",
        &[
            (1, Var("failureReg", 128)),
            (1, Bool("notCalib", true)),
            (3, Var("failureReg", 128)),
            (4, Bool("notCalib", true)),
            (5, Active("moveHandler.stopped")),
            (6, Active("moveHandler.running")),
            (6, Active("failureHandler.failure")),
            (16, Var("actualPos", 2058)),
            (17, Active("moveHandler.stopped")),
            (17, Var("failureReg", 128)),
            (18, Var("failureReg", 0)),
            (19, Bool("notCalib", false)),
        ],
    );
    assert_eq!(
        v["reached"]["fam_failure_running_possible"].as_u64(),
        Some(6)
    );
}

#[test]
fn scenario_failure_otf_ccf() {
    check_scenario(
        "failure_otf_ccf",
        &[
            (6, Var("failureReg", 16)),
            (6, Var("actualPos", 2052)),
            (7, Var("failureReg", 16)),
            (8, Var("failureReg", 16)),
            (9, Var("failureReg", 0)),
            (10, Var("failureReg", 2)),
            (11, Var("failureReg", 2)),
            (12, Var("failureReg", 0)),
            (13, Bool("notCalib", false)),
            (14, Active("moveHandler.running")),
            (15, Var("actualPos", 2053)),
        ],
    );
}

#[test]
fn scenario_failure_cof() {
    check_scenario(
        "failure_cof",
        &[
            (3, Var("failureReg", 8)),
            (3, Active("failureHandler.noFailure")),
            (3, Bool("notCalib", false)),
            (3, Var("actualPos", 2050)),
            (11, Var("actualPos", 2058)),
            (11, Var("failureReg", 8)),
            (12, Active("moveHandler.stopped")),
            (13, Var("failureReg", 0)),
        ],
    );
}

#[test]
fn scenario_cof_with_notcalib_violates() {
    let scn = fam_dir().join("scenarios/cof_with_notcalib.scn");
    let (code, v) = sim("fam.sc", "FamAlone", &scn);
    assert_eq!(code, 4, "{}", v["result"]);
    assert_eq!(
        v["result"]["property"].as_str(),
        Some("fam_cof_with_notcalib")
    );
    assert_eq!(v["result"]["tick"].as_u64(), Some(4));
    let t = &v["ticks"][2]["vars"];
    assert_eq!(t["fam.failureReg"].as_i64(), Some(32));
    assert_eq!(v["ticks"][3]["vars"]["fam.failureReg"].as_i64(), Some(0));
    assert_eq!(v["ticks"][3]["vars"]["fam.notCalib"].as_bool(), Some(true));
}

#[test]
fn scenario_power_loss() {
    check_scenario(
        "power_loss",
        &[
            (10, Var("actualPos", 2057)),
            (11, Var("failureReg", 1)),
            (11, Active("moveHandler.stopped")),
            (11, Var("actualPos", 2057)),
            (11, Bool("notCalib", true)),
            (13, Var("failureReg", 0)),
            (14, Bool("notCalib", false)),
            (15, Var("failureReg", 64)),
            (15, Var("actualPos", 2048)),
            (16, Bool("notCalib", true)),
            (17, Var("failureReg", 0)),
            (18, Bool("notCalib", false)),
            (19, Active("moveHandler.running")),
            (20, Var("actualPos", 2049)),
        ],
    );
}

#[test]
fn scenario_swap_across_zero() {
    check_scenario(
        "swap_across_zero",
        &[
            (1, Bool("dir", true)),
            (2, Var("actualPos", 2045)),
            (682, Var("actualPos", 5)),
            (683, Active("moveHandler.stopped")),
            (684, Bool("dir", true)),
            (689, Var("actualPos", 0)),
            (690, Var("actualPos", 4095)),
            (695, Var("actualPos", 4090)),
            (696, Active("moveHandler.stopped")),
            (697, Bool("dir", false)),
            (702, Var("actualPos", 4095)),
            (703, Var("actualPos", 0)),
            (723, Var("actualPos", 20)),
            (724, Active("moveHandler.stopped")),
            (725, Bool("dir", false)),
            (727, Var("actualPos", 22)),
            (728, Active("moveHandler.stopped")),
        ],
    );
}
