//! Translation of the IR into register code, statement by statement and node by node.
//!
//! Conditions in control context compile to (compare-and-)branch instructions; values, including
//! booleans, compile to data instructions where that evaluates nothing the tree evaluator would
//! not (see [`total`]): a comparison to a 0/1 value, `a && b` to [`Op::LAnd`] when `b` cannot fail
//! and is cheap, `if c then x else y` over constants, slots and locals to a branch-free
//! [`Op::Sel`]. A value is written straight into its destination when the destination is
//! written only by the expression's last instruction, after all operands are read, so a slot is
//! never written before the tree evaluator would write it (the state after a run-time error is
//! the same). Range checks that [`Intervals`] proves cannot fail are dropped; the others are
//! fused with the store.

use super::interval::Intervals;
use super::op::{Op, Reg};
use crate::program::*;
use statecheck_syntax::ast::{BinOp, UnOp};
use std::collections::HashMap;

/// The site of an instruction that cannot fail (and of `-`, as in the tree evaluator).
const NO_SITE: SiteId = u32::MAX;

/// Comparisons, for negating and mirroring them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Cmp {
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

impl Cmp {
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

    /// `!(a cmp b)` is `a cmp.negate() b`.
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

    /// `a cmp b` is `b cmp.mirror() a`.
    fn mirror(self) -> Cmp {
        match self {
            Cmp::Eq => Cmp::Eq,
            Cmp::Ne => Cmp::Ne,
            Cmp::Lt => Cmp::Gt,
            Cmp::Le => Cmp::Ge,
            Cmp::Gt => Cmp::Lt,
            Cmp::Ge => Cmp::Le,
        }
    }
}

/// A term of a tree of `|`: a `let` binding met on the way, or an operand.
enum OrTerm {
    Bind(u32, ExprId),
    Value(ExprId),
}

/// The output of the compiler, before peephole optimisation.
pub(super) struct Compiled {
    pub ops: Vec<Op>,
    pub sites: Vec<SiteId>,
    pub tables: Vec<u32>,
    pub bounds: Vec<(i64, i64)>,
    pub init_regs: Vec<i64>,
    /// The first constant register (the constants are never written).
    pub const_base: u32,
    pub step: u32,
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
/// instances' active-state expressions.
fn roots(p: &Program) -> Vec<ExprId> {
    let mut roots: Vec<ExprId> = p.assumes.clone();
    for prop in &p.properties {
        match &prop.kind {
            PropertyKind::Invariant { expr, assuming } => {
                roots.push(*expr);
                roots.extend(assuming);
            }
            PropertyKind::Reachable { expr } => roots.push(*expr),
            PropertyKind::Respond { ok, .. } | PropertyKind::Observer { ok, .. } => roots.push(*ok),
        }
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

/// True when evaluating `e` can neither fail nor write anything, so evaluating it where the
/// tree evaluator would skip it (the right operand of `&&`, `||`) is unobservable.
fn total(nodes: &[Node], e: ExprId) -> bool {
    match nodes[e as usize] {
        Node::Const(_) | Node::Slot(_) | Node::Local(_) => true,
        Node::Unary(UnOp::Not | UnOp::BitNot, a) => total(nodes, a),
        Node::Binary(
            BinOp::Eq
            | BinOp::Ne
            | BinOp::Lt
            | BinOp::Le
            | BinOp::Gt
            | BinOp::Ge
            | BinOp::BitAnd
            | BinOp::BitOr
            | BinOp::BitXor
            | BinOp::And
            | BinOp::Or,
            a,
            b,
            _,
        )
        | Node::Min(a, b)
        | Node::Max(a, b) => total(nodes, a) && total(nodes, b),
        Node::Ite(c, a, b) => total(nodes, c) && total(nodes, a) && total(nodes, b),
        Node::Unary(UnOp::Neg, _)
        | Node::Binary(..)
        | Node::Abs(..)
        | Node::Check(..)
        | Node::Let(..) => false,
    }
}

/// Number of operator nodes in `e`, up to `limit` (a leaf counts 0).
fn size(nodes: &[Node], e: ExprId, limit: u32) -> u32 {
    let kids: &[ExprId] = match &nodes[e as usize] {
        Node::Const(_) | Node::Slot(_) | Node::Local(_) => return 0,
        Node::Unary(_, a) | Node::Abs(a, _) | Node::Check(a, ..) => &[*a],
        Node::Binary(_, a, b, _) | Node::Min(a, b) | Node::Max(a, b) | Node::Let(_, a, b) => {
            &[*a, *b]
        }
        Node::Ite(c, a, b) => &[*c, *a, *b],
    };
    let mut n = 1;
    for &k in kids {
        if n > limit {
            break;
        }
        n += size(nodes, k, limit);
    }
    n
}

/// The right operand of `&&`/`||` is evaluated eagerly, without a branch, when it is total and
/// at most this many operators.
const EAGER_SIZE: u32 = 2;

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

    // ----- statements -----------------------------------------------------------------------

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

    // ----- conditions -----------------------------------------------------------------------

    /// Emit code that jumps (through `targets`, patched later) when `e` evaluates to `sense`
    /// and falls through otherwise.
    fn jump_when(&mut self, e: ExprId, sense: bool, targets: &mut Vec<usize>) {
        if let Some((x, set)) = self.set_test(e) {
            let a = self.expr(x);
            let t = 0;
            targets.push(self.emit_jump(if sense {
                Op::JIn { a, set, t }
            } else {
                Op::JNotIn { a, set, t }
            }));
            return;
        }
        if let Some((x, imm, nonzero)) = self.bit_test(e) {
            let a = self.expr(x);
            let t = 0;
            targets.push(self.emit_jump(if nonzero == sense {
                Op::JAnyI { a, imm, t }
            } else {
                Op::JNoneI { a, imm, t }
            }));
            return;
        }
        match *self.node(e) {
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
                    targets.push(self.emit_jump(Op::Jmp { t: 0 }));
                }
            }
            Node::Binary(op, a, b, _) if Cmp::of(op).is_some() => {
                let cmp = Cmp::of(op).unwrap_or(Cmp::Eq);
                let cmp = if sense { cmp } else { cmp.negate() };
                let op = self.compare_jump(cmp, a, b);
                targets.push(self.emit_jump(op));
            }
            _ => {
                let a = self.expr(e);
                targets.push(self.emit_jump(if sense {
                    Op::Jnz { a, t: 0 }
                } else {
                    Op::Jz { a, t: 0 }
                }));
            }
        }
    }

