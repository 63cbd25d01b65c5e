//! A BDD built directly from a set of minterms, in time linear in the number of minterms
//! times the number of variables (no chain of BDD operations): the explicit engine's guards.
//!
//! The minterms are sorted bit strings (variable 0 first); level by level from the last
//! variable up, each group of minterms that agree on the variables above becomes one node,
//! with a unique table so that equal subgraphs are shared. The result is the reduced BDD.

use biodivine_lib_bdd::{Bdd, BddNode, BddPointer, BddVariable, BddVariableSet};
use std::collections::HashMap;

/// Bit `v` of a minterm: variable `v` is bit `63 - v % 64` of word `v / 64`.
#[inline]
fn bit(m: &[u64], v: usize) -> bool {
    (m[v / 64] >> (63 - v % 64)) & 1 == 1
}

fn lcp(a: &[u64], b: &[u64], nv: usize) -> usize {
    for (w, (x, y)) in a.iter().zip(b).enumerate() {
        let d = x ^ y;
        if d != 0 {
            return (w * 64 + d.leading_zeros() as usize).min(nv);
        }
    }
    nv
}

/// Set a variable's bit in a minterm.
pub fn set_bit(m: &mut [u64], v: usize, value: bool) {
    let b = 1u64 << (63 - v % 64);
    if value {
        m[v / 64] |= b;
    } else {
        m[v / 64] &= !b;
    }
}

/// The BDD over the variables of `vars` of the minterms in `terms` (`words` words each, in any order;
/// duplicates allowed).
pub fn from_minterms(vars: &BddVariableSet, words: usize, terms: &mut [u64]) -> Bdd {
    let nv = vars.num_vars();
    let n = terms.len() / words.max(1);
    let mut idx: Vec<usize> = (0..n).collect();
    idx.sort_unstable_by(|&a, &b| {
        terms[a * words..(a + 1) * words].cmp(&terms[b * words..(b + 1) * words])
    });
    idx.dedup_by(|a, b| terms[*a * words..(*a + 1) * words] == terms[*b * words..(*b + 1) * words]);
    if idx.is_empty() {
        return vars.mk_false();
    }
    let nvu = nv as usize;
    let term = |i: usize| &terms[i * words..(i + 1) * words];
    // (representative minterm, node, longest common prefix with the next entry's minterm)
    let mut entries: Vec<(usize, u32, usize)> = idx
        .iter()
        .enumerate()
        .map(|(k, &i)| {
            let l = idx.get(k + 1).map_or(0, |&j| lcp(term(i), term(j), nvu));
            (i, 1u32, l)
        })
        .collect();
    let mut nodes = vec![BddNode::mk_zero(nv), BddNode::mk_one(nv)];
    let mut unique: HashMap<(usize, u32, u32), u32> = HashMap::new();
    let mut mk = |v: usize, lo: u32, hi: u32, nodes: &mut Vec<BddNode>| -> u32 {
        if lo == hi {
            return lo;
        }
        *unique.entry((v, lo, hi)).or_insert_with(|| {
            nodes.push(BddNode::mk_node(
                BddVariable::from_index(v),
                BddPointer::from_index(lo as usize),
                BddPointer::from_index(hi as usize),
            ));
            (nodes.len() - 1) as u32
        })
    };
    for v in (0..nvu).rev() {
        let mut next = Vec::with_capacity(entries.len());
        let mut i = 0;
        while i < entries.len() {
            let (rep, ptr, l) = entries[i];
            if i + 1 < entries.len() && l >= v {
                // Same prefix above `v`, so they differ at `v`: the first has 0 there.
                let (_, hi, l2) = entries[i + 1];
                next.push((rep, mk(v, ptr, hi, &mut nodes), l2));
                i += 2;
            } else {
                let node = if bit(term(rep), v) {
                    mk(v, 0, ptr, &mut nodes)
                } else {
                    mk(v, ptr, 0, &mut nodes)
                };
                next.push((rep, node, l));
                i += 1;
            }
        }
        entries = next;
    }
    // Every node built is reachable from the last one, the root, and children come first.
    Bdd::from_nodes(&nodes).unwrap_or_else(|_| vars.mk_false())
}

#[cfg(test)]
mod tests {
    use super::*;
    use biodivine_lib_bdd::{BddPartialValuation, BddVariableSet};

    /// Every subset of the 16 minterms over 4 variables (the first 300 subsets, and some
    /// larger ones): the built BDD equals the disjunction of the minterms built by the
    /// library.
    #[test]
    fn equals_library_disjunction() {
        let vars = BddVariableSet::new_anonymous(4);
        let vs = vars.variables();
        for set in (0u32..300).chain([0xffff, 0x8001, 0x7ffe, 0xa5a5]) {
            let mut terms = Vec::new();
            let mut clauses = Vec::new();
            for m in 0..16u64 {
                if set >> m & 1 == 1 {
                    let mut w = [0u64];
                    let vals: Vec<_> = (0..4)
                        .map(|v| {
                            let b = m >> v & 1 == 1;
                            set_bit(&mut w, v, b);
                            (vs[v], b)
                        })
                        .collect();
                    terms.push(w[0]);
                    terms.push(w[0]); // a duplicate
                    clauses.push(BddPartialValuation::from_values(&vals));
                }
            }
            let built = from_minterms(&vars, 1, &mut terms);
            assert!(built.xor(&vars.mk_dnf(&clauses)).is_false(), "set {set:#x}");
            assert!(built.validate().is_ok());
        }
    }
}
