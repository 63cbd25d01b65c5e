//! The concrete check of an abstract counterexample's depth, and the latches that refute it.
//!
//! One incremental unrolling of the concrete circuit in which every latch `j` can be cut
//! loose: its next value is `e_j ? next_j : f_j` (two fresh inputs per frame) and its reset
//! value is asserted only under `a_j`, with `a_j → e_j` in every frame. Under the assumptions
//! `a_j` for every latch the unrolling is the concrete circuit exactly (a model is a concrete
//! trace); when a depth is unsatisfiable under them, the solver's failed assumptions name
//! latches whose transition relation the refutation used — the other latches may be freed
//! and the depth stays refuted (proof-based abstraction, McMillan and Amla 2003; ABC's
//! `&gla` works on the same principle).

use crate::aig::{Aig, Lit};
use crate::engine::{Limits, Trace};
use crate::sat::{SLit, Solver, Start, Unroller};

/// `aig` with every latch made cuttable: inputs `f_j` and `e_j` appended (after the concrete
/// inputs, so concrete input vectors are a prefix), latch `j`'s next value `e_j ? next_j :
/// f_j`, and no reset values (they are asserted under the activation literals instead).
pub(crate) fn cuttable(aig: &Aig) -> Aig {
    let mut g = aig.clone();
    let n = aig.latches.len();
    let f: Vec<Lit> = (0..n).map(|_| g.input(None)).collect();
    let e: Vec<Lit> = (0..n).map(|_| g.input(None)).collect();
    for j in 0..n {
        let next = g.mux(e[j], aig.latches[j].next, f[j]);
        g.set_next(j, next);
        g.latches[j].init = None;
    }
    g
}

/// What a depth check answered.
pub(crate) enum Check {
    /// A concrete trace reaches the bad output in the last frame.
    Real(Trace),
    /// No concrete trace of this depth; the latches the refutation used.
    Refuted(Vec<usize>),
    /// A limit stopped the solver.
    Stopped(String),
}

/// The unrolling of a [`cuttable`] circuit, encoded frame by frame as depths are asked.
pub(crate) struct Concrete<'a> {
    /// The concrete circuit.
    aig: &'a Aig,
    /// Its cuttable copy's unrolling.
    u: Unroller<'a>,
    s: Solver,
    /// One activation literal per latch.
    act: Vec<SLit>,
    /// Frames whose constraints and activation clauses are in the solver.
    frames: usize,
}

impl<'a> Concrete<'a> {
    /// An empty unrolling of `cut` (made by [`cuttable`] from `aig`).
    pub(crate) fn new(aig: &'a Aig, cut: &'a Aig) -> Concrete<'a> {
        let mut s = Solver::new();
        let act: Vec<SLit> = (0..aig.latches.len()).map(|_| s.fresh()).collect();
        let mut u = Unroller::new(cut, Start::Free);
        for (j, l) in aig.latches.iter().enumerate() {
            if let Some(b) = l.init {
                let x = u.lit(&mut s, Lit::var_lit(l.var), 0);
                s.add(&[!act[j], if b { x } else { !x }]);
            }
        }
        Concrete {
            aig,
            u,
            s,
            act,
            frames: 0,
        }
    }

    /// Encode frames up to `k` (constraints hold in each; `a_j → e_j`).
    fn extend(&mut self, k: usize) {
        let n = self.aig.inputs.len();
        let nl = self.aig.latches.len();
        let cut = self.u.aig();
        while self.frames <= k {
            let t = self.frames;
            for &c in &cut.constraints {
                let x = self.u.lit(&mut self.s, c, t);
                self.s.add(&[x]);
            }
            for j in 0..nl {
                let e = Lit::var_lit(cut.inputs[n + nl + j]);
                let x = self.u.lit(&mut self.s, e, t);
                self.s.add(&[!self.act[j], x]);
            }
            self.frames += 1;
        }
    }

    /// Is there a concrete trace whose frame `k` (0-based) raises the bad output?
    pub(crate) fn check(&mut self, k: usize, limits: &Limits) -> Check {
        self.extend(k);
        let bad = self.u.aig().bad[0];
        let b = self.u.lit(&mut self.s, bad, k);
        let mut assumps = vec![b];
        assumps.extend(self.act.iter().copied());
        match self.s.solve(&assumps) {
            Some(true) => Check::Real(self.trace(k)),
            Some(false) => {
                let mut core = self.core();
                // Shrink the core by asking again with only its latches active (each round
                // is cheap: the solver has just refuted a superset of the question).
                for _ in 0..2 {
                    let mut again = vec![b];
                    again.extend(core.iter().map(|&j| self.act[j]));
                    if self.s.solve(&again) != Some(false) {
                        break;
                    }
                    let smaller = self.core();
                    if smaller.len() >= core.len() {
                        break;
                    }
                    core = smaller;
                }
                Check::Refuted(core)
            }
            None => Check::Stopped(limits.why_interrupted()),
        }
    }

    /// The latches whose activation literals the last refutation used.
    fn core(&mut self) -> Vec<usize> {
        let failed: std::collections::HashSet<SLit> = self.s.failed().into_iter().collect();
        (0..self.act.len())
            .filter(|&j| failed.contains(&self.act[j]))
            .collect()
    }

    /// The concrete trace of frames `0..=k` in the solver's model.
    fn trace(&mut self, k: usize) -> Trace {
        let n = self.aig.inputs.len();
        let nl = self.aig.latches.len();
        let mut init = self.u.latches(&mut self.s, 0);
        init.truncate(nl);
        // Latches the model leaves unencoded keep their reset values.
        for (j, l) in self.aig.latches.iter().enumerate() {
            if let Some(b) = l.init {
                init[j] = b;
            }
        }
        let inputs = (0..=k)
            .map(|t| {
                let mut v = self.u.inputs(&mut self.s, t);
                v.truncate(n);
                v
            })
            .collect();
        Trace { init, inputs }
    }
}
