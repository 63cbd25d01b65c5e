//! Symbolic evaluation of IR expressions, in the interpreter's evaluation order.

use super::Blaster;
use crate::aig::Lit;
use crate::bv::{self, Bv};
use statecheck_ir::{BinOp, UnOp};
use statecheck_ir::{ExprId, Node};

/// Error kinds, indexed like `statecheck_ir::verdict::Builtin::ALL`.
pub const RANGE: usize = 0;
/// Division or remainder by zero.
pub const DIV_ZERO: usize = 1;
/// Shift amount outside `0..=62`.
pub const BAD_SHIFT: usize = 2;

const I64: (i128, i128) = (i64::MIN as i128, i64::MAX as i128);

impl Blaster<'_> {
    /// Record a run-time error of `kind` when `cond` holds on the evaluated path `guard` and no
    /// earlier error happened.
    pub(crate) fn fail(&mut self, guard: Lit, cond: Lit, kind: usize) {
        let g = self.g.and(guard, self.ok);
        let hit = self.g.and(g, cond);
        self.errs[kind] = self.g.or(self.errs[kind], hit);
        self.ok = self.g.and(self.ok, !hit);
    }

    /// Report overflow when `r` may leave the `i64` range, and drop the impossible values.
    fn no_overflow(&mut self, guard: Lit, r: Bv) -> Bv {
        if r.lo >= I64.0 && r.hi <= I64.1 {
            return r;
        }
        let out = self.outside(&r, I64.0, I64.1);
        self.fail(guard, out, RANGE);
        r.restrict(I64.0, I64.1)
    }

    /// `r < lo || r > hi`.
    pub(crate) fn outside(&mut self, r: &Bv, lo: i128, hi: i128) -> Lit {
        let below = bv::lt(&mut self.g, r, &Bv::constant(lo));
        let above = bv::lt(&mut self.g, &Bv::constant(hi), r);
        self.g.or(below, above)
    }

    /// True when `e` evaluates without error to non-zero ("an expression whose evaluation
    /// fails counts as false"); errors do not count as run-time errors of the step.
    pub(crate) fn holds(&mut self, e: ExprId) -> Lit {
        let (ok, errs) = (self.ok, self.errs);
        self.ok = Lit::TRUE;
        let v = self.eval(e, Lit::TRUE);
        let nz = bv::nonzero(&mut self.g, &v);
        let r = self.g.and(self.ok, nz);
        self.ok = ok;
        self.errs = errs;
        r
    }

    /// The value of `e` where `guard` is the condition under which it is evaluated.
    pub(crate) fn eval(&mut self, e: ExprId, guard: Lit) -> Bv {
        let node = self.p.nodes[e as usize].clone();
        match node {
            Node::Const(v) => Bv::constant(i128::from(v)),
            Node::Slot(s) => self.env[s as usize].clone(),
            Node::Unary(op, a) => {
                let a = self.eval(a, guard);
                match op {
                    UnOp::Neg => {
                        let r = bv::neg(&mut self.g, &a);
                        self.no_overflow(guard, r)
                    }
                    UnOp::Not => {
                        let nz = bv::nonzero(&mut self.g, &a);
                        bv::from_bool(!nz)
                    }
                    UnOp::BitNot => bv::bitnot(&a),
                }
            }
            Node::Binary(op, a, b, _) => self.binary(op, a, b, guard),
            Node::Ite(c, a, b) => {
                let c = self.eval(c, guard);
                let c = bv::nonzero(&mut self.g, &c);
                let ga = self.g.and(guard, c);
                let gb = self.g.and(guard, !c);
                let a = self.eval(a, ga);
                let b = self.eval(b, gb);
                bv::mux(&mut self.g, c, &a, &b)
            }
            Node::Min(a, b) | Node::Max(a, b) => {
                let is_min = matches!(node, Node::Min(..));
                let a = self.eval(a, guard);
                let b = self.eval(b, guard);
                let a_lt = bv::lt(&mut self.g, &a, &b);
                let mut r = if is_min {
                    bv::mux(&mut self.g, a_lt, &a, &b)
                } else {
                    bv::mux(&mut self.g, a_lt, &b, &a)
                };
                let (lo, hi) = if is_min {
                    (a.lo.min(b.lo), a.hi.min(b.hi))
                } else {
                    (a.lo.max(b.lo), a.hi.max(b.hi))
                };
                r = r.restrict(lo, hi);
                r
            }
            Node::Abs(a, _) => {
                let a = self.eval(a, guard);
                let r = bv::abs(&mut self.g, &a);
                self.no_overflow(guard, r)
            }
            Node::Check(a, lo, hi, _) => {
                let v = self.eval(a, guard);
                let (lo, hi) = (i128::from(lo), i128::from(hi));
                if v.lo >= lo && v.hi <= hi {
                    return v;
                }
                let out = self.outside(&v, lo, hi);
                self.fail(guard, out, RANGE);
                v.restrict(lo, hi)
            }
            Node::Let(l, v, body) => {
                let v = self.eval(v, guard);
                let l = l as usize;
                if self.locals.len() <= l {
                    self.locals.resize(l + 1, Bv::constant(0));
                }
                self.locals[l] = v;
                self.eval(body, guard)
            }
            Node::Local(l) => self
                .locals
                .get(l as usize)
                .cloned()
                .unwrap_or_else(|| Bv::constant(0)),
        }
    }

    fn binary(&mut self, op: BinOp, a: ExprId, b: ExprId, guard: Lit) -> Bv {
        let a = self.eval(a, guard);
        if matches!(op, BinOp::And | BinOp::Or) {
            let na = bv::nonzero(&mut self.g, &a);
            let gb = if op == BinOp::And {
                self.g.and(guard, na)
            } else {
                self.g.and(guard, !na)
            };
            let b = self.eval(b, gb);
            let nb = bv::nonzero(&mut self.g, &b);
            let r = if op == BinOp::And {
                self.g.and(na, nb)
            } else {
                self.g.or(na, nb)
            };
            return bv::from_bool(r);
        }
        let b = self.eval(b, guard);
        let g = &mut self.g;
        match op {
            BinOp::Eq => bv::from_bool(bv::eq(g, &a, &b)),
            BinOp::Ne => bv::from_bool(!bv::eq(g, &a, &b)),
            BinOp::Lt => bv::from_bool(bv::lt(g, &a, &b)),
            BinOp::Le => bv::from_bool(!bv::lt(g, &b, &a)),
            BinOp::Gt => bv::from_bool(bv::lt(g, &b, &a)),
            BinOp::Ge => bv::from_bool(!bv::lt(g, &a, &b)),
            BinOp::BitAnd => bv::bitwise(g, 0, &a, &b),
            BinOp::BitOr => bv::bitwise(g, 1, &a, &b),
            BinOp::BitXor => bv::bitwise(g, 2, &a, &b),
            BinOp::Add => {
                let r = bv::add(g, &a, &b);
                self.no_overflow(guard, r)
            }
            BinOp::Sub => {
                let r = bv::sub(g, &a, &b);
                self.no_overflow(guard, r)
            }
            BinOp::Mul => {
                let r = bv::mul(g, &a, &b);
                self.no_overflow(guard, r)
            }
            BinOp::Shl | BinOp::Shr => {
                if b.lo < 0 || b.hi > 62 {
                    let out = self.outside(&b, 0, 62);
                    self.fail(guard, out, BAD_SHIFT);
                }
                let amount = b.restrict(0, 62);
                let r = bv::shift(&mut self.g, &a, &amount, op == BinOp::Shl);
                self.no_overflow(guard, r)
            }
            BinOp::Div | BinOp::Rem => {
                if b.lo <= 0 && b.hi >= 0 {
                    let z = bv::eq(g, &b, &Bv::constant(0));
                    self.fail(guard, z, DIV_ZERO);
                }
                if op == BinOp::Rem && a.lo == I64.0 && b.lo <= -1 && b.hi >= -1 {
                    // `i64::MIN % -1` overflows in the interpreter (`checked_rem`).
                    let am = bv::eq(&mut self.g, &a, &Bv::constant(I64.0));
                    let bm = bv::eq(&mut self.g, &b, &Bv::constant(-1));
                    let both = self.g.and(am, bm);
                    self.fail(guard, both, RANGE);
                }
                let (q, r) = bv::divrem(&mut self.g, &a, &b);
                let r = if op == BinOp::Div { q } else { r };
                self.no_overflow(guard, r)
            }
            BinOp::And | BinOp::Or => Bv::constant(0),
        }
    }
}
