//! Event renames on component instances: refused (E0191). A component has no events of its
//! own; its chart instances rename theirs (docs/synthesis.md, "Event renaming"). Renames on
//! chart instances are checked with the system (`system.rs`).

use statecheck_base::Diagnostic;
use statecheck_syntax::ast;

/// E0191 when `inst`, an instance of a component, has a rename block.
pub(super) fn refuse_on_component(inst: &ast::Instance) -> Option<Diagnostic> {
    let r = inst.renames.first()?;
    Some(
        Diagnostic::error(
            "E0191",
            format!(
                "`{}` is a component: only a chart instance renames events",
                inst.chart.name
            ),
            r.span,
        )
        .with_label("rename of a component instance")
        .with_hint("rename the events on the chart instances inside the component"),
    )
}
