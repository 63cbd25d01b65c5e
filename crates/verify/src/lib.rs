//! The verification portfolio: one entry point, [`verify`], that the CLI and the web studio
//! call to decide a program's properties with one engine or several side by side.
//!
//! The engines themselves (`statecheck-explicit`, `statecheck-symbolic`) know nothing of each
//! other; this crate races them ([`Engine::Auto`]), gives each property its budget, cancels the
//! engines that lost, and reports every verdict through the caller's [`Event`] callback the
//! moment it is decided, before the run ends.

mod cancel;
mod circuit;
mod error;
mod portfolio;
mod priority;
mod quick;
mod schedule;
mod shared_bmc;
mod single;
mod symmetry;
mod temporal;

pub use cancel::{Cancel, CancelReason};
pub use circuit::{decide_circuit, race, race_justice};
pub use error::{Error, ErrorKind};
pub use statecheck_explicit::{Options as ExplicitOptions, Progress, Report, Stats};
pub use statecheck_ir::verdict::{PropKind, PropResult, Verdict};
pub use temporal::row_names;

use statecheck_ir::Program;
use statecheck_symbolic::aig::Aig;
use statecheck_symbolic::engine::Invariant;

/// The depth bound of [`Engine::Bmc`] without a depth option.
pub const DEFAULT_BMC_DEPTH: u64 = 100;

/// Which engine decides the properties.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Engine {
    /// Explicit-state breadth-first search.
    Explicit,
    /// Bounded model checking (shortest counterexamples; no proofs).
    Bmc,
    /// k-induction with simple-path constraints.
    Kind,
    /// IC3/PDR (proofs with an inductive invariant).
    Ic3,
    /// IC3 on localization abstractions refined by counterexamples (`statecheck_symbolic::
    /// localize`): the same answers as IC3, for properties that depend on a small part of a
    /// large circuit.
    Cegar,
    /// Explicit and SAT engines side by side; the first definitive verdict wins.
    Auto,
}

impl Engine {
    /// The option word and the `engine` field of a result.
    pub fn as_str(self) -> &'static str {
        match self {
            Engine::Explicit => "explicit",
            Engine::Bmc => "bmc",
            Engine::Kind => "kind",
            Engine::Ic3 => "ic3",
            Engine::Cegar => "cegar",
            Engine::Auto => "auto",
        }
    }

    /// Every engine, in the order a user is offered them (the portfolio first).
    pub const ALL: [Engine; 6] = [
        Engine::Auto,
        Engine::Explicit,
        Engine::Bmc,
        Engine::Kind,
        Engine::Ic3,
        Engine::Cegar,
    ];

    /// The engine whose option word is `name` (the inverse of [`Engine::as_str`]).
    pub fn from_name(name: &str) -> Option<Engine> {
        Engine::ALL.into_iter().find(|e| e.as_str() == name)
    }

    /// The option words of every engine, comma-separated (for an error message).
    pub fn names() -> String {
        Engine::ALL.map(Engine::as_str).join(", ")
    }

    /// The SAT engine, for the four that are one.
    pub fn symbolic(self) -> Option<statecheck_symbolic::check::Engine> {
        use statecheck_symbolic::check::Engine as S;
        match self {
            Engine::Bmc => Some(S::Bmc),
            Engine::Kind => Some(S::Kind),
            Engine::Ic3 => Some(S::Ic3),
            Engine::Cegar => Some(S::Cegar),
            Engine::Explicit | Engine::Auto => None,
        }
    }
}

/// Options of a run.
#[derive(Clone, Debug)]
pub struct Options {
    /// The engine.
    pub engine: Engine,
    /// Properties, limits and threads (the explicit engine's options; the SAT engines read
    /// the properties, depth and timeout). `check.timeout` is the total for the run.
    pub check: ExplicitOptions,
    /// The most each SAT engine spends on one property (the explicit engine explores for
    /// all properties at once and has only the total).
    pub property_timeout: Option<std::time::Duration>,
    /// Raised from outside to end the run: the verdicts decided so far are kept and the rest
    /// are `unknown` with the cancellation's reason.
    pub cancel: Option<Cancel>,
}

impl Options {
    /// Options for `engine` with the explicit engine's options `check` and no per-property
    /// budget or cancellation.
    pub fn new(engine: Engine, check: ExplicitOptions) -> Options {
        Options {
            engine,
            check,
            property_timeout: None,
            cancel: None,
        }
    }
}

/// The reason given for a property left `unknown` when the run ended early.
pub const REASON_TIME_LIMIT: &str = "time limit";
/// The reason given for a property whose own budget (`property_timeout`) ran out.
pub const REASON_PROPERTY_LIMIT: &str = "property time limit";

