//! Lowering a checked system to the IR. **This module is the step semantics**: every rule of
//! `docs/semantics.md` is decided here, once, and every consumer runs the result.
//!
//! The rules, in the order a tick applies them (see docs/semantics.md for worked examples):
//! - R1 Tick 0 only initialises: every instance, in execution order, performs its default
//!   entry (entry actions outermost first, `initial` children, regions in order).
//! - R2 Later ticks run every instance's step in execution order; observers run last.
//! - R3 At the start of an instance's step, its output events are cleared, and local events
//!   raised in the previous tick become present (those raised now are present next tick).
//! - R4 The step walks the active configuration top-down. For an active state: its timer
//!   advances; its transitions are tried in priority order; the first enabled one fires and
//!   ends the walk below that state for this tick. If none fires: `during`, then the active
//!   child (OR) or every region in order (AND).
//! - R5 Firing: exit the source's branch below the transition's scope (innermost first,
//!   regions in reverse order), run the transition action, the taken choice branches'
//!   actions, then enter from the scope down to the target (outermost first), then the
//!   target's default entry. The scope is the innermost exclusive node that strictly contains
//!   both source and target (so self-transitions and transitions to a descendant exit and
//!   re-enter the source).
//! - R6 A transition that leaves a parallel state stops the walk of its later regions.
//! - R7 A choice fires only if some branch path ends in a state; branch guards see the values
//!   before the transition's actions.
//! - R8 Default entry of an OR state with history re-enters the remembered child (shallow:
//!   that child's default entry; deep: the remembered configuration all the way down).
//! - R9 Assigning a value out of the variable's range, dividing by zero or shifting by a bad
//!   amount is a run-time error: the tick stops there.

use crate::layout::{layout, Layout};

use crate::program::*;
use statecheck_base::{Diagnostic, Span};
use statecheck_model as m;
use statecheck_model::{Chart, Dest, Model, NodeKind, StateId, System, Trigger};
use statecheck_syntax::ast::{BinOp, HistoryKind, UnOp, VarKind};
use std::collections::HashMap;

/// Lower one system of a checked model. The model must have no errors; structural problems
/// only the lowering can see (e.g. a transition that would leave a chart-level parallel
/// state) are returned as diagnostics.
pub fn lower(model: &Model, sys: &System) -> Result<Program, Vec<Diagnostic>> {
    let lay = layout(model, sys);
    let mut lw = Lowerer {
        model,
        sys,
        nodes: Vec::new(),
        procs: Vec::new(),
        sites: Vec::new(),
        covers: Vec::new(),
        exit_procs: HashMap::new(),
        enter_procs: HashMap::new(),
        state_covers: HashMap::new(),
        locals: HashMap::new(),
        diags: Vec::new(),
        lay,
    };
    let program = lw.run();
    if lw.diags.is_empty() {
        Ok(program)
    } else {
        Err(lw.diags)
    }
}

struct Lowerer<'m> {
    model: &'m Model,
    sys: &'m System,
    lay: Layout,
    nodes: Vec<Node>,
    procs: Vec<Proc>,
    sites: Vec<Site>,
    covers: Vec<Cover>,
    exit_procs: HashMap<(u32, StateId), ProcId>,
    enter_procs: HashMap<(u32, StateId, bool), ProcId>,
    state_covers: HashMap<(u32, StateId), CoverId>,
    /// Model `Let` ids to expression locals.
    locals: HashMap<u32, u32>,
    diags: Vec<Diagnostic>,
}

/// The instance being lowered and the state whose code is being generated (for sites).
#[derive(Clone, Copy)]
struct Ctx {
    inst: u32,
    state: StateId,
}

