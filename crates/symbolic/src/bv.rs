//! Two's-complement bit-vectors over an [`Aig`], each with the interval of values it can take.
//!
//! Every operation computes its exact result in a width that can hold every value of the
//! result's interval (intervals are `i128`, and operands always lie within `i64`), so no
//! operation wraps: overflow of the interpreter's `i64` arithmetic is detected by the caller by
//! comparing the exact result with the `i64` bounds.

use crate::aig::{Aig, Lit};

/// A bit-vector: bits least significant first, two's complement, and the interval of values.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Bv {
    /// The bits, least significant first; the last bit is the sign.
    pub bits: Vec<Lit>,
    /// Smallest possible value.
    pub lo: i128,
    /// Largest possible value.
    pub hi: i128,
}

/// Bits needed to hold `v` in two's complement (at least 1).
pub fn bits_for(v: i128) -> usize {
    let m = if v >= 0 { v } else { !v };
    (128 - m.leading_zeros() as usize) + 1
}

/// Bits needed to hold every value in `lo..=hi`.
pub fn width_for(lo: i128, hi: i128) -> usize {
    bits_for(lo).max(bits_for(hi))
}

impl Bv {
    /// A constant.
    pub fn constant(v: i128) -> Bv {
        let w = bits_for(v);
        Bv {
            bits: (0..w).map(|i| Lit::constant((v >> i) & 1 == 1)).collect(),
            lo: v,
            hi: v,
        }
    }

    /// The sign bit.
    pub fn sign(&self) -> Lit {
        self.bits.last().copied().unwrap_or(Lit::FALSE)
    }

    /// The bits sign-extended (or truncated) to `w`.
    pub fn ext(&self, w: usize) -> Vec<Lit> {
        let s = self.sign();
        (0..w)
            .map(|i| self.bits.get(i).copied().unwrap_or(s))
            .collect()
    }

    /// Restrict the interval to `lo..=hi` (the caller knows other values do not matter) and
    /// drop the bits it no longer needs.
    pub fn restrict(mut self, lo: i128, hi: i128) -> Bv {
        let (nlo, nhi) = (self.lo.max(lo), self.hi.min(hi));
        if nlo > nhi {
            // No value survives: any value in range will do.
            return Bv::constant(lo);
        }
        self.lo = nlo;
        self.hi = nhi;
        let w = width_for(nlo, nhi);
        self.bits = self.ext(w);
        self
    }

    /// The value of a simulation (see [`Aig::simulate`]).
    pub fn value(&self, vals: &[bool]) -> i128 {
        let w = self.bits.len();
        let mut v: i128 = 0;
        for (i, b) in self.bits.iter().enumerate() {
            if crate::aig::lit_val(vals, *b) {
                v |= 1 << i;
            }
        }
        if w > 0 && w < 128 && (v >> (w - 1)) & 1 == 1 {
            v -= 1 << w;
        }
        v
    }
}

fn shaped(bits: Vec<Lit>, lo: i128, hi: i128) -> Bv {
    let w = width_for(lo, hi);
    let b = Bv { bits, lo, hi };
    Bv {
        bits: b.ext(w),
        lo,
        hi,
    }
}

/// Ripple-carry sum of two equal-width vectors plus a carry in.
fn adder(g: &mut Aig, a: &[Lit], b: &[Lit], mut c: Lit) -> Vec<Lit> {
    let mut out = Vec::with_capacity(a.len());
    for (&x, &y) in a.iter().zip(b) {
        let t = g.xor(x, y);
        out.push(g.xor(t, c));
        let c1 = g.and(x, y);
        let c2 = g.and(t, c);
        c = g.or(c1, c2);
    }
    out
}

/// `a + b`.
pub fn add(g: &mut Aig, a: &Bv, b: &Bv) -> Bv {
    let (lo, hi) = (a.lo + b.lo, a.hi + b.hi);
    let w = width_for(lo, hi).max(a.bits.len()).max(b.bits.len()) + 1;
    let s = adder(g, &a.ext(w), &b.ext(w), Lit::FALSE);
    shaped(s, lo, hi)
}

/// `a - b`.
pub fn sub(g: &mut Aig, a: &Bv, b: &Bv) -> Bv {
    let (lo, hi) = (a.lo - b.hi, a.hi - b.lo);
    let w = width_for(lo, hi).max(a.bits.len()).max(b.bits.len()) + 1;
    let nb: Vec<Lit> = b.ext(w).into_iter().map(|l| !l).collect();
    let s = adder(g, &a.ext(w), &nb, Lit::TRUE);
    shaped(s, lo, hi)
}

/// `-a`.
pub fn neg(g: &mut Aig, a: &Bv) -> Bv {
    sub(g, &Bv::constant(0), a)
}

