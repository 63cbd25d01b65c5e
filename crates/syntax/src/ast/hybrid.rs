//! The hybrid-plant elements of a chart (`continuous`, `grid`, `sensor`, `der`;
//! `docs/hybrid.md`), as written.

use super::{Duration, Expr, Ident};
use statecheck_base::Span;

/// An element of a hybrid plant (`docs/hybrid.md`).
#[derive(Clone, Debug, PartialEq)]
pub enum HybridElem {
    /// `continuous NAME: [lo .. hi] [= init];`
    Continuous {
        /// The variable.
        name: Ident,
        /// Lower end of the range.
        lo: Expr,
        /// Upper end of the range.
        hi: Expr,
        /// Initial value (the lower end when absent).
        init: Option<Expr>,
        /// The whole element.
        span: Span,
    },
    /// `grid NAME N;` or `grid NAME coarse;`
    Grid {
        /// The variable.
        var: Ident,
        /// The number of equal cells; `None` for `coarse`.
        cells: Option<Expr>,
        /// The whole element.
        span: Span,
    },
    /// `sensor OUT = VAR in [lo .. hi];`
    Sensor {
        /// The boolean variable kept equal to the range predicate.
        output: Ident,
        /// The continuous variable.
        var: Ident,
        /// Lower bound of the range.
        lo: Expr,
        /// Upper bound of the range.
        hi: Expr,
        /// The whole element.
        span: Span,
    },
    /// `der(VAR) = rate;` in a state.
    Der {
        /// The continuous variable.
        var: Ident,
        /// Its speed while the state is active.
        rate: SpeedExpr,
        /// The whole element.
        span: Span,
    },
}

impl HybridElem {
    /// The span of the whole element.
    pub fn span(&self) -> Span {
        match self {
            HybridElem::Continuous { span, .. }
            | HybridElem::Grid { span, .. }
            | HybridElem::Sensor { span, .. }
            | HybridElem::Der { span, .. } => *span,
        }
    }
}

/// The right-hand side of `der(x) = …`.
#[derive(Clone, Debug, PartialEq)]
pub enum SpeedExpr {
    /// A constant speed.
    Constant(Speed),
    /// `profile(r1 for d1, …, r)`: each speed for its duration from the state's entry, then
    /// the last speed.
    Profile(Vec<(Speed, Duration)>, Speed),
}

/// A speed: `[-] number [/ number]`, in units per second.
#[derive(Clone, Debug, PartialEq)]
pub struct Speed {
    /// A leading `-`.
    pub negative: bool,
    /// The numerator.
    pub num: SpeedNumber,
    /// The denominator after `/`.
    pub den: Option<SpeedNumber>,
    /// The whole speed.
    pub span: Span,
}

/// A number in a speed.
#[derive(Clone, Debug, PartialEq)]
pub enum SpeedNumber {
    /// A decimal literal as written (`0.8`, `2`).
    Decimal(String, Span),
    /// An integer constant or chart parameter (after parameter expansion, a literal).
    Expr(Expr),
}
