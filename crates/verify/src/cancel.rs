//! Ending a run from outside (Ctrl-C, a memory watchdog): one flag every engine polls, and the
//! reason the `unknown` rows give.

use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};
use std::sync::Arc;

/// Why a run was cancelled.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum CancelReason {
    /// The user interrupted the run (SIGINT).
    Interrupted,
    /// The process grew past its memory limit.
    Memory,
}

impl CancelReason {
    /// The `reason` of the rows left `unknown`.
    pub fn as_str(self) -> &'static str {
        match self {
            CancelReason::Interrupted => "interrupted",
            CancelReason::Memory => "memory limit",
        }
    }
}

/// A cancellation handle: cheap to clone, raised from any thread (a signal handler's thread
/// included), polled by the engines between units of work.
#[derive(Clone, Debug, Default)]
pub struct Cancel {
    flag: Arc<AtomicBool>,
    reason: Arc<AtomicU8>,
}

impl Cancel {
    /// A handle not yet raised.
    pub fn new() -> Cancel {
        Cancel::default()
    }

    /// End the run for `why` (the first reason given is kept).
    pub fn raise(&self, why: CancelReason) {
        let code = match why {
            CancelReason::Interrupted => 1,
            CancelReason::Memory => 2,
        };
        let _ = self
            .reason
            .compare_exchange(0, code, Ordering::SeqCst, Ordering::SeqCst);
        self.flag.store(true, Ordering::SeqCst);
    }

    /// Why the run was cancelled, if it was.
    pub fn reason(&self) -> Option<CancelReason> {
        if !self.flag.load(Ordering::SeqCst) {
            return None;
        }
        match self.reason.load(Ordering::SeqCst) {
            2 => Some(CancelReason::Memory),
            _ => Some(CancelReason::Interrupted),
        }
    }

    /// The flag the engines poll (raised with the handle).
    pub fn flag(&self) -> Arc<AtomicBool> {
        Arc::clone(&self.flag)
    }
}
