//! Function calls: built-ins, conversions, and inlining of user functions with their arguments
//! bound once (`Let`).

use super::{error_expr, type_name, ExprChecker};
use crate::model::{Builtin, Expr, ExprKind};
use crate::ops;
use crate::scope::Scope;
use crate::types::{interval, Type};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;

impl<'g> ExprChecker<'g> {
    pub(super) fn check_call(
        &mut self,
        scope: &Scope,
        func: &ast::Ident,
        args: &[ast::Expr],
        span: Span,
    ) -> Expr {
        let checked: Vec<Expr> = args.iter().map(|a| self.check(scope, a)).collect();
        if let Some(x) = self.conversion(func, &checked, span) {
            return x;
        }
        let builtin = match func.name.as_str() {
            "min" => Some((Builtin::Min, 2)),
            "max" => Some((Builtin::Max, 2)),
            "abs" => Some((Builtin::Abs, 1)),
            _ => None,
        };
        if let Some((b, arity)) = builtin {
            if checked.len() != arity {
                self.sink.push(
                    Diagnostic::error(
                        "E0112",
                        format!(
                            "`{}` takes {arity} argument{}, found {}",
                            func.name,
                            if arity == 1 { "" } else { "s" },
                            checked.len()
                        ),
                        span,
                    )
                    .with_label("wrong number of arguments"),
                );
                return error_expr(span);
            }
            for a in &checked {
                self.expect_int(a, &format!("`{}`", func.name));
            }
            let x = self.bounds(checked[0].ty);
            let (lo, hi) = match b {
                Builtin::Abs => interval::abs(x),
                Builtin::Min => {
                    let y = self.bounds(checked[1].ty);
                    (x.0.min(y.0), x.1.min(y.1))
                }
                Builtin::Max => {
                    let y = self.bounds(checked[1].ty);
                    (x.0.max(y.0), x.1.max(y.1))
                }
            };
            let consts: Option<Vec<i64>> = checked
                .iter()
                .map(|a| match a.kind {
                    ExprKind::Const(v) => Some(v),
                    _ => None,
                })
                .collect();
            if let Some(c) = consts {
                let v = match b {
                    Builtin::Abs => ops::abs(c[0]),
                    Builtin::Min => Ok(c[0].min(c[1])),
                    Builtin::Max => Ok(c[0].max(c[1])),
                };
                match v {
                    Ok(v) => {
                        return Expr {
                            kind: ExprKind::Const(v),
                            ty: Type::Int { lo: v, hi: v },
                            span,
                        }
                    }
                    Err(err) => {
                        self.sink.push(
                            Diagnostic::error(
                                "E0104",
                                format!("this constant expression fails: {}", err.describe()),
                                span,
                            )
                            .with_label(err.describe()),
                        );
                        return error_expr(span);
                    }
                }
            }
            return Expr {
                kind: ExprKind::Builtin(b, checked),
                ty: Type::Int { lo, hi },
                span,
            };
        }
        let Some((index, decl)) = self.globals.fns.get(&func.name) else {
            self.sink.push(
                Diagnostic::error(
                    "E0101",
                    format!("unknown function `{}`", func.name),
                    func.span,
                )
                .with_label("not declared")
                .with_hint("the built-in functions are `min`, `max` and `abs`"),
            );
            return error_expr(span);
        };
        if *index >= scope.fn_limit {
            // A call inside the called function's own declaration is recursion.
            let recursive = decl.span.start <= func.span.start && func.span.end <= decl.span.end;
            let d = if recursive {
                Diagnostic::error("E0113", format!("`{}` calls itself", func.name), func.span)
                    .with_label("recursive call")
                    .with_hint("functions are inlined, so they cannot be recursive")
            } else {
                Diagnostic::error("E0113", format!("`{}` is called before its declaration", func.name), func.span)
                    .with_label("called here")
                    .with_secondary(decl.name.span, "declared here")
                    .with_hint(format!(
                        "move `fn {}` above this use: a function or constant may only call functions declared before it (so there is no recursion)",
                        func.name
                    ))
            };
            self.sink.push(d);
            return error_expr(span);
        }
        if checked.len() != decl.params.len() {
            self.sink.push(
                Diagnostic::error(
                    "E0112",
                    format!(
                        "`{}` takes {} arguments, found {}",
                        func.name,
                        decl.params.len(),
                        checked.len()
                    ),
                    span,
                )
                .with_secondary(decl.name.span, "declared here"),
            );
            return error_expr(span);
        }
        // Inline: bind each parameter to its (range-checked) argument, then re-check the body.
        let mut inner = Scope {
            chart: None,
            instances: None,
            charts: scope.charts,
            locals: Vec::new(),
            fn_limit: *index,
        };
        // Arguments that are not trivial are evaluated once, into a `Let`-bound local.
        let mut bindings: Vec<(u32, Expr)> = Vec::new();
        for (p, a) in decl.params.iter().zip(checked) {
            let pty = self.resolve_type(&p.ty);
            let a = self.coerce(
                a,
                pty,
                &format!("argument `{}` of `{}`", p.name.name, func.name),
            );
            let bound = self.bind(a, &mut bindings);
            inner.locals.push((p.name.name.clone(), bound));
        }
        self.sink.muted += 1;
        for (name, e) in &decl.lets {
            let v = self.check(&inner, e);
            let bound = self.bind(v, &mut bindings);
            inner.locals.push((name.name.clone(), bound));
        }
        let body = self.check(&inner, &decl.body);
        self.sink.muted -= 1;
        let rty = self.resolve_type(&decl.ret);
        let mut r = self.coerce(body, rty, &format!("the result of `{}`", func.name));
        for (id, value) in bindings.into_iter().rev() {
            let ty = r.ty;
            r = Expr {
                kind: ExprKind::Let(id, Box::new(value), Box::new(r)),
                ty,
                span,
            };
        }
        r.span = span;
        r
    }