/// `~a` (bitwise complement, `-a - 1`).
pub fn bitnot(a: &Bv) -> Bv {
    Bv {
        bits: a.bits.iter().map(|l| !*l).collect(),
        lo: -a.hi - 1,
        hi: -a.lo - 1,
    }
}

/// `a * b`.
pub fn mul(g: &mut Aig, a: &Bv, b: &Bv) -> Bv {
    let c = [a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi];
    let lo = c.iter().copied().min().unwrap_or(0);
    let hi = c.iter().copied().max().unwrap_or(0);
    let w = width_for(lo, hi);
    let (x, y) = (a.ext(w), b.ext(w));
    let mut acc = vec![Lit::FALSE; w];
    for (i, &yb) in y.iter().enumerate() {
        if yb == Lit::FALSE {
            continue;
        }
        let mut row = vec![Lit::FALSE; w];
        for j in 0..w - i {
            row[i + j] = g.and(x[j], yb);
        }
        acc = adder(g, &acc, &row, Lit::FALSE);
    }
    shaped(acc, lo, hi)
}

/// Signed `a < b`.
pub fn lt(g: &mut Aig, a: &Bv, b: &Bv) -> Lit {
    if a.hi < b.lo {
        return Lit::TRUE;
    }
    if a.lo >= b.hi {
        return Lit::FALSE;
    }
    let w = a.bits.len().max(b.bits.len()) + 1;
    let nb: Vec<Lit> = b.ext(w).into_iter().map(|l| !l).collect();
    let d = adder(g, &a.ext(w), &nb, Lit::TRUE);
    d[w - 1]
}

/// `a == b`.
pub fn eq(g: &mut Aig, a: &Bv, b: &Bv) -> Lit {
    if a.hi < b.lo || b.hi < a.lo {
        return Lit::FALSE;
    }
    let w = a.bits.len().max(b.bits.len());
    let (x, y) = (a.ext(w), b.ext(w));
    let eqs: Vec<Lit> = x.iter().zip(&y).map(|(p, q)| g.iff(*p, *q)).collect();
    g.and_all(eqs)
}

/// `a != 0`.
pub fn nonzero(g: &mut Aig, a: &Bv) -> Lit {
    let bits = a.bits.clone();
    g.or_all(bits)
}

/// A Boolean as a 0/1 vector.
pub fn from_bool(l: Lit) -> Bv {
    match l {
        Lit::FALSE => Bv::constant(0),
        Lit::TRUE => Bv::constant(1),
        _ => Bv {
            bits: vec![l, Lit::FALSE],
            lo: 0,
            hi: 1,
        },
    }
}

/// `if c then a else b`.
pub fn mux(g: &mut Aig, c: Lit, a: &Bv, b: &Bv) -> Bv {
    if c == Lit::TRUE {
        return a.clone();
    }
    if c == Lit::FALSE {
        return b.clone();
    }
    let w = a.bits.len().max(b.bits.len());
    let (x, y) = (a.ext(w), b.ext(w));
    let bits = x.iter().zip(&y).map(|(p, q)| g.mux(c, *p, *q)).collect();
    shaped(bits, a.lo.min(b.lo), a.hi.max(b.hi))
}

/// Bitwise `&`, `|` or `^` (`op` 0, 1, 2).
pub fn bitwise(g: &mut Aig, op: u8, a: &Bv, b: &Bv) -> Bv {
    let w = a.bits.len().max(b.bits.len());
    let (x, y) = (a.ext(w), b.ext(w));
    let bits: Vec<Lit> = x
        .iter()
        .zip(&y)
        .map(|(p, q)| match op {
            0 => g.and(*p, *q),
            1 => g.or(*p, *q),
            _ => g.xor(*p, *q),
        })
        .collect();
    let full = (-(1i128 << (w - 1)), (1i128 << (w - 1)) - 1);
    let (lo, hi) = if a.lo >= 0 && b.lo >= 0 {
        let ub = (1i128 << (w - 1)) - 1;
        if op == 0 {
            (0, a.hi.min(b.hi))
        } else {
            (0, ub)
        }
    } else if op == 0 && (a.lo >= 0 || b.lo >= 0) {
        (0, if a.lo >= 0 { a.hi } else { b.hi })
    } else {
        full
    };
    shaped(bits, lo, hi)
}

