//! Interval evaluation of an expression over a partial input assignment: a sound
//! over-approximation used to prune the enumeration of input vectors.
//!
//! The result contains every value the expression takes, without a run-time error, in every
//! completion of the assignment (unassigned inputs range over their declared bounds). When it
//! is exactly `[0, 0]`, every completion makes the expression false or fails, so an `assume`
//! conjunct of that shape rules out the whole subtree. Anything not modelled precisely widens
//! to the full range, which never prunes; the final decision on a complete vector is always the
//! exact evaluator's.

use crate::{BinOp, UnOp};
use crate::{ExprId, Node, Program};

/// A closed interval of `i64` values.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Iv {
    pub lo: i64,
    pub hi: i64,
}

const TOP: Iv = Iv {
    lo: i64::MIN,
    hi: i64::MAX,
};
const FALSE: Iv = Iv { lo: 0, hi: 0 };
const TRUE: Iv = Iv { lo: 1, hi: 1 };
const BOOL: Iv = Iv { lo: 0, hi: 1 };

impl Iv {
    fn point(v: i64) -> Iv {
        Iv { lo: v, hi: v }
    }

    /// From `i128` bounds; the full range when they leave `i64` (that would be an overflow
    /// error, so any superset is sound).
    fn wide(lo: i128, hi: i128) -> Iv {
        match (i64::try_from(lo), i64::try_from(hi)) {
            (Ok(lo), Ok(hi)) => Iv { lo, hi },
            _ => TOP,
        }
    }

    /// True when every value is 0.
    pub fn is_false(self) -> bool {
        self == FALSE
    }

    fn has_zero(self) -> bool {
        self.lo <= 0 && 0 <= self.hi
    }

    fn nonzero(self) -> bool {
        !self.has_zero()
    }

    fn hull(self, o: Iv) -> Iv {
        Iv {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }

    fn truth(t: bool, f: bool) -> Iv {
        match (t, f) {
            (true, _) => TRUE,
            (_, true) => FALSE,
            _ => BOOL,
        }
    }
}

/// Evaluates expressions over slots that are either known (`Some`) or range over their
/// declared bounds (`None`).
pub(crate) struct IntervalEval<'a> {
    p: &'a Program,
    /// Per slot: its known value, if any.
    pub known: Vec<Option<i64>>,
    locals: Vec<Iv>,
}

impl<'a> IntervalEval<'a> {
    /// Every slot unknown.
    pub fn new(p: &'a Program) -> Self {
        IntervalEval {
            p,
            known: vec![None; p.slots.len()],
            locals: Vec::new(),
        }
    }

    /// An interval containing every error-free value of `e`.
    pub fn eval(&mut self, e: ExprId) -> Iv {
        let Some(node) = self.p.nodes.get(e as usize) else {
            return TOP;
        };
        match *node {
            Node::Const(v) => Iv::point(v),
            Node::Slot(s) => match (self.known.get(s as usize), self.p.slots.get(s as usize)) {
                (Some(Some(v)), _) => Iv::point(*v),
                (_, Some(sl)) => Iv {
                    lo: sl.lo,
                    hi: sl.hi,
                },
                _ => TOP,
            },
            Node::Unary(op, a) => {
                let a = self.eval(a);
                match op {
                    UnOp::Not => Iv::truth(a == FALSE, a.nonzero()),
                    UnOp::Neg => Iv::wide(-i128::from(a.hi), -i128::from(a.lo)),
                    // `!x == -x - 1`: decreasing.
                    UnOp::BitNot => Iv {
                        lo: !a.hi,
                        hi: !a.lo,
                    },
                }
            }
            Node::Binary(op, a, b, _) => self.binary(op, a, b),
            Node::Ite(c, a, b) => {
                let c = self.eval(c);
                if c.nonzero() {
                    self.eval(a)
                } else if c == FALSE {
                    self.eval(b)
                } else {
                    let a = self.eval(a);
                    a.hull(self.eval(b))
                }
            }
            Node::Min(a, b) => {
                let (a, b) = (self.eval(a), self.eval(b));
                Iv {
                    lo: a.lo.min(b.lo),
                    hi: a.hi.min(b.hi),
                }
            }
            Node::Max(a, b) => {
                let (a, b) = (self.eval(a), self.eval(b));
                Iv {
                    lo: a.lo.max(b.lo),
                    hi: a.hi.max(b.hi),
                }
            }
            Node::Abs(a, _) => {
                let a = self.eval(a);
                let (lo, hi) = (i128::from(a.lo), i128::from(a.hi));
                if lo >= 0 {
                    a
                } else if hi <= 0 {
                    Iv::wide(-hi, -lo)
                } else {
                    Iv::wide(0, (-lo).max(hi))
                }
            }
            Node::Check(a, lo, hi, _) => {
                let a = self.eval(a);
                let (l, h) = (a.lo.max(lo), a.hi.min(hi));
                // Empty: every completion fails; any interval is sound, keep the bounds.
                if l <= h {
                    Iv { lo: l, hi: h }
                } else {
                    Iv { lo, hi }
                }
            }
            Node::Let(l, v, body) => {
                let v = self.eval(v);
                let l = l as usize;
                if self.locals.len() <= l {
                    self.locals.resize(l + 1, TOP);
                }
                // Bound like the reference evaluator binds it (not restored afterwards).
                self.locals[l] = v;
                self.eval(body)
            }
            Node::Local(l) => self.locals.get(l as usize).copied().unwrap_or(TOP),
        }
    }

