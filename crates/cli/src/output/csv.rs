//! CSV traces: one row per tick, one column per instance's active leaf states and per variable.

use statecheck_ir::view::TraceView as Views;
use statecheck_ir::Program;
use statecheck_sim::TickRecord;

fn quote(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// Render a trace as CSV with a header row.
pub fn render(p: &Program, views: &Views, trace: &[TickRecord]) -> String {
    let mut header = vec!["tick".to_string()];
    header.extend(views.instances.iter().map(|i| format!("{}.active", i.name)));
    header.extend(views.vars.iter().map(|v| v.name.clone()));
    header.push("events".into());
    let mut out = header
        .iter()
        .map(|h| quote(h))
        .collect::<Vec<_>>()
        .join(",");
    out.push('\n');
    for rec in trace {
        let mut row = vec![rec.tick.to_string()];
        row.extend(
            (0..views.instances.len()).map(|i| views.active(p, i, &rec.slots, true).join("|")),
        );
        row.extend(
            views
                .vars
                .iter()
                .map(|v| v.display.format(rec.slots[v.slot as usize])),
        );
        row.push(views.present_events(&rec.slots).join("|"));
        out.push_str(&row.iter().map(|c| quote(c)).collect::<Vec<_>>().join(","));
        out.push('\n');
    }
    out
}