    /// The (unpatched) jump taken when `a cmp b`, operands evaluated left to right.
    fn compare_jump(&mut self, cmp: Cmp, a: ExprId, b: ExprId) -> Op {
        let (cmp, x, k) = match (self.imm_of(a), self.imm_of(b)) {
            (_, Some(k)) => (cmp, self.expr(a), k),
            (Some(k), None) => (cmp.mirror(), self.expr(b), k),
            (None, None) => {
                let (x, y) = self.operands(a, b);
                return match cmp {
                    Cmp::Eq => Op::JEq { a: x, b: y, t: 0 },
                    Cmp::Ne => Op::JNe { a: x, b: y, t: 0 },
                    Cmp::Lt => Op::JLt { a: x, b: y, t: 0 },
                    Cmp::Le => Op::JLe { a: x, b: y, t: 0 },
                    Cmp::Gt => Op::JLt { a: y, b: x, t: 0 },
                    Cmp::Ge => Op::JLe { a: y, b: x, t: 0 },
                };
            }
        };
        let t = 0;
        match (cmp, k) {
            (Cmp::Eq, 0) => Op::Jz { a: x, t },
            (Cmp::Ne, 0) => Op::Jnz { a: x, t },
            (Cmp::Eq, imm) => Op::JEqI { a: x, imm, t },
            (Cmp::Ne, imm) => Op::JNeI { a: x, imm, t },
            (Cmp::Lt, imm) => Op::JLtI { a: x, imm, t },
            (Cmp::Le, imm) => Op::JLeI { a: x, imm, t },
            (Cmp::Gt, imm) => Op::JGtI { a: x, imm, t },
            (Cmp::Ge, imm) => Op::JGeI { a: x, imm, t },
        }
    }

    // ----- values ---------------------------------------------------------------------------

    /// Compile an expression; returns the register holding its value.
    fn expr(&mut self, e: ExprId) -> Reg {
        self.expr_into(e, None)
    }

    /// Compile two operands, left to right. When the first one's value is a local's register
    /// and the second rebinds a local, the first is copied first: the tree evaluator has read
    /// it before the rebinding.
    fn operands(&mut self, a: ExprId, b: ExprId) -> (Reg, Reg) {
        let mut x = self.expr(a);
        if self.has_let[b as usize] && self.is_local_reg(x) {
            let t = self.temp();
            self.emit(Op::Mov { d: t, a: x });
            x = t;
        }
        (x, self.expr(b))
    }

