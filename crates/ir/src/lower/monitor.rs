//! Properties: the monitors that advance `respond` properties after every tick, and each
//! property's expressions.

use super::Lowerer;
use crate::program::*;
use statecheck_model as m;
use statecheck_syntax::ast::{BinOp, UnOp};

impl Lowerer<'_> {
    /// Statements that advance the `respond` monitors after every tick.
    pub(super) fn monitors(&mut self) -> Vec<Stmt> {
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

    pub(super) fn properties(&mut self) -> Vec<Property> {
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
                goal: goal_of(&kind),
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
            let kind = PropertyKind::Observer { instance: i, ok };
            out.push(Property {
                name: chart.name.clone(),
                goal: goal_of(&kind),
                kind,
                span: chart.span,
            });
        }
        out
    }
}

/// What a property asks of every state after a tick: the one place that says what each kind
/// of property means to its consumers.
fn goal_of(kind: &PropertyKind) -> Goal {
    match *kind {
        PropertyKind::Invariant { expr, assuming } => Goal::Always {
            when: assuming,
            holds: expr,
        },
        PropertyKind::Reachable { expr } => Goal::Reach { target: expr },
        PropertyKind::Respond { ok, .. } | PropertyKind::Observer { ok, .. } => Goal::Always {
            when: None,
            holds: ok,
        },
    }
}
