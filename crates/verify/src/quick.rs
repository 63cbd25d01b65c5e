//! Auto's first pass, the quick race: the explicit engine (at most [`QUICK_STATES`] states)
//! and IC3 side by side for at most [`QUICK_TIME`]. The first to decide *every* selected
//! property gives the run its verdicts and the other is stopped; when neither does, both are
//! thrown away and the portfolio starts (a large model has lost at most that time).
//!
//! A small state space is explored completely by the explicit engine in moments, before IC3
//! has bit-blasted the model; a model with tens of thousands of states and easy properties
//! (the FAM alone: 66,889 states, about 2 s to explore) is proved by IC3 in a fraction of a
//! second. Running them together makes `auto` about as fast as the better of the two on
//! either kind of model, where the explicit engine alone first cost the second model its
//! whole second. IC3 races only for safety rows: temporal rows are the explicit engine's here.

use crate::single::run_engine;
use crate::{Cancel, CancelReason, Event, Meta, Options, Run};
use statecheck_explicit::Report;
use statecheck_ir::verdict::PropResult;
use statecheck_ir::Program;
use statecheck_symbolic::check::Engine as SatEngine;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};

/// How many states the explicit engine may store in auto's first pass.
pub const QUICK_STATES: u64 = 1_000_000;

/// How long auto's first pass may take.
pub const QUICK_TIME: Duration = Duration::from_secs(1);

/// How long past its budget the race waits for an engine to notice that its time is up.
const GRACE: Duration = Duration::from_millis(100);

/// How often the race looks at the user's cancellation while it waits.
const POLL: Duration = Duration::from_millis(20);

/// Auto's first pass (see the module doc). `temporal`: the selection has temporal rows (then
/// the explicit engine runs alone). `None` when neither engine decided every row within the
/// budget, or a depth bound is asked (a bounded exploration is not a complete one).
pub(crate) fn quick_race(
    p: &Program,
    opts: &Options,
    temporal: bool,
    events: &(dyn Fn(Event) + Sync),
) -> Option<Run> {
    if opts.check.depth.is_some() {
        return None;
    }
    let budget = opts.check.timeout.map_or(QUICK_TIME, |t| t.min(QUICK_TIME));
    race(p, opts, temporal, budget, events)
}

