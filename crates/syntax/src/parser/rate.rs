//! `rate instance.input = 0.01;` in a system: how often random simulation makes a free input
//! true.
//!
//! `rate` is contextual (an identifier followed by a path), so models may keep variables called
//! `rate`. The language has no fractional numbers elsewhere; the probability is a decimal
//! literal read here from adjacent tokens (`0` `.` `01`), kept as written for the formatter and
//! converted by the checker.

use super::{PResult, Parser};
use crate::ast::Rate;
use crate::lexer::Tok;
use statecheck_base::{Diagnostic, Span};

impl Parser<'_> {
    /// True at `rate IDENT` (a rate declaration rather than some other use of the word).
    pub(super) fn at_rate_decl(&self) -> bool {
        self.at(Tok::Ident)
            && self.text(self.tok().span) == "rate"
            && self.nth(1).kind == Tok::Ident
    }

    /// `'rate' path '=' DECIMAL ';'` where `DECIMAL` is `INT` or `INT '.' INT` without spaces.
    pub(super) fn rate(&mut self) -> PResult<Rate> {
        let start = self.bump().span;
        let target = self.path()?;
        self.expect(Tok::Assign, "after the input of a `rate`")?;
        let first = self.tok();
        let Tok::Int(_) = first.kind else {
            let found = self.describe(first);
            self.report(
                Diagnostic::error(
                    "E0022",
                    format!("expected a probability such as `0.01` after `=`, found {found}"),
                    first.span,
                )
                .with_label("expected a decimal number from 0 to 1")
                .with_hint("write the rate as a decimal literal, e.g. `rate env.fault = 0.01;`"),
            );
            return Err(super::Failed);
        };
        self.bump();
        let mut end = first.span.end;
        let (dot, frac) = (self.nth(0), self.nth(1));
        if dot.kind == Tok::Dot && dot.span.start == end {
            if matches!(frac.kind, Tok::Int(_)) && frac.span.start == dot.span.end {
                self.bump();
                self.bump();
                end = frac.span.end;
            } else {
                self.report(
                    Diagnostic::error(
                        "E0022",
                        "expected digits right after the decimal point",
                        Span::new(dot.span.end as usize, dot.span.end as usize),
                    )
                    .with_label("expected digits")
                    .with_hint("write the rate as a decimal literal, e.g. `0.01`"),
                );
                self.bump();
                return Err(super::Failed);
            }
        }
        let value_span = Span::new(first.span.start as usize, end as usize);
        let value = self.text(value_span).to_string();
        self.expect_semi("after a `rate`");
        Ok(Rate {
            target,
            value,
            value_span,
            span: self.span_from(start),
        })
    }
}
