//! The compiled fast path must do exactly what the tree-walking reference evaluator does.
//!
//! Every model in `tests/` and `examples/` (every system of each) runs 3000 ticks of random
//! inputs on both, and the slots after every tick (also after a run-time error), and any
//! run-time error, must be identical. `src/vm/random_programs.rs` does the same on random IR.

use statecheck_ir::{lower, Machine};
use std::path::{Path, PathBuf};

fn models(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            models(&p, out);
        } else if p.extension().is_some_and(|e| e == "sc") {
            out.push(p);
        }
    }
}

#[test]
fn compiled_code_matches_the_reference_evaluator_on_every_model() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut files = Vec::new();
    models(&root.join("tests"), &mut files);
    models(&root.join("examples"), &mut files);
    let mut checked = 0;
    let mut rng = 7u64;
    let mut next = move || {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        rng
    };
    for f in &files {
        let src = std::fs::read_to_string(f).expect("readable");
        // Follow imports (examples/fam's models import lib/).
        let program = statecheck_model::imports::load_with(&f.to_string_lossy(), src, |k| {
            std::fs::read_to_string(k).ok()
        });
        let (model, d2) = statecheck_model::check(&program.file);
        if program.diags.iter().chain(&d2).any(|d| d.is_error()) {
            continue; // malformed on purpose (diagnostics tests)
        }
        for sys in &model.systems {
            let Ok(p) = lower(&model, sys) else { continue };
            let mut fast = Machine::new(&p);
            let mut slow = Machine::new(&p);
            for tick in 0..3000 {
                for inp in &p.inputs {
                    let s = &p.slots[inp.slot as usize];
                    let v = s.lo + (next() % ((s.hi - s.lo + 1) as u64)) as i64;
                    fast.set(inp.slot, v);
                    slow.set(inp.slot, v);
                }
                let (a, b) = (fast.step(), slow.step_reference());
                assert_eq!(
                    a,
                    b,
                    "{}: system {}: tick {tick}: different outcome",
                    f.display(),
                    sys.name
                );
                // Also after an error: slots are written at the same moments.
                assert_eq!(
                    fast.slots(),
                    slow.slots(),
                    "{}: system {}: tick {tick}: different slots",
                    f.display(),
                    sys.name
                );
                if a.is_err() {
                    break;
                }
                for prop in &p.properties {
                    if let statecheck_ir::PropertyKind::Invariant { expr, .. } = prop.kind {
                        assert_eq!(
                            fast.eval(expr),
                            statecheck_ir::eval(&p.nodes, slow.slots(), expr)
                        );
                    }
                }
            }
            checked += 1;
        }
    }
    eprintln!("checked {checked} systems");
    assert!(checked >= 10, "only {checked} systems checked");
}
