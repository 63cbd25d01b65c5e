//! Resource limits an engine polls while it works: a state count, an estimate of its own
//! memory, a deadline and a stop flag that another thread may set (the CLI's watchdog sets it
//! when the process's resident memory passes `--max-memory`).

use crate::error::{Error, ErrorKind, Limit, Partial};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Limits on one synthesis run; the default has none.
#[derive(Clone, Debug, Default)]
pub struct Limits {
    /// Stop once the explicit engine has enumerated more product states than this.
    pub max_states: Option<u64>,
    /// Stop once the engine's estimate of its data passes this many bytes.
    pub max_bytes: Option<u64>,
    /// Stop after this much time.
    pub timeout: Option<Duration>,
    /// Stop when this flag becomes true.
    pub stop: Option<Arc<AtomicBool>>,
}

/// A running budget: the limits and the start time.
#[derive(Clone, Debug)]
pub struct Budget {
    limits: Limits,
    start: Instant,
}

impl Budget {
    /// Start the clock on `limits`.
    pub fn new(limits: &Limits) -> Budget {
        Budget {
            limits: limits.clone(),
            start: Instant::now(),
        }
    }

    /// Seconds since the start.
    pub fn seconds(&self) -> f64 {
        self.start.elapsed().as_secs_f64()
    }

    /// `Err` if a limit is passed: `states` product states and about `bytes` bytes so far.
    pub fn check(&self, phase: &'static str, states: f64, bytes: u64) -> Result<(), Error> {
        let limit = if let Some(m) = self.limits.max_states.filter(|m| states > *m as f64) {
            Some(Limit::States(m))
        } else if let Some(m) = self.limits.max_bytes.filter(|m| bytes > *m) {
            Some(Limit::Memory(m))
        } else if self
            .limits
            .timeout
            .is_some_and(|t| self.start.elapsed() > t)
        {
            Some(Limit::Time)
        } else if self
            .limits
            .stop
            .as_ref()
            .is_some_and(|s| s.load(Ordering::Relaxed))
        {
            Some(Limit::Stopped)
        } else {
            None
        };
        match limit {
            None => Ok(()),
            Some(limit) => Err(Error::new(ErrorKind::Limit {
                limit,
                partial: Partial {
                    phase,
                    states,
                    seconds: self.seconds(),
                    bytes,
                },
            })),
        }
    }
}
