//! One mutable walk over the AST: [`VisitMut`] has a method per kind of node whose default
//! walks every child (through the matching `walk_*` function), so a rewrite overrides only the
//! hooks it cares about — expressions, paths, types — and sees every node a new AST variant
//! adds as soon as the walk here learns it. Parameter substitution and the components'
//! instance-path rewriting (`statecheck_model`) are both written on it.
//!
//! What the walk visits: every expression (guards, actions, initial values, delays, type
//! bounds, hybrid bounds and speeds, property and formula atoms), every path of an expression
//! (`a.x`, `in(a.S)`: [`VisitMut::visit_path`], after which the default walks the indices).
//! Transition and branch targets name states, not values: they go to
//! [`VisitMut::visit_state_target`], which does nothing by default. Identifiers that are not
//! paths (`initial` targets, assigned variables, raised events, declared names) are not
//! visited.

use super::*;

/// A mutable visitor of the AST. Every method's default walks the node's children.
pub trait VisitMut {
    /// An expression; the default walks its sub-expressions and paths.
    fn visit_expr(&mut self, e: &mut Expr) {
        walk_expr(self, e);
    }
    /// A path in an expression (`a.x`, and the state path of `in(...)`); the default walks
    /// the index expressions of its segments.
    fn visit_path(&mut self, p: &mut Path) {
        walk_path(self, p);
    }
    /// The state path a transition or branch leads to; nothing by default.
    fn visit_state_target(&mut self, _p: &mut Path) {}
    /// A type as written; the default walks the bounds of `int[lo..hi]`.
    fn visit_type(&mut self, t: &mut TypeExpr) {
        walk_type(self, t);
    }
    /// A block of statements.
    fn visit_block(&mut self, b: &mut Block) {
        walk_block(self, b);
    }
    /// A state body (a chart's top level, a state's or a region's inside).
    fn visit_body(&mut self, b: &mut StateBody) {
        walk_body(self, b);
    }
    /// A transition.
    fn visit_transition(&mut self, t: &mut Transition) {
        walk_transition(self, t);
    }
    /// A choice branch.
    fn visit_branch(&mut self, b: &mut Branch) {
        walk_branch(self, b);
    }
    /// A delay (`after`, `within`).
    fn visit_delay(&mut self, d: &mut Delay) {
        walk_delay(self, d);
    }
    /// A continuous-variable element.
    fn visit_hybrid(&mut self, h: &mut HybridElem) {
        walk_hybrid(self, h);
    }
    /// A variable or event declaration: its type and initial value.
    fn visit_var(&mut self, v: &mut VarDecl) {
        walk_var(self, v);
    }
    /// A property.
    fn visit_property(&mut self, p: &mut Property) {
        walk_property(self, p);
    }
    /// A temporal formula.
    fn visit_formula(&mut self, f: &mut Formula) {
        walk_formula(self, f);
    }
    /// A chart: parameters (types and defaults), variables, body and properties.
    fn visit_chart(&mut self, c: &mut Chart) {
        walk_chart(self, c);
    }
}

/// The children of an expression.
pub fn walk_expr<V: VisitMut + ?Sized>(v: &mut V, e: &mut Expr) {
    match e {
        Expr::Path(p) | Expr::In(p, _) => v.visit_path(p),
        Expr::Int(..) | Expr::Bool(..) | Expr::Error(_) => {}
        Expr::Call { args, .. } => args.iter_mut().for_each(|a| v.visit_expr(a)),
        Expr::Unary(_, a, _) => v.visit_expr(a),
        Expr::Binary(_, a, b, _) => {
            v.visit_expr(a);
            v.visit_expr(b);
        }
        Expr::If(c, a, b, _) => {
            v.visit_expr(c);
            v.visit_expr(a);
            v.visit_expr(b);
        }
    }
}

/// The index expressions of a path's segments.
pub fn walk_path<V: VisitMut + ?Sized>(v: &mut V, p: &mut Path) {
    for seg in &mut p.segments {
        if let Some(Index::At(e)) = &mut seg.index {
            v.visit_expr(e);
        }
    }
}

/// The bounds of a range type.
pub fn walk_type<V: VisitMut + ?Sized>(v: &mut V, t: &mut TypeExpr) {
    if let TypeExpr::Range { lo, hi, .. } = t {
        v.visit_expr(lo);
        v.visit_expr(hi);
    }
}

/// The statements of a block.
pub fn walk_block<V: VisitMut + ?Sized>(v: &mut V, b: &mut Block) {
    for s in &mut b.stmts {
        match s {
            Stmt::Assign { index, value, .. } => {
                if let Some(i) = index {
                    v.visit_expr(i);
                }
                v.visit_expr(value);
            }
            Stmt::Raise { .. } => {}
            Stmt::For { lo, hi, body, .. } => {
                v.visit_expr(lo);
                v.visit_expr(hi);
                v.visit_block(body);
            }
            Stmt::If {
                cond,
                then,
                otherwise,
                ..
            } => {
                v.visit_expr(cond);
                v.visit_block(then);
                if let Some(o) = otherwise {
                    v.visit_block(o);
                }
            }
        }
    }
}

/// Everything inside a state body, children included.
pub fn walk_body<V: VisitMut + ?Sized>(v: &mut V, b: &mut StateBody) {
    for blk in b.entry.iter_mut().chain(&mut b.during).chain(&mut b.exit) {
        v.visit_block(blk);
    }
    for h in &mut b.hybrid {
        v.visit_hybrid(h);
    }
    for i in &mut b.initial {
        if let Some(a) = &mut i.action {
            v.visit_block(a);
        }
    }
    for s in &mut b.states {
        v.visit_body(&mut s.body);
    }
    for r in &mut b.regions {
        v.visit_body(&mut r.body);
    }
    for j in &mut b.junctions {
        j.branches.iter_mut().for_each(|br| v.visit_branch(br));
    }
    for t in &mut b.transitions {
        v.visit_transition(t);
    }
}

