//! Shared by the explicit engine's benchmarks: a generated model's `Bench` system, lowered.

use statecheck_ir::Program;

/// Parse, check and lower system `Bench` of `text`; a bench model that fails is a bug of the
/// benchmark, reported and exited on.
pub fn bench_program(text: &str) -> Program {
    let (file, diags) = statecheck_syntax::parse(text);
    let (model, more) = statecheck_model::check(&file);
    if let Some(d) = diags.iter().chain(&more).find(|d| d.is_error()) {
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
