//! `statecheck sim`: run a system on a scenario or random inputs and show the trace.

use crate::load;
use crate::output;
use crate::{write_out, Exit};
use anyhow::{bail, Result};
use clap::Args;
use statecheck_ir::view::TraceView as Views;
use statecheck_sim::{random::RandomInputs, scenario, Options, ScenarioInputs, Stop};

/// Arguments of `statecheck sim`.
#[derive(Args)]
pub struct SimArgs {
    /// The `.sc` model file.
    model: String,
    /// The system (or chart) to simulate.
    #[arg(long)]
    system: Option<String>,
    /// A scenario file: the inputs per tick (`-`: standard input).
    #[arg(long, conflicts_with = "random")]
    scenario: Option<String>,
    /// Run N ticks of random inputs within their types and the `assume`s.
    #[arg(long, value_name = "N")]
    random: Option<u64>,
    /// Seed of the random inputs.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Write the inputs that were applied as a scenario file.
    #[arg(long, value_name = "FILE")]
    save_scenario: Option<String>,
    /// Print the trace as JSON.
    #[arg(long, conflicts_with = "csv")]
    json: bool,
    /// Print the trace as CSV.
    #[arg(long)]
    csv: bool,
    /// Write the trace as a VCD waveform file.
    #[arg(long, value_name = "FILE")]
    vcd: Option<String>,
    /// Count state entries and transition firings; print the summary and, with FILE, write JSON.
    #[arg(long, value_name = "FILE", num_args = 0..=1, default_missing_value = "")]
    coverage: Option<String>,
    /// Print nothing but errors (and the requested files).
    #[arg(long, short)]
    quiet: bool,
}

/// Run the command; returns the exit code.
pub fn run(a: SimArgs) -> Result<u8> {
    let loaded = load::load(&a.model, false)?;
    let sys = loaded.system(a.system.as_deref())?;
    let program = loaded.lower(sys)?;
    let opts = Options {
        coverage: a.coverage.is_some(),
        no_trace: false,
    };
    let run = match (&a.scenario, a.random) {
        (Some(path), _) => {
            let text = if path == "-" {
                let mut t = String::new();
                std::io::Read::read_to_string(&mut std::io::stdin(), &mut t)
                    .map_err(|e| anyhow::anyhow!("cannot read standard input: {e}"))?;
                t
            } else {
                std::fs::read_to_string(path)
                    .map_err(|e| anyhow::anyhow!("cannot read `{path}`: {e}"))?
            };
            let sc = match scenario::parse(&text, &program) {
                Ok(s) => s,
                Err(errs) => {
                    let shown = if path == "-" {
                        "<stdin>"
                    } else {
                        path.as_str()
                    };
                    crate::diag::eprint(shown, &text, &scenario_diagnostics(&text, &errs));
                    return Err(Exit(1).into());
                }
            };
            if sc.loop_start.is_some() {
                let l = statecheck_sim::lasso::run_lasso(&program, &sc, opts);
                if let Some(why) = &l.broken {
                    eprintln!("error: {why} ({path})");
                    return Err(Exit(1).into());
                }
                if !l.fair {
                    eprintln!("note: the lasso is not fair (a `fair` constraint fails on its loop); temporal properties were not evaluated");
                }
                l.run
            } else {
                statecheck_sim::run(&program, &mut ScenarioInputs::new(&sc), opts)
            }
        }
        (None, Some(n)) => statecheck_sim::run(&program, &mut RandomInputs::new(a.seed, n), opts),
        (None, None) => {
            bail!("give a scenario (--scenario FILE) or a number of random ticks (--random N)")
        }
    };
    let views = Views::new(&loaded.model, &program);
    if let Some(f) = &a.save_scenario {
        let sc = scenario::from_input_vectors(&program, &run.inputs);
        write_out(Some(f), &scenario::format(&sc, &program))?;
    }
    if let Some(f) = &a.vcd {
        write_out(
            Some(f),
            &output::vcd::render(
                &program,
                &views,
                &run.trace,
                loaded.model.tick_ms.unwrap_or(1),
            ),
        )?;
    }
    let (status, code, message) = describe_stop(&run.stop, &program, &loaded.sources);
    if a.json {
        let ticks: Vec<serde_json::Value> = run
            .trace
            .iter()
            .map(|r| output::json::tick(&program, &views, r))
            .collect();
        let reached: serde_json::Map<String, serde_json::Value> = run
            .reached
            .iter()
            .map(|(n, t)| (n.clone(), serde_json::json!(t)))
            .collect();
        let mut obj = serde_json::json!({"ticks": ticks, "result": {"status": status, "message": message}, "reached": reached});
        if let Stop::Violation { tick, property } = &run.stop {
            obj["result"]["tick"] = serde_json::json!(tick);
            obj["result"]["property"] = serde_json::json!(property);
        }
        if let Stop::RuntimeError { tick, error } = &run.stop {
            obj["result"]["tick"] = serde_json::json!(tick);
            obj["result"]["property"] = serde_json::json!(error.kind.builtin_property());
        }
        if let (Some(counts), Some(_)) = (&run.coverage, &a.coverage) {
            obj["coverage"] = output::coverage::to_json(&program, counts, &loaded.sources);
        }
        write_out(None, &format!("{}\n", serde_json::to_string(&obj)?))?;
    } else if a.csv {
        write_out(None, &output::csv::render(&program, &views, &run.trace))?;
    } else if !a.quiet {
        write_out(None, &output::table::render(&program, &views, &run.trace))?;
    }
    if let (Some(counts), Some(file)) = (&run.coverage, &a.coverage) {
        if !a.quiet && !a.json {
            eprint!(
                "{}",
                output::coverage::summary(&program, counts, &loaded.sources)
            );
        }
        if !file.is_empty() {
            let v = output::coverage::to_json(&program, counts, &loaded.sources);
            write_out(
                Some(file),
                &format!("{}\n", serde_json::to_string_pretty(&v)?),
            )?;
        }
    }
    if code != 0 || (!a.quiet && !a.json) {
        eprintln!("{message}");
    }
    Ok(code)
}

