//! Translation of the IR into register code, statement by statement and node by node.
//!
//! This module holds the driver (procedures, segments, constant numbering) and the statements;
//! `cond.rs` compiles conditions in control context to (compare-and-)branch instructions,
//! `value.rs` values to data instructions, `idioms.rs` the flag idioms to single instructions.
//! Values, including booleans, are computed without branches where that evaluates nothing the
//! tree evaluator would skip (see `value::total`). A value is written straight into its
//! destination when the destination is written only by the expression's last instruction,
//! after all operands are read, so a slot is never written before the tree evaluator would
//! write it (the state after a run-time error is the same). Range checks that [`Intervals`]
//! proves cannot fail are dropped; the others are fused with the store.

mod cond;
mod idioms;
mod value;

use super::interval::Intervals;
use super::op::{Op, Reg};
use crate::program::*;
use std::collections::HashMap;

/// The site of an instruction that cannot fail (and of `-`, as in the tree evaluator).
const NO_SITE: SiteId = u32::MAX;

/// The output of the compiler, before peephole optimisation.
pub(super) struct Compiled {
    /// The instructions.
    pub ops: Vec<Op>,
    /// The run-time check site of each instruction.
    pub sites: Vec<SiteId>,
    /// Switch tables (see [`Op::Switch`]).
    pub tables: Vec<u32>,
    /// Bounds of the range checks.
    pub bounds: Vec<(i64, i64)>,
    /// The initial register file.
    pub init_regs: Vec<i64>,
    /// The first constant register (the constants are never written).
    pub const_base: u32,
    /// Entry point of one tick.
    pub step: u32,
    /// Start and result register of each compiled expression.
    pub exprs: HashMap<ExprId, (u32, Reg)>,
}

struct Compiler<'p> {
    p: &'p Program,
    iv: Intervals<'p>,
    /// Whether each node contains a `Let` (evaluating it rebinds a local).
    has_let: Vec<bool>,
    /// Whether each node reads no local and binds none: its value depends only on the slots,
    /// which do not change while one statement's expression is evaluated.
    slots_only: Vec<bool>,
    /// Values already computed into temporaries on every path to the current instruction (in
    /// the current statement, since the last jump target).
    avail: HashMap<ExprId, Reg>,
    ops: Vec<Op>,
    sites: Vec<SiteId>,
    tables: Vec<u32>,
    bounds: Vec<(i64, i64)>,
    consts: HashMap<i64, Reg>,
    const_values: Vec<i64>,
    locals_base: u32,
    temps_base: u32,
    next_temp: u32,
    max_temp: u32,
    /// Set when the program needs more registers than a [`Reg`] can number.
    too_big: bool,
    /// How many `Call` statements name each procedure.
    calls: Vec<u32>,
    proc_entry: Vec<Option<u32>>,
    pending_calls: Vec<(usize, ProcId)>,
}

