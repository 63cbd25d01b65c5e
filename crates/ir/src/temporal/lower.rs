//! Lowering temporal declarations of the checked model to [`TemporalProperty`] and
//! [`Fairness`]: the derived operators are defined here and nowhere else.

use super::{Ctl, Fairness, Ltl, TemporalFormula, TemporalProperty, Written};
use crate::ExprId;
use statecheck_model::formula::{Formula, Quant, TempBin, TempOp};
use statecheck_model::{Expr, Property, PropertyKind};

/// The temporal properties and fairness constraints among `props`; `expr` lowers an atom.
pub(crate) fn lower(
    props: &[Property],
    expr: &mut dyn FnMut(&Expr) -> ExprId,
) -> (Vec<TemporalProperty>, Vec<Fairness>) {
    let mut temporal = Vec::new();
    let mut fairness = Vec::new();
    for p in props {
        let (written, formula) = match &p.kind {
            PropertyKind::Ltl(f) => (Written::Ltl, TemporalFormula::Ltl(ltl(f, expr))),
            PropertyKind::RespondEventually { trigger, response } => {
                // G(p => F q)
                let t = Ltl::Atom(expr(trigger));
                let r = Ltl::Atom(expr(response));
                let f = Ltl::Until(Box::new(Ltl::True), Box::new(r));
                let body = Ltl::Or(Box::new(t.negate()), Box::new(f));
                let g = Ltl::Release(Box::new(Ltl::False), Box::new(body));
                (Written::Respond, TemporalFormula::Ltl(g))
            }
            PropertyKind::Ctl(f) => (Written::Ctl, TemporalFormula::Ctl(ctl(f, expr))),
            PropertyKind::Nonblocking { expr: e } => {
                // AG EF e = !E[true U !E[true U e]]
                let ef = Ctl::Eu(Box::new(Ctl::True), Box::new(Ctl::Atom(expr(e))));
                let not_ef = Ctl::Not(Box::new(ef));
                let ag = Ctl::Not(Box::new(Ctl::Eu(Box::new(Ctl::True), Box::new(not_ef))));
                (Written::Nonblocking, TemporalFormula::Ctl(ag))
            }
            PropertyKind::Fair { trigger, expr: e } => {
                fairness.push(Fairness {
                    name: p.name.clone(),
                    trigger: trigger.as_ref().map(&mut *expr),
                    expr: expr(e),
                    span: p.span,
                });
                continue;
            }
            PropertyKind::Invariant { .. }
            | PropertyKind::Reachable { .. }
            | PropertyKind::Respond { .. } => continue,
        };
        temporal.push(TemporalProperty {
            name: p.name.clone(),
            written,
            formula,
            span: p.span,
        });
    }
    (temporal, fairness)
}

fn bx(f: Ltl) -> Box<Ltl> {
    Box::new(f)
}

/// The LTL core of a checked formula (depth bounded by the parser).
fn ltl(f: &Formula, expr: &mut dyn FnMut(&Expr) -> ExprId) -> Ltl {
    match f {
        Formula::Atom(e) => Ltl::Atom(expr(e)),
        Formula::Not(a) => ltl(a, expr).negate(),
        Formula::And(a, b) => Ltl::And(bx(ltl(a, expr)), bx(ltl(b, expr))),
        Formula::Or(a, b) => Ltl::Or(bx(ltl(a, expr)), bx(ltl(b, expr))),
        Formula::Implies(a, b) => Ltl::Or(bx(ltl(a, expr).negate()), bx(ltl(b, expr))),
        Formula::Unary(op, a) => {
            let a = ltl(a, expr);
            match op {
                TempOp::X | TempOp::AX | TempOp::EX => Ltl::Next(bx(a)),
                TempOp::F | TempOp::AF | TempOp::EF => Ltl::Until(bx(Ltl::True), bx(a)),
                TempOp::G | TempOp::AG | TempOp::EG => Ltl::Release(bx(Ltl::False), bx(a)),
            }
        }
        Formula::Binary(op, a, b) => {
            let (a, b) = (ltl(a, expr), ltl(b, expr));
            match op {
                TempBin::U => Ltl::Until(bx(a), bx(b)),
                TempBin::R => Ltl::Release(bx(a), bx(b)),
                // a W b = b R (a || b)
                TempBin::W => Ltl::Release(bx(b.clone()), bx(Ltl::Or(bx(a), bx(b)))),
            }
        }
        // Rejected by the checker (E0160); read as its LTL shadow.
        Formula::QuantUntil(_, a, b) => Ltl::Until(bx(ltl(a, expr)), bx(ltl(b, expr))),
    }
}

fn cbx(f: Ctl) -> Box<Ctl> {
    Box::new(f)
}

fn cnot(f: Ctl) -> Ctl {
    match f {
        Ctl::Not(a) => *a,
        a => Ctl::Not(cbx(a)),
    }
}

/// The existential CTL core of a checked formula (depth bounded by the parser). A formula
/// the checker rejected (an LTL operator in `ctl`) never reaches the lowering.
fn ctl(f: &Formula, expr: &mut dyn FnMut(&Expr) -> ExprId) -> Ctl {
    match f {
        Formula::Atom(e) => Ctl::Atom(expr(e)),
        Formula::Not(a) => cnot(ctl(a, expr)),
        Formula::And(a, b) => Ctl::And(cbx(ctl(a, expr)), cbx(ctl(b, expr))),
        Formula::Or(a, b) => Ctl::Or(cbx(ctl(a, expr)), cbx(ctl(b, expr))),
        Formula::Implies(a, b) => Ctl::Or(cbx(cnot(ctl(a, expr))), cbx(ctl(b, expr))),
        Formula::Unary(op, a) => {
            let a = ctl(a, expr);
            match op {
                TempOp::EX | TempOp::X => Ctl::Ex(cbx(a)),
                TempOp::AX => cnot(Ctl::Ex(cbx(cnot(a)))),
                TempOp::EF | TempOp::F => Ctl::Eu(cbx(Ctl::True), cbx(a)),
                TempOp::AG | TempOp::G => cnot(Ctl::Eu(cbx(Ctl::True), cbx(cnot(a)))),
                TempOp::EG => Ctl::Eg(cbx(a)),
                TempOp::AF => cnot(Ctl::Eg(cbx(cnot(a)))),
            }
        }
        Formula::QuantUntil(Quant::Exists, a, b) | Formula::Binary(_, a, b) => {
            Ctl::Eu(cbx(ctl(a, expr)), cbx(ctl(b, expr)))
        }
        Formula::QuantUntil(Quant::All, a, b) => {
            // A[a U b] = !E[!b U (!a && !b)] && !EG !b
            let (a, b) = (ctl(a, expr), ctl(b, expr));
            let nb = cnot(b);
            let both = Ctl::And(cbx(cnot(a)), cbx(nb.clone()));
            let eu = Ctl::Eu(cbx(nb.clone()), cbx(both));
            Ctl::And(cbx(cnot(eu)), cbx(cnot(Ctl::Eg(cbx(nb)))))
        }
    }
}
