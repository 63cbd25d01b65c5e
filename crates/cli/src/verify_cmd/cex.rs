//! Counterexamples: scenario files in the simulator's format, replayed through the simulator
//! for the table (and the VCD), and checked to stop where the checker says.

use crate::load::Loaded;
use crate::output;
use anyhow::Result;
use statecheck_explicit::{PropKind, PropResult};
use statecheck_ir::view::TraceView as Views;
use statecheck_ir::Program;
use statecheck_sim::minimise::{minimise_until, Target};
use statecheck_sim::{scenario, Options, ScenarioInputs, Stop, TickRecord};

/// A counterexample or witness after replay.
pub struct Cex {
    /// Where its scenario was written, if it was.
    pub path: Option<String>,
    /// The simulator's trace of it.
    pub trace: Vec<TickRecord>,
    /// The tick that decides the property (the last one).
    pub tick: u64,
    /// Set when the simulator does not stop at the same property and tick (it stops earlier,
    /// at another property violated on the way).
    pub mismatch: Option<String>,
    /// False when the time limit had passed before this counterexample's turn: its scenario
    /// is written as the engine found it (not minimised) and not replayed, so `trace` is
    /// empty (`--timeout` bounds the whole command, and minimising and replaying thousands of
    /// counterexamples against thousands of properties is not bounded).
    pub replayed: bool,
}

/// Create the counterexample directory (before the run, so that counterexamples can be
/// written the moment they are found).
pub fn create_dir(dir: Option<&str>) -> Result<()> {
    if let Some(d) = dir {
        crate::outpath::create_dir(d, "--cex-dir")?;
    }
    Ok(())
}

/// How counterexamples are written.
#[derive(Clone, Copy, Debug)]
pub struct Write {
    /// Also write a VCD waveform beside each scenario.
    pub vcd: bool,
    /// Keep inputs that do not matter at their previous value (`statecheck_sim::minimise`).
    pub minimise: bool,
    /// The end of `--timeout`: a counterexample met after it is written but neither
    /// minimised nor replayed ([`Cex::replayed`]).
    pub deadline: Option<std::time::Instant>,
}

/// Write and replay the counterexample of one result, if it has one (the directory exists).
pub fn one(
    loaded: &Loaded,
    program: &Program,
    r: &PropResult,
    dir: Option<&str>,
    write: Write,
) -> Result<Option<Cex>> {
    let vcd = write.vcd;
    let views = Views::new(&loaded.model, program);
    {
        let Some(raw) = &r.counterexample else {
            return Ok(None);
        };
        let late = write
            .deadline
            .is_some_and(|d| std::time::Instant::now() >= d);
        if late {
            return late_one(loaded, program, r, raw, dir).map(Some);
        }
        let minimised = match Target::of(r) {
            Some(t) if write.minimise => minimise_until(program, raw, &t, write.deadline),
            _ => None,
        };
        let vectors = minimised.as_ref().unwrap_or(raw);
        let (sc, run, broken) = match r.loop_start {
            Some(k) => {
                let sc = scenario::from_lasso(program, vectors, k as usize);
                let mut l = statecheck_sim::lasso::run_lasso(program, &sc, Options::default());
                // A lasso may violate several properties; the replay names the first one
                // declared, and what is checked is that it violates this one.
                if l.violated.contains(&r.name) {
                    l.run.stop = Stop::Violation {
                        tick: (sc.len() as u64).saturating_sub(1),
                        property: r.name.clone(),
                    };
                }
                (sc, l.run, l.broken)
            }
            None => {
                let sc = scenario::from_input_vectors(program, vectors);
                let run =
                    statecheck_sim::run(program, &mut ScenarioInputs::new(&sc), Options::default());
                (sc, run, None)
            }
        };
        let tick = r.depth.saturating_sub(1);
        let mismatch = match (&run.stop, r.kind) {
            _ if broken.is_some() => broken,
            // A CTL counterexample is a path to an initial position that fails the formula;
            // the simulator does not evaluate CTL.
            (Stop::Completed, PropKind::Ctl | PropKind::Nonblocking) => None,
            // A deadlock: the scenario ends in the state where no input is allowed.
            (Stop::Completed, PropKind::Builtin) if r.name == "deadlock_free" => None,
            (_, PropKind::Reachable) => {
                let at = run
                    .reached
                    .iter()
                    .find(|(n, _)| *n == r.name)
                    .and_then(|(_, t)| *t);
                (at != Some(tick)).then(|| {
                    format!(
                        "the simulator ended with {} before seeing `{}` at {}",
                        describe(program, &run.stop),
                        r.name,
                        program.tick_label(tick)
                    )
                })
            }
            (Stop::Violation { tick: t, property }, _) => (!(*property == r.name && *t == tick))
                .then(|| {
                    format!(
                        "the simulator stops earlier: property `{property}` violated at {}",
                        program.tick_label(*t)
                    )
                }),
            (Stop::RuntimeError { tick: t, error }, PropKind::Builtin)
                if error.kind.builtin_property() == r.name && *t == tick =>
            {
                None
            }
            (stop, _) => Some(format!(
                "the simulator ended with {} instead",
                describe(program, stop)
            )),
        };
        let path = match dir {
            Some(d) => {
                let file = write_scenario(loaded, program, r, &sc, d)?;
                if vcd {
                    let vfile = format!("{d}/{}.vcd", file_name(&r.name));
                    let text = output::vcd::render(program, &views, &run.trace);
                    crate::outpath::write(std::path::Path::new(&vfile), text.as_bytes())?;
                }
                Some(file)
            }
            None => None,
        };
        Ok(Some(Cex {
            path,
            trace: run.trace,
            tick,
            mismatch,
            replayed: true,
        }))
    }
}

