//! Type checking of expressions: name resolution, operator typing, interval bounds, inlining of
//! function calls and folding of constants.

use crate::model::{Expr, ExprKind};
use crate::scope::{Globals, Scope};
use crate::types::{interval, Type};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast::{self, UnOp};

mod call;
mod resolve;
mod typing;

/// Collects diagnostics; can be muted while re-checking an inlined function body.
pub(crate) struct Sink {
    /// Diagnostics so far.
    pub diags: Vec<Diagnostic>,
    /// While > 0, diagnostics are dropped.
    pub muted: u32,
    /// The (code, span) pairs [`Sink::first`] has seen.
    pub once: std::collections::HashSet<(&'static str, Span)>,
}

impl Sink {
    /// Report a diagnostic unless muted.
    pub fn push(&mut self, d: Diagnostic) {
        if self.muted == 0 {
            self.diags.push(d);
        }
    }

    /// True the first time `(code, span)` is asked. A component flattened into many copies
    /// repeats its source spans, so an error in it would be found once per copy (and printed
    /// once, after deduplication); callers ask this before building a costly diagnostic, such
    /// as one with a "did you mean" search over thousands of flattened instance names.
    pub fn first(&mut self, code: &'static str, span: Span) -> bool {
        // While muted nothing is reported, so nothing is remembered either.
        self.muted > 0 || self.once.insert((code, span))
    }
}

/// Expression checker over the global declarations.
pub(crate) struct ExprChecker<'g> {
    /// File-level declarations.
    pub globals: &'g Globals,
    /// Where diagnostics go.
    pub sink: Sink,
    /// Next id for a [`ExprKind::Let`] binding.
    pub next_local: u32,
}

fn error_expr(span: Span) -> Expr {
    Expr {
        kind: ExprKind::Const(0),
        ty: Type::UNBOUNDED,
        span,
    }
}

pub(crate) fn type_name(g: &Globals, ty: Type) -> String {
    match ty {
        Type::Bool => "bool".into(),
        Type::Int { lo, hi } if (lo, hi) == Type::UNBOUNDED.bounds(|_| 0) => "int".into(),
        Type::Int { lo, hi } => format!("int[{lo}..{hi}]"),
        Type::Enum(e) => g
            .enums
            .get(e as usize)
            .map_or_else(|| "enum".into(), |d| d.name.clone()),
    }
}

impl<'g> ExprChecker<'g> {
    fn bounds(&self, ty: Type) -> (i64, i64) {
        ty.bounds(|e| {
            self.globals
                .enums
                .get(e as usize)
                .map_or(1, |d| d.variants.len())
        })
    }

    /// Check an expression that must have a boolean type.
    pub fn check_bool(&mut self, scope: &Scope, e: &ast::Expr) -> Expr {
        let x = self.check(scope, e);
        self.expect_bool(&x);
        x
    }

    fn expect_bool(&mut self, x: &Expr) {
        if x.ty != Type::Bool && !is_placeholder(x) {
            let tn = type_name(self.globals, x.ty);
            self.sink.push(
                Diagnostic::error("E0103", format!("expected a `bool`, found `{tn}`"), x.span)
                    .with_label("this is not a condition")
                    .with_hint("compare it with something, e.g. `x != 0`"),
            );
        }
    }

    fn expect_int(&mut self, x: &Expr, what: &str) {
        if !x.ty.is_int() {
            let tn = type_name(self.globals, x.ty);
            self.sink.push(
                Diagnostic::error(
                    "E0103",
                    format!("{what} needs an integer operand, found `{tn}`"),
                    x.span,
                )
                .with_label(format!("this is a `{tn}`")),
            );
        }
    }

    /// Evaluate an expression that must be constant (array sizes, bounds, delays, priorities).
    pub fn const_value(&mut self, scope: &Scope, e: &ast::Expr) -> Option<i64> {
        let x = self.check(scope, e);
        if is_placeholder(&x) {
            // An error inside was already reported; do not invent a value to check further.
            return None;
        }
        match x.kind {
            ExprKind::Const(v) => Some(v),
            _ => {
                self.sink.push(
                    Diagnostic::error("E0105", "expected a constant expression", x.span)
                        .with_label("this depends on variables or states")
                        .with_hint("use literals, constants and operators only"),
                );
                None
            }
        }
    }

    /// Check and type an expression.
    pub fn check(&mut self, scope: &Scope, e: &ast::Expr) -> Expr {
        let span = e.span();
        match e {
            ast::Expr::Int(v, _) => Expr {
                kind: ExprKind::Const(*v),
                ty: Type::Int { lo: *v, hi: *v },
                span,
            },
            ast::Expr::Bool(b, _) => Expr {
                kind: ExprKind::Const(*b as i64),
                ty: Type::Bool,
                span,
            },
            ast::Expr::Error(_) => error_expr(span),
            ast::Expr::Path(p) => self.check_path(scope, p),
            ast::Expr::In(p, _) => match self.resolve_state(scope, p) {
                Some(s) => Expr {
                    kind: ExprKind::In(s),
                    ty: Type::Bool,
                    span,
                },
                None => Expr {
                    kind: ExprKind::Const(0),
                    ty: Type::Bool,
                    span,
                },
            },
            ast::Expr::Unary(op, a, _) => {
                let a = self.check(scope, a);
                let ty = match op {
                    UnOp::Not => {
                        self.expect_bool(&a);
                        Type::Bool
                    }
                    UnOp::Neg => {
                        self.expect_int(&a, "`-`");
                        let (lo, hi) = self.bounds(a.ty);
                        let (lo, hi) = interval::sub((0, 0), (lo, hi));
                        Type::Int { lo, hi }
                    }
                    UnOp::BitNot => {
                        self.expect_int(&a, "`~`");
                        let (lo, hi) = self.bounds(a.ty);
                        Type::Int {
                            lo: lo
                                .checked_neg()
                                .unwrap_or(i64::MAX)
                                .saturating_sub(1)
                                .min(!hi),
                            hi: (!lo).max(!hi),
                        }
                    }
                };
                self.fold(Expr {
                    kind: ExprKind::Unary(*op, Box::new(a)),
                    ty,
                    span,
                })
            }
            ast::Expr::Binary(op, a, b, _) => {
                let a = self.check(scope, a);
                let b = self.check(scope, b);
                let ty = self.binary_type(*op, &a, &b, span);
                self.fold(Expr {
                    kind: ExprKind::Binary(*op, Box::new(a), Box::new(b)),
                    ty,
                    span,
                })
            }
            ast::Expr::If(c, a, b, _) => {
                let c = self.check_bool(scope, c);
                let a = self.check(scope, a);
                let b = self.check(scope, b);
                let ty = self.join(&a, &b, span);
                if let ExprKind::Const(v) = c.kind {
                    let mut r = if v != 0 { a } else { b };
                    r.ty = ty;
                    r.span = span;
                    return r;
                }
                Expr {
                    kind: ExprKind::If(Box::new(c), Box::new(a), Box::new(b)),
                    ty,
                    span,
                }
            }
            ast::Expr::Call { func, args, .. } => self.check_call(scope, func, args, span),
        }
    }
}

/// True for the placeholder produced after an error (so one mistake gives one diagnostic).
pub(crate) fn is_placeholder(x: &Expr) -> bool {
    matches!(x.kind, ExprKind::Const(0)) && x.ty == Type::UNBOUNDED
}
