//! What the tests that drive the `statecheck` binary over a model and its hand-written twin
//! share: running the binary from the repository root, and reading `verify --json`.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

/// The repository root (models are named relative to it).
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Run the binary from the repository root; (exit code, stdout, stderr).
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(BIN)
        .current_dir(root())
        .env("NO_COLOR", "1")
        .args(args)
        .output()
        .expect("runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// (states, transitions, each property's name, verdict and decision tick) of a run.
pub type Summary = (u64, u64, Vec<(String, String, Option<u64>)>);

/// The [`Summary`] of `verify --json`'s output `out`.
pub fn summary_of(out: &str) -> Summary {
    let v: Value = serde_json::from_str(out).unwrap_or_else(|e| panic!("{e}: {out}"));
    let rows = v["results"]
        .as_array()
        .map(|a| {
            a.iter()
                .map(|r| {
                    (
                        r["property"].as_str().unwrap_or("?").to_string(),
                        r["verdict"].as_str().unwrap_or("?").to_string(),
                        r["tick"].as_u64(),
                    )
                })
                .collect()
        })
        .unwrap_or_default();
    (
        v["stats"]["states"].as_u64().unwrap_or(0),
        v["stats"]["transitions"].as_u64().unwrap_or(0),
        rows,
    )
}