/// Compile a program; `None` when it has too many registers for [`Reg`].
pub(super) fn compile(p: &Program) -> Option<Compiled> {
    let locals_base = p.slots.len() as u32;
    let temps_base = locals_base + p.n_locals as u32;
    if temps_base >= Reg::MAX as u32 / 2 {
        return None;
    }
    let mut calls = vec![0u32; p.procs.len()];
    count_calls(&p.step, &mut calls);
    for proc_ in &p.procs {
        count_calls(&proc_.body, &mut calls);
    }
    let mut has_let = vec![false; p.nodes.len()];
    for (i, n) in p.nodes.iter().enumerate() {
        // Children come before their parents in the arena.
        has_let[i] = match *n {
            Node::Let(..) => true,
            Node::Const(_) | Node::Slot(_) | Node::Local(_) => false,
            Node::Unary(_, a) | Node::Abs(a, _) | Node::Check(a, ..) => has_let[a as usize],
            Node::Binary(_, a, b, _) | Node::Min(a, b) | Node::Max(a, b) => {
                has_let[a as usize] || has_let[b as usize]
            }
            Node::Ite(c, a, b) => has_let[c as usize] || has_let[a as usize] || has_let[b as usize],
        };
    }
    let mut slots_only = vec![false; p.nodes.len()];
    for (i, n) in p.nodes.iter().enumerate() {
        slots_only[i] = match *n {
            Node::Let(..) | Node::Local(_) => false,
            Node::Const(_) | Node::Slot(_) => true,
            Node::Unary(_, a) | Node::Abs(a, _) | Node::Check(a, ..) => slots_only[a as usize],
            Node::Binary(_, a, b, _) | Node::Min(a, b) | Node::Max(a, b) => {
                slots_only[a as usize] && slots_only[b as usize]
            }
            Node::Ite(c, a, b) => {
                slots_only[c as usize] && slots_only[a as usize] && slots_only[b as usize]
            }
        };
    }
    let mut c = Compiler {
        p,
        iv: Intervals::new(&p.nodes),
        has_let,
        slots_only,
        avail: HashMap::new(),
        ops: Vec::new(),
        sites: Vec::new(),
        tables: Vec::new(),
        bounds: Vec::new(),
        consts: HashMap::new(),
        const_values: Vec::new(),
        locals_base,
        temps_base,
        next_temp: 0,
        max_temp: 0,
        too_big: false,
        calls,
        proc_entry: vec![None; p.procs.len()],
        pending_calls: Vec::new(),
    };
    let step = c.here();
    c.block(&p.step);
    c.emit(Op::End);
    // Procedures that are still called, compiled once each; calls are patched afterwards.
    while let Some((at, id)) = c.pending_calls.pop() {
        let entry = match c.proc_entry[id as usize] {
            Some(e) => e,
            None => {
                let e = c.here();
                c.proc_entry[id as usize] = Some(e);
                c.block(&p.procs[id as usize].body);
                c.emit(Op::Ret);
                e
            }
        };
        if let Op::Call { t } = &mut c.ops[at] {
            *t = entry;
        }
    }
    // Segments for every expression a consumer evaluates outside the step.
    let mut exprs = HashMap::new();
    for e in roots(p) {
        if exprs.contains_key(&e) {
            continue;
        }
        let start = c.here();
        c.next_temp = 0;
        c.avail.clear();
        let reg = c.expr(e);
        c.emit(Op::End);
        exprs.insert(e, (start, reg));
    }
    // Number the constants after the temporaries.
    let n_consts = c.const_values.len() as u32;
    let const_base = temps_base + c.max_temp;
    if c.too_big || const_base + n_consts > Reg::MAX as u32 + 1 {
        return None;
    }
    let first_const = Reg::MAX as u32 + 1 - n_consts;
    let fix = |r: &mut Reg| {
        if *r as u32 >= first_const {
            *r = (const_base + (Reg::MAX as u32 - *r as u32)) as Reg;
        }
    };
    for op in &mut c.ops {
        op.for_each_reg(fix);
    }
    for (_, reg) in exprs.values_mut() {
        fix(reg);
    }
    let mut init_regs: Vec<i64> = p.slots.iter().map(|s| s.init).collect();
    init_regs.resize(const_base as usize, 0);
    init_regs.extend(&c.const_values);
    Some(Compiled {
        ops: c.ops,
        sites: c.sites,
        tables: c.tables,
        bounds: c.bounds,
        init_regs,
        const_base,
        step,
        exprs,
    })
}

/// Every expression a consumer evaluates outside the step: assumptions, properties and the
/// instances' active-state expressions. The `&&` conjuncts of an assumption too: the explicit
/// checker evaluates them one by one.
fn roots(p: &Program) -> Vec<ExprId> {
    let mut roots: Vec<ExprId> = p.assumes.clone();
    let mut stack = p.assumes.clone();
    while let Some(e) = stack.pop() {
        if let Some(Node::Binary(statecheck_syntax::ast::BinOp::And, a, b, _)) =
            p.nodes.get(e as usize)
        {
            roots.extend([*a, *b]);
            stack.extend([*a, *b]);
        }
    }
    for prop in &p.properties {
        roots.extend(prop.goal.exprs());
    }
    for inst in &p.instances {
        roots.extend(inst.active.iter().copied());
    }
    roots
}

fn count_calls(b: &[Stmt], calls: &mut [u32]) {
    for s in b {
        match s {
            Stmt::If {
                then, otherwise, ..
            } => {
                count_calls(then, calls);
                count_calls(otherwise, calls);
            }
            Stmt::Switch { cases, .. } => cases.iter().for_each(|c| count_calls(c, calls)),
            Stmt::Call(id) => calls[*id as usize] += 1,
            Stmt::Assign { .. } | Stmt::Cover(_) => {}
        }
    }
}

/// A procedure body of at most this many statements (and no calls) is inlined at every call.
const INLINE_SIZE: usize = 4;

fn imm(v: i64) -> Option<i32> {
    i32::try_from(v).ok()
}

