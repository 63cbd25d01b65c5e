//! Exact rational numbers for clock readings: `i128` numerator and positive denominator in
//! lowest terms. Every operation is checked; an overflow is `None` (reported as "too large"
//! by the caller), never a wrong value.

use std::cmp::Ordering;
use std::fmt;

/// A rational number `num / den` with `den > 0` and `gcd(num, den) = 1`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Ratio {
    num: i128,
    den: i128,
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
}

impl Ratio {
    /// Zero.
    pub const ZERO: Ratio = Ratio { num: 0, den: 1 };

    /// `num / den`, reduced; `None` when `den` is zero.
    pub fn new(num: i128, den: i128) -> Option<Ratio> {
        if den == 0 {
            return None;
        }
        let g = gcd(num, den).max(1);
        let (mut n, mut d) = (num / g, den / g);
        if d < 0 {
            n = n.checked_neg()?;
            d = d.checked_neg()?;
        }
        Some(Ratio { num: n, den: d })
    }

    /// An integer.
    pub fn int(v: i64) -> Ratio {
        Ratio {
            num: v as i128,
            den: 1,
        }
    }

    /// A decimal literal such as `0.8` or `12` (digits, at most one point, `_` separators).
    pub fn decimal(text: &str) -> Option<Ratio> {
        let text: String = text.chars().filter(|c| *c != '_').collect();
        let (int, frac) = match text.split_once('.') {
            Some((i, f)) => (i, f),
            None => (text.as_str(), ""),
        };
        if int.is_empty()
            || (text.contains('.') && frac.is_empty())
            || !int.bytes().chain(frac.bytes()).all(|b| b.is_ascii_digit())
        {
            return None;
        }
        let mut num: i128 = 0;
        let mut den: i128 = 1;
        for b in int.bytes() {
            num = num.checked_mul(10)?.checked_add((b - b'0') as i128)?;
        }
        for b in frac.bytes() {
            num = num.checked_mul(10)?.checked_add((b - b'0') as i128)?;
            den = den.checked_mul(10)?;
        }
        Ratio::new(num, den)
    }

    /// The numerator.
    pub fn num(self) -> i128 {
        self.num
    }

    /// The denominator (positive).
    pub fn den(self) -> i128 {
        self.den
    }

    /// The value when it is a whole number.
    pub fn as_int(self) -> Option<i128> {
        (self.den == 1).then_some(self.num)
    }

    /// Sum.
    pub fn checked_add(self, o: Ratio) -> Option<Ratio> {
        let n = self
            .num
            .checked_mul(o.den)?
            .checked_add(o.num.checked_mul(self.den)?)?;
        Ratio::new(n, self.den.checked_mul(o.den)?)
    }

    /// Difference.
    pub fn checked_sub(self, o: Ratio) -> Option<Ratio> {
        self.checked_add(o.checked_neg()?)
    }

    /// Negation.
    pub fn checked_neg(self) -> Option<Ratio> {
        Some(Ratio {
            num: self.num.checked_neg()?,
            den: self.den,
        })
    }

    /// Product.
    pub fn checked_mul(self, o: Ratio) -> Option<Ratio> {
        Ratio::new(self.num.checked_mul(o.num)?, self.den.checked_mul(o.den)?)
    }

    /// Quotient; `None` when `o` is zero.
    pub fn checked_div(self, o: Ratio) -> Option<Ratio> {
        Ratio::new(self.num.checked_mul(o.den)?, self.den.checked_mul(o.num)?)
    }

    /// The sign: -1, 0 or 1.
    pub fn signum(self) -> i128 {
        self.num.signum()
    }

    /// The absolute value.
    pub fn abs(self) -> Ratio {
        Ratio {
            num: self.num.abs(),
            den: self.den,
        }
    }

    /// The value as a float (for display only).
    pub fn to_f64(self) -> f64 {
        self.num as f64 / self.den as f64
    }
}

impl PartialOrd for Ratio {
    fn partial_cmp(&self, o: &Ratio) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Ord for Ratio {
    fn cmp(&self, o: &Ratio) -> Ordering {
        // Cross-multiplication can overflow only for huge values; compare as floats then.
        match (self.num.checked_mul(o.den), o.num.checked_mul(self.den)) {
            (Some(a), Some(b)) => a.cmp(&b),
            _ => self.to_f64().total_cmp(&o.to_f64()),
        }
    }
}

impl fmt::Display for Ratio {
    /// A whole number, a terminating decimal (`118.75`), or `a/b`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            return write!(f, "{}", self.num);
        }
        // Terminating iff the denominator has no prime factors but 2 and 5.
        let mut d = self.den;
        let (mut twos, mut fives) = (0u32, 0u32);
        while d % 2 == 0 {
            d /= 2;
            twos += 1;
        }
        while d % 5 == 0 {
            d /= 5;
            fives += 1;
        }
        if d != 1 || twos.max(fives) > 18 {
            return write!(f, "{}/{}", self.num, self.den);
        }
        let digits = twos.max(fives);
        let scale = 10i128.pow(digits);
        let scaled = self.num * (scale / self.den);
        let sign = if scaled < 0 { "-" } else { "" };
        let a = scaled.abs();
        let frac = format!("{:0width$}", a % scale, width = digits as usize);
        write!(f, "{sign}{}.{}", a / scale, frac.trim_end_matches('0'))
    }
}

#[cfg(test)]
mod tests {
    use super::Ratio;

    #[test]
    fn decimals_and_display() {
        // 0.8 = 4/5; 118.75 = 475/4; 1/3 does not terminate.
        assert_eq!(Ratio::decimal("0.8"), Ratio::new(4, 5));
        let show = |n, d| Ratio::new(n, d).map(|r| r.to_string());
        assert_eq!(show(475, 4).as_deref(), Some("118.75"));
        assert_eq!(show(1, 3).as_deref(), Some("1/3"));
        assert_eq!(show(-5, 2).as_deref(), Some("-2.5"));
        assert_eq!(Ratio::decimal("1."), None);
    }
}
