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

/// Run `sim linear_drive --scenario - --message-format json` on `scenario`; the diagnostics.
fn scenario_errors(scenario: &str) -> (Option<i32>, Vec<serde_json::Value>) {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut child = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(&root)
        .args([
            "sim",
            "examples/linear_drive/linear_drive.sc",
            "--scenario",
            "-",
        ])
        .args(["--message-format", "json"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(scenario.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    let diags = String::from_utf8_lossy(&out.stderr)
        .lines()
        .filter(|l| l.starts_with('{'))
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    (out.status.code(), diags)
}

#[test]
fn scenario_errors_have_codes_positions_suggestions_and_type_errors() {
    // The linear drive's free inputs are the events `ctrl.Run` and `ctrl.Halt`.
    // Line 2: `true` given to an event; line 3: a misspelt input (`Hlat`, two edits from
    // `Halt`); line 4 (columns 6..7 after `Run, `): `Halt` given `1`.
    let (code, ds) = scenario_errors("Run\nHalt = true\nHlat\nRun, Halt = 1\n");
    assert_eq!(code, Some(1));
    let got: Vec<(String, u64, u64)> = ds
        .iter()
        .map(|d| {
            (
                d["code"].as_str().unwrap().to_string(),
                d["line"].as_u64().unwrap(),
                d["col"].as_u64().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        got,
        [
            ("E0805".to_string(), 2, 1),
            ("E0803".to_string(), 3, 1),
            ("E0805".to_string(), 4, 6)
        ]
    );
    assert_eq!(ds[0]["file"], "<stdin>");
    assert_eq!(
        ds[0]["message"],
        "event `ctrl.Halt` takes no value, found `true`"
    );
    assert_eq!(ds[1]["hint"], "did you mean `Halt`?");
    assert_eq!(ds[2]["end"]["col"], 14, "`Halt = 1` is columns 6..14");
}

#[test]
fn a_number_given_to_a_bool_is_a_type_error() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut child = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(&root)
        .args([
            "sim",
            "examples/fam/fam.sc",
            "--system",
            "FamAlone",
            "--scenario",
            "-",
        ])
        .args(["--message-format", "json"])
        .stdin(Stdio::piped())
        .stderr(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    // `stallNow` is `input stallNow: bool` of the FAM chart.
    child
        .stdin
        .take()
        .unwrap()
        .write_all(b"stallNow = 1\nstallNow = ture\n")
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let ds: Vec<serde_json::Value> = String::from_utf8_lossy(&out.stderr)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(ds.len(), 2);
    assert_eq!(ds[0]["code"], "E0808");
    assert_eq!(ds[0]["message"], "`fam.stallNow` is a `bool`, found `1`");
    assert_eq!(ds[0]["hint"], "`true` or `false`");
    assert_eq!(ds[1]["hint"], "did you mean `true`?");
}
