//! SPIN cross-check of `statecheck export promela`: for every property of the verification
//! test models and the examples, SPIN's verdict on the exported model (assertion violated or
//! not) equals `statecheck verify --json`'s, and with only proved properties asserted SPIN
//! stores exactly as many states as our explicit checker reaches (no offset: the inputs,
//! temporaries and the saved pre-tick state are `hidden`, and SPIN does not store the
//! intermediate states of an `atomic` tick). Compiled and run in a temporary directory.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn temp_dir() -> PathBuf {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos())
        .unwrap_or(0);
    let d = std::env::temp_dir().join(format!("statecheck-spin-{}-{nanos}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// SPIN on an exported model: (assertion violated, states stored).
fn spin(dir: &Path, model: &Path, system: &str, props: &[&str]) -> (bool, u64) {
    let pml = dir.join("m.pml");
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_statecheck"));
    cmd.args(["export", "promela"])
        .arg(model)
        .args(["--system", system, "-o"])
        .arg(&pml);
    for p in props {
        cmd.args(["--property", p]);
    }
    let out = cmd.output().expect("export runs");
    assert!(
        out.status.success(),
        "export: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let a = Command::new("spin")
        .arg("-a")
        .arg("m.pml")
        .current_dir(dir)
        .output()
        .expect("spin runs");
    assert!(
        a.status.success(),
        "spin -a: {}",
        String::from_utf8_lossy(&a.stdout)
    );
    let cc = Command::new("gcc")
        .args(["-O0", "-DSAFETY", "-DNOFAIR", "-o", "pan", "pan.c"])
        .current_dir(dir)
        .output()
        .expect("gcc runs");
    assert!(
        cc.status.success(),
        "gcc pan.c: {}",
        String::from_utf8_lossy(&cc.stderr)
    );
    let run = Command::new(dir.join("pan"))
        .arg("-m1000000")
        .current_dir(dir)
        .output()
        .expect("pan runs");
    let text = String::from_utf8_lossy(&run.stdout);
    let errors = text
        .lines()
        .find_map(|l| l.split("errors: ").nth(1))
        .and_then(|s| s.trim().parse::<u64>().ok())
        .unwrap_or_else(|| panic!("no error count in pan output:\n{text}"));
    let states = text
        .lines()
        .find(|l| l.contains("states, stored"))
        .and_then(|l| l.split_whitespace().next())
        .and_then(|s| s.parse::<u64>().ok())
        .unwrap_or_else(|| panic!("no state count in pan output:\n{text}"));
    (errors > 0, states)
}

fn verify(model: &Path, system: &str) -> Value {
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .arg("verify")
        .arg(model)
        .args([
            "--engine",
            "explicit",
            "--system",
            system,
            "--json",
            "--threads",
            "1",
        ])
        .output()
        .expect("verify runs");
    serde_json::from_slice(&out.stdout).expect("verify JSON")
}

#[test]
fn spin_agrees_with_the_explicit_checker_on_verdicts_and_state_counts() {
    let root = repo_root();
    let dir = temp_dir();
    let mut cases: Vec<(PathBuf, &str)> = vec![(
        root.join("examples/linear_drive/linear_drive.sc"),
        "LinearDrive",
    )];
    for (file, systems) in [
        ("counter.sc", &["Counting", "Reaching", "Observed"][..]),
        ("respond.sc", &["Prompt", "Slow", "Eager"][..]),
        ("runtime.sc", &["Divide", "SafeDivide", "Add"][..]),
        ("toggle.sc", &["Free", "Frozen"][..]),
    ] {
        for s in systems {
            cases.push((root.join("tests/verify").join(file), s));
        }
    }
    let mut verdicts = 0;
    for (model, system) in &cases {
        let v = verify(model, system);
        let results = v["results"].as_array().cloned().unwrap_or_default();
        let mut proved = Vec::new();
        for r in &results {
            let name = r["property"].as_str().unwrap_or("");
            let ours = match r["verdict"].as_str() {
                Some("violated") | Some("reachable") => true,
                Some("proved") | Some("unreachable") => false,
                other => panic!("{system}: undecided verdict {other:?} for {name}"),
            };
            if !ours {
                proved.push(name);
            }
            let (theirs, _) = spin(&dir, model, system, &[name]);
            assert_eq!(
                theirs,
                ours,
                "{}: {system}.{name}: SPIN says violated/reachable = {theirs}, statecheck {}",
                model.display(),
                r["verdict"]
            );
            verdicts += 1;
        }
        if v["stats"]["complete"].as_bool() == Some(true) && !proved.is_empty() {
            let (violated, states) = spin(&dir, model, system, &proved);
            assert!(!violated);
            assert_eq!(
                Some(states),
                v["stats"]["states"].as_u64(),
                "{system}: SPIN's stored states vs ours"
            );
        }
    }
    assert!(verdicts >= 30, "only {verdicts} verdicts compared");
    let _ = std::fs::remove_dir_all(&dir);
}

/// Properties and assumes that can fail at run time are exported (read as false where their
/// evaluation fails, as the IR reads them): SPIN's verdicts equal the ones derived by hand in
/// `tests/verify/goal_errors.sc`, which are also the explicit checker's.
#[test]
fn goals_that_can_fail_are_read_as_false_on_an_error() {
    let root = repo_root();
    let dir = temp_dir();
    let model = root.join("tests/verify/goal_errors.sc");
    // (system, property, violated or reachable) by hand.
    let expected = [
        ("Goals", "div_fails", true),
        ("Goals", "div_guarded", false),
        ("Goals", "six", true),
        ("Goals", "five", false),
        ("Assumed", "div_fails", false),
    ];
    for (system, prop, hand) in expected {
        let (theirs, _) = spin(&dir, &model, system, &[prop]);
        assert_eq!(theirs, hand, "SPIN on {system}.{prop}");
        let v = verify(&model, system);
        let ours = v["results"]
            .as_array()
            .and_then(|r| r.iter().find(|r| r["property"] == prop))
            .and_then(|r| r["verdict"].as_str())
            .map(|s| matches!(s, "violated" | "reachable"));
        assert_eq!(ours, Some(hand), "statecheck on {system}.{prop}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The FAM closed loop (master + 1 FAM), whose properties and assumes can fail at run time,
/// exports to Promela that SPIN accepts and gcc compiles (its state space is for
/// `scripts/bench_spin.sh`, not a test).
#[test]
fn the_fam_closed_loop_exports_to_promela_that_spin_and_gcc_accept() {
    let root = repo_root();
    let dir = temp_dir();
    let pml = dir.join("m.pml");
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .args(["export", "promela"])
        .arg(root.join("examples/fam/fam_system.sc"))
        .arg("-o")
        .arg(&pml)
        .output()
        .expect("export runs");
    assert!(
        out.status.success(),
        "export: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let a = Command::new("spin")
        .args(["-a", "m.pml"])
        .current_dir(&dir)
        .output()
        .expect("spin runs");
    assert!(
        a.status.success() && dir.join("pan.c").exists(),
        "spin -a: {}",
        String::from_utf8_lossy(&a.stdout)
    );
    let cc = Command::new("gcc")
        .args(["-O0", "-DSAFETY", "-DNOFAIR", "-o", "pan", "pan.c"])
        .current_dir(&dir)
        .output()
        .expect("gcc runs");
    assert!(
        cc.status.success(),
        "gcc pan.c: {}",
        String::from_utf8_lossy(&cc.stderr)
    );
    let _ = std::fs::remove_dir_all(&dir);
}
