//! Bit-blasting: the IR's step program as an And-Inverter Graph.
//!
//! The step is executed symbolically, statement by statement, exactly as [`Machine`] runs it:
//! an assignment under path condition `pc` becomes `slot := pc ? value : slot`; `if` and
//! `switch` split the path condition; calls are inlined. Every run-time check site becomes an
//! error condition under its path condition, guarded by "no earlier error in this step", so
//! the three error outputs say which built-in property the step's *first* error violates.
//!
//! Encoding (documented in `docs/verification.md`):
//! - each persistent state slot is a vector of latches (two's complement, reset to `init`);
//! - each free input is `width(lo..hi)` primary inputs holding `value - lo`, with codes past
//!   `hi` read as `hi` (so no constraint is needed for ranges that are not powers of two);
//! - one step is one AIG transition; a property's bad output is a function of the pre-state
//!   and the inputs (the post-state is computed combinationally);
//! - the constraint of a property is "the `assume`s hold and the step has no run-time error"
//!   (for a built-in property: no error of another kind). States after an error are thus
//!   unreachable, as in the explicit engine, which stops a run at its first error.
//!
//! [`Machine`]: statecheck_ir::Machine

mod expr;
mod retime;

use crate::aig::{Aig, Lit};
use crate::bv::{self, Bv};
use statecheck_ir::{Goal, Program, Stmt};

pub use expr::{BAD_SHIFT, DIV_ZERO, RANGE};
pub use retime::retimed_trace;

/// How one free input is encoded.
#[derive(Clone, Debug)]
pub struct InputEnc {
    /// The primary inputs holding `value - lo`, least significant first.
    pub bits: Vec<Lit>,
    /// The input's smallest value.
    pub lo: i64,
    /// The input's largest value.
    pub hi: i64,
}

impl InputEnc {
    /// The input bits' values for `value`.
    pub fn encode(&self, value: i64) -> Vec<bool> {
        let raw = (value as i128 - self.lo as i128) as u128;
        (0..self.bits.len()).map(|i| (raw >> i) & 1 == 1).collect()
    }

    /// The value of input bits (codes past `hi` read as `hi`).
    pub fn decode(&self, bits: &[bool]) -> i64 {
        let mut raw: u128 = 0;
        for (i, b) in bits.iter().enumerate() {
            if *b {
                raw |= 1 << i;
            }
        }
        let span = (self.hi as i128 - self.lo as i128) as u128;
        (self.lo as i128 + raw.min(span) as i128) as i64
    }
}

/// A property as an AIG signal.
#[derive(Clone, Debug)]
pub struct PropSignal {
    /// Its name.
    pub name: String,
    /// The built-in kind (`RANGE`, `DIV_ZERO`, `BAD_SHIFT`) for a built-in property.
    pub builtin: Option<usize>,
    /// True for `reachable` properties (the bad output is the target).
    pub reachable: bool,
    /// Set on a transition that violates (or, for `reachable`, witnesses) it; the step has
    /// no run-time error (except for built-ins, where it is the error).
    pub bad: Lit,
    /// The same violation (or target) read on the latches instead of the step's post-state:
    /// true in a state the step has produced that violates it. Only for an own property that
    /// reads nothing but persistent state (`None` otherwise: a built-in, or a property that
    /// reads an input or a temporary). [`Blasted::retimed_problem`] watches it one tick later.
    pub on_state: Option<Lit>,
}

/// The step of a program as a circuit.
#[derive(Clone, Debug)]
pub struct Blasted {
    /// The circuit; its latches are the state slots' bits, its inputs the inputs' bits.
    /// `bad` and `constraints` are empty: see [`Blasted::problem`].
    pub aig: Aig,
    /// Latch bits of each state slot.
    pub state: Vec<Bv>,
    /// Encoding of each free input, in `Program::inputs` order.
    pub inputs: Vec<InputEnc>,
    /// The `assume`s hold on the pre-state and inputs.
    pub assume: Lit,
    /// The step has a run-time error of each kind (first error in execution order).
    pub errs: [Lit; 3],
    /// Every property: the program's, then the built-ins (in `statecheck_ir::verdict::properties` order).
    pub props: Vec<PropSignal>,
    /// The value of every slot after the step (for tests and diagnostics).
    pub post: Vec<Bv>,
    /// Every atom of the temporal properties and fairness constraints, as it holds at the
    /// position a step produces (the post-state with the step's inputs; an evaluation that
    /// fails is false), in order of first occurrence.
    pub atoms: Vec<(statecheck_ir::ExprId, Lit)>,
}

