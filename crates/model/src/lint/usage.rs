//! Unused variables and events (W0308) and locals that are written but never read (W0309).
//!
//! A read is any use of the value: in a guard, an action, a trigger, a property, an
//! assumption, an observer, or as the source of a connection. An assignment's reads of the
//! variable it assigns (`n = n + 1`, `n += 1`) do not count: they only feed the variable itself.

use super::Cx;
use crate::model::{ChartId, Dest, Expr, ExprKind, PropertyKind, Stmt, System, Trigger, VarId};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast::VarKind;

/// Reads and writes of every variable of every chart.
struct Usage {
    /// `read[chart][var]`
    read: Vec<Vec<bool>>,
    /// `written[chart][var]`: where it is first written (assigned or raised).
    written: Vec<Vec<Option<Span>>>,
}

/// Where an expression is written: in a chart (resolving `inst.var` through the systems that
/// contain it) or at system level.
#[derive(Clone, Copy)]
enum Site<'a> {
    Chart(ChartId),
    System(&'a System),
}

impl Usage {
    fn read_ref(&mut self, cx: &Cx, site: Site, r: crate::model::VarRef, except: Option<VarId>) {
        let targets = match (site, r.instance) {
            (Site::Chart(c), _) => {
                if r.instance.is_none() && except == Some(r.var) {
                    return;
                }
                cx.resolve(c, r)
            }
            (Site::System(s), Some(i)) => cx.resolve_in(&[s], i, r.var),
            (Site::System(_), None) => Vec::new(),
        };
        for (c, v) in targets {
            self.read[c as usize][v as usize] = true;
        }
    }

    fn expr(&mut self, cx: &Cx, site: Site, e: &Expr, except: Option<VarId>) {
        match &e.kind {
            ExprKind::Const(_) | ExprKind::In(_) | ExprKind::Local(_) => {}
            ExprKind::Let(_, v, b) => {
                self.expr(cx, site, v, except);
                self.expr(cx, site, b, except);
            }
            ExprKind::Var(r) => self.read_ref(cx, site, *r, except),
            ExprKind::Unary(_, a) | ExprKind::Check(a, ..) => self.expr(cx, site, a, except),
            ExprKind::Binary(_, a, b) => {
                self.expr(cx, site, a, except);
                self.expr(cx, site, b, except);
            }
            ExprKind::If(c, a, b) => {
                self.expr(cx, site, c, except);
                self.expr(cx, site, a, except);
                self.expr(cx, site, b, except);
            }
            ExprKind::Builtin(_, args) => args.iter().for_each(|a| self.expr(cx, site, a, except)),
        }
    }

    fn stmts(&mut self, cx: &Cx, chart: ChartId, stmts: &[Stmt]) {
        for s in stmts {
            match s {
                Stmt::Assign {
                    var, value, span, ..
                } => {
                    self.write(chart, *var, *span);
                    self.expr(cx, Site::Chart(chart), value, Some(*var));
                }
                Stmt::Raise { event, span } => self.write(chart, *event, *span),
                Stmt::If {
                    cond,
                    then,
                    otherwise,
                } => {
                    self.expr(cx, Site::Chart(chart), cond, None);
                    self.stmts(cx, chart, then);
                    self.stmts(cx, chart, otherwise);
                }
            }
        }
    }

    fn write(&mut self, chart: ChartId, var: VarId, span: Span) {
        self.written[chart as usize][var as usize].get_or_insert(span);
    }

    fn dest(&mut self, cx: &Cx, chart: ChartId, d: &Dest) {
        if let Dest::Choice(branches) = d {
            for b in branches {
                if let Some(g) = &b.guard {
                    self.expr(cx, Site::Chart(chart), g, None);
                }
                self.stmts(cx, chart, &b.action);
                self.dest(cx, chart, &b.dest);
            }
        }
    }

    fn property(&mut self, cx: &Cx, site: Site, p: &PropertyKind) {
        match p {
            PropertyKind::Invariant { expr, assuming } => {
                self.expr(cx, site, expr, None);
                if let Some(a) = assuming {
                    self.expr(cx, site, a, None);
                }
            }
            PropertyKind::Reachable { expr } => self.expr(cx, site, expr, None),
            PropertyKind::Respond {
                trigger, response, ..
            }
            | PropertyKind::RespondEventually { trigger, response } => {
                self.expr(cx, site, trigger, None);
                self.expr(cx, site, response, None);
            }
            PropertyKind::Ltl(f) | PropertyKind::Ctl(f) => {
                f.atoms(&mut |e| self.expr(cx, site, e, None));
            }
            PropertyKind::Nonblocking { expr } => self.expr(cx, site, expr, None),
            PropertyKind::Fair { trigger, expr } => {
                if let Some(t) = trigger {
                    self.expr(cx, site, t, None);
                }
                self.expr(cx, site, expr, None);
            }
        }
    }
}

