//! Design-rule checks (the Modelica paper's §3.1 and what a demanding Stateflow user expects).
//!
//! Lints run on a model that checked without errors and only ever produce warnings. Each one is
//! written to have no false positives: where a rule cannot be decided from the model alone
//! (a guard that is hard to analyse, a value that depends on the environment), it stays silent.
//!
//! | Code  | Finding |
//! |-------|---------|
//! | W0301 | a state that no transition enters and that is not its parent's `initial` |
//! | W0302 | a state that cannot be reached from its level's initial state (isolated sub-graph) |
//! | W0303 | two transitions of one state with the same explicit `priority` |
//! | W0304 | a transition (or choice branch) that an earlier one always preempts |
//! | W0305 | a guard that is constant `false` |
//! | W0306 | a self-transition on a composite state |
//! | W0307 | a choice without `else` whose guards can all be false |
//! | W0308 | an unused variable or event (input never read, output never written, ...) |
//! | W0309 | a local variable or event that is written but never read |
//! | W0310 | a transition without a target that suppresses its state's `during` action |
//!
//! `docs/lints.md` describes each code with an example.

mod cover;
mod during;
mod reach;
mod trans;
mod usage;

use crate::model::{ChartId, Dest, Expr, ExprKind, Model, StateId, System, VarId, VarRef};
use crate::types::Type;
use statecheck_base::Diagnostic;

/// All design-rule findings of a model, as warnings.
///
/// Observer charts are linted like other charts, except that their top-level state `error`
/// (which a correct design never enters) is exempt from the reachability rules.
pub fn lint(model: &Model) -> Vec<Diagnostic> {
    let cx = Cx::new(model);
    let mut out = Vec::new();
    for id in 0..model.charts.len() as ChartId {
        reach::check(&cx, id, &mut out);
        trans::check(&cx, id, &mut out);
        during::check(&cx, id, &mut out);
    }
    usage::check(&cx, &mut out);
    // A junction reached from several transitions is expanded into each of them: report each
    // finding once.
    let mut seen = std::collections::HashSet::new();
    out.retain(|d| seen.insert((d.code, d.span, d.message.clone())));
    out
}

/// What every lint needs: the model and, per chart, the systems that instantiate it (to resolve
/// references to other instances' variables in observers).
struct Cx<'a> {
    model: &'a Model,
    /// For each chart, the systems with an instance of it.
    systems_of: Vec<Vec<&'a System>>,
}

impl<'a> Cx<'a> {
    fn new(model: &'a Model) -> Cx<'a> {
        let mut systems_of = vec![Vec::new(); model.charts.len()];
        for s in &model.systems {
            for inst in &s.instances {
                if let Some(list) = systems_of.get_mut(inst.chart as usize) {
                    if !list.iter().any(|x: &&System| std::ptr::eq(*x, s)) {
                        list.push(s);
                    }
                }
            }
        }
        Cx { model, systems_of }
    }

    /// The variables a reference written in chart `chart` may denote: its own variable, or
    /// the variable of another instance in each system that contains the chart.
    fn resolve(&self, chart: ChartId, r: VarRef) -> Vec<(ChartId, VarId)> {
        match r.instance {
            None => vec![(chart, r.var)],
            Some(i) => self.resolve_in(
                self.systems_of.get(chart as usize).map_or(&[][..], |v| v),
                i,
                r.var,
            ),
        }
    }

    /// Resolve `instance i, variable v` in each of `systems`.
    fn resolve_in(&self, systems: &[&System], i: u32, v: VarId) -> Vec<(ChartId, VarId)> {
        let mut out: Vec<(ChartId, VarId)> = Vec::new();
        for s in systems {
            if let Some(inst) = s.instances.get(i as usize) {
                let ok = self
                    .model
                    .charts
                    .get(inst.chart as usize)
                    .is_some_and(|c| (v as usize) < c.vars.len());
                if ok && !out.contains(&(inst.chart, v)) {
                    out.push((inst.chart, v));
                }
            }
        }
        out
    }

    /// The type of a variable reference written in chart `chart`, if it is unambiguous.
    fn var_type(&self, chart: ChartId, r: VarRef) -> Option<Type> {
        let mut ty = None;
        for (c, v) in self.resolve(chart, r) {
            let t = self.model.charts[c as usize].vars[v as usize].ty;
            match ty {
                None => ty = Some(t),
                Some(prev) if prev == t => {}
                Some(_) => return None,
            }
        }
        ty
    }

    /// True for the top-level state `error` of an observer chart.
    fn is_observer_error(&self, chart: ChartId, s: StateId) -> bool {
        self.model.charts[chart as usize].is_observer_error(s)
    }
}

/// True for a guard folded to the constant `true`.
fn const_true(e: &Expr) -> bool {
    matches!(e.kind, ExprKind::Const(v) if v != 0) && e.ty == Type::Bool
}

/// True for a guard folded to the constant `false`.
fn const_false(e: &Expr) -> bool {
    matches!(e.kind, ExprKind::Const(0)) && e.ty == Type::Bool
}

/// Every state a destination may lead to, through all choice branches.
fn targets(d: &Dest, out: &mut Vec<StateId>) {
    match d {
        Dest::Internal => {}
        Dest::State(s) => out.push(*s),
        Dest::Choice(branches) => branches.iter().for_each(|b| targets(&b.dest, out)),
    }
}

/// A state's name for messages: its dotted path.
fn state_name(model: &Model, chart: ChartId, s: StateId) -> String {
    model.charts[chart as usize].states[s as usize].path.clone()
}