/// Symbolic execution state.
pub(crate) struct Blaster<'p> {
    pub(crate) p: &'p Program,
    pub(crate) g: Aig,
    pub(crate) env: Vec<Bv>,
    pub(crate) locals: Vec<Bv>,
    /// No error so far in this step.
    pub(crate) ok: Lit,
    /// First-error conditions per kind.
    pub(crate) errs: [Lit; 3],
}

fn slot_bits_name(name: &str, i: usize, w: usize) -> Option<String> {
    Some(if w == 1 {
        name.to_string()
    } else {
        format!("{name}[{i}]")
    })
}

/// Bit-blast `p`'s step, assumptions and properties.
pub fn blast(p: &Program) -> Blasted {
    let mut g = Aig::new();
    let mut env = Vec::with_capacity(p.slots.len());
    let mut state = Vec::with_capacity(p.n_state);
    for s in p.state_slots() {
        let (lo, hi) = (s.lo.min(s.init) as i128, s.hi.max(s.init) as i128);
        let w = bv::width_for(lo, hi);
        let init = s.init as i128;
        // A non-negative slot's sign bit is the constant 0, not a latch.
        let nl = if lo >= 0 { w - 1 } else { w };
        let mut bits: Vec<Lit> = (0..nl)
            .map(|i| g.latch(Some((init >> i) & 1 == 1), slot_bits_name(&s.name, i, nl)))
            .collect();
        bits.resize(w, Lit::FALSE);
        let v = Bv { bits, lo, hi };
        state.push(v.clone());
        env.push(v);
    }
    let mut inputs = Vec::with_capacity(p.inputs.len());
    for inp in &p.inputs {
        let s = &p.slots[inp.slot as usize];
        let span = (s.hi as i128 - s.lo as i128).max(0);
        let w = (128 - span.leading_zeros()) as usize;
        let bits: Vec<Lit> = (0..w)
            .map(|i| g.input(slot_bits_name(&s.name, i, w)))
            .collect();
        let raw = Bv {
            bits: bits.iter().copied().chain([Lit::FALSE]).collect(),
            lo: 0,
            hi: (1i128 << w) - 1,
        };
        let sp = Bv::constant(span);
        let over = bv::lt(&mut g, &sp, &raw);
        let clamped = bv::mux(&mut g, over, &sp, &raw).restrict(0, span);
        let v = bv::add(&mut g, &clamped, &Bv::constant(s.lo as i128));
        debug_assert_eq!(env.len(), inp.slot as usize);
        env.push(v);
        inputs.push(InputEnc {
            bits,
            lo: s.lo,
            hi: s.hi,
        });
    }
    for s in &p.slots[env.len()..] {
        env.push(Bv::constant(s.init as i128));
    }
    let mut b = Blaster {
        p,
        g,
        env,
        locals: Vec::new(),
        ok: Lit::TRUE,
        errs: [Lit::FALSE; 3],
    };
    let assumes: Vec<Lit> = p.assumes.iter().map(|a| b.holds(*a)).collect();
    let assume = b.g.and_all(assumes);
    b.block(&p.step, Lit::TRUE);
    let no_err = b.ok;
    let mut atoms: Vec<(statecheck_ir::ExprId, Lit)> = Vec::new();
    let mut atom_exprs: Vec<statecheck_ir::ExprId> = Vec::new();
    for t in &p.temporal {
        match &t.formula {
            statecheck_ir::temporal::TemporalFormula::Ltl(f) => atom_exprs.extend(f.atoms()),
            statecheck_ir::temporal::TemporalFormula::Ctl(f) => atom_exprs.extend(f.atoms()),
        }
    }
    for f in &p.fairness {
        atom_exprs.extend(f.trigger);
        atom_exprs.push(f.expr);
    }
    for e in atom_exprs {
        if !atoms.iter().any(|&(a, _)| a == e) {
            let l = b.holds(e);
            atoms.push((e, l));
        }
    }
    let mut props = Vec::new();
    for prop in &p.properties {
        let (raw, reachable) = b.goal(prop.goal);
        let bad = b.g.and(raw, no_err);
        // The same goal on the pre-state: the latches hold the state slots' post-step values
        // of the tick before, so this is `raw` one tick later (temporaries and inputs are
        // not latched, so a goal that reads them has no such form).
        let on_state = retime::reads_only_state(p, prop.goal).then(|| {
            let post = std::mem::replace(&mut b.env, state_env(p, &state));
            let (raw, _) = b.goal(prop.goal);
            b.env = post;
            raw
        });
        props.push(PropSignal {
            name: prop.name.clone(),
            builtin: None,
            reachable,
            bad,
            on_state,
        });
    }
    for builtin in statecheck_ir::verdict::Builtin::ALL {
        let k = builtin.index();
        props.push(PropSignal {
            name: builtin.name().to_string(),
            builtin: Some(k),
            reachable: false,
            bad: b.errs[k],
            on_state: None,
        });
    }
    for (i, s) in state.iter().enumerate() {
        let w = s.bits.len();
        let next = b.env[i].ext(w);
        for (j, l) in s.bits.iter().enumerate() {
            let idx = b.g.nodes[l.var() as usize];
            if let crate::aig::Node::Latch(li) = idx {
                b.g.set_next(li as usize, next[j]);
            }
        }
    }
    Blasted {
        aig: b.g,
        state,
        inputs,
        assume,
        errs: b.errs,
        props,
        post: b.env,
        atoms,
    }
}

