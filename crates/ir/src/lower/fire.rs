//! R4–R7: the walk of the active configuration, transition enabling and firing (exit to the
//! scope, actions, choice branches, entry to the target), parallel-region aborts.

use super::{Ctx, Lowerer};
use crate::program::*;
use statecheck_base::{Diagnostic, Span};
use statecheck_model as m;
use statecheck_model::{Chart, Dest, NodeKind, StateId, Trigger};
use statecheck_syntax::ast::{BinOp, UnOp};

impl Lowerer<'_> {
    pub(super) fn visit(&mut self, i: u32, s: StateId) -> Vec<Stmt> {
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

    pub(super) fn descend(&mut self, i: u32, s: StateId) -> Vec<Stmt> {
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

    pub(super) fn region_slot(&self, i: u32, s: StateId) -> SlotId {
        self.lay.instances[i as usize].region_slots[s as usize].unwrap_or(0)
    }

    pub(super) fn enabled(&mut self, i: u32, t: u32) -> ExprId {
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

    pub(super) fn all(&mut self, parts: Vec<ExprId>) -> ExprId {
        let mut it = parts.into_iter();
        match it.next() {
            None => self.konst(1),
            Some(first) => it.fold(first, |acc, p| self.bin(BinOp::And, acc, p)),
        }
    }

    /// R7: the condition under which a destination leads to a state (`None` = always).
    pub(super) fn dest_valid(&mut self, d: &Dest, ctx: Ctx) -> Option<ExprId> {
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

    pub(super) fn fire(&mut self, i: u32, t: u32) -> Vec<Stmt> {
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
            expected_unreached: leads_only_to_observer_error(chart, &tr.dest),
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
    pub(super) fn fire_dest(
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
                        expected_unreached: leads_only_to_observer_error(chart, &b.dest),
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
    pub(super) fn transition_path(
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

/// True when every state `d` may lead to is an observer's `error` state (such a transition
/// fires only when the observer's property is violated).
fn leads_only_to_observer_error(chart: &statecheck_model::Chart, d: &Dest) -> bool {
    match d {
        Dest::Internal => false,
        Dest::State(s) => chart.is_observer_error(*s),
        Dest::Choice(branches) => branches
            .iter()
            .all(|b| leads_only_to_observer_error(chart, &b.dest)),
    }
}