    fn is_local_reg(&self, r: Reg) -> bool {
        (self.locals_base..self.temps_base).contains(&(r as u32))
    }

    /// Compile `e` into register `d`.
    fn into(&mut self, e: ExprId, d: Reg) {
        if let Node::Const(v) = *self.node(e) {
            if let Some(imm) = imm(v) {
                self.emit(Op::MovI { d, imm });
                return;
            }
        }
        let r = self.expr_into(e, Some(d));
        if r != d {
            self.emit(Op::Mov { d, a: r });
        }
    }

    /// Compile an expression, writing its value into `want` when that saves a move: only when
    /// the destination is written by the last instruction, after all operands are read. A value
    /// computed earlier in the statement on every path to here is reused (it cannot have
    /// failed: the statement would have ended).
    fn expr_into(&mut self, e: ExprId, want: Option<Reg>) -> Reg {
        if self.is_leaf(e) || !self.slots_only[e as usize] {
            return self.compute(e, want);
        }
        if let Some(r) = self.avail.get(&e) {
            return *r;
        }
        let r = self.compute(e, want);
        if (self.temps_base..Reg::MAX as u32 / 2).contains(&(r as u32)) {
            self.avail.insert(e, r);
        }
        r
    }

    /// [`Self::expr_into`] without reuse.
    fn compute(&mut self, e: ExprId, want: Option<Reg>) -> Reg {
        match *self.node(e) {
            Node::Const(v) => self.konst(v),
            Node::Slot(s) => s as Reg,
            Node::Local(l) => (self.locals_base + l) as Reg,
            Node::Let(l, v, body) => {
                self.into(v, (self.locals_base + l) as Reg);
                self.expr_into(body, want)
            }
            Node::Binary(op, a, b, _) if Cmp::of(op).is_some() => {
                let cmp = Cmp::of(op).unwrap_or(Cmp::Eq);
                self.compare_value(cmp, a, b, want)
            }
            Node::Unary(UnOp::Not, a) => match *self.node(a) {
                Node::Binary(op, x, y, _) if Cmp::of(op).is_some() => {
                    let cmp = Cmp::of(op).unwrap_or(Cmp::Eq);
                    self.compare_value(cmp.negate(), x, y, want)
                }
                _ => {
                    let a = self.expr(a);
                    let d = self.dest(want);
                    self.emit(Op::Not { d, a });
                    d
                }
            },
            Node::Binary(BinOp::Or, ..) if self.set_test(e).is_some() => {
                let (x, set) = self.set_test(e).unwrap_or((e, 0));
                let a = self.expr(x);
                let d = self.dest(want);
                self.emit(Op::InSet { d, a, set });
                d
            }
            Node::Binary(op @ (BinOp::And | BinOp::Or), a, b, _)
                if total(&self.p.nodes, b) && size(&self.p.nodes, b, EAGER_SIZE) <= EAGER_SIZE =>
            {
                if op == BinOp::And {
                    if let Some(d) = self.and_test(a, b, want) {
                        return d;
                    }
                }
                let (a, b) = (self.expr(a), self.expr(b));
                let d = self.dest(want);
                self.emit(if op == BinOp::And {
                    Op::LAnd { d, a, b }
                } else {
                    Op::LOr { d, a, b }
                });
                d
            }
            Node::Binary(BinOp::And | BinOp::Or, ..) => {
                // A boolean in value context: 0, then 1 unless the jump code says false. The
                // destination is written before the operands are read: always a temporary.
                let d = self.temp();
                self.emit(Op::MovI { d, imm: 0 });
                let mut fails = Vec::new();
                self.jump_when(e, false, &mut fails);
                self.emit(Op::MovI { d, imm: 1 });
                let end = self.here();
                self.patch_all(fails, end);
                d
            }
            Node::Unary(op, a) => {
                let a = self.expr(a);
                let d = self.dest(want);
                match op {
                    UnOp::Neg => self.emit_at(Op::Neg { d, a }, NO_SITE),
                    UnOp::BitNot => self.emit(Op::BitNot { d, a }),
                    UnOp::Not => self.emit(Op::Not { d, a }),
                }
                d
            }
            Node::Binary(op, a, b, site) => self.binary(op, a, b, site, want),
            Node::Ite(c, a, b) if self.is_leaf(a) && self.is_leaf(b) => {
                // Both branches are constants, slots or locals: select without a branch.
                let c = self.expr(c);
                let (a, b) = (self.expr(a), self.expr(b));
                let d = self.dest(want);
                self.emit(Op::Sel { d, c, a, b });
                d
            }
            Node::Ite(c, a, b) => {
                // The condition is read before either branch writes the destination, and each
                // branch writes it last.
                let d = self.dest(want);
                let mut fails = Vec::new();
                self.jump_when(c, false, &mut fails);
                self.into(a, d);
                let jmp = self.emit_jump(Op::Jmp { t: 0 });
                let else_start = self.here();
                self.patch_all(fails, else_start);
                self.into(b, d);
                let end = self.here();
                self.patch(jmp, end);
                d
            }
            Node::Min(a, b) | Node::Max(a, b) => {
                let is_min = matches!(self.node(e), Node::Min(..));
                let (a, b) = self.operands(a, b);
                let d = self.dest(want);
                self.emit(if is_min {
                    Op::Min { d, a, b }
                } else {
                    Op::Max { d, a, b }
                });
                d
            }
            Node::Abs(a, site) => {
                let a = self.expr(a);
                let d = self.dest(want);
                self.emit_at(Op::Abs { d, a }, site);
                d
            }
            Node::Check(a, lo, hi, site) => {
                if self.iv.within(a, lo, hi) {
                    return self.expr_into(a, want);
                }
                let a = self.expr(a);
                let bounds = self.bound(lo, hi);
                match want {
                    Some(d) => {
                        self.emit_at(Op::CheckMov { d, a, bounds }, site);
                        d
                    }
                    None => {
                        self.emit_at(Op::Check { a, bounds }, site);
                        a
                    }
                }
            }
        }
    }

