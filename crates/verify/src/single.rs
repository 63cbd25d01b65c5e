//! One engine alone: the explicit engine, or one SAT engine deciding the properties on the
//! fair schedule (`schedule.rs`); with symmetry reduction, the SAT engine checks one member
//! of each family and the others follow it (`symmetry.rs`).

use crate::schedule::{self, Work};
use crate::symmetry::Families;
use crate::{Error, Event, Meta, Options, Run, DEFAULT_BMC_DEPTH, REASON_TIME_LIMIT};
use statecheck_explicit::{Limit, Report, Stats};
use statecheck_ir::verdict::{PropResult, Verdict};
use statecheck_ir::Program;
use statecheck_symbolic::check::{problems, Engine, Reductions, SymResult};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::time::Instant;

/// The metadata of a SAT engine's result.
pub(crate) fn meta_of(engine: &'static str, s: &SymResult) -> Meta {
    Meta {
        engine,
        time_s: Some(s.time.as_secs_f64()),
        decided_at_s: None,
        symmetry_of: None,
        reason: s.reason.clone(),
    }
}

/// The reason of a property left undecided when the run ended early.
pub(crate) fn early_end_reason(opts: &Options, deadline: Option<Instant>) -> String {
    match opts.cancel.as_ref().and_then(|c| c.reason()) {
        Some(r) => r.as_str().to_string(),
        None if deadline.is_some_and(|d| Instant::now() >= d) => REASON_TIME_LIMIT.to_string(),
        None => "no engine answered within the limits".to_string(),
    }
}

/// The explicit engine alone; its verdicts are reported when the exploration ends.
pub(crate) fn run_explicit(
    p: &Program,
    opts: &Options,
    events: &(dyn Fn(Event) + Sync),
) -> Result<Run, Error> {
    let progress = |pr: &statecheck_explicit::Progress| events(Event::Progress(pr));
    let mut check = opts.check.clone();
    if let Some(c) = &opts.cancel {
        check.stop = Some(c.flag());
    }
    let report = statecheck_explicit::verify(p, &check, Some(&progress))?;
    // Stopped from outside: the rows left unknown say why.
    let reason = match (&report.stats.limit, &opts.cancel) {
        (Some(Limit::Stopped), Some(c)) => c.reason().map(|r| r.as_str().to_string()),
        _ => None,
    };
    let meta: Vec<Meta> = report
        .results
        .iter()
        .map(|r| Meta {
            engine: "explicit",
            reason: reason.clone().filter(|_| r.verdict == Verdict::Unknown),
            ..Meta::default()
        })
        .collect();
    for (i, (r, m)) in report.results.iter().zip(&meta).enumerate() {
        events(Event::Decided {
            index: i,
            result: r,
            meta: m,
        });
    }
    let invariants = vec![None; report.results.len()];
    Ok(Run {
        report,
        meta,
        invariants,
    })
}

