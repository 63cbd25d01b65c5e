//! Shared by the explicit engine's benchmarks: a generated model's `Bench` system, lowered.

use statecheck_explicit::{Backend, Stats};
use statecheck_ir::Program;

/// The backend named by `arg` (`native` when absent); exits on an unknown name.
pub fn backend(arg: Option<&String>) -> Backend {
    match arg.map(String::as_str) {
        None | Some("native") => Backend::Native,
        Some("interpreter") => Backend::Interpreter,
        Some("auto") => Backend::Auto,
        Some(other) => {
            eprintln!("unknown backend {other}: native, interpreter or auto");
            std::process::exit(2);
        }
    }
}

/// The line saying what computed the successors.
pub fn backend_line(s: &Stats, asked: Backend) -> String {
    format!(
        "backend: {} (asked {}){}{}",
        s.backend,
        asked.as_str(),
        s.native_build_time
            .map(|t| format!(", native code built in {:.3} s", t.as_secs_f64()))
            .unwrap_or_default(),
        s.native_note
            .as_ref()
            .map(|n| format!(", note: {n}"))
            .unwrap_or_default()
    )
}

/// Parse, check and lower system `Bench` of `text`, read as the file `path` (its imports are
/// read relative to it); a bench model that fails is a bug of the benchmark, reported and
/// exited on.
pub fn bench_program(path: &str, text: &str) -> Program {
    let program = statecheck_model::imports::load_with(path, text.to_string(), |k| {
        std::fs::read_to_string(k).ok()
    });
    let (model, more) = statecheck_model::check(&program.file);
    if let Some(d) = program.diags.iter().chain(&more).find(|d| d.is_error()) {
        eprintln!("bench model does not check: {d:?}");
        std::process::exit(1);
    }
    let Some(sys) = model.system("Bench") else {
        eprintln!("no system Bench");
        std::process::exit(1);
    };
    match statecheck_ir::lower(&model, sys) {
        Ok(p) => p,
        Err(d) => {
            eprintln!("lowering failed: {d:?}");
            std::process::exit(1);
        }
    }
}