/// Write the scenario of `r`'s counterexample into directory `d`; the file's path.
fn write_scenario(
    loaded: &Loaded,
    program: &Program,
    r: &PropResult,
    sc: &scenario::Scenario,
    d: &str,
) -> Result<String> {
    let file = format!("{d}/{}.scn", file_name(&r.name));
    let mut text = scenario::format(sc, program);
    text.insert_str(0, &format!("# counterexample for `{}` ({}, {}): {} ticks; replay with\n#   statecheck sim {} --system {} --scenario {file}\n", r.name, r.kind.as_str(), r.verdict.as_str(), r.depth, loaded.path, program.name));
    crate::outpath::write(std::path::Path::new(&file), text.as_bytes())?;
    Ok(file)
}

/// A counterexample met after the time limit: its scenario as the engine found it, written
/// but not minimised or replayed.
fn late_one(
    loaded: &Loaded,
    program: &Program,
    r: &PropResult,
    raw: &[Vec<i64>],
    dir: Option<&str>,
) -> Result<Cex> {
    let sc = match r.loop_start {
        Some(k) => scenario::from_lasso(program, raw, k as usize),
        None => scenario::from_input_vectors(program, raw),
    };
    let path = match dir {
        Some(d) => Some(write_scenario(loaded, program, r, &sc, d)?),
        None => None,
    };
    Ok(Cex {
        path,
        trace: Vec::new(),
        tick: r.depth.saturating_sub(1),
        mismatch: None,
        replayed: false,
    })
}

fn describe(p: &Program, stop: &Stop) -> String {
    match stop {
        Stop::Completed => "the scenario completed".into(),
        Stop::RuntimeError { tick, error } => format!(
            "a run-time error ({}) at {}",
            error.kind.builtin_property(),
            p.tick_label(*tick)
        ),
        Stop::Violation { tick, property } => {
            format!("property `{property}` violated at {}", p.tick_label(*tick))
        }
        Stop::AssumeViolated { tick, .. } => {
            format!("an `assume` violated at {}", p.tick_label(*tick))
        }
    }
}

/// A property name usable as a file name.
fn file_name(name: &str) -> String {
    name.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' || c == '-' {
                c
            } else {
                '_'
            }
        })
        .collect()
}
