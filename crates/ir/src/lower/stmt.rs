//! Actions and expressions: model statements and expressions to IR statements and nodes,
//! with the run-time check sites of R9.

use super::{Ctx, Lowerer};
use crate::program::*;
use statecheck_model as m;
use statecheck_syntax::ast::BinOp;

impl Lowerer<'_> {
    pub(super) fn stmts(&mut self, stmts: &[m::Stmt], ctx: Ctx) -> Vec<Stmt> {
        stmts.iter().map(|s| self.stmt(s, ctx)).collect()
    }

    pub(super) fn stmt(&mut self, s: &m::Stmt, ctx: Ctx) -> Stmt {
        match s {
            m::Stmt::Assign {
                var,
                value,
                checked,
                span,
            } => {
                let slot = self.lay.instances[ctx.inst as usize].var_slots[*var as usize];
                let expr = self.expr(value, Some(ctx));
                let site = checked.then(|| {
                    let name = self.chart(ctx.inst).vars[*var as usize].name.clone();
                    self.site(Some(ctx), *span, format!("assignment to `{name}`"))
                });
                Stmt::Assign { slot, expr, site }
            }
            m::Stmt::Raise { event, .. } => {
                let one = self.konst(1);
                let slot = match self.lay.pending[ctx.inst as usize][*event as usize] {
                    Some(p) => p,
                    None => self.lay.instances[ctx.inst as usize].var_slots[*event as usize],
                };
                Stmt::Assign {
                    slot,
                    expr: one,
                    site: None,
                }
            }
            m::Stmt::If {
                cond,
                then,
                otherwise,
            } => Stmt::If {
                cond: self.expr(cond, Some(ctx)),
                then: self.stmts(then, ctx),
                otherwise: self.stmts(otherwise, ctx),
            },
        }
    }

    /// Lower an expression; `ctx` is the instance that "this instance" references mean.
    pub(super) fn expr(&mut self, e: &m::Expr, ctx: Option<Ctx>) -> ExprId {
        match &e.kind {
            m::ExprKind::Const(v) => self.konst(*v),
            m::ExprKind::Var(r) => {
                let inst = r.instance.or(ctx.map(|c| c.inst)).unwrap_or(0);
                let slot = self.lay.instances[inst as usize].var_slots[r.var as usize];
                self.slot(slot)
            }
            m::ExprKind::In(r) => {
                let inst = r.instance.or(ctx.map(|c| c.inst)).unwrap_or(0);
                self.lay.instances[inst as usize].active[r.state as usize]
            }
            m::ExprKind::Unary(op, a) => {
                let a = self.expr(a, ctx);
                self.node(Node::Unary(*op, a))
            }
            m::ExprKind::Binary(op, a, b) => {
                let (a, b) = (self.expr(a, ctx), self.expr(b, ctx));
                let site = if matches!(
                    op,
                    BinOp::And
                        | BinOp::Or
                        | BinOp::Eq
                        | BinOp::Ne
                        | BinOp::Lt
                        | BinOp::Le
                        | BinOp::Gt
                        | BinOp::Ge
                        | BinOp::BitAnd
                        | BinOp::BitOr
                        | BinOp::BitXor
                ) {
                    u32::MAX
                } else {
                    self.site(ctx, e.span, format!("`{}`", op_symbol(*op)))
                };
                self.node(Node::Binary(*op, a, b, site))
            }
            m::ExprKind::If(c, a, b) => {
                let (c, a, b) = (self.expr(c, ctx), self.expr(a, ctx), self.expr(b, ctx));
                self.node(Node::Ite(c, a, b))
            }
            m::ExprKind::Builtin(f, args) => {
                let args: Vec<ExprId> = args.iter().map(|a| self.expr(a, ctx)).collect();
                match f {
                    m::Builtin::Min => self.node(Node::Min(args[0], args[1])),
                    m::Builtin::Max => self.node(Node::Max(args[0], args[1])),
                    m::Builtin::Abs => {
                        let site = self.site(ctx, e.span, "`abs`".into());
                        self.node(Node::Abs(args[0], site))
                    }
                }
            }
            m::ExprKind::Let(id, v, b) => {
                let n = self.locals.len() as u32;
                let l = *self.locals.entry(*id).or_insert(n);
                let (v, b) = (self.expr(v, ctx), self.expr(b, ctx));
                self.node(Node::Let(l, v, b))
            }
            m::ExprKind::Local(id) => {
                let n = self.locals.len() as u32;
                let l = *self.locals.entry(*id).or_insert(n);
                self.node(Node::Local(l))
            }
            m::ExprKind::Check(a, lo, hi, what) => {
                let a = self.expr(a, ctx);
                let site = self.site(ctx, e.span, what.clone());
                self.node(Node::Check(a, *lo, *hi, site))
            }
        }
    }
}

fn op_symbol(op: BinOp) -> &'static str {
    match op {
        BinOp::Add => "+",
        BinOp::Sub => "-",
        BinOp::Mul => "*",
        BinOp::Div => "/",
        BinOp::Rem => "%",
        BinOp::Shl => "<<",
        BinOp::Shr => ">>",
        _ => "op",
    }
}
