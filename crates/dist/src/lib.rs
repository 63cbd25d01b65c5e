//! Distributed explicit-state exploration on [timely dataflow](https://docs.rs/timely).
//!
//! The same transition system as `statecheck-explicit` (the closed system of a [`Program`],
//! every input vector the `assume`s allow, one tick of the IR each), explored breadth-first
//! by many workers — threads of one process, or of several processes on several hosts, as
//! timely arranges them (`Config::Cluster`: one `host:port` per process). Each state belongs
//! to one worker, chosen by a hash of its packed form; each worker stores the states it owns
//! with the transition that found each (source worker, source index, input), expands the
//! states it found in the last layer and sends every successor to its owner. A layer ends
//! when timely's progress tracking says every successor of the layer has arrived; the workers
//! then exchange their counts and findings, so all of them take the same decisions (go on,
//! stop at a limit, every property decided). Counterexamples are rebuilt by walking the parent
//! links back, one exchange per tick, from the source of the deciding transition to the
//! initial state.
//!
//! Properties are checked on every transition by the explicit engine's reading of their goals
//! ([`Spec::decided_by`], [`Spec::builtin`]), so verdicts, state and transition counts and
//! counterexample lengths are those of [`statecheck_explicit::verify`]. Temporal properties
//! (`ltl`, `ctl`, `nonblocking`, `fair`, `deadlock_free`) are not checked here: they are
//! reported `unknown` with the reason.

mod comm;
mod connect;
mod expand;
mod search;
mod store;
mod trace;

pub use statecheck_explicit::{Limit, PropResult, Report, Stats, Verdict};

use statecheck_explicit::props::{PropKind, Spec};
use statecheck_ir::temporal::Written;
use statecheck_ir::Program;
use std::sync::atomic::AtomicU64;
use std::sync::Arc;

/// Options of a distributed run.
#[derive(Clone, Debug)]
pub struct Options {
    /// The explicit engine's options: properties, depth, limits, stop flag. `max_memory` and
    /// `max_states` are per process; `threads`, `backend` and `compiler` are not used.
    pub check: statecheck_explicit::Options,
    /// Worker threads in this process (at least 1).
    pub workers: usize,
    /// `host:port` of every process, in process order; empty for a single process.
    pub hosts: Vec<String>,
    /// This process's position in `hosts`.
    pub process: usize,
}

/// What the distribution cost.
#[derive(Clone, Debug, Default)]
pub struct DistStats {
    /// Workers in all processes.
    pub workers: usize,
    /// Processes.
    pub processes: usize,
    /// Bytes of successor records sent from one worker to another (not to itself).
    pub exchange_bytes: u64,
    /// Bytes of the per-layer and counterexample messages between workers.
    pub control_bytes: u64,
    /// States stored by each worker, in worker order.
    pub worker_states: Vec<u64>,
    /// Largest memory estimate of each process, in process order.
    pub process_peak_bytes: Vec<u64>,
    /// Exchange rounds (two per layer, one per tick of the longest counterexample).
    pub rounds: u64,
}

impl DistStats {
    /// Bytes exchanged between workers per stored state.
    pub fn bytes_per_state(&self, states: u64) -> f64 {
        (self.exchange_bytes + self.control_bytes) as f64 / states.max(1) as f64
    }
}

/// The outcome of [`verify`]: the explicit engine's report, and the distribution's figures.
#[derive(Clone, Debug)]
pub struct DistReport {
    /// Results (system properties in declaration order, built-ins, then temporal ones) and
    /// statistics, as [`statecheck_explicit::verify`] gives them.
    pub report: Report,
    /// Communication and per-worker figures.
    pub dist: DistStats,
}

/// Why a run could not be made.
#[derive(Debug)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
}

/// The kinds of [`Error`].
#[derive(Debug)]
#[non_exhaustive]
pub enum ErrorKind {
    /// A property name that the system does not have.
    UnknownProperty(String),
    /// Bad options (no workers, a process index outside the host list).
    Options(String),
    /// Timely could not set up its workers or connections.
    Network(String),
    /// A worker stopped without a result.
    Worker(String),
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.kind {
            ErrorKind::UnknownProperty(m) | ErrorKind::Options(m) => write!(f, "{m}"),
            ErrorKind::Network(m) => write!(f, "distributed run not started: {m}"),
            ErrorKind::Worker(m) => write!(f, "a worker of the distributed run failed: {m}"),
        }
    }
}

impl std::error::Error for Error {}