/// An environment in which the state slots are their latches (the pre-state) and every other
/// slot its initial value (never read by a goal [`retime::reads_only_state`] accepts).
fn state_env(p: &Program, state: &[Bv]) -> Vec<Bv> {
    let mut env = state.to_vec();
    env.extend(
        p.slots[state.len()..]
            .iter()
            .map(|s| Bv::constant(s.init as i128)),
    );
    env
}

impl Blaster<'_> {
    /// A property's goal as a signal: the violation of an invariant, or the target of a
    /// `reachable` property (true), over the current environment.
    fn goal(&mut self, goal: Goal) -> (Lit, bool) {
        match goal {
            Goal::Always { when, holds } => {
                let a = when.map_or(Lit::TRUE, |a| self.holds(a));
                let e = self.holds(holds);
                (self.g.and(a, !e), false)
            }
            Goal::Reach { target } => (self.holds(target), true),
        }
    }

    fn block(&mut self, stmts: &[Stmt], pc: Lit) {
        for s in stmts {
            if pc == Lit::FALSE {
                return;
            }
            match s {
                Stmt::Assign { slot, expr, site } => {
                    let mut v = self.eval(*expr, pc);
                    if site.is_some() {
                        let sl = &self.p.slots[*slot as usize];
                        let (lo, hi) = (sl.lo as i128, sl.hi as i128);
                        if v.lo < lo || v.hi > hi {
                            let out = self.outside(&v, lo, hi);
                            self.fail(pc, out, RANGE);
                            v = v.restrict(lo, hi);
                        }
                    }
                    let old = &self.env[*slot as usize];
                    let nv = bv::mux(&mut self.g, pc, &v, old);
                    self.env[*slot as usize] = nv;
                }
                Stmt::If {
                    cond,
                    then,
                    otherwise,
                } => {
                    let c = self.eval(*cond, pc);
                    let c = bv::nonzero(&mut self.g, &c);
                    let pt = self.g.and(pc, c);
                    let pe = self.g.and(pc, !c);
                    self.block(then, pt);
                    self.block(otherwise, pe);
                }
                Stmt::Switch { slot, cases } => {
                    let sel = self.env[*slot as usize].clone();
                    let conds: Vec<Lit> = (0..cases.len())
                        .map(|i| bv::eq(&mut self.g, &sel, &Bv::constant(i as i128)))
                        .collect();
                    for (case, c) in cases.iter().zip(conds) {
                        let pcase = self.g.and(pc, c);
                        self.block(case, pcase);
                    }
                }
                Stmt::Call(proc_id) => {
                    let p = self.p;
                    if let Some(pr) = p.procs.get(*proc_id as usize) {
                        self.block(&pr.body, pc);
                    }
                }
                Stmt::Cover(_) => {}
            }
        }
    }
}

