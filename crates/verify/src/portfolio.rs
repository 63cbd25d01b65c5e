//! [`Engine::Auto`](crate::Engine::Auto): the explicit engine, IC3, k-induction and BMC run
//! side by side; each property gets the first definitive verdict and the engine that found it,
//! reported the moment it is found.

use crate::circuit::SYMBOLIC_RACE;
use crate::priority::lower_priority;
use crate::single::meta_of;
use crate::{Error, Event, Meta, Run};
use statecheck_explicit::{Options, Report, Stats};
use statecheck_ir::verdict::{PropKind, PropResult};
use statecheck_ir::Program;
use statecheck_symbolic::aig::Aig;
use statecheck_symbolic::check::{decide, problems, Engine, Reductions, SymResult};
use statecheck_symbolic::engine::{Invariant, Limits};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};

fn definitive(r: &PropResult) -> bool {
    r.verdict.is_definitive()
}

/// A definitive verdict with its metadata and, for IC3 proofs, the circuit and invariant.
type Decided = (PropResult, Meta, Option<(Aig, Invariant)>);

enum Msg {
    Explicit(Box<Result<Report, String>>, Duration),
    Symbolic(usize, &'static str, Box<SymResult>),
    Done,
}

/// Per-property budgets of the passes each racing engine makes over the undecided properties
/// (`None`: until the deadline).
const AUTO_BUDGETS: [Option<Duration>; 3] = [
    Some(Duration::from_secs(1)),
    Some(Duration::from_secs(10)),
    None,
];

/// `--engine auto`: the explicit engine, IC3, k-induction and BMC run side by side; each property gets the
/// first definitive verdict and the engine that found it.
pub(crate) fn run_auto(
    p: &Program,
    opts: &Options,
    events: &(dyn Fn(Event) + Sync),
) -> Result<Run, Error> {
    let (bl, idx) = problems(p, &opts.properties)?;
    let n = idx.len();
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    let stop = Arc::new(AtomicBool::new(false));
    let (tx, rx) = mpsc::channel::<Msg>();
    let started = Instant::now();
    {
        let tx = tx.clone();
        let p = p.clone();
        let mut o = opts.clone();
        if o.threads == 0 {
            o.threads = cores.saturating_sub(2).max(1);
        }
        // Detached: the explicit engine has no stop flag; the process exits without waiting.
        std::thread::spawn(move || {
            // A model small enough for the explicit engine is done in moments; on a large one
            // it would take the cores from the SAT engines until the deadline.
            lower_priority();
            let t = Instant::now();
            let r = statecheck_explicit::verify(&p, &o, None).map_err(|e| e.to_string());
            let _ = tx.send(Msg::Explicit(Box::new(r), t.elapsed()));
        });
    }
    let bl = Arc::new(bl);
    // One stop flag per property: raised when any engine decides it (the others move on to
    // the next property) and, for all, when the run ends.
    let flags: Arc<Vec<Arc<AtomicBool>>> =
        Arc::new((0..n).map(|_| Arc::new(AtomicBool::new(false))).collect());
    let deadline = opts.timeout.map(|t| started + t);
    let reductions = Arc::new(Reductions::new(bl.props.len()));
    let mut workers = Vec::new();
    for engine in SYMBOLIC_RACE {
        let tx = tx.clone();
        let p = p.clone();
        let bl = Arc::clone(&bl);
        let idx = idx.clone();
        let flags = Arc::clone(&flags);
        let depth = opts.depth.map(|d| d as usize);
        let stop = Arc::clone(&stop);
        let reductions = Arc::clone(&reductions);
        workers.push(std::thread::spawn(move || {
            // Passes with growing budgets per property, so that one hard property does not
            // starve the easy ones behind it; the last pass runs to the deadline.
            // BMC deepens one unrolling and would lose it on a restart: one pass.
            let budgets: &[Option<Duration>] = if engine == Engine::Bmc {
                &[None]
            } else {
                &AUTO_BUDGETS
            };
            // IC3 and k-induction take the `reachable` properties last: their witnesses are
            // BMC's to find, and a long search for one would hold up the proofs behind it.
            let mut order: Vec<usize> = (0..idx.len()).collect();
            if engine != Engine::Bmc {
                order.sort_by_key(|&i| idx[i].1 == PropKind::Reachable);
            }
            'passes: for (pass, budget) in budgets.iter().enumerate() {
                let last = pass + 1 == budgets.len();
                for &i in &order {
                    let (pi, kind) = idx[i];
                    if flags[i].load(Ordering::Relaxed) {
                        continue;
                    }
                    let until = budget.map(|b| Instant::now() + b);
                    let lim = Limits {
                        deadline,
                        attempt_deadline: until,
                        max_depth: depth,
                        stop: Some(Arc::clone(&flags[i])),
                    };
                    let s = decide(&p, &bl, pi, kind, engine, &lim, &reductions);
                    if last || definitive(&s.result) {
                        let _ = tx.send(Msg::Symbolic(i, engine.as_str(), Box::new(s)));
                    }
                    if stop.load(Ordering::Relaxed) || deadline.is_some_and(|d| Instant::now() >= d)
                    {
                        break 'passes;
                    }
                }
            }
            let _ = tx.send(Msg::Done);
        }));
    }
    drop(tx);
    let mut got: Vec<Option<Decided>> = vec![None; n];
    let mut fallback: Vec<Option<(PropResult, Meta)>> = vec![None; n];
    let mut explicit_stats = None;
    let mut done = 0;
    let mut explicit_done = false;
    while got.iter().any(Option::is_none) && !(done == SYMBOLIC_RACE.len() && explicit_done) {
        let wait = opts
            .timeout
            .map(|t| t.saturating_sub(started.elapsed()) + Duration::from_millis(200));
        let msg = match wait {
            Some(w) => match rx.recv_timeout(w) {
                Ok(m) => m,
                Err(_) => break,
            },
            None => match rx.recv() {
                Ok(m) => m,
                Err(_) => break,
            },
        };
        match msg {
            Msg::Explicit(r, t) => {
                explicit_done = true;
                if let Ok(rep) = *r {
                    for (i, r) in rep.results.iter().enumerate() {
                        let m = Meta {
                            engine: "explicit",
                            time_s: Some(t.as_secs_f64()),
                            reason: None,
                            decided_at_s: Some(started.elapsed().as_secs_f64()),
                        };
                        if definitive(r) && got[i].is_none() {
                            flags[i].store(true, Ordering::Relaxed);
                            events(Event::Decided {
                                index: i,
                                result: r,
                                meta: &m,
                            });
                            got[i] = Some((r.clone(), m, None));
                        } else if fallback[i].is_none() {
                            fallback[i] = Some((r.clone(), m));
                        }
                    }
                    explicit_stats = Some(rep.stats);
                }
            }
            Msg::Symbolic(i, engine, s) => {
                let mut m = meta_of(engine, &s);
                m.decided_at_s = Some(started.elapsed().as_secs_f64());
                if definitive(&s.result) && got[i].is_none() {
                    flags[i].store(true, Ordering::Relaxed);
                    events(Event::Decided {
                        index: i,
                        result: &s.result,
                        meta: &m,
                    });
                    got[i] = Some((s.result, m, s.invariant));
                } else if engine == "ic3" {
                    fallback[i] = Some((s.result, m));
                }
            }
            Msg::Done => done += 1,
        }
    }
    stop.store(true, Ordering::Relaxed);
    for f in flags.iter() {
        f.store(true, Ordering::Relaxed);
    }
    for w in workers {
        let _ = w.join();
    }
    let mut results = Vec::new();
    let mut meta = Vec::new();
    let mut invariants = Vec::new();
    for (i, g) in got.into_iter().enumerate() {
        match g {
            Some((r, m, inv)) => {
                results.push(r);
                meta.push(m);
                invariants.push(inv);
            }
            None => {
                let (r, m) = fallback[i].take().unwrap_or_else(|| {
                    (
                        PropResult::unknown(&bl.props[idx[i].0].name, idx[i].1),
                        Meta {
                            engine: "auto",
                            time_s: Some(started.elapsed().as_secs_f64()),
                            reason: Some("no engine answered within the limits".into()),
                            decided_at_s: None,
                        },
                    )
                });
                events(Event::Decided {
                    index: i,
                    result: &r,
                    meta: &m,
                });
                results.push(r);
                meta.push(m);
                invariants.push(None);
            }
        }
    }
    Ok(Run {
        report: Report {
            results,
            stats: explicit_stats.unwrap_or(Stats {
                threads: cores,
                state_bits: p.state_bits(),
                ..Stats::default()
            }),
        },
        meta,
        invariants,
    })
}
