//! An LTL property as a justice problem: the step circuit in product with the IR's Büchi
//! automaton of the property's negation ([`statecheck_ir::temporal::buchi`], the automaton
//! the explicit engine reads too), lowered into extra latches and inputs.
//!
//! Frame `i` of the circuit is tick `i`, and the position it produces (the post-state with
//! the tick's inputs) is where the atoms are read ([`Blasted::atoms`]). The monitor's latches
//! hold the automaton state that read the previous position (a code `n` for "none yet"); each
//! frame, choice inputs name the state that reads this position, and the constraint admits the
//! choice when it is an initial state (first frame) or a successor, and its literals hold.
//! The automaton's acceptance sets become justice signals (the chosen state is in the set),
//! followed by the fairness constraints' justice signals; compassion constraints are kept as
//! pairs.

use crate::aig::{Aig, Lit};
use crate::blast::Blasted;
use crate::bv::{self, Bv};
use statecheck_ir::temporal::buchi::{self, TranslateError};
use statecheck_ir::temporal::{Fairness, Ltl};

/// A circuit with constraints and fairness signals: its fair runs are the counterexamples.
#[derive(Clone, Debug)]
pub struct Justice {
    /// The circuit: every input of [`Blasted::aig`] first, in order, then the monitor's;
    /// `bad` is empty, `constraints` holds the one transition constraint.
    pub aig: Aig,
    /// Signals that must each hold infinitely often on a counterexample.
    pub justice: Vec<Lit>,
    /// Pairs `(p, q)`: if `p` holds infinitely often on a counterexample, so does `q`.
    pub compassion: Vec<(Lit, Lit)>,
}

/// The justice problem of "some fair run violates `f`" on `bl` (whose atoms include `f`'s
/// and the fairness constraints'), under `fairness`.
pub fn monitor(bl: &Blasted, f: &Ltl, fairness: &[Fairness]) -> Result<Justice, TranslateError> {
    let mut atoms = Vec::new();
    let aut = buchi::translate(&f.clone().negate(), &mut atoms)?;
    let mut g = bl.aig.clone();
    let atom = |e| {
        bl.atoms
            .iter()
            .find(|&&(a, _)| a == e)
            .map_or(Lit::FALSE, |&(_, l)| l)
    };
    let lits: Vec<Lit> = atoms.iter().map(|&e| atom(e)).collect();
    let n = aut.states.len();
    let w = (usize::BITS - n.leading_zeros()).max(1) as usize;
    // The automaton state that read the previous position; `n` before position 0.
    let cur: Vec<Lit> = (0..w)
        .map(|i| g.latch(Some((n >> i) & 1 == 1), Some(format!("buchi[{i}]"))))
        .collect();
    let choice: Vec<Lit> = (0..w)
        .map(|i| g.input(Some(format!("buchi_next[{i}]"))))
        .collect();
    let as_bv = |bits: &[Lit]| Bv {
        bits: bits.iter().copied().chain([Lit::FALSE]).collect(),
        lo: 0,
        hi: (1i128 << w) - 1,
    };
    let (cur_v, choice_v) = (as_bv(&cur), as_bv(&choice));
    let is_cur: Vec<Lit> = (0..=n)
        .map(|p| bv::eq(&mut g, &cur_v, &Bv::constant(p as i128)))
        .collect();
    let mut preds: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (p, succ) in aut.succ.iter().enumerate() {
        for &q in succ {
            preds[q as usize].push(p);
        }
    }
    for &q in &aut.initial {
        preds[q as usize].push(n);
    }
    let mut chosen = Vec::with_capacity(n);
    let mut oks = Vec::with_capacity(n);
    for (q, st) in aut.states.iter().enumerate() {
        let is_q = bv::eq(&mut g, &choice_v, &Bv::constant(q as i128));
        chosen.push(is_q);
        let mut label = Vec::new();
        for (k, &l) in lits.iter().enumerate() {
            if st.pos >> k & 1 == 1 {
                label.push(l);
            }
            if st.neg >> k & 1 == 1 {
                label.push(!l);
            }
        }
        let label = g.and_all(label);
        let pred = g.or_all(preds[q].iter().map(|&p| is_cur[p]));
        let ok = g.and_all([is_q, label, pred]);
        oks.push(ok);
    }
    let mon_ok = g.or_all(oks);
    for (i, &c) in cur.iter().enumerate() {
        let li = g.nodes[c.var() as usize].latch_index();
        g.set_next(li, choice[i]);
    }
    let any_err = g.or_all(bl.errs);
    let c = g.and_all([bl.assume, !any_err, mon_ok]);
    g.constraints = vec![c];
    let mut justice: Vec<Lit> = aut
        .accepting
        .iter()
        .map(|set| {
            let members: Vec<Lit> = (0..n).filter(|&q| set[q]).map(|q| chosen[q]).collect();
            g.or_all(members)
        })
        .collect();
    let mut compassion = Vec::new();
    for f in fairness {
        match f.trigger {
            None => justice.push(atom(f.expr)),
            Some(t) => compassion.push((atom(t), atom(f.expr))),
        }
    }
    if justice.is_empty() {
        justice.push(Lit::TRUE);
    }
    Ok(Justice {
        aig: g,
        justice,
        compassion,
    })
}