impl Blasted {
    /// The verification problem of property `prop` (index into [`Blasted::props`]): a copy of
    /// the circuit with its bad output and constraint, reduced to its cone of influence.
    pub fn problem(&self, prop: usize) -> Aig {
        self.problem_with_latches(prop).0
    }

    /// [`Blasted::problem`], with the index in [`Blasted::aig`] of each of its latches.
    pub fn problem_with_latches(&self, prop: usize) -> (Aig, Vec<usize>) {
        let sig = &self.props[prop];
        let mut g = self.aig.clone();
        let any_err = g.or_all(self.errs);
        let allowed_err = match sig.builtin {
            Some(k) => g.and(any_err, !self.errs[k]),
            None => any_err,
        };
        let c = g.and(self.assume, !allowed_err);
        g.bad = vec![sig.bad];
        g.bad_names = vec![Some(sig.name.clone())];
        g.constraints = if c == Lit::TRUE { vec![] } else { vec![c] };
        g.reduced_with_latches()
    }

    /// The problem shared by the program's own properties (not the built-ins: each of those
    /// allows its own run-time error, so their constraints differ): every own property's bad
    /// output, in [`Blasted::props`] order, under the common constraint, reduced to their joint
    /// cone of influence. With it: per property, the index of its bad output (`None` for a
    /// built-in), and the index in [`Blasted::aig`] of each latch. One reduction by signal
    /// correspondence of this circuit serves every own property: the equalities it proves hold
    /// on every valid trace, whichever output is watched.
    pub fn shared_problem(&self) -> SharedProblem {
        let mut g = self.aig.clone();
        let any_err = g.or_all(self.errs);
        let c = g.and(self.assume, !any_err);
        let mut bad_index = Vec::with_capacity(self.props.len());
        g.bad.clear();
        g.bad_names.clear();
        for sig in &self.props {
            if sig.builtin.is_some() {
                bad_index.push(None);
                continue;
            }
            bad_index.push(Some(g.bad.len()));
            g.bad.push(sig.bad);
            g.bad_names.push(Some(sig.name.clone()));
        }
        g.constraints = if c == Lit::TRUE { vec![] } else { vec![c] };
        let (aig, latch_origin) = g.reduced_with_latches();
        SharedProblem {
            aig,
            bad_index,
            latch_origin,
        }
    }
}

/// The circuit of all own properties of a program ([`Blasted::shared_problem`]).
#[derive(Clone, Debug)]
pub struct SharedProblem {
    /// The circuit, with one bad output per own property.
    pub aig: Aig,
    /// Per property of [`Blasted::props`], the index of its bad output (`None`: a built-in).
    pub bad_index: Vec<Option<usize>>,
    /// The index in [`Blasted::aig`] of each latch.
    pub latch_origin: Vec<usize>,
}

impl SharedProblem {
    /// The circuit with only bad output `k` (same latches, numbered alike).
    pub fn with_bad(&self, k: usize) -> Aig {
        let mut g = self.aig.clone();
        g.bad = vec![self.aig.bad[k]];
        g.bad_names = vec![self.aig.bad_names.get(k).cloned().flatten()];
        g
    }
}
