//! The product of the position graph with the Büchi automaton of `!φ`, built breadth-first
//! (so every product state has a shortest prefix), and the search for a fair accepting cycle
//! by SCC decomposition (`super::scc`). SCC-based rather than nested DFS because the
//! automaton's acceptance is generalised and compassion is a Streett condition, which nested
//! DFS does not handle; the product is stored anyway for the lasso.

use super::buchi::Buchi;
use super::graph::Kripke;
use super::scc::{fair_component, path_within, BoxPred, Fairness, Pred};
use std::collections::HashMap;

/// A lasso of the product: input positions of every tick, and the tick where the loop starts.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lasso {
    /// Input position (in the enumeration) of each tick, from tick 0.
    pub inputs: Vec<u32>,
    /// First tick of the loop: after the last tick, the state after tick `loop_start - 1`
    /// recurs and the ticks from `loop_start` repeat forever.
    pub loop_start: usize,
}

/// Fairness constraints as letter bits.
#[derive(Clone, Debug, Default)]
pub struct FairBits {
    /// Justice: each bit must hold infinitely often.
    pub justice: Vec<u32>,
    /// Compassion: (trigger bit, response bit).
    pub compassion: Vec<(u32, u32)>,
}

/// Why the check stopped early.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TooLarge;

/// Some fair run of `g` accepted by `a` (a counterexample when `a` is the automaton of `!φ`),
/// as a lasso; `None` when there is none. Errs when the product exceeds `max_states`.
pub fn find_lasso(
    g: &Kripke,
    a: &Buchi,
    fair: &FairBits,
    max_states: u64,
) -> Result<Option<Lasso>, TooLarge> {
    find_lasso_counted(g, a, fair, max_states).0
}

/// [`find_lasso`], with the number of product states built (for benchmarks).
pub fn find_lasso_counted(
    g: &Kripke,
    a: &Buchi,
    fair: &FairBits,
    max_states: u64,
) -> (Result<Option<Lasso>, TooLarge>, u64) {
    let mut built = 0u64;
    let r = product_lasso(g, a, fair, max_states, &mut built);
    (r, built)
}

