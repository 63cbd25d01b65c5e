//! The SAT-based engines in `statecheck verify`: `--engine bmc|kind|ic3|auto`, certificates,
//! and AIGER input files.

use super::report::Meta;
use anyhow::{bail, Context, Result};
use statecheck_explicit::{Options, PropKind, PropResult, Report, Stats, Verdict};
use statecheck_ir::Program;
use statecheck_symbolic::aig::Aig;
use statecheck_symbolic::check::{decide, problems, run_reduced, Engine, Reductions, SymResult};
use statecheck_symbolic::engine::{Invariant, Limits, Outcome};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};

/// The depth bound of `--engine bmc` without `--depth`.
pub const DEFAULT_BMC_DEPTH: u64 = 100;

/// The engine chosen on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum EngineArg {
    /// Explicit-state breadth-first search (the default).
    Explicit,
    /// Bounded model checking (shortest counterexamples; no proofs).
    Bmc,
    /// k-induction with simple-path constraints.
    Kind,
    /// IC3/PDR (proofs with an inductive invariant).
    Ic3,
    /// Explicit and symbolic engines side by side; the first definitive verdict wins.
    Auto,
}

impl EngineArg {
    fn symbolic(self) -> Option<Engine> {
        match self {
            EngineArg::Bmc => Some(Engine::Bmc),
            EngineArg::Kind => Some(Engine::Kind),
            EngineArg::Ic3 => Some(Engine::Ic3),
            EngineArg::Explicit | EngineArg::Auto => None,
        }
    }
}

/// Results of a symbolic or mixed run, in the explicit engine's report shape.
pub struct Run {
    /// The report (stats are the explicit engine's when it ran to the end, else empty).
    pub report: Report,
    /// Engine, time and reason per result.
    pub meta: Vec<Meta>,
    /// IC3 invariants per result, with their circuits.
    pub invariants: Vec<Option<(Aig, Invariant)>>,
}

fn limits(timeout: Option<Duration>, depth: Option<u64>, stop: Option<Arc<AtomicBool>>) -> Limits {
    Limits {
        deadline: timeout.map(|t| Instant::now() + t),
        attempt_deadline: None,
        max_depth: depth.map(|d| d as usize),
        stop,
    }
}

fn meta_of(engine: &'static str, s: &SymResult) -> Meta {
    Meta {
        engine,
        time_s: Some(s.time.as_secs_f64()),
        decided_at_s: None,
        reason: s.reason.clone(),
    }
}

