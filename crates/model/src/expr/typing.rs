//! Operator typing, joins of branch types, coercion to an expected type, written types, and
//! folding of constant operations (with the arithmetic of `crate::ops`).

use super::{error_expr, is_placeholder, type_name, ExprChecker};
use crate::model::{Expr, ExprKind};
use crate::ops;
use crate::scope::Scope;
use crate::types::{interval, Type};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast::{self, BinOp};

impl<'g> ExprChecker<'g> {
    pub(super) fn join(&mut self, a: &Expr, b: &Expr, span: Span) -> Type {
        match (a.ty, b.ty) {
            (Type::Int { .. }, Type::Int { .. }) => {
                let (lo, hi) = interval::union(self.bounds(a.ty), self.bounds(b.ty));
                Type::Int { lo, hi }
            }
            (x, y) if x == y => x,
            _ if is_placeholder(a) => b.ty,
            _ if is_placeholder(b) => a.ty,
            (x, y) => {
                let (xn, yn) = (type_name(self.globals, x), type_name(self.globals, y));
                self.sink.push(
                    Diagnostic::error(
                        "E0103",
                        format!("the branches have different types: `{xn}` and `{yn}`"),
                        span,
                    )
                    .with_secondary(a.span, format!("this is a `{xn}`"))
                    .with_secondary(b.span, format!("this is a `{yn}`")),
                );
                x
            }
        }
    }

    pub(super) fn binary_type(&mut self, op: BinOp, a: &Expr, b: &Expr, span: Span) -> Type {
        use BinOp::*;
        match op {
            Or | And => {
                self.expect_bool(a);
                self.expect_bool(b);
                Type::Bool
            }
            Eq | Ne => {
                if !a.ty.compatible(b.ty) && !is_placeholder(a) && !is_placeholder(b) {
                    let (an, bn) = (type_name(self.globals, a.ty), type_name(self.globals, b.ty));
                    let mut d = Diagnostic::error(
                        "E0103",
                        format!("cannot compare `{an}` with `{bn}`"),
                        span,
                    )
                    .with_label("different types")
                    .with_secondary(a.span, format!("this is a `{an}`"))
                    .with_secondary(b.span, format!("this is a `{bn}`"));
                    if let Some(Type::Enum(e)) = [a.ty, b.ty]
                        .into_iter()
                        .find(|t| matches!(t, Type::Enum(_)))
                    {
                        if let Some(def) = self.globals.enums.get(e as usize) {
                            d = d.with_hint(format!(
                                "enums are not numbers; compare with a literal of `{}`: {}",
                                def.name,
                                def.variants.join(", ")
                            ));
                        }
                    }
                    self.sink.push(d);
                }
                Type::Bool
            }
            Lt | Le | Gt | Ge => {
                self.expect_int(a, "an ordering comparison");
                self.expect_int(b, "an ordering comparison");
                Type::Bool
            }
            _ => {
                let name = match op {
                    BitOr => "`|`",
                    BitXor => "`^`",
                    BitAnd => "`&`",
                    Shl => "`<<`",
                    Shr => "`>>`",
                    Add => "`+`",
                    Sub => "`-`",
                    Mul => "`*`",
                    Div => "`/`",
                    _ => "`%`",
                };
                self.expect_int(a, name);
                self.expect_int(b, name);
                let (x, y) = (self.bounds(a.ty), self.bounds(b.ty));
                let (lo, hi) = match op {
                    Add => interval::add(x, y),
                    Sub => interval::sub(x, y),
                    Mul => interval::mul(x, y),
                    Div => interval::div(x, y),
                    Rem => interval::rem(x, y),
                    Shl => interval::shl(x, y),
                    Shr => interval::shr(x, y),
                    _ => interval::bits(x, y),
                };
                Type::Int { lo, hi }
            }
        }
    }

