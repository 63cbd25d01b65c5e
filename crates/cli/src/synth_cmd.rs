//! `statecheck synth`: supervisory controller synthesis, and the supervisor check behind
//! `statecheck verify SUP.sc --plant MODEL.sc` (see `docs/synthesis.md`).
//!
//! Exit codes: 0 a supervisor was found (or the check passed), 1 model errors (or the check
//! found violations), 2 usage errors, 3 no supervisor exists (the reason is printed).

use crate::{diag, load, write_out};
use anyhow::{anyhow, Result};
use clap::Args;
use statecheck_synth::{check, emit, extract, synthesize, Engine, Outcome, Problem};
use std::time::Instant;

/// Arguments of `statecheck synth`.
#[derive(Args)]
pub struct SynthArgs {
    /// The `.sc` model file with plant and requirement charts and a system.
    model: String,
    /// The system of plants and requirements (default: the only system).
    #[arg(long)]
    system: Option<String>,
    /// Write the supervisor as a `.sc` system to this file.
    #[arg(short, long, value_name = "OUT.sc")]
    output: Option<String>,
    /// `explicit` (enumerates the reachable product) or `symbolic` (BDDs).
    #[arg(long, default_value = "explicit")]
    engine: String,
    /// Also check the emitted supervisor against the plant in the closed loop.
    #[arg(long)]
    check: bool,
    /// Print only one line: engine, time, supervisor states and transitions.
    #[arg(long, short)]
    quiet: bool,
}

/// Read a model and build the synthesis problem of one of its systems.
fn problem(path: &str, system: Option<&str>) -> Result<Problem> {
    let loaded = load::load(path, false)?;
    let file = &loaded.file;
    let sys = extract::find_system(file, system).map_err(|e| anyhow!("{path}: {e}"))?;
    extract::extract(file, sys).map_err(|diags| {
        diag::eprint_sources(&loaded.sources, &diags);
        anyhow::Error::new(load::ModelErrors)
    })
}

/// Run the command; returns the exit code.
pub fn run(a: SynthArgs) -> Result<u8> {
    let engine: Engine = a.engine.parse().map_err(|e: String| anyhow!(e))?;
    let p = problem(&a.model, a.system.as_deref())?;
    let t = Instant::now();
    let s = synthesize(&p, engine).map_err(|e| anyhow!(e))?;
    let secs = t.elapsed().as_secs_f64();
    let sup = match s.outcome {
        Outcome::Empty(why) => {
            println!("{why}");
            return Ok(3);
        }
        Outcome::Supervisor(sup) => sup,
    };
    let engine_name = match engine {
        Engine::Explicit => "explicit",
        Engine::Symbolic => "symbolic",
    };
    if a.quiet {
        println!(
            "{engine_name} {secs:.3}s product {:.3e} supervisor {} states {} transitions",
            s.product_states, sup.states, sup.transitions
        );
    } else {
        println!(
            "system {}: {} automata, {} events; {engine_name} engine, {secs:.3} s",
            p.name,
            p.automata.len(),
            p.events.len()
        );
        println!(
            "supervisor: {} states, {} transitions (product: {:.0} states)",
            sup.states, sup.transitions, s.product_states
        );
        println!("guards (where each controllable event is allowed):");
        for g in &sup.guards {
            println!(
                "  {}: {}",
                p.events[g.event as usize].name,
                emit::guard_text(&p, &g.allow)
            );
        }
    }
    let text = emit::emit(&p, &sup, &a.model);
    if let Some(out) = &a.output {
        write_out(Some(out), &text)?;
    }
    if a.check {
        let r = check_text(&p, &text, a.output.as_deref().unwrap_or("<supervisor>"))?;
        print_report(&r, a.quiet);
        if !r.violations.is_empty() {
            return Ok(1);
        }
    }
    Ok(0)
}

fn check_text(p: &Problem, text: &str, name: &str) -> Result<check::Report> {
    let (file, mut diags) = statecheck_syntax::parse(text);
    let (model, more) = statecheck_model::check(&file);
    diags.extend(more);
    diags.retain(|d| d.is_error());
    if !diags.is_empty() {
        diag::eprint(name, text, &diags);
        return Err(load::ModelErrors.into());
    }
    let sys = model
        .systems
        .iter()
        .find(|s| !s.implicit)
        .ok_or_else(|| anyhow!("{name}: no system"))?;
    let program = statecheck_ir::lower(&model, sys).map_err(|d| {
        diag::eprint(name, text, &d);
        anyhow::Error::new(load::ModelErrors)
    })?;
    check::check(p, &model, &program).map_err(|e| anyhow!("{name}: {e}"))
}

fn print_report(r: &check::Report, quiet: bool) {
    if !quiet {
        println!(
            "closed loop: {} states ({} plant states), {} event transitions",
            r.closed_loop_states, r.plant_states, r.event_transitions
        );
    }
    if r.violations.is_empty() {
        println!("supervisor check: controllable, nonblocking, requirements hold");
    } else {
        for v in &r.violations {
            println!("violation: {v}");
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