fn product_lasso(
    g: &Kripke,
    a: &Buchi,
    fair: &FairBits,
    max_states: u64,
    built: &mut u64,
) -> Result<Option<Lasso>, TooLarge> {
    // Product states (node, automaton state), numbered in BFS order.
    let mut pairs: Vec<(u32, u32)> = Vec::new();
    let mut parent: Vec<(u32, u32)> = Vec::new(); // (parent product state or MAX, input)
    let mut index: HashMap<(u32, u32), u32> = HashMap::new();
    let mut edge_start: Vec<u32> = vec![0];
    let mut targets: Vec<u32> = Vec::new();
    let mut inputs: Vec<u32> = Vec::new();
    for &(n, inp) in g.initial() {
        for &q in &a.initial {
            if a.states[q as usize].admits(g.node_letter[n as usize])
                && !index.contains_key(&(n, q))
            {
                index.insert((n, q), pairs.len() as u32);
                pairs.push((n, q));
                parent.push((u32::MAX, inp));
            }
        }
    }
    let mut i = 0usize;
    while i < pairs.len() {
        if pairs.len() as u64 > max_states {
            *built = pairs.len() as u64;
            return Err(TooLarge);
        }
        let (n, q) = pairs[i];
        for &(n2, inp) in g.succ(n) {
            let l = g.node_letter[n2 as usize];
            for &q2 in &a.succ[q as usize] {
                if !a.states[q2 as usize].admits(l) {
                    continue;
                }
                let next = pairs.len() as u32;
                let t = *index.entry((n2, q2)).or_insert(next);
                if t == next {
                    pairs.push((n2, q2));
                    parent.push((i as u32, inp));
                }
                targets.push(t);
                inputs.push(inp);
            }
        }
        edge_start.push(targets.len() as u32);
        i += 1;
    }
    let n = pairs.len();
    *built = n as u64;
    let succ = |v: u32| -> &[u32] {
        &targets[edge_start[v as usize] as usize..edge_start[v as usize + 1] as usize]
    };
    let pairs = &pairs;
    let letter = move |v: u32| g.node_letter[pairs[v as usize].0 as usize];
    let acc: Vec<Box<dyn Fn(u32) -> bool + '_>> = a
        .accepting
        .iter()
        .map(|set| {
            let f: Box<dyn Fn(u32) -> bool> =
                Box::new(move |v: u32| set[pairs[v as usize].1 as usize]);
            f
        })
        .chain(fair.justice.iter().map(|&b| {
            let f: Box<dyn Fn(u32) -> bool> = Box::new(move |v: u32| letter(v) >> b & 1 == 1);
            f
        }))
        .collect();
    let visit: Vec<&dyn Fn(u32) -> bool> = acc.iter().map(|b| b.as_ref()).collect();
    let comp_fns: Vec<(BoxPred<'_>, BoxPred<'_>)> = fair
        .compassion
        .iter()
        .map(|&(p, q)| {
            let a: Box<dyn Fn(u32) -> bool> = Box::new(move |v: u32| letter(v) >> p & 1 == 1);
            let b: Box<dyn Fn(u32) -> bool> = Box::new(move |v: u32| letter(v) >> q & 1 == 1);
            (a, b)
        })
        .collect();
    let compassion: Vec<(Pred<'_>, Pred<'_>)> = comp_fns
        .iter()
        .map(|(a, b)| (a.as_ref(), b.as_ref()))
        .collect();
    let verts: Vec<u32> = (0..n as u32).collect();
    let fairness = Fairness {
        visit: &visit,
        compassion: &compassion,
    };
    let Some(comp) = fair_component(&verts, n, &succ, &fairness) else {
        return Ok(None);
    };
    let mut member = vec![false; n];
    for &v in &comp {
        member[v as usize] = true;
    }
    let inside = |v: u32| member[v as usize];
    // Entry: the component's state found first (BFS order: a shortest prefix).
    let entry = comp.iter().copied().min().unwrap_or(0);
    let mut prefix = vec![entry];
    let mut cur = entry;
    while parent[cur as usize].0 != u32::MAX {
        cur = parent[cur as usize].0;
        prefix.push(cur);
    }
    prefix.reverse();
    // The cycle visits every set the component must meet, then returns to the entry.
    let mut goals: Vec<&dyn Fn(u32) -> bool> = visit.clone();
    for (p, q) in &compassion {
        if comp.iter().any(|&v| p(v)) {
            goals.push(*q);
        }
    }
    let mut cycle: Vec<u32> = Vec::new();
    let mut at = entry;
    for goal in goals {
        if cycle.is_empty() && goal(entry) {
            continue;
        }
        if cycle.iter().any(|&v| goal(v)) {
            continue;
        }
        let Some(p) = path_within(at, goal, &inside, &succ, false) else {
            return Ok(None);
        };
        if let Some(&last) = p.last() {
            at = last;
        }
        cycle.extend(p);
    }
    let Some(back) = path_within(at, &|v| v == entry, &inside, &succ, true) else {
        return Ok(None);
    };
    cycle.extend(back);
    // Ticks: the prefix's (tick 0 from the initial state), then the cycle's edges.
    let mut ticks: Vec<u32> = prefix.iter().map(|&v| parent[v as usize].1).collect();
    let loop_start = ticks.len();
    let mut from = entry;
    for &v in &cycle {
        let (a0, b0) = (
            edge_start[from as usize] as usize,
            edge_start[from as usize + 1] as usize,
        );
        let k = (a0..b0).find(|&k| targets[k] == v).unwrap_or(a0);
        ticks.push(inputs[k]);
        from = v;
    }
    Ok(Some(Lasso {
        inputs: ticks,
        loop_start,
    }))
}
