//! Proving candidate equalities by induction, refining the classes by the counterexamples.
//!
//! The base case checks every equality in the reset frame (inputs free, constraints holding).
//! The inductive step (van Eijk's method with speculative reduction, as in ABC's `scorr`)
//! builds two frames: in frame 0 the state is free and every member is *replaced* by its
//! representative — assuming all equalities at once, and shrinking the formula — and frame 1
//! follows by one transition; the constraints hold in both. An equality that can differ in
//! frame 1 is refuted: the solver's model, simulated through both frames, splits every class
//! it separates. A round that refutes nothing proves the remaining equalities inductive.
//! Refuting an equality only removes an assumption, so the base case stays true throughout.

use super::classes::Classes;
use super::signature::{eval, Rng};
use crate::aig::{Aig, Lit, Node};
use crate::engine::Limits;
use crate::error::{Error, ErrorKind};
use crate::sat::{Solver, Start, Unroller};

/// What the refinement did.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Rounds {
    /// Rounds of the inductive step (the last one refuted nothing).
    pub rounds: usize,
    /// SAT calls.
    pub calls: usize,
    /// Equalities refuted by a SAT model.
    pub refuted: usize,
}

/// One or two frames of the circuit as a combinational graph `g` over fresh inputs: the
/// literal of every original variable in each frame, and the constraints of every frame.
struct Frames {
    g: Aig,
    at: Vec<Vec<Lit>>,
    constraints: Vec<Lit>,
}

/// Frame 0 at reset (`speculate == false`) or free and speculatively reduced by `repr`;
/// `frames` is 1 or 2.
fn unroll(aig: &Aig, repr: &[Option<(u32, bool)>], speculate: bool, frames: usize) -> Frames {
    let mut g = Aig::new();
    let mut at: Vec<Vec<Lit>> = Vec::new();
    for t in 0..frames {
        let mut m = vec![Lit::FALSE; aig.nodes.len()];
        for (v, node) in aig.nodes.iter().enumerate() {
            let x = match *node {
                Node::False => Lit::FALSE,
                Node::Input(_) => g.input(None),
                Node::Latch(i) => {
                    let l = &aig.latches[i as usize];
                    match (t, speculate, l.init) {
                        (0, false, Some(b)) => Lit::constant(b),
                        (0, _, _) => g.input(None),
                        _ => {
                            let prev: &Vec<Lit> = &at[t - 1];
                            prev[l.next.var() as usize].xor(l.next.is_neg())
                        }
                    }
                }
                Node::And(a, b) => {
                    let (x, y) = (m[a.var() as usize], m[b.var() as usize]);
                    g.and(x.xor(a.is_neg()), y.xor(b.is_neg()))
                }
            };
            m[v] = match repr[v] {
                Some((r, p)) if speculate && t == 0 => m[r as usize].xor(p),
                _ => x,
            };
        }
        at.push(m);
    }
    let constraints = at
        .iter()
        .flat_map(|m| {
            aig.constraints
                .iter()
                .map(move |c| m[c.var() as usize].xor(c.is_neg()))
        })
        .collect();
    Frames { g, at, constraints }
}

/// Refute equalities checked in the last frame of `unroll(.., speculate, frames)` until one
/// pass refutes none; `Ok(true)` when some class was refined. `Err`: a limit or solver failure.
fn pass(
    aig: &Aig,
    classes: &mut Classes,
    speculate: bool,
    frames: usize,
    limits: &Limits,
    stats: &mut Rounds,
) -> Result<bool, Error> {
    let repr = classes.repr_map(aig.nodes.len());
    let mut f = unroll(aig, &repr, speculate, frames);
    let last = frames - 1;
    // Miters for every claimed equality, built before the solver borrows the graph.
    let miters: Vec<(u32, u32, bool, Lit)> = classes
        .pairs()
        .into_iter()
        .map(|(v, r, p)| {
            let (x, y) = (f.at[last][v as usize], f.at[last][r as usize].xor(p));
            (v, r, p, f.g.xor(x, y))
        })
        .filter(|m| m.3 != Lit::FALSE)
        .collect();
    let mut miters = miters;
    miters.sort_unstable_by_key(|m| m.0);
    let g = f.g;
    let mut s = Solver::plain();
    let mut u = Unroller::new(&g, Start::Free);
    for &c in &f.constraints {
        let l = u.lit(&mut s, c, 0);
        s.add(&[l]);
    }
    let mut changed = false;
    let mut rng = Rng::new(0xC0FFEE ^ stats.calls as u64);
    let mut live = classes.repr_map(aig.nodes.len());
    // Miters in topological order, one call each; a proved equality becomes a clause, so the
    // later miters above it are local problems (SAT sweeping's cut points).
    for &(v, r, p, miter) in &miters {
        if live[v as usize] != Some((r, p)) {
            continue;
        }
        if let Some(why) = limits.expired() {
            return Err(Error::of(ErrorKind::Limit(why)));
        }
        let m = u.lit(&mut s, miter, 0);
        stats.calls += 1;
        match s.solve(&[m]) {
            Some(false) => s.add(&[!m]),
            Some(true) => {
                let ins = u.inputs(&mut s, 0);
                resimulate(&g, &f.constraints, &f.at[last], &ins, classes, &mut rng);
                stats.refuted += 1;
                changed = true;
                live = classes.repr_map(aig.nodes.len());
            }
            None => return Err(Error::of(ErrorKind::SolverFailed)),
        }
    }
    Ok(changed)
}

/// Refine `classes` until every remaining equality holds initially and inductively.
pub(crate) fn prove(aig: &Aig, classes: &mut Classes, limits: &Limits) -> Result<Rounds, Error> {
    let mut stats = Rounds::default();
    while pass(aig, classes, false, 1, limits, &mut stats)? {}
    loop {
        stats.rounds += 1;
        if !pass(aig, classes, true, 2, limits, &mut stats)? {
            return Ok(stats);
        }
    }
}

/// Refine by the model `ins` of `g` and by 63 neighbours of it (about one input in 32
/// flipped): every lane where the constraints hold is a point where the speculative frame 0
/// holds by construction, so its values in `frame` are a valid sample.
fn resimulate(
    g: &Aig,
    constraints: &[Lit],
    frame: &[Lit],
    ins: &[bool],
    classes: &mut Classes,
    rng: &mut Rng,
) {
    let words: Vec<u64> = ins
        .iter()
        .map(|&b| {
            let flips = rng.next() & rng.next() & rng.next() & rng.next() & rng.next() & !1;
            (if b { !0 } else { 0 }) ^ flips
        })
        .collect();
    let mut val = vec![0u64; g.nodes.len()];
    eval(g, 1, &words, &[], &mut val);
    let word = |l: Lit| val[l.var() as usize] ^ if l.is_neg() { !0 } else { 0 };
    let ok = constraints.iter().fold(!0u64, |m, &c| m & word(c)) | 1;
    classes.refine_lanes(|x| word(frame[x as usize]), ok);
}
