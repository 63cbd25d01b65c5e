//! Temporal properties in the IR: the meaning of `ltl`, `ctl`, unbounded `respond`,
//! `nonblocking` and `fair` declarations, decided here once (docs/properties.md, "Temporal
//! properties") and consumed by every engine.
//!
//! - A **position** of a run is the state after a tick, with that tick's inputs still
//!   visible; position 0 is the state after tick 0 (the initial, pre-tick-0 state is not a
//!   position, as for every property). An atom is an IR boolean expression evaluated at a
//!   position; an evaluation that fails counts as false.
//! - Runs are the infinite sequences of positions the `assume`s allow; a tick that stops with a
//!   run-time error ends no run (the built-in properties report it), and a state where the
//!   `assume`s allow no input vector (a deadlock) has no infinite continuation.
//! - LTL is lowered to the core `true false atom ! && || X U R`: `F φ = true U φ`,
//!   `G φ = false R φ`, `φ W ψ = ψ R (φ || ψ)`, `φ => ψ = !φ || ψ`; `respond p => q;` is
//!   `G(p => F q)`.
//! - CTL is lowered to the existential core `EX`, `E[U]`, `EG` with negation: `AX φ = !EX !φ`,
//!   `EF φ = E[true U φ]`, `AG φ = !EF !φ`, `AF φ = !EG !φ`,
//!   `A[φ U ψ] = !E[!ψ U (!φ && !ψ)] && !EG !ψ`; `nonblocking N: e;` is `AG EF e`. A CTL
//!   property holds when every position 0 satisfies it.
//! - Fairness constraints restrict the runs of every temporal property of the system to the
//!   fair ones: justice `fair N: e;` (e holds at infinitely many positions) and compassion
//!   `fair N: p => q;` (if p holds infinitely often, so does q). Path quantifiers of CTL range
//!   over fair runs.
//! - [`buchi`] translates an LTL formula (the negation of a property) into the one generalised
//!   Büchi automaton every engine uses: the explicit engine's product and the SAT engines'
//!   monitor circuit read the same states, labels and acceptance sets.

pub mod buchi;
mod lasso;
mod lower;

pub use lasso::holds_on_lasso;

pub(crate) use lower::lower;

use crate::ExprId;
use statecheck_base::Span;

/// An LTL formula over IR atoms, in the core operators.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Ltl {
    /// Holds everywhere.
    True,
    /// Holds nowhere.
    False,
    /// An IR boolean expression at the current position.
    Atom(ExprId),
    /// Negation.
    Not(Box<Ltl>),
    /// Conjunction.
    And(Box<Ltl>, Box<Ltl>),
    /// Disjunction.
    Or(Box<Ltl>, Box<Ltl>),
    /// At the next position.
    Next(Box<Ltl>),
    /// `a U b`: `b` at some position `j >= i`, `a` at every position in `i..j`.
    Until(Box<Ltl>, Box<Ltl>),
    /// `a R b`: `b` holds up to and including the first position where `a` holds (forever if
    /// none).
    Release(Box<Ltl>, Box<Ltl>),
}

/// A CTL formula over IR atoms, in the existential core.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Ctl {
    /// Holds everywhere.
    True,
    /// An IR boolean expression at the position.
    Atom(ExprId),
    /// Negation.
    Not(Box<Ctl>),
    /// Conjunction.
    And(Box<Ctl>, Box<Ctl>),
    /// Disjunction.
    Or(Box<Ctl>, Box<Ctl>),
    /// Some (fair) successor satisfies it.
    Ex(Box<Ctl>),
    /// `E[a U b]` on some fair run.
    Eu(Box<Ctl>, Box<Ctl>),
    /// Some fair run satisfies it at every position.
    Eg(Box<Ctl>),
}

/// What a temporal property was written as (reported as its kind).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Written {
    /// `ltl NAME: φ;`
    Ltl,
    /// `respond NAME: p => q;` (no bound).
    Respond,
    /// `ctl NAME: ψ;`
    Ctl,
    /// `nonblocking NAME: e;`
    Nonblocking,
}

impl Written {
    /// The JSON and table word.
    pub fn as_str(self) -> &'static str {
        match self {
            Written::Ltl => "ltl",
            Written::Respond => "respond",
            Written::Ctl => "ctl",
            Written::Nonblocking => "nonblocking",
        }
    }
}

/// The formula of a temporal property.
#[derive(Clone, Debug)]
pub enum TemporalFormula {
    /// Every fair run satisfies it.
    Ltl(Ltl),
    /// Every position 0 satisfies it.
    Ctl(Ctl),
}

/// A temporal property of the system.
#[derive(Clone, Debug)]
pub struct TemporalProperty {
    /// Its name (a contract).
    pub name: String,
    /// What was written.
    pub written: Written,
    /// Its meaning.
    pub formula: TemporalFormula,
    /// Where it was declared.
    pub span: Span,
}

/// A fairness constraint: the runs temporal properties speak of are those where, if `trigger`
/// holds at infinitely many positions (always, for justice), `expr` does too.
#[derive(Clone, Debug)]
pub struct Fairness {
    /// Its name.
    pub name: String,
    /// The compassion trigger; `None` for justice.
    pub trigger: Option<ExprId>,
    /// What must hold infinitely often.
    pub expr: ExprId,
    /// Where it was declared.
    pub span: Span,
}

impl Ltl {
    /// `!self`, without double negations.
    pub fn negate(self) -> Ltl {
        match self {
            Ltl::Not(a) => *a,
            Ltl::True => Ltl::False,
            Ltl::False => Ltl::True,
            a => Ltl::Not(Box::new(a)),
        }
    }

    /// Every atom, in order of first occurrence (each once).
    pub fn atoms(&self) -> Vec<ExprId> {
        let mut out = Vec::new();
        let mut stack = vec![self];
        while let Some(f) = stack.pop() {
            match f {
                Ltl::True | Ltl::False => {}
                Ltl::Atom(e) => {
                    if !out.contains(e) {
                        out.push(*e);
                    }
                }
                Ltl::Not(a) | Ltl::Next(a) => stack.push(a),
                Ltl::And(a, b) | Ltl::Or(a, b) | Ltl::Until(a, b) | Ltl::Release(a, b) => {
                    stack.push(b);
                    stack.push(a);
                }
            }
        }
        out
    }
}

impl Ctl {
    /// Every atom, in order of first occurrence (each once).
    pub fn atoms(&self) -> Vec<ExprId> {
        let mut out = Vec::new();
        let mut stack = vec![self];
        while let Some(f) = stack.pop() {
            match f {
                Ctl::True => {}
                Ctl::Atom(e) => {
                    if !out.contains(e) {
                        out.push(*e);
                    }
                }
                Ctl::Not(a) | Ctl::Ex(a) | Ctl::Eg(a) => stack.push(a),
                Ctl::And(a, b) | Ctl::Or(a, b) | Ctl::Eu(a, b) => {
                    stack.push(b);
                    stack.push(a);
                }
            }
        }
        out
    }
}