    /// Fold an operation on constants, reporting constant errors (division by zero, ...).
    pub(super) fn fold(&mut self, x: Expr) -> Expr {
        let v = match &x.kind {
            ExprKind::Unary(op, a) => match a.kind {
                ExprKind::Const(va) => Some(ops::unary(*op, va)),
                _ => None,
            },
            ExprKind::Binary(op, a, b) => match (&a.kind, &b.kind) {
                (ExprKind::Const(va), ExprKind::Const(vb)) => Some(ops::binary(*op, *va, *vb)),
                _ => None,
            },
            _ => None,
        };
        match v {
            Some(Ok(v)) => Expr {
                kind: ExprKind::Const(v),
                ty: if x.ty == Type::Bool {
                    Type::Bool
                } else if x.ty.is_int() {
                    Type::Int { lo: v, hi: v }
                } else {
                    x.ty
                },
                span: x.span,
            },
            Some(Err(err)) => {
                self.sink.push(
                    Diagnostic::error(
                        "E0104",
                        format!("this constant expression fails: {}", err.describe()),
                        x.span,
                    )
                    .with_label(err.describe()),
                );
                error_expr(x.span)
            }
            None => x,
        }
    }

    /// Make `x` usable where `ty` is expected: check compatibility, and wrap integers whose
    /// bounds may exceed `ty`'s in a run-time range check.
    pub fn coerce(&mut self, x: Expr, ty: Type, what: &str) -> Expr {
        if is_placeholder(&x) {
            return Expr { ty, ..x };
        }
        if !x.ty.compatible(ty) {
            let (xn, tn) = (type_name(self.globals, x.ty), type_name(self.globals, ty));
            self.sink.push(
                Diagnostic::error(
                    "E0103",
                    format!("mismatched types in {what}: expected `{tn}`, found `{xn}`"),
                    x.span,
                )
                .with_label(format!("this is a `{xn}`")),
            );
            return Expr { ty, ..x };
        }
        if let (Type::Int { lo, hi }, Type::Int { lo: tl, hi: th }) = (x.ty, ty) {
            if let ExprKind::Const(v) = x.kind {
                if v < tl || v > th {
                    self.sink.push(
                        Diagnostic::error(
                            "E0104",
                            format!("{what} is out of range: {v} is not within {tl}..{th}"),
                            x.span,
                        )
                        .with_label(format!("must be within {tl}..{th}")),
                    );
                }
                return x;
            }
            if lo < tl || hi > th {
                let span = x.span;
                return Expr {
                    kind: ExprKind::Check(Box::new(x), tl, th, what.to_string()),
                    ty: Type::Int {
                        lo: lo.max(tl),
                        hi: hi.min(th),
                    },
                    span,
                };
            }
        }
        x
    }

    /// Resolve a written type; reports unknown enums and bad bounds.
    pub fn resolve_type(&mut self, t: &ast::TypeExpr) -> Type {
        match t {
            ast::TypeExpr::Bool(_) => Type::Bool,
            ast::TypeExpr::Int(_) => Type::UNBOUNDED,
            ast::TypeExpr::Range { lo, hi, span } => {
                let empty = Scope::constants(usize::MAX);
                let l = self.const_value(&empty, lo);
                let h = self.const_value(&empty, hi);
                match (l, h) {
                    (Some(l), Some(h)) if l <= h => Type::Int { lo: l, hi: h },
                    (Some(l), Some(h)) => {
                        self.sink.push(
                            Diagnostic::error("E0114", format!("empty range {l}..{h}"), *span)
                                .with_label("the lower bound exceeds the upper bound")
                                .with_hint(format!("write `int[{h}..{l}]`")),
                        );
                        Type::Int { lo: h, hi: l }
                    }
                    _ => Type::UNBOUNDED,
                }
            }
            ast::TypeExpr::Named(id) => match self.globals.enum_ids.get(&id.name) {
                Some(e) => Type::Enum(*e),
                None => {
                    let hint = match crate::suggest::closest(
                        &id.name,
                        self.globals.enum_ids.keys().map(String::as_str),
                    ) {
                        Some(e) => format!("did you mean `{e}`?"),
                        None => "types are `bool`, `int[lo..hi]` or a declared enum".to_string(),
                    };
                    self.sink.push(
                        Diagnostic::error("E0101", format!("unknown type `{}`", id.name), id.span)
                            .with_label("not a declared enum")
                            .with_hint(hint),
                    );
                    Type::UNBOUNDED
                }
            },
        }
    }
}