/// A transition's delay, guard, action and target.
pub fn walk_transition<V: VisitMut + ?Sized>(v: &mut V, t: &mut Transition) {
    if let Some(Trigger::After { delay, .. }) = &mut t.trigger {
        v.visit_delay(delay);
    }
    if let Some(g) = &mut t.guard {
        v.visit_expr(g);
    }
    if let Some(a) = &mut t.action {
        v.visit_block(a);
    }
    if let Some(target) = &mut t.target {
        walk_target(v, target);
    }
}

/// A target: a state path, or an inline choice's branches.
pub fn walk_target<V: VisitMut + ?Sized>(v: &mut V, t: &mut Target) {
    match t {
        Target::Path(p) => v.visit_state_target(p),
        Target::Choice { branches, .. } => branches.iter_mut().for_each(|b| v.visit_branch(b)),
    }
}

/// A branch's guard, action and target.
pub fn walk_branch<V: VisitMut + ?Sized>(v: &mut V, b: &mut Branch) {
    if let Some(g) = &mut b.guard {
        v.visit_expr(g);
    }
    if let Some(a) = &mut b.action {
        v.visit_block(a);
    }
    walk_target(v, &mut b.target);
}

/// A delay's amount.
pub fn walk_delay<V: VisitMut + ?Sized>(v: &mut V, d: &mut Delay) {
    match d {
        Delay::Ticks(e) => v.visit_expr(e),
        Delay::Time(d) => v.visit_expr(&mut d.amount),
    }
}

/// The bounds, cells and speeds of a continuous-variable element.
pub fn walk_hybrid<V: VisitMut + ?Sized>(v: &mut V, h: &mut HybridElem) {
    let speed = |v: &mut V, s: &mut Speed| {
        for n in std::iter::once(&mut s.num).chain(s.den.as_mut()) {
            if let SpeedNumber::Expr(e) = n {
                v.visit_expr(e);
            }
        }
    };
    match h {
        HybridElem::Continuous { lo, hi, init, .. } => {
            v.visit_expr(lo);
            v.visit_expr(hi);
            if let Some(i) = init {
                v.visit_expr(i);
            }
        }
        HybridElem::Grid { cells, .. } => {
            if let Some(c) = cells {
                v.visit_expr(c);
            }
        }
        HybridElem::Sensor { lo, hi, .. } => {
            v.visit_expr(lo);
            v.visit_expr(hi);
        }
        HybridElem::Der { rate, .. } => match rate {
            SpeedExpr::Constant(s) => speed(v, s),
            SpeedExpr::Profile(segs, last) => {
                for (s, d) in segs.iter_mut() {
                    speed(v, s);
                    v.visit_expr(&mut d.amount);
                }
                speed(v, last);
            }
        },
    }
}

/// A declaration's array length, type and initial value.
pub fn walk_var<V: VisitMut + ?Sized>(v: &mut V, d: &mut VarDecl) {
    if let Some(n) = &mut d.len {
        v.visit_expr(n);
    }
    if let Some(t) = &mut d.ty {
        v.visit_type(t);
    }
    if let Some(e) = &mut d.init {
        v.visit_expr(e);
    }
}

/// A property's expressions and formulas.
pub fn walk_property<V: VisitMut + ?Sized>(v: &mut V, p: &mut Property) {
    match &mut p.kind {
        PropertyKind::Invariant { expr, assuming } => {
            v.visit_expr(expr);
            if let Some(a) = assuming {
                v.visit_expr(a);
            }
        }
        PropertyKind::Reachable { expr } | PropertyKind::Nonblocking { expr } => v.visit_expr(expr),
        PropertyKind::Respond {
            trigger,
            response,
            within,
        } => {
            v.visit_expr(trigger);
            v.visit_expr(response);
            v.visit_delay(within);
        }
        PropertyKind::RespondEventually { trigger, response } => {
            v.visit_expr(trigger);
            v.visit_expr(response);
        }
        PropertyKind::Ltl { formula } | PropertyKind::Ctl { formula } => v.visit_formula(formula),
        PropertyKind::Fair { trigger, expr } => {
            if let Some(t) = trigger {
                v.visit_expr(t);
            }
            v.visit_expr(expr);
        }
    }
}

/// A formula's atoms.
pub fn walk_formula<V: VisitMut + ?Sized>(v: &mut V, f: &mut Formula) {
    match f {
        Formula::Atom(e) => v.visit_expr(e),
        Formula::Not(a, _) | Formula::Unary(_, a, _) => v.visit_formula(a),
        Formula::And(a, b, _)
        | Formula::Or(a, b, _)
        | Formula::Implies(a, b, _)
        | Formula::Binary(_, a, b, _)
        | Formula::QuantUntil(_, a, b, _) => {
            v.visit_formula(a);
            v.visit_formula(b);
        }
    }
}

/// A chart's parameters, variables, body and properties.
pub fn walk_chart<V: VisitMut + ?Sized>(v: &mut V, c: &mut Chart) {
    for p in &mut c.params {
        v.visit_type(&mut p.ty);
        if let Some(d) = &mut p.default {
            v.visit_expr(d);
        }
    }
    for d in &mut c.vars {
        v.visit_var(d);
    }
    v.visit_body(&mut c.body);
    for p in &mut c.properties {
        v.visit_property(p);
    }
}
