//! `statecheck sim`: run a system on a scenario or random inputs and show the trace.

use crate::load;
use crate::output;
use crate::sim_sink::{Format, SimSink};
use crate::{write_out, Exit};
use anyhow::{bail, Result};
use clap::Args;
use statecheck_ir::view::TraceView as Views;
use statecheck_sim::{random::RandomInputs, scenario, NoInput, Options, ScenarioInputs, Stop};

/// Arguments of `statecheck sim`.
#[derive(Args)]
pub struct SimArgs {
    /// The `.sc` model file.
    model: String,
    /// The system (or chart) to simulate.
    #[arg(long)]
    system: Option<String>,
    /// The system's configuration (`configuration NAME { … }`, docs/components.md).
    #[arg(long, value_name = "NAME")]
    config: Option<String>,
    /// A scenario file: the inputs per tick (`-`: standard input).
    #[arg(long, conflicts_with = "random")]
    scenario: Option<String>,
    /// Run N ticks of random inputs within their types and the `assume`s.
    #[arg(long, value_name = "N")]
    random: Option<u64>,
    /// With --random: make a boolean input or event be true/present with probability P
    /// (default ½), e.g. `--rate fam.stallNow=0.01`; repeatable.
    #[arg(long, value_name = "INPUT=P", requires = "random")]
    rate: Vec<String>,
    /// With --random: guide the inputs towards coverage — each tick, among candidate input
    /// vectors allowed by the `assume`s, take one whose next state enters a state or fires a
    /// transition not covered yet (the ordinary draw when none does); prints coverage growth.
    #[arg(long, requires = "random", conflicts_with = "scenario")]
    guided: bool,
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
    /// Do not stop at a property violation: run every tick, report the first violation at
    /// the end (exit 4).
    #[arg(long)]
    keep_going: bool,
    /// Print nothing but errors (and the requested files).
    #[arg(long, short)]
    quiet: bool,
    /// Show only these variables and events in the table: globs over `instance.name` (`*`
    /// any characters, `?` one), comma-separated or repeated. JSON, CSV and VCD are unchanged.
    #[arg(long, value_name = "PATTERN")]
    show: Vec<String>,
}