/// Without a time limit, how long a process waits for the others to connect.
pub const CONNECT_TIMEOUT: std::time::Duration = std::time::Duration::from_secs(120);

/// What every worker of a process shares.
pub(crate) struct Shared {
    pub program: Program,
    pub opts: statecheck_explicit::Options,
    /// The safety properties checked.
    pub specs: Vec<Spec>,
    /// Workers per process.
    pub per_process: usize,
    /// Each local worker's current memory estimate (their sum is the process's).
    pub meter: Vec<AtomicU64>,
    pub start: std::time::Instant,
}

/// Verify `program`'s properties with workers in this process and, with `opts.hosts`, in the
/// other processes (each started with the same model and options and its own
/// `opts.process`). Every process returns the same report.
pub fn verify(program: &Program, opts: &Options) -> Result<DistReport, Error> {
    let start = std::time::Instant::now();
    let bad = |m: String| Error {
        kind: ErrorKind::Options(m),
    };
    if opts.workers == 0 {
        return Err(bad("--workers must be at least 1".into()));
    }
    if !opts.hosts.is_empty() && opts.process >= opts.hosts.len() {
        return Err(bad(format!(
            "--process {} is not below the {} host(s) of the host file",
            opts.process,
            opts.hosts.len()
        )));
    }
    let names = &opts.check.properties;
    let (temporal, safety) = statecheck_explicit::ltl::split(program, names);
    let specs = if safety.is_empty() && !temporal.is_empty() {
        Vec::new()
    } else {
        statecheck_explicit::props::select(program, &safety).map_err(|e| Error {
            kind: ErrorKind::UnknownProperty(e.to_string()),
        })?
    };
    let shared = Arc::new(Shared {
        program: program.clone(),
        opts: opts.check.clone(),
        specs,
        per_process: opts.workers,
        meter: (0..opts.workers).map(|_| AtomicU64::new(0)).collect(),
        start,
    });
    let sh = Arc::clone(&shared);
    let net = |e: String| Error {
        kind: ErrorKind::Network(e),
    };
    let worker = timely::WorkerConfig::default();
    let run = move |w: &mut timely::worker::Worker| search::run(w, &sh);
    let guards = if opts.hosts.is_empty() {
        let config = timely::Config {
            communication: timely::CommunicationConfig::Process(opts.workers),
            worker,
        };
        timely::execute(config, run).map_err(net)?
    } else {
        // The other processes get the run's time limit to connect, or CONNECT_TIMEOUT.
        let deadline = start + opts.check.timeout.unwrap_or(CONNECT_TIMEOUT);
        let (builders, guard) =
            connect::allocators(&opts.hosts, opts.process, opts.workers, deadline).map_err(net)?;
        timely::execute::execute_from(builders, guard, worker, run).map_err(net)?
    };
    let mut first = None;
    for r in guards.join() {
        let out = r.map_err(|e| Error {
            kind: ErrorKind::Worker(e),
        })?;
        first.get_or_insert(out);
    }
    let mut out = first.ok_or_else(|| Error {
        kind: ErrorKind::Worker("no worker ran".into()),
    })?;
    if opts.check.properties.is_empty() || !temporal.is_empty() {
        let sel = (!opts.check.properties.is_empty()).then_some(temporal.as_slice());
        out.report.results.extend(temporal_rows(program, sel));
    }
    Ok(out)
}

/// The temporal properties' rows (as the explicit engine orders them), all `unknown`.
fn temporal_rows(program: &Program, selected: Option<&[String]>) -> Vec<PropResult> {
    let why = "temporal properties are not checked by the distributed engine (--workers); \
               verify them without --workers";
    let props: Vec<_> = program
        .temporal
        .iter()
        .filter(|t| selected.is_none_or(|s| s.contains(&t.name)))
        .collect();
    let deadlock_free = statecheck_explicit::ltl::DEADLOCK_FREE;
    let deadlock = match selected {
        None => !props.is_empty(),
        Some(s) => s.iter().any(|n| n == deadlock_free),
    };
    let mut rows: Vec<PropResult> = props
        .iter()
        .map(|t| {
            let kind = match t.written {
                Written::Ltl => PropKind::Ltl,
                Written::Respond => PropKind::Respond,
                Written::Ctl => PropKind::Ctl,
                Written::Nonblocking => PropKind::Nonblocking,
            };
            PropResult::unknown(&t.name, kind)
        })
        .collect();
    if deadlock {
        rows.push(PropResult::unknown(deadlock_free, PropKind::Builtin));
    }
    for r in &mut rows {
        r.note = Some(why.to_string());
    }
    rows
}
