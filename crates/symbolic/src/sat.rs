//! The SAT solver (CaDiCaL through `rustsat`) and the Tseitin encoding of AIG time frames.

use crate::aig::{Aig, Lit, Node};
use rustsat::solvers::{Solve, SolveIncremental, SolverResult};
use rustsat::types::{Lit as SLit, TernaryVal};
use rustsat_cadical::CaDiCaL;

/// An incremental SAT solver.
pub struct Solver {
    s: CaDiCaL<'static, 'static>,
    vars: u32,
    t: SLit,
    /// One more than the highest variable the solver has seen in a clause or assumption;
    /// asking the backend for another one's value builds an error (and, with
    /// `RUST_BACKTRACE` set, a backtrace) on a hot path.
    known: u32,
}

impl Default for Solver {
    fn default() -> Self {
        Solver::new()
    }
}

impl Solver {
    /// A fresh solver with a constant-true variable.
    pub fn new() -> Solver {
        Solver::with(CaDiCaL::default())
    }

    /// A solver without pre- and inprocessing, for the many small incremental queries of IC3
    /// (variable elimination then only costs model reconstruction on every call).
    pub fn plain() -> Solver {
        let mut c = CaDiCaL::default();
        // Fails only for an unknown configuration name; the default configuration is sound.
        let _ = c.set_configuration(rustsat_cadical::Config::Plain);
        // "Lucky" phase checks try eight trivial assignments by full propagation before every
        // call: on thousands of small incremental queries over a large formula they cost more
        // than the search itself. (Fails only for an unknown option name.)
        let _ = c.set_option("lucky", 0);
        Solver::with(c)
    }

    fn with(c: CaDiCaL<'static, 'static>) -> Solver {
        let mut s = Solver {
            s: c,
            vars: 0,
            t: SLit::positive(0),
            known: 0,
        };
        s.t = s.fresh();
        s.add(&[s.t]);
        s
    }

    /// The constant true literal.
    pub fn tru(&self) -> SLit {
        self.t
    }

    /// A new variable's positive literal.
    pub fn fresh(&mut self) -> SLit {
        let l = SLit::positive(self.vars);
        self.vars += 1;
        l
    }

    /// Add a clause.
    pub fn add(&mut self, clause: &[SLit]) {
        self.note(clause);
        // CaDiCaL only fails on out-of-memory; the solver then answers `unknown` later.
        let _ = self.s.add_clause(clause.iter().copied().collect());
    }

    fn note(&mut self, lits: &[SLit]) {
        for l in lits {
            self.known = self.known.max(l.vidx32() + 1);
        }
    }

    /// Solve under assumptions: `Some(true)` satisfiable, `Some(false)` unsatisfiable, `None`
    /// when the solver failed.
    pub fn solve(&mut self, assumps: &[SLit]) -> Option<bool> {
        self.note(assumps);
        match self.s.solve_assumps(assumps) {
            Ok(SolverResult::Sat) => Some(true),
            Ok(SolverResult::Unsat) => Some(false),
            _ => None,
        }
    }

    /// A literal's value in the last model (false when unassigned).
    pub fn value(&self, l: SLit) -> bool {
        l.vidx32() < self.known && matches!(self.s.lit_val(l), Ok(TernaryVal::True))
    }

    /// The assumptions (as given) that the last unsatisfiable answer depends on.
    pub fn failed(&mut self) -> Vec<SLit> {
        self.s
            .core()
            .map(|c| c.into_iter().map(|l| !l).collect())
            .unwrap_or_default()
    }
}

/// How latches are encoded in frame 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Start {
    /// At their reset values (uninitialized latches free).
    Reset,
    /// Free.
    Free,
}

/// Time frames of an AIG in one solver, encoded lazily (only the cones that are asked for).
pub struct Unroller<'a> {
    aig: &'a Aig,
    start: Start,
    frames: Vec<Vec<Option<SLit>>>,
}