    /// The slot or local a leaf reads, to tell whether two leaves are the same.
    fn leaf_key(&self, e: ExprId) -> Option<(bool, u32)> {
        match *self.node(e) {
            Node::Slot(s) => Some((false, s)),
            Node::Local(l) => Some((true, l)),
            _ => None,
        }
    }

    /// `(x, set)` when `e` is `x == k1 || x == k2 || ..` for one slot or local `x` and at least
    /// two constants in `0..32` (an enumeration tested against several literals). The tests
    /// are total, so one membership test computes the same value.
    fn set_test(&self, e: ExprId) -> Option<(ExprId, u32)> {
        fn walk(
            c: &Compiler,
            e: ExprId,
            key: &mut Option<(bool, u32)>,
            set: &mut u32,
        ) -> Option<ExprId> {
            match *c.node(e) {
                Node::Binary(BinOp::Or, a, b, _) => {
                    let x = walk(c, a, key, set)?;
                    walk(c, b, key, set)?;
                    Some(x)
                }
                Node::Binary(BinOp::Eq, a, b, _) => {
                    let (x, k) = match (c.imm_of(a), c.imm_of(b)) {
                        (_, Some(k)) => (a, k),
                        (Some(k), None) => (b, k),
                        (None, None) => return None,
                    };
                    let this = c.leaf_key(x)?;
                    if *key.get_or_insert(this) != this || !(0..32).contains(&k) {
                        return None;
                    }
                    *set |= 1 << k;
                    Some(x)
                }
                _ => None,
            }
        }
        if !matches!(self.node(e), Node::Binary(BinOp::Or, ..)) {
            return None;
        }
        let (mut key, mut set) = (None, 0u32);
        let x = walk(self, e, &mut key, &mut set)?;
        (set.count_ones() >= 2).then_some((x, set))
    }

    /// `(x, k, nonzero)` when `e` is `(x & k) != 0` (`nonzero`) or `(x & k) == 0`, for an
    /// immediate `k` (a flag register tested against a mask).
    fn bit_test(&self, e: ExprId) -> Option<(ExprId, i32, bool)> {
        let Node::Binary(op @ (BinOp::Eq | BinOp::Ne), a, b, _) = *self.node(e) else {
            return None;
        };
        let masked = match (self.imm_of(a), self.imm_of(b)) {
            (_, Some(0)) => a,
            (Some(0), _) => b,
            _ => return None,
        };
        let Node::Binary(BinOp::BitAnd, x, y, _) = *self.node(masked) else {
            return None;
        };
        let (x, k) = match (self.imm_of(x), self.imm_of(y)) {
            (_, Some(k)) => (x, k),
            (Some(k), None) => (y, k),
            (None, None) => return None,
        };
        Some((x, k, op == BinOp::Ne))
    }

