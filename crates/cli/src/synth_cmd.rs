//! `statecheck synth`: supervisory controller synthesis, and the supervisor check behind
//! `statecheck verify SUP.sc --plant MODEL.sc` (see `docs/synthesis.md`).
//!
//! Exit codes: 0 a supervisor was found (or the check passed), 1 model errors (or the check
//! found violations), 2 usage errors, 3 no supervisor exists (the reason is printed) or
//! `unknown`: a limit (`--timeout`, `--max-memory`, `--max-states`) stopped the engine (the
//! figures it reached are printed).
//!
//! Standard output may be a closed pipe (`synth … | head`): printing stops quietly, and the
//! `-o` file is written before anything is printed.

use crate::supervisor::{print_report, problem, sc_problem};
use crate::{diag, load, write_out};
use anyhow::{anyhow, bail, Result};
use clap::Args;
use statecheck_synth::{
    check, emit, synthesize_with, Engine, ErrorKind, Limits, Options, Outcome, Problem,
};
use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// `println!` that ignores a closed standard output instead of panicking.
macro_rules! out {
    ($($t:tt)*) => {{
        let _ = writeln!(std::io::stdout().lock(), $($t)*);
    }};
}

/// Arguments of `statecheck synth`.
#[derive(Args)]
pub struct SynthArgs {
    /// The `.sc` model file with plant and requirement charts and a system, or a Supremica
    /// automata file (`.xml`).
    model: String,
    /// The system of plants and requirements (default: the only system).
    #[arg(long)]
    system: Option<String>,
    /// Write the supervisor as a `.sc` system to this file.
    #[arg(short, long, value_name = "OUT.sc")]
    output: Option<String>,
    /// `explicit` (enumerates the reachable product), `symbolic` (BDDs) or `auto` (explicit
    /// for products of at most 10^5 states, else both raced on two threads).
    #[arg(long, default_value = "auto")]
    engine: String,
    /// Stop with `unknown` (exit 3) after this many seconds.
    #[arg(long, value_name = "SECS")]
    timeout: Option<f64>,
    /// Stop with `unknown` (exit 3) when the process's memory exceeds SIZE (e.g. 512M, 2G).
    #[arg(long, value_name = "SIZE")]
    max_memory: Option<String>,
    /// Stop with `unknown` (exit 3) when the explicit engine has found more product states.
    #[arg(long, value_name = "N")]
    max_states: Option<u64>,
    /// Also check the emitted supervisor against the plant in the closed loop.
    #[arg(long)]
    check: bool,
    /// Print only one line: engine, time, product and supervisor sizes (or "no supervisor").
    #[arg(long, short)]
    quiet: bool,
    /// Threads of the explicit engine's exploration: 1, or 2 for its pipeline (one thread
    /// computes successors, the other numbers them; the same result). Default: 2 on a machine
    /// with two or more cores. Under `--engine auto`'s race the explicit engine has one.
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
}

/// Parse a size such as `512M`, `2G`, `1.5GiB`, `1000000` (bytes).
fn parse_size(s: &str) -> Result<u64> {
    let t = s.trim();
    let split = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (num, unit) = t.split_at(split);
    let Ok(n) = num.parse::<f64>() else {
        bail!("bad size `{s}`: write a number with an optional unit, e.g. 512M or 2G");
    };
    let shift = match unit
        .trim()
        .to_ascii_uppercase()
        .trim_end_matches("IB")
        .trim_end_matches('B')
    {
        "" => 0,
        "K" => 10,
        "M" => 20,
        "G" => 30,
        "T" => 40,
        _ => bail!("bad size unit in `{s}`: use K, M, G or T"),
    };
    let bytes = n * (1u64 << shift) as f64;
    if !(bytes >= 1.0 && bytes.is_finite()) {
        bail!("bad size `{s}`: must be at least one byte");
    }
    Ok(bytes as u64)
}