/// Shift `a` left (`left`) or arithmetically right by `amount`, whose values are `0..=62`
/// whenever the result matters.
pub fn shift(g: &mut Aig, a: &Bv, amount: &Bv, left: bool) -> Bv {
    let (slo, shi) = (amount.lo.clamp(0, 62), amount.hi.clamp(0, 62));
    let (lo, hi) = if left {
        let c = [a.lo << slo, a.lo << shi, a.hi << slo, a.hi << shi];
        (
            c.iter().copied().min().unwrap_or(0),
            c.iter().copied().max().unwrap_or(0),
        )
    } else {
        let c = [a.lo >> slo, a.lo >> shi, a.hi >> slo, a.hi >> shi];
        (
            c.iter().copied().min().unwrap_or(0),
            c.iter().copied().max().unwrap_or(0),
        )
    };
    let w = width_for(lo, hi).max(a.bits.len());
    let mut cur = a.ext(w);
    let sign = a.sign();
    let amt = amount.ext(7);
    for (k, &bit) in amt.iter().take(6).enumerate() {
        if bit == Lit::FALSE {
            continue;
        }
        let d = 1usize << k;
        let shifted: Vec<Lit> = (0..w)
            .map(|i| {
                if left {
                    if i >= d {
                        cur[i - d]
                    } else {
                        Lit::FALSE
                    }
                } else {
                    cur.get(i + d).copied().unwrap_or(sign)
                }
            })
            .collect();
        cur = cur
            .iter()
            .zip(&shifted)
            .map(|(o, s)| g.mux(bit, *s, *o))
            .collect();
    }
    shaped(cur, lo, hi)
}

/// `|a|` (exact, one bit wider).
pub fn abs(g: &mut Aig, a: &Bv) -> Bv {
    let n = neg(g, a);
    let s = a.sign();
    let (lo, hi) = if a.lo >= 0 {
        (a.lo, a.hi)
    } else if a.hi <= 0 {
        (-a.hi, -a.lo)
    } else {
        (0, a.hi.max(-a.lo))
    };
    let m = mux(g, s, &n, a);
    shaped(m.bits, lo, hi)
}

/// Signed division truncating toward zero and remainder with the sign of the dividend, for
/// `b != 0` (the caller reports division by zero). Returns `(quotient, remainder)`.
pub fn divrem(g: &mut Aig, a: &Bv, b: &Bv) -> (Bv, Bv) {
    let ma = abs(g, a);
    let mb = abs(g, b);
    let n = ma.bits.len().max(mb.bits.len());
    // Unsigned restoring division over n bits (magnitudes are non-negative).
    let x = ma.ext(n);
    let y = mb.ext(n);
    let mut r: Vec<Lit> = vec![Lit::FALSE; n + 1];
    let mut q = vec![Lit::FALSE; n];
    let yy: Vec<Lit> = y
        .iter()
        .copied()
        .chain(std::iter::once(Lit::FALSE))
        .collect();
    for i in (0..n).rev() {
        // r = (r << 1) | x[i]
        let mut sh = vec![x[i]];
        sh.extend_from_slice(&r[..n]);
        let ny: Vec<Lit> = yy.iter().map(|l| !*l).collect();
        let mut d = adder(g, &sh, &ny, Lit::TRUE);
        // carry out = no borrow: compute sh >= yy via comparison of the (n+1)-bit values.
        let ge = {
            let sv = Bv {
                bits: sh.iter().copied().chain([Lit::FALSE]).collect(),
                lo: 0,
                hi: i128::MAX >> 1,
            };
            let yv = Bv {
                bits: yy.iter().copied().chain([Lit::FALSE]).collect(),
                lo: 0,
                hi: i128::MAX >> 1,
            };
            !lt(g, &sv, &yv)
        };
        q[i] = ge;
        d.truncate(n + 1);
        r = sh
            .iter()
            .zip(&d)
            .map(|(s, dd)| g.mux(ge, *dd, *s))
            .collect();
    }
    let amax = a.lo.abs().max(a.hi.abs());
    let bmax = b.lo.abs().max(b.hi.abs()).max(1);
    let qu = shaped(q.into_iter().chain([Lit::FALSE]).collect(), 0, amax.max(0));
    let ru = shaped(
        r.into_iter().take(n).chain([Lit::FALSE]).collect(),
        0,
        (bmax - 1).min(amax).max(0),
    );
    let qs = g.xor(a.sign(), b.sign());
    let nq = neg(g, &qu);
    let quot = mux(g, qs, &nq, &qu);
    let nr = neg(g, &ru);
    let rem = mux(g, a.sign(), &nr, &ru);
    let quot = Bv {
        lo: -amax,
        hi: amax,
        ..quot
    };
    let rlo = if a.lo < 0 { -(bmax - 1).min(amax) } else { 0 };
    let rhi = if a.hi > 0 { (bmax - 1).min(amax) } else { 0 };
    let rem = Bv {
        lo: rlo.min(0),
        hi: rhi.max(0),
        ..rem
    };
    let quot = shaped(quot.bits.clone(), quot.lo, quot.hi);
    let rem = shaped(rem.ext(rem.bits.len()), rem.lo, rem.hi);
    (quot, rem)
}
