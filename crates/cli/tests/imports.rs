//! Imports through the binary: the library search path (`--lib`, `STATECHECK_PATH`), files
//! relative to the importing one, and equality with the same model written out by hand
//! (`tests/imports/app/plant_flat.sc`): same verdicts, state counts and traces.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn app(name: &str) -> String {
    format!("tests/imports/app/{name}")
}

/// Run the binary from the repository root; (exit code, stdout, stderr).
fn run(args: &[&str], path_env: Option<&str>) -> (i32, String, String) {
    let mut c = Command::new(BIN);
    c.current_dir(root()).env("NO_COLOR", "1").args(args);
    match path_env {
        Some(p) => c.env("STATECHECK_PATH", p),
        None => c.env_remove("STATECHECK_PATH"),
    };
    let out = c.output().expect("runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// (states, transitions, verdict of `follows`, verdict of `lit`) of `verify --json`.
fn stats(v: &Value) -> (u64, u64, String, String) {
    let verdict = |n: &str| {
        v["results"]
            .as_array()
            .and_then(|a| a.iter().find(|r| r["property"] == n))
            .and_then(|r| r["verdict"].as_str())
            .unwrap_or("?")
            .to_string()
    };
    (
        v["stats"]["states"].as_u64().unwrap_or(0),
        v["stats"]["transitions"].as_u64().unwrap_or(0),
        verdict("follows"),
        verdict("lit"),
    )
}

fn verify(args: &[&str], path_env: Option<&str>) -> Value {
    let mut all = vec!["verify", "--engine", "explicit", "--json"];
    all.extend_from_slice(args);
    let (code, out, err) = run(&all, path_env);
    assert_eq!(code, 0, "{err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"))
}

#[test]
fn a_library_file_is_not_found_without_the_search_path() {
    let (code, _, err) = run(&["check", &app("plant.sc")], None);
    assert_eq!(code, 1);
    assert!(
        err.contains("E0140") && err.contains("cannot find `sensors.sc`"),
        "{err}"
    );
    // The hint lists where the file was looked for: next to the importing file.
    assert!(err.contains("tests/imports/app/sensors.sc"), "{err}");
}

#[test]
fn lib_flag_and_statecheck_path_find_the_library() {
    // Derived by hand in plant.sc: 3 states, 10 input vectors each; `follows` holds, `lit`
    // is reachable.
    let want = (3, 30, "proved".to_string(), "reachable".to_string());
    let by_flag = verify(&[&app("plant.sc"), "--lib", "tests/imports/lib"], None);
    assert_eq!(stats(&by_flag), want, "{by_flag}");
    let by_env = verify(&[&app("plant.sc")], Some("/nonexistent:tests/imports/lib"));
    assert_eq!(stats(&by_env), want, "{by_env}");
    let flat = verify(&[&app("plant_flat.sc")], None);
    assert_eq!(stats(&flat), want, "{flat}");
}

#[test]
fn the_imported_model_runs_like_the_one_written_out() {
    let sim = |file: &str| {
        let (code, out, err) = run(
            &[
                "sim",
                &app(file),
                "--lib",
                "tests/imports/lib",
                "--scenario",
                &app("run.scn"),
                "--json",
            ],
            None,
        );
        assert_eq!(code, 0, "{err}");
        let v: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"));
        v["ticks"].clone()
    };
    let imported = sim("plant.sc");
    assert_eq!(imported, sim("plant_flat.sc"));
    // By hand (run.scn): lit is false, true, false in ticks 0, 1, 2.
    let lits: Vec<Value> = imported
        .as_array()
        .map(|a| a.iter().map(|t| t["vars"]["lamp.lit"].clone()).collect())
        .unwrap_or_default();
    assert_eq!(lits, [false, true, false], "{imported}");
}
