//! Value intervals of expressions, to drop range checks that cannot fail.
//!
//! The analysis assumes nothing about slots and locals: they may hold any 64-bit value, so the
//! result does not depend on inputs being within their declared ranges. An interval bounds the
//! value of an expression *when its evaluation succeeds*; the run-time errors of its operators
//! are checked where they occur, independently of this analysis. A range check is dropped only
//! when the checked expression's interval lies within the allowed range.

use crate::program::{ExprId, Node};
use statecheck_syntax::ast::{BinOp, UnOp};

/// An inclusive interval `lo..=hi`.
pub(crate) type Interval = (i64, i64);

const FULL: Interval = (i64::MIN, i64::MAX);

/// Memoised intervals of the nodes of one program.
pub(crate) struct Intervals<'p> {
    nodes: &'p [Node],
    memo: Vec<Option<Interval>>,
}

fn clamp(lo: i128, hi: i128) -> Interval {
    let c = |v: i128| v.clamp(i64::MIN as i128, i64::MAX as i128) as i64;
    (c(lo), c(hi))
}

/// Smallest `2^k - 1` that is at least `v` (for `v >= 0`).
fn all_ones_above(v: i64) -> i64 {
    if v <= 0 {
        0
    } else {
        (u64::MAX >> (v as u64).leading_zeros()) as i64
    }
}

