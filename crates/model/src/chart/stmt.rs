//! Statements of actions: assignments, `raise`, `if`, and their checks in a chart scope.

use crate::expr::{is_placeholder, type_name, ExprChecker};
use crate::model::Stmt;
use crate::scope::Scope;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast::{self, VarKind};

/// Check a block of statements in a chart scope.
pub(crate) fn check_block(ck: &mut ExprChecker, scope: &Scope, b: &ast::Block) -> Vec<Stmt> {
    b.stmts
        .iter()
        .filter_map(|s| check_stmt(ck, scope, s))
        .collect()
}

pub(super) fn check_stmt(ck: &mut ExprChecker, scope: &Scope, s: &ast::Stmt) -> Option<Stmt> {
    let chart = scope.chart?;
    match s {
        // (Indices and loops are expanded before checking, `crate::arrays`.)
        ast::Stmt::For { .. } => None,
        ast::Stmt::Assign {
            target,
            value,
            span,
            ..
        } => {
            let value = ck.check(scope, value);
            let Some(v) = chart.var(&target.name) else {
                let mut d = Diagnostic::error(
                    "E0101",
                    format!("unknown variable `{}`", target.name),
                    target.span,
                )
                .with_label("not declared in this chart");
                if let Some(s) = crate::suggest::closest(
                    &target.name,
                    chart.vars.iter().map(|v| v.name.as_str()),
                ) {
                    d = d.with_hint(format!("did you mean `{s}`?"));
                } else {
                    d = d.with_hint(format!(
                        "declare it: `local {}: int[0..10] = 0;`",
                        target.name
                    ));
                }
                ck.sink.push(d);
                return None;
            };
            let var = &chart.vars[v as usize];
            if var.is_event {
                ck.sink.push(
                    Diagnostic::error(
                        "E0110",
                        format!(
                            "`{}` is an event; events are raised, not assigned",
                            var.name
                        ),
                        target.span,
                    )
                    .with_hint(format!("write `raise {};`", var.name)),
                );
                return None;
            }
            if var.kind == VarKind::Input {
                ck.sink.push(
                    Diagnostic::error(
                        "E0110",
                        format!("cannot assign to input `{}`", var.name),
                        target.span,
                    )
                    .with_label("inputs are read-only inside the chart")
                    .with_secondary(var.span, "declared as an input here")
                    .with_hint("declare it `output` or `local` if the chart computes it"),
                );
                return None;
            }
            let before = value.ty;
            let value = ck.coerce(value, var.ty, &format!("assignment to `{}`", var.name));
            let checked = matches!(value.kind, crate::model::ExprKind::Check(..));
            let value = match value.kind {
                // The assignment itself performs the range check, so unwrap it here.
                crate::model::ExprKind::Check(inner, ..) => *inner,
                _ => value,
            };
            let _ = (
                before,
                is_placeholder(&value),
                type_name(ck.globals, var.ty),
            );
            Some(Stmt::Assign {
                var: v,
                value,
                checked,
                span: *span,
            })
        }
        ast::Stmt::Raise { event, span } => {
            let Some(v) = chart.var(&event.name) else {
                ck.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!("unknown event `{}`", event.name),
                        event.span,
                    )
                    .with_hint(format!("declare it: `local event {};`", event.name)),
                );
                return None;
            };
            let var = &chart.vars[v as usize];
            if !var.is_event || var.kind == VarKind::Input {
                ck.sink.push(
                    Diagnostic::error(
                        "E0116",
                        format!("cannot raise `{}`", event.name),
                        event.span,
                    )
                    .with_label(if var.is_event {
                        "input events come from outside"
                    } else {
                        "not an event"
                    })
                    .with_hint("only `local event` and `output event` declarations can be raised"),
                );
                return None;
            }
            Some(Stmt::Raise {
                event: v,
                span: *span,
            })
        }
        ast::Stmt::If {
            cond,
            then,
            otherwise,
            ..
        } => {
            let cond = ck.check_bool(scope, cond);
            let then = check_block(ck, scope, then);
            let otherwise = otherwise
                .as_ref()
                .map(|b| check_block(ck, scope, b))
                .unwrap_or_default();
            Some(Stmt::If {
                cond,
                then,
                otherwise,
            })
        }
    }
}
