//! The interpreter's fast path: the IR compiled once into flat register code.
//!
//! This is not a second semantics: it is a mechanical translation of [`Program::step`] and of
//! the property and assumption expressions, statement by statement and node by node, into
//! three-address instructions over one register file (the slots, then expression locals,
//! temporaries and constants). The tree evaluator in `interp.rs` stays the reference; tests run
//! both on the same inputs and compare.

use crate::program::*;
use statecheck_syntax::ast::{BinOp, UnOp};
use std::collections::HashMap;

/// Arithmetic and comparison operators of [`Op::Bin`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Bin {
    Add,
    Sub,
    Mul,
    Div,
    Rem,
    Shl,
    Shr,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    And,
    Or,
    Xor,
    Min,
    Max,
}

/// Comparisons of [`Op::JCmp`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Cmp {
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

impl Cmp {
    fn negate(self) -> Cmp {
        match self {
            Cmp::Eq => Cmp::Ne,
            Cmp::Ne => Cmp::Eq,
            Cmp::Lt => Cmp::Ge,
            Cmp::Le => Cmp::Gt,
            Cmp::Gt => Cmp::Le,
            Cmp::Ge => Cmp::Lt,
        }
    }

    fn of(op: BinOp) -> Option<Cmp> {
        Some(match op {
            BinOp::Eq => Cmp::Eq,
            BinOp::Ne => Cmp::Ne,
            BinOp::Lt => Cmp::Lt,
            BinOp::Le => Cmp::Le,
            BinOp::Gt => Cmp::Gt,
            BinOp::Ge => Cmp::Ge,
            _ => return None,
        })
    }
}

/// One instruction. Operands are register indices.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Op {
    /// `dst = a op b`; `site` reports division by zero, bad shifts and overflow.
    Bin {
        op: Bin,
        dst: u32,
        a: u32,
        b: u32,
        site: u32,
    },
    /// `dst = !a` (logical).
    Not { dst: u32, a: u32 },
    /// `dst = -a`.
    Neg { dst: u32, a: u32 },
    /// `dst = ~a`.
    BitNot { dst: u32, a: u32 },
    /// `dst = |a|`.
    Abs { dst: u32, a: u32, site: u32 },
    /// `dst = src`.
    Mov { dst: u32, src: u32 },
    /// Fail unless `lo <= reg <= hi` (bounds in `Code::bounds[b]`).
    Check { reg: u32, bounds: u32, site: u32 },
    /// Jump if `reg == 0`.
    Jz { reg: u32, target: u32 },
    /// Jump if `reg != 0`.
    Jnz { reg: u32, target: u32 },
    /// Jump if `a cmp b`.
    JCmp {
        cmp: Cmp,
        a: u32,
        b: u32,
        target: u32,
    },
    /// Jump.
    Jmp { target: u32 },
    /// Jump to `Code::tables[table + reg]` (falls through past the table when out of range).
    Switch {
        reg: u32,
        table: u32,
        len: u32,
        end: u32,
    },
    /// Call the code at `target`, returning to the next instruction.
    Call { target: u32 },
    /// Return from a call.
    Ret,
    /// Count a coverage item.
    Cover { id: u32 },
    /// End of a segment.
    End,
}

/// A compiled expression: run from `start` to its `End`, result in `reg`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Segment {
    pub start: u32,
    pub reg: u32,
}

/// The compiled form of a program.
#[derive(Clone, Debug)]
pub(crate) struct Code {
    pub ops: Vec<Op>,
    pub tables: Vec<u32>,
    pub bounds: Vec<(i64, i64)>,
    /// Initial register file: slots' initial values, zeros, and the constants.
    pub init_regs: Vec<i64>,
    /// Entry point of one tick.
    pub step: u32,
    /// Compiled property/assumption/active-state expressions by expression id.
    pub exprs: HashMap<ExprId, Segment>,
    /// Deepest call nesting (for the return stack).
    pub max_depth: usize,
}

struct Compiler<'p> {
    p: &'p Program,
    ops: Vec<Op>,
    tables: Vec<u32>,
    bounds: Vec<(i64, i64)>,
    consts: HashMap<i64, u32>,
    const_values: Vec<i64>,
    /// Registers: slots, then locals, then temporaries; constants are numbered after compiling.
    locals_base: u32,
    temps_base: u32,
    next_temp: u32,
    max_temp: u32,
    proc_entry: Vec<Option<u32>>,
    pending_calls: Vec<(usize, ProcId)>,
}