/// One SAT engine on every selected property: passes with growing budgets, each verdict
/// reported as it is decided.
pub(crate) fn run_engine(
    p: &Program,
    opts: &Options,
    engine: Engine,
    events: &(dyn Fn(Event) + Sync),
) -> Result<Run, Error> {
    let started = Instant::now();
    let deadline = opts.check.timeout.map(|t| started + t);
    let (bl, idx) = problems(p, &opts.check.properties)?;
    // BMC never proves: without a depth it stops at DEFAULT_BMC_DEPTH ticks (`bounded`).
    let depth = match (engine, opts.check.depth) {
        (Engine::Bmc, None) => Some(DEFAULT_BMC_DEPTH),
        (_, d) => d,
    };
    let n = idx.len();
    let stop = opts
        .cancel
        .as_ref()
        .map_or_else(|| Arc::new(AtomicBool::new(false)), |c| c.flag());
    // One flag per property, raised with the run's stop flag by a watcher thread.
    let flags: Vec<Arc<AtomicBool>> = (0..n).map(|_| Arc::new(AtomicBool::new(false))).collect();
    // The rows answered by symmetry are never scheduled: their flags are raised up front.
    let rows: Vec<&str> = idx
        .iter()
        .map(|&(pi, _)| bl.props[pi].name.as_str())
        .collect();
    let families = Families::raising(p, opts.check.symmetry.as_ref(), &rows, &flags);
    let reductions = Reductions::new(bl.props.len());
    let mut got: Vec<Option<(PropResult, Meta, _)>> = vec![None; n];
    // What the attempts on each property cleared, for the rows the run's end leaves open.
    let mut tried = Vec::new();
    // BMC alone: the depth its shared unrolling cleared each property to.
    let bmc_cleared: Vec<AtomicU64> = (0..n).map(|_| AtomicU64::new(0)).collect();
    let mut bmc_time = std::time::Duration::ZERO;
    // Dropped when the engine is done, which wakes the watcher at once.
    let (finished, finished_rx) = std::sync::mpsc::channel::<()>();
    std::thread::scope(|s| {
        // Relay the cancellation and the deadline to the attempt in progress.
        let (flags, stop) = (&flags, &stop);
        s.spawn(move || loop {
            if stop.load(Ordering::Relaxed) || deadline.is_some_and(|d| Instant::now() >= d) {
                for f in flags {
                    f.store(true, Ordering::Relaxed);
                }
                return;
            }
            match finished_rx.recv_timeout(std::time::Duration::from_millis(20)) {
                Err(std::sync::mpsc::RecvTimeoutError::Timeout) => {}
                _ => return,
            }
        });
        let work = Work {
            open_ended: true,
            program: p,
            blasted: &bl,
            idx: &idx,
            engine,
            deadline,
            max_depth: depth.map(|d| d as usize),
            property_timeout: opts.property_timeout,
            flags,
            stop,
            reductions: &reductions,
        };
        let order: Vec<usize> = (0..n).collect();
        let mut record = |i: usize, r: SymResult| {
            // An attempt cut short by the end of the run is not a verdict.
            if stop.load(Ordering::Relaxed) && !schedule::settled(&r) {
                return;
            }
            flags[i].store(true, Ordering::Relaxed);
            let m = meta_of(engine.as_str(), &r);
            events(Event::Decided {
                index: i,
                result: &r.result,
                meta: &m,
            });
            for &k in families.followers(i) {
                if let Some((rk, mk)) = families.derive(k, &r.result, &m) {
                    events(Event::Decided {
                        index: k,
                        result: &rk,
                        meta: &mk,
                    });
                    got[k] = Some((rk, mk, None));
                }
            }
            got[i] = Some((r.result, m, r.invariant));
        };
        if engine == Engine::Bmc {
            bmc_time = crate::shared_bmc::bmc_all(&work, &bmc_cleared, events, &mut record);
        }
        tried = schedule::run(&work, &order, events, &mut record);
        drop(finished);
    });
    let mut results = Vec::new();
    let mut meta = Vec::new();
    let mut invariants = Vec::new();
    for (i, g) in got.into_iter().enumerate() {
        let (r, m, inv) = g.unwrap_or_else(|| {
            let (pi, kind) = idx[i];
            let mut t: schedule::Tried = tried.get(i).copied().unwrap_or_default();
            let by_bmc = bmc_cleared[i].load(Ordering::Relaxed);
            if by_bmc > 0 {
                // The shared unrolling worked on it too.
                t.time += bmc_time;
            }
            let r = PropResult {
                depth: t.depth.max(by_bmc),
                ..PropResult::unknown(&bl.props[pi].name, kind)
            };
            let m = Meta {
                engine: engine.as_str(),
                time_s: Some(t.time.as_secs_f64()),
                reason: Some(early_end_reason(opts, deadline)),
                decided_at_s: None,
                symmetry_of: None,
            };
            events(Event::Decided {
                index: i,
                result: &r,
                meta: &m,
            });
            (r, m, None)
        });
        results.push(r);
        meta.push(m);
        invariants.push(inv);
    }
    Ok(Run {
        report: Report {
            results,
            stats: Stats {
                threads: 1,
                state_bits: p.state_bits(),
                symmetry_note: families.note,
                ..Stats::default()
            },
        },
        meta,
        invariants,
    })
}
