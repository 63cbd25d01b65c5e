//! Values: one instruction per operator, immediates for constant operands, branch-free
//! booleans and selects where that evaluates nothing the tree evaluator would skip, results
//! written straight into their destination, values reused within a statement.

use super::cond::Cmp;
use super::{imm, Compiler, Op, Reg, NO_SITE};
use crate::program::*;
use statecheck_model::ops;
use statecheck_syntax::ast::{BinOp, UnOp};

/// True when evaluating `e` can neither fail nor write anything, so evaluating it where the
/// tree evaluator would skip it (the right operand of `&&`, `||`) is unobservable.
fn total(nodes: &[Node], e: ExprId) -> bool {
    match nodes[e as usize] {
        Node::Const(_) | Node::Slot(_) | Node::Local(_) => true,
        Node::Unary(op, a) => !ops::unary_can_fail(op) && total(nodes, a),
        Node::Binary(op, a, b, _) => {
            let rhs = match nodes[b as usize] {
                Node::Const(k) => Some(k),
                _ => None,
            };
            !ops::binary_can_fail(op, rhs) && total(nodes, a) && total(nodes, b)
        }
        Node::Min(a, b) | Node::Max(a, b) => total(nodes, a) && total(nodes, b),
        Node::Ite(c, a, b) => total(nodes, c) && total(nodes, a) && total(nodes, b),
        Node::Abs(..) | Node::Check(..) | Node::Let(..) => false,
    }
}

/// Number of operator nodes in `e` (a leaf counts 0), or any number above `limit` once it is
/// known to exceed it: the walk visits at most `limit + 1` operators.
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
        n += size(nodes, k, limit - n);
    }
    n
}

/// The right operand of `&&`/`||` is evaluated eagerly, without a branch, when it is total and
/// at most this many operators.
const EAGER_SIZE: u32 = 2;

impl Compiler<'_> {
    /// Compile an expression; returns the register holding its value.
    pub(super) fn expr(&mut self, e: ExprId) -> Reg {
        self.expr_into(e, None)
    }

    /// Compile two operands, left to right. When the first one's value is a local's register
    /// and the second rebinds a local, the first is copied first: the tree evaluator has read
    /// it before the rebinding.
    pub(super) fn operands(&mut self, a: ExprId, b: ExprId) -> (Reg, Reg) {
        let mut x = self.expr(a);
        if self.has_let[b as usize] && self.is_local_reg(x) {
            let t = self.temp();
            self.emit(Op::Mov { d: t, a: x });
            x = t;
        }
        (x, self.expr(b))
    }

    pub(super) fn is_local_reg(&self, r: Reg) -> bool {
        (self.locals_base..self.temps_base).contains(&(r as u32))
    }

    /// The constant `v` into register `d`.
    pub(super) fn load_const(&mut self, v: i64, d: Reg) {
        match imm(v) {
            Some(imm) => self.emit(Op::MovI { d, imm }),
            None => {
                let a = self.konst(v);
                self.emit(Op::Mov { d, a });
            }
        }
    }

    /// Compile `e` into register `d`.
    pub(super) fn into(&mut self, e: ExprId, d: Reg) {
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
    pub(super) fn expr_into(&mut self, e: ExprId, want: Option<Reg>) -> Reg {
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
    pub(super) fn compute(&mut self, e: ExprId, want: Option<Reg>) -> Reg {
        let node = self.node(e).clone();
        match node {
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
                if size(&self.p.nodes, b, EAGER_SIZE) <= EAGER_SIZE && total(&self.p.nodes, b) =>
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
            Node::Binary(BinOp::BitAnd | BinOp::BitXor, ..) if self.mask_of_choice(e) => {
                self.masked_choice(e, Vec::new(), want)
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

    /// `a cmp b` as a 0/1 value.
    pub(super) fn compare_value(
        &mut self,
        cmp: Cmp,
        a: ExprId,
        b: ExprId,
        want: Option<Reg>,
    ) -> Reg {
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

    /// Arithmetic and bitwise operators (not comparisons, not `&&`/`||`).
    pub(super) fn binary(
        &mut self,
        op: BinOp,
        a: ExprId,
        b: ExprId,
        site: SiteId,
        want: Option<Reg>,
    ) -> Reg {
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
