//! The flag idioms of supervisory-controller models as single instructions: a flag combined
//! with a state test (`a && s == k`) and the packing of booleans into a flag register
//! (`r | (if c then K else 0) | ..`, through the `let`-bound arguments of an inlined function).

use super::{Compiler, Op, Reg};
use crate::program::*;
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
}
