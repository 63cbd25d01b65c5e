//! Data-driven tests of the step semantics (docs/semantics.md).
//!
//! Every `tests/semantics/*.scn` scenario runs through `statecheck sim` on its model (the
//! `.sc` file with the same stem, or the stem before the first `_`), and the printed trace must
//! equal the hand-derived `.expected` file next to it. Directives in the scenario's comments:
//! `# args: ...` extra CLI arguments, `# exit: N` the expected exit code (default 0),
//! `# stderr: text` a substring expected on stderr. `UPDATE_EXPECT=1` rewrites the expected
//! files — only do that after deriving the new expectation by hand.

use std::path::{Path, PathBuf};
use std::process::Command;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn directive<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    text.lines()
        .find_map(|l| l.strip_prefix(&format!("# {key}:")).map(str::trim))
}

#[test]
fn every_scenario_matches_its_hand_derived_trace() {
    let root = repo_root();
    let dir = root.join("tests/semantics");
    let mut scenarios: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("tests/semantics exists")
        .map(|e| e.expect("readable dir entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "scn"))
        .collect();
    scenarios.sort();
    assert!(
        scenarios.len() >= 9,
        "expected the semantics scenarios, found {}",
        scenarios.len()
    );
    let mut failures = Vec::new();
    for scn in &scenarios {
        let stem = scn
            .file_stem()
            .and_then(|s| s.to_str())
            .expect("utf-8 name");
        let model = if dir.join(format!("{stem}.sc")).exists() {
            format!("{stem}.sc")
        } else {
            format!("{}.sc", stem.split('_').next().unwrap_or(stem))
        };
        let text = std::fs::read_to_string(scn).expect("scenario readable");
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_statecheck"));
        cmd.current_dir(&root)
            .env("NO_COLOR", "1")
            .arg("sim")
            .arg(format!("tests/semantics/{model}"));
        cmd.arg("--scenario")
            .arg(format!("tests/semantics/{stem}.scn"));
        if let Some(args) = directive(&text, "args") {
            cmd.args(args.split_whitespace());
        }
        let out = cmd.output().expect("statecheck runs");
        let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
        let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
        assert!(!stderr.contains("panicked"), "{stem}: panic: {stderr}");
        let want_exit: i32 = directive(&text, "exit").map_or(0, |e| e.parse().expect("exit code"));
        if out.status.code() != Some(want_exit) {
            failures.push(format!(
                "{stem}: exit {:?}, expected {want_exit}; stderr:\n{stderr}",
                out.status.code()
            ));
        }
        if let Some(needle) = directive(&text, "stderr") {
            if !stderr.contains(needle) {
                failures.push(format!("{stem}: stderr lacks `{needle}`:\n{stderr}"));
            }
        }
        let expected_path = dir.join(format!("{stem}.expected"));
        if std::env::var_os("UPDATE_EXPECT").is_some() {
            std::fs::write(&expected_path, &stdout).expect("write expected");
            continue;
        }
        let expected = std::fs::read_to_string(&expected_path).unwrap_or_default();
        if expected != stdout {
            failures.push(format!(
                "{stem}: trace differs\n--- expected\n{expected}--- actual\n{stdout}"
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}