/// Resident memory of this process, in bytes (Linux; `None` elsewhere).
fn rss() -> Option<u64> {
    let statm = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = statm.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

/// The limits of the command line; a watchdog thread sets the stop flag when the resident
/// memory passes `--max-memory` (the engines also stop on their own estimate).
fn limits(a: &SynthArgs) -> Result<(Limits, Arc<AtomicBool>)> {
    let stop = Arc::new(AtomicBool::new(false));
    let timeout = match a.timeout {
        Some(t) if !(t > 0.0 && t.is_finite()) => bail!("--timeout must be a positive number"),
        Some(t) => Some(Duration::from_secs_f64(t)),
        None => None,
    };
    let max_bytes = a.max_memory.as_deref().map(parse_size).transpose()?;
    if let Some(max) = max_bytes {
        let flag = stop.clone();
        std::thread::spawn(move || loop {
            if rss().is_some_and(|r| r > max) {
                flag.store(true, Ordering::Relaxed);
                return;
            }
            std::thread::sleep(Duration::from_millis(20));
        });
    }
    let limits = Limits {
        max_states: a.max_states,
        max_bytes,
        timeout,
        stop: Some(stop.clone()),
    };
    Ok((limits, stop))
}

/// Run the command; returns the exit code.
pub fn run(a: SynthArgs) -> Result<u8> {
    let engine: Engine = a.engine.parse()?;
    let (limits, stop) = limits(&a)?;
    let p = problem(&a.model, a.system.as_deref())?;
    let t = Instant::now();
    let opts = Options {
        engine,
        limits,
        guards: !a.quiet || a.output.is_some() || a.check,
        threads: a.threads.unwrap_or_else(|| {
            std::thread::available_parallelism()
                .map(|n| n.get().min(2))
                .unwrap_or(1)
        }),
    };
    let s = match synthesize_with(&p, &opts) {
        Ok(s) => s,
        Err(e) => {
            if let ErrorKind::Limit { limit, partial } = &e.kind {
                let limit =
                    if stop.load(Ordering::Relaxed) && *limit == statecheck_synth::Limit::Stopped {
                        format!(
                            "the memory limit ({}) was reached",
                            a.max_memory.as_deref().unwrap_or("?")
                        )
                    } else {
                        limit.to_string()
                    };
                out!(
                    "unknown: {limit} during {} after {:.3} s; product states so far: {:.0}; engine data about {} MiB",
                    partial.phase,
                    t.elapsed().as_secs_f64(),
                    partial.states,
                    partial.bytes >> 20
                );
                return Ok(3);
            }
            return Err(e.into());
        }
    };
    let secs = t.elapsed().as_secs_f64();
    let engine_name = s.engine.name();
    let sup = match s.outcome {
        Outcome::Empty(why) => {
            if a.quiet {
                out!(
                    "{engine_name} {secs:.3}s product {:.3e} no supervisor",
                    s.product_states
                );
            } else {
                out!("{why}");
            }
            return Ok(3);
        }
        Outcome::Supervisor(sup) => sup,
    };
    // The file first: a closed standard output must not lose it.
    // Names that are not `.sc` identifiers (from a Supremica file) are mapped, and listed.
    let (sc, notes) = sc_problem(&p);
    let text = (a.output.is_some() || a.check).then(|| {
        let mut t = emit::emit(&sc, &sup, &a.model);
        if let Some(i) = t.find("\n\n") {
            t.insert_str(i + 1, &notes);
        }
        t
    });
    if let (Some(out), Some(text)) = (&a.output, &text) {
        write_out(Some(out), text)?;
    }
    if a.quiet {
        out!(
            "{engine_name} {secs:.3}s product {:.3e} supervisor {} states {} transitions",
            s.product_states,
            sup.states,
            sup.transitions
        );
    } else {
        out!(
            "system {}: {} automata, {} events; {engine_name} engine, {secs:.3} s",
            p.name,
            p.automata.len(),
            p.events.len()
        );
        out!(
            "supervisor: {} states, {} transitions (product: {:.0} reachable states)",
            sup.states,
            sup.transitions,
            s.product_states
        );
        out!("guards (where each controllable event is allowed):");
        for g in &sup.guards {
            out!(
                "  {}: {}",
                p.events[g.event as usize].name,
                emit::guard_text(&p, &g.allow)
            );
        }
    }
    if let (true, Some(text)) = (a.check, &text) {
        let r = check_text(&sc, text, a.output.as_deref().unwrap_or("<supervisor>"))?;
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
