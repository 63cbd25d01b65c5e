//! The flag idioms of supervisory-controller models as single instructions: a flag combined
//! with a state test (`a && s == k`), the packing of booleans into a flag register
//! (`r | (if c then K else 0) | ..`, through the `let`-bound arguments of an inlined function),
//! and masks computed by a choice with a constant branch (`r & (K ^ (if c then .. else 0))`).

use super::{Compiler, Op, Reg};
use crate::program::*;
use statecheck_model::ops;
use statecheck_syntax::ast::BinOp;

/// A term of a tree of `|`: a `let` binding met on the way, or an operand.
pub(super) enum OrTerm {
    Bind(u32, ExprId),
    Value(ExprId),
}

impl Compiler<'_> {
    /// `(x, k, equal)` when `e` is `x == k` or `x != k` (either way round) for a leaf `x` and
    /// an immediate `k`, and its value is not already available.
    pub(super) fn leaf_test(&self, e: ExprId) -> Option<(ExprId, i32, bool)> {
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
    pub(super) fn and_test(&mut self, a: ExprId, b: ExprId, want: Option<Reg>) -> Option<Reg> {
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

    /// The terms of a tree of `|`, left to right, looking through `let`s and range checks that
    /// cannot fail: the bindings (in evaluation order) and the operands.
    pub(super) fn or_terms(&mut self, e: ExprId, out: &mut Vec<OrTerm>) {
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
    pub(super) fn or_tree(&mut self, a: ExprId, b: ExprId, want: Option<Reg>) -> Reg {
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

    /// True when `e` is a choice `if c then x else y` (compiled with jumps, one branch a
    /// constant) under `let`s, range checks that cannot fail, and `&`/`^` with a constant or
    /// slot operand: the pending
    /// operations are then applied in each branch, and fold with the constant one.
    pub(super) fn mask_of_choice(&mut self, e: ExprId) -> bool {
        let known = |c: &Self, x: ExprId| matches!(c.node(x), Node::Const(_) | Node::Slot(_));
        match *self.node(e) {
            Node::Let(_, _, body) => self.mask_of_choice(body),
            Node::Check(a, lo, hi, _) => self.iv.within(a, lo, hi) && self.mask_of_choice(a),
            Node::Binary(BinOp::BitAnd | BinOp::BitXor, a, b, _) => {
                (known(self, a) && self.mask_of_choice(b))
                    || (known(self, b) && self.mask_of_choice(a))
            }
            Node::Ite(_, x, y) => {
                !(self.is_leaf(x) && self.is_leaf(y))
                    && (self.imm_of(x).is_some() || self.imm_of(y).is_some())
            }
            _ => false,
        }
    }

    /// Compile `e` (for which [`Self::mask_of_choice`] holds) followed by the `pending`
    /// operations (applied first to last), into `want`. The constant or slot operand of an
    /// `&`/`^` is read when the operation is applied: slots do not change during an
    /// expression, and `&`, `^` cannot fail, so the order of evaluation is the tree
    /// evaluator's.
    pub(super) fn masked_choice(
        &mut self,
        e: ExprId,
        mut pending: Vec<Pending>,
        want: Option<Reg>,
    ) -> Reg {
        let node = self.node(e).clone();
        match node {
            Node::Let(l, v, body) => {
                self.into(v, (self.locals_base + l) as Reg);
                self.masked_choice(body, pending, want)
            }
            // A check that cannot fail (`mask_of_choice` holds only then).
            Node::Check(a, ..) => self.masked_choice(a, pending, want),
            Node::Binary(op @ (BinOp::BitAnd | BinOp::BitXor), a, b, _) => {
                let (operand, rest) = if self.mask_of_choice(b) {
                    (a, b)
                } else {
                    (b, a)
                };
                let p = match self.imm_of(operand) {
                    Some(k) => Pending::Imm(op, k),
                    None => Pending::Reg(op, self.expr(operand)),
                };
                // Applied to `rest`'s value before the operations already pending.
                pending.insert(0, p);
                self.masked_choice(rest, pending, want)
            }
            Node::Ite(c, x, y) => {
                // The condition is read before either branch writes the destination, and each
                // branch writes it last.
                let d = self.dest(want);
                let mut fails = Vec::new();
                self.jump_when(c, false, &mut fails);
                self.apply_pending(x, &pending, d);
                let jmp = self.emit_jump(Op::Jmp { t: 0 });
                let else_start = self.here();
                self.patch_all(fails, else_start);
                self.apply_pending(y, &pending, d);
                let end = self.here();
                self.patch(jmp, end);
                d
            }
            _ => {
                let d = self.dest(want);
                self.apply_pending(e, &pending, d);
                d
            }
        }
    }

    /// `e`'s value with the `pending` operations applied, into `d`; operations on constants
    /// are folded.
    fn apply_pending(&mut self, e: ExprId, pending: &[Pending], d: Reg) {
        let mut k = match *self.node(e) {
            Node::Const(v) => Some(v),
            _ => None,
        };
        let mut r = None;
        if k.is_none() {
            r = Some(self.expr(e));
        }
        for (i, p) in pending.iter().enumerate() {
            let last = i + 1 == pending.len();
            let dst = if last { d } else { self.temp() };
            let op = match (*p, k, r) {
                (Pending::Imm(op, x), Some(v), _) => {
                    k = ops::binary(op, v, x as i64).ok();
                    continue;
                }
                (Pending::Imm(op, x), None, Some(a)) => bitwise_imm(op, dst, a, x),
                (Pending::Reg(op, b), Some(v), _) => match i32::try_from(v) {
                    Ok(x) => bitwise_imm(op, dst, b, x),
                    Err(_) => {
                        let a = self.konst(v);
                        bitwise(op, dst, a, b)
                    }
                },
                (Pending::Reg(op, b), None, Some(a)) => bitwise(op, dst, a, b),
                (_, None, None) => return,
            };
            self.emit(op);
            k = None;
            r = Some(dst);
        }
        match (k, r) {
            (Some(v), _) => self.load_const(v, d),
            (None, Some(a)) if a != d => self.emit(Op::Mov { d, a }),
            _ => {}
        }
    }
}

/// An operation waiting for its left operand: `& k`, `^ k`, `& r`, `^ r`.
#[derive(Clone, Copy)]
pub(super) enum Pending {
    Imm(BinOp, i32),
    Reg(BinOp, Reg),
}

fn bitwise_imm(op: BinOp, d: Reg, a: Reg, imm: i32) -> Op {
    if op == BinOp::BitAnd {
        Op::AndI { d, a, imm }
    } else {
        Op::XorI { d, a, imm }
    }
}

fn bitwise(op: BinOp, d: Reg, a: Reg, b: Reg) -> Op {
    if op == BinOp::BitAnd {
        Op::And { d, a, b }
    } else {
        Op::Xor { d, a, b }
    }
}
