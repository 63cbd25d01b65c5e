//! The terminal table: per tick, the active leaf states and what changed.

use statecheck_ir::view::TraceView as Views;
use statecheck_ir::Program;
use statecheck_sim::TickRecord;
use std::fmt::Write;

/// Render a trace as a table of active states and changed variables per tick.
pub fn render(p: &Program, views: &Views, trace: &[TickRecord]) -> String {
    let mut rows: Vec<(String, String, String)> = Vec::new();
    let mut prev: Option<&[i64]> = None;
    for rec in trace {
        let active: Vec<String> = (0..views.instances.len())
            .map(|i| {
                let a = views.active(p, i, &rec.slots, true).join(", ");
                if views.instances.len() == 1 {
                    a
                } else {
                    format!("{}: {a}", views.instances[i].name)
                }
            })
            .collect();
        let mut changes: Vec<String> = views
            .present_events(&rec.slots)
            .into_iter()
            .map(|e| format!("{}!", short(views, &e)))
            .collect();
        for v in &views.vars {
            let now = rec.slots[v.slot as usize];
            if prev.is_none_or(|pv| pv[v.slot as usize] != now) {
                changes.push(format!(
                    "{}={}",
                    short(views, &v.name),
                    v.display.format(now)
                ));
            }
        }
        rows.push((rec.tick.to_string(), active.join("; "), changes.join(" ")));
        prev = Some(&rec.slots);
    }
    let w0 = rows.iter().map(|r| r.0.len()).max().unwrap_or(0).max(4);
    let w1 = rows
        .iter()
        .map(|r| r.1.chars().count())
        .max()
        .unwrap_or(0)
        .clamp(6, 60);
    let mut out = String::new();
    let _ = writeln!(out, "{:>w0$}  {:<w1$}  changes", "tick", "active");
    for (t, a, c) in rows {
        let line = format!("{t:>w0$}  {a:<w1$}  {c}");
        let _ = writeln!(out, "{}", line.trim_end());
    }
    out
}

/// Drop the instance prefix when there is only one instance.
fn short<'a>(views: &Views, name: &'a str) -> &'a str {
    if views.instances.len() == 1 {
        name.split_once('.').map_or(name, |(_, v)| v)
    } else {
        name
    }
}
