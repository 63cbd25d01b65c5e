//! Critical points: the numbers a model compares a continuous variable with. Each one is
//! forced onto the variable's grid, so that every comparison is exact at the grid points.
//!
//! A comparison counts when one side names the variable (`pos`, or `feeder.pos` from a
//! system or observer: any path ending in the name) and the other side is an integer literal,
//! possibly negated, or a global constant of the file.

use super::plan::Plan;
use statecheck_syntax::ast::{self, BinOp, Expr, UnOp};
use std::collections::HashMap;

/// Every (variable, number) compared in `chart` and in the file's systems, for the
/// variables of `plans`.
pub fn collect(chart: &ast::Chart, file: &ast::File, plans: &[Plan]) -> Vec<(String, i64)> {
    let consts: HashMap<&str, i64> = file
        .items
        .iter()
        .filter_map(|i| match i {
            ast::Item::Const(c) => {
                literal(&c.value, &HashMap::new()).map(|v| (c.name.name.as_str(), v))
            }
            _ => None,
        })
        .collect();
    let mut c = Collector {
        vars: plans.iter().map(|p| p.var.as_str()).collect(),
        consts,
        out: Vec::new(),
        local: true,
    };
    c.body(&chart.body);
    for p in &chart.properties {
        c.property(p);
    }
    c.local = false;
    for item in &file.items {
        if let ast::Item::System(s) = item {
            for p in &s.properties {
                c.property(p);
            }
            for a in &s.assumes {
                c.expr(&a.expr);
            }
            for o in &s.observers {
                c.body(&o.body);
                for p in &o.properties {
                    c.property(p);
                }
            }
        }
    }
    c.out.sort();
    c.out.dedup();
    c.out
}

/// An integer literal, a negated one, or a known constant.
fn literal(e: &Expr, consts: &HashMap<&str, i64>) -> Option<i64> {
    match e {
        Expr::Int(v, _) => Some(*v),
        Expr::Unary(UnOp::Neg, x, _) => literal(x, consts).and_then(i64::checked_neg),
        Expr::Path(p) if p.segments.len() == 1 && p.segments[0].index.is_none() => {
            consts.get(p.segments[0].name.name.as_str()).copied()
        }
        _ => None,
    }
}

struct Collector<'a> {
    vars: Vec<&'a str>,
    consts: HashMap<&'a str, i64>,
    out: Vec<(String, i64)>,
    /// Inside the chart: a bare name is the variable; outside, a dotted path ending in it.
    local: bool,
}

impl Collector<'_> {
    fn var_of(&self, e: &Expr) -> Option<String> {
        let Expr::Path(p) = e else { return None };
        let last = p.segments.last()?;
        let ok = if self.local {
            p.segments.len() == 1
        } else {
            p.segments.len() >= 2
        };
        (ok && last.index.is_none() && self.vars.contains(&last.name.name.as_str()))
            .then(|| last.name.name.clone())
    }

    fn expr(&mut self, e: &Expr) {
        match e {
            Expr::Binary(op, a, b, _) => {
                if matches!(
                    op,
                    BinOp::Eq | BinOp::Ne | BinOp::Lt | BinOp::Le | BinOp::Gt | BinOp::Ge
                ) {
                    for (x, y) in [(a, b), (b, a)] {
                        if let (Some(v), Some(n)) = (self.var_of(x), literal(y, &self.consts)) {
                            self.out.push((v, n));
                        }
                    }
                }
                self.expr(a);
                self.expr(b);
            }
            Expr::Unary(_, x, _) => self.expr(x),
            Expr::If(c, t, f, _) => {
                self.expr(c);
                self.expr(t);
                self.expr(f);
            }
            Expr::Call { args, .. } => args.iter().for_each(|a| self.expr(a)),
            Expr::Int(..) | Expr::Bool(..) | Expr::Path(_) | Expr::In(..) | Expr::Error(_) => {}
        }
    }

    fn block(&mut self, b: &ast::Block) {
        for s in &b.stmts {
            match s {
                ast::Stmt::Assign { value, .. } => self.expr(value),
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
                ast::Stmt::For { body, .. } => self.block(body),
                ast::Stmt::Raise { .. } => {}
            }
        }
    }

    fn branch(&mut self, b: &ast::Branch) {
        if let Some(g) = &b.guard {
            self.expr(g);
        }
        if let Some(a) = &b.action {
            self.block(a);
        }
        self.target(&b.target);
    }

    fn target(&mut self, t: &ast::Target) {
        if let ast::Target::Choice { branches, .. } = t {
            branches.iter().for_each(|b| self.branch(b));
        }
    }

    fn body(&mut self, body: &ast::StateBody) {
        for b in body.entry.iter().chain(&body.during).chain(&body.exit) {
            self.block(b);
        }
        for t in &body.transitions {
            if let Some(g) = &t.guard {
                self.expr(g);
            }
            if let Some(a) = &t.action {
                self.block(a);
            }
            if let Some(tg) = &t.target {
                self.target(tg);
            }
        }
        for j in &body.junctions {
            j.branches.iter().for_each(|b| self.branch(b));
        }
        for s in &body.states {
            self.body(&s.body);
        }
        for r in &body.regions {
            self.body(&r.body);
        }
    }

    fn property(&mut self, p: &ast::Property) {
        use ast::PropertyKind as K;
        match &p.kind {
            K::Invariant { expr, assuming } => {
                self.expr(expr);
                if let Some(a) = assuming {
                    self.expr(a);
                }
            }
            K::Reachable { expr } | K::Nonblocking { expr } => self.expr(expr),
            K::Respond {
                trigger, response, ..
            }
            | K::RespondEventually { trigger, response } => {
                self.expr(trigger);
                self.expr(response);
            }
            K::Fair { trigger, expr } => {
                if let Some(t) = trigger {
                    self.expr(t);
                }
                self.expr(expr);
            }
            K::Ltl { formula } | K::Ctl { formula } => self.formula(formula),
        }
    }

    /// The atoms of a temporal formula (its nesting is bounded by the parser's).
    fn formula(&mut self, f: &ast::Formula) {
        use ast::Formula as F;
        match f {
            F::Atom(e) => self.expr(e),
            F::Not(a, _) | F::Unary(_, a, _) => self.formula(a),
            F::And(a, b, _)
            | F::Or(a, b, _)
            | F::Implies(a, b, _)
            | F::Binary(_, a, b, _)
            | F::QuantUntil(_, a, b, _) => {
                self.formula(a);
                self.formula(b);
            }
        }
    }
}
