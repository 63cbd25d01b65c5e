//! The interpreter of the IR: the only executor of the step semantics.
//!
//! A [`Machine`] owns one slot vector and runs [`Program::step`] on it. It allocates nothing
//! per step (an error, which ends the step, allocates its report); the checkers run one
//! machine per thread and load and store packed states around each step.

use crate::error::{fault, op_fault, Fault, RuntimeError, RuntimeErrorKind};
use crate::program::*;
use statecheck_model::ops;
use statecheck_syntax::ast::BinOp;

impl Program {
    /// Expression `e` ready for [`Machine::holds`]: its compiled code when it has some (the
    /// program's assumptions, their `&&` conjuncts, properties and active-state expressions),
    /// so that evaluating it repeatedly costs no look-up.
    pub fn prepare(&self, e: ExprId) -> Prepared {
        match self.code().exprs.get(&e) {
            Some(seg) if self.code().runnable => Prepared(PreparedKind::Code(*seg)),
            _ => Prepared(PreparedKind::Tree(e)),
        }
    }

    /// Render a run-time error with its site: what, where in the model, which instance/state.
    pub fn describe_error(&self, e: &RuntimeError) -> String {
        match self.sites.get(e.site as usize) {
            Some(site) => {
                let inst = site
                    .instance
                    .and_then(|i| self.instances.get(i as usize))
                    .map(|i| i.name.as_str())
                    .unwrap_or("system");
                let state = if site.state.is_empty() {
                    String::new()
                } else {
                    format!(", state {}", site.state)
                };
                format!(
                    "{} in {} (instance {inst}{state})",
                    e.kind.describe(),
                    site.what
                )
            }
            None => e.kind.describe(),
        }
    }
}

/// The state of one running system.
///
/// Its register file holds the program's slots first, then the compiled code's locals,
/// temporaries and constants.
#[derive(Clone, Debug)]
pub struct Machine<'p> {
    program: &'p Program,
    code: &'p crate::vm::Code,
    /// All registers; `regs[..slots.len()]` are the slots.
    regs: Vec<i64>,
    /// The compiled code's return stack.
    stack: Vec<u32>,
    /// Number of slots.
    n_slots: usize,
    /// Coverage counters, if enabled.
    coverage: Option<Vec<u64>>,
    /// True when input `i` is slot `n_state + i` (see [`Machine::load`]).
    inputs_follow_state: bool,
}

impl<'p> Machine<'p> {
    /// A machine in the state before tick 0 (every slot at its initial value).
    pub fn new(program: &'p Program) -> Machine<'p> {
        let code = program.code();
        Machine {
            program,
            code,
            regs: code.init_regs.clone(),
            stack: vec![0; code.max_depth],
            n_slots: program.slots.len(),
            coverage: None,
            inputs_follow_state: program
                .inputs
                .iter()
                .enumerate()
                .all(|(i, inp)| inp.slot as usize == program.n_state + i),
        }
    }

    /// The program this machine runs.
    pub fn program(&self) -> &'p Program {
        self.program
    }

    /// Start counting coverage items.
    pub fn enable_coverage(&mut self) {
        self.coverage = Some(vec![0; self.program.covers.len()]);
    }

    /// Set every coverage counter back to zero (when enabled), to see what one tick covers.
    pub fn clear_coverage(&mut self) {
        if let Some(c) = &mut self.coverage {
            c.fill(0);
        }
    }

    /// Coverage counters (if enabled), indexed like [`Program::covers`].
    pub fn coverage(&self) -> Option<&[u64]> {
        self.coverage.as_deref()
    }

    /// All slot values.
    pub fn slots(&self) -> &[i64] {
        &self.regs[..self.n_slots]
    }

    /// The persistent state.
    pub fn state(&self) -> &[i64] {
        &self.regs[..self.program.n_state]
    }

    /// Overwrite the persistent state.
    pub fn load_state(&mut self, state: &[i64]) {
        self.regs[..self.program.n_state].copy_from_slice(state);
    }