const CONST_TAG: u32 = 1 << 31;

impl Code {
    /// Compile a program.
    pub(crate) fn compile(p: &Program) -> Code {
        let locals_base = p.slots.len() as u32;
        let temps_base = locals_base + p.n_locals as u32;
        let mut c = Compiler {
            p,
            ops: Vec::new(),
            tables: Vec::new(),
            bounds: Vec::new(),
            consts: HashMap::new(),
            const_values: Vec::new(),
            locals_base,
            temps_base,
            next_temp: 0,
            max_temp: 0,
            proc_entry: vec![None; p.procs.len()],
            pending_calls: Vec::new(),
        };
        let step = c.ops.len() as u32;
        c.block(&p.step);
        c.ops.push(Op::End);
        // Procedures, compiled once each; calls are patched afterwards.
        for (id, proc_) in p.procs.iter().enumerate() {
            c.proc_entry[id] = Some(c.ops.len() as u32);
            c.block(&proc_.body);
            c.ops.push(Op::Ret);
        }
        for (at, id) in std::mem::take(&mut c.pending_calls) {
            if let Op::Call { target } = &mut c.ops[at] {
                *target = c.proc_entry[id as usize].unwrap_or(0);
            }
        }
        // Segments for every expression a consumer evaluates outside the step.
        let mut roots: Vec<ExprId> = p.assumes.clone();
        for prop in &p.properties {
            match &prop.kind {
                PropertyKind::Invariant { expr, assuming } => {
                    roots.push(*expr);
                    roots.extend(assuming);
                }
                PropertyKind::Reachable { expr } => roots.push(*expr),
                PropertyKind::Respond { ok, .. } | PropertyKind::Observer { ok, .. } => {
                    roots.push(*ok)
                }
            }
        }
        for inst in &p.instances {
            roots.extend(inst.active.iter().copied());
        }
        let mut exprs = HashMap::new();
        for e in roots {
            if exprs.contains_key(&e) {
                continue;
            }
            let start = c.ops.len() as u32;
            c.next_temp = 0;
            let reg = c.expr(e);
            c.ops.push(Op::End);
            exprs.insert(e, Segment { start, reg });
        }
        let depth = max_call_depth(p);
        // Number the constants after the temporaries and patch the tagged operands.
        let const_base = temps_base + c.max_temp;
        let fix = |r: &mut u32| {
            if *r & CONST_TAG != 0 {
                *r = const_base + (*r & !CONST_TAG);
            }
        };
        for op in &mut c.ops {
            match op {
                Op::Bin { a, b, .. } => {
                    fix(a);
                    fix(b);
                }
                Op::Not { a, .. }
                | Op::Neg { a, .. }
                | Op::BitNot { a, .. }
                | Op::Abs { a, .. } => fix(a),
                Op::Mov { src, .. } => fix(src),
                Op::Check { reg, .. }
                | Op::Jz { reg, .. }
                | Op::Jnz { reg, .. }
                | Op::Switch { reg, .. } => fix(reg),
                Op::JCmp { a, b, .. } => {
                    fix(a);
                    fix(b);
                }
                _ => {}
            }
        }
        for seg in exprs.values_mut() {
            fix(&mut seg.reg);
        }
        let mut init_regs: Vec<i64> = p.slots.iter().map(|s| s.init).collect();
        init_regs.resize(const_base as usize, 0);
        init_regs.extend(&c.const_values);
        Code {
            ops: c.ops,
            tables: c.tables,
            bounds: c.bounds,
            init_regs,
            step,
            exprs,
            max_depth: depth + 2,
        }
    }
}

