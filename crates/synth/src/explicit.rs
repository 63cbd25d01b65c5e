//! The explicit engine: the reachable synchronous product, then the classic fixpoint that
//! alternately removes blocking states and states from which an uncontrollable event leads
//! to a removed state.

use crate::problem::{EventId, Kind, Problem};
use std::collections::HashMap;

/// The result of the explicit fixpoint, before guards are derived.
pub struct Explicit {
    /// Reachable product states (location vectors), state 0 initial.
    pub states: Vec<Vec<u32>>,
    /// Kept states after the fixpoint, restricted to those reachable from the initial one
    /// through kept states.
    pub kept: Vec<bool>,
    /// Transitions `(from, event, to)` of the product (requirement-allowed ones).
    pub edges: Vec<(u32, EventId, u32)>,
    /// Reachable states of the unrestricted product (plant × requirements).
    pub product_states: usize,
}

/// Refuse products larger than this (the symbolic engine is for those).
pub const STATE_LIMIT: usize = 20_000_000;

/// Run the explicit engine. `Err` when the reachable product exceeds [`STATE_LIMIT`].
pub fn run(p: &Problem) -> Result<Explicit, String> {
    let mut index: HashMap<Vec<u32>, u32> = HashMap::new();
    let mut states: Vec<Vec<u32>> = vec![p.initial()];
    index.insert(p.initial(), 0);
    let mut bad: Vec<bool> = Vec::new();
    let mut edges: Vec<(u32, EventId, u32)> = Vec::new();
    let mut i = 0;
    while i < states.len() {
        let locs = states[i].clone();
        let mut is_bad = p.is_forbidden(&locs);
        if !is_bad {
            for e in 0..p.events.len() as EventId {
                if !p.enabled_by(Kind::Plant, &locs, e) {
                    continue;
                }
                if !p.allowed(&locs, e) {
                    if !p.events[e as usize].controllable {
                        is_bad = true;
                    }
                    continue;
                }
                let Some(next) = p.successor(&locs, e) else {
                    continue;
                };
                let id = match index.get(&next) {
                    Some(id) => *id,
                    None => {
                        if states.len() >= STATE_LIMIT {
                            return Err(format!(
                                "the reachable product exceeds {STATE_LIMIT} states; use --engine symbolic"
                            ));
                        }
                        let id = states.len() as u32;
                        index.insert(next.clone(), id);
                        states.push(next);
                        id
                    }
                };
                edges.push((i as u32, e, id));
            }
        }
        bad.push(is_bad);
        i += 1;
    }
    let n = states.len();
    let mut alive: Vec<bool> = bad.iter().map(|b| !b).collect();
    let mut preds: Vec<Vec<(u32, EventId)>> = vec![Vec::new(); n];
    for &(s, e, t) in &edges {
        preds[t as usize].push((s, e));
    }
    loop {
        let before = alive.iter().filter(|a| **a).count();
        // Nonblocking: keep only states that reach a marked state through kept states.
        let mut coreach = vec![false; n];
        let mut stack: Vec<u32> = (0..n as u32)
            .filter(|&s| alive[s as usize] && p.is_marked(&states[s as usize]))
            .collect();
        for &s in &stack {
            coreach[s as usize] = true;
        }
        while let Some(t) = stack.pop() {
            for &(s, _) in &preds[t as usize] {
                if alive[s as usize] && !coreach[s as usize] {
                    coreach[s as usize] = true;
                    stack.push(s);
                }
            }
        }
        for s in 0..n {
            if alive[s] && !coreach[s] {
                alive[s] = false;
            }
        }
        // Controllability: a state with an uncontrollable edge into a removed state goes too.
        let mut work: Vec<u32> = (0..n as u32).filter(|&s| !alive[s as usize]).collect();
        while let Some(t) = work.pop() {
            for &(s, e) in &preds[t as usize] {
                if alive[s as usize] && !p.events[e as usize].controllable {
                    alive[s as usize] = false;
                    work.push(s);
                }
            }
        }
        if alive.iter().filter(|a| **a).count() == before {
            break;
        }
    }
    // Restrict to what is reachable from the initial state through kept states.
    let mut kept = vec![false; n];
    if alive[0] {
        let mut succ: Vec<Vec<u32>> = vec![Vec::new(); n];
        for &(s, _, t) in &edges {
            succ[s as usize].push(t);
        }
        kept[0] = true;
        let mut stack = vec![0u32];
        while let Some(s) = stack.pop() {
            for &t in &succ[s as usize] {
                if alive[t as usize] && !kept[t as usize] {
                    kept[t as usize] = true;
                    stack.push(t);
                }
            }
        }
    }
    Ok(Explicit {
        states,
        kept,
        edges,
        product_states: n,
    })
}

impl Explicit {
    /// Number of supervisor states (kept and reachable).
    pub fn size(&self) -> usize {
        self.kept.iter().filter(|k| **k).count()
    }

    /// Number of supervisor transitions (between kept states).
    pub fn transitions(&self) -> usize {
        self.edges
            .iter()
            .filter(|(s, _, t)| self.kept[*s as usize] && self.kept[*t as usize])
            .count()
    }
}
