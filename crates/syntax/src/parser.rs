//! The recursive-descent parser: tokens → [`ast::File`] plus diagnostics.
//!
//! The parser never stops at the first error and never panics. Each `{ … }` list (chart,
//! state, block, system, choice, …) parses its elements in a loop; when an element is
//! malformed the error is reported and the parser skips to a synchronisation point (a `;` or
//! `}` at the current depth, or a keyword that starts an element or item). Missing expressions
//! become [`ast::Expr::Error`] placeholders. Nesting deeper than [`MAX_DEPTH`] levels is
//! reported instead of overflowing the stack.
//!
//! # Diagnostic codes
//!
//! Codes are a contract: a code keeps its meaning forever and is never reused.
//!
//! | Code  | Meaning |
//! |-------|---------|
//! | E0001 | unexpected character (lexer) |
//! | E0002 | unterminated block comment (lexer) |
//! | E0003 | integer literal out of range for `i64` (lexer) |
//! | E0004 | malformed integer literal: invalid digit or no digits after `0x`/`0b` (lexer) |
//! | E0010 | unexpected token / expected X, found Y |
//! | E0011 | missing `;` |
//! | E0012 | unclosed delimiter (`{`, `(` or `[` never closed) |
//! | E0013 | nesting too deep (more than [`MAX_DEPTH`] levels, or an expression tree taller than [`MAX_HEIGHT`]) |
//! | E0014 | empty transition: `on` without trigger, guard or target |
//! | E0015 | `=` used where a comparison is expected (did you mean `==`?) |
//! | E0016 | chained comparison such as `a < b < c` (comparisons are non-associative) |
//! | E0017 | declaration in the wrong place (variable or property inside a state, element of a chart inside a system, …) |
//! | E0018 | malformed duration: missing or unknown time unit, or an amount that is not a primary expression |
//! | E0019 | `if` expression used as an operand without parentheses |
//! | E0020 | missing `return` in a function body |
//! | E0021 | malformed `import`: no quoted path, or a bad name list |
//! | E0022 | malformed `rate`: the probability is not a decimal literal such as `0.01` |
//! | E0030 | malformed CTL until: `A[`/`E[` without `U` |

mod body;
mod components;
mod expr;
mod hybrid;
mod imports;
mod items;
mod rate;
mod temporal;

use crate::ast;
use crate::lexer::{Kw, Tok, Token};
use statecheck_base::{Diagnostic, Span};

/// Maximum nesting of expressions, blocks and states before E0013 is reported.
pub const MAX_DEPTH: u32 = 256;

/// Maximum height of an expression tree (long operator chains) before E0013 is reported.
pub const MAX_HEIGHT: u32 = 512;

/// Parse a token list (ending with [`Tok::Eof`]) lexed from byte `base` of `src` on into a
/// file, appending diagnostics to `diags`.
pub fn parse_tokens_from(
    src: &str,
    base: usize,
    toks: Vec<Token>,
    diags: &mut Vec<Diagnostic>,
) -> ast::File {
    let mut p = Parser {
        src,
        base,
        toks,
        pos: 0,
        diags: Vec::new(),
        depth: 0,
        last_error_at: None,
    };
    let file = p.file();
    diags.append(&mut p.diags);
    file
}

/// Marker: an error was reported and the caller must resynchronise.
pub(crate) struct Failed;

/// Result of parsing a piece that may fail.
pub(crate) type PResult<T> = Result<T, Failed>;

pub(crate) struct Parser<'a> {
    src: &'a str,
    /// Where this file's text starts in `src` (several files share one offset space).
    base: usize,
    toks: Vec<Token>,
    pos: usize,
    diags: Vec<Diagnostic>,
    depth: u32,
    /// Token index of the last reported error; a second error there is a cascade and dropped.
    last_error_at: Option<usize>,
}

/// Keywords that start a top-level item; recovery always stops at them.
fn is_item_kw(t: Tok) -> bool {
    matches!(
        t,
        Tok::Kw(
            Kw::Const
                | Kw::Enum
                | Kw::Fn
                | Kw::Chart
                | Kw::System
                | Kw::Tick
                | Kw::Plant
                | Kw::Requirement
        )
    )
}

/// Keywords that start a chart element (declaration, property or state-body element).
fn is_chart_elem_kw(t: Tok) -> bool {
    matches!(
        t,
        Tok::Kw(
            Kw::Input
                | Kw::Output
                | Kw::Local
                | Kw::Invariant
                | Kw::Reachable
                | Kw::Respond
                | Kw::Parallel
                | Kw::Entry
                | Kw::During
                | Kw::Exit
                | Kw::Initial
                | Kw::History
                | Kw::State
                | Kw::Region
                | Kw::Junction
                | Kw::On
                | Kw::Controllable
                | Kw::Uncontrollable
                | Kw::Marked
        )
    )
}

/// Keywords that start a system element.
fn is_system_kw(t: Tok) -> bool {
    matches!(
        t,
        Tok::Kw(Kw::Instance | Kw::Connect | Kw::Order | Kw::Assume | Kw::Observer)
    )
}