fn max_call_depth(p: &Program) -> usize {
    fn block(p: &Program, b: &[Stmt], memo: &mut Vec<Option<usize>>) -> usize {
        b.iter()
            .map(|s| match s {
                Stmt::If {
                    then, otherwise, ..
                } => block(p, then, memo).max(block(p, otherwise, memo)),
                Stmt::Switch { cases, .. } => {
                    cases.iter().map(|c| block(p, c, memo)).max().unwrap_or(0)
                }
                Stmt::Call(id) => 1 + proc_depth(p, *id, memo),
                _ => 0,
            })
            .max()
            .unwrap_or(0)
    }
    fn proc_depth(p: &Program, id: ProcId, memo: &mut Vec<Option<usize>>) -> usize {
        if let Some(d) = memo[id as usize] {
            return d;
        }
        memo[id as usize] = Some(0);
        let d = block(p, &p.procs[id as usize].body, memo);
        memo[id as usize] = Some(d);
        d
    }
    let mut memo = vec![None; p.procs.len()];
    block(p, &p.step, &mut memo)
}

impl Compiler<'_> {
    fn konst(&mut self, v: i64) -> u32 {
        if let Some(r) = self.consts.get(&v) {
            return *r;
        }
        let r = CONST_TAG | self.const_values.len() as u32;
        self.const_values.push(v);
        self.consts.insert(v, r);
        r
    }

    fn temp(&mut self) -> u32 {
        let r = self.temps_base + self.next_temp;
        self.next_temp += 1;
        self.max_temp = self.max_temp.max(self.next_temp);
        r
    }

    fn here(&self) -> u32 {
        self.ops.len() as u32
    }

    fn patch(&mut self, at: usize, target: u32) {
        match &mut self.ops[at] {
            Op::Jz { target: t, .. }
            | Op::Jnz { target: t, .. }
            | Op::JCmp { target: t, .. }
            | Op::Jmp { target: t } => *t = target,
            _ => {}
        }
    }

    fn patch_all(&mut self, list: Vec<usize>, target: u32) {
        for at in list {
            self.patch(at, target);
        }
    }

    /// Emit code that jumps (through `targets`, patched later) when `e` evaluates to `sense`
    /// and falls through otherwise: booleans compile to control flow, not to 0/1 values.
    fn jump_when(&mut self, e: ExprId, sense: bool, targets: &mut Vec<usize>) {
        match self.p.nodes[e as usize] {
            // `a && b` is false as soon as one operand is, `a || b` true as soon as one is:
            // both operands jump to the same place.
            Node::Binary(BinOp::And, a, b, _) if !sense => {
                self.jump_when(a, false, targets);
                self.jump_when(b, false, targets);
            }
            Node::Binary(BinOp::Or, a, b, _) if sense => {
                self.jump_when(a, true, targets);
                self.jump_when(b, true, targets);
            }
            // Otherwise the first operand can only decide the opposite outcome, by skipping the
            // second one.
            Node::Binary(op @ (BinOp::And | BinOp::Or), a, b, _) => {
                let mut skip = Vec::new();
                self.jump_when(a, op == BinOp::Or, &mut skip);
                self.jump_when(b, sense, targets);
                let here = self.here();
                self.patch_all(skip, here);
            }
            Node::Unary(UnOp::Not, a) => self.jump_when(a, !sense, targets),
            Node::Const(v) => {
                if (v != 0) == sense {
                    targets.push(self.ops.len());
                    self.ops.push(Op::Jmp { target: 0 });
                }
            }
            Node::Binary(op, a, b, _) if Cmp::of(op).is_some() => {
                let cmp = Cmp::of(op).unwrap_or(Cmp::Eq);
                let cmp = if sense { cmp } else { cmp.negate() };
                let (ra, rb) = (self.expr(a), self.expr(b));
                targets.push(self.ops.len());
                self.ops.push(Op::JCmp {
                    cmp,
                    a: ra,
                    b: rb,
                    target: 0,
                });
            }
            _ => {
                let reg = self.expr(e);
                targets.push(self.ops.len());
                self.ops.push(if sense {
                    Op::Jnz { reg, target: 0 }
                } else {
                    Op::Jz { reg, target: 0 }
                });
            }
        }
    }

    fn block(&mut self, stmts: &[Stmt]) {
        for s in stmts {
            self.next_temp = 0;
            match s {
                Stmt::Assign {
                    slot,
                    expr,
                    site: None,
                } => {
                    let r = self.expr_into(*expr, Some(*slot));
                    if r != *slot {
                        self.ops.push(Op::Mov { dst: *slot, src: r });
                    }
                }
                Stmt::Assign { slot, expr, site } => {
                    let r = self.expr(*expr);
                    if let Some(site) = site {
                        let sl = &self.p.slots[*slot as usize];
                        self.bounds.push((sl.lo, sl.hi));
                        let bounds = self.bounds.len() as u32 - 1;
                        self.ops.push(Op::Check {
                            reg: r,
                            bounds,
                            site: *site,
                        });
                    }
                    self.ops.push(Op::Mov { dst: *slot, src: r });
                }
                Stmt::If {
                    cond,
                    then,
                    otherwise,
                } => {
                    let mut fails = Vec::new();
                    self.jump_when(*cond, false, &mut fails);
                    self.block(then);
                    if otherwise.is_empty() {
                        let end = self.here();
                        self.patch_all(fails, end);
                    } else {
                        let jmp = self.ops.len();
                        self.ops.push(Op::Jmp { target: 0 });
                        let else_start = self.here();
                        self.patch_all(fails, else_start);
                        self.block(otherwise);
                        let end = self.here();
                        self.patch(jmp, end);
                    }
                }
                Stmt::Switch { slot, cases } => {
                    let table = self.tables.len() as u32;
                    self.tables.extend(std::iter::repeat_n(0, cases.len()));
                    let sw = self.ops.len();
                    self.ops.push(Op::Switch {
                        reg: *slot,
                        table,
                        len: cases.len() as u32,
                        end: 0,
                    });
                    let mut jumps = Vec::new();
                    for (k, case) in cases.iter().enumerate() {
                        self.tables[table as usize + k] = self.here();
                        self.block(case);
                        jumps.push(self.ops.len());
                        self.ops.push(Op::Jmp { target: 0 });
                    }
                    let end = self.here();
                    for j in jumps {
                        self.patch(j, end);
                    }
                    if let Op::Switch { end: e, .. } = &mut self.ops[sw] {
                        *e = end;
                    }
                }
                Stmt::Call(id) => {
                    self.pending_calls.push((self.ops.len(), *id));
                    self.ops.push(Op::Call { target: 0 });
                }
                Stmt::Cover(id) => self.ops.push(Op::Cover { id: *id }),
            }
        }
    }

    /// Compile an expression; returns the register holding its value.
    fn expr(&mut self, e: ExprId) -> u32 {
        self.expr_into(e, None)
    }

    fn is_leaf(&self, e: ExprId) -> bool {
        matches!(
            self.p.nodes[e as usize],
            Node::Const(_) | Node::Slot(_) | Node::Local(_)
        )
    }

    /// A fresh temporary, or the requested destination.
    fn dest(&mut self, want: Option<u32>) -> u32 {
        match want {
            Some(d) => d,
            None => self.temp(),
        }
    }

    /// Compile an expression, writing its value into `want` when that saves a move (the
    /// destination is written only by the last instruction, after all operands are read).
    fn expr_into(&mut self, e: ExprId, want: Option<u32>) -> u32 {
        match self.p.nodes[e as usize] {
            Node::Const(v) => self.konst(v),
            Node::Slot(s) => s,
            Node::Local(l) => self.locals_base + l,
            Node::Let(l, v, body) => {
                let local = self.locals_base + l;
                let rv = self.expr_into(v, Some(local));
                if rv != local {
                    self.ops.push(Op::Mov {
                        dst: local,
                        src: rv,
                    });
                }
                self.expr_into(body, want)
            }
            Node::Binary(BinOp::And | BinOp::Or, ..) | Node::Unary(UnOp::Not, _) => {
                // A boolean in value context: 0, then 1 unless the jump code says false.
                let dst = self.temp();
                let zero = self.konst(0);
                let one = self.konst(1);
                self.ops.push(Op::Mov { dst, src: zero });
                let mut fails = Vec::new();
                self.jump_when(e, false, &mut fails);
                self.ops.push(Op::Mov { dst, src: one });
                let end = self.here();
                self.patch_all(fails, end);
                dst
            }
            Node::Unary(op, a) => {
                let ra = self.expr(a);
                let dst = self.dest(want);
                self.ops.push(match op {
                    UnOp::Not => Op::Not { dst, a: ra },
                    UnOp::Neg => Op::Neg { dst, a: ra },
                    UnOp::BitNot => Op::BitNot { dst, a: ra },
                });
                dst
            }
            Node::Binary(op, a, b, _) if Cmp::of(op).is_some() && want.is_none() => {
                let dst = self.temp();
                let zero = self.konst(0);
                let one = self.konst(1);
                let (ra, rb) = (self.expr(a), self.expr(b));
                let cmp = Cmp::of(op).map_or(Cmp::Eq, Cmp::negate);
                self.ops.push(Op::Mov { dst, src: zero });
                let j = self.ops.len();
                self.ops.push(Op::JCmp {
                    cmp,
                    a: ra,
                    b: rb,
                    target: 0,
                });
                self.ops.push(Op::Mov { dst, src: one });
                let end = self.here();
                self.patch(j, end);
                dst
            }
            Node::Binary(op, a, b, site) => {
                let ra = self.expr(a);
                let rb = self.expr(b);
                let dst = self.dest(want);
                let op = match op {
                    BinOp::Add => Bin::Add,
                    BinOp::Sub => Bin::Sub,
                    BinOp::Mul => Bin::Mul,
                    BinOp::Div => Bin::Div,
                    BinOp::Rem => Bin::Rem,
                    BinOp::Shl => Bin::Shl,
                    BinOp::Shr => Bin::Shr,
                    BinOp::Eq => Bin::Eq,
                    BinOp::Ne => Bin::Ne,
                    BinOp::Lt => Bin::Lt,
                    BinOp::Le => Bin::Le,
                    BinOp::Gt => Bin::Gt,
                    BinOp::Ge => Bin::Ge,
                    BinOp::BitAnd => Bin::And,
                    BinOp::BitOr => Bin::Or,
                    BinOp::BitXor => Bin::Xor,
                    BinOp::And | BinOp::Or => unreachable_logic(),
                };
                self.ops.push(Op::Bin {
                    op,
                    dst,
                    a: ra,
                    b: rb,
                    site,
                });
                dst
            }
            Node::Ite(c, a, b) if self.is_leaf(a) && self.is_leaf(b) => {
                // Both branches are constants, slots or locals: no jump over the else part.
                let dst = self.temp();
                let rb = self.expr(b);
                self.ops.push(Op::Mov { dst, src: rb });
                let mut fails = Vec::new();
                self.jump_when(c, false, &mut fails);
                let ra = self.expr(a);
                self.ops.push(Op::Mov { dst, src: ra });
                let end = self.here();
                self.patch_all(fails, end);
                dst
            }
            Node::Ite(c, a, b) => {
                let dst = self.temp();
                let mut fails = Vec::new();
                self.jump_when(c, false, &mut fails);
                let ra = self.expr(a);
                self.ops.push(Op::Mov { dst, src: ra });
                let jmp = self.ops.len();
                self.ops.push(Op::Jmp { target: 0 });
                let else_start = self.here();
                self.patch_all(fails, else_start);
                let rb = self.expr(b);
                self.ops.push(Op::Mov { dst, src: rb });
                let end = self.here();
                self.patch(jmp, end);
                dst
            }
            Node::Min(a, b) | Node::Max(a, b) => {
                let is_min = matches!(self.p.nodes[e as usize], Node::Min(..));
                let ra = self.expr(a);
                let rb = self.expr(b);
                let dst = self.dest(want);
                self.ops.push(Op::Bin {
                    op: if is_min { Bin::Min } else { Bin::Max },
                    dst,
                    a: ra,
                    b: rb,
                    site: u32::MAX,
                });
                dst
            }
            Node::Abs(a, site) => {
                let ra = self.expr(a);
                let dst = self.dest(want);
                self.ops.push(Op::Abs { dst, a: ra, site });
                dst
            }
            Node::Check(a, lo, hi, site) => {
                let ra = self.expr(a);
                self.bounds.push((lo, hi));
                let bounds = self.bounds.len() as u32 - 1;
                self.ops.push(Op::Check {
                    reg: ra,
                    bounds,
                    site,
                });
                ra
            }
        }
    }
}

