//! Shared by the integration tests: every model of `tests/` and `examples/` that checks.

#![allow(dead_code)] // reason: each test binary that includes this module uses only some of it

use std::path::{Path, PathBuf};

fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            walk(&p, out);
        } else if p.extension().is_some_and(|e| e == "sc") {
            out.push(p);
        }
    }
}

/// Every (file, program) of the repository's models that parse, check and lower.
pub fn programs() -> Vec<(String, statecheck_ir::Program)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut files = Vec::new();
    walk(&root.join("tests"), &mut files);
    walk(&root.join("examples"), &mut files);
    let mut out = Vec::new();
    for f in files {
        // The WDS's configurations are beyond a CI budget for the SAT engines and ABC (the
        // circuit of the plant's grids is deep: `docs/case-studies/wds.md`);
        // `crates/cli/tests/wds.rs` compares BMC with the explicit engine on its orderings.
        if f.components().any(|c| c.as_os_str() == "wds") {
            continue;
        }
        let Ok(src) = std::fs::read_to_string(&f) else {
            continue;
        };
        // Follow imports (examples/fam's models import lib/).
        let program = statecheck_model::imports::load_with(&f.to_string_lossy(), src, |k| {
            std::fs::read_to_string(k).ok()
        });
        let (model, d2) = statecheck_model::check(&program.file);
        if program.diags.iter().chain(&d2).any(|d| d.is_error()) {
            continue;
        }
        for sys in &model.systems {
            if let Ok(p) = statecheck_ir::lower(&model, sys) {
                let name = f.strip_prefix(&root).unwrap_or(&f).display().to_string();
                out.push((format!("{name}: {}", sys.name), p));
            }
        }
    }
    out
}
