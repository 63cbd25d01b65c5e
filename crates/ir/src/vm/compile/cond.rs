//! Conditions in control context: (compare-and-)branch instructions, with the short-circuit
//! of `&&` and `||` compiled as jumps, enumeration membership and mask tests as one jump each.

use super::{Compiler, Op};
use crate::program::*;
use statecheck_syntax::ast::{BinOp, UnOp};

/// Comparisons, for negating and mirroring them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Cmp {
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
}

impl Cmp {
    pub(super) fn of(op: BinOp) -> Option<Cmp> {
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
    pub(super) fn negate(self) -> Cmp {
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
    pub(super) fn mirror(self) -> Cmp {
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

impl Compiler<'_> {
    /// Emit code that jumps (through `targets`, patched later) when `e` evaluates to `sense`
    /// and falls through otherwise.
    pub(super) fn jump_when(&mut self, e: ExprId, sense: bool, targets: &mut Vec<usize>) {
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
    pub(super) fn compare_jump(&mut self, cmp: Cmp, a: ExprId, b: ExprId) -> Op {
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

    /// The slot or local a leaf reads, to tell whether two leaves are the same.
    pub(super) fn leaf_key(&self, e: ExprId) -> Option<(bool, u32)> {
        match *self.node(e) {
            Node::Slot(s) => Some((false, s)),
            Node::Local(l) => Some((true, l)),
            _ => None,
        }
    }

    /// `(x, set)` when `e` is `x == k1 || x == k2 || ..` for one slot or local `x` and at least
    /// two constants in `0..32` (an enumeration tested against several literals). The tests
    /// are total, so one membership test computes the same value.
    pub(super) fn set_test(&self, e: ExprId) -> Option<(ExprId, u32)> {
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
    pub(super) fn bit_test(&self, e: ExprId) -> Option<(ExprId, i32, bool)> {
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
}