impl<'a> Unroller<'a> {
    /// An unrolling of `aig` with frame 0 as `start` says.
    pub fn new(aig: &'a Aig, start: Start) -> Unroller<'a> {
        Unroller {
            aig,
            start,
            frames: Vec::new(),
        }
    }

    /// The graph.
    pub fn aig(&self) -> &'a Aig {
        self.aig
    }

    /// The solver literal of `l` in frame `t`.
    pub fn lit(&mut self, s: &mut Solver, l: Lit, t: usize) -> SLit {
        let v = self.var(s, l.var(), t);
        if l.is_neg() {
            !v
        } else {
            v
        }
    }

    fn slot(&mut self, v: u32, t: usize) -> Option<SLit> {
        while self.frames.len() <= t {
            self.frames.push(vec![None; self.aig.nodes.len()]);
        }
        self.frames[t][v as usize]
    }

    fn var(&mut self, s: &mut Solver, v: u32, t: usize) -> SLit {
        if let Some(x) = self.slot(v, t) {
            return x;
        }
        // Iterative post-order over the cone (AIG chains can be thousands deep).
        let mut stack: Vec<(u32, usize, bool)> = vec![(v, t, false)];
        while let Some((v, t, expanded)) = stack.pop() {
            if self.slot(v, t).is_some() {
                continue;
            }
            let node = self.aig.nodes[v as usize];
            let x = match node {
                Node::False => !s.tru(),
                Node::Input(_) => s.fresh(),
                Node::Latch(i) => {
                    let latch = &self.aig.latches[i as usize];
                    if t == 0 {
                        match (self.start, latch.init) {
                            (Start::Reset, Some(b)) => {
                                if b {
                                    s.tru()
                                } else {
                                    !s.tru()
                                }
                            }
                            _ => s.fresh(),
                        }
                    } else {
                        let n = latch.next;
                        match self.slot(n.var(), t - 1) {
                            Some(x) => {
                                if n.is_neg() {
                                    !x
                                } else {
                                    x
                                }
                            }
                            None => {
                                stack.push((v, t, false));
                                stack.push((n.var(), t - 1, false));
                                continue;
                            }
                        }
                    }
                }
                Node::And(a, b) => {
                    let (xa, xb) = (self.slot(a.var(), t), self.slot(b.var(), t));
                    match (xa, xb) {
                        (Some(xa), Some(xb)) => {
                            let xa = if a.is_neg() { !xa } else { xa };
                            let xb = if b.is_neg() { !xb } else { xb };
                            let o = s.fresh();
                            s.add(&[!o, xa]);
                            s.add(&[!o, xb]);
                            s.add(&[o, !xa, !xb]);
                            o
                        }
                        _ => {
                            debug_assert!(!expanded, "children encoded before the gate");
                            stack.push((v, t, true));
                            if xa.is_none() {
                                stack.push((a.var(), t, false));
                            }
                            if xb.is_none() {
                                stack.push((b.var(), t, false));
                            }
                            continue;
                        }
                    }
                }
            };
            self.frames[t][v as usize] = Some(x);
        }
        self.slot(v, t).unwrap_or(!s.tru())
    }

    /// The values of the inputs in frame `t` of the last model (unencoded inputs: false).
    pub fn inputs(&mut self, s: &Solver, t: usize) -> Vec<bool> {
        let ins = &self.aig.inputs;
        ins.iter()
            .map(|&v| self.slot(v, t).is_some_and(|x| s.value(x)))
            .collect()
    }

    /// The values of the latches in frame `t` of the last model (unencoded latches: their reset
    /// value, or false).
    pub fn latches(&mut self, s: &Solver, t: usize) -> Vec<bool> {
        let ls: Vec<(u32, Option<bool>)> =
            self.aig.latches.iter().map(|l| (l.var, l.init)).collect();
        ls.into_iter()
            .map(|(v, init)| match self.slot(v, t) {
                Some(x) => s.value(x),
                None => init.unwrap_or(false),
            })
            .collect()
    }
}
