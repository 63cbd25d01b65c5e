//! Systems with temporal properties (`ltl`, unbounded `respond`, `ctl`, `nonblocking`,
//! `deadlock_free`) on an engine other than the explicit one.
//!
//! The rows are the safety properties first (decided as on any system: the portfolio, or one
//! SAT engine), then the temporal ones in declaration order, then `deadlock_free` — the
//! explicit engine's order. The two groups run side by side. A temporal row is raced, under
//! [`Engine::Auto`], between the explicit engine's position graph and the SAT engines'
//! reductions to safety (`statecheck_symbolic::live`: liveness-to-safety with IC3 and BMC,
//! k-liveness with IC3); with one SAT engine it is that engine's reduction (IC3: both
//! liveness-to-safety and k-liveness; k-induction and BMC: liveness-to-safety). CTL,
//! `nonblocking` and `deadlock_free` are the explicit engine's only: under one SAT engine
//! they are `unknown`, "not supported by this engine".

use crate::single::early_end_reason;
use crate::{portfolio, single, Engine, Error, Event, Meta, Options, Run, DEFAULT_BMC_DEPTH};
use statecheck_explicit::ltl::DEADLOCK_FREE;
use statecheck_explicit::{Report, Stats};
use statecheck_ir::temporal::TemporalFormula;
use statecheck_ir::verdict::{PropKind, PropResult};
use statecheck_ir::Program;
use statecheck_symbolic::blast::blast;
use statecheck_symbolic::check::Engine as Sat;
use statecheck_symbolic::engine::Limits;
use statecheck_symbolic::live::{self, Method};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc, Mutex};
use std::time::{Duration, Instant};

/// The names of the rows a run reports, in report order: the selected safety properties (own
/// and built-in), then the selected temporal properties, then `deadlock_free` (when the
/// system has temporal properties or it is named).
pub fn row_names(program: &Program, properties: &[String]) -> Vec<String> {
    let (temporal, safety) = statecheck_explicit::ltl::split(program, properties);
    let (safety, temporal) = if properties.is_empty() {
        (
            statecheck_ir::verdict::properties(program)
                .into_iter()
                .map(|p| p.name)
                .collect(),
            temporal_all(program),
        )
    } else {
        (safety, temporal)
    };
    let mut out: Vec<String> = safety;
    out.extend(
        program
            .temporal
            .iter()
            .filter(|t| temporal.contains(&t.name))
            .map(|t| t.name.clone()),
    );
    if temporal.iter().any(|n| n == DEADLOCK_FREE) {
        out.push(DEADLOCK_FREE.to_string());
    }
    out
}

/// Every temporal row of `program`, `deadlock_free` last.
fn temporal_all(program: &Program) -> Vec<String> {
    let mut t: Vec<String> = program.temporal.iter().map(|t| t.name.clone()).collect();
    if !t.is_empty() {
        t.push(DEADLOCK_FREE.to_string());
    }
    t
}

/// One temporal row: its name, kind and index in `Program::temporal` (`None`:
/// `deadlock_free`).
struct Row {
    name: String,
    kind: PropKind,
    temporal: Option<usize>,
}

enum Msg {
    Explicit(Vec<PropResult>, Duration),
    Hunt(usize, PropResult, Duration),
    Sat(
        usize,
        &'static str,
        Box<statecheck_symbolic::check::SymResult>,
    ),
    Done,
}

/// `verify` of a system with temporal rows, on `opts.engine` (not `Explicit`).
pub(crate) fn run(
    program: &Program,
    opts: &Options,
    events: &(dyn Fn(Event) + Sync),
) -> Result<Run, Error> {
    let names = row_names(program, &opts.check.properties);
    let (temporal_names, safety_names) = statecheck_explicit::ltl::split(program, &names);
    let rows: Vec<Row> = temporal_names
        .iter()
        .map(|n| {
            let t = program.temporal.iter().position(|t| &t.name == n);
            Row {
                name: n.clone(),
                kind: t.map_or(PropKind::Builtin, |i| {
                    live::kind(program.temporal[i].written)
                }),
                temporal: t,
            }
        })
        .collect();
    let offset = safety_names.len();
    let mut safety_opts = opts.clone();
    safety_opts.check.properties = safety_names.clone();
    let (safety, temporal) = std::thread::scope(|s| {
        let safety = s.spawn(|| {
            if safety_names.is_empty() {
                return Ok(None);
            }
            match (opts.engine, opts.engine.symbolic()) {
                (_, Some(e)) => single::run_engine(program, &safety_opts, e, events),
                _ => portfolio::run_auto(program, &safety_opts, events, Instant::now()),
            }
            .map(Some)
        });
        let temporal = race(program, opts, &rows, offset, events);
        // A panic in the safety thread is a bug: passed on as it is.
        let safety = safety
            .join()
            .unwrap_or_else(|e| std::panic::resume_unwind(e));
        (safety, temporal)
    });
    let safety = safety?;
    let (mut results, mut meta, mut invariants, stats) = match safety {
        Some(r) => (r.report.results, r.meta, r.invariants, r.report.stats),
        None => (
            Vec::new(),
            Vec::new(),
            Vec::new(),
            Stats {
                state_bits: program.state_bits(),
                ..Stats::default()
            },
        ),
    };
    for (r, m) in temporal {
        results.push(r);
        meta.push(m);
        invariants.push(None);
    }
    Ok(Run {
        report: Report { results, stats },
        meta,
        invariants,
    })
}

