//! The native library is loaded from a cache directory, so that directory must be private:
//! without one (no `STATECHECK_CACHE_DIR`, `XDG_CACHE_HOME` or `HOME`), or with one that others
//! can write to, the engine runs the interpreter, gives the same answer and says why; the
//! shared temp directory is never used. Its own test binary: it sets process-wide variables.

use statecheck_explicit::{verify, Backend, Options, Report};
use statecheck_native::CCompiler;
use std::sync::Arc;

fn run_toggle() -> Report {
    // x flips on `a`, so x == 1 is reached after tick 1 (tick 0 starts the chart).
    let text = "chart T {\n  input event a;\n  output x: int[0..1] = 0;\n  initial S;\n  state S {\n    on a / { x = 1 - x; };\n  }\n}\nsystem Sys {\n  instance t: T;\n  reachable set: t.x == 1;\n}\n";
    let (file, _) = statecheck_syntax::parse(text);
    let (model, _) = statecheck_model::check(&file);
    let p = statecheck_ir::lower(&model, model.system("Sys").expect("system")).expect("lowers");
    verify(
        &p,
        &Options {
            backend: Backend::Native,
            compiler: Some(Arc::new(CCompiler)),
            ..Options::default()
        },
        None,
    )
    .expect("runs")
}

fn assert_interpreter_answer(r: &Report, note_part: &str) {
    assert_eq!(r.stats.backend, "interpreter");
    let note = r.stats.native_note.clone().unwrap_or_default();
    assert!(note.contains(note_part), "{note}");
    // Pre-start state (x = 0), then x = 0 after tick 0, x = 1 after tick 1: 3 states.
    assert_eq!(r.stats.states, 3);
    assert_eq!(r.results[0].depth, 2);
}

#[test]
fn native_code_only_from_a_private_cache_directory() {
    for v in ["STATECHECK_CACHE_DIR", "XDG_CACHE_HOME", "HOME"] {
        std::env::remove_var(v);
    }
    let tmp_lib_count = || {
        std::fs::read_dir(std::env::temp_dir())
            .map(|d| {
                d.flatten()
                    .filter(|e| {
                        e.file_name()
                            .to_string_lossy()
                            .starts_with("statecheck-native")
                    })
                    .count()
            })
            .unwrap_or(0)
    };
    let before = tmp_lib_count();
    assert_interpreter_answer(&run_toggle(), "no private cache directory");
    assert_eq!(
        tmp_lib_count(),
        before,
        "nothing written to the temp directory"
    );

    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let shared = std::env::temp_dir().join(format!("sc-shared-cache-{}", std::process::id()));
        std::fs::create_dir_all(&shared).expect("mkdir");
        std::fs::set_permissions(&shared, std::fs::Permissions::from_mode(0o777)).expect("chmod");
        std::env::set_var("STATECHECK_CACHE_DIR", &shared);
        let r = run_toggle();
        let _ = std::fs::remove_dir_all(&shared);
        assert_interpreter_answer(&r, "not a private directory");
    }
}
