//! CTL by fixpoints on the stored position graph (Clarke–Emerson–Sistla), over fair paths:
//! `EG` under fairness is the greatest fixpoint of fair SCCs (states from which a fair cycle
//! within the formula's states is reachable), `fair` = `EG true`, and `EX`/`E[U]` are
//! restricted to successors that are fair. A property holds when every position 0 (after
//! tick 0) that has a fair run satisfies it; initial positions without any fair run are
//! ignored, as NuSMV does.

use super::graph::Kripke;
use super::product::FairBits;
use super::scc::{fair_component, sccs, BoxPred, Fairness, Pred, Scratch};
use crate::props::PropKind;
use crate::{PropResult, Verdict};
use statecheck_ir::temporal::Ctl;
use statecheck_ir::{ExprId, Program};

/// The verdict of `f` on `g`; a violation's counterexample is the shortest scenario to an
/// initial position that does not satisfy it.
pub fn verdict(
    program: &Program,
    g: &Kripke,
    f: &Ctl,
    atoms: &[ExprId],
    fair: &FairBits,
    name: &str,
    kind: PropKind,
) -> PropResult {
    let n = g.n_nodes();
    let succ: Vec<Vec<u32>> = (0..n as u32)
        .map(|v| g.succ(v).iter().map(|&(w, _)| w).collect())
        .collect();
    let fair_states = eg(g, &succ, &vec![true; n], fair);
    let sat = eval(g, &succ, f, atoms, fair, &fair_states);
    let bad = g
        .initial()
        .iter()
        .find(|&&(v, _)| fair_states[v as usize] && !sat[v as usize]);
    match bad {
        None => PropResult {
            name: name.to_string(),
            kind,
            verdict: Verdict::Proved,
            depth: 0,
            counterexample: None,
            error: None,
            note: None,
            loop_start: None,
        },
        Some(&(_, inp)) => PropResult {
            name: name.to_string(),
            kind,
            verdict: Verdict::Violated,
            depth: 1,
            counterexample: Some(vec![super::graph::input_vector(program, inp)]),
            error: None,
            note: Some(
                "the initial position reached by this tick does not satisfy the formula".into(),
            ),
            loop_start: None,
        },
    }
}

/// The nodes satisfying `f`. Recursion is bounded by the formula's depth (parser-bounded).
fn eval(
    g: &Kripke,
    succ: &[Vec<u32>],
    f: &Ctl,
    atoms: &[ExprId],
    fair: &FairBits,
    fair_states: &[bool],
) -> Vec<bool> {
    let n = g.n_nodes();
    let rec = |h: &Ctl| eval(g, succ, h, atoms, fair, fair_states);
    match f {
        Ctl::True => vec![true; n],
        Ctl::Atom(e) => {
            let b = atoms.iter().position(|a| a == e).unwrap_or(0);
            (0..n).map(|v| g.node_letter[v] >> b & 1 == 1).collect()
        }
        Ctl::Not(a) => rec(a).into_iter().map(|x| !x).collect(),
        Ctl::And(a, b) => rec(a)
            .into_iter()
            .zip(rec(b))
            .map(|(x, y)| x && y)
            .collect(),
        Ctl::Or(a, b) => rec(a)
            .into_iter()
            .zip(rec(b))
            .map(|(x, y)| x || y)
            .collect(),
        Ctl::Ex(a) => {
            let s = rec(a);
            (0..n)
                .map(|v| {
                    succ[v]
                        .iter()
                        .any(|&w| s[w as usize] && fair_states[w as usize])
                })
                .collect()
        }
        Ctl::Eu(a, b) => {
            let (sa, sb) = (rec(a), rec(b));
            let goal: Vec<bool> = (0..n).map(|v| sb[v] && fair_states[v]).collect();
            backward(succ, &goal, &sa)
        }
        Ctl::Eg(a) => eg(g, succ, &rec(a), fair),
    }
}

/// Nodes with a path through `via` nodes to a `goal` node (least fixpoint, by a backward
/// search over the predecessor lists).
fn backward(succ: &[Vec<u32>], goal: &[bool], via: &[bool]) -> Vec<bool> {
    let n = succ.len();
    let mut pred: Vec<Vec<u32>> = vec![Vec::new(); n];
    for (v, ss) in succ.iter().enumerate() {
        for &w in ss {
            pred[w as usize].push(v as u32);
        }
    }
    let mut out = goal.to_vec();
    let mut stack: Vec<u32> = (0..n as u32).filter(|&v| goal[v as usize]).collect();
    while let Some(w) = stack.pop() {
        for &v in &pred[w as usize] {
            if !out[v as usize] && via[v as usize] {
                out[v as usize] = true;
                stack.push(v);
            }
        }
    }
    out
}

/// Fair `EG s`: the nodes in `s` with a path within `s` to a fair SCC of the subgraph `s`.
fn eg(g: &Kripke, succ: &[Vec<u32>], s: &[bool], fair: &FairBits) -> Vec<bool> {
    let n = g.n_nodes();
    let verts: Vec<u32> = (0..n as u32).filter(|&v| s[v as usize]).collect();
    let succ_in = |v: u32| -> &[u32] { &succ[v as usize] };
    let mut sc = Scratch::new(n);
    let comps = sccs(&verts, &|w| s[w as usize], &succ_in, &mut sc);
    let letter = |v: u32| g.node_letter[v as usize];
    let just: Vec<Box<dyn Fn(u32) -> bool + '_>> = fair
        .justice
        .iter()
        .map(|&b| {
            let f: Box<dyn Fn(u32) -> bool> = Box::new(move |v| letter(v) >> b & 1 == 1);
            f
        })
        .collect();
    let visit: Vec<&dyn Fn(u32) -> bool> = just.iter().map(|b| b.as_ref()).collect();
    let comp_fns: Vec<(BoxPred<'_>, BoxPred<'_>)> = fair
        .compassion
        .iter()
        .map(|&(p, q)| {
            let a: Box<dyn Fn(u32) -> bool> = Box::new(move |v| letter(v) >> p & 1 == 1);
            let b: Box<dyn Fn(u32) -> bool> = Box::new(move |v| letter(v) >> q & 1 == 1);
            (a, b)
        })
        .collect();
    let compassion: Vec<(Pred<'_>, Pred<'_>)> = comp_fns
        .iter()
        .map(|(a, b)| (a.as_ref(), b.as_ref()))
        .collect();
    let fairness = Fairness {
        visit: &visit,
        compassion: &compassion,
    };
    // Every fair cycle within `s` lies in one SCC of `s`; each SCC is searched on its own.
    let mut goal = vec![false; n];
    for comp in comps {
        let mut inside = vec![false; n];
        for &v in &comp {
            inside[v as usize] = true;
        }
        let sub = |v: u32| -> Vec<u32> {
            succ[v as usize]
                .iter()
                .copied()
                .filter(|&w| inside[w as usize])
                .collect()
        };
        let local: Vec<Vec<u32>> = comp.iter().map(|&v| sub(v)).collect();
        let pos: std::collections::HashMap<u32, usize> =
            comp.iter().enumerate().map(|(i, &v)| (v, i)).collect();
        let succ_local = |v: u32| -> &[u32] { &local[pos[&v]] };
        // Repeat: each found fair sub-component marks its SCC's nodes.
        if fair_component(&comp, n, &succ_local, &fairness).is_some() {
            for &v in &comp {
                goal[v as usize] = true;
            }
        }
    }
    backward(succ, &goal, s)
}