impl<'m> Lowerer<'m> {
    fn chart(&self, inst: u32) -> &'m Chart {
        &self.model.charts[self.sys.instances[inst as usize].chart as usize]
    }

    fn node(&mut self, n: Node) -> ExprId {
        self.nodes.push(n);
        self.nodes.len() as ExprId - 1
    }

    fn konst(&mut self, v: i64) -> ExprId {
        self.node(Node::Const(v))
    }

    fn slot(&mut self, s: SlotId) -> ExprId {
        self.node(Node::Slot(s))
    }

    fn bin(&mut self, op: BinOp, a: ExprId, b: ExprId) -> ExprId {
        self.node(Node::Binary(op, a, b, u32::MAX))
    }

    fn site(&mut self, ctx: Option<Ctx>, span: Span, what: String) -> SiteId {
        let (instance, state) = match ctx {
            Some(c) => (
                Some(c.inst),
                self.chart(c.inst).states[c.state as usize].path.clone(),
            ),
            None => (None, String::new()),
        };
        self.sites.push(Site {
            span,
            instance,
            state,
            what,
        });
        self.sites.len() as SiteId - 1
    }

    fn new_proc(&mut self, name: String) -> ProcId {
        self.procs.push(Proc {
            name,
            body: Vec::new(),
        });
        self.procs.len() as ProcId - 1
    }

    fn run(&mut self) -> Program {
        // `in(state)` of every state of every instance.
        for i in 0..self.sys.instances.len() as u32 {
            let chart = self.chart(i);
            let mut active = Vec::with_capacity(chart.states.len());
            for s in 0..chart.states.len() as StateId {
                let mut conj: Option<ExprId> = None;
                for n in chart.ancestry(s) {
                    let Some(p) = chart.states[n as usize].parent else {
                        continue;
                    };
                    if let NodeKind::Or { children, .. } = &chart.states[p as usize].kind {
                        let idx = children.iter().position(|c| *c == n).unwrap_or(0) as i64;
                        let slot =
                            self.lay.instances[i as usize].region_slots[p as usize].unwrap_or(0);
                        let sv = self.slot(slot);
                        let kv = self.konst(idx);
                        let eq = self.bin(BinOp::Eq, sv, kv);
                        conj = Some(match conj {
                            Some(c) => self.bin(BinOp::And, c, eq),
                            None => eq,
                        });
                    }
                }
                let e = match conj {
                    Some(e) => e,
                    None => self.konst(1),
                };
                active.push(e);
            }
            self.lay.instances[i as usize].active = active;
        }
        // State coverage items, in instance and state order.
        for i in 0..self.sys.instances.len() as u32 {
            let chart = self.chart(i);
            for (s, node) in chart.states.iter().enumerate() {
                if s == 0 || node.is_region {
                    continue;
                }
                self.covers.push(Cover {
                    instance: i,
                    kind: CoverKind::State(s as StateId),
                    label: node.path.clone(),
                    span: node.span,
                });
                self.state_covers
                    .insert((i, s as StateId), self.covers.len() as CoverId - 1);
            }
        }
        let mut init_calls = Vec::new();
        let mut step_calls = Vec::new();
        for &i in &self.sys.order {
            let (init, step) = self.instance(i);
            init_calls.push(Stmt::Call(init));
            step_calls.push(Stmt::Call(step));
        }
        let started = self.lay.started;
        let started_e = self.slot(started);
        let one = self.konst(1);
        let mut init_block = vec![Stmt::Assign {
            slot: started,
            expr: one,
            site: None,
        }];
        init_block.extend(init_calls);
        let mut step = vec![Stmt::If {
            cond: started_e,
            then: step_calls,
            otherwise: init_block,
        }];
        step.extend(self.monitors());
        let assumes = self
            .sys
            .assumes
            .iter()
            .map(|a| self.expr(a, None))
            .collect();
        let properties = self.properties();
        let (temporal, fairness) = {
            let props = &self.sys.properties;
            crate::temporal::lower(props, &mut |e| self.expr(e, None))
        };
        Program {
            name: self.sys.name.clone(),
            slots: std::mem::take(&mut self.lay.slots),
            n_state: self.lay.n_state,
            inputs: std::mem::take(&mut self.lay.inputs),
            nodes: std::mem::take(&mut self.nodes),
            procs: std::mem::take(&mut self.procs),
            step,
            sites: std::mem::take(&mut self.sites),
            covers: std::mem::take(&mut self.covers),
            instances: std::mem::take(&mut self.lay.instances),
            order: self.sys.order.clone(),
            assumes,
            properties,
            temporal,
            fairness,
            started,
            n_locals: self.locals.len(),
            code: std::sync::OnceLock::new(),
        }
    }

    /// The init and step procedures of one instance.
    fn instance(&mut self, i: u32) -> (ProcId, ProcId) {
        let chart = self.chart(i);
        let name = sanitize(&self.sys.instances[i as usize].name);
        let init = self.new_proc(format!("init_{name}"));
        let step = self.new_proc(format!("step_{name}"));
        // R3: clear output events; local events raised last tick become present.
        let mut prologue = Vec::new();
        for (v, var) in chart.vars.iter().enumerate() {
            if !var.is_event {
                continue;
            }
            let slot = self.lay.instances[i as usize].var_slots[v];
            match var.kind {
                VarKind::Output => {
                    let z = self.konst(0);
                    prologue.push(Stmt::Assign {
                        slot,
                        expr: z,
                        site: None,
                    });
                }
                VarKind::Local => {
                    if let Some(p) = self.lay.pending[i as usize][v] {
                        let pe = self.slot(p);
                        prologue.push(Stmt::Assign {
                            slot,
                            expr: pe,
                            site: None,
                        });
                        let z = self.konst(0);
                        prologue.push(Stmt::Assign {
                            slot: p,
                            expr: z,
                            site: None,
                        });
                    }
                }
                VarKind::Input => {}
            }
        }
        for a in self.lay.aborts[i as usize].clone().into_iter().flatten() {
            let z = self.konst(0);
            prologue.push(Stmt::Assign {
                slot: a,
                expr: z,
                site: None,
            });
        }
        // R1: tick 0 is the default entry of the root.
        let mut init_body = prologue.clone();
        let root_entry = self.enter_default(i, 0, false);
        init_body.push(Stmt::Call(root_entry));
        self.procs[init as usize].body = init_body;
        // R2/R4: later ticks walk the configuration.
        let mut step_body = prologue;
        step_body.extend(self.visit(i, 0));
        self.procs[step as usize].body = step_body;
        (init, step)
    }

    // ----- R4: the walk -------------------------------------------------------------------

    fn visit(&mut self, i: u32, s: StateId) -> Vec<Stmt> {
        let chart = self.chart(i);
        let node = &chart.states[s as usize];
        let mut out = Vec::new();
        if let Some((t, max)) = self.lay.timers[i as usize][s as usize] {
            let te = self.slot(t);
            let one = self.konst(1);
            let inc = self.bin(BinOp::Add, te, one);
            let mx = self.konst(max);
            let sat = self.node(Node::Min(inc, mx));
            out.push(Stmt::Assign {
                slot: t,
                expr: sat,
                site: None,
            });
        }
        let ctx = Ctx { inst: i, state: s };
        let mut rest = self.stmts(&node.during, ctx);
        rest.extend(self.descend(i, s));
        // Build the if / else-if chain from the last transition backwards.
        let mut chain = rest;
        for &t in node.transitions.iter().rev() {
            let cond = self.enabled(i, t);
            let fire = self.fire(i, t);
            chain = vec![Stmt::If {
                cond,
                then: fire,
                otherwise: chain,
            }];
        }
        out.extend(chain);
        out
    }

    fn descend(&mut self, i: u32, s: StateId) -> Vec<Stmt> {
        let chart = self.chart(i);
        match &chart.states[s as usize].kind {
            NodeKind::Simple => Vec::new(),
            NodeKind::Or { children, .. } => {
                let slot = self.region_slot(i, s);
                let cases = children.iter().map(|c| self.visit(i, *c)).collect();
                vec![Stmt::Switch { slot, cases }]
            }
            NodeKind::And { regions } => {
                let abort = self.lay.aborts[i as usize][s as usize];
                let mut out = Vec::new();
                for (k, r) in regions.iter().enumerate() {
                    let body = self.descend(i, *r);
                    match (k, abort) {
                        (0, _) | (_, None) => out.extend(body),
                        (_, Some(a)) => {
                            // R6: skip later regions once a transition has left this state.
                            let ae = self.slot(a);
                            let not = self.node(Node::Unary(UnOp::Not, ae));
                            out.push(Stmt::If {
                                cond: not,
                                then: body,
                                otherwise: Vec::new(),
                            });
                        }
                    }
                }
                out
            }
        }
    }

    fn region_slot(&self, i: u32, s: StateId) -> SlotId {
        self.lay.instances[i as usize].region_slots[s as usize].unwrap_or(0)
    }

    fn enabled(&mut self, i: u32, t: u32) -> ExprId {
        let chart = self.chart(i);
        let tr = &chart.transitions[t as usize];
        let mut parts = Vec::new();
        match tr.trigger {
            Trigger::None => {}
            Trigger::Event(v) => {
                let slot = self.lay.instances[i as usize].var_slots[v as usize];
                parts.push(self.slot(slot));
            }
            Trigger::After(n) => {
                if let Some((ts, _)) = self.lay.timers[i as usize][tr.source as usize] {
                    let te = self.slot(ts);
                    let ne = self.konst(n);
                    parts.push(self.bin(BinOp::Ge, te, ne));
                }
            }
        }
        let ctx = Ctx {
            inst: i,
            state: tr.source,
        };
        if let Some(g) = &tr.guard {
            parts.push(self.expr(g, Some(ctx)));
        }
        if let Some(v) = self.dest_valid(&tr.dest, ctx) {
            parts.push(v);
        }
        self.all(parts)
    }

    fn all(&mut self, parts: Vec<ExprId>) -> ExprId {
        let mut it = parts.into_iter();
        match it.next() {
            None => self.konst(1),
            Some(first) => it.fold(first, |acc, p| self.bin(BinOp::And, acc, p)),
        }
    }

    /// R7: the condition under which a destination leads to a state (`None` = always).
    fn dest_valid(&mut self, d: &Dest, ctx: Ctx) -> Option<ExprId> {
        match d {
            Dest::Internal | Dest::State(_) => None,
            Dest::Choice(branches) => {
                let mut any: Option<ExprId> = None;
                for b in branches {
                    let g = b.guard.as_ref().map(|g| self.expr(g, Some(ctx)));
                    let v = self.dest_valid(&b.dest, ctx);
                    let this = match (g, v) {
                        // An unguarded branch to a state: the choice can always fire.
                        (None, None) => return None,
                        (Some(g), None) => g,
                        (None, Some(v)) => v,
                        (Some(g), Some(v)) => self.bin(BinOp::And, g, v),
                    };
                    any = Some(match any {
                        Some(a) => self.bin(BinOp::Or, a, this),
                        None => this,
                    });
                }
                Some(any.unwrap_or_else(|| self.konst(0)))
            }
        }
    }

    // ----- R5: firing -----------------------------------------------------------------------

    fn fire(&mut self, i: u32, t: u32) -> Vec<Stmt> {
        let chart = self.chart(i);
        let tr = &chart.transitions[t as usize];
        let ctx = Ctx {
            inst: i,
            state: tr.source,
        };
        let label = transition_label(chart, tr);
        self.covers.push(Cover {
            instance: i,
            kind: CoverKind::Transition(t),
            label,
            span: tr.span,
        });
        let cover = self.covers.len() as CoverId - 1;
        let action = self.stmts(&tr.action, ctx);
        let mut out = vec![Stmt::Cover(cover)];
        let mut branch_counter = 0;
        out.extend(self.fire_dest(
            i,
            t,
            tr.source,
            &tr.dest,
            action,
            ctx,
            tr.span,
            &mut branch_counter,
        ));
        out
    }

    #[allow(clippy::too_many_arguments)] // reason: the recursion threads the same context through every branch
    fn fire_dest(
        &mut self,
        i: u32,
        t: u32,
        source: StateId,
        d: &Dest,
        actions: Vec<Stmt>,
        ctx: Ctx,
        span: Span,
        counter: &mut u32,
    ) -> Vec<Stmt> {
        match d {
            Dest::Internal => actions,
            Dest::State(target) => self.transition_path(i, source, *target, actions, span),
            Dest::Choice(branches) => {
                // An if / else-if chain over the branches, built back to front.
                let mut arms = Vec::new();
                for b in branches {
                    let index = *counter;
                    *counter += 1;
                    let chart = self.chart(i);
                    self.covers.push(Cover {
                        instance: i,
                        kind: CoverKind::Branch(t, index),
                        label: format!(
                            "{} [branch {}]",
                            transition_label(chart, &chart.transitions[t as usize]),
                            index + 1
                        ),
                        span: b.span,
                    });
                    let cover = self.covers.len() as CoverId - 1;
                    let g = b.guard.as_ref().map(|g| self.expr(g, Some(ctx)));
                    let v = self.dest_valid(&b.dest, ctx);
                    let cond = match (g, v) {
                        (None, None) => None,
                        (Some(g), None) => Some(g),
                        (None, Some(v)) => Some(v),
                        (Some(g), Some(v)) => Some(self.bin(BinOp::And, g, v)),
                    };
                    let mut acts = actions.clone();
                    acts.push(Stmt::Cover(cover));
                    acts.extend(self.stmts(&b.action, ctx));
                    let body = self.fire_dest(i, t, source, &b.dest, acts, ctx, b.span, counter);
                    arms.push((cond, body));
                }
                let mut chain: Vec<Stmt> = Vec::new();
                for (cond, body) in arms.into_iter().rev() {
                    chain = match cond {
                        None => body,
                        Some(c) => vec![Stmt::If {
                            cond: c,
                            then: body,
                            otherwise: chain,
                        }],
                    };
                }
                chain
            }
        }
    }

    /// Exit from `source`'s side of the scope, run `actions`, enter down to `target`.
    fn transition_path(
        &mut self,
        i: u32,
        source: StateId,
        target: StateId,
        actions: Vec<Stmt>,
        span: Span,
    ) -> Vec<Stmt> {
        let chart = self.chart(i);
        let src_chain = chart.ancestry(source);
        let tgt_chain = chart.ancestry(target);
        // The scope: innermost OR node that strictly contains both.
        let mut scope = None;
        for (k, n) in src_chain.iter().enumerate() {
            let strictly_src = k + 1 < src_chain.len();
            let strictly_tgt = tgt_chain.len() > k + 1 && tgt_chain[k] == *n;
            if !(strictly_src && strictly_tgt) {
                break;
            }
            if matches!(chart.states[*n as usize].kind, NodeKind::Or { .. }) {
                scope = Some(k);
            }
        }
        let Some(k) = scope else {
            self.diags.push(
                Diagnostic::error("E0131", "this transition would leave the chart's top level", span)
                    .with_label("source and target are in different top-level regions")
                    .with_hint("transitions between parallel regions of the chart itself are not possible; wrap the regions in a state"),
            );
            return actions;
        };
        let exit_top = src_chain[k + 1];
        let mut out = Vec::new();
        // R6: every parallel state being left stops its remaining regions.
        for n in &src_chain[k + 1..] {
            if let Some(a) = self.lay.aborts[i as usize][*n as usize] {
                let one = self.konst(1);
                out.push(Stmt::Assign {
                    slot: a,
                    expr: one,
                    site: None,
                });
            }
        }
        let exit = self.exit_proc(i, exit_top);
        out.push(Stmt::Call(exit));
        out.extend(actions);
        out.extend(self.enter_chain(i, &tgt_chain[k + 1..]));
        out
    }

    /// Exit a state: its active descendants first (innermost first, regions in reverse order),
    /// then its exit action; reset its timer and, unless history must remember it, its active
    /// child, so that equal configurations have equal state vectors.
    fn exit_proc(&mut self, i: u32, s: StateId) -> ProcId {
        if let Some(p) = self.exit_procs.get(&(i, s)) {
            return *p;
        }
        let chart = self.chart(i);
        let name = format!(
            "exit_{}_{}",
            sanitize(&self.sys.instances[i as usize].name),
            sanitize(&chart.states[s as usize].path)
        );
        let id = self.new_proc(name);
        self.exit_procs.insert((i, s), id);
        let mut body = Vec::new();
        match chart.states[s as usize].kind.clone() {
            NodeKind::Simple => {}
            NodeKind::Or { .. } => body.extend(self.exit_or(i, s)),
            NodeKind::And { regions } => {
                for r in regions.iter().rev() {
                    body.extend(self.exit_or(i, *r));
                }
            }
        }
        body.extend(self.stmts(&chart.states[s as usize].exit, Ctx { inst: i, state: s }));
        if let Some((t, _)) = self.lay.timers[i as usize][s as usize] {
            let z = self.konst(0);
            body.push(Stmt::Assign {
                slot: t,
                expr: z,
                site: None,
            });
        }
        self.procs[id as usize].body = body;
        id
    }

    fn exit_or(&mut self, i: u32, n: StateId) -> Vec<Stmt> {
        let chart = self.chart(i);
        let NodeKind::Or {
            children, initial, ..
        } = chart.states[n as usize].kind.clone()
        else {
            return Vec::new();
        };
        let slot = self.region_slot(i, n);
        let cases = children
            .iter()
            .map(|c| vec![Stmt::Call(self.exit_proc(i, *c))])
            .collect();
        let mut out = vec![Stmt::Switch { slot, cases }];
        if !crate::layout::remembers(chart, n) {
            let v = self.konst(initial as i64);
            out.push(Stmt::Assign {
                slot,
                expr: v,
                site: None,
            });
        }
        out
    }

    /// Enter the states of `chain` (outermost first), then the last one's default entry.
    fn enter_chain(&mut self, i: u32, chain: &[StateId]) -> Vec<Stmt> {
        let Some((&x, rest)) = chain.split_first() else {
            return Vec::new();
        };
        let chart = self.chart(i);
        let mut out = Vec::new();
        if let Some(p) = chart.states[x as usize].parent {
            if let NodeKind::Or { children, .. } = &chart.states[p as usize].kind {
                let idx = children.iter().position(|c| *c == x).unwrap_or(0) as i64;
                let slot = self.region_slot(i, p);
                let v = self.konst(idx);
                out.push(Stmt::Assign {
                    slot,
                    expr: v,
                    site: None,
                });
                out.extend(self.mark_visited(i, p));
            }
        }
        out.extend(self.entry_of(i, x));
        if rest.is_empty() {
            out.extend(self.enter_children(i, x, false));
            return out;
        }
        match chart.states[x as usize].kind.clone() {
            NodeKind::And { regions } => {
                for r in regions {
                    if r == rest[0] {
                        out.extend(self.enter_chain(i, rest));
                    } else {
                        let p = self.enter_default(i, r, false);
                        out.push(Stmt::Call(p));
                    }
                }
            }
            _ => out.extend(self.enter_chain(i, rest)),
        }
        out
    }

    /// Record that a remembering OR node has been entered (no-op for other nodes).
    fn mark_visited(&mut self, i: u32, n: StateId) -> Vec<Stmt> {
        match self.lay.visited[i as usize][n as usize] {
            Some(vis) => {
                let one = self.konst(1);
                vec![Stmt::Assign {
                    slot: vis,
                    expr: one,
                    site: None,
                }]
            }
            None => Vec::new(),
        }
    }

    /// Coverage count and entry action of a state (nothing for regions and the root's cover).
    fn entry_of(&mut self, i: u32, s: StateId) -> Vec<Stmt> {
        let chart = self.chart(i);
        let mut out = Vec::new();
        if let Some(c) = self.state_covers.get(&(i, s)) {
            out.push(Stmt::Cover(*c));
        }
        out.extend(self.stmts(&chart.states[s as usize].entry, Ctx { inst: i, state: s }));
        out
    }

    /// Default entry of a state (R8 for history): entry action, then its children.
    fn enter_default(&mut self, i: u32, s: StateId, deep: bool) -> ProcId {
        if let Some(p) = self.enter_procs.get(&(i, s, deep)) {
            return *p;
        }
        let chart = self.chart(i);
        let name = format!(
            "enter_{}{}_{}",
            if deep { "deep_" } else { "" },
            sanitize(&self.sys.instances[i as usize].name),
            sanitize(&chart.states[s as usize].path)
        );
        let id = self.new_proc(name);
        self.enter_procs.insert((i, s, deep), id);
        let mut body = self.entry_of(i, s);
        body.extend(self.enter_children(i, s, deep));
        self.procs[id as usize].body = body;
        id
    }

    fn enter_children(&mut self, i: u32, s: StateId, deep: bool) -> Vec<Stmt> {
        let chart = self.chart(i);
        match chart.states[s as usize].kind.clone() {
            NodeKind::Simple => Vec::new(),
            NodeKind::And { regions } => regions
                .iter()
                .map(|r| Stmt::Call(self.enter_default(i, *r, deep)))
                .collect(),
            NodeKind::Or {
                children,
                initial,
                history,
            } => {
                let slot = self.region_slot(i, s);
                // The default path: the initial action, then the initial child.
                let mut default = self.stmts(
                    &chart.states[s as usize].initial_action,
                    Ctx { inst: i, state: s },
                );
                let v = self.konst(initial as i64);
                default.push(Stmt::Assign {
                    slot,
                    expr: v,
                    site: None,
                });
                default.push(Stmt::Call(self.enter_default(i, children[initial], false)));
                let visited = self.lay.visited[i as usize][s as usize];
                match (deep || history.is_some(), visited) {
                    (true, Some(vis)) => {
                        // R8: resume the remembered child once the node has been entered before.
                        let child_deep = deep || history == Some(HistoryKind::Deep);
                        let cases = children
                            .iter()
                            .map(|c| vec![Stmt::Call(self.enter_default(i, *c, child_deep))])
                            .collect();
                        let ve = self.slot(vis);
                        let one = self.konst(1);
                        vec![
                            Stmt::If {
                                cond: ve,
                                then: vec![Stmt::Switch { slot, cases }],
                                otherwise: default,
                            },
                            Stmt::Assign {
                                slot: vis,
                                expr: one,
                                site: None,
                            },
                        ]
                    }
                    _ => {
                        default.extend(self.mark_visited(i, s));
                        default
                    }
                }
            }
        }
    }

    // ----- actions and expressions --------------------------------------------------------

    fn stmts(&mut self, stmts: &[m::Stmt], ctx: Ctx) -> Vec<Stmt> {
        stmts.iter().map(|s| self.stmt(s, ctx)).collect()
    }

    fn stmt(&mut self, s: &m::Stmt, ctx: Ctx) -> Stmt {
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
    fn expr(&mut self, e: &m::Expr, ctx: Option<Ctx>) -> ExprId {
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

    // ----- properties -----------------------------------------------------------------------

    /// Statements that advance the `respond` monitors after every tick.
    fn monitors(&mut self) -> Vec<Stmt> {
        let mut out = Vec::new();
        for (p, prop) in self.sys.properties.iter().enumerate() {
            let m::PropertyKind::Respond {
                trigger, response, ..
            } = &prop.kind
            else {
                continue;
            };
            let Some(mon) = self.lay.monitors[p] else {
                continue;
            };
            let r = self.expr(response, None);
            let t = self.expr(trigger, None);
            let me = self.slot(mon);
            let zero = self.konst(0);
            let one = self.konst(1);
            let waiting = self.bin(BinOp::Gt, me, zero);
            let inc = self.bin(BinOp::Add, me, one);
            let hi = self.konst(self.lay.slots[mon as usize].hi);
            let inc = self.node(Node::Min(inc, hi));
            // respond: 0 = no obligation; k = the oldest unanswered trigger was k-1 ticks ago.
            out.push(Stmt::If {
                cond: r,
                then: vec![Stmt::Assign {
                    slot: mon,
                    expr: zero,
                    site: None,
                }],
                otherwise: vec![Stmt::If {
                    cond: waiting,
                    then: vec![Stmt::Assign {
                        slot: mon,
                        expr: inc,
                        site: None,
                    }],
                    otherwise: vec![Stmt::If {
                        cond: t,
                        then: vec![Stmt::Assign {
                            slot: mon,
                            expr: one,
                            site: None,
                        }],
                        otherwise: Vec::new(),
                    }],
                }],
            });
        }
        out
    }

    fn properties(&mut self) -> Vec<Property> {
        let mut out = Vec::new();
        for (p, prop) in self.sys.properties.iter().enumerate() {
            let kind = match &prop.kind {
                m::PropertyKind::Invariant { expr, assuming } => PropertyKind::Invariant {
                    expr: self.expr(expr, None),
                    assuming: assuming.as_ref().map(|a| self.expr(a, None)),
                },
                m::PropertyKind::Reachable { expr } => PropertyKind::Reachable {
                    expr: self.expr(expr, None),
                },
                m::PropertyKind::Respond { within, .. } => {
                    let Some(mon) = self.lay.monitors[p] else {
                        continue;
                    };
                    let me = self.slot(mon);
                    let w = self.konst(*within);
                    PropertyKind::Respond {
                        monitor: mon,
                        within: *within,
                        ok: self.bin(BinOp::Le, me, w),
                    }
                }
                // Temporal properties: `crate::temporal`.
                _ => continue,
            };
            out.push(Property {
                name: prop.name.clone(),
                kind,
                span: prop.span,
            });
        }
        for i in 0..self.sys.instances.len() as u32 {
            let chart = self.chart(i);
            if chart.role != m::ChartRole::Observer {
                continue;
            }
            let Some(err) = chart.state_by_path("error") else {
                continue;
            };
            let active = self.lay.instances[i as usize].active[err as usize];
            let ok = self.node(Node::Unary(UnOp::Not, active));
            out.push(Property {
                name: chart.name.clone(),
                kind: PropertyKind::Observer { instance: i, ok },
                span: chart.span,
            });
        }
        out
    }
}

fn transition_label(chart: &Chart, tr: &m::Transition) -> String {
    let src = &chart.states[tr.source as usize].path;
    let src = if src.is_empty() { "(chart)" } else { src };
    match &tr.dest {
        Dest::Internal => format!("{src} (internal)"),
        Dest::State(t) => format!("{src} -> {}", chart.states[*t as usize].path),
        Dest::Choice(_) => format!("{src} -> (choice)"),
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

/// A name usable as an identifier in generated code.
pub fn sanitize(s: &str) -> String {
    let out: String = s
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    if out.is_empty() {
        "root".into()
    } else {
        out
    }
}
