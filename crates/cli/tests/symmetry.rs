//! `verify --symmetry` end to end: the state counts of `tests/verify/symmetry.sc` derived by
//! hand in the model, equal verdicts with and without it, every counterexample replayed by
//! `sim` to its own violation, and W0317 naming the property that breaks the symmetry.

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

fn verify(system: &str, extra: &[&str]) -> (serde_json::Value, String) {
    let mut args = vec![
        "verify",
        "tests/verify/symmetry.sc",
        "--system",
        system,
        "--engine",
        "explicit",
        "--json",
        "--threads",
        "1",
    ];
    args.extend(extra);
    let out = statecheck(&args);
    assert_eq!(out.status.code(), Some(1), "{system} {extra:?}");
    let v = serde_json::from_slice(&out.stdout).expect("json");
    (v, String::from_utf8_lossy(&out.stderr).into_owned())
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
fn a_property_naming_one_element_is_diagnosed() {
    let (v, err) = verify("Named", &["--symmetry"]);
    assert!(err.contains("W0317") && err.contains("`first`"), "{err}");
    assert_eq!(v["stats"]["symmetry"], false);
    assert_eq!(v["stats"]["states"], 28);
}
