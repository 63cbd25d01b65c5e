//! Checking property declarations (invariant, reachable, respond, and the temporal ones).

use crate::expr::ExprChecker;
use crate::formula::{self, Logic};
use crate::model::{Property, PropertyKind};
use crate::scope::Scope;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast;

/// Check a list of properties in a scope.
pub(crate) fn check_properties(
    ck: &mut ExprChecker,
    scope: &Scope,
    props: &[ast::Property],
) -> Vec<Property> {
    props
        .iter()
        .map(|p| {
            let kind = match &p.kind {
                ast::PropertyKind::Invariant { expr, assuming } => PropertyKind::Invariant {
                    expr: ck.check_bool(scope, expr),
                    assuming: assuming.as_ref().map(|a| ck.check_bool(scope, a)),
                },
                ast::PropertyKind::Reachable { expr } => PropertyKind::Reachable {
                    expr: ck.check_bool(scope, expr),
                },
                ast::PropertyKind::Respond {
                    trigger,
                    response,
                    within,
                } => {
                    let n = crate::duration::delay_ticks(ck, scope, within).unwrap_or(0);
                    let span = match within {
                        ast::Delay::Ticks(e) => e.span(),
                        ast::Delay::Time(d) => d.span,
                    };
                    if !(0..=1_000_000).contains(&n) {
                        ck.sink.push(
                            Diagnostic::error(
                                "E0104",
                                format!("`within {n}` must be between 0 and 1000000 ticks"),
                                span,
                            )
                            .with_label("out of range"),
                        );
                    }
                    PropertyKind::Respond {
                        trigger: ck.check_bool(scope, trigger),
                        response: ck.check_bool(scope, response),
                        within: n.clamp(0, 1_000_000),
                    }
                }
                ast::PropertyKind::RespondEventually { trigger, response } => {
                    PropertyKind::RespondEventually {
                        trigger: ck.check_bool(scope, trigger),
                        response: ck.check_bool(scope, response),
                    }
                }
                ast::PropertyKind::Ltl { formula } => {
                    PropertyKind::Ltl(formula::check(ck, scope, formula, Logic::Ltl))
                }
                ast::PropertyKind::Ctl { formula } => {
                    PropertyKind::Ctl(formula::check(ck, scope, formula, Logic::Ctl))
                }
                ast::PropertyKind::Nonblocking { expr } => PropertyKind::Nonblocking {
                    expr: ck.check_bool(scope, expr),
                },
                ast::PropertyKind::Fair { trigger, expr } => PropertyKind::Fair {
                    trigger: trigger.as_ref().map(|t| ck.check_bool(scope, t)),
                    expr: ck.check_bool(scope, expr),
                },
            };
            Property {
                name: p.name.name.clone(),
                kind,
                span: p.name.span,
            }
        })
        .collect()
}
