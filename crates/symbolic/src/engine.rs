//! What every engine answers, and the limits it runs under.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Instant;

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
    /// A limit stopped the engine; the text says which.
    Unknown(String),
}

/// Limits of a run.
#[derive(Clone, Debug, Default)]
pub struct Limits {
    /// Stop at this time.
    pub deadline: Option<Instant>,
    /// Consider traces of at most this many frames.
    pub max_depth: Option<usize>,
    /// Stop when this flag is raised (another engine answered first).
    pub stop: Option<Arc<AtomicBool>>,
}

impl Limits {
    /// Why the engine must stop now, if it must.
    pub fn expired(&self) -> Option<String> {
        if self
            .stop
            .as_ref()
            .is_some_and(|s| s.load(Ordering::Relaxed))
        {
            return Some("another engine answered first".into());
        }
        match self.deadline {
            Some(d) if Instant::now() >= d => Some("time limit reached".into()),
            _ => None,
        }
    }
}
