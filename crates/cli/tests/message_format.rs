//! `--message-format json`: one JSON object per diagnostic and line on standard error, for
//! `check`, `lint` and `verify`. Positions are counted by hand on the files (1-based).

#![allow(clippy::unwrap_used)] // tests may unwrap

use serde_json::Value;
use std::process::Command;

fn run(args: &[&str]) -> (Option<i32>, Vec<Value>) {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(root)
        .args(args)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    let lines = err
        .lines()
        .filter(|l| l.starts_with('{'))
        .map(|l| serde_json::from_str(l).unwrap_or_else(|e| panic!("{e}: {l}")))
        .collect();
    (out.status.code(), lines)
}

#[test]
fn check_prints_each_diagnostic_as_one_json_line() {
    let f = "tests/diagnostics/e0111_unknown_target.sc";
    let (code, ds) = run(&["check", f, "--message-format", "json"]);
    assert_eq!(code, Some(1));
    assert_eq!(ds.len(), 2, "{ds:?}");
    // Line 8 `      state A { on go -> B; }`: `B` is column 26.
    let d = &ds[0];
    assert_eq!(d["code"], "E0111");
    assert_eq!(d["severity"], "error");
    assert_eq!(d["message"], "no state `B` to go to");
    assert_eq!(d["file"], f);
    assert_eq!((d["line"].as_u64(), d["col"].as_u64()), (Some(8), Some(26)));
    assert_eq!(d["end"], serde_json::json!({ "line": 8, "col": 27 }));
    assert_eq!(d["label"], "unknown target");
    assert_eq!(d["labels"], serde_json::json!([]));
    assert!(d["hint"].as_str().unwrap().contains("right.B"));
    // Line 12 `      state B { on go -> Idel; }`: `Idel` is columns 26..30.
    assert_eq!(
        (ds[1]["line"].as_u64(), ds[1]["col"].as_u64()),
        (Some(12), Some(26))
    );
    assert_eq!(ds[1]["end"]["col"], 30);
    assert_eq!(ds[1]["hint"], "did you mean `Idle`?");
}

#[test]
fn verify_and_lint_use_the_same_format() {
    // Line 5 `    on [x = 3] -> A;`: the `=` is column 11.
    let f = "tests/diagnostics/e0015_assign_in_guard.sc";
    for cmd in ["verify", "lint"] {
        let (code, ds) = run(&[cmd, "--message-format", "json", f]);
        assert_eq!(code, Some(1), "{cmd}");
        assert_eq!(ds.len(), 1, "{cmd}: {ds:?}");
        assert_eq!(ds[0]["code"], "E0015");
        assert_eq!(
            (ds[0]["line"].as_u64(), ds[0]["col"].as_u64()),
            (Some(5), Some(11))
        );
        assert_eq!(ds[0]["hint"], "did you mean `==`?");
    }
}
