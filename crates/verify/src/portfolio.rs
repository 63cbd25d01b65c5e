//! [`Engine::Auto`](crate::Engine::Auto): the explicit engine, BMC, IC3 and k-induction run
//! side by side; each property gets the first definitive verdict and the engine that found
//! it, reported the moment it is found.
//!
//! The schedule takes the cheap wins first: the explicit engine and BMC start at once, IC3 and
//! k-induction after a head start of [`HEAD_START`] (a small model is then decided by the
//! explicit engine alone, at its own speed); IC3 and k-induction go over the properties in
//! passes with growing budgets (`schedule.rs`), so a hard property never starves the others.
//! BMC first unrolls the circuit of all own properties once, asking every open one at each
//! depth (its shortest traces for all of them for the price of the deepest), then takes what
//! is left (the built-ins) through the same passes.
//!
//! With symmetry reduction the SAT engines check one member of each family (their flags of
//! the other members are raised up front) and a member's verdict is its followers' too
//! (`symmetry.rs`); the explicit engine decides every row itself, with its own reduction.
//!
//! Before any of that, [`crate::verify`] runs the quick race of `quick.rs`: a small model is
//! decided there in moments, without starting the whole portfolio.

use crate::circuit::SYMBOLIC_RACE;
use crate::priority::lower_priority;
use crate::schedule::{self, Work};
use crate::single::{early_end_reason, meta_of};
use crate::symmetry::Families;
use crate::{Error, Event, Meta, Options, Run, REASON_PROPERTY_LIMIT};
use statecheck_explicit::{Progress, Report, Stats};
use statecheck_ir::verdict::{PropKind, PropResult, Verdict};
use statecheck_ir::Program;
use statecheck_symbolic::aig::Aig;
use statecheck_symbolic::check::{problems, Engine, Reductions, SymResult};
use statecheck_symbolic::engine::Invariant;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};

/// How long the explicit engine and BMC have the cores to themselves.
pub const HEAD_START: Duration = Duration::from_millis(300);

/// How often the run checks the cancellation flag and the deadline while it waits.
const POLL: Duration = Duration::from_millis(50);

/// A definitive verdict with its metadata and, for IC3 proofs, the circuit and invariant.
type Decided = (PropResult, Meta, Option<(Aig, Invariant)>);