    /// `(x, k, equal)` when `e` is `x == k` or `x != k` (either way round) for a leaf `x` and
    /// an immediate `k`, and its value is not already available.
    fn leaf_test(&self, e: ExprId) -> Option<(ExprId, i32, bool)> {
        let Node::Binary(op @ (BinOp::Eq | BinOp::Ne), a, b, _) = *self.node(e) else {
            return None;
        };
        if self.avail.contains_key(&e) {
            return None;
        }
        let (x, k) = match (self.imm_of(a), self.imm_of(b)) {
            (_, Some(k)) => (a, k),
            (Some(k), None) => (b, k),
            (None, None) => return None,
        };
        self.is_leaf(x).then_some((x, k, op == BinOp::Eq))
    }

    /// `a && (x == k)` (or `!=`, either operand) as one instruction: a state test combined with
    /// a flag. Both operands are total here (`b` by the caller's condition, the test because it
    /// reads a leaf), so their order does not matter.
    fn and_test(&mut self, a: ExprId, b: ExprId, want: Option<Reg>) -> Option<Reg> {
        let (other, (x, imm, equal)) = match (self.leaf_test(b), self.leaf_test(a)) {
            (Some(t), _) => (a, t),
            (None, Some(t)) => (b, t),
            (None, None) => return None,
        };
        let a = self.expr(other);
        let b = self.expr(x);
        let d = self.dest(want);
        self.emit(if equal {
            Op::LAndEqI { d, a, b, imm }
        } else {
            Op::LAndNeI { d, a, b, imm }
        });
        Some(d)
    }

    /// `a cmp b` as a 0/1 value.
    fn compare_value(&mut self, cmp: Cmp, a: ExprId, b: ExprId, want: Option<Reg>) -> Reg {
        let (cmp, x, k) = match (self.imm_of(a), self.imm_of(b)) {
            (_, Some(k)) => (cmp, self.expr(a), k),
            (Some(k), None) => (cmp.mirror(), self.expr(b), k),
            (None, None) => {
                let (x, y) = self.operands(a, b);
                let d = self.dest(want);
                self.emit(match cmp {
                    Cmp::Eq => Op::Eq { d, a: x, b: y },
                    Cmp::Ne => Op::Ne { d, a: x, b: y },
                    Cmp::Lt => Op::Lt { d, a: x, b: y },
                    Cmp::Le => Op::Le { d, a: x, b: y },
                    Cmp::Gt => Op::Lt { d, a: y, b: x },
                    Cmp::Ge => Op::Le { d, a: y, b: x },
                });
                return d;
            }
        };
        let d = self.dest(want);
        self.emit(match cmp {
            Cmp::Eq => Op::EqI { d, a: x, imm: k },
            Cmp::Ne => Op::NeI { d, a: x, imm: k },
            Cmp::Lt => Op::LtI { d, a: x, imm: k },
            Cmp::Le => Op::LeI { d, a: x, imm: k },
            Cmp::Gt => Op::GtI { d, a: x, imm: k },
            Cmp::Ge => Op::GeI { d, a: x, imm: k },
        });
        d
    }

    /// The terms of a tree of `|`, left to right, looking through `let`s and range checks that
    /// cannot fail: the bindings (in evaluation order) and the operands.
    fn or_terms(&mut self, e: ExprId, out: &mut Vec<OrTerm>) {
        if self.avail.contains_key(&e) {
            out.push(OrTerm::Value(e));
            return;
        }
        let node = self.p.nodes[e as usize].clone();
        match node {
            Node::Binary(BinOp::BitOr, a, b, _) => {
                self.or_terms(a, out);
                self.or_terms(b, out);
            }
            Node::Let(l, v, body) => {
                out.push(OrTerm::Bind(l, v));
                self.or_terms(body, out);
            }
            Node::Check(a, lo, hi, _) if self.iv.within(a, lo, hi) => self.or_terms(a, out),
            _ => out.push(OrTerm::Value(e)),
        }
    }

