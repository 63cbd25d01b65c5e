//! Liveness as safety, two ways, on a [`Justice`] circuit.
//!
//! - [`l2s`]: Biere, Artho and Schuppan, "Liveness checking as safety checking" (2002). An
//!   input `save` (taken once) copies the state into shadow latches; from then on a latch per
//!   fairness signal records that it was seen. The bad output is "saved, the state equals the
//!   copy, and every justice signal was seen since the save (and, per compassion pair, the
//!   response if the trigger)": a trace to it is a lasso whose loop is fair. Complete for
//!   justice and compassion: every fair lasso of the circuit is such a trace.
//! - [`klive`]: Claessen and Sörensson, "A liveness checking algorithm that counts" (2012).
//!   The justice signals are merged into one (a latch per signal remembers it was seen since
//!   the merged signal last fired), and a counter saturating at `k + 1` counts its firings; the
//!   bad output is the `k + 1`-th. If no trace reaches it, no run fires the merged signal more
//!   than `k` times, so no run is fair: the property holds. It proves only (compassion is not
//!   handled: the caller says so).

use super::Justice;
use crate::aig::{Aig, Lit};

/// The circuit of [`l2s`], with where its `save` input is.
#[derive(Clone, Debug)]
pub struct L2s {
    /// The safety circuit: the justice circuit's inputs, then `save`; one bad output.
    pub aig: Aig,
    /// The input index of `save`: the first frame where it is set is the loop's first frame.
    pub save: usize,
}

/// A latch that records `x` on the frames where `on` holds (the value is the disjunction of
/// `x` over earlier such frames).
fn seen(g: &mut Aig, on: Lit, x: Lit, name: String) -> Lit {
    let l = g.latch(Some(false), Some(name));
    let v = g.or(l, x);
    let next = g.and(on, v);
    let li = g.nodes[l.var() as usize].latch_index();
    g.set_next(li, next);
    l
}

/// Liveness to safety (module doc).
pub fn l2s(j: &Justice) -> L2s {
    let mut g = j.aig.clone();
    let originals: Vec<Lit> = g.latches.iter().map(|l| Lit::var_lit(l.var)).collect();
    let save_index = g.inputs.len();
    let save = g.input(Some("l2s_save".into()));
    let saved = g.latch(Some(false), Some("l2s_saved".into()));
    let save_now = g.and(save, !saved);
    let in_loop = g.or(saved, save_now);
    let si = g.nodes[saved.var() as usize].latch_index();
    g.set_next(si, in_loop);
    let mut eqs = Vec::with_capacity(originals.len());
    for (k, &l) in originals.iter().enumerate() {
        let c = g.latch(Some(false), Some(format!("l2s_copy[{k}]")));
        let next = g.mux(save_now, l, c);
        let ci = g.nodes[c.var() as usize].latch_index();
        g.set_next(ci, next);
        eqs.push(g.iff(l, c));
    }
    let mut loop_ok = eqs;
    loop_ok.push(saved);
    for (k, &x) in j.justice.iter().enumerate() {
        loop_ok.push(seen(&mut g, in_loop, x, format!("l2s_justice[{k}]")));
    }
    for (k, &(p, q)) in j.compassion.iter().enumerate() {
        let sp = seen(&mut g, in_loop, p, format!("l2s_trigger[{k}]"));
        let sq = seen(&mut g, in_loop, q, format!("l2s_response[{k}]"));
        loop_ok.push(g.or(!sp, sq));
    }
    let bad = g.and_all(loop_ok);
    g.bad = vec![bad];
    g.bad_names = vec![Some("l2s".into())];
    L2s {
        aig: g.reduced(),
        save: save_index,
    }
}

/// The safety circuit of k-liveness with bound `k` (module doc); the justice circuit's
/// compassion pairs are ignored (the caller must not claim a proof when there are any).
pub fn klive(j: &Justice, k: u32) -> Aig {
    let mut g = j.aig.clone();
    // Merge the justice signals: `all` fires when each was seen since it last fired.
    let marks: Vec<Lit> = (0..j.justice.len())
        .map(|i| g.latch(Some(false), Some(format!("klive_seen[{i}]"))))
        .collect();
    let seen_now: Vec<Lit> = marks
        .iter()
        .zip(&j.justice)
        .map(|(&m, &x)| g.or(m, x))
        .collect();
    let all = g.and_all(seen_now.iter().copied());
    for (&m, &s) in marks.iter().zip(&seen_now) {
        let next = g.and(!all, s);
        let mi = g.nodes[m.var() as usize].latch_index();
        g.set_next(mi, next);
    }
    // A counter of firings of `all` before this frame, saturating at k + 1.
    let w = (u32::BITS - (k + 1).leading_zeros()).max(1) as usize;
    let count: Vec<Lit> = (0..w)
        .map(|i| g.latch(Some(false), Some(format!("klive_count[{i}]"))))
        .collect();
    let at = |g: &mut Aig, v: u32| {
        let bits: Vec<Lit> = count
            .iter()
            .enumerate()
            .map(|(i, &b)| b.xor(v >> i & 1 == 0))
            .collect();
        g.and_all(bits)
    };
    let at_k = at(&mut g, k);
    // Increment (ripple carry) when `all` fires.
    let mut carry = all;
    for &b in &count {
        let next = g.xor(b, carry);
        carry = g.and(b, carry);
        let bi = g.nodes[b.var() as usize].latch_index();
        g.set_next(bi, next);
    }
    // The (k + 1)-th firing.
    let bad = g.and(all, at_k);
    g.bad = vec![bad];
    g.bad_names = vec![Some(format!("klive_{k}"))];
    g.reduced()
}
