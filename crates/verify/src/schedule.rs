//! The fair schedule of one SAT engine over many properties: passes with growing budgets per
//! property (1 s, then 10 s, then a fair share of the time left), so that one hard property
//! never starves the easy ones behind it, capped by the per-property budget.

use crate::{Event, REASON_PROPERTY_LIMIT, REASON_TIME_LIMIT};
use statecheck_ir::verdict::{PropKind, Verdict};
use statecheck_ir::Program;
use statecheck_symbolic::blast::Blasted;
use statecheck_symbolic::check::{decide, Engine, Reductions, SymResult};
use statecheck_symbolic::engine::Limits;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// The budgets of the first passes; the last pass gives each property still undecided its
/// share of the time left.
const FIRST_PASSES: [Duration; 2] = [Duration::from_secs(1), Duration::from_secs(10)];

/// What one engine works on and within which limits.
pub(crate) struct Work<'a> {
    pub program: &'a Program,
    pub blasted: &'a Blasted,
    /// Per result: the property's index in `blasted` and its kind.
    pub idx: &'a [(usize, PropKind)],
    pub engine: Engine,
    /// The end of the whole run.
    pub deadline: Option<Instant>,
    pub max_depth: Option<usize>,
    pub property_timeout: Option<Duration>,
    /// Per result: raised once it is decided (or the run ends); the engine then skips it
    /// and abandons an attempt on it.
    pub flags: &'a [Arc<AtomicBool>],
    /// Raised when the run ends.
    pub stop: &'a AtomicBool,
    pub reductions: &'a Reductions,
    /// Whether the engine takes the last pass, open-ended (a share of the time left) after
    /// the fixed budgets; `false` leaves it to the other engines of a portfolio.
    pub open_ended: bool,
}

/// A result that is final for its engine: definitive, or bounded at the depth asked for.
pub(crate) fn settled(s: &SymResult) -> bool {
    s.result.verdict.is_definitive() || s.result.verdict == Verdict::Bounded
}

/// What the attempts on one property cleared and cost, whether or not they decided it.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Tried {
    /// The deepest depth an attempt cleared: no trace of at most this many ticks violates
    /// the property (or reaches its target).
    pub depth: u64,
    /// The time of all attempts on it.
    pub time: Duration,
}

impl Tried {
    /// Count attempt `s` in, and give `s` the statistics of all attempts so far when it is
    /// `unknown` (so an undecided row shows the deepest depth any pass cleared).
    fn add(&mut self, s: &mut SymResult) {
        self.time += s.time;
        if s.result.verdict == Verdict::Unknown {
            self.depth = self.depth.max(s.result.depth);
            s.result.depth = self.depth;
            s.time = self.time;
        }
    }
}

/// Run `w.engine` over the properties in `order`, pass after pass; `found(i, result)` gets
/// every settled result and, in the last pass, every other one (its budget ran out), an
/// `unknown` with the deepest depth and the time of all attempts on it. Returns those
/// statistics per property, for the rows the run's end leaves unreported.
pub(crate) fn run(
    w: &Work,
    order: &[usize],
    events: &(dyn Fn(Event) + Sync),
    found: &mut dyn FnMut(usize, SymResult),
) -> Vec<Tried> {
    let mut tried = vec![Tried::default(); w.flags.len()];
    let pt = w.property_timeout;
    let mut budgets: Vec<Option<Duration>> = FIRST_PASSES
        .iter()
        .filter(|&&b| pt.is_none_or(|pt| b < pt))
        .map(|&b| Some(b))
        .collect();
    if w.open_ended || budgets.is_empty() {
        budgets.push(None);
    }
    let name = w.engine.as_str();
    for (pass, budget) in budgets.iter().enumerate() {
        let last = pass + 1 == budgets.len();
        for (pos, &i) in order.iter().enumerate() {
            if w.flags[i].load(Ordering::Relaxed) {
                continue;
            }
            let now = Instant::now();
            if w.stop.load(Ordering::Relaxed) || w.deadline.is_some_and(|d| now >= d) {
                events(Event::Idle { engine: name });
                return tried;
            }
            // The last pass: an equal share of the time left for each property still open
            // in this pass (a property that finishes early leaves its time to the others).
            let share = match (budget, w.deadline) {
                (Some(b), _) => Some(*b),
                (None, Some(d)) => {
                    let open = order[pos..]
                        .iter()
                        .filter(|&&j| !w.flags[j].load(Ordering::Relaxed))
                        .count()
                        .max(1) as u32;
                    Some(d.saturating_duration_since(now) / open)
                }
                (None, None) => None,
            };
            let budget = match (share, pt) {
                (Some(s), Some(p)) => Some(s.min(p)),
                (s, p) => s.or(p),
            };
            events(Event::Working {
                engine: name,
                index: i,
                budget,
            });
            let (pi, kind) = w.idx[i];
            let lim = Limits {
                deadline: w.deadline,
                attempt_deadline: budget.map(|b| now + b),
                max_depth: w.max_depth,
                stop: Some(Arc::clone(&w.flags[i])),
            };
            let mut s = decide(w.program, w.blasted, pi, kind, w.engine, &lim, w.reductions);
            tried[i].add(&mut s);
            if settled(&s) {
                found(i, s);
            } else if last {
                let out_of_time = w.deadline.is_some_and(|d| Instant::now() >= d);
                if s.result.verdict == Verdict::Unknown {
                    s.reason = Some(
                        if out_of_time {
                            REASON_TIME_LIMIT
                        } else if pt.is_some() {
                            REASON_PROPERTY_LIMIT
                        } else {
                            s.reason.as_deref().unwrap_or(REASON_TIME_LIMIT)
                        }
                        .to_string(),
                    );
                }
                found(i, s);
            }
        }
    }
    events(Event::Idle { engine: name });
    tried
}

#[cfg(test)]
mod tests {
    use super::*;
    use statecheck_ir::verdict::PropResult;

    fn attempt(verdict: Verdict, depth: u64, secs: u64) -> SymResult {
        SymResult {
            result: PropResult {
                verdict,
                depth,
                ..PropResult::unknown("p", PropKind::Invariant)
            },
            invariant: None,
            time: Duration::from_secs(secs),
            reason: None,
        }
    }

    #[test]
    fn an_unknown_row_shows_the_deepest_pass_and_the_time_of_all() {
        let mut t = Tried::default();
        // A 1 s pass cleared 7 ticks; a longer one, restarted, was stopped at 5.
        let mut first = attempt(Verdict::Unknown, 7, 1);
        t.add(&mut first);
        assert_eq!(
            (first.result.depth, first.time),
            (7, Duration::from_secs(1))
        );
        let mut second = attempt(Verdict::Unknown, 5, 10);
        t.add(&mut second);
        assert_eq!(
            (second.result.depth, second.time),
            (7, Duration::from_secs(11))
        );
        // A verdict keeps its own depth and time (a counterexample's length is not a bound).
        let mut third = attempt(Verdict::Violated, 3, 2);
        t.add(&mut third);
        assert_eq!(
            (third.result.depth, third.time),
            (3, Duration::from_secs(2))
        );
        assert_eq!((t.depth, t.time), (7, Duration::from_secs(13)));
    }
}
