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
    format!(
        "no supervisor exists: from the initial state ({}) no marked state can be reached without risking, through uncontrollable events, a state that blocks or violates a requirement",
        p.describe(&init)
    )
}
