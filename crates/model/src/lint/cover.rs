//! Guard coverage: can a choice fail to reach a state, i.e. can all its branches be blocked?
//!
//! Decided by evaluating the guards over the values the variables they read may take. Small
//! domains are enumerated completely (an exact answer); large integer ranges are sampled at
//! their bounds and around every constant in the guards, which can prove a gap (the sample is a
//! real valuation) but never that there is none. `in(...)` tests are treated as free booleans,
//! which over-approximates the reachable configurations: it can prove that there is no gap but
//! not that one exists.

use super::{const_true, Cx};
use crate::model::{Builtin, ChartId, Dest, Expr, ExprKind, StateRef, VarId, VarRef};
use crate::ops;

/// The answer of a coverage question.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Coverage {
    /// The destination always leads to a state.
    Always,
    /// Some valuation (consistent with the assumptions) blocks every branch.
    Gap,
    /// Not decided: treat as "may fail" but do not report it.
    Unknown,
}

/// Domains larger than this are sampled instead of enumerated.
const FULL_DOMAIN: i128 = 4096;
/// Domains up to this size are always enumerated, even when others must be sampled.
const SMALL_DOMAIN: i128 = 64;
/// At most this many valuations are evaluated per question.
const MAX_VALUATIONS: u128 = 100_000;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Atom {
    Var(VarRef),
    In(StateRef),
}

/// True when `d` leads to a state whatever the values: a target, an internal transition, or
/// a choice with an unconditional branch whose own destination is always valid.
pub(super) fn structurally_valid(d: &Dest) -> bool {
    match d {
        Dest::Internal | Dest::State(_) => true,
        Dest::Choice(branches) => branches
            .iter()
            .any(|b| b.guard.as_ref().is_none_or(const_true) && structurally_valid(&b.dest)),
    }
}

/// Does `dest` lead to a state for every valuation in which all of `assume` hold (and the
/// event `trigger`, if any, is present)? Expressions are those of chart `chart`.
pub(super) fn coverage(
    cx: &Cx,
    chart: ChartId,
    assume: &[&Expr],
    trigger: Option<VarId>,
    dest: &Dest,
) -> Coverage {
    if structurally_valid(dest) {
        return Coverage::Always;
    }
    let mut atoms: Vec<Atom> = Vec::new();
    let mut consts: Vec<i64> = Vec::new();
    for e in assume {
        collect(e, &mut atoms, &mut consts);
    }
    collect_dest(dest, &mut atoms, &mut consts);

    let mut has_in = false;
    let mut exact = true;
    let mut domains: Vec<(i64, i64)> = Vec::new();
    for a in &atoms {
        let (lo, hi) = match a {
            Atom::In(_) => {
                has_in = true;
                (0, 1)
            }
            Atom::Var(r) if r.instance.is_none() && Some(r.var) == trigger => (1, 1),
            Atom::Var(r) => match cx.var_type(chart, *r) {
                Some(ty) => cx.model.bounds(ty),
                None => return Coverage::Unknown,
            },
        };
        domains.push((lo, hi));
    }
    let size = |(lo, hi): (i64, i64)| hi as i128 - lo as i128 + 1;
    if domains.iter().any(|d| size(*d) < 1) {
        return Coverage::Unknown;
    }
    let product = domains
        .iter()
        .try_fold(1u128, |acc, d| acc.checked_mul(size(*d) as u128));
    let full: Vec<bool> = if domains.iter().all(|d| size(*d) <= FULL_DOMAIN)
        && product.is_some_and(|p| p <= MAX_VALUATIONS)
    {
        vec![true; domains.len()]
    } else {
        domains.iter().map(|d| size(*d) <= SMALL_DOMAIN).collect()
    };
    let values: Vec<Vec<i64>> = domains
        .iter()
        .zip(&full)
        .map(|(&(lo, hi), &full)| {
            if full {
                (lo..=hi).collect()
            } else {
                exact = false;
                sample(lo, hi, &consts)
            }
        })
        .collect();
    let total = values
        .iter()
        .try_fold(1u128, |acc, v| acc.checked_mul(v.len() as u128));
    if total.is_none_or(|t| t > MAX_VALUATIONS) || values.iter().any(Vec::is_empty) {
        return Coverage::Unknown;
    }

    let mut index = vec![0usize; values.len()];
    let mut env: Vec<i64> = values.iter().map(|v| v[0]).collect();
    loop {
        let ev = Eval {
            atoms: &atoms,
            env: &env,
        };
        let mut holds = true;
        for e in assume {
            match ev.eval(e) {
                Some(0) => holds = false,
                Some(_) => {}
                None => return Coverage::Unknown,
            }
        }
        if holds {
            match ev.valid(dest) {
                Some(true) => {}
                Some(false) => {
                    return if has_in {
                        Coverage::Unknown
                    } else {
                        Coverage::Gap
                    }
                }
                None => return Coverage::Unknown,
            }
        }
        // Next valuation (odometer order).
        let mut k = 0;
        loop {
            if k == index.len() {
                return if exact {
                    Coverage::Always
                } else {
                    Coverage::Unknown
                };
            }
            index[k] += 1;
            if index[k] < values[k].len() {
                env[k] = values[k][index[k]];
                break;
            }
            index[k] = 0;
            env[k] = values[k][0];
            k += 1;
        }
    }
}