    /// `int(x)` (an enum's index or a bool as 0/1) and `Enum(n)` (the literal with index `n`,
    /// checked at run time); `None` when `func` names neither.
    pub(super) fn conversion(
        &mut self,
        func: &ast::Ident,
        args: &[Expr],
        span: Span,
    ) -> Option<Expr> {
        let target = if func.name == "int" {
            None
        } else {
            Some(*self.globals.enum_ids.get(&func.name)?)
        };
        if args.len() != 1 {
            self.sink.push(
                Diagnostic::error(
                    "E0112",
                    format!(
                        "`{}(...)` converts one value, found {} arguments",
                        func.name,
                        args.len()
                    ),
                    span,
                )
                .with_label("wrong number of arguments"),
            );
            return Some(error_expr(span));
        }
        let arg = args[0].clone();
        match target {
            None => {
                if arg.ty.is_int() {
                    return Some(Expr { span, ..arg });
                }
                let (lo, hi) = self.bounds(arg.ty);
                Some(Expr {
                    kind: arg.kind,
                    ty: Type::Int { lo, hi },
                    span,
                })
            }
            Some(e) => {
                if !arg.ty.is_int() {
                    let tn = type_name(self.globals, arg.ty);
                    self.sink.push(
                        Diagnostic::error(
                            "E0103",
                            format!("`{}(...)` converts an integer, found `{tn}`", func.name),
                            arg.span,
                        )
                        .with_label(format!("this is a `{tn}`")),
                    );
                    return Some(error_expr(span));
                }
                let n = self.globals.enums[e as usize].variants.len() as i64;
                let what = format!("conversion to `{}` (0..{})", func.name, n - 1);
                let (lo, hi) = self.bounds(arg.ty);
                let kind = if let ExprKind::Const(v) = arg.kind {
                    if !(0..n).contains(&v) {
                        self.sink.push(
                            Diagnostic::error(
                                "E0104",
                                format!(
                                    "{v} is not a literal index of `{}` (0..{})",
                                    func.name,
                                    n - 1
                                ),
                                arg.span,
                            )
                            .with_label("out of range"),
                        );
                    }
                    ExprKind::Const(v.clamp(0, n - 1))
                } else if lo >= 0 && hi < n {
                    arg.kind
                } else {
                    ExprKind::Check(Box::new(arg), 0, n - 1, what)
                };
                Some(Expr {
                    kind,
                    ty: Type::Enum(e),
                    span,
                })
            }
        }
    }

    /// The expression to substitute for a parameter: `x` itself when it is cheap to repeat,
    /// else a local bound to it (recorded in `bindings`).
    pub(super) fn bind(&mut self, x: Expr, bindings: &mut Vec<(u32, Expr)>) -> Expr {
        match x.kind {
            ExprKind::Const(_) | ExprKind::Var(_) | ExprKind::Local(_) => x,
            _ => {
                let id = self.next_local;
                self.next_local += 1;
                let local = Expr {
                    kind: ExprKind::Local(id),
                    ty: x.ty,
                    span: x.span,
                };
                bindings.push((id, x));
                local
            }
        }
    }
}
