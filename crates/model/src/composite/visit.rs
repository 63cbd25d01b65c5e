//! Every instance path of a system's expressions, properties, assumptions and rates, visited
//! mutably: the flattening rewrites each one through the hierarchy of components.

use statecheck_syntax::ast;

/// Calls `f` on every path that names an instance's variable, event or state (`a.x`,
/// `in(a.S)`, `storage.feeder.pos`), after rewriting the paths inside its indices.
pub(super) struct Paths<'f> {
    pub f: &'f mut dyn FnMut(&mut ast::Path),
}

impl Paths<'_> {
    pub fn expr(&mut self, e: &mut ast::Expr) {
        match e {
            ast::Expr::Path(p) | ast::Expr::In(p, _) => self.path(p),
            ast::Expr::Int(..) | ast::Expr::Bool(..) | ast::Expr::Error(_) => {}
            ast::Expr::Call { args, .. } => args.iter_mut().for_each(|a| self.expr(a)),
            ast::Expr::Unary(_, a, _) => self.expr(a),
            ast::Expr::Binary(_, a, b, _) => {
                self.expr(a);
                self.expr(b);
            }
            ast::Expr::If(c, a, b, _) => {
                self.expr(c);
                self.expr(a);
                self.expr(b);
            }
        }
    }

    pub fn path(&mut self, p: &mut ast::Path) {
        for seg in &mut p.segments {
            if let Some(ast::Index::At(e)) = &mut seg.index {
                self.expr(e);
            }
        }
        (self.f)(p);
    }

    pub fn property(&mut self, p: &mut ast::Property) {
        match &mut p.kind {
            ast::PropertyKind::Invariant { expr, assuming } => {
                self.expr(expr);
                if let Some(a) = assuming {
                    self.expr(a);
                }
            }
            ast::PropertyKind::Reachable { expr } | ast::PropertyKind::Nonblocking { expr } => {
                self.expr(expr)
            }
            ast::PropertyKind::Respond {
                trigger,
                response,
                within,
            } => {
                self.expr(trigger);
                self.expr(response);
                match within {
                    ast::Delay::Ticks(e) => self.expr(e),
                    ast::Delay::Time(d) => self.expr(&mut d.amount),
                }
            }
            ast::PropertyKind::RespondEventually { trigger, response } => {
                self.expr(trigger);
                self.expr(response);
            }
            ast::PropertyKind::Ltl { formula } | ast::PropertyKind::Ctl { formula } => {
                self.formula(formula)
            }
            ast::PropertyKind::Fair { trigger, expr } => {
                if let Some(t) = trigger {
                    self.expr(t);
                }
                self.expr(expr);
            }
        }
    }

    fn formula(&mut self, f: &mut ast::Formula) {
        match f {
            ast::Formula::Atom(e) => self.expr(e),
            ast::Formula::Not(a, _) | ast::Formula::Unary(_, a, _) => self.formula(a),
            ast::Formula::And(a, b, _)
            | ast::Formula::Or(a, b, _)
            | ast::Formula::Implies(a, b, _)
            | ast::Formula::Binary(_, a, b, _)
            | ast::Formula::QuantUntil(_, a, b, _) => {
                self.formula(a);
                self.formula(b);
            }
        }
    }

    /// Every expression of an observer chart: initial values, actions, guards, delays,
    /// choices and its properties.
    pub fn chart(&mut self, c: &mut ast::Chart) {
        for v in &mut c.vars {
            if let Some(e) = &mut v.init {
                self.expr(e);
            }
        }
        self.body(&mut c.body);
        for p in &mut c.properties {
            self.property(p);
        }
    }

    fn block(&mut self, b: &mut ast::Block) {
        for s in &mut b.stmts {
            match s {
                ast::Stmt::Assign { value, .. } => self.expr(value),
                ast::Stmt::Raise { .. } => {}
                ast::Stmt::If {
                    cond,
                    then,
                    otherwise,
                    ..
                } => {
                    self.expr(cond);
                    self.block(then);
                    if let Some(o) = otherwise {
                        self.block(o);
                    }
                }
            }
        }
    }

    fn body(&mut self, b: &mut ast::StateBody) {
        for blk in b.entry.iter_mut().chain(&mut b.during).chain(&mut b.exit) {
            self.block(blk);
        }
        for i in &mut b.initial {
            if let Some(a) = &mut i.action {
                self.block(a);
            }
        }
        for s in &mut b.states {
            self.body(&mut s.body);
        }
        for r in &mut b.regions {
            self.body(&mut r.body);
        }
        for j in &mut b.junctions {
            self.branches(&mut j.branches);
        }
        for t in &mut b.transitions {
            if let Some(ast::Trigger::After { delay, .. }) = &mut t.trigger {
                match delay {
                    ast::Delay::Ticks(e) => self.expr(e),
                    ast::Delay::Time(d) => self.expr(&mut d.amount),
                }
            }
            if let Some(g) = &mut t.guard {
                self.expr(g);
            }
            if let Some(a) = &mut t.action {
                self.block(a);
            }
            if let Some(ast::Target::Choice { branches, .. }) = &mut t.target {
                self.branches(branches);
            }
        }
    }

    fn branches(&mut self, bs: &mut [ast::Branch]) {
        for b in bs {
            if let Some(g) = &mut b.guard {
                self.expr(g);
            }
            if let Some(a) = &mut b.action {
                self.block(a);
            }
            if let ast::Target::Choice { branches, .. } = &mut b.target {
                self.branches(branches);
            }
        }
    }
}
