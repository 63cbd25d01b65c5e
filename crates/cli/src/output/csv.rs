//! CSV traces: one row per tick, one column per instance's active leaf states and per variable;
//! a `time` column (seconds) after `tick` when the model declares its tick length.

use statecheck_ir::view::TraceView as Views;
use statecheck_ir::Program;

fn quote(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The header row.
pub fn header(p: &Program, views: &Views) -> String {
    let mut header = vec!["tick".to_string()];
    if p.tick_ms.is_some() {
        header.push("time".into());
    }
    header.extend(views.instances.iter().map(|i| format!("{}.active", i.name)));
    header.extend(views.vars.iter().map(|v| v.name.clone()));
    header.push("events".into());
    let mut out = header
        .iter()
        .map(|h| quote(h))
        .collect::<Vec<_>>()
        .join(",");
    out.push('\n');
    out
}

/// The row of one tick.
pub fn row(p: &Program, views: &Views, tick: u64, slots: &[i64]) -> String {
    let mut row = vec![tick.to_string()];
    row.extend(p.time_text(tick));
    row.extend((0..views.instances.len()).map(|i| views.active(p, i, slots, true).join("|")));
    row.extend(
        views
            .vars
            .iter()
            .map(|v| v.display.format(slots[v.slot as usize])),
    );
    row.push(views.present_events(slots).join("|"));
    let mut out = row.iter().map(|c| quote(c)).collect::<Vec<_>>().join(",");
    out.push('\n');
    out
}