/// Keywords at which error recovery stops (at the current depth).
fn is_sync_kw(t: Tok) -> bool {
    is_item_kw(t)
        || is_chart_elem_kw(t)
        || is_system_kw(t)
        || matches!(t, Tok::Kw(Kw::Raise | Kw::Let | Kw::Return))
}

impl<'a> Parser<'a> {
    // ----- token access -------------------------------------------------------------------

    fn tok(&self) -> Token {
        self.nth(0)
    }

    fn nth(&self, n: usize) -> Token {
        let i = self.pos.saturating_add(n);
        match self.toks.get(i).or_else(|| self.toks.last()) {
            Some(t) => *t,
            None => Token {
                kind: Tok::Eof,
                span: Span::new(self.src.len(), self.src.len()),
            },
        }
    }

    fn peek(&self) -> Tok {
        self.tok().kind
    }

    fn at(&self, t: Tok) -> bool {
        self.peek() == t
    }

    fn at_kw(&self, k: Kw) -> bool {
        self.peek() == Tok::Kw(k)
    }

    fn bump(&mut self) -> Token {
        let t = self.tok();
        if t.kind != Tok::Eof {
            self.pos += 1;
        }
        t
    }

    fn eat(&mut self, t: Tok) -> Option<Span> {
        if self.at(t) {
            Some(self.bump().span)
        } else {
            None
        }
    }

    fn eat_kw(&mut self, k: Kw) -> Option<Span> {
        self.eat(Tok::Kw(k))
    }

    /// End of the previously consumed token (the file's start at the start).
    fn prev_end(&self) -> usize {
        match self.pos.checked_sub(1).and_then(|i| self.toks.get(i)) {
            Some(t) => t.span.end as usize,
            None => self.base,
        }
    }

    /// An empty span right after the previous token: where something is missing.
    fn missing_span(&self) -> Span {
        let e = self.prev_end();
        Span::new(e, e)
    }

    /// The span from `start` to the end of the previous token.
    fn span_from(&self, start: Span) -> Span {
        Span::new(
            start.start as usize,
            self.prev_end().max(start.end as usize),
        )
    }

