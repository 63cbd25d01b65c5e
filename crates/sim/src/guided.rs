//! Coverage-guided random inputs (`sim --random N --guided`): each tick, among candidate input
//! vectors that satisfy the `assume`s, prefer one whose one-tick successor enters a state or
//! fires a transition that the run has not covered yet.
//!
//! The successor of a candidate is computed by stepping a scratch [`Machine`] from the current
//! state — the IR's own step, nothing re-decided here — and reading which coverage counters
//! moved. The candidates are every input vector the `assume`s allow when there are few
//! ([`MAX_LISTED`]), otherwise the tick's ordinary draw, [`EXTRA_DRAWS`] more draws and the
//! ordinary draw with each boolean input flipped (so a rare input is tried every tick).
//! When no candidate covers anything new, the ordinary draw is kept: the run then has the
//! distribution of an unguided one, rates included.

use statecheck_ir::{CoverKind, Machine, Program};

/// Most vectors in a tick for every one to be tried as a candidate.
pub const MAX_LISTED: usize = 512;

/// Draws besides the ordinary one when the vectors are not listed.
pub const EXTRA_DRAWS: usize = 8;

/// Which coverage items a run has covered, and what a candidate would add.
pub(crate) struct Guide {
    covered: Vec<bool>,
    /// Per coverage item: its weight in a candidate's score (a state entry counts more than a
    /// transition firing, since state coverage is what a user reads first).
    weight: Vec<u32>,
    candidates: Vec<i64>,
    buf: Vec<i64>,
}

impl Guide {
    pub(crate) fn new(p: &Program) -> Guide {
        Guide {
            covered: vec![false; p.covers.len()],
            weight: p
                .covers
                .iter()
                .map(|c| match c.kind {
                    _ if c.expected_unreached => 0,
                    CoverKind::State(_) => 4,
                    _ => 1,
                })
                .collect(),
            candidates: Vec::new(),
            buf: Vec::new(),
        }
    }

    /// The candidates of one tick, flat (`w` values each), the ordinary draw first.
    pub(crate) fn candidates_mut(&mut self) -> &mut Vec<i64> {
        &mut self.candidates
    }

    /// Among the candidates, the index of the one that covers most that is new (the first
    /// such, so the ordinary draw wins ties), and record what it covers; `0` when none adds
    /// anything.
    pub(crate) fn choose(&mut self, m: &Machine, w: usize) -> usize {
        let p = m.program();
        let mut scratch = Machine::new(p);
        scratch.enable_coverage();
        let n = self.candidates.len().checked_div(w).unwrap_or(1);
        let (mut best, mut best_score) = (0, 0u64);
        for i in 0..n {
            self.buf.clear();
            self.buf
                .extend_from_slice(&self.candidates[i * w..i * w + w]);
            scratch.load(m.state(), &self.buf);
            scratch.clear_coverage();
            if scratch.step().is_err() {
                continue;
            }
            let hits = scratch.coverage().unwrap_or(&[]);
            let score = self.score(hits);
            if score > best_score {
                (best, best_score) = (i, score);
            }
        }
        // Record what the chosen vector covers (the real step will do exactly this).
        self.buf.clear();
        self.buf
            .extend_from_slice(&self.candidates[best * w..best * w + w]);
        scratch.load(m.state(), &self.buf);
        scratch.clear_coverage();
        if scratch.step().is_ok() {
            if let Some(c) = scratch.coverage() {
                for (k, &x) in c.iter().enumerate() {
                    if x > 0 {
                        self.covered[k] = true;
                    }
                }
            }
        }
        best
    }

    fn score(&self, counts: &[u64]) -> u64 {
        counts
            .iter()
            .zip(&self.covered)
            .zip(&self.weight)
            .filter(|((&c, &done), _)| c > 0 && !done)
            .map(|(_, &w)| u64::from(w))
            .sum()
    }
}