/// Run one symbolic engine on every selected property, one after the other.
pub fn run_engine(p: &Program, opts: &Options, engine: Engine) -> Result<Run> {
    let (bl, idx) = problems(p, &opts.properties).map_err(|e| anyhow::anyhow!(e))?;
    // BMC never proves: without --depth it stops at DEFAULT_BMC_DEPTH ticks (`bounded`).
    let depth = match (engine, opts.depth) {
        (Engine::Bmc, None) => Some(DEFAULT_BMC_DEPTH),
        (_, d) => d,
    };
    let lim = limits(opts.timeout, depth, None);
    let reductions = Reductions::new(bl.props.len());
    let mut results = Vec::new();
    let mut meta = Vec::new();
    let mut invariants = Vec::new();
    for &(pi, kind) in &idx {
        let s = decide(p, &bl, pi, kind, engine, &lim, &reductions);
        meta.push(meta_of(engine.as_str(), &s));
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

fn definitive(r: &PropResult) -> bool {
    !matches!(r.verdict, Verdict::Unknown | Verdict::Bounded)
}

/// A definitive verdict with its metadata and, for IC3 proofs, the circuit and invariant.
type Decided = (PropResult, Meta, Option<(Aig, Invariant)>);

enum Msg {
    Explicit(Box<Result<Report, String>>, Duration),
    Symbolic(usize, &'static str, Box<SymResult>),
    Done,
}

/// The symbolic engines `--engine auto` races (besides the explicit one): IC3 for proofs,
/// k-induction for proofs whose invariant is "no bad state within k ticks", BMC for deep
/// counterexamples.
const SYMBOLIC_RACE: [Engine; 3] = [Engine::Ic3, Engine::Kind, Engine::Bmc];

/// Per-property budgets of the passes each racing engine makes over the undecided properties
/// (`None`: until the deadline).
const AUTO_BUDGETS: [Option<Duration>; 3] = [
    Some(Duration::from_secs(1)),
    Some(Duration::from_secs(10)),
    None,
];

/// `--engine auto`: the explicit engine, IC3, k-induction and BMC run side by side; each property gets the
/// first definitive verdict and the engine that found it.
pub fn run_auto(p: &Program, opts: &Options) -> Result<Run> {
    let (bl, idx) = problems(p, &opts.properties).map_err(|e| anyhow::anyhow!(e))?;
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
            let r = statecheck_explicit::verify(&p, &o, None);
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
                        PropResult {
                            name: bl.props[idx[i].0].name.clone(),
                            kind: idx[i].1,
                            verdict: Verdict::Unknown,
                            depth: 0,
                            counterexample: None,
                            error: None,
                            note: None,
                        },
                        Meta {
                            engine: "auto",
                            time_s: Some(started.elapsed().as_secs_f64()),
                            reason: Some("no engine answered within the limits".into()),
                            decided_at_s: None,
                        },
                    )
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

/// Lower the calling thread's scheduling priority (nice 10; on Linux the nice value is per
/// thread and inherited by the threads it starts). Failure leaves the priority as it was.
#[cfg(target_os = "linux")]
#[allow(unsafe_code)] // reason: two FFI calls with integer arguments only (gettid, setpriority)
fn lower_priority() {
    // SAFETY: `gettid` has no preconditions and `setpriority` reads only its integer
    // arguments; neither touches memory of ours. An error (-1) is ignored on purpose.
    unsafe {
        let tid = libc::syscall(libc::SYS_gettid);
        if let Ok(tid) = libc::id_t::try_from(tid) {
            libc::setpriority(libc::PRIO_PROCESS, tid, 10);
        }
    }
}

/// Elsewhere the explicit engine keeps the default priority.
#[cfg(not(target_os = "linux"))]
fn lower_priority() {}

/// Choose the engine of a `.sc` run; `None` means the explicit engine alone.
pub fn run_model(p: &Program, opts: &Options, engine: EngineArg) -> Result<Option<Run>> {
    match (engine, engine.symbolic()) {
        (_, Some(e)) => run_engine(p, opts, e).map(Some),
        (EngineArg::Auto, None) => run_auto(p, opts).map(Some),
        _ => Ok(None),
    }
}

/// Write the certificate of the single proved property of a run.
pub fn write_certificate(run: &Run, file: &str) -> Result<()> {
    let found: Vec<(usize, &(Aig, Invariant))> = run
        .invariants
        .iter()
        .enumerate()
        .filter_map(|(i, x)| x.as_ref().map(|x| (i, x)))
        .collect();
    match found.as_slice() {
        [(i, (aig, inv))] => {
            let name = &run.report.results[*i].name;
            let text = statecheck_symbolic::cert::write(aig, name, inv);
            crate::outpath::write(std::path::Path::new(file), text.as_bytes())?;
            eprintln!(
                "wrote {file}: inductive invariant of `{name}`, {} clause(s)",
                inv.len()
            );
            Ok(())
        }
        [] => bail!(
            "no certificate written: no property was proved by IC3 (use --engine ic3 and a property that holds)"
        ),
        _ => bail!("--certificate needs exactly one property: choose it with --property"),
    }
}

/// `--check-certificate FILE`: check the invariant in FILE for the one circuit given.
pub fn check_certificate(aig: &Aig, name: &str, file: &str) -> Result<u8> {
    crate::outpath::note_input(file);
    let text = std::fs::read_to_string(file).with_context(|| format!("cannot read `{file}`"))?;
    let inv = statecheck_symbolic::cert::parse(&text, aig.latches.len())
        .map_err(|e| anyhow::anyhow!("{file}: {e}"))?;
    match statecheck_symbolic::cert::check(aig, &inv) {
        Ok(()) => {
            println!(
                "certificate valid: {file} proves `{name}` ({} clause(s); initiation, consecution and safety each checked by one SAT call)",
                inv.len()
            );
            Ok(0)
        }
        Err(e) => {
            println!("certificate INVALID for `{name}`: {e}");
            Ok(1)
        }
    }
}

/// The one-property circuit of `name` in a program (for `--check-certificate`).
pub fn model_problem(p: &Program, names: &[String]) -> Result<(Aig, String)> {
    let [name] = names else {
        bail!("--check-certificate needs exactly one --property");
    };
    let (bl, idx) = problems(p, names).map_err(|e| anyhow::anyhow!(e))?;
    let Some(&(pi, _)) = idx.first() else {
        bail!("no property named `{name}`");
    };
    Ok((bl.problem(pi), name.clone()))
}

/// Names of an AIGER file's properties (`b0`, `b1`, ... unless the symbol table names them).
/// The bad outputs' names as shown and selected: the file's symbols with control characters
/// escaped (a symbol is external text and must not drive the terminal), else `bN`.
fn aiger_names(aig: &Aig) -> Vec<String> {
    (0..aig.bad.len())
        .map(|i| match aig.bad_names.get(i).cloned().flatten() {
            Some(n) => crate::diag::escape_controls(&n).into_owned(),
            None => format!("b{i}"),
        })
        .collect()
}

/// Read an AIGER file.
pub fn load_aiger(path: &str) -> Result<Aig> {
    crate::outpath::note_input(path);
    let bytes = std::fs::read(path).with_context(|| format!("cannot read `{path}`"))?;
    statecheck_symbolic::aiger::parse(&bytes).map_err(|e| anyhow::anyhow!("{path}: {e}"))
}

/// The circuit of bad output `i`.
fn single(aig: &Aig, i: usize) -> Aig {
    let mut g = aig.clone();
    g.bad = vec![aig.bad[i]];
    g.bad_names = vec![aig.bad_names.get(i).cloned().flatten()];
    g.reduced()
}

/// Options of an AIGER run.
pub struct AigerRun<'a> {
    /// The file.
    pub path: &'a str,
    /// Properties to check (names or `bN`); all when empty.
    pub properties: &'a [String],
    /// The engine (`auto` and `explicit` mean IC3 with BMC alongside).
    pub engine: EngineArg,
    /// Time limit.
    pub timeout: Option<Duration>,
    /// Depth bound.
    pub depth: Option<u64>,
    /// JSON output.
    pub json: bool,
    /// Write the certificate here.
    pub certificate: Option<&'a str>,
    /// Check this certificate instead of verifying.
    pub check_certificate: Option<&'a str>,
}

/// `statecheck verify FILE.aag|FILE.aig`.
pub fn run_aiger(a: &AigerRun) -> Result<u8> {
    let aig = load_aiger(a.path)?;
    let names = aiger_names(&aig);
    let chosen: Vec<usize> = if a.properties.is_empty() {
        (0..names.len()).collect()
    } else {
        let mut v = Vec::new();
        for p in a.properties {
            match names.iter().position(|n| n == p) {
                Some(i) => v.push(i),
                None => bail!(
                    "no property named `{p}` in {}; the properties are: {}",
                    a.path,
                    names.join(", ")
                ),
            }
        }
        v
    };
    if let Some(cf) = a.check_certificate {
        let [i] = chosen.as_slice() else {
            bail!("--check-certificate needs exactly one property: choose it with --property");
        };
        return check_certificate(&single(&aig, *i), &names[*i], cf);
    }
    let engine = a.engine.symbolic().unwrap_or(Engine::Ic3);
    let mut rows = Vec::new();
    let mut invariants = Vec::new();
    let mut code = 0u8;
    for &i in &chosen {
        let g = single(&aig, i);
        let lim = limits(a.timeout, a.depth, None);
        let t = Instant::now();
        let out = if matches!(a.engine, EngineArg::Auto | EngineArg::Explicit) {
            race(&g, &lim)
        } else {
            (
                run_reduced(engine, &g, 0, &Reductions::new(1), &lim),
                engine.as_str(),
            )
        };
        let time = t.elapsed().as_secs_f64();
        let (verdict, depth, reason) = match &out.0 {
            Outcome::Reached(tr) => ("violated", tr.inputs.len(), None),
            Outcome::Proved(inv) => {
                if let Some(inv) = inv {
                    invariants.push((g.clone(), names[i].clone(), inv.clone()));
                }
                ("proved", 0, None)
            }
            Outcome::Bounded(k) => ("bounded", *k, None),
            Outcome::Unknown(why) => ("unknown", 0, Some(why.clone())),
        };
        code = match verdict {
            "violated" => 1,
            "unknown" if code == 0 => 3,
            _ => code,
        };
        rows.push((names[i].clone(), verdict, out.1, depth, time, reason));
    }
    if let Some(cf) = a.certificate {
        match invariants.as_slice() {
            [(g, name, inv)] => {
                let text = statecheck_symbolic::cert::write(g, name, inv);
                crate::outpath::write(std::path::Path::new(cf), text.as_bytes())?;
                eprintln!(
                    "wrote {cf}: inductive invariant of `{name}`, {} clause(s)",
                    inv.len()
                );
            }
            [] => bail!("no certificate written: no property was proved by IC3"),
            _ => bail!("--certificate needs exactly one property: choose it with --property"),
        }
    }
    if a.json {
        let results: Vec<serde_json::Value> = rows
            .iter()
            .map(|(n, v, e, d, t, r)| {
                let mut o = serde_json::json!({"property": n, "kind": "bad", "verdict": v,
                    "engine": e, "depth": d, "time_s": t, "counterexample": null});
                if let Some(r) = r {
                    o["reason"] = serde_json::json!(r);
                }
                o
            })
            .collect();
        let v = serde_json::json!({"results": results, "stats": {"inputs": aig.inputs.len(),
            "latches": aig.latches.len(), "ands": aig.num_ands(), "constraints": aig.constraints.len()}});
        crate::write_out(None, &format!("{v}\n"))?;
    } else {
        let w = rows.iter().map(|r| r.0.len()).max().unwrap_or(8).max(8);
        let mut out = format!(
            "{:<w$}  {:<9}  {:<6}  {:>5}  time\n",
            "property", "verdict", "engine", "depth"
        );
        for (n, v, e, d, t, r) in &rows {
            out.push_str(&format!(
                "{n:<w$}  {v:<9}  {e:<6}  {d:>5}  {t:.3} s{}\n",
                r.as_ref().map(|x| format!("  ({x})")).unwrap_or_default()
            ));
        }
        crate::write_out(None, &out)?;
    }
    Ok(code)
}

/// IC3, k-induction and BMC side by side on one circuit; the first definitive answer.
fn race(g: &Aig, lim: &Limits) -> (Outcome, &'static str) {
    let stop = Arc::new(AtomicBool::new(false));
    let mut l = lim.clone();
    l.stop = Some(Arc::clone(&stop));
    let reductions = Reductions::new(1);
    std::thread::scope(|s| {
        let (tx, rx) = mpsc::channel();
        for e in SYMBOLIC_RACE {
            let tx = tx.clone();
            let l = l.clone();
            let reductions = &reductions;
            s.spawn(move || {
                let _ = tx.send((run_reduced(e, g, 0, reductions, &l), e.as_str()));
            });
        }
        drop(tx);
        let mut last = (Outcome::Unknown("no engine answered".into()), "ic3");
        for (o, e) in rx.iter() {
            let def = matches!(o, Outcome::Reached(_) | Outcome::Proved(_));
            last = (o, e);
            if def {
                stop.store(true, Ordering::Relaxed);
                break;
            }
        }
        stop.store(true, Ordering::Relaxed);
        last
    })
}