    fn text(&self, span: Span) -> &'a str {
        self.src.get(span.range()).unwrap_or("")
    }

    fn ident_of(&self, t: Token) -> ast::Ident {
        ast::Ident {
            name: self.text(t.span).to_string(),
            span: t.span,
        }
    }

    /// Describes a token for "found …" messages.
    fn describe(&self, t: Token) -> String {
        match t.kind {
            Tok::Ident => format!("identifier `{}`", self.text(t.span)),
            Tok::Int(_) => format!("integer `{}`", self.text(t.span)),
            Tok::Str => format!("string {}", self.text(t.span)),
            Tok::Eof => "end of file".to_string(),
            Tok::Kw(k) => format!("keyword `{}`", k.as_str()),
            other => format!("`{}`", other.spelling().unwrap_or("?")),
        }
    }

    // ----- diagnostics --------------------------------------------------------------------

    /// Report `d` unless an error was already reported at this token (a cascade).
    fn report(&mut self, d: Diagnostic) {
        if self.last_error_at == Some(self.pos) {
            return;
        }
        self.last_error_at = Some(self.pos);
        self.diags.push(d);
    }

    /// True if the current token terminates something, so an error is a *missing* item.
    fn at_terminator(&self) -> bool {
        matches!(
            self.peek(),
            Tok::Semi | Tok::RBrace | Tok::RParen | Tok::RBracket | Tok::Eof
        )
    }

    /// Where to point for "expected X": an empty span after the previous token if X seems
    /// missing, else the offending token.
    fn expected_span(&self) -> Span {
        if self.at_terminator() {
            self.missing_span()
        } else {
            self.tok().span
        }
    }

    /// Build (but do not report) an E0010 "expected {what}, found …" diagnostic.
    fn expected_diag(&self, what: &str) -> Diagnostic {
        let found = self.describe(self.tok());
        Diagnostic::error(
            "E0010",
            format!("expected {what}, found {found}"),
            self.expected_span(),
        )
        .with_label(format!("expected {what}"))
    }

    /// Report E0010 "expected {what}, found …" and return [`Failed`].
    fn expected(&mut self, what: &str) -> Failed {
        let d = self.expected_diag(what);
        self.report(d);
        Failed
    }

    /// Consume token `t` or report "expected `t` {ctx}".
    fn expect(&mut self, t: Tok, ctx: &str) -> PResult<Span> {
        if let Some(s) = self.eat(t) {
            return Ok(s);
        }
        let spelled = t.spelling().unwrap_or("?");
        let found = self.describe(self.tok());
        let d = Diagnostic::error(
            "E0010",
            format!("expected `{spelled}` {ctx}, found {found}"),
            self.missing_span(),
        )
        .with_label(format!("expected `{spelled}`"));
        self.report(d);
        Err(Failed)
    }

    /// Consume an identifier or report "expected {what}".
    fn expect_ident(&mut self, what: &str) -> PResult<ast::Ident> {
        if self.at(Tok::Ident) {
            let t = self.bump();
            return Ok(self.ident_of(t));
        }
        let mut d = self.expected_diag(what);
        if let Tok::Kw(k) = self.peek() {
            d = d.with_hint(format!(
                "`{}` is a keyword and cannot be used as a name",
                k.as_str()
            ));
        }
        self.report(d);
        Err(Failed)
    }

    /// Consume the `;` ending a declaration or statement. When it is missing, report E0011
    /// and, unless the next token plausibly starts something new, skip to a sync point.
    /// The declaration itself is kept either way.
    fn expect_semi(&mut self, ctx: &str) {
        if self.eat(Tok::Semi).is_some() {
            return;
        }
        let found = self.describe(self.tok());
        let d = Diagnostic::error(
            "E0011",
            format!("expected `;` {ctx}, found {found}"),
            self.missing_span(),
        )
        .with_label("expected `;`");
        self.report(d);
        let t = self.peek();
        if !(t == Tok::RBrace || t == Tok::Eof || is_sync_kw(t)) {
            self.recover();
        }
    }

    /// Report that the `{` at `open` (of `what`) was never closed.
    fn unclosed(&mut self, open: Span, what: &str) {
        let found = self.describe(self.tok());
        let d = Diagnostic::error(
            "E0012",
            format!("expected `}}` to close {what}, found {found}"),
            self.missing_span(),
        )
        .with_label("expected `}`")
        .with_secondary(open, "unclosed `{` opened here");
        self.report(d);
    }

    // ----- recovery -----------------------------------------------------------------------

    /// Skip tokens to a synchronisation point: past a `;` at depth 0, past a `{ … }` group
    /// (and a `;` right after it) unless `->` or `priority` follows it, or before a `}` at
    /// depth 0, a sync keyword at depth 0, an item keyword at any depth, or the end of file.
    fn recover(&mut self) {
        let mut depth = 0u32;
        loop {
            let t = self.peek();
            match t {
                Tok::Eof => return,
                Tok::Semi if depth == 0 => {
                    self.bump();
                    return;
                }
                Tok::RBrace if depth == 0 => return,
                Tok::RBrace if depth == 1 => {
                    // A `{ … }` group just closed: most elements end here (states, blocks).
                    // Unless the element visibly goes on (`-> target`, `priority`), stop.
                    self.bump();
                    depth = 0;
                    match self.peek() {
                        Tok::Semi => {
                            self.bump();
                            return;
                        }
                        Tok::Arrow | Tok::Kw(Kw::Priority) => continue,
                        _ => return,
                    }
                }
                Tok::LBrace | Tok::LParen | Tok::LBracket => depth += 1,
                Tok::RBrace | Tok::RParen | Tok::RBracket => depth = depth.saturating_sub(1),
                _ if is_item_kw(t) => return,
                _ if depth == 0 && is_sync_kw(t) => return,
                _ => {}
            }
            self.bump();
        }
    }

    /// Skip a balanced group starting at the current opening delimiter (or one token).
    fn skip_group(&mut self) {
        let mut depth = 0u32;
        loop {
            match self.peek() {
                Tok::Eof => return,
                Tok::LBrace | Tok::LParen | Tok::LBracket => depth += 1,
                Tok::RBrace | Tok::RParen | Tok::RBracket => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        self.bump();
                        return;
                    }
                }
                _ if depth == 0 => {
                    self.bump();
                    return;
                }
                _ => {}
            }
            self.bump();
        }
    }

    /// Skip the rest of an over-deep construct: up to (not including) a `;` or an unmatched
    /// closing delimiter at depth 0.
    fn skip_rest(&mut self) {
        let mut depth = 0u32;
        loop {
            match self.peek() {
                Tok::Eof => return,
                Tok::Semi if depth == 0 => return,
                Tok::LBrace | Tok::LParen | Tok::LBracket => depth += 1,
                Tok::RBrace | Tok::RParen | Tok::RBracket => {
                    if depth == 0 {
                        return;
                    }
                    depth -= 1;
                }
                _ => {}
            }
            self.bump();
        }
    }

    /// Enter one nesting level; false (after reporting E0013) when too deep.
    fn enter(&mut self) -> bool {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            self.depth -= 1;
            self.too_deep(format!("more than {MAX_DEPTH} levels of nesting"));
            return false;
        }
        true
    }

    fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }

    fn too_deep(&mut self, label: String) {
        let d = Diagnostic::error("E0013", "nesting too deep", self.tok().span)
            .with_label(label)
            .with_hint("split the expression or hierarchy into smaller named parts");
        self.report(d);
    }

    /// Report an unexpected token (E0010 "expected {what}"), skip it, and resynchronise.
    fn unexpected(&mut self, what: &str, hint: Option<String>) {
        let mut d = self.expected_diag(what);
        if let Some(h) = hint {
            d = d.with_hint(h);
        }
        self.report(d);
        self.skip_group();
        self.recover();
    }
}
