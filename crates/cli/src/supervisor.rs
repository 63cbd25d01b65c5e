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

/// Read a model and build the synthesis problem of one of its systems.
pub fn problem(path: &str, system: Option<&str>) -> Result<Problem> {
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
    let p = problem(plant_path, plant_system)?;
    let loaded = load::load(sup_path, false)?;
    let sys = loaded.system(sup_system)?;
    let program = loaded.lower(sys)?;
    let r = check::check(&p, &loaded.model, &program).map_err(|e| anyhow!("{sup_path}: {e}"))?;
    print_report(&r, quiet);
    Ok(if r.violations.is_empty() { 0 } else { 1 })
}
