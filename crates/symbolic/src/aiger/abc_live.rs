//! A justice property in ABC's own liveness conventions, for the ABC builds that do not read
//! AIGER 1.9's justice sections (`statecheck export aiger --abc-liveness` and `--abc-kcs`).
//!
//! ABC's `l2s` reads a liveness property from the outputs' names: every `assume_fair_K`
//! output must hold infinitely often and the `assert_fair_0` output must not, so a loop on
//! which every `assume_fair` output holds (and the constant-false `assert_fair_0` trivially
//! does not) is a counterexample: exactly a run on which every justice literal of ours holds
//! infinitely often ([`abc_liveness`]).
//!
//! ABC's `kcs` (its k-liveness, Claessen–Sörensson) proves a *stabilisation* `F G t` of the
//! output named `csLiveTarget_0` (conjunctions with `csLiveConst_K` outputs aside): it counts
//! the ticks where `t` is false and proves with IC3 that they are at most k, for k = 1, 2, …
//! A justice property holds exactly when its accepting condition holds only finitely often,
//! so `t` is the negated acceptance; several literals (the justice set and the fairness
//! constraints) are first merged into one by the standard degeneralisation: a latch per
//! literal remembers that it was seen since the last acceptance, and the acceptance is the
//! tick that completes the set, which then starts again ([`abc_kcs`]). `kcs` only proves:
//! on a violated property it reports "DISPROVED" for every k it tries.
//!
//! AIGER's invariant constraint has no place in either convention, so it is folded into a
//! latch "every step so far was allowed" (reset true) that gates each literal: after a
//! disallowed step no literal holds again, so no such run is accepted.

use super::write::binary;
use crate::aig::{Aig, Lit};

/// Justice property 0 of `j` (with its fairness literals) in ABC's `l2s` convention, as
/// binary AIGER (module doc). `None` when `j` has no justice property.
pub fn abc_liveness(j: &Aig, comment: &str) -> Option<Vec<u8>> {
    let (mut g, signals) = gated(j)?;
    let mut names: Vec<String> = (0..signals.len())
        .map(|k| format!("assume_fair_{k}"))
        .collect();
    let mut outs = signals;
    outs.push(Lit::FALSE);
    names.push("assert_fair_0".to_string());
    g.bad = outs;
    with_named_outputs(g, &names, comment)
}

/// Justice property 0 of `j` (with its fairness literals) in ABC's `kcs` convention: one
/// output `csLiveTarget_0`, false exactly at the accepting ticks of the merged literals
/// (module doc), as binary AIGER. `None` when `j` has no justice property.
pub fn abc_kcs(j: &Aig, comment: &str) -> Option<Vec<u8>> {
    let (mut g, signals) = gated(j)?;
    let accept = if let [one] = signals.as_slice() {
        *one
    } else {
        let seen: Vec<(usize, Lit)> = signals
            .iter()
            .enumerate()
            .map(|(k, _)| {
                let l = g.latch(Some(false), Some(format!("seen_{k}")));
                (g.latches.len() - 1, l)
            })
            .collect();
        let now: Vec<Lit> = seen
            .iter()
            .zip(&signals)
            .map(|(&(_, s), &l)| g.or(s, l))
            .collect();
        let all = g.and_all(now.iter().copied());
        for (&(i, _), &n) in seen.iter().zip(&now) {
            let next = g.and(!all, n);
            g.set_next(i, next);
        }
        all
    };
    g.bad = vec![!accept];
    with_named_outputs(g, &["csLiveTarget_0".to_string()], comment)
}

/// `j` with its constraint folded into a latch `ok`, and its justice property 0's literals
/// and fairness literals, each gated by "every step so far, this one included, was allowed".
fn gated(j: &Aig) -> Option<(Aig, Vec<Lit>)> {
    let first = j.justice.first()?;
    let mut g = j.clone();
    let cons = g.constraints.clone();
    let c = g.and_all(cons);
    let ok = g.latch(Some(true), Some("ok".into()));
    let ok_now = g.and(ok, c);
    let oi = g.latches.len() - 1;
    g.set_next(oi, ok_now);
    g.constraints.clear();
    g.justice.clear();
    g.justice_names.clear();
    g.fairness.clear();
    let signals = first
        .iter()
        .chain(&j.fairness)
        .map(|&l| g.and(l, ok_now))
        .collect();
    Some((g, signals))
}

/// `g`'s bad literals written as AIGER 1.0 outputs named `names`, as binary AIGER.
fn with_named_outputs(mut g: Aig, names: &[String], comment: &str) -> Option<Vec<u8>> {
    g.bad_names = vec![None; g.bad.len()];
    g.input_names = vec![None; g.inputs.len()];
    g.latch_names = vec![None; g.latches.len()];
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
