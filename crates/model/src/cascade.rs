//! Cascade suppression: one mistake, one diagnostic.
//!
//! An instance whose chart name is unknown (E0101 on the chart name) makes every later use of
//! that instance in its system unresolvable: its connections, `order`, properties and
//! `in(inst.State)` would each report E0101 again. Those follow from the first error and say
//! nothing new, so they are dropped; the chart name's E0101 (with its "did you mean" hint)
//! stays.

use statecheck_base::Diagnostic;
use statecheck_syntax::ast;

/// Drop the E0101 diagnostics that name an instance of an unknown chart, inside its system.
pub(crate) fn suppress(file: &ast::File, diags: &mut Vec<Diagnostic>) {
    let charts: Vec<&str> = file
        .items
        .iter()
        .filter_map(|i| match i {
            ast::Item::Chart(c) => Some(c.name.name.as_str()),
            _ => None,
        })
        .collect();
    for item in &file.items {
        let ast::Item::System(s) = item else { continue };
        for inst in &s.instances {
            if charts.contains(&inst.chart.name.as_str()) {
                continue;
            }
            let name = &inst.name.name;
            let mentions = |m: &str| {
                m.contains(&format!("`{name}`"))
                    || m.contains(&format!("`{name}."))
                    || m.contains(&format!("`{name}["))
            };
            diags.retain(|d| {
                let inside = s.span.start <= d.span.start && d.span.end <= s.span.end;
                let is_cause = d.span == inst.chart.span;
                !(d.code == "E0101" && inside && !is_cause && mentions(&d.message))
            });
        }
    }
}