/// The methods each SAT engine runs on an LTL row.
fn methods(engine: Engine) -> Vec<Method> {
    match engine {
        // Localization abstraction is for safety rows; liveness runs IC3's methods.
        Engine::Ic3 | Engine::Cegar => vec![Method::L2s(Sat::Ic3), Method::KLive],
        Engine::Kind => vec![Method::L2s(Sat::Kind)],
        Engine::Bmc => vec![Method::L2s(Sat::Bmc)],
        Engine::Auto | Engine::Explicit => {
            vec![Method::L2s(Sat::Bmc), Method::L2s(Sat::Ic3), Method::KLive]
        }
    }
}

/// Decide the temporal rows: the explicit engine (under `Auto`) and the SAT methods side by
/// side, the first definitive verdict per row winning; each reported at `offset + row`.
fn race(
    program: &Program,
    opts: &Options,
    rows: &[Row],
    offset: usize,
    events: &(dyn Fn(Event) + Sync),
) -> Vec<(PropResult, Meta)> {
    let started = Instant::now();
    let deadline = opts.check.timeout.map(|t| started + t);
    let n = rows.len();
    let auto = opts.engine == Engine::Auto;
    let ltl: Vec<bool> = rows
        .iter()
        .map(|r| {
            r.temporal
                .is_some_and(|t| matches!(program.temporal[t].formula, TemporalFormula::Ltl(_)))
        })
        .collect();
    let flags: Vec<Arc<AtomicBool>> = (0..n).map(|_| Arc::new(AtomicBool::new(false))).collect();
    let stop = Arc::new(AtomicBool::new(false));
    let got: Mutex<Vec<Option<(PropResult, Meta)>>> = Mutex::new(vec![None; n]);
    let mut fallback: Vec<Option<(PropResult, Meta)>> = vec![None; n];
    let decide = |i: usize, r: PropResult, m: Meta| {
        flags[i].store(true, Ordering::Relaxed);
        events(Event::Decided {
            index: offset + i,
            result: &r,
            meta: &m,
        });
        if let Ok(mut g) = got.lock() {
            g[i] = Some((r, m));
        }
    };
    // `deadlock_free` needs no search when the assumes read only inputs and allow some
    // vector: every state then has a successor.
    if let Some(i) = rows.iter().position(|r| r.temporal.is_none()) {
        if inputs_only_and_satisfiable(program) {
            let m = Meta {
                engine: opts.engine.as_str(),
                time_s: Some(started.elapsed().as_secs_f64()),
                reason: None,
                decided_at_s: Some(started.elapsed().as_secs_f64()),
                symmetry_of: None,
            };
            let mut r = PropResult::unknown(&rows[i].name, rows[i].kind);
            r.verdict = statecheck_ir::verdict::Verdict::Proved;
            r.note = Some("the `assume`s read only inputs and allow an input vector".into());
            decide(i, r, m);
        }
    }
    // Rows no SAT engine decides, under one SAT engine.
    if !auto {
        let open: Vec<usize> = (0..n)
            .filter(|&i| !ltl[i] && got.lock().is_ok_and(|g| g[i].is_none()))
            .collect();
        for i in open {
            let row = &rows[i];
            let m = Meta {
                engine: opts.engine.as_str(),
                time_s: Some(0.0),
                reason: Some(if row.temporal.is_some() {
                    live::CTL_UNSUPPORTED.to_string()
                } else {
                    "not supported by this engine: deadlock_free is decided by the explicit engine"
                        .to_string()
                }),
                decided_at_s: None,
                symmetry_of: None,
            };
            decide(i, PropResult::unknown(&row.name, row.kind), m);
        }
    }
    let (tx, rx) = mpsc::channel::<Msg>();
    let mut workers = 0;
    if auto {
        workers += 1;
        let tx = tx.clone();
        let p = program.clone();
        let sel: Vec<String> = rows.iter().map(|r| r.name.clone()).collect();
        let o = opts.check.clone();
        // Detached: the position graph has no stop flag; its own limits end it.
        std::thread::spawn(move || {
            crate::priority::lower_priority();
            let t = Instant::now();
            let (r, _) = statecheck_explicit::ltl::check(&p, Some(&sel), &o);
            let _ = tx.send(Msg::Explicit(r, t.elapsed()));
        });
    }
    let order: Vec<usize> = (0..n).filter(|&i| ltl[i]).collect();
    let depth = match (opts.engine, opts.check.depth) {
        (Engine::Bmc, None) => Some(DEFAULT_BMC_DEPTH as usize),
        (_, d) => d.map(|d| d as usize),
    };
    let bl = (!order.is_empty()).then(|| blast(program));
    std::thread::scope(|s| {
        if auto && !order.is_empty() {
            workers += 1;
            let tx = tx.clone();
            let (order, flags, stop) = (&order, &flags, &stop);
            // At the SAT threads' priority, unlike the explicit engine: on a closed loop too
            // deep for the other engines the hunt is the one that finds the violations, and at
            // nice 10 beside three busy SAT threads on two cores it got about 3 % of them (the
            // FAM's stall lasso for N = 4, found in 4.5 s with a core, was not found in 60 s).
            s.spawn(move || {
                hunt(program, rows, order, flags, stop, deadline, &tx);
                let _ = tx.send(Msg::Done);
            });
        }
        if let Some(bl) = &bl {
            for m in methods(opts.engine) {
                workers += 1;
                let tx = tx.clone();
                let (order, flags, stop, rows) = (&order, &flags, &stop, rows);
                s.spawn(move || {
                    for (pos, &i) in order.iter().enumerate() {
                        if flags[i].load(Ordering::Relaxed) || stop.load(Ordering::Relaxed) {
                            continue;
                        }
                        // An equal share of the time left for each row still open (a row
                        // decided early leaves its time to the others), within the per-property
                        // budget: one hard row never starves the rows behind it.
                        let now = Instant::now();
                        let open = order[pos..]
                            .iter()
                            .filter(|&&j| !flags[j].load(Ordering::Relaxed))
                            .count()
                            .max(1) as u32;
                        let share = deadline.map(|d| now + d.saturating_duration_since(now) / open);
                        let own = opts.property_timeout.map(|d| now + d);
                        let attempt = match (share, own) {
                            (Some(a), Some(b)) => Some(a.min(b)),
                            (a, b) => a.or(b),
                        };
                        let lim = Limits {
                            deadline,
                            attempt_deadline: attempt,
                            max_depth: depth,
                            stop: Some(Arc::clone(&flags[i])),
                        };
                        let t = rows[i].temporal.unwrap_or(0);
                        let r = live::decide(program, bl, t, m, &lim);
                        let _ = tx.send(Msg::Sat(i, m.as_str(), Box::new(r)));
                    }
                    let _ = tx.send(Msg::Done);
                });
            }
        }
        drop(tx);
        let open = |got: &Mutex<Vec<Option<(PropResult, Meta)>>>| {
            got.lock()
                .map_or(0, |g| g.iter().filter(|x| x.is_none()).count())
        };
        let mut done = 0;
        // At the deadline the engines stop too, and their last words (how far each got, or a
        // verdict found at the last moment) arrive just after it: they are waited for a little.
        let mut grace: Option<Instant> = None;
        while open(&got) > 0 && done < workers {
            let cancelled = opts.cancel.as_ref().is_some_and(|c| c.reason().is_some());
            if cancelled {
                break;
            }
            if deadline.is_some_and(|d| Instant::now() >= d) {
                let end = *grace.get_or_insert_with(|| {
                    stop.store(true, Ordering::Relaxed);
                    Instant::now() + DEADLINE_GRACE
                });
                if Instant::now() >= end {
                    break;
                }
            }
            let msg = match rx.recv_timeout(Duration::from_millis(50)) {
                Ok(m) => m,
                Err(mpsc::RecvTimeoutError::Timeout) => continue,
                Err(mpsc::RecvTimeoutError::Disconnected) => break,
            };
            let at = Some(started.elapsed().as_secs_f64());
            let is_open = |i: usize| got.lock().is_ok_and(|g| g[i].is_none());
            match msg {
                Msg::Explicit(results, t) => {
                    done += 1;
                    for r in results {
                        let Some(i) = rows.iter().position(|row| row.name == r.name) else {
                            continue;
                        };
                        let m = Meta {
                            engine: "explicit",
                            time_s: Some(t.as_secs_f64()),
                            reason: None,
                            decided_at_s: at,
                            symmetry_of: None,
                        };
                        if r.verdict.is_definitive() && is_open(i) {
                            decide(i, r, m);
                        } else if fallback[i].is_none() {
                            fallback[i] = Some((r, m));
                        }
                    }
                }
                Msg::Hunt(i, r, t) => {
                    let m = Meta {
                        engine: HUNT_ENGINE,
                        time_s: Some(t.as_secs_f64()),
                        reason: None,
                        decided_at_s: at,
                        symmetry_of: None,
                    };
                    if is_open(i) {
                        decide(i, r, m);
                    }
                }
                Msg::Sat(i, engine, s) => {
                    let mut m = single::meta_of(engine, &s);
                    m.decided_at_s = at;
                    if s.result.verdict.is_definitive() && is_open(i) {
                        decide(i, s.result, m);
                    } else if is_open(i) {
                        match &mut fallback[i] {
                            // Under auto the row keeps the first report, and its reason says
                            // how far every SAT method got ("bmc: …; klive: …").
                            Some((_, kept)) if auto => {
                                if let Some(why) = m.reason {
                                    let said = format!("{engine}: {why}");
                                    kept.reason = Some(match kept.reason.take() {
                                        Some(before) => format!("{before}; {said}"),
                                        None => said,
                                    });
                                }
                            }
                            slot => {
                                if auto {
                                    m.reason = m.reason.map(|why| format!("{engine}: {why}"));
                                }
                                *slot = Some((s.result, m));
                            }
                        }
                    }
                }
                Msg::Done => done += 1,
            }
        }
        stop.store(true, Ordering::Relaxed);
        for f in &flags {
            f.store(true, Ordering::Relaxed);
        }
    });
    let why = early_end_reason(opts, deadline);
    let mut got = got.into_inner().unwrap_or_default();
    for (i, g) in got.iter_mut().enumerate() {
        if g.is_some() {
            continue;
        }
        let (r, mut m) = fallback[i].take().unwrap_or_else(|| {
            (
                PropResult::unknown(&rows[i].name, rows[i].kind),
                Meta {
                    engine: opts.engine.as_str(),
                    time_s: Some(started.elapsed().as_secs_f64()),
                    reason: None,
                    decided_at_s: None,
                    symmetry_of: None,
                },
            )
        });
        // The run's end is the reason, unless the engine gave its own (its budget, a bound).
        if r.verdict == statecheck_ir::verdict::Verdict::Unknown && m.reason.is_none() {
            m.reason = Some(why.clone());
        }
        events(Event::Decided {
            index: offset + i,
            result: &r,
            meta: &m,
        });
        *g = Some((r, m));
    }
    got.into_iter().flatten().collect()
}

