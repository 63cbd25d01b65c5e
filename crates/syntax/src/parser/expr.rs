//! Expressions, paths, types and durations.
//!
//! Expression functions never fail: a missing operand is reported and replaced by
//! [`Expr::Error`]. Internally they return the expression with its tree height, so that
//! very long operator chains are cut off (E0013) before dropping or printing the tree could
//! overflow the stack.

use super::{PResult, Parser, MAX_HEIGHT};
use crate::ast::{
    BinOp, Duration, Expr, Ident, Index, Path, PathSegment, TimeUnit, TypeExpr, UnOp,
};
use crate::lexer::{Kw, Tok};
use statecheck_base::{Diagnostic, Span};

/// An expression with the height of its tree.
type Ex = (Expr, u32);

/// Binding levels, loosest first.
const LVL_OR: u8 = 0;
const LVL_AND: u8 = 1;
const LVL_CMP: u8 = 2;
const LVL_BITOR: u8 = 3;
const LVL_BITXOR: u8 = 4;
const LVL_BITAND: u8 = 5;
const LVL_SHIFT: u8 = 6;
const LVL_ADD: u8 = 7;
const LVL_MUL: u8 = 8;

/// The binary operator a token stands for, with its level. `=` is accepted as a (reported)
/// misspelling of `==`.
fn binop(t: Tok) -> Option<(BinOp, u8)> {
    Some(match t {
        Tok::OrOr => (BinOp::Or, LVL_OR),
        Tok::AndAnd => (BinOp::And, LVL_AND),
        Tok::EqEq | Tok::Assign => (BinOp::Eq, LVL_CMP),
        Tok::NotEq => (BinOp::Ne, LVL_CMP),
        Tok::Lt => (BinOp::Lt, LVL_CMP),
        Tok::Le => (BinOp::Le, LVL_CMP),
        Tok::Gt => (BinOp::Gt, LVL_CMP),
        Tok::Ge => (BinOp::Ge, LVL_CMP),
        Tok::Pipe => (BinOp::BitOr, LVL_BITOR),
        Tok::Caret => (BinOp::BitXor, LVL_BITXOR),
        Tok::Amp => (BinOp::BitAnd, LVL_BITAND),
        Tok::Shl => (BinOp::Shl, LVL_SHIFT),
        Tok::Shr => (BinOp::Shr, LVL_SHIFT),
        Tok::Plus => (BinOp::Add, LVL_ADD),
        Tok::Minus => (BinOp::Sub, LVL_ADD),
        Tok::Star => (BinOp::Mul, LVL_MUL),
        Tok::Slash => (BinOp::Div, LVL_MUL),
        Tok::Percent => (BinOp::Rem, LVL_MUL),
        _ => return None,
    })
}

fn is_cmp(t: Tok) -> bool {
    matches!(
        t,
        Tok::EqEq | Tok::NotEq | Tok::Lt | Tok::Le | Tok::Gt | Tok::Ge
    )
}

/// Parse a contextual time unit.
pub(super) fn time_unit(text: &str) -> Option<TimeUnit> {
    match text {
        "ms" => Some(TimeUnit::Ms),
        "s" => Some(TimeUnit::S),
        "min" => Some(TimeUnit::Min),
        _ => None,
    }
}

