//! Supervisors and their plants, shared by `synth` (which writes and checks a supervisor) and
//! `verify --plant` (which checks one written before): subcommands do not call each other.

use crate::{diag, load};
use anyhow::{anyhow, Result};
use statecheck_synth::{check, extract, Problem};
use std::io::Write;

macro_rules! out {
    ($($t:tt)*) => {{
        let _ = writeln!(std::io::stdout().lock(), $($t)*);
    }};
}

/// True if `path` names a Supremica automata file (`.xml`), read instead of a `.sc` model.
pub fn is_xml(path: &str) -> bool {
    std::path::Path::new(path)
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("xml"))
}

/// True if the `.sc` language accepts `s` as a name (an identifier, not a keyword).
fn is_ident(s: &str) -> bool {
    s.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
        && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && statecheck_syntax::parse(&format!("enum E_ {{ {s} }}"))
            .1
            .is_empty()
}

/// `p` with every name a `.sc` identifier (names of a Supremica file may not be), and the
/// names that changed as `//` comment lines for the emitted file (empty for `.sc` models).
pub fn sc_problem(p: &Problem) -> (Problem, String) {
    let (q, renamed) = statecheck_synth::supremica::idents::sc_names(p, &is_ident);
    let mut notes = String::new();
    if !renamed.is_empty() {
        notes.push_str("// Names of the Supremica file that are not .sc identifiers:\n");
        for r in &renamed {
            notes.push_str(&format!("//   {} `{}` -> {}\n", r.what, r.from, r.to));
        }
    }
    (q, notes)
}

/// Read a model (or a Supremica automata file, by its `.xml` extension) and build the
/// synthesis problem of one of its systems.
pub fn problem(path: &str, system: Option<&str>) -> Result<Problem> {
    if is_xml(path) {
        if system.is_some() {
            return Err(anyhow!(
                "{path}: --system does not apply to a Supremica file (it holds one set of automata)"
            ));
        }
        let text = std::fs::read_to_string(path).map_err(|e| anyhow!("{path}: {e}"))?;
        return statecheck_synth::supremica::read::read(&text).map_err(|e| {
            let d = statecheck_base::Diagnostic::error(e.code, e.message, e.span);
            diag::eprint(path, &text, &[d]);
            anyhow::Error::new(load::ModelErrors)
        });
    }
    let loaded = load::load(path, false)?;
    let sys = extract::find_system(&loaded.model, system).map_err(|e| anyhow!("{path}: {e}"))?;
    extract::extract(&loaded.model, sys).map_err(|diags| {
        diag::eprint_sources(&loaded.sources, &diags);
        anyhow::Error::new(load::ModelErrors)
    })
}

/// Print a supervisor check: the closed loop's size (unless `quiet`) and the verdict.
pub fn print_report(r: &check::Report, quiet: bool) {
    if !quiet {
        out!(
            "closed loop: {} states ({} plant states), {} event transitions",
            r.closed_loop_states,
            r.plant_states,
            r.event_transitions
        );
    }
    if r.violations.is_empty() {
        out!("supervisor check: controllable, nonblocking, requirements hold");
    } else {
        for v in &r.violations {
            out!("violation: {v}");
        }
    }
}

/// `statecheck verify SUP.sc --plant MODEL.sc`: check a supervisor system against a plant.
pub fn verify_supervisor(
    sup_path: &str,
    sup_system: Option<&str>,
    plant_path: &str,
    plant_system: Option<&str>,
    quiet: bool,
) -> Result<u8> {
    let (p, _) = sc_problem(&problem(plant_path, plant_system)?);
    let loaded = load::load(sup_path, false)?;
    let sys = loaded.system(sup_system)?;
    let program = loaded.lower(sys)?;
    let r = check::check(&p, &loaded.model, &program).map_err(|e| anyhow!("{sup_path}: {e}"))?;
    print_report(&r, quiet);
    Ok(if r.violations.is_empty() { 0 } else { 1 })
}