/// Run the command; returns the exit code.
pub fn run(a: SimArgs) -> Result<u8> {
    let loaded = load::load(&a.model, false)?;
    let sys = loaded.system_in(a.system.as_deref(), a.config.as_deref())?;
    let program = loaded.lower(sys)?;
    let opts = Options {
        coverage: a.coverage.is_some() || a.guided,
        no_trace: true,
        keep_going: a.keep_going,
    };
    let mut views = Views::new(&loaded.model, &program);
    output::table::show(&mut views, &a.show)?;
    let views = views;
    let format = if a.json {
        Format::Json
    } else if a.csv {
        Format::Csv
    } else if a.quiet {
        Format::Quiet
    } else {
        Format::Table
    };
    let sink = |views| {
        SimSink::new(
            &program,
            views,
            format,
            a.vcd.as_deref(),
            a.save_scenario.as_deref(),
        )
    };
    let (run, sink) = match (&a.scenario, a.random) {
        (Some(path), _) => {
            if path != "-" {
                crate::outpath::note_input(path);
            }
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
                    let (kept, more) = crate::diag::cap_scenario_errors(&errs);
                    crate::diag::eprint(shown, &text, &scenario_diagnostics(&text, &kept));
                    eprint!("{more}");
                    return Err(Exit(1).into());
                }
            };
            let mut sink = sink(&views)?;
            if sc.loop_start.is_some() {
                // A lasso is replayed in memory (its loop runs twice and the recurrence of
                // the loop's first state is checked), then rendered tick by tick.
                // The replay compares states along the trace: it needs the trace kept.
                let traced = Options {
                    no_trace: false,
                    ..opts
                };
                let l = statecheck_sim::lasso::run_lasso(&program, &sc, traced);
                if let Some(why) = &l.broken {
                    eprintln!("error: {why} ({path})");
                    return Err(Exit(1).into());
                }
                if !l.fair {
                    eprintln!("note: the lasso is not fair (a `fair` constraint fails on its loop); temporal properties were not evaluated");
                }
                for (t, inputs) in l.run.inputs.iter().enumerate() {
                    statecheck_sim::Sink::inputs(&mut sink, t as u64, inputs);
                }
                for rec in &l.run.trace {
                    statecheck_sim::Sink::tick(&mut sink, rec.tick, &rec.slots);
                }
                (l.run, sink)
            } else {
                let run = statecheck_sim::run_streaming(
                    &program,
                    &mut ScenarioInputs::new(&sc),
                    opts,
                    &mut sink,
                );
                (run, sink)
            }
        }
        (None, Some(n)) => {
            let mut source = RandomInputs::new(&program, a.seed, n);
            if a.guided {
                source.set_guided(&program);
            }
            for r in &a.rate {
                let (name, p) = r
                    .split_once('=')
                    .ok_or_else(|| anyhow::anyhow!("--rate takes INPUT=P, got `{r}`"))?;
                let (name, p) = (name.trim(), p.trim());
                let p: f64 = p
                    .parse()
                    .map_err(|_| anyhow::anyhow!("--rate {r}: `{p}` is not a number"))?;
                let Some(k) = program.inputs.iter().position(|i| i.name == name) else {
                    let names: Vec<&str> = program.inputs.iter().map(|i| i.name.as_str()).collect();
                    bail!(
                        "--rate {r}: `{name}` is not a free input of the system (free inputs: {})",
                        names.join(", ")
                    );
                };
                source
                    .set_rate(&program, k, p)
                    .map_err(|e| anyhow::anyhow!("--rate {r}: {}", e.message))?;
            }
            let mut sink = sink(&views)?;
            let run = statecheck_sim::run_streaming(&program, &mut source, opts, &mut sink);
            (run, sink)
        }
        (None, None) => {
            bail!("give a scenario (--scenario FILE) or a number of random ticks (--random N)")
        }
    };
    let (mut status, code, mut message) = describe_stop(&run.stop, &program, &loaded.sources);
    if let Some(why) = run.no_input {
        let initial;
        let slots = match &sink.last {
            Some(l) => l.as_slice(),
            None => {
                initial = statecheck_ir::Machine::new(&program);
                initial.slots()
            }
        };
        let state = output::table::state_line(&program, &views, slots);
        let tick = tick_of(&run.stop);
        let after = match tick {
            0 => "the initial state".to_string(),
            t => format!("the state after tick {}", t - 1),
        };
        message = match why {
            NoInput::Deadlock { assume } => {
                status = "deadlock";
                format!(
                    "deadlock at {}: no input satisfies the `assume`s (`assume` #{} blocks) in {after}: {state}",
                    program.tick_label(tick),
                    assume + 1,
                )
            }
            NoInput::NotFound { assume } => format!(
                "no random inputs satisfying `assume` #{} found at {} within {} draws, in {after}: {state}",
                assume + 1,
                program.tick_label(tick),
                statecheck_sim::random::MAX_TRIES,
            ),
        };
    }
    let mut json_tail = String::new();
    if a.json {
        let reached: serde_json::Map<String, serde_json::Value> = run
            .reached
            .iter()
            .map(|(n, t)| (n.clone(), serde_json::json!(t)))
            .collect();
        let mut result = serde_json::json!({"status": status, "message": message});
        if let Some(t) = program
            .seconds(tick_of(&run.stop))
            .filter(|_| result_tick(&run.stop))
        {
            result["time"] = serde_json::json!(t);
        }
        match &run.stop {
            Stop::Violation { tick, property } => {
                result["tick"] = serde_json::json!(tick);
                result["property"] = serde_json::json!(property);
            }
            Stop::RuntimeError { tick, error } => {
                result["tick"] = serde_json::json!(tick);
                result["property"] = serde_json::json!(error.kind.builtin_property());
            }
            Stop::AssumeViolated { tick, assume } => {
                result["tick"] = serde_json::json!(tick);
                result["assume"] = serde_json::json!(assume + 1);
            }
            Stop::Completed => {}
        }
        json_tail = format!(
            "\"result\":{},\"reached\":{}",
            serde_json::to_string(&result)?,
            serde_json::to_string(&reached)?
        );
        if let (Some(counts), Some(_)) = (&run.coverage, &a.coverage) {
            let c = output::coverage::to_json(&program, counts, &loaded.sources);
            json_tail.push_str(&format!(",\"coverage\":{}", serde_json::to_string(&c)?));
        }
        if run.coverage.is_some() && (a.coverage.is_some() || a.guided) {
            let g: Vec<serde_json::Value> = run
                .coverage_growth
                .iter()
                .map(|g| serde_json::json!({"tick": g.tick, "states": g.states, "transitions": g.transitions}))
                .collect();
            json_tail.push_str(&format!(
                ",\"coverage_growth\":{}",
                serde_json::to_string(&g)?
            ));
        }
    }
    sink.finish(&json_tail)?;
    if run.coverage.is_some() && (a.coverage.is_some() || a.guided) && !a.quiet && !a.json {
        eprint!("{}", growth_lines(&program, &run.coverage_growth));
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

/// How coverage grew along a run: for states and for transitions, the ticks at which 50, 90
/// and 100 % were reached and the tick of the last new item.
fn growth_lines(p: &statecheck_ir::Program, growth: &[statecheck_sim::Growth]) -> String {
    let counted = p.covers.iter().filter(|c| !c.expected_unreached);
    let states = counted
        .clone()
        .filter(|c| matches!(c.kind, statecheck_ir::CoverKind::State(_)))
        .count() as u32;
    let total = [states, counted.count() as u32 - states];
    let mut out = String::new();
    for (i, what) in ["states", "transitions"].into_iter().enumerate() {
        let count = |g: &statecheck_sim::Growth| if i == 0 { g.states } else { g.transitions };
        let mut parts = Vec::new();
        for pct in [50u32, 90, 100] {
            let need = (u64::from(total[i]) * u64::from(pct)).div_ceil(100) as u32;
            parts.push(match growth.iter().find(|g| count(g) >= need) {
                Some(g) => format!("{pct}% at tick {}", g.tick),
                None => format!("{pct}% not reached"),
            });
        }
        let last = growth
            .iter()
            .enumerate()
            .rfind(|(k, g)| *k == 0 || count(g) > count(&growth[k - 1]))
            .map(|(_, g)| format!("; last new at tick {} ({}/{})", g.tick, count(g), total[i]))
            .unwrap_or_default();
        out.push_str(&format!(
            "coverage growth, {what}: {}{last}\n",
            parts.join(", ")
        ));
    }
    out
}

/// The tick at which a run stopped (0 when it completed).
fn tick_of(stop: &Stop) -> u64 {
    match stop {
        Stop::Completed => 0,
        Stop::RuntimeError { tick, .. }
        | Stop::Violation { tick, .. }
        | Stop::AssumeViolated { tick, .. } => *tick,
    }
}

/// Whether the JSON result of a run that ended with `stop` names a tick.
fn result_tick(stop: &Stop) -> bool {
    !matches!(stop, Stop::Completed)
}

/// Status word, exit code and a message for how a run ended.
fn describe_stop(
    stop: &Stop,
    p: &statecheck_ir::Program,
    sources: &statecheck_model::imports::Sources,
) -> (&'static str, u8, String) {
    match stop {
        Stop::Completed => ("completed", 0, "run completed".into()),
        Stop::Violation { tick, property } => (
            "violated",
            4,
            format!("property `{property}` violated at {}", p.tick_label(*tick)),
        ),
        Stop::RuntimeError { tick, error } => {
            let at = p
                .sites
                .get(error.site as usize)
                .map(|s| format!(" at {}", sources.position(s.span)));
            (
                "runtime_error",
                1,
                format!(
                    "run-time error at {}: {}{}",
                    p.tick_label(*tick),
                    p.describe_error(error),
                    at.unwrap_or_default()
                ),
            )
        }
        Stop::AssumeViolated { tick, assume } => (
            "assume_violated",
            1,
            format!(
                "the inputs of tick {tick} violate `assume` #{} of the system",
                assume + 1
            ),
        ),
    }
}

/// Scenario errors as diagnostics (byte spans from their 1-based line and column), so that
/// they render like the model's and follow `--message-format`.
pub(crate) fn scenario_diagnostics(
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
