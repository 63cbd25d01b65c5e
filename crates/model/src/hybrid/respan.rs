//! Give every node of a generated tree one span: the hybrid declaration it comes from, so
//! that a diagnostic or a run-time report about generated code points at the `continuous`
//! line of the user's file.

use statecheck_base::Span;
use statecheck_syntax::ast::{Block, Expr, Ident, Path, Stmt, TypeExpr, VarDecl};

fn ident(i: &mut Ident, at: Span) {
    i.span = at;
}

fn path(p: &mut Path, at: Span) {
    p.span = at;
    for s in &mut p.segments {
        ident(&mut s.name, at);
        if let Some(statecheck_syntax::ast::Index::At(e)) = &mut s.index {
            expr(e, at);
        }
    }
}

/// Respan an expression.
pub fn expr(e: &mut Expr, at: Span) {
    match e {
        Expr::Int(_, s) | Expr::Bool(_, s) | Expr::Error(s) => *s = at,
        Expr::Path(p) => path(p, at),
        Expr::In(p, s) => {
            path(p, at);
            *s = at;
        }
        Expr::Call { func, args, span } => {
            ident(func, at);
            args.iter_mut().for_each(|a| expr(a, at));
            *span = at;
        }
        Expr::Unary(_, x, s) => {
            expr(x, at);
            *s = at;
        }
        Expr::Binary(_, a, b, s) => {
            expr(a, at);
            expr(b, at);
            *s = at;
        }
        Expr::If(c, t, f, s) => {
            expr(c, at);
            expr(t, at);
            expr(f, at);
            *s = at;
        }
    }
}

fn block(b: &mut Block, at: Span) {
    b.span = at;
    b.stmts.iter_mut().for_each(|s| stmt(s, at));
}

/// Respan a statement.
pub fn stmt(s: &mut Stmt, at: Span) {
    match s {
        Stmt::Assign {
            target,
            index,
            value,
            span,
        } => {
            ident(target, at);
            if let Some(i) = index {
                expr(i, at);
            }
            expr(value, at);
            *span = at;
        }
        Stmt::For {
            var,
            lo,
            hi,
            body,
            span,
        } => {
            ident(var, at);
            expr(lo, at);
            expr(hi, at);
            block(body, at);
            *span = at;
        }
        Stmt::Raise { event, span } => {
            ident(event, at);
            *span = at;
        }
        Stmt::If {
            cond,
            then,
            otherwise,
            span,
        } => {
            expr(cond, at);
            block(then, at);
            if let Some(o) = otherwise {
                block(o, at);
            }
            *span = at;
        }
    }
}

/// Respan a declaration.
pub fn var_decl(v: &mut VarDecl, at: Span) {
    ident(&mut v.name, at);
    v.span = at;
    if let Some(n) = &mut v.len {
        expr(n, at);
    }
    if let Some(t) = &mut v.ty {
        match t {
            TypeExpr::Bool(s) | TypeExpr::Int(s) => *s = at,
            TypeExpr::Range { lo, hi, span } => {
                expr(lo, at);
                expr(hi, at);
                *span = at;
            }
            TypeExpr::Named(i) => ident(i, at),
        }
    }
    if let Some(e) = &mut v.init {
        expr(e, at);
    }
}
