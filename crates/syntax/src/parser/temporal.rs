//! Temporal properties: `ltl`, `ctl`, `nonblocking` and `fair` declarations and their
//! formulas.
//!
//! The declaration words are contextual (an identifier followed by a name and `:`), so models
//! may keep variables called `fair` or `ltl`. Inside a formula the words `G F X U R W`,
//! `AG AF AX EG EF EX` and `A[`/`E[` are operators; an atom is a state expression at
//! comparison level, so `&&`, `||`, `!` and `=>` between atoms belong to the formula.
//!
//! Precedence, loosest first: `=>` (right-associative), `||`, `&&`, `U R W`
//! (right-associative), then the prefix operators `! G F X AG ...`.

use super::{PResult, Parser};
use crate::ast::{Expr, Formula, Property, PropertyKind, Quant, TempBin, TempOp};
use crate::lexer::Tok;
use statecheck_base::Diagnostic;

/// The declaration words this module parses.
pub(super) const WORDS: [&str; 4] = ["ltl", "ctl", "nonblocking", "fair"];

impl Parser<'_> {
    /// True at `WORD NAME :` for one of [`WORDS`].
    pub(super) fn at_temporal_decl(&self) -> bool {
        self.at(Tok::Ident)
            && WORDS.contains(&self.text(self.tok().span))
            && self.nth(1).kind == Tok::Ident
            && self.nth(2).kind == Tok::Colon
    }

    /// `('ltl'|'ctl') NAME ':' formula ';'`, `'nonblocking' NAME ':' expr ';'`,
    /// `'fair' NAME ':' expr ['=>' expr] ';'`.
    pub(super) fn temporal_property(&mut self) -> PResult<Property> {
        let t = self.bump();
        let word = self.text(t.span).to_string();
        let name = self.expect_ident(&format!("a property name after `{word}`"))?;
        self.expect(Tok::Colon, "after the property name")?;
        let kind = match word.as_str() {
            "ltl" => PropertyKind::Ltl {
                formula: self.formula(),
            },
            "ctl" => PropertyKind::Ctl {
                formula: self.formula(),
            },
            "nonblocking" => PropertyKind::Nonblocking { expr: self.expr() },
            _ => {
                let first = self.expr();
                if self.eat(Tok::FatArrow).is_some() {
                    PropertyKind::Fair {
                        trigger: Some(first),
                        expr: self.expr(),
                    }
                } else {
                    PropertyKind::Fair {
                        trigger: None,
                        expr: first,
                    }
                }
            }
        };
        self.expect_semi("after the property");
        Ok(Property {
            name,
            kind,
            span: self.span_from(t.span),
        })
    }

    /// A whole formula (`=>` level).
    pub(super) fn formula(&mut self) -> Formula {
        let start = self.tok().span;
        if !self.enter() {
            self.skip_rest();
            return Formula::Atom(Expr::Error(self.span_from(start)));
        }
        let lhs = self.f_or();
        let f = if self.eat(Tok::FatArrow).is_some() {
            let rhs = self.formula();
            let span = lhs.span().to(rhs.span());
            Formula::Implies(Box::new(lhs), Box::new(rhs), span)
        } else {
            lhs
        };
        self.leave();
        f
    }

    fn f_or(&mut self) -> Formula {
        let mut lhs = self.f_and();
        while self.eat(Tok::OrOr).is_some() {
            let rhs = self.f_and();
            let span = lhs.span().to(rhs.span());
            lhs = Formula::Or(Box::new(lhs), Box::new(rhs), span);
        }
        lhs
    }

    /// The left operand of `A[.. U ..]`: `||` and `&&` of prefix formulas (no infix `U`,
    /// which belongs to the quantifier).
    fn f_or_operand(&mut self) -> Formula {
        let mut lhs = self.f_and_operand();
        while self.eat(Tok::OrOr).is_some() {
            let rhs = self.f_and_operand();
            let span = lhs.span().to(rhs.span());
            lhs = Formula::Or(Box::new(lhs), Box::new(rhs), span);
        }
        lhs
    }

    fn f_and_operand(&mut self) -> Formula {
        let mut lhs = self.f_unary();
        while self.eat(Tok::AndAnd).is_some() {
            let rhs = self.f_unary();
            let span = lhs.span().to(rhs.span());
            lhs = Formula::And(Box::new(lhs), Box::new(rhs), span);
        }
        lhs
    }

    fn f_and(&mut self) -> Formula {
        let mut lhs = self.f_until();
        while self.eat(Tok::AndAnd).is_some() {
            let rhs = self.f_until();
            let span = lhs.span().to(rhs.span());
            lhs = Formula::And(Box::new(lhs), Box::new(rhs), span);
        }
        lhs
    }

    fn f_until(&mut self) -> Formula {
        let lhs = self.f_unary();
        let Some(op) = self.at_binary_word() else {
            return lhs;
        };
        self.bump();
        if !self.enter() {
            self.skip_rest();
            return lhs;
        }
        let rhs = self.f_until();
        self.leave();
        let span = lhs.span().to(rhs.span());
        Formula::Binary(op, Box::new(lhs), Box::new(rhs), span)
    }

    /// `U`, `R` or `W` in infix position.
    fn at_binary_word(&self) -> Option<TempBin> {
        if !self.at(Tok::Ident) || self.nth(1).kind == Tok::Dot {
            return None;
        }
        TempBin::from_word(self.text(self.tok().span))
    }

    /// A prefix operator word at token `n` (not a path such as `F.x`).
    fn prefix_word_at(&self, n: usize) -> Option<TempOp> {
        let t = self.nth(n);
        if t.kind != Tok::Ident || matches!(self.nth(n + 1).kind, Tok::Dot | Tok::LBracket) {
            return None;
        }
        TempOp::from_word(self.text(t.span))
    }

    /// `A[` or `E[` at token `n`.
    fn quant_at(&self, n: usize) -> Option<Quant> {
        let t = self.nth(n);
        if t.kind != Tok::Ident || self.nth(n + 1).kind != Tok::LBracket {
            return None;
        }
        match self.text(t.span) {
            "A" => Some(Quant::All),
            "E" => Some(Quant::Exists),
            _ => None,
        }
    }

    /// True when the tokens from `n` start a formula that is not a plain expression: a
    /// temporal operator, or `(`/`!` leading to one. Looks ahead without consuming.
    fn starts_temporal(&self, mut n: usize) -> bool {
        loop {
            if self.prefix_word_at(n).is_some() || self.quant_at(n).is_some() {
                return true;
            }
            match self.nth(n).kind {
                Tok::Bang => n += 1,
                Tok::LParen => return self.group_is_temporal(n),
                _ => return false,
            }
        }
    }

    /// True when the parenthesised group opening at token `n` contains a temporal operator
    /// or `=>` at any depth.
    fn group_is_temporal(&self, n: usize) -> bool {
        let mut depth = 0u32;
        let mut i = n;
        loop {
            let t = self.nth(i);
            match t.kind {
                Tok::Eof => return false,
                Tok::LParen | Tok::LBracket => depth += 1,
                Tok::RParen | Tok::RBracket => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        return false;
                    }
                }
                Tok::Semi | Tok::LBrace | Tok::RBrace => return false,
                Tok::FatArrow => return true,
                Tok::Ident => {
                    let w = self.text(t.span);
                    let path = self.nth(i + 1).kind == Tok::Dot;
                    if !path && (TempOp::from_word(w).is_some() || TempBin::from_word(w).is_some())
                    {
                        return true;
                    }
                    if self.quant_at(i).is_some() {
                        return true;
                    }
                }
                _ => {}
            }
            i += 1;
        }
    }

    fn f_unary(&mut self) -> Formula {
        let start = self.tok().span;
        if !self.enter() {
            self.skip_rest();
            return Formula::Atom(Expr::Error(self.span_from(start)));
        }
        let f = if let Some(op) = self.prefix_word_at(0) {
            self.bump();
            let arg = self.f_unary();
            let span = start.to(arg.span());
            Formula::Unary(op, Box::new(arg), span)
        } else if let Some(q) = self.quant_at(0) {
            self.quant_until(q)
        } else if self.at(Tok::Bang) && self.starts_temporal(1) {
            self.bump();
            let arg = self.f_unary();
            let span = start.to(arg.span());
            Formula::Not(Box::new(arg), span)
        } else if self.at(Tok::LParen) && self.group_is_temporal(0) {
            let open = self.bump().span;
            let f = self.formula();
            self.close(Tok::RParen, open, "`(`");
            f
        } else {
            Formula::Atom(self.atom_expr())
        };
        self.leave();
        f
    }

    /// `A[φ U ψ]` / `E[φ U ψ]`.
    fn quant_until(&mut self, q: Quant) -> Formula {
        let start = self.bump().span;
        let open = self.bump().span;
        let lhs = self.f_or_operand();
        if self.at(Tok::Ident) && self.text(self.tok().span) == "U" {
            self.bump();
        } else {
            let d = Diagnostic::error(
                "E0030",
                "expected `U` inside `A[...]` or `E[...]`",
                self.tok().span,
            )
            .with_label("here")
            .with_hint("CTL's until is written `A[p U q]` or `E[p U q]`");
            self.report(d);
        }
        let rhs = self.f_or();
        self.close(Tok::RBracket, open, "`[`");
        let span = self.span_from(start);
        Formula::QuantUntil(q, Box::new(lhs), Box::new(rhs), span)
    }
}
