//! Certificates: an inductive invariant written to a file and re-checked with one SAT call per
//! obligation, independently of the engine that found it.
//!
//! Format (text): comment lines start with `c`; a header `p inv LATCHES CLAUSES`; then one
//! clause per line as signed 1-based latch numbers ending with `0` (`-3` means "latch 3 is 0").
//! The obligations, for a circuit with constraint `C`, transition `T` and bad output `B`:
//! `Init ⇒ Inv`, `Inv ∧ C ∧ T ⇒ Inv'`, and `Inv ∧ C ⇒ ¬B`.

use crate::aig::{Aig, Lit};
use crate::engine::Invariant;
use crate::error::{Error, ErrorKind};
use crate::sat::{SLit, Solver, Start, Unroller};
use std::fmt::Write;

/// Render an invariant of `aig` in the certificate format.
pub fn write(aig: &Aig, property: &str, inv: &Invariant) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "c statecheck inductive invariant for `{property}`");
    let _ = writeln!(
        out,
        "c check with: statecheck verify ... --property {property} --check-certificate FILE"
    );
    for (i, name) in aig.latch_names.iter().enumerate() {
        if let Some(n) = name {
            let _ = writeln!(out, "c latch {} {n}", i + 1);
        }
    }
    let _ = writeln!(out, "p inv {} {}", aig.latches.len(), inv.len());
    for cl in inv {
        for &(j, v) in cl {
            let n = j as i64 + 1;
            let _ = write!(out, "{} ", if v { n } else { -n });
        }
        out.push_str("0\n");
    }
    out
}

/// Parse a certificate for a circuit with `latches` latches.
pub fn parse(text: &str, latches: usize) -> Result<Invariant, Error> {
    let mut inv = Vec::new();
    let mut header = false;
    for (ln, line) in text.lines().enumerate() {
        let at = ln + 1;
        let t = line.trim();
        if t.is_empty() || t.starts_with('c') {
            continue;
        }
        if let Some(rest) = t.strip_prefix("p inv") {
            let nums: Vec<&str> = rest.split_whitespace().collect();
            let n: usize = nums.first().and_then(|x| x.parse().ok()).ok_or_else(|| {
                Error::syntax(Some(at), "bad header (expected `p inv LATCHES CLAUSES`)")
            })?;
            if n != latches {
                return Err(Error::syntax(
                    Some(at),
                    format!("the certificate is for {n} latches, the circuit has {latches}"),
                ));
            }
            header = true;
            continue;
        }
        if !header {
            return Err(Error::syntax(Some(at), "clause before the `p inv` header"));
        }
        let mut cl = Vec::new();
        let mut ended = false;
        for tok in t.split_whitespace() {
            let v: i64 = tok
                .parse()
                .map_err(|_| Error::syntax(Some(at), format!("`{tok}` is not a latch number")))?;
            if v == 0 {
                ended = true;
                break;
            }
            let j = v.unsigned_abs() as usize;
            if j > latches {
                return Err(Error::syntax(Some(at), format!("latch {j} does not exist")));
            }
            cl.push((j - 1, v > 0));
        }
        if !ended {
            return Err(Error::syntax(Some(at), "clause does not end with 0"));
        }
        inv.push(cl);
    }
    if !header {
        return Err(Error::syntax(None, "no `p inv` header"));
    }
    Ok(inv)
}

fn clause_lits(
    u: &mut Unroller,
    s: &mut Solver,
    aig: &Aig,
    cl: &[(usize, bool)],
    t: usize,
) -> Vec<SLit> {
    cl.iter()
        .map(|&(j, v)| {
            let x = u.lit(s, Lit::var_lit(aig.latches[j].var), t);
            if v {
                x
            } else {
                !x
            }
        })
        .collect()
}

/// Assert that some clause of `inv` is false in frame `t`.
fn violate(u: &mut Unroller, s: &mut Solver, aig: &Aig, inv: &Invariant, t: usize) {
    let mut some = Vec::new();
    for cl in inv {
        let lits = clause_lits(u, s, aig, cl, t);
        let d = s.fresh();
        for l in lits {
            s.add(&[!d, !l]);
        }
        some.push(d);
    }
    s.add(&some);
}

fn assert_inv(u: &mut Unroller, s: &mut Solver, aig: &Aig, inv: &Invariant, t: usize) {
    for cl in inv {
        let lits = clause_lits(u, s, aig, cl, t);
        s.add(&lits);
    }
}

/// Check that `inv` proves `aig.bad[0]` unreachable; `Err` names the failed obligation.
pub fn check(aig: &Aig, inv: &Invariant) -> Result<(), Error> {
    let bad = aig.bad.first().copied().unwrap_or(Lit::FALSE);
    let unsat = |s: &mut Solver, obligation: &'static str| match s.solve(&[]) {
        Some(false) => Ok(()),
        Some(true) => Err(Error::of(ErrorKind::CertificateFails { obligation })),
        None => Err(Error::of(ErrorKind::SolverFailed)),
    };
    // Init ⇒ Inv.
    let mut s = Solver::new();
    let mut u = Unroller::new(aig, Start::Reset);
    violate(&mut u, &mut s, aig, inv, 0);
    unsat(&mut s, "an initial state violates the invariant")?;
    // Inv ∧ C ∧ T ⇒ Inv'.
    let mut s = Solver::new();
    let mut u = Unroller::new(aig, Start::Free);
    assert_inv(&mut u, &mut s, aig, inv, 0);
    for &c in &aig.constraints {
        let x = u.lit(&mut s, c, 0);
        s.add(&[x]);
    }
    violate(&mut u, &mut s, aig, inv, 1);
    unsat(&mut s, "the invariant is not inductive")?;
    // Inv ∧ C ⇒ ¬B.
    let mut s = Solver::new();
    let mut u = Unroller::new(aig, Start::Free);
    assert_inv(&mut u, &mut s, aig, inv, 0);
    for &c in &aig.constraints {
        let x = u.lit(&mut s, c, 0);
        s.add(&[x]);
    }
    let b = u.lit(&mut s, bad, 0);
    s.add(&[b]);
    unsat(&mut s, "a state of the invariant reaches the bad output")
}
