//! The interpreter of the IR: the only executor of the step semantics.
//!
//! A [`Machine`] owns one slot vector and runs [`Program::step`] on it. It allocates nothing
//! per step; the checkers run one machine per thread and load and store packed states around
//! each step.

use crate::program::*;
use statecheck_model::ops;
use statecheck_syntax::ast::BinOp;

/// Why a tick stopped.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RuntimeError {
    /// What went wrong.
    pub kind: RuntimeErrorKind,
    /// Where (index into [`Program::sites`]).
    pub site: SiteId,
}

/// The kinds of run-time error.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RuntimeErrorKind {
    /// A value outside the destination's range.
    Range {
        /// The value.
        value: i64,
        /// Allowed minimum.
        lo: i64,
        /// Allowed maximum.
        hi: i64,
    },
    /// Division or remainder by zero.
    DivisionByZero,
    /// Shift amount outside `0..=62`.
    BadShift,
    /// A 64-bit overflow in an intermediate result.
    Overflow,
}

impl RuntimeErrorKind {
    /// The built-in property this error violates.
    pub fn builtin_property(&self) -> &'static str {
        match self {
            RuntimeErrorKind::Range { .. } | RuntimeErrorKind::Overflow => "no_range_overflow",
            RuntimeErrorKind::DivisionByZero => "no_division_by_zero",
            RuntimeErrorKind::BadShift => "no_bad_shift",
        }
    }

    /// A sentence describing the error.
    pub fn describe(&self) -> String {
        match self {
            RuntimeErrorKind::Range { value, lo, hi } => format!("value {value} is out of range {lo}..{hi}"),
            RuntimeErrorKind::DivisionByZero => "division by zero".into(),
            RuntimeErrorKind::BadShift => "shift amount outside 0..62".into(),
            RuntimeErrorKind::Overflow => "arithmetic overflow".into(),
        }
    }
}

impl Program {
    /// Render a run-time error with its site: what, where in the model, which instance/state.
    pub fn describe_error(&self, e: &RuntimeError) -> String {
        match self.sites.get(e.site as usize) {
            Some(site) => {
                let inst = site.instance.and_then(|i| self.instances.get(i as usize)).map(|i| i.name.as_str()).unwrap_or("system");
                let state = if site.state.is_empty() { String::new() } else { format!(", state {}", site.state) };
                format!("{} in {} (instance {inst}{state})", e.kind.describe(), site.what)
            }
            None => e.kind.describe(),
        }
    }
}

/// The state of one running system.
#[derive(Clone, Debug)]
pub struct Machine<'p> {
    program: &'p Program,
    /// All slot values.
    slots: Vec<i64>,
    /// Coverage counters, if enabled.
    coverage: Option<Vec<u64>>,
}

