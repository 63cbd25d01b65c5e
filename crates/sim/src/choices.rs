//! Runs for every sequence of discrete choices up to a bound (`statecheck analyse --depth`,
//! docs/hybrid.md).
//!
//! A *choice* is a valuation of the system's free inputs. The environment chooses at tick 1
//! (tick 0 only initialises) and again at every *choice point*: the tick after a watched slot
//! changed (the active state of a plant with continuous variables: a switch of the dynamics),
//! other than in the choice's own tick, or after the system came to rest (a tick that changed no state with the inputs held). Between choice points the
//! inputs are held (events are present in the first tick only). Delays are not enumerated: a
//! choice is made as soon as the previous one has played out; a scenario gives other timings.
//!
//! The enumeration is a depth-first search over segments (from one choice point to the next)
//! that stores each segment once, so memory grows with the ticks simulated, which are bounded
//! ([`Limits`]). Two segments that end at the same tick in the same state after the same
//! recorded history have the same futures and the same report: the second is not explored again. A
//! choice that changes nothing (the system stays at rest) is not a new sequence.

use crate::run::{tick_once, unreached, Stop};
use statecheck_ir::{Machine, Program, SlotId};
use std::collections::HashSet;
use std::hash::{Hash, Hasher};

/// The bounds of an enumeration.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// The most choices per sequence.
    pub depth: usize,
    /// The most sequences reported.
    pub max_runs: usize,
    /// The most ticks between two choice points.
    pub max_segment_ticks: u64,
    /// The most ticks simulated in all.
    pub max_total_ticks: u64,
    /// The most input valuations per choice (the product of the inputs' domains).
    pub max_valuations: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            depth: 4,
            max_runs: 1_000,
            max_segment_ticks: 10_000,
            max_total_ticks: 1_000_000,
            max_valuations: 256,
        }
    }
}

/// One choice: the inputs held from `tick` on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Choice {
    /// The tick from which the inputs apply.
    pub tick: u64,
    /// One value per input, in `Program::inputs` order.
    pub inputs: Vec<i64>,
}

/// Why a sequence ends.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum End {
    /// It has `Limits::depth` choices.
    Depth,
    /// The system is at rest and no choice changes anything.
    Rest,
    /// A segment ran `Limits::max_segment_ticks` ticks without a choice point.
    SegmentLimit,
    /// A run-time error in this tick.
    RuntimeError(u64),
    /// No valuation of the inputs satisfies the `assume`s at this tick.
    Blocked(u64),
}

/// One sequence of choices and its run.
#[derive(Clone, Debug)]
pub struct ChoiceRun {
    /// The choices, in order.
    pub choices: Vec<Choice>,
    /// The recorded slots (in the order asked for) after every tick, from tick 0.
    pub rows: Vec<Vec<i64>>,
    /// Property violations along the run: (tick, property), in order.
    pub violations: Vec<(u64, String)>,
    /// Why the sequence ends.
    pub end: End,
}

/// A bound that cut the enumeration short.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Truncation {
    /// `Limits::max_runs` sequences were reported; more exist.
    Runs(usize),
    /// `Limits::max_total_ticks` ticks were simulated.
    Ticks(u64),
    /// The inputs have this many valuations per choice, more than `Limits::max_valuations`:
    /// nothing was enumerated.
    Valuations(u128),
}

/// The result of [`enumerate`].
#[derive(Clone, Debug)]
pub struct Enumeration {
    /// The sequences found, in depth-first order of the choices (inputs in ascending value).
    pub runs: Vec<ChoiceRun>,
    /// The input valuations tried at each choice.
    pub valuations: usize,
    /// Why the enumeration is incomplete, if it is.
    pub truncated: Option<Truncation>,
}

/// A segment: the ticks from one choice point to the next.
struct Segment {
    parent: Option<usize>,
    choice: Option<Choice>,
    rows: Vec<Vec<i64>>,
    violations: Vec<(u64, String)>,
    /// The state after the segment's last tick.
    state: Vec<i64>,
    /// The next tick.
    tick: u64,
    /// Choices made so far.
    depth: usize,
    /// A hash of what the sequence recorded so far (two sequences with the same hash, tick
    /// and state report the same and continue alike).
    history: u64,
    end: Option<End>,
}

