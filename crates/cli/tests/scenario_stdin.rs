//! `sim --scenario -` reads the scenario from standard input: the same run as from the file
//! (whose trace `examples.rs` checks against the scenario's hand-derived `# expect` lines).

#![allow(clippy::unwrap_used)] // tests may unwrap

use std::io::Write;
use std::process::{Command, Stdio};

#[test]
fn scenario_from_standard_input_runs_like_the_file() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let model = "examples/linear_drive/linear_drive.sc";
    let scn = "examples/linear_drive/scenarios/halt_resume.scn";
    let bin = env!("CARGO_BIN_EXE_statecheck");
    let from_file = Command::new(bin)
        .current_dir(&root)
        .args(["sim", model, "--scenario", scn, "--json"])
        .output()
        .unwrap();
    assert_eq!(from_file.status.code(), Some(0));
    let mut child = Command::new(bin)
        .current_dir(&root)
        .args(["sim", model, "--scenario", "-", "--json"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let text = std::fs::read(root.join(scn)).unwrap();
    child.stdin.take().unwrap().write_all(&text).unwrap();
    let from_stdin = child.wait_with_output().unwrap();
    assert_eq!(from_stdin.status.code(), Some(0));
    assert!(!from_file.stdout.is_empty());
    assert!(from_file.stdout == from_stdin.stdout, "the two runs differ");
}
