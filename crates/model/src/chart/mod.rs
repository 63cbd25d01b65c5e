//! Checking one chart: variables, the state hierarchy, actions and transitions.

use crate::expr::ExprChecker;
use crate::model::{Chart, StateId, Stmt};
use crate::scope::Scope;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast;
use std::collections::HashMap;

mod hierarchy;
mod stmt;
mod transition;

pub(crate) use hierarchy::{skeleton, Skeleton};
pub(crate) use stmt::check_block;
use transition::check_transition;

/// Phase 2: actions, transitions and chart properties, with the complete hierarchy in scope.
pub(crate) fn fill(
    ck: &mut ExprChecker,
    sk: Skeleton,
    c: &ast::Chart,
    scope_instances: Option<&HashMap<String, crate::scope::InstanceGroup>>,
    charts: &[Chart],
) -> Chart {
    let Skeleton { mut chart, bodies } = sk;
    let snapshot = chart.clone();
    let scope = Scope {
        chart: Some(&snapshot),
        instances: scope_instances,
        charts,
        locals: Vec::new(),
        fn_limit: usize::MAX,
    };
    let mut transitions = Vec::new();
    for (id, body) in bodies.iter().enumerate() {
        let block = |ck: &mut ExprChecker, blocks: &[ast::Block]| -> Vec<Stmt> {
            blocks
                .iter()
                .flat_map(|b| check_block(ck, &scope, b))
                .collect()
        };
        let entry = block(ck, &body.entry);
        let during = block(ck, &body.during);
        let exit = block(ck, &body.exit);
        let initial_action = body
            .initial
            .first()
            .and_then(|i| i.action.as_ref())
            .map(|b| check_block(ck, &scope, b))
            .unwrap_or_default();
        for kind in [
            (&body.entry, "entry"),
            (&body.during, "during"),
            (&body.exit, "exit"),
        ] {
            if let Some(b) = kind.0.get(1) {
                ck.sink.push(
                    Diagnostic::error("E0108", format!("more than one `{}` block", kind.1), b.span)
                        .with_secondary(kind.0[0].span, "first one here")
                        .with_hint("merge them into one block"),
                );
            }
        }
        let node = &mut chart.states[id];
        node.entry = entry;
        node.during = during;
        node.exit = exit;
        node.initial_action = initial_action;
        let mut own = Vec::new();
        for (text_index, t) in body.transitions.iter().enumerate() {
            let tr = check_transition(ck, &scope, &snapshot, &bodies, id as StateId, t);
            own.push((
                tr.priority.is_none(),
                tr.priority.unwrap_or(0),
                text_index,
                tr,
            ));
        }
        own.sort_by_key(|(implicit, p, i, _)| (*implicit, *p, *i));
        for (_, _, _, tr) in own {
            let tid = transitions.len() as u32;
            transitions.push(tr);
            chart.states[id].transitions.push(tid);
        }
    }
    chart.transitions = transitions;
    chart.properties = crate::property::check_properties(ck, &scope, &c.properties);
    chart
}