/// Sample values of a large range: its bounds, zero, and every constant of the guards with its
/// neighbours (so each side of a comparison with a constant is represented).
fn sample(lo: i64, hi: i64, consts: &[i64]) -> Vec<i64> {
    let mut v = vec![lo, hi, 0];
    for &c in consts {
        v.extend([c.saturating_sub(1), c, c.saturating_add(1)]);
    }
    v.retain(|x| (lo..=hi).contains(x));
    v.sort_unstable();
    v.dedup();
    v
}

fn collect_dest(d: &Dest, atoms: &mut Vec<Atom>, consts: &mut Vec<i64>) {
    if let Dest::Choice(branches) = d {
        for b in branches {
            if let Some(g) = &b.guard {
                collect(g, atoms, consts);
            }
            collect_dest(&b.dest, atoms, consts);
        }
    }
}

fn collect(e: &Expr, atoms: &mut Vec<Atom>, consts: &mut Vec<i64>) {
    let mut add = |a: Atom| {
        if !atoms.contains(&a) {
            atoms.push(a);
        }
    };
    match &e.kind {
        ExprKind::Const(v) => consts.push(*v),
        ExprKind::Var(r) => add(Atom::Var(*r)),
        ExprKind::In(s) => add(Atom::In(*s)),
        ExprKind::Unary(_, a) => collect(a, atoms, consts),
        ExprKind::Check(a, lo, hi, _) => {
            consts.extend([*lo, *hi]);
            collect(a, atoms, consts);
        }
        ExprKind::Binary(_, a, b) => {
            collect(a, atoms, consts);
            collect(b, atoms, consts);
        }
        ExprKind::If(c, a, b) => {
            collect(c, atoms, consts);
            collect(a, atoms, consts);
            collect(b, atoms, consts);
        }
        ExprKind::Builtin(_, args) => args.iter().for_each(|a| collect(a, atoms, consts)),
        ExprKind::Let(_, v, b) => {
            collect(v, atoms, consts);
            collect(b, atoms, consts);
        }
        ExprKind::Local(_) => {}
    }
}

/// Evaluation of guards under one valuation of the atoms. `None`: the expression has no value
/// (a run-time error, or an atom we did not collect), so the question is left undecided.
struct Eval<'a> {
    atoms: &'a [Atom],
    env: &'a [i64],
}

impl Eval<'_> {
    fn atom(&self, a: Atom) -> Option<i64> {
        self.atoms.iter().position(|x| *x == a).map(|i| self.env[i])
    }

    fn eval(&self, e: &Expr) -> Option<i64> {
        match &e.kind {
            ExprKind::Const(v) => Some(*v),
            ExprKind::Var(r) => self.atom(Atom::Var(*r)),
            ExprKind::In(s) => self.atom(Atom::In(*s)),
            ExprKind::Unary(op, a) => ops::unary(*op, self.eval(a)?).ok(),
            ExprKind::Binary(op, a, b) => ops::binary(*op, self.eval(a)?, self.eval(b)?).ok(),
            ExprKind::If(c, a, b) => {
                if self.eval(c)? != 0 {
                    self.eval(a)
                } else {
                    self.eval(b)
                }
            }
            ExprKind::Builtin(f, args) => {
                let v: Option<Vec<i64>> = args.iter().map(|a| self.eval(a)).collect();
                match (f, v?.as_slice()) {
                    (Builtin::Min, [a, b]) => Some(*a.min(b)),
                    (Builtin::Max, [a, b]) => Some(*a.max(b)),
                    (Builtin::Abs, [a]) => a.checked_abs(),
                    _ => None,
                }
            }
            ExprKind::Check(a, lo, hi, _) => self.eval(a).filter(|v| (*lo..=*hi).contains(v)),
            // Substitute the bound value: a local is its value, evaluated again here.
            ExprKind::Let(id, v, b) => self.eval(&substitute(b, *id, v)),
            ExprKind::Local(_) => None,
        }
    }

    /// R7: does the destination lead to a state under this valuation?
    fn valid(&self, d: &Dest) -> Option<bool> {
        match d {
            Dest::Internal | Dest::State(_) => Some(true),
            Dest::Choice(branches) => {
                for b in branches {
                    let open = match &b.guard {
                        None => true,
                        Some(g) => self.eval(g)? != 0,
                    };
                    if open && self.valid(&b.dest)? {
                        return Some(true);
                    }
                }
                Some(false)
            }
        }
    }
}

/// `body` with every `Local(id)` replaced by `value` (for this evaluator only).
fn substitute(body: &Expr, id: u32, value: &Expr) -> Expr {
    let mut out = body.clone();
    replace(&mut out, id, value);
    out
}

fn replace(e: &mut Expr, id: u32, value: &Expr) {
    match &mut e.kind {
        ExprKind::Local(l) if *l == id => *e = value.clone(),
        ExprKind::Const(_) | ExprKind::Var(_) | ExprKind::In(_) | ExprKind::Local(_) => {}
        ExprKind::Unary(_, a) | ExprKind::Check(a, ..) => replace(a, id, value),
        ExprKind::Binary(_, a, b) | ExprKind::Let(_, a, b) => {
            replace(a, id, value);
            replace(b, id, value);
        }
        ExprKind::If(c, a, b) => {
            replace(c, id, value);
            replace(a, id, value);
            replace(b, id, value);
        }
        ExprKind::Builtin(_, args) => args.iter_mut().for_each(|a| replace(a, id, value)),
    }
}
