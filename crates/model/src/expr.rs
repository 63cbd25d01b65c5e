//! Type checking of expressions: name resolution, operator typing, interval bounds, inlining of
//! function calls and folding of constants.

use crate::model::{Builtin, Expr, ExprKind, StateRef, VarRef};
use crate::ops;
use crate::scope::{Globals, Scope};
use crate::types::{interval, Type};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast::{self, BinOp, UnOp};

/// Collects diagnostics; can be muted while re-checking an inlined function body.
pub(crate) struct Sink {
    /// Diagnostics so far.
    pub diags: Vec<Diagnostic>,
    /// While > 0, diagnostics are dropped.
    pub muted: u32,
}

impl Sink {
    /// Report a diagnostic unless muted.
    pub fn push(&mut self, d: Diagnostic) {
        if self.muted == 0 {
            self.diags.push(d);
        }
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

    fn join(&mut self, a: &Expr, b: &Expr, span: Span) -> Type {
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

    fn binary_type(&mut self, op: BinOp, a: &Expr, b: &Expr, span: Span) -> Type {
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
    fn fold(&mut self, x: Expr) -> Expr {
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

    fn check_call(
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
                Builtin::Abs => {
                    if x.0 >= 0 {
                        x
                    } else if x.1 <= 0 {
                        (-x.1, -x.0)
                    } else {
                        (0, (-x.0).max(x.1))
                    }
                }
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
                    Builtin::Abs => c[0].checked_abs(),
                    Builtin::Min => Some(c[0].min(c[1])),
                    Builtin::Max => Some(c[0].max(c[1])),
                };
                if let Some(v) = v {
                    return Expr {
                        kind: ExprKind::Const(v),
                        ty: Type::Int { lo: v, hi: v },
                        span,
                    };
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
    fn conversion(&mut self, func: &ast::Ident, args: &[Expr], span: Span) -> Option<Expr> {
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
    fn bind(&mut self, x: Expr, bindings: &mut Vec<(u32, Expr)>) -> Expr {
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
                let empty = Scope {
                    chart: None,
                    instances: None,
                    charts: &[],
                    locals: Vec::new(),
                    fn_limit: usize::MAX,
                };
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

    fn check_path(&mut self, scope: &Scope, p: &ast::Path) -> Expr {
        let span = p.span;
        let segs = &p.segments;
        let first = &segs[0];
        if segs.len() == 1 && first.index.is_none() {
            let name = first.name.name.as_str();
            if let Some((_, e)) = scope.locals.iter().rev().find(|(n, _)| n == name) {
                let mut e = e.clone();
                e.span = span;
                return e;
            }
            if let Some(v) = scope.own_var(name) {
                let chart = scope.chart.expect("own_var implies a chart");
                return Expr {
                    kind: ExprKind::Var(VarRef {
                        instance: None,
                        var: v,
                    }),
                    ty: chart.vars[v as usize].ty,
                    span,
                };
            }
            if let Some((ty, v, _)) = self.globals.consts.get(name) {
                return Expr {
                    kind: ExprKind::Const(*v),
                    ty: if ty.is_int() {
                        Type::Int { lo: *v, hi: *v }
                    } else {
                        *ty
                    },
                    span,
                };
            }
            if let Some(owners) = self.globals.literal_owners.get(name) {
                if owners.len() == 1 {
                    let e = owners[0];
                    let idx = self.globals.enums[e as usize]
                        .variants
                        .iter()
                        .position(|v| v == name)
                        .unwrap_or(0);
                    return Expr {
                        kind: ExprKind::Const(idx as i64),
                        ty: Type::Enum(e),
                        span,
                    };
                }
                let names: Vec<String> = owners
                    .iter()
                    .map(|e| format!("{}.{name}", self.globals.enums[*e as usize].name))
                    .collect();
                self.sink.push(
                    Diagnostic::error("E0101", format!("ambiguous enum literal `{name}`"), span)
                        .with_label("several enums declare it")
                        .with_hint(format!("qualify it: {}", names.join(" or "))),
                );
                return error_expr(span);
            }
        }
        // `Enum.LITERAL`
        if segs.len() == 2 && first.index.is_none() && segs[1].index.is_none() {
            if let Some(&e) = self.globals.enum_ids.get(&first.name.name) {
                let lit = &segs[1].name.name;
                if let Some(idx) = self.globals.enums[e as usize]
                    .variants
                    .iter()
                    .position(|v| v == lit)
                {
                    return Expr {
                        kind: ExprKind::Const(idx as i64),
                        ty: Type::Enum(e),
                        span,
                    };
                }
                self.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!("enum `{}` has no literal `{lit}`", first.name.name),
                        segs[1].name.span,
                    )
                    .with_label("unknown literal")
                    .with_hint(format!(
                        "its literals are {}",
                        self.globals.enums[e as usize].variants.join(", ")
                    )),
                );
                return error_expr(span);
            }
        }
        // `inst.var` / `inst[i].var` in a system scope.
        if let Some(groups) = scope.instances {
            if let Some(g) = groups.get(&first.name.name) {
                if let Some(inst) = self.instance_index(scope, g, first) {
                    let chart = &scope.charts[g.chart as usize];
                    if segs.len() == 2 && segs[1].index.is_none() {
                        let vname = &segs[1].name.name;
                        if let Some(v) = chart.var(vname) {
                            return Expr {
                                kind: ExprKind::Var(VarRef {
                                    instance: Some(inst),
                                    var: v,
                                }),
                                ty: chart.vars[v as usize].ty,
                                span,
                            };
                        }
                        let mut d = Diagnostic::error(
                            "E0101",
                            format!("chart `{}` has no variable `{vname}`", chart.name),
                            segs[1].name.span,
                        )
                        .with_label("unknown variable");
                        if chart.state_by_path(vname).is_some() {
                            d = d.with_hint(format!(
                                "`{vname}` is a state: test it with `in({}.{vname})`",
                                first.name.name
                            ));
                        } else if let Some(c) = crate::suggest::closest(
                            vname,
                            chart.vars.iter().map(|v| v.name.as_str()),
                        ) {
                            d = d.with_hint(format!("did you mean `{c}`?"));
                        }
                        self.sink.push(d);
                        return error_expr(span);
                    }
                    self.sink.push(
                        Diagnostic::error("E0101", "expected `instance.variable`", span)
                            .with_hint("use `in(instance.state)` to test a state"),
                    );
                    return error_expr(span);
                }
                return error_expr(span);
            }
        }
        let name = &first.name.name;
        if segs.len() == 1 {
            if let Some(decl) = self.globals.declared_consts.get(name) {
                self.sink.push(
                    Diagnostic::error("E0101", format!("constant `{name}` is used before its declaration"), first.name.span)
                        .with_label("not declared yet")
                        .with_secondary(*decl, "declared here")
                        .with_hint(format!("move `const {name}` above this use: a constant sees only the constants declared before it")),
                );
                return error_expr(span);
            }
        }
        let mut d = Diagnostic::error("E0101", format!("unknown name `{name}`"), first.name.span)
            .with_label("not found in this scope");
        if let Some(s) = self.suggest(scope, name) {
            d = d.with_hint(format!("did you mean `{s}`?"));
        }
        self.sink.push(d);
        error_expr(span)
    }

    fn suggest(&self, scope: &Scope, name: &str) -> Option<String> {
        let mut cands: Vec<String> = Vec::new();
        if let Some(c) = scope.chart {
            cands.extend(c.vars.iter().map(|v| v.name.clone()));
        }
        cands.extend(self.globals.consts.keys().cloned());
        cands.extend(self.globals.literal_owners.keys().cloned());
        cands.extend(scope.locals.iter().map(|(n, _)| n.clone()));
        if let Some(g) = scope.instances {
            cands.extend(g.keys().cloned());
        }
        crate::suggest::closest(name, cands.iter().map(String::as_str))
    }

    /// The flat instance index of `fam` / `fam[2]`, reporting index errors.
    fn instance_index(
        &mut self,
        scope: &Scope,
        g: &crate::scope::InstanceGroup,
        seg: &ast::PathSegment,
    ) -> Option<u32> {
        match (&seg.index, g.len) {
            (None, None) => Some(g.first),
            (Some(ast::Index::At(e)), Some(len)) => {
                let i = self.const_value(scope, e)?;
                if i < 0 || i >= len as i64 {
                    self.sink.push(
                        Diagnostic::error(
                            "E0104",
                            format!(
                                "index {i} out of range for `{}` (length {len})",
                                seg.name.name
                            ),
                            e.span(),
                        )
                        .with_label(format!("must be within 0..{}", len - 1)),
                    );
                    return None;
                }
                Some(g.first + i as u32)
            }
            (None, Some(len)) => {
                self.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!("`{}` is an array of {len} instances", seg.name.name),
                        seg.name.span,
                    )
                    .with_label("needs an index")
                    .with_hint(format!("write `{}[0]`", seg.name.name)),
                );
                None
            }
            (Some(ast::Index::All(span)), _) => {
                self.sink.push(
                    Diagnostic::error("E0101", "`[*]` is only allowed in `connect`", *span)
                        .with_label("not allowed here"),
                );
                None
            }
            (Some(ast::Index::At(e)), None) => {
                self.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!("`{}` is not an instance array", seg.name.name),
                        e.span(),
                    )
                    .with_label("remove the index"),
                );
                None
            }
        }
    }

    /// Resolve `in(path)`: a state of this chart (from its root), or `inst.path` in a system.
    pub fn resolve_state(&mut self, scope: &Scope, p: &ast::Path) -> Option<StateRef> {
        let names: Vec<&str> = p.segments.iter().map(|s| s.name.name.as_str()).collect();
        if let Some(chart) = scope.chart {
            if p.segments.iter().all(|s| s.index.is_none()) {
                if let Some(s) = Scope::state_in(chart, &names) {
                    return Some(StateRef {
                        instance: None,
                        state: s,
                    });
                }
            }
        }
        if let Some(groups) = scope.instances {
            if let Some(g) = groups.get(names[0]) {
                let inst = self.instance_index(scope, g, &p.segments[0])?;
                let chart = &scope.charts[g.chart as usize];
                if let Some(s) = Scope::state_in(chart, &names[1..]) {
                    return Some(StateRef {
                        instance: Some(inst),
                        state: s,
                    });
                }
                self.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!(
                            "chart `{}` has no state `{}`",
                            chart.name,
                            names[1..].join(".")
                        ),
                        p.span,
                    )
                    .with_label("unknown state")
                    .with_hint(
                        "state paths start at the chart's top level, e.g. `in(inst.Go.Pause)`",
                    ),
                );
                return None;
            }
        }
        let mut d = Diagnostic::error(
            "E0101",
            format!("unknown state `{}`", names.join(".")),
            p.span,
        )
        .with_label("no such state")
        .with_hint("state paths start at the chart's top level, e.g. `in(Go.Pause)`");
        if let Some(chart) = scope.chart {
            let paths = chart.states.iter().map(|s| s.path.as_str());
            if let Some(s) = crate::suggest::closest(&names.join("."), paths) {
                d = d.with_hint(format!("did you mean `in({s})`?"));
            }
        }
        self.sink.push(d);
        None
    }
}

/// True for the placeholder produced after an error (so one mistake gives one diagnostic).
pub(crate) fn is_placeholder(x: &Expr) -> bool {
    matches!(x.kind, ExprKind::Const(0)) && x.ty == Type::UNBOUNDED
}
