//! Checked temporal formulas of `ltl` and `ctl` properties: atoms are checked boolean
//! expressions; each logic admits its own operators (E0160, E0161).

use crate::expr::ExprChecker;
use crate::model::Expr;
use crate::scope::Scope;
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;

pub use statecheck_syntax::ast::{Quant, TempBin, TempOp};

/// Which temporal logic a formula is written in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Logic {
    /// Linear time (`ltl`): `G F X U R W`.
    Ltl,
    /// Branching time (`ctl`): `AG AF AX EG EF EX A[U] E[U]`.
    Ctl,
}

/// A checked temporal formula.
#[derive(Clone, Debug)]
pub enum Formula {
    /// A boolean state expression, evaluated after a tick (with the tick's inputs).
    Atom(Expr),
    /// Negation.
    Not(Box<Formula>),
    /// Conjunction.
    And(Box<Formula>, Box<Formula>),
    /// Disjunction.
    Or(Box<Formula>, Box<Formula>),
    /// Implication.
    Implies(Box<Formula>, Box<Formula>),
    /// A unary temporal operator.
    Unary(TempOp, Box<Formula>),
    /// `U`, `R`, `W` (LTL).
    Binary(TempBin, Box<Formula>, Box<Formula>),
    /// `A[φ U ψ]` / `E[φ U ψ]` (CTL).
    QuantUntil(Quant, Box<Formula>, Box<Formula>),
}

impl Formula {
    /// Every atom, in order, for rewriting (instance rebasing).
    pub fn atoms_mut(&mut self, f: &mut dyn FnMut(&mut Expr)) {
        match self {
            Formula::Atom(e) => f(e),
            Formula::Not(a) | Formula::Unary(_, a) => a.atoms_mut(f),
            Formula::And(a, b)
            | Formula::Or(a, b)
            | Formula::Implies(a, b)
            | Formula::Binary(_, a, b)
            | Formula::QuantUntil(_, a, b) => {
                a.atoms_mut(f);
                b.atoms_mut(f);
            }
        }
    }

    /// Every atom, in order.
    pub fn atoms(&self, f: &mut dyn FnMut(&Expr)) {
        match self {
            Formula::Atom(e) => f(e),
            Formula::Not(a) | Formula::Unary(_, a) => a.atoms(f),
            Formula::And(a, b)
            | Formula::Or(a, b)
            | Formula::Implies(a, b)
            | Formula::Binary(_, a, b)
            | Formula::QuantUntil(_, a, b) => {
                a.atoms(f);
                b.atoms(f);
            }
        }
    }
}

/// Check a formula of `logic`. The parser bounds its depth, so the recursion is bounded.
pub(crate) fn check(
    ck: &mut ExprChecker,
    scope: &Scope,
    f: &ast::Formula,
    logic: Logic,
) -> Formula {
    let sub = |g: &ast::Formula, ck: &mut ExprChecker| Box::new(check(ck, scope, g, logic));
    match f {
        ast::Formula::Atom(e) => Formula::Atom(ck.check_bool(scope, e)),
        ast::Formula::Not(a, _) => Formula::Not(sub(a, ck)),
        ast::Formula::And(a, b, _) => Formula::And(sub(a, ck), sub(b, ck)),
        ast::Formula::Or(a, b, _) => Formula::Or(sub(a, ck), sub(b, ck)),
        ast::Formula::Implies(a, b, _) => Formula::Implies(sub(a, ck), sub(b, ck)),
        ast::Formula::Unary(op, a, span) => {
            match (logic, op.is_ctl()) {
                (Logic::Ltl, true) => wrong_logic(ck, *span, op.as_str(), logic),
                (Logic::Ctl, false) => wrong_logic(ck, *span, op.as_str(), logic),
                _ => {}
            }
            Formula::Unary(*op, sub(a, ck))
        }
        ast::Formula::Binary(op, a, b, span) => {
            if logic == Logic::Ctl {
                wrong_logic(ck, *span, op.as_str(), logic);
            }
            Formula::Binary(*op, sub(a, ck), sub(b, ck))
        }
        ast::Formula::QuantUntil(q, a, b, span) => {
            if logic == Logic::Ltl {
                let w = if *q == Quant::All {
                    "A[..U..]"
                } else {
                    "E[..U..]"
                };
                wrong_logic(ck, *span, w, logic);
            }
            Formula::QuantUntil(*q, sub(a, ck), sub(b, ck))
        }
    }
}

fn wrong_logic(ck: &mut ExprChecker, span: Span, op: &str, logic: Logic) {
    let d = match logic {
        Logic::Ltl => Diagnostic::error(
            "E0160",
            format!("`{op}` is a CTL operator; `ltl` formulas use `G F X U R W`"),
            span,
        )
        .with_label("path quantifier in an LTL formula")
        .with_hint("drop the `A`/`E` (an `ltl` property holds on every run), or declare a `ctl` property"),
        Logic::Ctl => Diagnostic::error(
            "E0161",
            format!("`{op}` needs a path quantifier in a `ctl` formula"),
            span,
        )
        .with_label("LTL operator in a CTL formula")
        .with_hint("write `AG`, `AF`, `AX`, `EG`, `EF`, `EX`, `A[p U q]` or `E[p U q]`, or declare an `ltl` property"),
    };
    ck.sink.push(d);
}