/// Run W0308 and W0309 over the whole model.
pub(super) fn check(cx: &Cx, out: &mut Vec<Diagnostic>) {
    let model = cx.model;
    let mut u = Usage {
        read: model
            .charts
            .iter()
            .map(|c| vec![false; c.vars.len()])
            .collect(),
        written: model
            .charts
            .iter()
            .map(|c| vec![None; c.vars.len()])
            .collect(),
    };
    for (id, chart) in model.charts.iter().enumerate() {
        let id = id as ChartId;
        let site = Site::Chart(id);
        for node in &chart.states {
            for block in [&node.entry, &node.during, &node.exit, &node.initial_action] {
                u.stmts(cx, id, block);
            }
        }
        for t in &chart.transitions {
            if let Trigger::Event(e) = t.trigger {
                u.read[id as usize][e as usize] = true;
            }
            if let Some(g) = &t.guard {
                u.expr(cx, site, g, None);
            }
            u.stmts(cx, id, &t.action);
            u.dest(cx, id, &t.dest);
        }
        for p in &chart.properties {
            u.property(cx, site, &p.kind);
        }
    }
    for s in &model.systems {
        let site = Site::System(s);
        for a in &s.assumes {
            u.expr(cx, site, a, None);
        }
        for p in &s.properties {
            u.property(cx, site, &p.kind);
        }
        for c in &s.connections {
            if let Some(inst) = s.instances.get(c.from.0 as usize) {
                if let Some(r) = u
                    .read
                    .get_mut(inst.chart as usize)
                    .and_then(|v| v.get_mut(c.from.1 as usize))
                {
                    *r = true;
                }
            }
        }
    }

    for (id, chart) in model.charts.iter().enumerate() {
        for (v, var) in chart.vars.iter().enumerate() {
            let read = u.read[id][v];
            let written = u.written[id][v];
            let name = &var.name;
            let d = match (var.kind, var.is_event) {
                (VarKind::Input, _) if !read => Diagnostic::warning(
                    "W0308",
                    format!(
                        "input {} `{name}` is never used",
                        if var.is_event { "event" } else { "variable" }
                    ),
                    var.span,
                )
                .with_label("never read")
                .with_hint(format!(
                    "remove `{name}`, or use it in a guard, trigger or action"
                )),
                (VarKind::Output, false) if written.is_none() => Diagnostic::warning(
                    "W0308",
                    format!("output `{name}` is never written"),
                    var.span,
                )
                .with_label(format!("always {}", model.format_value(var.ty, var.init)))
                .with_hint(format!("assign `{name}` in an action, or remove it")),
                (VarKind::Output, true) if written.is_none() => Diagnostic::warning(
                    "W0308",
                    format!("output event `{name}` is never raised"),
                    var.span,
                )
                .with_label("never raised")
                .with_hint(format!("`raise {name};` in an action, or remove it")),
                (VarKind::Local, false) if !read && written.is_none() => Diagnostic::warning(
                    "W0308",
                    format!("local variable `{name}` is never used"),
                    var.span,
                )
                .with_label("never read or written")
                .with_hint(format!("remove `{name}`")),
                (VarKind::Local, true) if written.is_none() => {
                    let d = Diagnostic::warning(
                        "W0308",
                        format!("local event `{name}` is never raised"),
                        var.span,
                    )
                    .with_label("never raised");
                    if read {
                        d.with_hint(format!("transitions triggered by `{name}` can never fire; `raise {name};` in an action"))
                    } else {
                        d.with_hint(format!("remove `{name}`"))
                    }
                }
                (VarKind::Local, _) if !read => {
                    let what = if var.is_event { "event" } else { "variable" };
                    let did = if var.is_event { "raised" } else { "written" };
                    let mut d = Diagnostic::warning("W0309", format!("local {what} `{name}` is {did} but never read"), var.span)
                        .with_label("never read")
                        .with_hint(format!(
                            "nothing depends on `{name}`: remove it, or use it where it was meant to matter"
                        ));
                    if let Some(w) = written {
                        d = d.with_secondary(w, format!("{did} here"));
                    }
                    d
                }
                _ => continue,
            };
            out.push(d);
        }
    }
}
