//! Which free inputs one tick can read from a given state: the explicit engine's input
//! abstraction (an input that the tick does not read from this state cannot change the
//! successor, so only one vector per combination of the read inputs need be stepped).
//!
//! [`InputReads::from_state`] walks the step program once with the persistent state known and
//! every input unknown (a small abstract interpretation of the reference evaluator of
//! `interp.rs`): a value is known or unknown; an `if` or `switch` whose selector is known runs
//! one branch; one whose selector is unknown runs every branch, and an assignment under such a
//! branch makes its slot unknown (it may or may not happen). Every input slot read by an
//! expression the walk evaluates is recorded. A run-time error on known values ends the walk
//! (every tick from this state stops there); one on unknown values is only a possibility, so
//! the walk goes on.
//!
//! Soundness: every slot the walk holds as known has that value in every concrete tick from
//! the state that gets there, whatever the inputs, so each concrete tick follows a path the
//! walk visited and reads only recorded inputs. Two input vectors that agree on the recorded
//! inputs therefore run exactly the same statements with the same values: the same successor,
//! the same run-time error, the same coverage items.

use super::reads::slots_read;
use crate::program::{ExprId, Node, Program, Stmt};
use statecheck_model::ops;
use statecheck_syntax::ast::BinOp;

/// Most expression nodes and statements one walk visits before it gives up and reports every
/// input as read (a walk costs about as much as a tick; the cap bounds a model whose unknown
/// branches multiply).
const MAX_WORK: u64 = 1 << 20;

/// The walk stopped: a run-time error on known values, or the work cap.
enum Stop {
    /// Every tick from the state stops here: what was recorded so far is complete.
    Error,
    /// Too much work: report every input.
    Work,
}

/// The input slots a tick reads, state by state, for one program.
#[derive(Clone, Debug)]
pub struct InputReads<'p> {
    p: &'p Program,
    /// Per slot: its value when known.
    vals: Vec<Option<i64>>,
    /// Per local of `let`: its value when known.
    locals: Vec<Option<i64>>,
    /// Per slot: the input's position in [`Program::inputs`], for input slots.
    input_of: Vec<Option<u32>>,
    /// Inputs read whatever the state (properties and assumes checked per transition).
    always: Vec<u64>,
    /// Nesting depth of branches whose selector is unknown.
    unsure: u32,
    work: u64,
}