impl Compiler<'_> {
    fn here(&self) -> u32 {
        self.ops.len() as u32
    }

    fn emit(&mut self, op: Op) {
        self.emit_at(op, NO_SITE);
    }

    /// Emit an instruction that can fail, reporting `site`.
    fn emit_at(&mut self, op: Op, site: SiteId) {
        self.ops.push(op);
        self.sites.push(site);
    }

    /// Emit a jump whose target is patched later; returns its index.
    fn emit_jump(&mut self, op: Op) -> usize {
        self.emit(op);
        self.ops.len() - 1
    }

    /// Point the jump at `at` to `target`, always the current position: a jump target, where
    /// values computed before are no longer known to be available.
    fn patch(&mut self, at: usize, target: u32) {
        if let Some(t) = self.ops[at].target_mut() {
            *t = target;
        }
        self.avail.clear();
    }

    fn patch_all(&mut self, list: Vec<usize>, target: u32) {
        for at in list {
            self.patch(at, target);
        }
        self.avail.clear();
    }

    /// The register of a constant. While compiling, constants are numbered down from
    /// [`Reg::MAX`]; they are renumbered after the temporaries at the end.
    fn konst(&mut self, v: i64) -> Reg {
        if let Some(r) = self.consts.get(&v) {
            return *r;
        }
        let k = self.const_values.len() as u32;
        if k >= Reg::MAX as u32 / 2 {
            self.too_big = true;
            return 0;
        }
        let r = (Reg::MAX as u32 - k) as Reg;
        self.const_values.push(v);
        self.consts.insert(v, r);
        r
    }

    fn temp(&mut self) -> Reg {
        let r = self.temps_base + self.next_temp;
        self.next_temp += 1;
        self.max_temp = self.max_temp.max(self.next_temp);
        if r >= Reg::MAX as u32 / 2 {
            self.too_big = true;
            return 0;
        }
        r as Reg
    }

    /// A fresh temporary, or the requested destination.
    fn dest(&mut self, want: Option<Reg>) -> Reg {
        match want {
            Some(d) => d,
            None => self.temp(),
        }
    }

    fn node(&self, e: ExprId) -> &Node {
        &self.p.nodes[e as usize]
    }

    /// The constant value of `e` as an immediate, if it is a constant that fits.
    fn imm_of(&self, e: ExprId) -> Option<i32> {
        match *self.node(e) {
            Node::Const(v) => imm(v),
            _ => None,
        }
    }

    fn is_leaf(&self, e: ExprId) -> bool {
        matches!(
            self.node(e),
            Node::Const(_) | Node::Slot(_) | Node::Local(_)
        )
    }

    fn block(&mut self, stmts: &[Stmt]) {
        for s in stmts {
            self.next_temp = 0;
            self.avail.clear();
            match s {
                Stmt::Assign { slot, expr, site } => {
                    let sl = &self.p.slots[*slot as usize];
                    let (lo, hi) = (sl.lo, sl.hi);
                    let d = *slot as Reg;
                    match site {
                        Some(site) if !self.iv.within(*expr, lo, hi) => {
                            let a = self.expr(*expr);
                            let bounds = self.bound(lo, hi);
                            self.emit_at(Op::CheckMov { d, a, bounds }, *site);
                        }
                        _ => self.into(*expr, d),
                    }
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
                        let jmp = self.emit_jump(Op::Jmp { t: 0 });
                        let else_start = self.here();
                        self.patch_all(fails, else_start);
                        self.block(otherwise);
                        let end = self.here();
                        self.patch(jmp, end);
                    }
                }
                Stmt::Switch { slot, cases } => {
                    let table = self.tables.len();
                    self.tables.extend(std::iter::repeat_n(0, 1 + cases.len()));
                    let Ok(len) = u16::try_from(cases.len()) else {
                        self.too_big = true;
                        continue;
                    };
                    self.emit(Op::Switch {
                        a: *slot as Reg,
                        len,
                        table: table as u32,
                    });
                    let mut jumps = Vec::new();
                    for (k, case) in cases.iter().enumerate() {
                        self.tables[table + 1 + k] = self.here();
                        self.avail.clear();
                        self.block(case);
                        jumps.push(self.emit_jump(Op::Jmp { t: 0 }));
                    }
                    let end = self.here();
                    self.patch_all(jumps, end);
                    self.tables[table] = end;
                }
                Stmt::Call(id) => {
                    let body = &self.p.procs[*id as usize].body;
                    let small = body.len() <= INLINE_SIZE
                        && body
                            .iter()
                            .all(|s| matches!(s, Stmt::Assign { .. } | Stmt::Cover(_)));
                    if self.calls[*id as usize] == 1 || small {
                        // Procedures never recurse, so inlining terminates.
                        self.block(body);
                    } else {
                        let at = self.emit_jump(Op::Call { t: 0 });
                        self.pending_calls.push((at, *id));
                    }
                }
                Stmt::Cover(id) => self.emit(Op::Cover { id: *id }),
            }
        }
    }

    fn bound(&mut self, lo: i64, hi: i64) -> u32 {
        self.bounds.push((lo, hi));
        self.bounds.len() as u32 - 1
    }
}
