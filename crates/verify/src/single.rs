//! One engine alone: the explicit engine, or one SAT engine deciding the properties one after
//! the other.

use crate::{Error, Event, Meta, Run, DEFAULT_BMC_DEPTH};
use statecheck_explicit::{Options, Report, Stats};
use statecheck_ir::Program;
use statecheck_symbolic::check::{decide, problems, Engine, Reductions, SymResult};
use statecheck_symbolic::engine::Limits;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Limits of one SAT run.
pub(crate) fn limits(
    timeout: Option<Duration>,
    depth: Option<u64>,
    stop: Option<Arc<AtomicBool>>,
) -> Limits {
    Limits {
        deadline: timeout.map(|t| Instant::now() + t),
        attempt_deadline: None,
        max_depth: depth.map(|d| d as usize),
        stop,
    }
}

/// The metadata of a SAT engine's result.
pub(crate) fn meta_of(engine: &'static str, s: &SymResult) -> Meta {
    Meta {
        engine,
        time_s: Some(s.time.as_secs_f64()),
        decided_at_s: None,
        reason: s.reason.clone(),
    }
}

/// The explicit engine alone; its verdicts are reported when the exploration ends.
pub(crate) fn run_explicit(
    p: &Program,
    opts: &Options,
    events: &(dyn Fn(Event) + Sync),
) -> Result<Run, Error> {
    let progress = |pr: &statecheck_explicit::Progress| events(Event::Progress(pr));
    let report = statecheck_explicit::verify(p, opts, Some(&progress))?;
    let meta: Vec<Meta> = report
        .results
        .iter()
        .map(|_| Meta {
            engine: "explicit",
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

/// One SAT engine on every selected property, one after the other.
pub(crate) fn run_engine(
    p: &Program,
    opts: &Options,
    engine: Engine,
    events: &(dyn Fn(Event) + Sync),
) -> Result<Run, Error> {
    let (bl, idx) = problems(p, &opts.properties)?;
    // BMC never proves: without a depth it stops at DEFAULT_BMC_DEPTH ticks (`bounded`).
    let depth = match (engine, opts.depth) {
        (Engine::Bmc, None) => Some(DEFAULT_BMC_DEPTH),
        (_, d) => d,
    };
    let lim = limits(opts.timeout, depth, None);
    let reductions = Reductions::new(bl.props.len());
    let mut results = Vec::new();
    let mut meta = Vec::new();
    let mut invariants = Vec::new();
    for (i, &(pi, kind)) in idx.iter().enumerate() {
        let s = decide(p, &bl, pi, kind, engine, &lim, &reductions);
        let m = meta_of(engine.as_str(), &s);
        events(Event::Decided {
            index: i,
            result: &s.result,
            meta: &m,
        });
        meta.push(m);
        invariants.push(s.invariant.clone());
        results.push(s.result);
    }
    Ok(Run {
        report: Report {
            results,
            stats: Stats {
                threads: 1,
                state_bits: p.state_bits(),
                ..Stats::default()
            },
        },
        meta,
        invariants,
    })
}
