//! `rate instance.input = P;` in a system: the probability that random simulation makes a free
//! boolean input true (an input event present) in a tick. Only random simulation reads it; it
//! constrains nothing, so the checkers ignore it (the `assume`s say what is possible, a rate
//! only how likely).

use crate::expr::ExprChecker;
use crate::model::{Connection, InputRate, Instance};
use crate::scope::Scope;
use crate::types::Type;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast::{self, VarKind};

/// Check a system's `rate` declarations against its instances and connections.
pub(crate) fn check_rates(
    ck: &mut ExprChecker,
    scope: &Scope,
    s: &ast::System,
    instances: &[Instance],
    connections: &[Connection],
) -> Vec<InputRate> {
    let mut out: Vec<InputRate> = Vec::new();
    for r in &s.rates {
        let rate = match r.value.parse::<f64>() {
            Ok(x) if (0.0..=1.0).contains(&x) => x,
            _ => {
                ck.sink.push(
                    Diagnostic::error(
                        "E0125",
                        format!("the rate `{}` is not a probability", r.value),
                        r.value_span,
                    )
                    .with_label("must be from 0 to 1")
                    .with_hint("a rate is the probability per tick, e.g. `0.01` for once in about 100 ticks"),
                );
                continue;
            }
        };
        let Some(targets) = crate::system::endpoint(ck, scope, &r.target, true) else {
            continue;
        };
        for (inst, var) in targets {
            let chart = &scope.charts[instances[inst as usize].chart as usize];
            let v = &chart.vars[var as usize];
            let name = format!("{}.{}", instances[inst as usize].name, v.name);
            let problem = if v.kind != VarKind::Input {
                Some((
                    format!("`{}` of `{}` is not an input", v.name, chart.name),
                    "a rate applies to a free input of the system".to_string(),
                ))
            } else if v.ty != Type::Bool && !v.is_event {
                Some((
                    format!("`{name}` is not a boolean input or an input event"),
                    "a rate is the probability of `true` (or of presence): integers and enums are drawn uniformly within their range and the `assume`s".to_string(),
                ))
            } else if connections.iter().any(|c| c.to == (inst, var)) {
                Some((
                    format!("`{name}` is driven by a connection"),
                    "a rate applies to a free input; this one takes the value of the connected output".to_string(),
                ))
            } else {
                None
            };
            if let Some((msg, hint)) = problem {
                ck.sink.push(
                    Diagnostic::error("E0125", msg, r.target.span)
                        .with_label("not a free boolean input")
                        .with_hint(hint),
                );
                continue;
            }
            if let Some(prev) = out.iter().find(|x| (x.instance, x.var) == (inst, var)) {
                ck.sink.push(
                    Diagnostic::error("E0125", format!("`{name}` has two rates"), r.span)
                        .with_label("second rate")
                        .with_secondary(prev.span, "first given here")
                        .with_hint("give each input one rate"),
                );
                continue;
            }
            out.push(InputRate {
                instance: inst,
                var,
                rate,
                span: r.span,
            });
        }
    }
    out
}
