//! Repository rules that code review alone would let slip (after rust-analyzer's `tidy.rs`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// Where each workspace crate sits in the pipeline: a crate may depend only on crates of a
/// lower layer, so crates of one layer (the engines and generators above all) never depend on
/// each other. A new crate must be placed here.
const LAYERS: [(&str, u32); 19] = [
    ("statecheck-base", 0),
    ("statecheck-syntax", 1),
    ("statecheck-fmt", 2),
    ("statecheck-model", 2),
    ("statecheck-ir", 3),
    // The consumers of the IR, side by side.
    ("statecheck-sim", 4),
    ("statecheck-explicit", 4),
    ("statecheck-symbolic", 4),
    ("statecheck-synth", 4),
    ("statecheck-codegen", 4),
    // The explicit engine's native successor generator (explicit + codegen).
    ("statecheck-native", 5),
    // The explicit search distributed over timely dataflow workers (explicit's hooks).
    ("statecheck-dist", 5),
    // The portfolio over the engines.
    ("statecheck-verify", 6),
    // The edges: they read files, serve, print.
    ("statecheck-lsp", 7),
    ("statecheck-studio", 7),
    ("statecheck-cli", 8),
    ("statecheck-tidy", 9),
    ("statecheck-bench", 9),
    // Fuzzing and differential testing over every consumer of the IR.
    ("statecheck-fuzz", 9),
];

/// The checkers: not even their tests depend on one another (cross-checks live above them).
const CHECKERS: [&str; 3] = [
    "statecheck-explicit",
    "statecheck-symbolic",
    "statecheck-synth",
];

/// Crates for the edges only (argument parsing, error reporting, serialisation, rendering).
const EDGE_ONLY: [&str; 4] = ["clap", "anyhow", "ariadne", "serde"];

/// Crates allowed the edge-only dependencies.
const EDGES: [&str; 3] = ["statecheck-cli", "statecheck-studio", "statecheck-lsp"];

struct Manifest {
    name: String,
    deps: Vec<String>,
    dev_deps: Vec<String>,
}

fn dep_names(t: &toml::Table, key: &str) -> Vec<String> {
    let mut out: Vec<String> = t
        .get(key)
        .and_then(|d| d.as_table())
        .map(|d| d.keys().cloned().collect())
        .unwrap_or_default();
    // Target-specific tables: `[target.'cfg(..)'.dependencies]`.
    if let Some(targets) = t.get("target").and_then(|x| x.as_table()) {
        for spec in targets.values().filter_map(|v| v.as_table()) {
            if let Some(d) = spec.get(key).and_then(|d| d.as_table()) {
                out.extend(d.keys().cloned());
            }
        }
    }
    out
}

fn manifests() -> Vec<Manifest> {
    let mut out = Vec::new();
    let dir = root().join("crates");
    let mut entries: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("crates/")
        .flatten()
        .map(|e| e.path().join("Cargo.toml"))
        .filter(|p| p.exists())
        .collect();
    entries.sort();
    for path in entries {
        let text = std::fs::read_to_string(&path).expect("readable manifest");
        let t: toml::Table = text.parse().expect("valid manifest");
        let name = t["package"]["name"].as_str().expect("name").to_string();
        out.push(Manifest {
            name,
            deps: dep_names(&t, "dependencies"),
            dev_deps: dep_names(&t, "dev-dependencies"),
        });
    }
    out
}

#[test]
fn crates_depend_only_on_lower_layers() {
    let layer: BTreeMap<&str, u32> = LAYERS.iter().copied().collect();
    let mut errors = Vec::new();
    for m in manifests() {
        let Some(&own) = layer.get(m.name.as_str()) else {
            errors.push(format!(
                "{}: not placed in a layer (add it to LAYERS in crates/tidy/tests/tidy.rs)",
                m.name
            ));
            continue;
        };
        for d in m.deps.iter().filter(|d| d.starts_with("statecheck-")) {
            match layer.get(d.as_str()) {
                Some(&l) if l < own => {}
                _ => errors.push(format!(
                    "{} (layer {own}) depends on {d}, which is not in a lower layer",
                    m.name
                )),
            }
        }
        if CHECKERS.contains(&m.name.as_str()) {
            for d in m.dev_deps.iter().filter(|d| *d != &m.name) {
                if CHECKERS.contains(&d.as_str()) {
                    errors.push(format!(
                        "{}: its tests depend on the checker {d}; cross-checks belong above both",
                        m.name
                    ));
                }
            }
        }
        if own == 4 && m.deps.iter().any(|d| d == "statecheck-syntax") {
            errors.push(format!(
                "{}: consumers of the IR do not depend on the parser (use the IR's re-exports)",
                m.name
            ));
        }
        if !EDGES.contains(&m.name.as_str()) {
            for d in m.deps.iter().filter(|d| EDGE_ONLY.contains(&d.as_str())) {
                errors.push(format!(
                    "{}: depends on {d}, which only the edges (cli, studio, lsp) use",
                    m.name
                ));
            }
        }
    }
    assert!(errors.is_empty(), "layering:\n{}", errors.join("\n"));
}

/// Every `.rs` file of the workspace's crates.
fn sources() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let p = e.path();
            let name = e.file_name();
            if p.is_dir() {
                if name != "target" && name != "node_modules" {
                    walk(&p, out);
                }
            } else if p.extension().is_some_and(|x| x == "rs") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(&root().join("crates"), &mut out);
    out.sort();
    out
}

#[test]
fn no_ignored_or_should_panic_tests() {
    // Built at run time so that this file does not match itself.
    let banned = [format!("#[{}", "ignore"), format!("#[{}", "should_panic")];
    let mut errors = Vec::new();
    for f in sources() {
        let text = std::fs::read_to_string(&f).unwrap_or_default();
        for (i, line) in text.lines().enumerate() {
            let t = line.trim_start();
            if banned.iter().any(|b| t.starts_with(b.as_str())) {
                errors.push(format!("{}:{}: {}", f.display(), i + 1, t));
            }
        }
    }
    assert!(
        errors.is_empty(),
        "tests must run and must not expect a panic:\n{}",
        errors.join("\n")
    );
}

#[test]
fn every_allow_has_a_reason() {
    let mut errors = Vec::new();
    for f in sources() {
        let text = std::fs::read_to_string(&f).unwrap_or_default();
        let lines: Vec<&str> = text.lines().collect();
        for (i, line) in lines.iter().enumerate() {
            let t = line.trim_start();
            if !(t.starts_with("#[allow(") || t.starts_with("#![allow(")) {
                continue;
            }
            let same_line = t.contains("//");
            let above = i > 0 && lines[i - 1].trim_start().starts_with("//");
            if !same_line && !above {
                errors.push(format!("{}:{}: {}", f.display(), i + 1, t));
            }
        }
    }
    assert!(
        errors.is_empty(),
        "an `#[allow(...)]` needs a comment saying why, on its line or the line above:\n{}",
        errors.join("\n")
    );
}