/// Which engine decided a result, how long it took, and why it is `unknown`.
#[derive(Clone, Debug, Default)]
pub struct Meta {
    /// `explicit`, `bmc`, `kind`, `ic3`, `klive` (k-liveness), `sim` (the lasso hunt of a
    /// temporal row), or `auto` when no engine answered.
    pub engine: &'static str,
    /// Seconds spent on this property (`None`: the explicit engine's run time, shared by all).
    pub time_s: Option<f64>,
    /// Why the verdict is `unknown`.
    pub reason: Option<String>,
    /// With [`Engine::Auto`]: seconds from the start of the run to the verdict (the engines
    /// run side by side, so this, not `time_s`, is when the user had the answer).
    pub decided_at_s: Option<f64>,
    /// With symmetry reduction (`ExplicitOptions::symmetry`): the family member whose SAT
    /// check answered this row too (`a[0].p` for `a[2].p`); the counterexample is that
    /// member's with the two elements exchanged (docs/verification.md, "Symmetry reduction").
    pub symmetry_of: Option<String>,
}

/// Something that happened during a run, reported as it happens.
#[derive(Debug)]
#[non_exhaustive]
pub enum Event<'a> {
    /// Property `index` (of the run's selection, in report order) is decided: definitive, or
    /// final for its engine.
    Decided {
        /// Index into the run's results.
        index: usize,
        /// The result.
        result: &'a PropResult,
        /// Its engine and times.
        meta: &'a Meta,
    },
    /// The explicit engine's exploration progressed.
    Progress(&'a Progress),
    /// A SAT engine started on property `index` with this budget.
    Working {
        /// `bmc`, `kind` or `ic3`.
        engine: &'static str,
        /// Index into the run's results.
        index: usize,
        /// Its budget for this attempt (`None`: until the run ends).
        budget: Option<std::time::Duration>,
    },
    /// A SAT engine has nothing left to do.
    Idle {
        /// `bmc`, `kind` or `ic3`.
        engine: &'static str,
    },
}

/// The outcome of [`verify`].
#[derive(Clone, Debug)]
pub struct Run {
    /// One result per selected property (report order) and the statistics (the explicit
    /// engine's when it ran to the end, else the program's sizes only).
    pub report: Report,
    /// Engine, time and reason per result.
    pub meta: Vec<Meta>,
    /// IC3 invariants per result, with their circuits.
    pub invariants: Vec<Option<(Aig, Invariant)>>,
}

/// Decide the selected properties of `program` as `opts` says, calling `events` as verdicts
/// are decided and as the exploration progresses (from any thread).
pub fn verify(
    program: &Program,
    opts: &Options,
    events: &(dyn Fn(Event) + Sync),
) -> Result<Run, Error> {
    // Temporal rows (`ltl`, `ctl`, `nonblocking`, unbounded `respond`, `deadlock_free`) are
    // raced between the explicit engine and the SAT engines' liveness checks, or decided by
    // the one SAT engine asked for (`temporal.rs`).
    let (temporal, _) = statecheck_explicit::ltl::split(program, &opts.check.properties);
    let temporal = !program.temporal.is_empty() || !temporal.is_empty();
    let started = std::time::Instant::now();
    if opts.engine == Engine::Auto {
        if let Some(run) = quick::quick_race(program, opts, temporal, events) {
            return Ok(run);
        }
    }
    // The quick pass's time counts against `--timeout`.
    let rest;
    let opts = match opts.check.timeout {
        Some(t) if opts.engine == Engine::Auto => {
            let mut o = opts.clone();
            o.check.timeout = Some(t.saturating_sub(started.elapsed()));
            rest = o;
            &rest
        }
        _ => opts,
    };
    let mut run = match (opts.engine, opts.engine.symbolic()) {
        (Engine::Explicit, _) => single::run_explicit(program, opts, events),
        _ if temporal => temporal::run(program, opts, events),
        (_, Some(e)) => single::run_engine(program, opts, e, events),
        _ => portfolio::run_auto(program, opts, events, started),
    }?;
    // A run the memory watchdog stopped hit the memory limit, whatever engine noticed first.
    let by_memory = opts
        .cancel
        .as_ref()
        .is_some_and(|c| c.reason() == Some(CancelReason::Memory));
    if by_memory {
        if let Some(max) = opts.check.max_memory {
            let stats = &mut run.report.stats;
            if matches!(
                stats.limit,
                None | Some(statecheck_explicit::Limit::Stopped)
            ) {
                stats.limit = Some(statecheck_explicit::Limit::Memory(max));
            }
        }
    }
    Ok(run)
}
