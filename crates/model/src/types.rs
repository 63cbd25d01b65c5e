//! Types of the checked model and the interval arithmetic that bounds integer expressions.

/// Index of an enum declaration in [`crate::Model::enums`].
pub type EnumId = u32;

/// The type of a variable or expression.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Type {
    /// `bool`, stored as 0 or 1.
    Bool,
    /// An integer known to lie in `lo..=hi`.
    Int {
        /// Smallest value.
        lo: i64,
        /// Largest value.
        hi: i64,
    },
    /// A literal of the given enum, stored as its index.
    Enum(EnumId),
}

impl Type {
    /// The full range of integers an unbounded `int` may take.
    pub const UNBOUNDED: Type = Type::Int {
        lo: i64::MIN / 4,
        hi: i64::MAX / 4,
    };

    /// True for integer types.
    pub fn is_int(self) -> bool {
        matches!(self, Type::Int { .. })
    }

    /// The inclusive value range, given the number of literals of each enum.
    pub fn bounds(self, enum_len: impl Fn(EnumId) -> usize) -> (i64, i64) {
        match self {
            Type::Bool => (0, 1),
            Type::Int { lo, hi } => (lo, hi),
            Type::Enum(e) => (0, enum_len(e) as i64 - 1),
        }
    }

    /// True when values of `self` may be stored in a variable of type `other` (maybe after a
    /// run-time range check for integers).
    pub fn compatible(self, other: Type) -> bool {
        match (self, other) {
            (Type::Bool, Type::Bool) => true,
            (Type::Int { .. }, Type::Int { .. }) => true,
            (Type::Enum(a), Type::Enum(b)) => a == b,
            _ => false,
        }
    }
}

fn clamp(v: i128) -> i64 {
    v.clamp(i64::MIN as i128 / 4, i64::MAX as i128 / 4) as i64
}

/// A 128-bit bound saturated to `i64`'s range.
fn saturate(v: i128) -> i64 {
    v.clamp(i64::MIN as i128, i64::MAX as i128) as i64
}

/// Interval arithmetic on `lo..=hi` bounds, saturating far from `i64`'s limits.
pub mod interval {
    use super::{clamp, saturate};

    /// Bounds of `a + b`.
    pub fn add(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
        (
            clamp(a.0 as i128 + b.0 as i128),
            clamp(a.1 as i128 + b.1 as i128),
        )
    }

    /// Bounds of `a - b`.
    pub fn sub(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
        (
            clamp(a.0 as i128 - b.1 as i128),
            clamp(a.1 as i128 - b.0 as i128),
        )
    }

    /// Bounds of `a * b`.
    pub fn mul(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
        let c = [
            a.0 as i128 * b.0 as i128,
            a.0 as i128 * b.1 as i128,
            a.1 as i128 * b.0 as i128,
            a.1 as i128 * b.1 as i128,
        ];
        let lo = c.iter().copied().min().unwrap_or(0);
        let hi = c.iter().copied().max().unwrap_or(0);
        (clamp(lo), clamp(hi))
    }

    /// Bounds of `a / b` (truncating); a divisor range containing 0 is treated as excluding it.
    /// Computed in 128 bits: `i64::MIN / -1` has no 64-bit value (the operation itself fails
    /// at run time with an overflow), so its bound saturates at `i64::MAX`.
    pub fn div(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
        let m = (a.0 as i128).abs().max((a.1 as i128).abs());
        if b.0 > 0 || b.1 < 0 {
            let mut c = [0i128; 4];
            for (k, (x, y)) in [(a.0, b.0), (a.0, b.1), (a.1, b.0), (a.1, b.1)]
                .into_iter()
                .enumerate()
            {
                c[k] = x as i128 / y as i128;
            }
            let lo = c.iter().copied().min().unwrap_or(0);
            let hi = c.iter().copied().max().unwrap_or(0);
            (
                saturate(lo.min(0).max(-m).min(lo)),
                saturate(hi.max(0).min(m).max(hi)),
            )
        } else {
            (saturate(-m), saturate(m))
        }
    }

    /// Bounds of `abs(a)`, saturating at `i64::MAX` (`abs(i64::MIN)` fails at run time).
    pub fn abs(a: (i64, i64)) -> (i64, i64) {
        let (lo, hi) = (a.0 as i128, a.1 as i128);
        if lo >= 0 {
            a
        } else if hi <= 0 {
            (saturate(-hi), saturate(-lo))
        } else {
            (0, saturate((-lo).max(hi)))
        }
    }

    /// Bounds of `a % b` (sign of the dividend).
    pub fn rem(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
        let m = b.0.unsigned_abs().max(b.1.unsigned_abs()).saturating_sub(1) as i64;
        let lo = if a.0 < 0 { (-m).max(a.0) } else { 0 };
        let hi = if a.1 > 0 { m.min(a.1) } else { 0 };
        (lo, hi)
    }

    /// Bounds of a bitwise operation or shift: the smallest power-of-two span covering both.
    pub fn bits(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
        let m =
            a.0.unsigned_abs()
                .max(a.1.unsigned_abs())
                .max(b.0.unsigned_abs())
                .max(b.1.unsigned_abs());
        let p = m.checked_next_power_of_two().unwrap_or(u64::MAX / 2) as i64;
        if a.0 < 0 || b.0 < 0 {
            (-p, p - 1)
        } else {
            (0, p.saturating_mul(2) - 1)
        }
    }

    /// Bounds of `a << b`.
    pub fn shl(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
        let s = b.1.clamp(0, 62) as u32;
        (
            clamp((a.0 as i128) << s).min(a.0),
            clamp((a.1 as i128) << s).max(a.1),
        )
    }

    /// Bounds of `a >> b`.
    pub fn shr(a: (i64, i64), _b: (i64, i64)) -> (i64, i64) {
        (a.0.min(0), a.1.max(0))
    }

    /// Bounds of the union of two intervals.
    pub fn union(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
        (a.0.min(b.0), a.1.max(b.1))
    }
}
