//! Cascade suppression: one mistake, one diagnostic.
//!
//! An instance whose chart name is unknown (E0101 on the chart name) makes every later use of
//! that instance in its system unresolvable: its connections, `order`, properties and
//! `in(inst.State)` would each report E0101 again. Those follow from the first error and say
//! nothing new, so they are dropped; the chart name's E0101 (with its "did you mean" hint)
//! stays.

use statecheck_base::Diagnostic;
use statecheck_syntax::ast;
use std::collections::HashSet;

/// Drop the E0101 diagnostics that name an instance of an unknown chart, inside its system.
///
/// One pass over the diagnostics per system, with the system's instances of unknown charts in
/// a set: a pass per instance (with three `format!`s per diagnostic) was instances ×
/// diagnostics, minutes for a flattened system of thousands of such instances.
pub(crate) fn suppress(file: &ast::File, diags: &mut Vec<Diagnostic>) {
    let charts: HashSet<&str> = file
        .items
        .iter()
        .filter_map(|i| match i {
            ast::Item::Chart(c) => Some(c.name.name.as_str()),
            _ => None,
        })
        .collect();
    for item in &file.items {
        let ast::Item::System(s) = item else { continue };
        let unknown: Vec<&ast::Instance> = s
            .instances
            .iter()
            .filter(|i| !charts.contains(i.chart.name.as_str()))
            .collect();
        if unknown.is_empty() {
            continue;
        }
        let names: HashSet<&str> = unknown.iter().map(|i| i.name.name.as_str()).collect();
        let causes: HashSet<statecheck_base::Span> = unknown.iter().map(|i| i.chart.span).collect();
        diags.retain(|d| {
            let inside = s.span.start <= d.span.start && d.span.end <= s.span.end;
            !(d.code == "E0101"
                && inside
                && !causes.contains(&d.span)
                && mentions(&d.message, &names))
        });
    }
}

/// Whether `message` quotes one of `names` as `` `name` ``, `` `name.…` `` or `` `name[…` ``:
/// every text after a backtick up to a backtick, `.` or `[` (before the next backtick) is a
/// candidate.
fn mentions(message: &str, names: &HashSet<&str>) -> bool {
    let b = message.as_bytes();
    for (i, &c) in b.iter().enumerate() {
        if c != b'`' {
            continue;
        }
        for (j, &e) in b.iter().enumerate().skip(i + 1) {
            if matches!(e, b'`' | b'.' | b'[') && names.contains(&message[i + 1..j]) {
                return true;
            }
            if e == b'`' {
                break;
            }
        }
    }
    false
}