/// `&&` and `||` are compiled as jumps above; this arm cannot be reached.
fn unreachable_logic() -> Bin {
    Bin::And
}

/// Depth of the return stack; programs nested deeper run on the reference evaluator.
pub(crate) const STACK: usize = 64;

/// Run a segment from `start` until its `End`.
#[inline(never)]
pub(crate) fn run(
    code: &Code,
    regs: &mut [i64],
    mut cov: Option<&mut [u64]>,
    start: u32,
) -> Result<(), Box<crate::RuntimeError>> {
    use crate::interp::{fault_of, RuntimeErrorKind as K};
    let ops = &code.ops[..];
    let mut stack = [0u32; STACK];
    let mut sp = 0usize;
    let mut pc = start as usize;
    loop {
        let op = &ops[pc];
        pc += 1;
        match *op {
            Op::Bin {
                op,
                dst,
                a,
                b,
                site,
            } => {
                let (x, y) = (regs[a as usize], regs[b as usize]);
                let v = match op {
                    Bin::Add => x
                        .checked_add(y)
                        .ok_or_else(|| fault_of(K::Overflow, site))?,
                    Bin::Sub => x
                        .checked_sub(y)
                        .ok_or_else(|| fault_of(K::Overflow, site))?,
                    Bin::Mul => x
                        .checked_mul(y)
                        .ok_or_else(|| fault_of(K::Overflow, site))?,
                    Bin::Eq => (x == y) as i64,
                    Bin::Ne => (x != y) as i64,
                    Bin::Lt => (x < y) as i64,
                    Bin::Le => (x <= y) as i64,
                    Bin::Gt => (x > y) as i64,
                    Bin::Ge => (x >= y) as i64,
                    Bin::And => x & y,
                    Bin::Or => x | y,
                    Bin::Xor => x ^ y,
                    Bin::Min => x.min(y),
                    Bin::Max => x.max(y),
                    Bin::Div | Bin::Rem | Bin::Shl | Bin::Shr => {
                        let bop = match op {
                            Bin::Div => BinOp::Div,
                            Bin::Rem => BinOp::Rem,
                            Bin::Shl => BinOp::Shl,
                            _ => BinOp::Shr,
                        };
                        statecheck_model::ops::binary(bop, x, y)
                            .map_err(|e| crate::interp::op_fault(e, site))?
                    }
                };
                regs[dst as usize] = v;
            }
            Op::Not { dst, a } => regs[dst as usize] = (regs[a as usize] == 0) as i64,
            Op::Neg { dst, a } => {
                regs[dst as usize] = regs[a as usize]
                    .checked_neg()
                    .ok_or_else(|| fault_of(K::Overflow, u32::MAX))?
            }
            Op::BitNot { dst, a } => regs[dst as usize] = !regs[a as usize],
            Op::Abs { dst, a, site } => {
                regs[dst as usize] = regs[a as usize]
                    .checked_abs()
                    .ok_or_else(|| fault_of(K::Overflow, site))?
            }
            Op::Mov { dst, src } => regs[dst as usize] = regs[src as usize],
            Op::Check { reg, bounds, site } => {
                let v = regs[reg as usize];
                let (lo, hi) = code.bounds[bounds as usize];
                if v < lo || v > hi {
                    return Err(fault_of(K::Range { value: v, lo, hi }, site));
                }
            }
            Op::Jz { reg, target } => {
                if regs[reg as usize] == 0 {
                    pc = target as usize;
                }
            }
            Op::Jnz { reg, target } => {
                if regs[reg as usize] != 0 {
                    pc = target as usize;
                }
            }
            Op::JCmp { cmp, a, b, target } => {
                let (x, y) = (regs[a as usize], regs[b as usize]);
                let t = match cmp {
                    Cmp::Eq => x == y,
                    Cmp::Ne => x != y,
                    Cmp::Lt => x < y,
                    Cmp::Le => x <= y,
                    Cmp::Gt => x > y,
                    Cmp::Ge => x >= y,
                };
                if t {
                    pc = target as usize;
                }
            }
            Op::Jmp { target } => pc = target as usize,
            Op::Switch {
                reg,
                table,
                len,
                end,
            } => {
                let v = regs[reg as usize];
                pc = if v >= 0 && (v as u32) < len {
                    code.tables[(table + v as u32) as usize] as usize
                } else {
                    end as usize
                };
            }
            Op::Call { target } => {
                stack[sp] = pc as u32;
                sp += 1;
                pc = target as usize;
            }
            Op::Ret => {
                sp -= 1;
                pc = stack[sp] as usize;
            }
            Op::Cover { id } => {
                if let Some(c) = cov.as_deref_mut() {
                    c[id as usize] += 1;
                }
            }
            Op::End => return Ok(()),
        }
    }
}