    /// The persistent state, to overwrite in place (for instance by unpacking a stored state
    /// straight into it, without the copy of [`Machine::load_state`]).
    #[inline]
    pub fn state_mut(&mut self) -> &mut [i64] {
        &mut self.regs[..self.program.n_state]
    }

    /// Overwrite the persistent state and the tick's inputs (`inputs` holds one value per
    /// input, in [`Program::inputs`] order): one copy when the input slots follow the state,
    /// as the layout places them.
    #[inline]
    pub fn load(&mut self, state: &[i64], inputs: &[i64]) {
        let ns = self.program.n_state;
        self.regs[..ns].copy_from_slice(state);
        if self.inputs_follow_state {
            let k = self.program.inputs.len();
            self.regs[ns..ns + k].copy_from_slice(&inputs[..k]);
        } else {
            for (inp, &x) in self.program.inputs.iter().zip(inputs) {
                self.regs[inp.slot as usize] = x;
            }
        }
    }

    /// Set a slot (normally an input slot) to a value.
    #[inline]
    pub fn set(&mut self, slot: SlotId, value: i64) {
        self.regs[slot as usize] = value;
    }

    /// Value of a slot.
    #[inline]
    pub fn get(&self, slot: SlotId) -> i64 {
        self.regs[slot as usize]
    }

    /// Evaluate an expression on the current slots (compiled when it is a property,
    /// assumption or active-state expression of the program).
    pub fn eval(&mut self, e: ExprId) -> Result<i64, RuntimeError> {
        if let Some(seg) = self.code.exprs.get(&e) {
            crate::vm::run(self.code, &mut self.regs, &mut self.stack, None, seg.start)
                .map_err(|f| *f)?;
            return Ok(self.regs[seg.reg as usize]);
        }
        eval(&self.program.nodes, &self.regs[..self.n_slots], e)
    }

    /// True when the prepared expression evaluates to non-zero on the current slots; false
    /// when it is zero or its evaluation fails (the reading of properties and assumptions).
    #[inline]
    pub fn holds(&mut self, e: Prepared) -> bool {
        match e.0 {
            PreparedKind::Code(seg) => {
                crate::vm::run(self.code, &mut self.regs, &mut self.stack, None, seg.start).is_ok()
                    && self.regs[seg.reg as usize] != 0
            }
            PreparedKind::Tree(e) => {
                matches!(eval(&self.program.nodes, &self.regs[..self.n_slots], e), Ok(v) if v != 0)
            }
        }
    }

    /// Run one tick with the inputs currently in the input slots.
    #[inline]
    pub fn step(&mut self) -> Result<(), RuntimeError> {
        if !self.code.runnable {
            return self.step_reference();
        }
        crate::vm::run(
            self.code,
            &mut self.regs,
            &mut self.stack,
            self.coverage.as_deref_mut(),
            self.code.step,
        )
        .map_err(|f| *f)
    }

    /// Run one tick with the tree-walking reference evaluator (for testing the fast path).
    pub fn step_reference(&mut self) -> Result<(), RuntimeError> {
        let p = self.program;
        let mut slots = self.regs[..self.n_slots].to_vec();
        let mut locals = vec![0; p.n_locals];
        let mut ex = Exec {
            p,
            slots: &mut slots,
            locals: &mut locals,
            cov: self.coverage.as_deref_mut(),
        };
        let r = ex.block(&p.step).map_err(|f| *f);
        self.regs[..self.n_slots].copy_from_slice(&slots);
        r
    }
}

/// An expression prepared by [`Machine::prepare`] for the machines of one program.
#[derive(Clone, Copy, Debug)]
pub struct Prepared(PreparedKind);

#[derive(Clone, Copy, Debug)]
enum PreparedKind {
    /// Compiled: run this segment of the register code.
    Code(crate::vm::Segment),
    /// Not compiled: walk the expression tree.
    Tree(ExprId),
}

