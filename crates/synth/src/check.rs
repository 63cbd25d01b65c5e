//! Independent check of a supervisor against a plant, in the tick semantics.
//!
//! The supervisor is any lowered system that follows the bridge interface of
//! `docs/synthesis.md`: exactly one free input, of an enum type whose literals are `none` and
//! event names (the event the environment proposes this tick), and one output variable named
//! `fire` of such an enum (the event that occurred, or `none`). The check explores the closed
//! loop — the system's IR states (run with the reference [`Machine`], so with the semantics of
//! `lower/`) paired with the locations of the plant and requirement automata of the
//! *model*, which it tracks itself from the fired events — and reports:
//!
//! - **plant conformance**: a fired event must be the proposed one and possible in the plant;
//! - **controllability**: when the plant can do an uncontrollable event and the environment
//!   proposes it, it must fire;
//! - **requirements**: every fired event is allowed by the requirement automata and `needs`
//!   conditions; no reachable state satisfies a `never` condition;
//! - **nonblocking**: from every reachable closed-loop state, a state where every automaton is
//!   marked is reachable.
//!
//! It shares no code with the synthesis fixpoints: it walks the closed loop's own graph.

use crate::error::Error;
use crate::problem::{EventId, Kind, Problem};
use statecheck_ir::{Machine, Program, ValueKind};
use statecheck_model::Model;
use statecheck_model::VarKind;
use std::collections::{HashMap, VecDeque};

/// What the check found.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// Closed-loop states explored (IR state × automaton locations).
    pub closed_loop_states: usize,
    /// Distinct automaton location vectors reached (comparable with a synthesized supervisor's
    /// state count: equal for a maximally permissive one).
    pub plant_states: usize,
    /// Closed-loop transitions that fired an event.
    pub event_transitions: usize,
    /// Violations, each with a trace of events from the start; empty means the supervisor is
    /// controllable, nonblocking and meets the requirements.
    pub violations: Vec<String>,
}

/// Refuse closed loops larger than this.
pub const LIMIT: usize = 5_000_000;

