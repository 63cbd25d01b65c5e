//! A justice property in ABC's own liveness convention, for the ABC builds that do not read
//! AIGER 1.9's justice sections (`statecheck export aiger --abc-liveness`).
//!
//! ABC's `l2s` reads a liveness property from the outputs' names: every `assume_fair_K`
//! output must hold infinitely often and the `assert_fair_0` output must not, so a loop on
//! which every `assume_fair` output holds (and the constant-false `assert_fair_0` trivially
//! does not) is a counterexample: exactly a run on which every justice literal of ours holds
//! infinitely often. AIGER's invariant constraint has no place in that convention, so it is
//! folded into a latch "every step so far was allowed" (reset true) that gates each signal:
//! after a disallowed step no signal holds again, so no such run is accepted.

use super::write::binary;
use crate::aig::{Aig, Lit};

/// Justice property 0 of `j` (with its fairness literals) in ABC's liveness convention, as
/// binary AIGER (module doc). `None` when `j` has no justice property.
pub fn abc_liveness(j: &Aig, comment: &str) -> Option<Vec<u8>> {
    let first = j.justice.first()?;
    let mut g = j.clone();
    let cons = g.constraints.clone();
    let c = g.and_all(cons);
    let ok = g.latch(Some(true), Some("ok".into()));
    let ok_now = g.and(ok, c);
    let oi = g.latches.len() - 1;
    g.set_next(oi, ok_now);
    g.constraints.clear();
    let mut outs = Vec::new();
    let mut names = Vec::new();
    let signals: Vec<Lit> = first.iter().chain(&j.fairness).copied().collect();
    for (k, l) in signals.into_iter().enumerate() {
        outs.push(g.and(l, ok_now));
        names.push(format!("assume_fair_{k}"));
    }
    outs.push(Lit::FALSE);
    names.push("assert_fair_0".to_string());
    g.bad = outs;
    g.bad_names = vec![None; names.len()];
    g.input_names = vec![None; g.inputs.len()];
    g.latch_names = vec![None; g.latches.len()];
    g.justice.clear();
    g.justice_names.clear();
    g.fairness.clear();
    // ABC reads the outputs of AIGER 1.0 and names them; our writer puts bad outputs where
    // AIGER 1.0 puts outputs, so only the header's counts change (`aig M I L O A`, the bad
    // count moved to the outputs), and the output names follow the AND gates.
    let bytes = binary(&g, "");
    let nl = bytes.iter().position(|&b| b == b'\n')?;
    let h: Vec<u64> = std::str::from_utf8(&bytes[..nl])
        .ok()?
        .split(' ')
        .skip(1)
        .map(|x| x.parse().ok())
        .collect::<Option<_>>()?;
    let (m, i, l, b, a) = (h.first()?, h.get(1)?, h.get(2)?, h.get(5)?, h.get(4)?);
    let mut out = format!("aig {m} {i} {l} {b} {a}").into_bytes();
    out.extend_from_slice(&bytes[nl..]);
    for (k, n) in names.iter().enumerate() {
        out.extend_from_slice(format!("o{k} {n}\n").as_bytes());
    }
    if !comment.is_empty() {
        out.extend_from_slice(format!("c\n{comment}\n").as_bytes());
    }
    Some(out)
}