impl<'p> Machine<'p> {
    /// A machine in the state before tick 0 (every slot at its initial value).
    pub fn new(program: &'p Program) -> Machine<'p> {
        Machine {
            program,
            slots: program.slots.iter().map(|s| s.init).collect(),
            coverage: None,
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

    /// Coverage counters (if enabled), indexed like [`Program::covers`].
    pub fn coverage(&self) -> Option<&[u64]> {
        self.coverage.as_deref()
    }

    /// All slot values.
    pub fn slots(&self) -> &[i64] {
        &self.slots
    }

    /// The persistent state.
    pub fn state(&self) -> &[i64] {
        &self.slots[..self.program.n_state]
    }

    /// Overwrite the persistent state.
    pub fn load_state(&mut self, state: &[i64]) {
        self.slots[..self.program.n_state].copy_from_slice(state);
    }

    /// Set a slot (normally an input slot) to a value.
    pub fn set(&mut self, slot: SlotId, value: i64) {
        self.slots[slot as usize] = value;
    }

    /// Value of a slot.
    pub fn get(&self, slot: SlotId) -> i64 {
        self.slots[slot as usize]
    }

    /// Evaluate an expression on the current slots.
    pub fn eval(&self, e: ExprId) -> Result<i64, RuntimeError> {
        eval(&self.program.nodes, &self.slots, e)
    }

    /// Run one tick with the inputs currently in the input slots.
    pub fn step(&mut self) -> Result<(), RuntimeError> {
        let p = self.program;
        exec(p, &mut self.slots, &mut self.coverage, &p.step)
    }
}

fn exec(p: &Program, slots: &mut [i64], cov: &mut Option<Vec<u64>>, stmts: &[Stmt]) -> Result<(), RuntimeError> {
    for s in stmts {
        match s {
            Stmt::Assign { slot, expr, site } => {
                let v = eval(&p.nodes, slots, *expr)?;
                if let Some(site) = site {
                    let sl = &p.slots[*slot as usize];
                    if v < sl.lo || v > sl.hi {
                        return Err(RuntimeError { kind: RuntimeErrorKind::Range { value: v, lo: sl.lo, hi: sl.hi }, site: *site });
                    }
                }
                slots[*slot as usize] = v;
            }
            Stmt::If { cond, then, otherwise } => {
                if eval(&p.nodes, slots, *cond)? != 0 {
                    exec(p, slots, cov, then)?;
                } else {
                    exec(p, slots, cov, otherwise)?;
                }
            }
            Stmt::Switch { slot, cases } => {
                let v = slots[*slot as usize];
                if let Some(block) = cases.get(v as usize) {
                    exec(p, slots, cov, block)?;
                }
            }
            Stmt::Call(proc_id) => exec(p, slots, cov, &p.procs[*proc_id as usize].body)?,
            Stmt::Cover(c) => {
                if let Some(counts) = cov {
                    counts[*c as usize] += 1;
                }
            }
        }
    }
    Ok(())
}

fn op_error(e: ops::OpError, site: SiteId) -> RuntimeError {
    let kind = match e {
        ops::OpError::DivisionByZero => RuntimeErrorKind::DivisionByZero,
        ops::OpError::BadShift => RuntimeErrorKind::BadShift,
        ops::OpError::Overflow => RuntimeErrorKind::Overflow,
    };
    RuntimeError { kind, site }
}

/// Evaluate expression `e` over `slots`.
pub fn eval(nodes: &[Node], slots: &[i64], e: ExprId) -> Result<i64, RuntimeError> {
    Ok(match &nodes[e as usize] {
        Node::Const(v) => *v,
        Node::Slot(s) => slots[*s as usize],
        Node::Unary(op, a) => {
            let a = eval(nodes, slots, *a)?;
            ops::unary(*op, a).map_err(|err| op_error(err, u32::MAX))?
        }
        Node::Binary(op, a, b, site) => {
            let a = eval(nodes, slots, *a)?;
            match op {
                BinOp::And if a == 0 => return Ok(0),
                BinOp::Or if a != 0 => return Ok(1),
                _ => {}
            }
            let b = eval(nodes, slots, *b)?;
            ops::binary(*op, a, b).map_err(|err| op_error(err, *site))?
        }
        Node::Ite(c, a, b) => {
            if eval(nodes, slots, *c)? != 0 {
                eval(nodes, slots, *a)?
            } else {
                eval(nodes, slots, *b)?
            }
        }
        Node::Min(a, b) => eval(nodes, slots, *a)?.min(eval(nodes, slots, *b)?),
        Node::Max(a, b) => eval(nodes, slots, *a)?.max(eval(nodes, slots, *b)?),
        Node::Abs(a, site) => {
            let a = eval(nodes, slots, *a)?;
            a.checked_abs().ok_or(RuntimeError { kind: RuntimeErrorKind::Overflow, site: *site })?
        }
        Node::Check(a, lo, hi, site) => {
            let v = eval(nodes, slots, *a)?;
            if v < *lo || v > *hi {
                return Err(RuntimeError { kind: RuntimeErrorKind::Range { value: v, lo: *lo, hi: *hi }, site: *site });
            }
            v
        }
    })
}