    fn binary(&mut self, op: BinOp, a: ExprId, b: ExprId) -> Iv {
        let x = self.eval(a);
        match op {
            // Short-circuit: `b` is not evaluated when `x` decides.
            BinOp::And if x == FALSE => return FALSE,
            BinOp::Or if x.nonzero() => return TRUE,
            _ => {}
        }
        let y = self.eval(b);
        let (xl, xh, yl, yh) = (
            i128::from(x.lo),
            i128::from(x.hi),
            i128::from(y.lo),
            i128::from(y.hi),
        );
        match op {
            BinOp::And => Iv::truth(x.nonzero() && y.nonzero(), y == FALSE),
            BinOp::Or => Iv::truth(y.nonzero(), x == FALSE && y == FALSE),
            BinOp::Eq => Iv::truth(x.lo == x.hi && x == y, x.hi < y.lo || y.hi < x.lo),
            BinOp::Ne => Iv::truth(x.hi < y.lo || y.hi < x.lo, x.lo == x.hi && x == y),
            BinOp::Lt => Iv::truth(x.hi < y.lo, x.lo >= y.hi),
            BinOp::Le => Iv::truth(x.hi <= y.lo, x.lo > y.hi),
            BinOp::Gt => Iv::truth(x.lo > y.hi, x.hi <= y.lo),
            BinOp::Ge => Iv::truth(x.lo >= y.hi, x.hi < y.lo),
            BinOp::Add => Iv::wide(xl + yl, xh + yh),
            BinOp::Sub => Iv::wide(xl - yh, xh - yl),
            BinOp::Mul => {
                let c = [xl * yl, xl * yh, xh * yl, xh * yh];
                let lo = c.iter().copied().min().unwrap_or(i128::MIN);
                let hi = c.iter().copied().max().unwrap_or(i128::MAX);
                Iv::wide(lo, hi)
            }
            // Exact on two known values (an error keeps the full range), otherwise the full range.
            _ if x.lo == x.hi && y.lo == y.hi => exact(op, x.lo, y.lo).map_or(TOP, Iv::point),
            _ => TOP,
        }
    }
}

/// The value of the remaining operators on known operands, when it is certain (`None` for
/// shifts and errors).
fn exact(op: BinOp, a: i64, b: i64) -> Option<i64> {
    match op {
        BinOp::BitAnd => Some(a & b),
        BinOp::BitOr => Some(a | b),
        BinOp::BitXor => Some(a ^ b),
        // Both truncate toward zero, like the model's operators.
        BinOp::Div => a.checked_div(b),
        BinOp::Rem => a.checked_rem(b),
        _ => None,
    }
}
