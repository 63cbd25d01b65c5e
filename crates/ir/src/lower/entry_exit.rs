//! R5 and R8: exit procedures (innermost first, regions in reverse order), entry chains and
//! default entry, with shallow and deep history.

use super::{sanitize, Ctx, Lowerer};
use crate::program::*;
use statecheck_model::{NodeKind, StateId};
use statecheck_syntax::ast::HistoryKind;

impl Lowerer<'_> {
    /// Exit a state: its active descendants first (innermost first, regions in reverse order),
    /// then its exit action; reset its timer and, unless history must remember it, its active
    /// child, so that equal configurations have equal state vectors.
    pub(super) fn exit_proc(&mut self, i: u32, s: StateId) -> ProcId {
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

    pub(super) fn exit_or(&mut self, i: u32, n: StateId) -> Vec<Stmt> {
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
    pub(super) fn enter_chain(&mut self, i: u32, chain: &[StateId]) -> Vec<Stmt> {
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
    pub(super) fn mark_visited(&mut self, i: u32, n: StateId) -> Vec<Stmt> {
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
    pub(super) fn entry_of(&mut self, i: u32, s: StateId) -> Vec<Stmt> {
        let chart = self.chart(i);
        let mut out = Vec::new();
        if let Some(c) = self.state_covers.get(&(i, s)) {
            out.push(Stmt::Cover(*c));
        }
        out.extend(self.stmts(&chart.states[s as usize].entry, Ctx { inst: i, state: s }));
        out
    }

    /// Default entry of a state (R8 for history): entry action, then its children.
    pub(super) fn enter_default(&mut self, i: u32, s: StateId, deep: bool) -> ProcId {
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

    pub(super) fn enter_children(&mut self, i: u32, s: StateId, deep: bool) -> Vec<Stmt> {
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
}