impl<'p> InputReads<'p> {
    /// A walker for `program`; the inputs read by `extra` (per-transition properties, assumes
    /// evaluated per transition) count as read in every state.
    pub fn new(program: &'p Program, extra: &[ExprId]) -> InputReads<'p> {
        let mut input_of = vec![None; program.slots.len()];
        for (i, inp) in program.inputs.iter().enumerate() {
            if let Some(x) = input_of.get_mut(inp.slot as usize) {
                *x = Some(i as u32);
            }
        }
        let words = program.inputs.len().div_ceil(64);
        let mut always = vec![0u64; words];
        for &e in extra {
            for s in slots_read(program, e) {
                if let Some(Some(i)) = input_of.get(s as usize) {
                    always[*i as usize / 64] |= 1 << (i % 64);
                }
            }
        }
        InputReads {
            p: program,
            vals: vec![None; program.slots.len()],
            locals: vec![None; program.n_locals],
            input_of,
            always,
            unsure: 0,
            work: 0,
        }
    }

    /// Words of an input mask (bit `i % 64` of word `i / 64` is input `i`).
    pub fn words(&self) -> usize {
        self.always.len()
    }

    /// Into `mask` ([`InputReads::words`] words): the inputs a tick from `state` (the
    /// persistent slots) may read, with those read in every state.
    pub fn from_state(&mut self, state: &[i64], mask: &mut [u64]) {
        mask.copy_from_slice(&self.always);
        let n = self.p.n_state.min(state.len());
        for (v, &s) in self.vals.iter_mut().zip(&state[..n]) {
            *v = Some(s);
        }
        // Inputs and temporaries are unknown at the start of a tick.
        self.vals[n..].fill(None);
        self.locals.fill(None);
        self.unsure = 0;
        self.work = 0;
        let p = self.p;
        if let Err(Stop::Work) = self.block(&p.step, mask) {
            for (i, w) in mask.iter_mut().enumerate() {
                let bits = p.inputs.len().saturating_sub(i * 64).min(64);
                *w = if bits == 64 {
                    u64::MAX
                } else {
                    (1u64 << bits) - 1
                };
            }
        }
    }

    fn tick(&mut self) -> Result<(), Stop> {
        self.work += 1;
        if self.work > MAX_WORK {
            Err(Stop::Work)
        } else {
            Ok(())
        }
    }

    /// A run-time error on `known` operands: the end of every tick when it is certain to be
    /// reached, otherwise an unknown value.
    fn fail(&self) -> Result<Option<i64>, Stop> {
        if self.unsure == 0 {
            Err(Stop::Error)
        } else {
            Ok(None)
        }
    }

    fn block(&mut self, stmts: &[Stmt], mask: &mut [u64]) -> Result<(), Stop> {
        let p = self.p;
        for s in stmts {
            self.tick()?;
            match s {
                Stmt::Assign { slot, expr, site } => {
                    let mut v = self.eval(*expr, mask)?;
                    if let (Some(x), Some(_)) = (v, site) {
                        let sl = &p.slots[*slot as usize];
                        if x < sl.lo || x > sl.hi {
                            v = self.fail()?;
                        }
                    }
                    let old = &mut self.vals[*slot as usize];
                    *old = if self.unsure > 0 && *old != v {
                        None
                    } else {
                        v
                    };
                }
                Stmt::If {
                    cond,
                    then,
                    otherwise,
                } => match self.eval(*cond, mask)? {
                    Some(0) => self.block(otherwise, mask)?,
                    Some(_) => self.block(then, mask)?,
                    None => {
                        self.unsure += 1;
                        self.block(then, mask)?;
                        self.block(otherwise, mask)?;
                        self.unsure -= 1;
                    }
                },
                Stmt::Switch { slot, cases } => {
                    self.read_slot(*slot, mask);
                    match self.vals[*slot as usize] {
                        Some(v) => {
                            if let Some(b) = usize::try_from(v).ok().and_then(|v| cases.get(v)) {
                                self.block(b, mask)?;
                            }
                        }
                        None => {
                            self.unsure += 1;
                            for b in cases {
                                self.block(b, mask)?;
                            }
                            self.unsure -= 1;
                        }
                    }
                }
                Stmt::Call(id) => self.block(&p.procs[*id as usize].body, mask)?,
                Stmt::Cover(_) => {}
            }
        }
        Ok(())
    }

    fn read_slot(&mut self, s: u32, mask: &mut [u64]) {
        if let Some(Some(i)) = self.input_of.get(s as usize) {
            mask[*i as usize / 64] |= 1 << (i % 64);
        }
    }

    /// The value of `e` when known; every input it may read is recorded.
    fn eval(&mut self, e: ExprId, mask: &mut [u64]) -> Result<Option<i64>, Stop> {
        self.tick()?;
        Ok(match self.p.nodes[e as usize] {
            Node::Const(v) => Some(v),
            Node::Slot(s) => {
                self.read_slot(s, mask);
                self.vals[s as usize]
            }
            Node::Unary(op, a) => match self.eval(a, mask)? {
                Some(a) => match ops::unary(op, a) {
                    Ok(v) => Some(v),
                    Err(_) => self.fail()?,
                },
                None => None,
            },
            Node::Binary(op, a, b, _) => {
                let a = self.eval(a, mask)?;
                match (op, a) {
                    (BinOp::And, Some(0)) => return Ok(Some(0)),
                    (BinOp::Or, Some(x)) if x != 0 => return Ok(Some(1)),
                    _ => {}
                }
                // After an unknown `&&`/`||` operand, the other may not be evaluated.
                let lazy = matches!(op, BinOp::And | BinOp::Or) && a.is_none();
                let b = self.unsure_if(lazy, |w| w.eval(b, mask))?;
                match (a, b) {
                    (Some(a), Some(b)) => match ops::binary(op, a, b) {
                        Ok(v) => Some(v),
                        Err(_) => self.fail()?,
                    },
                    _ => None,
                }
            }
            Node::Ite(c, a, b) => match self.eval(c, mask)? {
                Some(0) => self.eval(b, mask)?,
                Some(_) => self.eval(a, mask)?,
                None => {
                    let (x, y) =
                        self.unsure_if(true, |w| Ok((w.eval(a, mask)?, w.eval(b, mask)?)))?;
                    if x == y {
                        x
                    } else {
                        None
                    }
                }
            },
            Node::Min(a, b) => {
                let (a, b) = (self.eval(a, mask)?, self.eval(b, mask)?);
                a.zip(b).map(|(a, b)| a.min(b))
            }
            Node::Max(a, b) => {
                let (a, b) = (self.eval(a, mask)?, self.eval(b, mask)?);
                a.zip(b).map(|(a, b)| a.max(b))
            }
            Node::Abs(a, _) => match self.eval(a, mask)? {
                Some(a) => match ops::abs(a) {
                    Ok(v) => Some(v),
                    Err(_) => self.fail()?,
                },
                None => None,
            },
            Node::Check(a, lo, hi, _) => match self.eval(a, mask)? {
                Some(v) if v < lo || v > hi => self.fail()?,
                v => v,
            },
            Node::Let(l, v, body) => {
                let v = self.eval(v, mask)?;
                if self.locals.len() <= l as usize {
                    self.locals.resize(l as usize + 1, None);
                }
                self.locals[l as usize] = v;
                self.eval(body, mask)?
            }
            Node::Local(l) => self.locals.get(l as usize).copied().flatten(),
        })
    }

    /// Run `f` as if under a branch whose selector is unknown when `unsure`.
    fn unsure_if<T>(
        &mut self,
        unsure: bool,
        f: impl FnOnce(&mut Self) -> Result<T, Stop>,
    ) -> Result<T, Stop> {
        self.unsure += u32::from(unsure);
        let r = f(self);
        self.unsure -= u32::from(unsure);
        r
    }
}