impl<'p> Intervals<'p> {
    /// An analysis over `nodes`.
    pub(crate) fn new(nodes: &'p [Node]) -> Intervals<'p> {
        Intervals {
            nodes,
            memo: vec![None; nodes.len()],
        }
    }

    /// True when every successful evaluation of `e` lies within `lo..=hi`.
    pub(crate) fn within(&mut self, e: ExprId, lo: i64, hi: i64) -> bool {
        let (a, b) = self.of(e);
        lo <= a && b <= hi
    }

    /// The interval of `e`.
    pub(crate) fn of(&mut self, e: ExprId) -> Interval {
        if let Some(i) = self.memo[e as usize] {
            return i;
        }
        let i = self.compute(e);
        self.memo[e as usize] = Some(i);
        i
    }

    fn compute(&mut self, e: ExprId) -> Interval {
        match self.nodes[e as usize] {
            Node::Const(v) => (v, v),
            Node::Slot(_) | Node::Local(_) => FULL,
            Node::Unary(UnOp::Not, _) => (0, 1),
            Node::Unary(UnOp::Neg, a) => {
                let (lo, hi) = self.of(a);
                clamp(-(hi as i128), -(lo as i128))
            }
            Node::Unary(UnOp::BitNot, a) => {
                let (lo, hi) = self.of(a);
                (!hi, !lo)
            }
            Node::Binary(op, a, b, _) => {
                let (x, y) = (self.of(a), self.of(b));
                binary(op, x, y)
            }
            Node::Ite(_, a, b) => {
                let (x, y) = (self.of(a), self.of(b));
                (x.0.min(y.0), x.1.max(y.1))
            }
            Node::Min(a, b) => {
                let (x, y) = (self.of(a), self.of(b));
                (x.0.min(y.0), x.1.min(y.1))
            }
            Node::Max(a, b) => {
                let (x, y) = (self.of(a), self.of(b));
                (x.0.max(y.0), x.1.max(y.1))
            }
            Node::Abs(a, _) => {
                let (lo, hi) = self.of(a);
                if lo >= 0 {
                    (lo, hi)
                } else if hi <= 0 {
                    clamp(-(hi as i128), -(lo as i128))
                } else {
                    clamp(0, (-(lo as i128)).max(hi as i128))
                }
            }
            Node::Check(a, lo, hi, _) => {
                let (x, y) = self.of(a);
                let (l, h) = (x.max(lo), y.min(hi));
                if l <= h {
                    (l, h)
                } else {
                    // The check always fails: no successful evaluation.
                    (lo, hi)
                }
            }
            Node::Let(_, _, body) => self.of(body),
        }
    }
}

fn binary(op: BinOp, (al, ah): Interval, (bl, bh): Interval) -> Interval {
    let (al, ah, bl, bh) = (al as i128, ah as i128, bl as i128, bh as i128);
    match op {
        BinOp::And
        | BinOp::Or
        | BinOp::Eq
        | BinOp::Ne
        | BinOp::Lt
        | BinOp::Le
        | BinOp::Gt
        | BinOp::Ge => (0, 1),
        BinOp::Add => clamp(al + bl, ah + bh),
        BinOp::Sub => clamp(al - bh, ah - bl),
        BinOp::Mul => {
            let p = [al * bl, al * bh, ah * bl, ah * bh];
            let lo = p.iter().copied().min().unwrap_or(i128::MIN);
            let hi = p.iter().copied().max().unwrap_or(i128::MAX);
            clamp(lo, hi)
        }
        // |a / b| <= |a| for every non-zero b.
        BinOp::Div => {
            let m = al.abs().max(ah.abs());
            clamp(-m, m)
        }
        // |a % b| < |b|, and the remainder has the sign of `a`.
        BinOp::Rem => {
            let m = (bl.abs().max(bh.abs()) - 1).max(0);
            let lo = if al >= 0 { 0 } else { -m };
            let hi = if ah <= 0 { 0 } else { m };
            clamp(lo, hi)
        }
        // An arithmetic right shift moves a value towards 0 (or -1), never past it.
        BinOp::Shr => clamp(al.min(0), ah.max(0)),
        BinOp::Shl => FULL,
        BinOp::BitAnd => match (al >= 0, bl >= 0) {
            (true, true) => clamp(0, ah.min(bh)),
            (true, false) => clamp(0, ah),
            (false, true) => clamp(0, bh),
            (false, false) => FULL,
        },
        BinOp::BitOr | BinOp::BitXor if al >= 0 && bl >= 0 => {
            (0, all_ones_above(ah.max(bh) as i64))
        }
        BinOp::BitOr | BinOp::BitXor => FULL,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use statecheck_model::ops;

    /// Every successful evaluation of a random operator on random operands drawn from random
    /// intervals lies in the operator's interval.
    /// A value of `lo..=hi` chosen by `r`.
    fn within(lo: i64, hi: i64, r: u64) -> i64 {
        let span = (hi as i128 - lo as i128 + 1) as u128;
        (lo as i128 + (r as u128 % span) as i128) as i64
    }

    #[test]
    fn operator_intervals_contain_every_result() {
        let mut rng = 0x1234_5678_9abc_def1u64;
        let mut next = move || {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            rng
        };
        let edges = [
            i64::MIN,
            i64::MIN + 1,
            -4096,
            -255,
            -3,
            -1,
            0,
            1,
            2,
            3,
            62,
            63,
            255,
            4095,
            i64::MAX - 1,
            i64::MAX,
        ];
        let pick = |next: &mut dyn FnMut() -> u64| -> i64 {
            let r = next();
            if r.is_multiple_of(3) {
                edges[(r >> 8) as usize % edges.len()]
            } else {
                ((r >> 8) % 9000) as i64 - 4500
            }
        };
        let opsl = [
            BinOp::Add,
            BinOp::Sub,
            BinOp::Mul,
            BinOp::Div,
            BinOp::Rem,
            BinOp::Shl,
            BinOp::Shr,
            BinOp::BitAnd,
            BinOp::BitOr,
            BinOp::BitXor,
            BinOp::Lt,
            BinOp::And,
        ];
        for _ in 0..200_000 {
            let (mut a0, mut a1, mut b0, mut b1) = (
                pick(&mut next),
                pick(&mut next),
                pick(&mut next),
                pick(&mut next),
            );
            if a0 > a1 {
                std::mem::swap(&mut a0, &mut a1);
            }
            if b0 > b1 {
                std::mem::swap(&mut b0, &mut b1);
            }
            let op = opsl[next() as usize % opsl.len()];
            let (lo, hi) = binary(op, (a0, a1), (b0, b1));
            for _ in 0..8 {
                let (x, y) = (within(a0, a1, next()), within(b0, b1, next()));
                if let Ok(v) = ops::binary(op, x, y) {
                    assert!(
                        lo <= v && v <= hi,
                        "{op:?} {x} {y} = {v} outside {lo}..{hi} (operands {a0}..{a1}, {b0}..{b1})"
                    );
                }
            }
        }
    }

    #[test]
    fn flags_of_conditional_constants_stay_in_a_byte() {
        // (if s then 0x80 else 0) | (if t then 0x40 else 0), and `reg & 0xF7`.
        let nodes = vec![
            Node::Slot(0),
            Node::Const(0x80),
            Node::Const(0),
            Node::Ite(0, 1, 2),
            Node::Const(0x40),
            Node::Ite(0, 4, 2),
            Node::Binary(BinOp::BitOr, 3, 5, u32::MAX),
            Node::Const(0xF7),
            Node::Binary(BinOp::BitAnd, 0, 7, u32::MAX),
            Node::Binary(BinOp::Add, 6, 8, 0),
        ];
        let mut iv = Intervals::new(&nodes);
        assert_eq!(iv.of(6), (0, 0xFF));
        assert!(iv.within(6, 0, 255));
        assert_eq!(iv.of(8), (0, 0xF7));
        assert_eq!(iv.of(9), (0, 0xFF + 0xF7));
        assert!(!iv.within(9, 0, 255));
        assert_eq!(iv.of(0), FULL);
    }
}