/// Every input valuation, in ascending order (the last input varies fastest), or the count
/// when it exceeds `max`.
fn valuations(program: &Program, max: usize) -> Result<Vec<Vec<i64>>, u128> {
    let domains: Vec<(i64, i64)> = program
        .inputs
        .iter()
        .map(|i| {
            let s = &program.slots[i.slot as usize];
            (s.lo, s.hi)
        })
        .collect();
    let mut count: u128 = 1;
    for (lo, hi) in &domains {
        let n = (*hi as i128 - *lo as i128 + 1).max(0) as u128;
        count = count.saturating_mul(n);
    }
    if count > max as u128 {
        return Err(count);
    }
    let mut out = vec![Vec::new()];
    for (lo, hi) in domains {
        let mut next = Vec::with_capacity(out.len() * (hi - lo + 1).max(0) as usize);
        for prefix in &out {
            for v in lo..=hi {
                let mut p = prefix.clone();
                p.push(v);
                next.push(p);
            }
        }
        out = next;
    }
    Ok(out)
}

/// The history after a segment: everything a report reads of it (the recorded slots and the
/// violations) hashed onto the history before it.
fn mix(history: u64, rows: &[Vec<i64>], violations: &[(u64, String)]) -> u64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    (history, rows, violations).hash(&mut h);
    h.finish()
}

