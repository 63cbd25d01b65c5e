//! Without a working C compiler, `--backend native` falls back to the interpreter, says why,
//! and gives the interpreter's answer. Its own test binary: it sets process-wide variables.

use statecheck_explicit::{verify, Backend, Options};
use statecheck_native::CCompiler;
use std::sync::Arc;

#[test]
fn no_compiler_means_the_interpreter_with_a_note() {
    let cache = std::env::temp_dir().join(format!("statecheck-no-cc-{}", std::process::id()));
    std::env::set_var("STATECHECK_CACHE_DIR", &cache);
    std::env::set_var("CC", "/nonexistent/cc");
    // Two toggles: x flips on `a`, so x == 1 is reached after tick 1 (tick 0 starts the chart).
    let text = "chart T {\n  input event a;\n  output x: int[0..1] = 0;\n  initial S;\n  state S {\n    on a / { x = 1 - x; };\n  }\n}\nsystem Sys {\n  instance t: T;\n  reachable set: t.x == 1;\n}\n";
    let (file, _) = statecheck_syntax::parse(text);
    let (model, _) = statecheck_model::check(&file);
    let p = statecheck_ir::lower(&model, model.system("Sys").expect("system")).expect("lowers");
    let r = verify(
        &p,
        &Options {
            backend: Backend::Native,
            compiler: Some(Arc::new(CCompiler)),
            ..Options::default()
        },
        None,
    )
    .expect("runs");
    let _ = std::fs::remove_dir_all(&cache);
    assert_eq!(r.stats.backend, "interpreter");
    let note = r.stats.native_note.clone().unwrap_or_default();
    assert!(note.contains("/nonexistent/cc"), "{note}");
    // Pre-start state (x = 0), then x = 0 after tick 0, x = 1 after tick 1: 3 states.
    assert_eq!(r.stats.states, 3);
    assert_eq!(r.results[0].depth, 2);
}