/// The engine name of a lasso found by [`hunt`] (`"engine"` in `verify --json`).
const HUNT_ENGINE: &str = "sim";

/// How long the race waits after the deadline for the engines' last reports.
const DEADLINE_GRACE: Duration = Duration::from_secs(1);

/// The lasso hunt of the simulator (`statecheck_sim::hunt`) on the LTL rows `order`, until
/// each is decided (by it or another engine), the deadline or `stop`: each lasso it finds,
/// already confirmed by a replay of its scenario, is sent as the row's violation.
fn hunt(
    program: &Program,
    rows: &[Row],
    order: &[usize],
    flags: &[Arc<AtomicBool>],
    stop: &AtomicBool,
    deadline: Option<Instant>,
    tx: &mpsc::Sender<Msg>,
) {
    let started = Instant::now();
    let targets: Vec<usize> = order.iter().filter_map(|&i| rows[i].temporal).collect();
    let row_of = |t: usize| order.iter().copied().find(|&i| rows[i].temporal == Some(t));
    let opts = statecheck_sim::hunt::HuntOptions {
        deadline,
        stop: Some(stop),
        ..Default::default()
    };
    let is_open = |t: usize| row_of(t).is_some_and(|i| !flags[i].load(Ordering::Relaxed));
    statecheck_sim::hunt::hunt(program, &targets, &opts, &is_open, &mut |f| {
        let Some(i) = row_of(f.property) else {
            return;
        };
        let r = PropResult {
            name: rows[i].name.clone(),
            kind: rows[i].kind,
            verdict: statecheck_ir::verdict::Verdict::Violated,
            depth: f.inputs.len() as u64,
            counterexample: Some(f.inputs),
            error: None,
            note: None,
            loop_start: Some(f.loop_start as u64),
        };
        let _ = tx.send(Msg::Hunt(i, r, started.elapsed()));
    });
}

/// True when every `assume` conjunct reads only inputs and some input vector satisfies them
/// all (found by the IR's pruned enumeration): then no reachable state is a deadlock.
fn inputs_only_and_satisfiable(program: &Program) -> bool {
    let mut space = statecheck_ir::assume::InputSpace::new(program);
    if !space.state_assumes.is_empty() || !space.mixed_assumes.is_empty() {
        return false;
    }
    if space.input_assumes.is_empty() {
        return true;
    }
    space.solve_static(program) && space.listed().is_some_and(|(_, n)| n > 0)
}
