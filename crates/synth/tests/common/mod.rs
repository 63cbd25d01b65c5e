//! Helpers shared by the synthesis test binaries: a model from text, its synthesis problem,
//! the examples of `examples/synthesis/`, supervisor sizes.

// Each test binary compiles this module and uses a subset of the helpers.
#![allow(dead_code)]

use statecheck_synth::{extract, synthesize, Engine, Outcome, Problem};

/// The checked model of `text`, which must parse and check without errors.
pub fn model_of(text: &str) -> statecheck_model::Model {
    let (file, diags) = statecheck_syntax::parse(text);
    assert!(diags.is_empty(), "{diags:?}");
    let (model, diags) = statecheck_model::check(&file);
    assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
    model
}

/// The synthesis problem of `system` (or the only system) of `text`.
pub fn problem_of(text: &str, system: Option<&str>) -> Problem {
    let model = model_of(text);
    let sys = extract::find_system(&model, system).expect("system");
    extract::extract(&model, sys).expect("extract")
}

/// The text of `examples/synthesis/NAME`.
pub fn example(name: &str) -> String {
    let path = format!(
        "{}/../../examples/synthesis/{name}",
        env!("CARGO_MANIFEST_DIR")
    );
    std::fs::read_to_string(&path).expect("example file")
}

/// The supervisor's states and transitions, `None` when none exists.
pub fn sizes(p: &Problem, engine: Engine) -> Option<(u128, u128)> {
    match synthesize(p, engine).expect("synthesis").outcome {
        Outcome::Supervisor(s) => Some((s.states, s.transitions)),
        Outcome::Empty(_) => None,
    }
}
