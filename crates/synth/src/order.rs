//! A static BDD variable order for the symbolic engine: the FORCE heuristic (Aloul, Markov,
//! Sakallah 2003) over the hypergraph whose vertices are the automata and whose hyperedges are
//! the events (the automata that share an event) and the state requirements (the automata a
//! `never`/`needs` condition mentions). FORCE moves every automaton to the mean of the centres
//! of gravity of its hyperedges and re-sorts, which pulls automata that synchronise next to
//! each other; the order with the least total span (sum over hyperedges of last − first
//! position) is kept. See docs/synthesis.md ("Variable order").

use crate::problem::{Pred, Problem};

/// Most FORCE iterations (it usually settles in a few).
const MAX_ITERATIONS: usize = 64;

/// The automata of `p` in the order their bits are placed (a permutation of `0..n`).
pub fn force(p: &Problem) -> Vec<usize> {
    let n = p.automata.len();
    let edges = hyperedges(p);
    let mut order: Vec<usize> = (0..n).collect();
    if n <= 2 || edges.is_empty() {
        return order;
    }
    let mut best = order.clone();
    let mut best_span = span(&edges, &positions(&order));
    for _ in 0..MAX_ITERATIONS {
        let pos = positions(&order);
        let mut sum = vec![0.0f64; n];
        let mut cnt = vec![0usize; n];
        for e in &edges {
            let cog = e.iter().map(|&a| pos[a] as f64).sum::<f64>() / e.len() as f64;
            for &a in e {
                sum[a] += cog;
                cnt[a] += 1;
            }
        }
        let target: Vec<f64> = (0..n)
            .map(|a| {
                if cnt[a] == 0 {
                    pos[a] as f64
                } else {
                    sum[a] / cnt[a] as f64
                }
            })
            .collect();
        let mut next: Vec<usize> = (0..n).collect();
        // Ties keep the previous order (stable sort on the previous position).
        next.sort_by(|&a, &b| target[a].total_cmp(&target[b]).then(pos[a].cmp(&pos[b])));
        let s = span(&edges, &positions(&next));
        if next == order {
            break;
        }
        order = next;
        if s < best_span {
            best_span = s;
            best = order.clone();
        }
    }
    best
}

/// The total span of the hyperedges under the identity order and under [`force`]'s order.
pub fn spans(p: &Problem, order: &[usize]) -> (usize, usize) {
    let edges = hyperedges(p);
    let id: Vec<usize> = (0..p.automata.len()).collect();
    (
        span(&edges, &positions(&id)),
        span(&edges, &positions(order)),
    )
}

fn positions(order: &[usize]) -> Vec<usize> {
    let mut pos = vec![0; order.len()];
    for (i, &a) in order.iter().enumerate() {
        pos[a] = i;
    }
    pos
}

fn span(edges: &[Vec<usize>], pos: &[usize]) -> usize {
    edges
        .iter()
        .map(|e| {
            let lo = e.iter().map(|&a| pos[a]).min().unwrap_or(0);
            let hi = e.iter().map(|&a| pos[a]).max().unwrap_or(0);
            hi - lo
        })
        .sum()
}

/// Sets of at least two automata that interact: per event, its automata; per state
/// requirement, the automata it mentions.
fn hyperedges(p: &Problem) -> Vec<Vec<usize>> {
    let mut edges = Vec::new();
    for e in 0..p.events.len() as u32 {
        let with: Vec<usize> = (0..p.automata.len())
            .filter(|&a| p.automata[a].has(e))
            .collect();
        if with.len() >= 2 {
            edges.push(with);
        }
    }
    let conds = p
        .never
        .iter()
        .map(|c| (c, None))
        .chain(p.needs.iter().map(|n| (&n.cond, Some(n.event))));
    for (c, event) in conds {
        let mut with = Vec::new();
        mentioned(c, &mut with);
        // A `needs` ties its condition's automata to the event's.
        if let Some(e) = event {
            with.extend((0..p.automata.len()).filter(|&a| p.automata[a].has(e)));
        }
        with.sort_unstable();
        with.dedup();
        if with.len() >= 2 {
            edges.push(with);
        }
    }
    edges
}

fn mentioned(p: &Pred, out: &mut Vec<usize>) {
    // An explicit stack: conditions can be deep.
    let mut stack = vec![p];
    while let Some(p) = stack.pop() {
        match p {
            Pred::Const(_) => {}
            Pred::At(a, _) => out.push(*a as usize),
            Pred::Not(x) => stack.push(x),
            Pred::And(a, b) | Pred::Or(a, b) => {
                stack.push(a);
                stack.push(b);
            }
        }
    }
}