    /// `a | b` as one accumulation over the terms of the `|`-tree, left to right (the tree
    /// evaluator's order; `|` is associative and cannot fail): a term `if c then x else y` over
    /// leaves is one [`Op::OrSel`], a constant an [`Op::OrI`]. This is the idiom that packs
    /// booleans into a flag register, often through an inlined function (whose arguments are
    /// `let`-bound).
    fn or_tree(&mut self, a: ExprId, b: ExprId, want: Option<Reg>) -> Reg {
        let mut terms = Vec::new();
        self.or_terms(a, &mut terms);
        self.or_terms(b, &mut terms);
        let values = terms
            .iter()
            .filter(|t| matches!(t, OrTerm::Value(_)))
            .count();
        let mut acc: Option<Reg> = None;
        let mut left = values;
        for term in terms {
            let e = match term {
                OrTerm::Bind(l, v) => {
                    let local = (self.locals_base + l) as Reg;
                    if let Some(r) = acc.filter(|r| self.is_local_reg(*r)) {
                        // The tree evaluator has read the local before this rebinding.
                        let t = self.temp();
                        self.emit(Op::Mov { d: t, a: r });
                        acc = Some(t);
                    }
                    self.into(v, local);
                    continue;
                }
                OrTerm::Value(e) => e,
            };
            left -= 1;
            let Some(x) = acc else {
                acc = Some(self.expr(e));
                continue;
            };
            let leaf_ite = match *self.node(e) {
                Node::Ite(c, p, q) if self.is_leaf(p) && self.is_leaf(q) => Some((c, p, q)),
                _ => None,
            };
            let op = if let Some((c, p, q)) = leaf_ite.filter(|_| !self.avail.contains_key(&e)) {
                let c = self.expr(c);
                let (p, q) = (self.expr(p), self.expr(q));
                let d = if left == 0 {
                    self.dest(want)
                } else {
                    self.temp()
                };
                Op::OrSel {
                    d,
                    a: x,
                    c,
                    x: p,
                    y: q,
                }
            } else if let Some(imm) = self.imm_of(e) {
                let d = if left == 0 {
                    self.dest(want)
                } else {
                    self.temp()
                };
                Op::OrI { d, a: x, imm }
            } else {
                let y = self.expr(e);
                let d = if left == 0 {
                    self.dest(want)
                } else {
                    self.temp()
                };
                Op::Or { d, a: x, b: y }
            };
            self.emit(op);
            acc = op.dest();
        }
        acc.unwrap_or(0)
    }

    /// Arithmetic and bitwise operators (not comparisons, not `&&`/`||`).
    fn binary(&mut self, op: BinOp, a: ExprId, b: ExprId, site: SiteId, want: Option<Reg>) -> Reg {
        // A constant operand becomes an immediate (either side of a commutative operator).
        let commutative = matches!(
            op,
            BinOp::Add | BinOp::BitAnd | BinOp::BitOr | BinOp::BitXor
        );
        let with_imm = match (self.imm_of(a), self.imm_of(b)) {
            (_, Some(k)) if op == BinOp::Sub && k != i32::MIN => Some((a, -k)),
            (_, Some(k)) if commutative => Some((a, k)),
            (Some(k), None) if commutative => Some((b, k)),
            _ => None,
        };
        if op == BinOp::BitOr {
            return self.or_tree(a, b, want);
        }
        if let Some((x, imm)) = with_imm {
            let a = self.expr(x);
            let d = self.dest(want);
            match op {
                BinOp::Add | BinOp::Sub => self.emit_at(Op::AddI { d, a, imm }, site),
                BinOp::BitAnd => self.emit(Op::AndI { d, a, imm }),
                BinOp::BitOr => self.emit(Op::OrI { d, a, imm }),
                _ => self.emit(Op::XorI { d, a, imm }),
            }
            return d;
        }
        let (a, b) = self.operands(a, b);
        let d = self.dest(want);
        let op = match op {
            BinOp::Add => Op::Add { d, a, b },
            BinOp::Sub => Op::Sub { d, a, b },
            BinOp::Mul => Op::Mul { d, a, b },
            BinOp::Div => Op::Div { d, a, b },
            BinOp::Rem => Op::Rem { d, a, b },
            BinOp::Shl => Op::Shl { d, a, b },
            BinOp::Shr => Op::Shr { d, a, b },
            BinOp::BitAnd => Op::And { d, a, b },
            BinOp::BitOr => Op::Or { d, a, b },
            BinOp::BitXor => Op::Xor { d, a, b },
            // Comparisons and `&&`/`||` are compiled by `expr_into`; these arms are not
            // reached, and would compute the same values.
            BinOp::Eq => Op::Eq { d, a, b },
            BinOp::Ne => Op::Ne { d, a, b },
            BinOp::Lt => Op::Lt { d, a, b },
            BinOp::Le => Op::Le { d, a, b },
            BinOp::Gt => Op::Lt { d, a: b, b: a },
            BinOp::Ge => Op::Le { d, a: b, b: a },
            BinOp::And => Op::LAnd { d, a, b },
            BinOp::Or => Op::LOr { d, a, b },
        };
        self.emit_at(op, site);
        d
    }
}
