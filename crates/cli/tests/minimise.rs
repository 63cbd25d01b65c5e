//! Minimised counterexamples and witnesses (docs/verification.md, "Minimised
//! counterexamples"): inputs that do not matter are kept at their previous value, and the
//! minimised scenario still replays to the same verdict.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn statecheck(args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(root())
        .env("NO_COLOR", "1")
        .args(args)
        .output()
        .expect("statecheck runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    out
}

/// The scenario lines of a counterexample file (its comments dropped).
fn scenario_lines(path: &Path) -> Vec<String> {
    std::fs::read_to_string(path)
        .expect("counterexample written")
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(str::to_string)
        .collect()
}

/// tests/verify/minimise.sc (derivation in the model): BMC's raw counterexample sets the
/// irrelevant `noise` (initially true) to false at tick 0; minimised, the only change is
/// `go = true` at tick 1, held to the violation at tick 3 (and to the witness of `two`
/// at tick 2). Both engines give the same minimised traces, and they replay in `sim`.
#[test]
fn counterexamples_keep_only_the_inputs_that_matter() {
    let dir = std::env::temp_dir().join(format!("statecheck-minimise-{}", std::process::id()));
    let d = dir.to_string_lossy().into_owned();
    let raw = dir.join("raw");
    let r = raw.to_string_lossy().into_owned();
    let out = statecheck(&[
        "verify",
        "tests/verify/minimise.sc",
        "--engine",
        "bmc",
        "--cex-dir",
        &r,
        "--no-minimise",
        "-q",
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        scenario_lines(&raw.join("below_three.scn")).contains(&"c.noise = false".to_string()),
        "the raw BMC trace changes `noise`"
    );
    for engine in ["bmc", "explicit"] {
        let out = statecheck(&[
            "verify",
            "tests/verify/minimise.sc",
            "--engine",
            engine,
            "--cex-dir",
            &d,
            "-q",
        ]);
        assert_eq!(out.status.code(), Some(1), "{engine}");
        assert_eq!(
            scenario_lines(&dir.join("below_three.scn")),
            ["-", "c.go = true", "- * 2"],
            "{engine}"
        );
        assert_eq!(
            scenario_lines(&dir.join("two.scn")),
            ["-", "c.go = true", "-"],
            "{engine}"
        );
        let scn = dir.join("below_three.scn").to_string_lossy().into_owned();
        let out = statecheck(&["sim", "tests/verify/minimise.sc", "--scenario", &scn, "-q"]);
        assert_eq!(out.status.code(), Some(4), "{engine}");
        assert!(String::from_utf8_lossy(&out.stderr)
            .contains("property `below_three` violated at tick 3"));
        let scn = dir.join("two.scn").to_string_lossy().into_owned();
        let out = statecheck(&[
            "sim",
            "tests/verify/minimise.sc",
            "--scenario",
            &scn,
            "--json",
        ]);
        assert_eq!(out.status.code(), Some(0), "{engine}");
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
        assert_eq!(v["reached"]["two"], 2, "{engine}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
