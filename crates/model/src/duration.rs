//! Delays and bounds written in ticks (`after(3)`, `within 20`) or in time units with the
//! file's `tick` declaration (`after(3 s)`, `within 2 s`), converted to ticks once, here.

use crate::expr::ExprChecker;
use crate::scope::Scope;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast;

/// A delay or bound in ticks: a constant tick count as written, or a duration converted with
/// the file's `tick` (`None` after reporting why it has no value).
pub(crate) fn delay_ticks(ck: &mut ExprChecker, scope: &Scope, d: &ast::Delay) -> Option<i64> {
    match d {
        ast::Delay::Ticks(e) => ck.const_value(scope, e),
        ast::Delay::Time(d) => duration_ticks(ck, scope, d),
    }
}

/// A duration in ticks with the file's `tick` length; E0120 when there is none or the
/// duration is not a whole number of ticks.
fn duration_ticks(ck: &mut ExprChecker, scope: &Scope, d: &ast::Duration) -> Option<i64> {
    let amount = ck.const_value(scope, &d.amount)?;
    let ms = match d.unit {
        ast::TimeUnit::Ms => amount,
        ast::TimeUnit::S => amount.checked_mul(1000)?,
        ast::TimeUnit::Min => amount.checked_mul(60_000)?,
    };
    let Some(tick) = ck.globals.tick_ms else {
        ck.sink.push(
            Diagnostic::error("E0120", "a delay in time units needs a tick length", d.span)
                .with_label("how many ticks is this?")
                .with_hint("declare the tick length at the top of the file, e.g. `tick 100 ms;`"),
        );
        return None;
    };
    if ms % tick != 0 {
        ck.sink.push(
            Diagnostic::error(
                "E0120",
                format!("{ms} ms is not a whole number of {tick} ms ticks"),
                d.span,
            )
            .with_hint("choose a delay that is a multiple of the tick length"),
        );
        return None;
    }
    Some(ms / tick)
}
