//! Rendered-diagnostics snapshots: every `tests/diagnostics/*.sc` file (at the repository root)
//! is run through `statecheck check` and its standard error is snapshotted, so the message,
//! the `file:line:col`, the underline and the hint of every diagnostic are pinned as a user
//! sees them.
//!
//! A file whose name starts with `w` holds only warnings and must pass (exit 0); every other
//! file must be rejected (exit 1). No run may panic.

#![allow(clippy::unwrap_used)] // tests may unwrap

use std::path::{Path, PathBuf};
use std::process::Command;

/// The repository root, from which the binary runs so that displayed paths are relative.
fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The model files, sorted, as paths relative to the repository root.
fn model_files() -> Vec<String> {
    let dir = repo_root().join("tests/diagnostics");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".sc"))
        .collect();
    names.sort();
    names
        .into_iter()
        .map(|n| format!("tests/diagnostics/{n}"))
        .collect()
}

#[test]
fn rendered_diagnostics() {
    let files = model_files();
    assert!(
        files.len() >= 30,
        "expected at least 30 diagnostic models, found {}",
        files.len()
    );
    for rel in files {
        let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
            .current_dir(repo_root())
            .env("NO_COLOR", "1")
            .args(["check", &rel])
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        let stderr = String::from_utf8_lossy(&out.stderr);
        let stem = Path::new(&rel)
            .file_stem()
            .unwrap()
            .to_string_lossy()
            .into_owned();
        assert!(
            !stdout.contains("panicked") && !stderr.contains("panicked"),
            "{rel}: the checker panicked:\n{stderr}"
        );
        let expected = if stem.starts_with('w') { 0 } else { 1 };
        assert_eq!(
            out.status.code(),
            Some(expected),
            "{rel}: wrong exit code; stderr:\n{stderr}"
        );
        if expected == 1 {
            assert!(
                stderr.contains("Error"),
                "{rel}: exit 1 but no error was shown:\n{stderr}"
            );
        }
        insta::with_settings!({ prepend_module_to_snapshot => true, description => rel.as_str(), omit_expression => true }, {
            insta::assert_snapshot!(stem.as_str(), stderr.as_ref());
        });
    }
}
