//! Temporal formulas of `ltl` and `ctl` properties (docs/properties.md, "Temporal
//! properties"). One tree for both logics; the checker says which operators each allows.

use crate::ast::Expr;
use statecheck_base::Span;

/// A unary temporal operator, with its path quantifier for CTL.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TempOp {
    /// `G φ`: always.
    G,
    /// `F φ`: eventually.
    F,
    /// `X φ`: next.
    X,
    /// `AG ψ`.
    AG,
    /// `AF ψ`.
    AF,
    /// `AX ψ`.
    AX,
    /// `EG ψ`.
    EG,
    /// `EF ψ`.
    EF,
    /// `EX ψ`.
    EX,
}

impl TempOp {
    /// The operator as written.
    pub fn as_str(self) -> &'static str {
        match self {
            TempOp::G => "G",
            TempOp::F => "F",
            TempOp::X => "X",
            TempOp::AG => "AG",
            TempOp::AF => "AF",
            TempOp::AX => "AX",
            TempOp::EG => "EG",
            TempOp::EF => "EF",
            TempOp::EX => "EX",
        }
    }

    /// The operator a word stands for in a formula.
    pub fn from_word(w: &str) -> Option<TempOp> {
        Some(match w {
            "G" => TempOp::G,
            "F" => TempOp::F,
            "X" => TempOp::X,
            "AG" => TempOp::AG,
            "AF" => TempOp::AF,
            "AX" => TempOp::AX,
            "EG" => TempOp::EG,
            "EF" => TempOp::EF,
            "EX" => TempOp::EX,
            _ => return None,
        })
    }

    /// True for the CTL operators (with a path quantifier).
    pub fn is_ctl(self) -> bool {
        !matches!(self, TempOp::G | TempOp::F | TempOp::X)
    }
}

/// A binary temporal operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TempBin {
    /// `φ U ψ`: until (ψ must happen).
    U,
    /// `φ R ψ`: release.
    R,
    /// `φ W ψ`: weak until.
    W,
}

impl TempBin {
    /// The operator as written.
    pub fn as_str(self) -> &'static str {
        match self {
            TempBin::U => "U",
            TempBin::R => "R",
            TempBin::W => "W",
        }
    }

    /// The operator a word stands for in infix position.
    pub fn from_word(w: &str) -> Option<TempBin> {
        Some(match w {
            "U" => TempBin::U,
            "R" => TempBin::R,
            "W" => TempBin::W,
            _ => return None,
        })
    }
}

/// The path quantifier of `A[p U q]` / `E[p U q]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quant {
    /// `A[...]`: on every path.
    All,
    /// `E[...]`: on some path.
    Exists,
}

/// A temporal formula.
#[derive(Clone, Debug, PartialEq)]
pub enum Formula {
    /// A state expression (over variables, `in(...)`, events and inputs).
    Atom(Expr),
    /// `!φ`
    Not(Box<Formula>, Span),
    /// `φ && ψ`
    And(Box<Formula>, Box<Formula>, Span),
    /// `φ || ψ`
    Or(Box<Formula>, Box<Formula>, Span),
    /// `φ => ψ`
    Implies(Box<Formula>, Box<Formula>, Span),
    /// `G φ`, `AG ψ`, ...
    Unary(TempOp, Box<Formula>, Span),
    /// `φ U ψ`, `φ R ψ`, `φ W ψ` (LTL).
    Binary(TempBin, Box<Formula>, Box<Formula>, Span),
    /// `A[φ U ψ]` / `E[φ U ψ]` (CTL).
    QuantUntil(Quant, Box<Formula>, Box<Formula>, Span),
}

impl Formula {
    /// Where it was written.
    pub fn span(&self) -> Span {
        match self {
            Formula::Atom(e) => e.span(),
            Formula::Not(_, s)
            | Formula::And(_, _, s)
            | Formula::Or(_, _, s)
            | Formula::Implies(_, _, s)
            | Formula::Unary(_, _, s)
            | Formula::Binary(_, _, _, s)
            | Formula::QuantUntil(_, _, _, s) => *s,
        }
    }
}
