//! The circuit with every proved member replaced by its representative.
//!
//! The equalities are proved where the invariant constraints hold, so the merged circuit
//! agrees with the original on every valid trace of the original, step by step: there the
//! constraints hold, the equalities hold, and so the merged constraints, next states and bad
//! outputs have the original's values. Every valid trace of the original is therefore a valid
//! trace of the merged circuit with the same outputs, and a proof on the merged circuit is a
//! proof on the original. The converse can fail — on an input that violates the original
//! constraint, the merged one may hold — so a counterexample of the merged circuit is
//! replayed on the original before it is believed ([`super::Reduction::lift`]).

use crate::aig::{Aig, Lit, Node};

/// The merged circuit (before cone-of-influence reduction) and the original latch of each of
/// its latches.
pub(crate) fn merge(aig: &Aig, repr: &[Option<(u32, bool)>]) -> (Aig, Vec<usize>) {
    let mut g = Aig::new();
    let mut origin: Vec<usize> = Vec::new();
    let mut map = vec![Lit::FALSE; aig.nodes.len()];
    for (v, node) in aig.nodes.iter().enumerate() {
        map[v] = match (*node, repr[v]) {
            (Node::Input(i), _) => g.input(aig.input_names[i as usize].clone()),
            (_, Some((r, p))) => map[r as usize].xor(p),
            (Node::False, None) => Lit::FALSE,
            (Node::Latch(i), None) => {
                origin.push(i as usize);
                g.latch(
                    aig.latches[i as usize].init,
                    aig.latch_names[i as usize].clone(),
                )
            }
            (Node::And(a, b), None) => {
                let (x, y) = (map[a.var() as usize], map[b.var() as usize]);
                g.and(x.xor(a.is_neg()), y.xor(b.is_neg()))
            }
        };
    }
    let m = |l: Lit| map[l.var() as usize].xor(l.is_neg());
    for (k, &i) in origin.iter().enumerate() {
        g.set_next(k, m(aig.latches[i].next));
    }
    g.bad = aig.bad.iter().map(|&b| m(b)).collect();
    g.bad_names = aig.bad_names.clone();
    g.constraints = aig
        .constraints
        .iter()
        .map(|&c| m(c))
        .filter(|&c| c != Lit::TRUE)
        .collect();
    (g, origin)
}
