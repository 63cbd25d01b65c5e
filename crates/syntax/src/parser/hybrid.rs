//! Continuous plant variables (`docs/hybrid.md`): `continuous`, `grid` and `sensor` at chart
//! level, `der(x) = …` in states.
//!
//! The words are contextual (each is recognised only when followed by the token its element
//! needs), so models may keep variables called `grid` or `sensor`. Speeds are exact decimals
//! read from adjacent tokens (`0` `.` `8`), like a system's `rate`.

use super::{Failed, PResult, Parser};
use crate::ast::{HybridElem, Speed, SpeedExpr, SpeedNumber};
use crate::lexer::{Kw, Tok};
use statecheck_base::{Diagnostic, Span};

impl Parser<'_> {
    /// True at the start of a hybrid element: `continuous IDENT :`, `grid IDENT`,
    /// `sensor IDENT =` or `der (`.
    pub(super) fn at_hybrid_elem(&self) -> bool {
        if !self.at(Tok::Ident) {
            return false;
        }
        let (a, b) = (self.nth(1).kind, self.nth(2).kind);
        match self.text(self.tok().span) {
            "continuous" => a == Tok::Ident && b == Tok::Colon,
            "grid" => a == Tok::Ident && b != Tok::Colon && b != Tok::Assign,
            "sensor" => a == Tok::Ident && b == Tok::Assign,
            "der" => a == Tok::LParen,
            _ => false,
        }
    }

    /// One hybrid element (the current token satisfies [`Parser::at_hybrid_elem`]).
    pub(super) fn hybrid_elem(&mut self) -> PResult<HybridElem> {
        let kw = self.bump();
        let start = kw.span;
        let elem = match self.text(kw.span) {
            "continuous" => {
                let name = self.expect_ident("a variable name after `continuous`")?;
                self.expect(Tok::Colon, "after the continuous variable's name")?;
                let (lo, hi) = self.bracket_range("the range of a continuous variable")?;
                let init = if self.eat(Tok::Assign).is_some() {
                    Some(self.expr())
                } else {
                    None
                };
                self.expect_semi("after a `continuous` declaration");
                HybridElem::Continuous {
                    name,
                    lo,
                    hi,
                    init,
                    span: self.span_from(start),
                }
            }
            "grid" => {
                let var = self.expect_ident("a continuous variable after `grid`")?;
                let cells = if self.at(Tok::Ident) && self.text(self.tok().span) == "coarse" {
                    self.bump();
                    None
                } else {
                    Some(self.expr())
                };
                self.expect_semi("after a `grid`");
                HybridElem::Grid {
                    var,
                    cells,
                    span: self.span_from(start),
                }
            }
            "sensor" => {
                let output = self.expect_ident("an output name after `sensor`")?;
                self.expect(Tok::Assign, "after the sensor's output")?;
                let var = self.expect_ident("a continuous variable")?;
                if self.eat_kw(Kw::In).is_none() {
                    let d = self
                        .expected_diag("`in [lo .. hi]` after the variable")
                        .with_hint(
                            "a sensor is a range predicate: `sensor at_end = pos in [95 .. 100];`",
                        );
                    self.report(d);
                    return Err(Failed);
                }
                let (lo, hi) = self.bracket_range("a sensor's range")?;
                self.expect_semi("after a `sensor`");
                HybridElem::Sensor {
                    output,
                    var,
                    lo,
                    hi,
                    span: self.span_from(start),
                }
            }
            _ => {
                self.expect(Tok::LParen, "after `der`")?;
                let var = self.expect_ident("a continuous variable in `der( … )`")?;
                self.expect(Tok::RParen, "after the variable of `der`")?;
                self.expect(Tok::Assign, "after `der( … )`")?;
                let rate_start = self.tok().span.start as usize;
                let rate = if self.at(Tok::LParen) {
                    None
                } else {
                    Some(self.speed_expr()?)
                };
                let rate = match rate {
                    Some(r) if self.at(Tok::Semi) || self.at(Tok::RBrace) || self.at(Tok::Eof) => r,
                    _ => {
                        // `der(x) = k * (target - x)` and the like: not a constant speed.
                        let d = Diagnostic::error(
                        "E0183",
                        format!(
                            "the speed of `{}` must be a constant or a profile of constants, \
                             not an expression",
                            var.name
                        ),
                        Span::new(rate_start, self.tok().span.end as usize),
                    )
                    .with_label("not a constant speed")
                    .with_hint(
                        "only piecewise-constant speeds have exact clock readings: write \
                         `der(x) = 2;`, `der(x) = SPEED / 10;` or `der(x) = profile(4 for 5 s, 1);` \
                         (docs/hybrid.md, \"Why every reading is exact\")",
                    );
                        self.report(d);
                        return Err(Failed);
                    }
                };
                self.expect_semi("after `der( … ) = …`");
                HybridElem::Der {
                    var,
                    rate,
                    span: self.span_from(start),
                }
            }
        };
        Ok(elem)
    }

    /// `'[' expr '..' expr ']'`
    fn bracket_range(&mut self, what: &str) -> PResult<(crate::ast::Expr, crate::ast::Expr)> {
        self.expect(Tok::LBracket, &format!("to open {what}"))?;
        let lo = self.expr();
        self.expect(Tok::DotDot, &format!("between the bounds of {what}"))?;
        let hi = self.expr();
        self.expect(Tok::RBracket, &format!("to close {what}"))?;
        Ok((lo, hi))
    }

    /// `speed | 'profile' '(' speed 'for' duration { ',' speed 'for' duration } ',' speed ')'`
    fn speed_expr(&mut self) -> PResult<SpeedExpr> {
        if !(self.at(Tok::Ident)
            && self.text(self.tok().span) == "profile"
            && self.nth(1).kind == Tok::LParen)
        {
            return Ok(SpeedExpr::Constant(self.speed()?));
        }
        self.bump();
        self.bump();
        let mut segments = Vec::new();
        loop {
            let s = self.speed()?;
            if self.at(Tok::Ident) && self.text(self.tok().span) == "for" {
                self.bump();
                let d = self.duration();
                segments.push((s, d));
                self.expect(
                    Tok::Comma,
                    "after a profile segment (the last speed has no `for`)",
                )?;
            } else {
                self.expect(Tok::RParen, "after the last speed of a profile")?;
                return Ok(SpeedExpr::Profile(segments, s));
            }
        }
    }

    /// `[ '-' ] number [ '/' number ]`
    fn speed(&mut self) -> PResult<Speed> {
        let start = self.tok().span;
        let negative = self.eat(Tok::Minus).is_some();
        let num = self.speed_number()?;
        let den = if self.eat(Tok::Slash).is_some() {
            Some(self.speed_number()?)
        } else {
            None
        };
        Ok(Speed {
            negative,
            num,
            den,
            span: self.span_from(start),
        })
    }

    /// `DECIMAL | IDENT`
    fn speed_number(&mut self) -> PResult<SpeedNumber> {
        let first = self.tok();
        match first.kind {
            Tok::Int(_) => {
                self.bump();
                let mut end = first.span.end;
                let (dot, frac) = (self.nth(0), self.nth(1));
                if dot.kind == Tok::Dot
                    && dot.span.start == end
                    && matches!(frac.kind, Tok::Int(_))
                    && frac.span.start == dot.span.end
                {
                    self.bump();
                    self.bump();
                    end = frac.span.end;
                }
                let span = Span::new(first.span.start as usize, end as usize);
                Ok(SpeedNumber::Decimal(self.text(span).to_string(), span))
            }
            Tok::Ident => {
                let t = self.bump();
                Ok(SpeedNumber::Expr(crate::ast::Expr::Path(
                    crate::ast::Path {
                        segments: vec![crate::ast::PathSegment {
                            name: self.ident_of(t),
                            index: None,
                        }],
                        span: t.span,
                    },
                )))
            }
            _ => {
                let d = Diagnostic::error(
                    "E0023",
                    format!(
                        "expected a speed such as `2`, `0.8` or `1/2`, found {}",
                        self.describe(first)
                    ),
                    self.expected_span(),
                )
                .with_label("expected a speed")
                .with_hint("speeds are units per second: a decimal, a constant's name, or `a/b`");
                self.report(d);
                Err(Failed)
            }
        }
    }
}