impl Parser<'_> {
    /// `expr = 'if' expr 'then' expr 'else' expr | or`
    pub(super) fn expr(&mut self) -> Expr {
        self.expr_h().0
    }

    fn expr_h(&mut self) -> Ex {
        let start = self.tok().span;
        if !self.enter() {
            self.skip_rest();
            return (Expr::Error(self.span_from(start)), 0);
        }
        let r = if self.at_kw(Kw::If) {
            self.if_expr()
        } else {
            self.binary(LVL_OR)
        };
        self.leave();
        r
    }

    fn if_expr(&mut self) -> Ex {
        let start = self.bump().span;
        let (c, hc) = self.expr_h();
        if self.eat_kw(Kw::Then).is_none() {
            self.if_expr_missing(
                "`then` after the condition of an `if` expression",
                "an `if` expression is written `if c then a else b`",
            );
        }
        let (a, ha) = self.expr_h();
        if self.eat_kw(Kw::Else).is_none() {
            self.if_expr_missing(
                "`else` in an `if` expression",
                "an `if` expression must have both branches: `if c then a else b`",
            );
        }
        let (b, hb) = self.expr_h();
        let span = self.span_from(start);
        let h = hc.max(ha).max(hb) + 1;
        (Expr::If(Box::new(c), Box::new(a), Box::new(b), span), h)
    }

    #[inline(never)]
    fn if_expr_missing(&mut self, what: &str, hint: &str) {
        let d = self.expected_diag(what).with_hint(hint);
        self.report(d);
    }

    /// An atom of a temporal formula: an expression whose operators bind at least as tightly
    /// as comparisons (`&&`, `||` and `=>` belong to the formula).
    pub(super) fn atom_expr(&mut self) -> Expr {
        let start = self.tok().span;
        if !self.enter() {
            self.skip_rest();
            return Expr::Error(self.span_from(start));
        }
        let (e, _) = self.binary(LVL_CMP);
        self.leave();
        e
    }

    fn binary(&mut self, min: u8) -> Ex {
        let lhs = self.unary();
        self.binary_rest(lhs, min)
    }

    /// Continue a binary expression whose first operand is `lhs`, with operators binding at
    /// least as tightly as `min`.
    fn binary_rest(&mut self, lhs: Ex, min: u8) -> Ex {
        let (mut lhs, mut h) = lhs;
        loop {
            let t = self.peek();
            let Some((op, lvl)) = binop(t) else { break };
            if lvl < min {
                break;
            }
            let op_span = self.tok().span;
            if t == Tok::Assign {
                self.assign_in_expr(op_span);
            }
            self.bump();
            let (rhs, rh) = self.binary(lvl + 1);
            let span = lhs.span().to(rhs.span());
            h = h.max(rh) + 1;
            lhs = Expr::Binary(op, Box::new(lhs), Box::new(rhs), span);
            if h > MAX_HEIGHT {
                return self.too_tall(span);
            }
            if lvl == LVL_CMP && is_cmp(self.peek()) {
                self.chained_comparison(op_span);
            }
        }
        (lhs, h)
    }

    #[inline(never)]
    fn assign_in_expr(&mut self, op_span: Span) {
        let d = Diagnostic::error("E0015", "`=` is not a comparison", op_span)
            .with_label("assignment operator used in an expression")
            .with_hint("did you mean `==`?");
        self.report(d);
    }

    #[inline(never)]
    fn chained_comparison(&mut self, first: Span) {
        let d = Diagnostic::error(
            "E0016",
            "comparison operators cannot be chained",
            self.tok().span,
        )
        .with_label("second comparison")
        .with_secondary(first, "first comparison")
        .with_hint("split the comparison with `&&`, e.g. `a < b && b < c`");
        self.report(d);
    }

    #[inline(never)]
    fn too_tall(&mut self, span: Span) -> Ex {
        self.too_deep(format!(
            "this expression is more than {MAX_HEIGHT} operators deep"
        ));
        self.skip_rest();
        (Expr::Error(span), 0)
    }

    fn unary(&mut self) -> Ex {
        let op = match self.peek() {
            Tok::Minus => UnOp::Neg,
            Tok::Bang => UnOp::Not,
            Tok::Tilde => UnOp::BitNot,
            _ => return self.primary(),
        };
        let start = self.tok().span;
        if !self.enter() {
            self.skip_rest();
            return (Expr::Error(self.span_from(start)), 0);
        }
        self.bump();
        let (e, h) = self.unary();
        self.leave();
        let span = start.to(e.span());
        (Expr::Unary(op, Box::new(e), span), h + 1)
    }

    fn primary(&mut self) -> Ex {
        let t = self.tok();
        match t.kind {
            Tok::Int(v) => {
                self.bump();
                (Expr::Int(v, t.span), 1)
            }
            Tok::Kw(Kw::True) => {
                self.bump();
                (Expr::Bool(true, t.span), 1)
            }
            Tok::Kw(Kw::False) => {
                self.bump();
                (Expr::Bool(false, t.span), 1)
            }
            Tok::LParen => {
                self.bump();
                let (e, h) = self.expr_h();
                self.close(Tok::RParen, t.span, "`(`");
                (e, h)
            }
            Tok::Kw(Kw::In) => self.in_expr(),
            // `int(x)` converts an enum or a bool to its integer value.
            Tok::Ident | Tok::Kw(Kw::Int) if self.nth(1).kind == Tok::LParen => self.call(),
            Tok::Ident => match self.path_h() {
                Ok((p, h)) => (Expr::Path(p), h),
                Err(_) => (Expr::Error(self.span_from(t.span)), 0),
            },
            Tok::Kw(Kw::If) => {
                self.if_operand(t.span);
                self.if_expr()
            }
            _ => self.no_expression(),
        }
    }

    #[inline(never)]
    fn if_operand(&mut self, span: Span) {
        let d = Diagnostic::error("E0019", "`if` expression used as an operand", span)
            .with_label("needs parentheses here")
            .with_hint("wrap it in parentheses: `(if c then a else b)`");
        self.report(d);
    }

    #[inline(never)]
    fn no_expression(&mut self) -> Ex {
        let mut d = self.expected_diag("expression");
        if self.at(Tok::Plus) {
            d = d.with_hint("there is no unary `+`; remove it");
        }
        self.report(d);
        (Expr::Error(self.expected_span()), 0)
    }

    /// Consume the closing delimiter `close` matching `open`, or report E0012.
    pub(super) fn close(&mut self, close: Tok, open: Span, what: &str) -> bool {
        if self.eat(close).is_some() {
            return true;
        }
        let spelled = close.spelling().unwrap_or("?");
        let found = self.describe(self.tok());
        let d = Diagnostic::error(
            "E0012",
            format!("expected `{spelled}` to close {what}, found {found}"),
            self.missing_span(),
        )
        .with_label(format!("expected `{spelled}`"))
        .with_secondary(open, format!("{what} opened here"));
        self.report(d);
        false
    }

    fn in_expr(&mut self) -> Ex {
        let start = self.bump().span;
        let Ok(open) = self.expect(Tok::LParen, "after `in`") else {
            return (Expr::Error(self.span_from(start)), 0);
        };
        let (path, h) = match self.path_h() {
            Ok(p) => p,
            Err(_) => {
                self.skip_rest();
                self.eat(Tok::RParen);
                return (Expr::Error(self.span_from(start)), 0);
            }
        };
        self.close(Tok::RParen, open, "`in(`");
        (Expr::In(path, self.span_from(start)), h + 1)
    }

    fn call(&mut self) -> Ex {
        let name = self.bump();
        let func = self.ident_of(name);
        let open = self.bump().span;
        let mut args = Vec::new();
        let mut h = 0;
        if self.eat(Tok::RParen).is_none() {
            loop {
                let (e, eh) = self.expr_h();
                h = h.max(eh);
                args.push(e);
                if self.eat(Tok::Comma).is_some() {
                    continue;
                }
                let what = format!("the argument list of `{}`", func.name);
                if !self.close(Tok::RParen, open, &what) {
                    self.skip_rest();
                    self.eat(Tok::RParen);
                }
                break;
            }
        }
        let span = self.span_from(name.span);
        (Expr::Call { func, args, span }, h + 1)
    }

    /// `path = segment { '.' segment }`, `segment = IDENT [ '[' ( expr | '*' ) ']' ]`
    pub(super) fn path(&mut self) -> PResult<Path> {
        Ok(self.path_h()?.0)
    }

    /// A path with the height of its tallest index expression plus one.
    fn path_h(&mut self) -> PResult<(Path, u32)> {
        let first = self.expect_ident("a name")?;
        let start = first.span;
        let (seg, mut h) = self.segment_rest(first);
        let mut segments = vec![seg];
        while self.eat(Tok::Dot).is_some() {
            let name = self.expect_ident("a name after `.`")?;
            let (seg, sh) = self.segment_rest(name);
            h = h.max(sh);
            segments.push(seg);
        }
        let path = Path {
            segments,
            span: self.span_from(start),
        };
        Ok((path, h + 1))
    }

    fn segment_rest(&mut self, name: Ident) -> (PathSegment, u32) {
        let Some(open) = self.eat(Tok::LBracket) else {
            return (PathSegment { name, index: None }, 0);
        };
        let (index, h) = if let Some(star) = self.eat(Tok::Star) {
            (Index::All(star), 0)
        } else {
            let (e, h) = self.expr_h();
            (Index::At(Box::new(e)), h)
        };
        self.close(Tok::RBracket, open, "the index `[`");
        let seg = PathSegment {
            name,
            index: Some(index),
        };
        (seg, h)
    }

    /// `type = 'bool' | 'int' | 'int' '[' expr '..' expr ']' | IDENT`
    pub(super) fn ty(&mut self) -> PResult<TypeExpr> {
        let t = self.tok();
        match t.kind {
            Tok::Kw(Kw::Bool) => {
                self.bump();
                Ok(TypeExpr::Bool(t.span))
            }
            Tok::Kw(Kw::Int) => {
                self.bump();
                let Some(open) = self.eat(Tok::LBracket) else {
                    return Ok(TypeExpr::Int(t.span));
                };
                let lo = self.expr();
                if self.eat(Tok::DotDot).is_none() {
                    let d = self
                        .expected_diag("`..` between the bounds of a range type")
                        .with_hint("a bounded integer type is written `int[lo..hi]`");
                    self.report(d);
                    return Err(super::Failed);
                }
                let hi = self.expr();
                if !self.close(Tok::RBracket, open, "the range type's `[`") {
                    return Err(super::Failed);
                }
                Ok(TypeExpr::Range {
                    lo: Box::new(lo),
                    hi: Box::new(hi),
                    span: self.span_from(t.span),
                })
            }
            Tok::Ident => {
                self.bump();
                Ok(TypeExpr::Named(self.ident_of(t)))
            }
            _ => {
                let d = self.expected_diag("a type (`bool`, `int`, `int[lo..hi]` or an enum name)");
                self.report(d);
                Err(super::Failed)
            }
        }
    }

    /// The time unit at the current token, if it is one.
    fn at_time_unit(&self) -> Option<TimeUnit> {
        let t = self.tok();
        if t.kind == Tok::Ident {
            time_unit(self.text(t.span))
        } else {
            None
        }
    }

    /// Build a duration from `amount` and the unit at the current token (consumed).
    fn finish_duration(&mut self, amount: Expr, unit: TimeUnit, primary: bool) -> Duration {
        self.bump();
        if !primary {
            let d = Diagnostic::error(
                "E0018",
                "the amount of a duration must be a number, a name or a parenthesised expression",
                amount.span(),
            )
            .with_label("not a primary expression")
            .with_hint("put the amount in parentheses, e.g. `(2 * N) s`");
            self.report(d);
        }
        let span = self.span_from(amount.span());
        Duration {
            amount: Box::new(amount),
            unit,
            span,
        }
    }

    /// Report a missing or unknown time unit after a duration amount (E0018).
    fn bad_unit(&mut self) {
        let t = self.tok();
        let d = if t.kind == Tok::Ident {
            Diagnostic::error(
                "E0018",
                format!("unknown time unit `{}`", self.text(t.span)),
                t.span,
            )
            .with_label("not a time unit")
        } else {
            let found = self.describe(t);
            Diagnostic::error(
                "E0018",
                format!("expected a time unit after the duration amount, found {found}"),
                self.missing_span(),
            )
            .with_label("expected `ms`, `s` or `min`")
        };
        self.report(d.with_hint("time units are `ms`, `s` and `min`, e.g. `100 ms`"));
        if t.kind == Tok::Ident {
            self.bump();
        }
    }

    /// `duration = primary ( 'ms' | 's' | 'min' )`, as in `tick 100 ms;`.
    pub(super) fn duration(&mut self) -> Duration {
        let primary = !matches!(self.peek(), Tok::Minus | Tok::Bang | Tok::Tilde);
        let (amount, _) = self.unary();
        match self.at_time_unit() {
            Some(u) => self.finish_duration(amount, u, primary),
            None => {
                self.bad_unit();
                let span = amount.span();
                Duration {
                    amount: Box::new(amount),
                    unit: TimeUnit::Ms,
                    span,
                }
            }
        }
    }

    /// The inside of `after( … )`: a tick count expression or a duration.
    pub(super) fn delay(&mut self) -> crate::ast::Delay {
        use crate::ast::Delay;
        let simple = matches!(
            self.peek(),
            Tok::Int(_) | Tok::Ident | Tok::LParen | Tok::Kw(Kw::True | Kw::False | Kw::In)
        );
        if !simple {
            let e = self.expr();
            if let Some(u) = self.at_time_unit() {
                return Delay::Time(self.finish_duration(e, u, false));
            }
            return Delay::Ticks(e);
        }
        let first = self.primary();
        if let Some(u) = self.at_time_unit() {
            return Delay::Time(self.finish_duration(first.0, u, true));
        }
        let (e, _) = self.binary_rest(first, LVL_OR);
        if let Some(u) = self.at_time_unit() {
            return Delay::Time(self.finish_duration(e, u, false));
        }
        if self.at(Tok::Ident) {
            self.bad_unit();
        }
        Delay::Ticks(e)
    }
}
