//! Sessions kept for a while after their page went away, so that a browser reload (or a
//! dropped connection) resumes the run: each session has a random resume key, sent in its
//! hello; the page keeps it in `sessionStorage` and presents it when it connects again.
//! Bounded: at most [`PARK_MAX`] sessions, each for at most [`PARK_TTL`] (the oldest go first).

use crate::session::Session;
use std::collections::VecDeque;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Most sessions kept after their page closed.
pub const PARK_MAX: usize = 32;
/// How long a closed page's session is kept.
pub const PARK_TTL: Duration = Duration::from_secs(600);

/// The sessions whose pages went away, oldest first.
#[derive(Default)]
pub struct Parking {
    kept: Mutex<VecDeque<(String, Instant, Session)>>,
}

impl Parking {
    /// Keep `session` under `key`, dropping expired sessions and the oldest beyond the bound.
    pub fn park(&self, key: String, session: Session) {
        let mut kept = self.kept.lock().unwrap_or_else(|e| e.into_inner());
        let now = Instant::now();
        kept.retain(|(_, at, _)| now.duration_since(*at) < PARK_TTL);
        kept.push_back((key, now, session));
        while kept.len() > PARK_MAX {
            kept.pop_front();
        }
    }

    /// Take the session kept under `key`, if it has not expired.
    pub fn take(&self, key: &str) -> Option<Session> {
        let mut kept = self.kept.lock().unwrap_or_else(|e| e.into_inner());
        let now = Instant::now();
        kept.retain(|(_, at, _)| now.duration_since(*at) < PARK_TTL);
        let i = kept.iter().position(|(k, _, _)| k == key)?;
        kept.remove(i).map(|(_, _, s)| s)
    }

    /// How many sessions are kept.
    pub fn len(&self) -> usize {
        self.kept.lock().unwrap_or_else(|e| e.into_inner()).len()
    }

    /// True when none is kept.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}
