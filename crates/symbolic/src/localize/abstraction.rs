//! The abstract circuit of a set of kept latches: every other latch becomes a free input.

use crate::aig::{Aig, Lit, Node};

/// A circuit in which only some latches of a concrete one are latches.
#[derive(Clone, Debug)]
pub(crate) struct Abstraction {
    /// The abstract circuit: the concrete inputs first, in order (so an input vector of the
    /// concrete circuit is a prefix of an abstract one), then one input per freed latch.
    pub aig: Aig,
    /// The concrete latch of each latch of [`Abstraction::aig`].
    pub origin: Vec<usize>,
}

/// The latches the bad outputs of `aig` read in the same tick (their combinational support:
/// the search stops at latches, it does not follow next-state functions). Not those the
/// constraints read: of a blasted model, "no run-time error" reads nearly every latch, and a
/// freed latch under a constraint is still an over-approximation (the constraint only
/// restricts the free value); refinement adds the ones a refutation needs.
pub(crate) fn support(aig: &Aig) -> Vec<bool> {
    comb_support(aig, aig.bad.iter().copied())
}

/// The latches the literals `roots` read in the same tick.
pub(crate) fn comb_support(aig: &Aig, roots: impl Iterator<Item = Lit>) -> Vec<bool> {
    let mut keep = vec![false; aig.latches.len()];
    let mut seen = vec![false; aig.nodes.len()];
    let mut stack: Vec<u32> = roots.map(|l| l.var()).collect();
    while let Some(v) = stack.pop() {
        if std::mem::replace(&mut seen[v as usize], true) {
            continue;
        }
        match aig.nodes[v as usize] {
            Node::And(a, b) => {
                stack.push(a.var());
                stack.push(b.var());
            }
            Node::Latch(i) => keep[i as usize] = true,
            Node::False | Node::Input(_) => {}
        }
    }
    keep
}

/// The latches the next-state functions of the `keep` latches read: one step further back.
pub(crate) fn grow(aig: &Aig, keep: &[bool]) -> Vec<bool> {
    let roots = aig
        .latches
        .iter()
        .zip(keep)
        .filter(|(_, &k)| k)
        .map(|(l, _)| l.next);
    let more = comb_support(aig, roots);
    keep.iter().zip(more).map(|(&a, b)| a || b).collect()
}

impl Abstraction {
    /// `aig` with the latches not in `keep` made inputs, reduced to the cone of influence of
    /// its bad output and constraints.
    pub(crate) fn new(aig: &Aig, keep: &[bool]) -> Abstraction {
        let mut g = Aig::new();
        let mut map: Vec<Lit> = vec![Lit::FALSE; aig.nodes.len()];
        for (i, &v) in aig.inputs.iter().enumerate() {
            map[v as usize] = g.input(aig.input_names[i].clone());
        }
        let mut kept = Vec::new();
        for (i, l) in aig.latches.iter().enumerate() {
            if keep[i] {
                map[l.var as usize] = g.latch(l.init, aig.latch_names[i].clone());
                kept.push(i);
            }
        }
        for (i, l) in aig.latches.iter().enumerate() {
            if !keep[i] {
                map[l.var as usize] = g.input(aig.latch_names[i].clone());
            }
        }
        for (v, n) in aig.nodes.iter().enumerate() {
            if let Node::And(a, b) = *n {
                let (x, y) = (map[a.var() as usize], map[b.var() as usize]);
                map[v] = g.and(x.xor(a.is_neg()), y.xor(b.is_neg()));
            }
        }
        let m = |l: Lit| map[l.var() as usize].xor(l.is_neg());
        for (k, &i) in kept.iter().enumerate() {
            g.set_next(k, m(aig.latches[i].next));
        }
        g.bad = aig.bad.iter().map(|&l| m(l)).collect();
        g.bad_names = aig.bad_names.clone();
        g.constraints = aig.constraints.iter().map(|&l| m(l)).collect();
        let (reduced, in_cone) = g.reduced_with_latches();
        Abstraction {
            aig: reduced,
            origin: in_cone.iter().map(|&k| kept[k]).collect(),
        }
    }
}
