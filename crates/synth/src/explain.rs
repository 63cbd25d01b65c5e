//! Why no supervisor exists: a path of uncontrollable events from the initial state to a
//! state that violates a requirement, found by direct search over the product (independent
//! of either engine's fixpoint).

use crate::problem::{EventId, Kind, Problem};
use std::collections::{HashMap, VecDeque};

/// Why `locs` is bad on its own, if it is: a `never` requirement holds, or a requirement
/// forbids an uncontrollable event the plant can do.
pub fn immediate_violation(p: &Problem, locs: &[u32]) -> Option<String> {
    if let Some(i) = p.never.iter().position(|n| n.eval(locs)) {
        return Some(format!("`requirement never` number {} holds", i + 1));
    }
    (0..p.events.len() as EventId)
        .find(|&u| {
            !p.events[u as usize].controllable
                && p.enabled_by(Kind::Plant, locs, u)
                && !p.allowed(locs, u)
        })
        .map(|u| {
            format!(
                "the plant can do uncontrollable `{}` but the requirements forbid it",
                p.events[u as usize].name
            )
        })
}

/// Explain an empty supervisor.
pub fn why_empty(p: &Problem) -> String {
    let init = p.initial();
    let mut parent: HashMap<Vec<u32>, Option<(Vec<u32>, EventId)>> = HashMap::new();
    parent.insert(init.clone(), None);
    let mut queue = VecDeque::from([init.clone()]);
    while let Some(s) = queue.pop_front() {
        if let Some(why) = immediate_violation(p, &s) {
            let mut path = Vec::new();
            let mut at = s.clone();
            while let Some(Some((prev, e))) = parent.get(&at) {
                path.push(p.events[*e as usize].name.clone());
                at = prev.clone();
            }
            path.reverse();
            let how = if path.is_empty() {
                "in the initial state".to_string()
            } else {
                format!(
                    "after the uncontrollable event(s) {} from the initial state",
                    path.iter()
                        .map(|e| format!("`{e}`"))
                        .collect::<Vec<_>>()
                        .join(", ")
                )
            };
            return format!(
                "no supervisor exists: {how}, the plant reaches ({}) where {why}; no controllable event can prevent it",
                p.describe(&s)
            );
        }
        for u in 0..p.events.len() as EventId {
            if p.events[u as usize].controllable || !p.enabled_by(Kind::Plant, &s, u) {
                continue;
            }
            if let Some(t) = p.successor(&s, u) {
                if !parent.contains_key(&t) {
                    parent.insert(t.clone(), Some((s.clone(), u)));
                    queue.push_back(t);
                }
            }
        }
    }
    let witness = blocking_witness(p)
        .map(|(path, locs)| {
            format!(
                "\nwitness: {} reaches ({}), from which no marked state can be reached without a state that violates a requirement",
                if path.is_empty() {
                    "the initial state".to_string()
                } else {
                    format!("the event trace {}", path.join(" "))
                },
                locs
            )
        })
        .unwrap_or_default();
    format!(
        "no supervisor exists: from the initial state ({}) no marked state can be reached without risking, through uncontrollable events, a state that blocks or violates a requirement{witness}",
        p.describe(&init)
    )
}

/// Explore at most this many product states for a witness.
const WITNESS_LIMIT: usize = 1_000_000;

/// The shortest event trace from the initial state to a state of the product (requirement-
/// allowed moves, bad states not expanded) that is not bad but cannot reach a marked state
/// that is not bad: where every continuation fails. `None` when there is none, or the product
/// is too large to search.
fn blocking_witness(p: &Problem) -> Option<(Vec<String>, String)> {
    let init = p.initial();
    let mut index: HashMap<Vec<u32>, usize> = HashMap::new();
    let mut states = vec![init.clone()];
    let mut parent: Vec<Option<(usize, EventId)>> = vec![None];
    let mut preds: Vec<Vec<usize>> = vec![Vec::new()];
    let mut bad = Vec::new();
    index.insert(init, 0);
    let mut i = 0;
    while i < states.len() {
        let s = states[i].clone();
        let is_bad = immediate_violation(p, &s).is_some();
        bad.push(is_bad);
        if !is_bad {
            for e in 0..p.events.len() as EventId {
                if !p.enabled_by(Kind::Plant, &s, e) || !p.allowed(&s, e) {
                    continue;
                }
                let Some(t) = p.successor(&s, e) else {
                    continue;
                };
                let j = match index.get(&t) {
                    Some(j) => *j,
                    None => {
                        if states.len() >= WITNESS_LIMIT {
                            return None;
                        }
                        index.insert(t.clone(), states.len());
                        states.push(t);
                        parent.push(Some((i, e)));
                        preds.push(Vec::new());
                        states.len() - 1
                    }
                };
                preds[j].push(i);
            }
        }
        i += 1;
    }
    let mut co = vec![false; states.len()];
    let mut stack: Vec<usize> = (0..states.len())
        .filter(|&k| !bad[k] && p.is_marked(&states[k]))
        .collect();
    for &k in &stack {
        co[k] = true;
    }
    while let Some(t) = stack.pop() {
        for &s in &preds[t] {
            if !bad[s] && !co[s] {
                co[s] = true;
                stack.push(s);
            }
        }
    }
    // States are numbered in breadth-first order, so the first one has a shortest trace.
    let k = (0..states.len()).find(|&k| !bad[k] && !co[k])?;
    let mut path = Vec::new();
    let mut at = k;
    while let Some((prev, e)) = parent[at] {
        path.push(p.events[e as usize].name.clone());
        at = prev;
    }
    path.reverse();
    Some((path, p.describe(&states[k])))
}