enum Msg {
    Explicit(Box<Result<Report, String>>, Duration),
    Progress(Box<Progress>),
    Symbolic(usize, &'static str, Box<SymResult>),
    Done,
}

/// `--engine auto`.
/// `origin`: the start of the whole run (before auto's quick pass), from which `decided_at_s`
/// counts.
pub(crate) fn run_auto(
    p: &Program,
    opts: &Options,
    events: &(dyn Fn(Event) + Sync),
    origin: Instant,
) -> Result<Run, Error> {
    let started = Instant::now();
    let deadline = opts.check.timeout.map(|t| started + t);
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    let cancel = opts.cancel.clone().unwrap_or_default();
    // Raised when the run ends, for whatever reason; the engines poll it.
    let stop = Arc::new(AtomicBool::new(false));
    let explicit_stop = Arc::new(AtomicBool::new(false));
    let explicit_done = Arc::new(AtomicBool::new(false));
    let (tx, rx) = mpsc::channel::<Msg>();
    {
        let tx = tx.clone();
        let p = p.clone();
        let mut o = opts.check.clone();
        if o.threads == 0 {
            o.threads = cores.saturating_sub(2).max(1);
        }
        o.stop = Some(Arc::clone(&explicit_stop));
        let done = Arc::clone(&explicit_done);
        // Detached: once stopped it may still rebuild a counterexample it found, and the run
        // need not wait for it.
        std::thread::spawn(move || {
            // A model small enough for the explicit engine is done in moments; on a large one
            // it would take the cores from the SAT engines until the deadline.
            lower_priority();
            let t = Instant::now();
            let ptx = tx.clone();
            let progress = move |pr: &Progress| {
                let _ = ptx.send(Msg::Progress(Box::new(pr.clone())));
            };
            let r = statecheck_explicit::verify(&p, &o, Some(&progress)).map_err(|e| e.to_string());
            done.store(true, Ordering::Relaxed);
            let _ = tx.send(Msg::Explicit(Box::new(r), t.elapsed()));
        });
    }
    let (bl, idx) = match problems(p, &opts.check.properties) {
        Ok(x) => x,
        Err(e) => {
            explicit_stop.store(true, Ordering::Relaxed);
            return Err(e.into());
        }
    };
    let n = idx.len();
    // One flag per property: raised when any engine decides it (the others move on to the
    // next property) and, for all, when the run ends.
    let flags: Vec<Arc<AtomicBool>> = (0..n).map(|_| Arc::new(AtomicBool::new(false))).collect();
    // Rows answered by symmetry: raised for the SAT engines, which then skip them.
    let rows: Vec<&str> = idx
        .iter()
        .map(|&(pi, _)| bl.props[pi].name.as_str())
        .collect();
    let families = Families::raising(p, opts.check.symmetry.as_ref(), &rows, &flags);
    let reductions = Reductions::new(bl.props.len());
    let depth = opts.check.depth.map(|d| d as usize);
    let mut got: Vec<Option<Decided>> = vec![None; n];
    let mut fallback: Vec<Option<(PropResult, Meta)>> = vec![None; n];
    let mut explicit_stats = None;
    // The layer the explicit engine was expanding: no property has a counterexample (or
    // witness) of at most that many ticks, whatever the engines leave undecided.
    let mut explicit_cleared = 0u64;
    // Per row: the depth BMC's shared unrolling cleared it to.
    let bmc_cleared: Vec<AtomicU64> = (0..n).map(|_| AtomicU64::new(0)).collect();
    std::thread::scope(|s| {
        for engine in SYMBOLIC_RACE {
            let tx = tx.clone();
            let work = Work {
                // k-induction has the fixed passes only: a property it has not proved within
                // them is one whose step case keeps failing at every depth it reaches, and
                // each pass starts again from depth 0, so the open-ended pass only took the
                // cores from IC3 (complete) and BMC (on the FAM closed loop, 6.7 s of CPU on
                // `master_failure_sequence` without a verdict).
                open_ended: engine != Engine::Kind,
                program: p,
                blasted: &bl,
                idx: &idx,
                engine,
                deadline,
                max_depth: depth,
                property_timeout: opts.property_timeout,
                flags: &flags,
                stop: &stop,
                reductions: &reductions,
            };
            let explicit_done = &explicit_done;
            let bmc_cleared = &bmc_cleared;
            let stop = &stop;
            let idx = &idx;
            s.spawn(move || {
                if engine != Engine::Bmc {
                    while started.elapsed() < HEAD_START
                        && !explicit_done.load(Ordering::Relaxed)
                        && !stop.load(Ordering::Relaxed)
                    {
                        std::thread::sleep(Duration::from_millis(10));
                    }
                }
                // IC3 and k-induction take the `reachable` properties last: their witnesses
                // are BMC's to find, and a long search for one would hold up the proofs.
                let mut order: Vec<usize> = (0..n).collect();
                if engine != Engine::Bmc {
                    order.sort_by_key(|&i| idx[i].1 == PropKind::Reachable);
                }
                let mut send = |i: usize, r: SymResult| {
                    let _ = tx.send(Msg::Symbolic(i, engine.as_str(), Box::new(r)));
                };
                if engine == Engine::Bmc {
                    // All own properties in one unrolling (their shortest traces as it
                    // reaches them); what it leaves (built-ins, or every property at a depth
                    // bound) goes through the schedule below.
                    crate::shared_bmc::bmc_all(&work, bmc_cleared, events, &mut send);
                }
                schedule::run(&work, &order, events, &mut send);
                let _ = tx.send(Msg::Done);
            });
        }
        let mut done = 0;
        let mut explicit_over = false;
        let decide = |i: usize, r: PropResult, m: Meta, inv, got: &mut Vec<Option<Decided>>| {
            flags[i].store(true, Ordering::Relaxed);
            events(Event::Decided {
                index: i,
                result: &r,
                meta: &m,
            });
            got[i] = Some((r, m, inv));
        };
        while got.iter().any(Option::is_none) && !(done == SYMBOLIC_RACE.len() && explicit_over) {
            if cancel.reason().is_some() || deadline.is_some_and(|d| Instant::now() >= d) {
                break;
            }
            let msg = match rx.recv_timeout(POLL) {
                Ok(m) => m,
                Err(mpsc::RecvTimeoutError::Timeout) => continue,
                Err(mpsc::RecvTimeoutError::Disconnected) => break,
            };
            match msg {
                Msg::Progress(pr) => {
                    explicit_cleared = explicit_cleared.max(pr.depth);
                    events(Event::Progress(&pr));
                }
                Msg::Explicit(r, t) => {
                    explicit_over = true;
                    if let Ok(rep) = *r {
                        // Only the rows of this run's selection (temporal rows never come:
                        // `verify` gives systems with temporal properties to explicit alone).
                        for (i, r) in rep.results.iter().enumerate().take(got.len()) {
                            let m = Meta {
                                engine: "explicit",
                                time_s: Some(t.as_secs_f64()),
                                reason: None,
                                decided_at_s: Some(origin.elapsed().as_secs_f64()),
                                symmetry_of: None,
                            };
                            if r.verdict.is_definitive() && got[i].is_none() {
                                decide(i, r.clone(), m, None, &mut got);
                            } else if fallback[i].is_none() {
                                fallback[i] = Some((r.clone(), m));
                            }
                        }
                        explicit_stats = Some(rep.stats);
                    }
                }
                Msg::Symbolic(i, engine, s) => {
                    let mut m = meta_of(engine, &s);
                    m.decided_at_s = Some(origin.elapsed().as_secs_f64());
                    let definitive = s.result.verdict.is_definitive() && got[i].is_none();
                    let replaces = |f: &Option<(PropResult, Meta)>| engine == "ic3" || f.is_none();
                    let derived: Vec<(usize, PropResult, Meta)> = families
                        .followers(i)
                        .iter()
                        .filter_map(|&k| {
                            let (r, m) = families.derive(k, &s.result, &m)?;
                            Some((k, r, m))
                        })
                        .collect();
                    if definitive {
                        decide(i, s.result, m, s.invariant, &mut got);
                    } else if replaces(&fallback[i]) {
                        fallback[i] = Some((s.result, m));
                    }
                    for (k, r, mk) in derived {
                        if definitive && got[k].is_none() {
                            decide(k, r, mk, None, &mut got);
                        } else if !definitive && replaces(&fallback[k]) {
                            fallback[k] = Some((r, mk));
                        }
                    }
                }
                Msg::Done => done += 1,
            }
        }
        // The rows nobody decided, reported before the engines are told to stop.
        let why = early_end_reason(opts, deadline);
        for (i, g) in got.iter_mut().enumerate() {
            if g.is_some() {
                continue;
            }
            let (mut r, mut m) = fallback[i].take().unwrap_or_else(|| {
                (
                    PropResult::unknown(&bl.props[idx[i].0].name, idx[i].1),
                    Meta {
                        engine: "auto",
                        time_s: Some(started.elapsed().as_secs_f64()),
                        reason: None,
                        decided_at_s: None,
                        symmetry_of: None,
                    },
                )
            });
            // The reason is the run's end, unless this property's own budget ran out.
            if !r.verdict.is_definitive() && m.reason.as_deref() != Some(REASON_PROPERTY_LIMIT) {
                m.reason = Some(why.clone());
            }
            // An unknown row shows the deepest depth any engine cleared, and which one.
            if r.verdict == Verdict::Unknown {
                let by_bmc = bmc_cleared[i].load(Ordering::Relaxed);
                for (depth, engine) in [(by_bmc, "bmc"), (explicit_cleared, "explicit")] {
                    if depth > r.depth {
                        r.depth = depth;
                        // That engine worked on it for the whole run, undecided.
                        m = Meta {
                            engine,
                            time_s: Some(started.elapsed().as_secs_f64()),
                            reason: m.reason.take(),
                            decided_at_s: None,
                            symmetry_of: m.symmetry_of.take(),
                        };
                    }
                }
            }
            events(Event::Decided {
                index: i,
                result: &r,
                meta: &m,
            });
            *g = Some((r, m, None));
        }
        stop.store(true, Ordering::Relaxed);
        explicit_stop.store(true, Ordering::Relaxed);
        for f in &flags {
            f.store(true, Ordering::Relaxed);
        }
    });
    let mut results = Vec::new();
    let mut meta = Vec::new();
    let mut invariants = Vec::new();
    for (r, m, inv) in got.into_iter().flatten() {
        results.push(r);
        meta.push(m);
        invariants.push(inv);
    }
    Ok(Run {
        report: Report {
            results,
            stats: explicit_stats.unwrap_or(Stats {
                threads: cores,
                state_bits: p.state_bits(),
                symmetry_note: families.note.clone(),
                ..Stats::default()
            }),
        },
        meta,
        invariants,
    })
}