/// [`quick_race`] with its budget.
fn race(
    p: &Program,
    opts: &Options,
    temporal: bool,
    budget: Duration,
    events: &(dyn Fn(Event) + Sync),
) -> Option<Run> {
    let started = Instant::now();
    let explicit_stop = Arc::new(AtomicBool::new(false));
    let ic3_cancel = Cancel::new();
    let (tx, rx) = mpsc::channel::<Option<Run>>();
    // Detached: the loser is told to stop and may take a moment to notice (the explicit engine
    // looks at its flag between layers); the run does not wait for it.
    {
        let tx = tx.clone();
        let stop = Arc::clone(&explicit_stop);
        let (p, opts) = (p.clone(), opts.clone());
        std::thread::spawn(move || {
            let _ = tx.send(quick_explicit(&p, &opts, budget, stop, started, !temporal));
        });
    }
    if !temporal {
        let tx = tx.clone();
        let cancel = ic3_cancel.clone();
        let (p, opts) = (p.clone(), opts.clone());
        std::thread::spawn(move || {
            let _ = tx.send(quick_ic3(&p, &opts, budget, cancel, started));
        });
    }
    drop(tx);
    let racers = if temporal { 1 } else { 2 };
    let deadline = started + budget + GRACE;
    let mut answered = 0;
    let mut winner = None;
    while answered < racers && Instant::now() < deadline {
        match rx.recv_timeout(POLL) {
            Ok(Some(run)) => {
                winner = Some(run);
                break;
            }
            Ok(None) => answered += 1,
            Err(mpsc::RecvTimeoutError::Timeout) => {
                if opts.cancel.as_ref().is_some_and(|c| c.reason().is_some()) {
                    break;
                }
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => break,
        }
    }
    explicit_stop.store(true, Ordering::Relaxed);
    ic3_cancel.raise(CancelReason::Interrupted);
    let winner = winner?;
    // The winner's verdicts are reported once the race is over, in row order.
    for (i, (r, m)) in winner.report.results.iter().zip(&winner.meta).enumerate() {
        events(Event::Decided {
            index: i,
            result: r,
            meta: m,
        });
    }
    Some(winner)
}

/// The explicit engine with at most [`QUICK_STATES`] states and `budget`; `Some` only when it
/// explored the whole state space (then every verdict is definitive). `beside_ic3`: IC3 races
/// too, and gets a core of its own.
fn quick_explicit(
    p: &Program,
    opts: &Options,
    budget: Duration,
    stop: Arc<AtomicBool>,
    started: Instant,
    beside_ic3: bool,
) -> Option<Run> {
    let mut o = opts.check.clone();
    o.max_states = Some(o.max_states.map_or(QUICK_STATES, |m| m.min(QUICK_STATES)));
    o.timeout = Some(budget);
    o.stop = Some(stop);
    // One core for the exploration, the other for IC3 (a small model needs no more).
    if o.threads == 0 && beside_ic3 {
        o.threads = 1;
    }
    // The rows in report order, each found by name among the explicit engine's results.
    let rows = crate::row_names(p, &opts.check.properties);
    let report = statecheck_explicit::verify(p, &o, None).ok()?;
    if report.stats.limit.is_some() {
        return None;
    }
    let results = rows
        .iter()
        .map(|name| {
            report
                .results
                .iter()
                .find(|r| &r.name == name && r.verdict.is_definitive())
                .cloned()
        })
        .collect::<Option<Vec<PropResult>>>()?;
    let n = results.len();
    let time_s = started.elapsed().as_secs_f64();
    let meta = vec![
        Meta {
            engine: "explicit",
            time_s: Some(time_s),
            reason: None,
            decided_at_s: Some(time_s),
            symmetry_of: None,
        };
        n
    ];
    Some(Run {
        invariants: vec![None; n],
        report: Report {
            results,
            stats: report.stats,
        },
        meta,
    })
}

/// IC3 alone on every row for `budget`; `Some` only when it decided all of them.
fn quick_ic3(
    p: &Program,
    opts: &Options,
    budget: Duration,
    cancel: Cancel,
    started: Instant,
) -> Option<Run> {
    let mut o = opts.clone();
    o.check.timeout = Some(budget);
    o.cancel = Some(cancel);
    let decided_at = std::sync::Mutex::new(Vec::new());
    let note = |e: Event| {
        if let Event::Decided { index, .. } = e {
            if let Ok(mut d) = decided_at.lock() {
                d.push((index, started.elapsed().as_secs_f64()));
            }
        }
    };
    let mut run = run_engine(p, &o, SatEngine::Ic3, &note).ok()?;
    if !run.report.results.iter().all(|r| r.verdict.is_definitive()) {
        return None;
    }
    let decided_at = decided_at.into_inner().ok()?;
    for (index, at) in decided_at {
        if let Some(m) = run.meta.get_mut(index) {
            m.decided_at_s = Some(at);
        }
    }
    Some(run)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Engine, ExplicitOptions, Verdict};

    fn program(src: &str) -> Program {
        let file = statecheck_syntax::parse(src).0;
        let (model, diags) = statecheck_model::check(&file);
        assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
        statecheck_ir::lower(&model, &model.systems[0]).expect("lowers")
    }

    /// Two inputs of 1,024 values each, latched every tick: a million states after the first
    /// tick, past the explicit engine's quick limit of [`QUICK_STATES`], so only IC3 can
    /// decide the rows in the first pass. By hand: `x` and `y` never exceed 1023, so
    /// `sum_in_range` (x + y <= 2046) holds; both are 1023 after any tick whose inputs are
    /// 1023, so `sum_small` (x + y < 2000) is violated. The built-in checks hold: no
    /// assignment leaves its range (`x = a` with equal ranges), no division, no shift.
    #[test]
    fn a_model_too_large_to_explore_quickly_is_decided_by_ic3_in_the_first_pass() {
        let p = program(
            "chart Latch {
               input a: int[0..1023];
               input b: int[0..1023];
               output x: int[0..1023] = 0;
               output y: int[0..1023] = 0;
               initial S;
               state S { during { x = a; y = b; } }
             }
             system Big {
               instance l: Latch;
               invariant sum_in_range: l.x + l.y <= 2046;
               invariant sum_small: l.x + l.y < 2000;
             }",
        );
        let opts = Options::new(Engine::Auto, ExplicitOptions::default());
        let decided = std::sync::atomic::AtomicUsize::new(0);
        let events = |e: Event| {
            if matches!(e, Event::Decided { .. }) {
                decided.fetch_add(1, Ordering::Relaxed);
            }
        };
        // A generous budget: the test is about who can decide, not how fast.
        let run = race(&p, &opts, false, Duration::from_secs(120), &events)
            .expect("IC3 decides both rows");
        let verdicts: Vec<(&str, Verdict, &str)> = run
            .report
            .results
            .iter()
            .zip(&run.meta)
            .map(|(r, m)| (r.name.as_str(), r.verdict, m.engine))
            .collect();
        assert_eq!(
            verdicts,
            [
                ("sum_in_range", Verdict::Proved, "ic3"),
                ("sum_small", Verdict::Violated, "ic3"),
                ("no_range_overflow", Verdict::Proved, "ic3"),
                ("no_division_by_zero", Verdict::Proved, "ic3"),
                ("no_bad_shift", Verdict::Proved, "ic3"),
            ]
        );
        assert_eq!(decided.load(Ordering::Relaxed), 5, "each row reported once");
        assert!(
            run.invariants[0].is_some(),
            "the proof comes with its invariant"
        );
    }

    /// A four-state model: the explicit engine explores it completely; whichever engine wins,
    /// the verdicts are the hand-derived ones (c counts 0..3 and stays: c <= 3 holds, c < 3
    /// does not; `c += 1` only below 3 stays in range; no division, no shift).
    #[test]
    fn a_small_model_is_decided_in_the_first_pass() {
        let p = program(
            "chart Counter {
               output c: int[0..3] = 0;
               initial Run;
               state Run { on [c < 3] / { c += 1; }; }
             }
             system Small {
               instance k: Counter;
               invariant at_most3: k.c <= 3;
               invariant below3: k.c < 3;
             }",
        );
        let opts = Options::new(Engine::Auto, ExplicitOptions::default());
        let run = race(&p, &opts, false, Duration::from_secs(120), &|_| {})
            .expect("decided in the first pass");
        let verdicts: Vec<Verdict> = run.report.results.iter().map(|r| r.verdict).collect();
        use Verdict::{Proved, Violated};
        assert_eq!(verdicts, [Proved, Violated, Proved, Proved, Proved]);
    }
}