/// Status word, exit code and a message for how a run ended.
fn describe_stop(
    stop: &Stop,
    p: &statecheck_ir::Program,
    sources: &statecheck_model::imports::Sources,
) -> (&'static str, u8, String) {
    match stop {
        Stop::Completed => ("completed", 0, "run completed".into()),
        Stop::Violation { tick, property } => ("violated", 4, format!("property `{property}` violated at tick {tick}")),
        Stop::RuntimeError { tick, error } => {
            let at = p
                .sites
                .get(error.site as usize)
                .map(|s| format!(" at {}", sources.position(s.span)));
            ("runtime_error", 1, format!("run-time error at tick {tick}: {}{}", p.describe_error(error), at.unwrap_or_default()))
        }
        Stop::AssumeViolated { tick, assume } => (
            "assume_violated",
            1,
            format!("the inputs of tick {tick} violate `assume` #{} of the system (or no random inputs satisfy it)", assume + 1),
        ),
    }
}

/// Scenario errors as diagnostics (byte spans from their 1-based line and column), so that
/// they render like the model's and follow `--message-format`.
fn scenario_diagnostics(
    text: &str,
    errs: &[scenario::ScenarioError],
) -> Vec<statecheck_base::Diagnostic> {
    let starts: Vec<usize> = std::iter::once(0)
        .chain(text.match_indices('\n').map(|(i, _)| i + 1))
        .collect();
    errs.iter()
        .map(|e| {
            let line_start = starts.get(e.line - 1).copied().unwrap_or(text.len());
            let start = (line_start + e.col - 1).min(text.len());
            let end = (start + e.len).min(text.len());
            let mut d = statecheck_base::Diagnostic::error(
                e.code,
                e.message.clone(),
                statecheck_base::Span::new(start, end),
            )
            .with_label("here");
            if let Some(h) = &e.hint {
                d = d.with_hint(h.clone());
            }
            d
        })
        .collect()
}
