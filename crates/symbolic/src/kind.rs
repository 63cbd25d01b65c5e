//! k-induction with simple-path constraints.
//!
//! Base case: bounded model checking from the reset state. Step case: from any state, `k`
//! constrained frames without the bad output, pairwise-distinct latch states, then the bad
//! output in frame `k`; when that is unsatisfiable and the base case found no trace of `k + 1`
//! frames, the property holds. The simple-path constraints make the method complete for
//! finite circuits (k reaches at most the longest simple path). They are added lazily, only
//! for the pairs of frames a model of the step case makes equal (most pairs never need one).

use crate::aig::Aig;
use crate::bmc::extract;
use crate::engine::{Limits, Outcome};
use crate::sat::{Solver, Start, Unroller};

/// Decide `aig.bad[0]` by k-induction.
pub fn kind(aig: &Aig, limits: &Limits) -> Outcome {
    let Some(&bad) = aig.bad.first() else {
        return Outcome::Proved(None);
    };
    let mut bs = Solver::new();
    let mut bu = Unroller::new(aig, Start::Reset);
    let mut ss = Solver::new();
    let mut su = Unroller::new(aig, Start::Free);
    let latches: Vec<u32> = crate::ic3::coi_latches(aig)
        .into_iter()
        .map(|i| aig.latches[i].var)
        .collect();
    let mut k = 0;
    loop {
        if limits.max_depth.is_some_and(|d| k >= d) {
            return Outcome::Bounded(k);
        }
        if let Some(why) = limits.expired() {
            return Outcome::unknown_after(why, k);
        }
        // Base case: frame k from the reset state.
        for &c in &aig.constraints {
            let x = bu.lit(&mut bs, c, k);
            bs.add(&[x]);
        }
        let b = bu.lit(&mut bs, bad, k);
        match bs.solve(&[b]) {
            Some(true) => return Outcome::Reached(extract(&mut bu, &mut bs, k)),
            Some(false) => bs.add(&[!b]),
            None => return Outcome::unknown_after(limits.why_interrupted(), k),
        }
        // Step case: frames 0..=k free, bad only in frame k, states distinct.
        for &c in &aig.constraints {
            let x = su.lit(&mut ss, c, k);
            ss.add(&[x]);
        }
        if k > 0 {
            let prev = su.lit(&mut ss, bad, k - 1);
            ss.add(&[!prev]);
        }
        for &v in &latches {
            // Encode frame k's latches now, so reading them from a model adds no clauses.
            su.lit(&mut ss, crate::aig::Lit::var_lit(v), k);
        }
        let b = su.lit(&mut ss, bad, k);
        // Simple-path constraints are added lazily: only for pairs of frames whose states the
        // solver made equal.
        loop {
            match ss.solve(&[b]) {
                Some(false) => return Outcome::Proved(None),
                Some(true) => {}
                None => return Outcome::unknown_after(limits.why_interrupted(), k + 1),
            }
            if let Some(why) = limits.expired() {
                return Outcome::unknown_after(why, k + 1);
            }
            let states: Vec<Vec<bool>> = (0..=k)
                .map(|t| {
                    latches
                        .iter()
                        .map(|&v| {
                            let x = su.lit(&mut ss, crate::aig::Lit::var_lit(v), t);
                            ss.value(x)
                        })
                        .collect()
                })
                .collect();
            let mut equal = Vec::new();
            for i in 0..=k {
                for j in i + 1..=k {
                    if states[i] == states[j] {
                        equal.push((i, j));
                    }
                }
            }
            if equal.is_empty() {
                break;
            }
            for (i, j) in equal {
                let mut diff = Vec::with_capacity(latches.len());
                for &v in &latches {
                    let l = crate::aig::Lit::var_lit(v);
                    let x = su.lit(&mut ss, l, i);
                    let y = su.lit(&mut ss, l, j);
                    let d = ss.fresh();
                    // d -> (x xor y)
                    ss.add(&[!d, x, y]);
                    ss.add(&[!d, !x, !y]);
                    diff.push(d);
                }
                ss.add(&diff);
            }
        }
        k += 1;
    }
}