/// Check the supervisor `program` (a system of `model`) against the plant of `p`.
pub fn check(p: &Problem, model: &Model, program: &Program) -> Result<Report, Error> {
    let free: Vec<_> = program.inputs.iter().collect();
    let [input] = free.as_slice() else {
        return Err(Error::supervisor(format!(
            "the supervisor system must have exactly one free input (the proposed event); it has {}",
            free.len()
        )));
    };
    let names = match &program.slots[input.slot as usize].display {
        ValueKind::Enum(n) => n.clone(),
        _ => {
            return Err(Error::supervisor(format!(
                "input `{}` is not of an event enum type",
                input.name
            )))
        }
    };
    let mut fire_slot = None;
    for inst in &program.instances {
        let chart = &model.charts[inst.chart as usize];
        for (vi, v) in chart.vars.iter().enumerate() {
            if v.name == "fire" && v.kind == VarKind::Output && fire_slot.is_none() {
                fire_slot = Some(inst.var_slots[vi]);
            }
        }
    }
    let fire_slot = fire_slot.ok_or("the supervisor system has no output variable `fire`")?;
    // Map enum values to problem events (None for `none`).
    let ev_of = |v: i64| -> Result<Option<EventId>, String> {
        let name = names.get(v as usize).ok_or("event value out of range")?;
        if name == "none" {
            return Ok(None);
        }
        p.events
            .iter()
            .position(|e| &e.name == name)
            .map(|i| Some(i as EventId))
            .ok_or_else(|| {
                format!("the supervisor's event `{name}` is not an event of the plant model")
            })
    };
    let none = names
        .iter()
        .position(|n| n == "none")
        .ok_or("the event enum has no `none` literal")? as i64;
    let values: Vec<i64> = (0..names.len() as i64).collect();

    let mut m = Machine::new(program);
    m.set(input.slot, none);
    m.step()
        .map_err(|e| format!("tick 0: {}", program.describe_error(&e)))?;
    type Node = (Vec<i64>, Vec<u32>);
    let start: Node = (m.state().to_vec(), p.initial());
    let mut index: HashMap<Node, usize> = HashMap::new();
    let mut nodes: Vec<Node> = vec![start.clone()];
    let mut parent: Vec<Option<(usize, Option<EventId>)>> = vec![None];
    let mut preds: Vec<Vec<usize>> = vec![Vec::new()];
    index.insert(start, 0);
    let mut report = Report::default();
    let mut queue = VecDeque::from([0usize]);
    let trace = |parent: &[Option<(usize, Option<EventId>)>], mut at: usize| -> String {
        let mut evs = Vec::new();
        while let Some((prev, e)) = parent[at] {
            if let Some(e) = e {
                evs.push(p.events[e as usize].name.clone());
            }
            at = prev;
        }
        evs.reverse();
        if evs.is_empty() {
            "initially".to_string()
        } else {
            format!("after {}", evs.join(" "))
        }
    };
    while let Some(i) = queue.pop_front() {
        let (state, locs) = nodes[i].clone();
        if let Some(k) = p.never.iter().position(|n| n.eval(&locs)) {
            report.violations.push(format!(
                "requirement `never` number {} holds {} ({})",
                k + 1,
                trace(&parent, i),
                p.describe(&locs)
            ));
        }
        for &v in &values {
            let proposed = ev_of(v)?;
            m.load_state(&state);
            m.set(input.slot, v);
            m.step()
                .map_err(|e| format!("{}: {}", trace(&parent, i), program.describe_error(&e)))?;
            let fired = ev_of(m.get(fire_slot))?;
            let mut next_locs = locs.clone();
            if let Some(e) = fired {
                let name = &p.events[e as usize].name;
                if Some(e) != proposed {
                    report.violations.push(format!(
                        "the supervisor fired `{name}` when another event was proposed, {}",
                        trace(&parent, i)
                    ));
                    continue;
                }
                if !p.enabled_by(Kind::Plant, &locs, e) {
                    report.violations.push(format!(
                        "the supervisor fired `{name}`, which the plant cannot do, {} ({})",
                        trace(&parent, i),
                        p.describe(&locs)
                    ));
                    continue;
                }
                if !p.allowed(&locs, e) {
                    report.violations.push(format!(
                        "event `{name}` violates the requirements {} ({})",
                        trace(&parent, i),
                        p.describe(&locs)
                    ));
                    continue;
                }
                for (ai, a) in p.automata.iter().enumerate() {
                    if a.has(e) {
                        if let Some(t) = a.step(locs[ai], e) {
                            next_locs[ai] = t;
                        }
                    }
                }
                report.event_transitions += 1;
            } else if let Some(u) = proposed {
                if !p.events[u as usize].controllable && p.enabled_by(Kind::Plant, &locs, u) {
                    report.violations.push(format!(
                        "not controllable: the plant can do uncontrollable `{}` {} ({}) but the supervisor prevents it",
                        p.events[u as usize].name,
                        trace(&parent, i),
                        p.describe(&locs)
                    ));
                }
            }
            let node: Node = (m.state().to_vec(), next_locs);
            let j = match index.get(&node) {
                Some(j) => *j,
                None => {
                    if nodes.len() >= LIMIT {
                        return Err(Error::supervisor(format!(
                            "the closed loop exceeds {LIMIT} states"
                        )));
                    }
                    let j = nodes.len();
                    index.insert(node.clone(), j);
                    nodes.push(node);
                    parent.push(Some((i, fired)));
                    preds.push(Vec::new());
                    queue.push_back(j);
                    j
                }
            };
            preds[j].push(i);
        }
    }
    // Nonblocking: backward search from marked closed-loop states.
    let mut co = vec![false; nodes.len()];
    let mut stack: Vec<usize> = (0..nodes.len())
        .filter(|&i| p.is_marked(&nodes[i].1))
        .collect();
    for &i in &stack {
        co[i] = true;
    }
    while let Some(j) = stack.pop() {
        for &i in &preds[j] {
            if !co[i] {
                co[i] = true;
                stack.push(i);
            }
        }
    }
    if let Some(i) = (0..nodes.len()).find(|&i| !co[i]) {
        let blocked = co.iter().filter(|c| !**c).count();
        report.violations.push(format!(
            "blocking: no marked state can be reached {} ({}); {blocked} closed-loop state(s) block",
            trace(&parent, i),
            p.describe(&nodes[i].1)
        ));
    }
    report.closed_loop_states = nodes.len();
    let distinct: std::collections::HashSet<&Vec<u32>> = nodes.iter().map(|n| &n.1).collect();
    report.plant_states = distinct.len();
    Ok(report)
}
