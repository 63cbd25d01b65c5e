//! The arithmetic of every operator, defined once.
//!
//! Constant folding in the checker and the IR interpreter both call [`binary`] and [`unary`],
//! so a constant and a run-time value of the same expression can never differ. Integers are
//! `i64`; booleans are 0 and 1. Division truncates toward zero and `%` takes the sign of the
//! dividend (C99 semantics, so generated C agrees).

use statecheck_syntax::ast::{BinOp, UnOp};

/// Why an operation has no value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OpError {
    /// `/` or `%` by zero.
    DivisionByZero,
    /// A shift by a negative amount or by 63 or more bits.
    BadShift,
    /// The exact result does not fit in 64 bits.
    Overflow,
}

impl OpError {
    /// A short description for messages.
    pub fn describe(self) -> &'static str {
        match self {
            OpError::DivisionByZero => "division by zero",
            OpError::BadShift => "shift amount outside 0..62",
            OpError::Overflow => "arithmetic overflow",
        }
    }
}

/// Largest allowed shift amount.
pub const MAX_SHIFT: i64 = 62;

/// Whether `a op b` can fail for some operand values, given the right operand when it is a
/// constant: the one definition of operator totality that the interpreter's register code and
/// the code generators use to decide what needs no check.
pub fn binary_can_fail(op: BinOp, rhs: Option<i64>) -> bool {
    match op {
        BinOp::Or
        | BinOp::And
        | BinOp::Eq
        | BinOp::Ne
        | BinOp::Lt
        | BinOp::Le
        | BinOp::Gt
        | BinOp::Ge
        | BinOp::BitOr
        | BinOp::BitXor
        | BinOp::BitAnd => false,
        // Overflow, whatever the operands' constness (a shift can overflow too).
        BinOp::Add | BinOp::Sub | BinOp::Mul | BinOp::Shl => true,
        BinOp::Shr => !matches!(rhs, Some(k) if (0..=MAX_SHIFT).contains(&k)),
        // Division by zero, and `i64::MIN / -1`.
        BinOp::Div | BinOp::Rem => !matches!(rhs, Some(k) if k != 0 && k != -1),
    }
}

/// Whether `op a` can fail for some operand value (`-i64::MIN` overflows).
pub fn unary_can_fail(op: UnOp) -> bool {
    op == UnOp::Neg
}

/// Apply a binary operator to two values. `&&` and `||` take 0/1 operands.
#[inline]
pub fn binary(op: BinOp, a: i64, b: i64) -> Result<i64, OpError> {
    Ok(match op {
        BinOp::Or => ((a != 0) || (b != 0)) as i64,
        BinOp::And => ((a != 0) && (b != 0)) as i64,
        BinOp::Eq => (a == b) as i64,
        BinOp::Ne => (a != b) as i64,
        BinOp::Lt => (a < b) as i64,
        BinOp::Le => (a <= b) as i64,
        BinOp::Gt => (a > b) as i64,
        BinOp::Ge => (a >= b) as i64,
        BinOp::BitOr => a | b,
        BinOp::BitXor => a ^ b,
        BinOp::BitAnd => a & b,
        BinOp::Shl => {
            if !(0..=MAX_SHIFT).contains(&b) {
                return Err(OpError::BadShift);
            }
            a.checked_mul(1i64 << b).ok_or(OpError::Overflow)?
        }
        BinOp::Shr => {
            if !(0..=MAX_SHIFT).contains(&b) {
                return Err(OpError::BadShift);
            }
            a >> b
        }
        BinOp::Add => a.checked_add(b).ok_or(OpError::Overflow)?,
        BinOp::Sub => a.checked_sub(b).ok_or(OpError::Overflow)?,
        BinOp::Mul => a.checked_mul(b).ok_or(OpError::Overflow)?,
        BinOp::Div => {
            if b == 0 {
                return Err(OpError::DivisionByZero);
            }
            a.checked_div(b).ok_or(OpError::Overflow)?
        }
        BinOp::Rem => {
            if b == 0 {
                return Err(OpError::DivisionByZero);
            }
            a.checked_rem(b).ok_or(OpError::Overflow)?
        }
    })
}

/// Apply a unary operator.
#[inline]
pub fn unary(op: UnOp, a: i64) -> Result<i64, OpError> {
    Ok(match op {
        UnOp::Neg => a.checked_neg().ok_or(OpError::Overflow)?,
        UnOp::Not => (a == 0) as i64,
        UnOp::BitNot => !a,
    })
}

/// The absolute value (`abs`); `abs(i64::MIN)` overflows.
#[inline]
pub fn abs(a: i64) -> Result<i64, OpError> {
    a.checked_abs().ok_or(OpError::Overflow)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn division_truncates_toward_zero_like_c() {
        assert_eq!(binary(BinOp::Div, -7, 2), Ok(-3));
        assert_eq!(binary(BinOp::Rem, -7, 2), Ok(-1));
        assert_eq!(binary(BinOp::Rem, 7, -2), Ok(1));
        assert_eq!(binary(BinOp::Div, 1, 0), Err(OpError::DivisionByZero));
    }

    #[test]
    fn totality_agrees_with_evaluation() {
        // Every operator on a grid of operands that includes the extremes: whenever the
        // evaluation fails, `binary_can_fail` must say it can (for that constant right operand
        // and for an unknown one).
        let vals = [
            i64::MIN,
            i64::MIN + 1,
            -63,
            -2,
            -1,
            0,
            1,
            2,
            62,
            63,
            i64::MAX - 1,
            i64::MAX,
        ];
        let ops = [
            BinOp::Or,
            BinOp::And,
            BinOp::Eq,
            BinOp::Ne,
            BinOp::Lt,
            BinOp::Le,
            BinOp::Gt,
            BinOp::Ge,
            BinOp::BitOr,
            BinOp::BitXor,
            BinOp::BitAnd,
            BinOp::Shl,
            BinOp::Shr,
            BinOp::Add,
            BinOp::Sub,
            BinOp::Mul,
            BinOp::Div,
            BinOp::Rem,
        ];
        for op in ops {
            for a in vals {
                for b in vals {
                    let (a, b) = match op {
                        BinOp::Or | BinOp::And => (a & 1, b & 1),
                        _ => (a, b),
                    };
                    if binary(op, a, b).is_err() {
                        assert!(binary_can_fail(op, Some(b)), "{op:?} {a} {b}");
                        assert!(binary_can_fail(op, None), "{op:?}");
                    }
                }
            }
        }
        for op in [UnOp::Neg, UnOp::Not, UnOp::BitNot] {
            for a in vals {
                let a = if op == UnOp::Not { a & 1 } else { a };
                if unary(op, a).is_err() {
                    assert!(unary_can_fail(op), "{op:?} {a}");
                }
            }
        }
    }

    #[test]
    fn shifts_are_checked() {
        assert_eq!(binary(BinOp::Shl, 1, 8), Ok(256));
        assert_eq!(binary(BinOp::Shr, -8, 1), Ok(-4));
        assert_eq!(binary(BinOp::Shl, 1, 63), Err(OpError::BadShift));
        assert_eq!(binary(BinOp::Shl, 1, -1), Err(OpError::BadShift));
    }
}
