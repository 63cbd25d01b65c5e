//! What every engine answers, and the limits it runs under.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, RwLock};
use std::time::Instant;

/// A check of the process's memory limit: `probe(extra)` is true once the process has grown
/// past it, or would with `extra` more bytes (an allocation about to be made: the SAT
/// solver's tables doubled when its variables pass a power of two, see [`crate::sat`]).
/// Once it has answered true it must keep answering true (the run is being stopped).
pub type MemoryProbe = Arc<dyn Fn(u64) -> bool + Send + Sync>;

/// The process's memory probe, installed by the edge that owns `--max-memory` (the resident
/// set is the whole process's, and reading it is I/O, which this crate does not do).
static MEMORY_PROBE: RwLock<Option<MemoryProbe>> = RwLock::new(None);

/// Install (or, with `None`, remove) the process's memory probe. Every engine asks it
/// synchronously, on its own thread, wherever it asks its other limits: between BMC frames
/// and IC3 queries, and inside every SAT call through CaDiCaL's terminator. So a SAT engine
/// stops within one unit of its own work of the limit being passed, however late a watchdog
/// thread would be scheduled on a loaded machine. The probe should be cheap when called
/// often (it may answer from a reading a millisecond old).
pub fn set_memory_probe(probe: Option<MemoryProbe>) {
    // A poisoned lock holds a valid `Option`: a panic elsewhere cannot corrupt it.
    let mut g = MEMORY_PROBE.write().unwrap_or_else(|e| e.into_inner());
    *g = probe;
}

/// Has the process passed its memory limit (false without a probe)?
fn memory_exceeded() -> bool {
    memory_exceeded_by(0)
}

/// Would the process pass its memory limit with `extra` more bytes (false without a probe)?
/// A true answer stops the run with the memory limit as its reason.
pub(crate) fn memory_exceeded_by(extra: u64) -> bool {
    let probe = MEMORY_PROBE
        .read()
        .unwrap_or_else(|e| e.into_inner())
        .clone();
    probe.is_some_and(|p| p(extra))
}

/// The reason of an `unknown` when the memory probe stopped the engine.
pub const MEMORY_LIMIT: &str = "memory limit";

/// A trace of the circuit reaching its bad output.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Trace {
    /// Latch values in the first frame (their reset values, or a choice for uninitialized ones).
    pub init: Vec<bool>,
    /// Input values of each frame; the bad output holds in the last one.
    pub inputs: Vec<Vec<bool>>,
}

/// An inductive invariant: clauses over latches (`(latch index, polarity)`; a clause holds
/// when some latch has the given value).
pub type Invariant = Vec<Vec<(usize, bool)>>;

/// The answer of an engine.
#[derive(Clone, Debug)]
pub enum Outcome {
    /// The bad output is reachable.
    Reached(Trace),
    /// The bad output is unreachable; IC3 gives the inductive invariant it found.
    Proved(Option<Invariant>),
    /// No trace of at most this many frames reaches it (a depth bound stopped the search).
    Bounded(usize),
    /// A limit stopped the engine before it decided.
    Unknown {
        /// Which limit stopped it, or what failed.
        why: String,
        /// No trace of at most this many frames reaches the bad output: the depth the engine
        /// had cleared when it stopped (0 when it knows none).
        cleared: usize,
    },
}

impl Outcome {
    /// An `unknown` with no depth cleared.
    pub fn unknown(why: impl Into<String>) -> Outcome {
        Outcome::Unknown {
            why: why.into(),
            cleared: 0,
        }
    }

    /// An `unknown` after clearing `cleared` frames.
    pub fn unknown_after(why: impl Into<String>, cleared: usize) -> Outcome {
        Outcome::Unknown {
            why: why.into(),
            cleared,
        }
    }
}

/// The reason of an `unknown` when a SAT call gave no answer and no limit had expired.
pub const SOLVER_FAILED: &str = "the SAT solver failed";

/// Limits of a run.
#[derive(Clone, Debug, Default)]
pub struct Limits {
    /// Stop at this time.
    pub deadline: Option<Instant>,
    /// Stop this attempt at this time: a budget within the run (`--engine auto` gives each
    /// property growing slices). Work shared between attempts, such as a circuit reduction
    /// that is computed once, runs to [`Limits::deadline`] instead.
    pub attempt_deadline: Option<Instant>,
    /// Consider traces of at most this many frames.
    pub max_depth: Option<usize>,
    /// Stop when this flag is raised (another engine answered first).
    pub stop: Option<Arc<AtomicBool>>,
}

impl Limits {
    /// The same limits with the attempt ending at `until` at the latest.
    pub fn attempt_until(&self, until: Instant) -> Limits {
        Limits {
            attempt_deadline: Some(self.attempt_deadline.map_or(until, |d| d.min(until))),
            ..self.clone()
        }
    }

    /// The time until the earlier of the run's and the attempt's deadline (`None` without
    /// either).
    pub fn time_left(&self) -> Option<std::time::Duration> {
        [self.deadline, self.attempt_deadline]
            .into_iter()
            .flatten()
            .min()
            .map(|d| d.saturating_duration_since(Instant::now()))
    }

    /// The limits of work shared between attempts (no attempt budget).
    pub fn for_run(&self) -> Limits {
        Limits {
            attempt_deadline: None,
            ..self.clone()
        }
    }
}

impl Limits {
    /// Why the engine must stop now, if it must.
    pub fn expired(&self) -> Option<String> {
        if self.attempt_deadline.is_some_and(|d| Instant::now() >= d) {
            return Some("time budget of this attempt used up".into());
        }
        self.run_expired()
    }

    /// Why a SAT call answered "unknown": the limit that interrupted it (CaDiCaL's
    /// terminator asks these limits inside the call, so a deadline, an attempt budget or a
    /// stop flag raised by the memory watchdog ends the call this way), or, when no limit has
    /// expired, a failure of the solver itself.
    pub fn why_interrupted(&self) -> String {
        self.expired().unwrap_or_else(|| SOLVER_FAILED.to_string())
    }

    /// Why work shared between attempts must stop now: the stop flag or the run's deadline.
    pub fn run_expired(&self) -> Option<String> {
        if self
            .stop
            .as_ref()
            .is_some_and(|s| s.load(Ordering::Relaxed))
        {
            return Some("another engine answered first".into());
        }
        if memory_exceeded() {
            return Some(MEMORY_LIMIT.into());
        }
        match self.deadline {
            Some(d) if Instant::now() >= d => Some("time limit reached".into()),
            _ => None,
        }
    }
}