/// Evaluate expression `e` over `slots` (for read-only views such as trace rendering).
pub fn eval(nodes: &[Node], slots: &[i64], e: ExprId) -> Result<i64, RuntimeError> {
    let mut locals = Vec::new();
    let mut ev = Eval {
        nodes,
        slots,
        locals: &mut locals,
    };
    ev.eval(e).map_err(|f| *f)
}

struct Exec<'a> {
    p: &'a Program,
    slots: &'a mut Vec<i64>,
    locals: &'a mut Vec<i64>,
    cov: Option<&'a mut [u64]>,
}

impl Exec<'_> {
    fn value(&mut self, e: ExprId) -> Result<i64, Fault> {
        Eval {
            nodes: &self.p.nodes,
            slots: self.slots,
            locals: self.locals,
        }
        .eval(e)
    }

    fn block(&mut self, stmts: &[Stmt]) -> Result<(), Fault> {
        for s in stmts {
            match s {
                Stmt::Assign { slot, expr, site } => {
                    let v = self.value(*expr)?;
                    if let Some(site) = site {
                        let sl = &self.p.slots[*slot as usize];
                        if v < sl.lo || v > sl.hi {
                            return Err(fault(
                                RuntimeErrorKind::Range {
                                    value: v,
                                    lo: sl.lo,
                                    hi: sl.hi,
                                },
                                *site,
                            ));
                        }
                    }
                    self.slots[*slot as usize] = v;
                }
                Stmt::If {
                    cond,
                    then,
                    otherwise,
                } => {
                    if self.value(*cond)? != 0 {
                        self.block(then)?;
                    } else {
                        self.block(otherwise)?;
                    }
                }
                Stmt::Switch { slot, cases } => {
                    let v = self.slots[*slot as usize];
                    if let Some(block) = cases.get(v as usize) {
                        self.block(block)?;
                    }
                }
                Stmt::Call(proc_id) => {
                    let p = self.p;
                    self.block(&p.procs[*proc_id as usize].body)?;
                }
                Stmt::Cover(c) => {
                    if let Some(counts) = self.cov.as_deref_mut() {
                        counts[*c as usize] += 1;
                    }
                }
            }
        }
        Ok(())
    }
}

struct Eval<'a> {
    nodes: &'a [Node],
    slots: &'a [i64],
    locals: &'a mut Vec<i64>,
}

impl Eval<'_> {
    fn eval(&mut self, e: ExprId) -> Result<i64, Fault> {
        Ok(match self.nodes[e as usize] {
            Node::Const(v) => v,
            Node::Slot(s) => self.slots[s as usize],
            Node::Unary(op, a) => {
                let a = self.eval(a)?;
                ops::unary(op, a).map_err(|err| op_fault(err, u32::MAX))?
            }
            Node::Binary(op, a, b, site) => {
                let a = self.eval(a)?;
                match op {
                    BinOp::And if a == 0 => return Ok(0),
                    BinOp::Or if a != 0 => return Ok(1),
                    _ => {}
                }
                let b = self.eval(b)?;
                ops::binary(op, a, b).map_err(|err| op_fault(err, site))?
            }
            Node::Ite(c, a, b) => {
                if self.eval(c)? != 0 {
                    self.eval(a)?
                } else {
                    self.eval(b)?
                }
            }
            Node::Min(a, b) => self.eval(a)?.min(self.eval(b)?),
            Node::Max(a, b) => self.eval(a)?.max(self.eval(b)?),
            Node::Abs(a, site) => {
                let a = self.eval(a)?;
                ops::abs(a).map_err(|err| op_fault(err, site))?
            }
            Node::Check(a, lo, hi, site) => {
                let v = self.eval(a)?;
                if v < lo || v > hi {
                    return Err(fault(RuntimeErrorKind::Range { value: v, lo, hi }, site));
                }
                v
            }
            Node::Let(l, v, body) => {
                let v = self.eval(v)?;
                if self.locals.len() <= l as usize {
                    self.locals.resize(l as usize + 1, 0);
                }
                self.locals[l as usize] = v;
                self.eval(body)?
            }
            Node::Local(l) => self.locals.get(l as usize).copied().unwrap_or(0),
        })
    }
}