/// Enumerate the sequences of choices of `program` up to `limits.depth` choices, recording
/// the `record` slots after every tick; a change of a `watch` slot is a choice point.
pub fn enumerate(
    program: &Program,
    watch: &[SlotId],
    record: &[SlotId],
    limits: Limits,
) -> Enumeration {
    let vals = match valuations(program, limits.max_valuations) {
        Ok(v) => v,
        Err(n) => {
            return Enumeration {
                runs: Vec::new(),
                valuations: 0,
                truncated: Some(Truncation::Valuations(n)),
            }
        }
    };
    let mut m = Machine::new(program);
    let mut reached = unreached(program);
    let init: Vec<i64> = program
        .inputs
        .iter()
        .map(|i| program.slots[i.slot as usize].init)
        .collect();
    let row = |m: &Machine| -> Vec<i64> { record.iter().map(|s| m.get(*s)).collect() };
    let wrow = |m: &Machine| -> Vec<i64> { watch.iter().map(|s| m.get(*s)).collect() };
    let mut root = Segment {
        parent: None,
        choice: None,
        rows: Vec::new(),
        violations: Vec::new(),
        state: Vec::new(),
        tick: 1,
        depth: 0,
        history: 0,
        end: None,
    };
    match tick_once(program, &mut m, 0, &init, &mut reached, &mut || {}) {
        Ok(()) => {}
        Err(Stop::Violation { .. }) => {
            for name in violated(program, &mut m) {
                root.violations.push((0, name));
            }
        }
        Err(Stop::AssumeViolated { .. }) => root.end = Some(End::Blocked(0)),
        Err(_) => root.end = Some(End::RuntimeError(0)),
    }
    root.rows.push(row(&m));
    root.state = m.state().to_vec();
    let mut segs = vec![root];
    let mut stack = vec![0usize];
    let mut seen: HashSet<(u64, Vec<i64>, u64)> = HashSet::new();
    let mut runs = Vec::new();
    let mut total: u64 = 1;
    let mut truncated = None;
    'search: while let Some(at) = stack.pop() {
        let (depth, start, history) = (segs[at].depth, segs[at].tick, segs[at].history);
        if segs[at].end.is_none() && depth >= limits.depth {
            segs[at].end = Some(End::Depth);
        }
        if let Some(end) = segs[at].end.clone() {
            if runs.len() >= limits.max_runs {
                truncated = Some(Truncation::Runs(limits.max_runs));
                break;
            }
            runs.push(collect(&segs, at, end));
            continue;
        }
        let mut children = Vec::new();
        let mut any_allowed = false;
        for v in &vals {
            let mut seg = Segment {
                parent: Some(at),
                choice: Some(Choice {
                    tick: start,
                    inputs: v.clone(),
                }),
                rows: Vec::new(),
                violations: Vec::new(),
                state: Vec::new(),
                tick: start,
                depth: depth + 1,
                history,
                end: None,
            };
            m.load_state(&segs[at].state);
            let mut inputs = v.clone();
            let mut changed = false;
            let mut t = start;
            loop {
                if total >= limits.max_total_ticks {
                    truncated = Some(Truncation::Ticks(limits.max_total_ticks));
                    break 'search;
                }
                let before = m.state().to_vec();
                let w0 = wrow(&m);
                let r = tick_once(program, &mut m, t, &inputs, &mut reached, &mut || {});
                match r {
                    Ok(()) => {}
                    Err(Stop::Violation { .. }) => {
                        // Every property violated in this tick, not only the first.
                        for name in violated(program, &mut m) {
                            seg.violations.push((t, name));
                        }
                    }
                    Err(Stop::AssumeViolated { .. }) => {
                        // Held inputs no longer allowed: the environment must choose again.
                        m.load_state(&before);
                        break;
                    }
                    Err(_) => {
                        seg.end = Some(End::RuntimeError(t));
                        break;
                    }
                }
                total += 1;
                seg.rows.push(row(&m));
                t += 1;
                let w1 = wrow(&m);
                let events_present = program
                    .inputs
                    .iter()
                    .zip(&inputs)
                    .any(|(i, v)| i.is_event && *v != 0);
                let same = m.state() == before.as_slice();
                changed |= !same;
                // The change the choice causes in its own tick starts the segment's dynamics;
                // the next one ends it.
                if w1 != w0 && t - 1 > start {
                    break;
                }
                if same && !events_present {
                    break; // At rest.
                }
                if t - start >= limits.max_segment_ticks {
                    seg.end = Some(End::SegmentLimit);
                    break;
                }
                for (k, i) in program.inputs.iter().enumerate() {
                    if i.is_event {
                        inputs[k] = 0;
                    }
                }
            }
            if seg.rows.is_empty() && seg.end.is_none() {
                continue; // The `assume`s refuse this valuation here.
            }
            any_allowed = true;
            if !changed && seg.end.is_none() {
                continue; // Nothing happens: not a new sequence.
            }
            seg.state = m.state().to_vec();
            seg.tick = t;
            seg.history = mix(history, &seg.rows, &seg.violations);
            if !seen.insert((seg.tick, seg.state.clone(), seg.history)) {
                continue;
            }
            children.push(seg);
        }
        if children.is_empty() {
            segs[at].end = Some(if any_allowed {
                End::Rest
            } else {
                End::Blocked(start)
            });
            stack.push(at);
            continue;
        }
        // Depth-first, first valuation first: push in reverse.
        let first = segs.len();
        segs.extend(children);
        stack.extend((first..segs.len()).rev());
    }
    Enumeration {
        runs,
        valuations: vals.len(),
        truncated,
    }
}

/// The safety properties (not `reachable`) the machine's state violates, in declaration order.
fn violated(program: &Program, m: &mut Machine) -> Vec<String> {
    let mut holds = |e| m.eval(e).is_ok_and(|v| v != 0);
    program
        .properties
        .iter()
        .filter(|p| !p.goal.is_reach() && p.goal.decided_by(&mut holds))
        .map(|p| p.name.clone())
        .collect()
}

/// The run of the sequence that ends with segment `at`.
fn collect(segs: &[Segment], at: usize, end: End) -> ChoiceRun {
    let mut chain = Vec::new();
    let mut k = Some(at);
    while let Some(i) = k {
        chain.push(i);
        k = segs[i].parent;
    }
    chain.reverse();
    let mut run = ChoiceRun {
        choices: Vec::new(),
        rows: Vec::new(),
        violations: Vec::new(),
        end,
    };
    for i in chain {
        let s = &segs[i];
        run.choices.extend(s.choice.clone());
        run.rows.extend(s.rows.iter().cloned());
        run.violations.extend(s.violations.iter().cloned());
    }
    run
}
