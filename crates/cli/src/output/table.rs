//! The terminal table: per tick, the active leaf states and what changed.

use statecheck_ir::view::TraceView as Views;
use statecheck_ir::Program;
use statecheck_sim::TickRecord;
use std::fmt::Write;

/// Render a trace as a table of active states and changed variables per tick.
pub fn render(p: &Program, views: &Views, trace: &[TickRecord]) -> String {
    let mut t = Stream::new(p, views, usize::MAX);
    let mut out = String::new();
    for rec in trace {
        out.push_str(&t.tick(rec.tick, &rec.slots));
    }
    out.push_str(&t.finish());
    out
}

/// Ticks a streamed table holds back to size its columns: a trace of up to this many ticks
/// looks exactly as [`render`] draws it; longer ones keep the widths of these first rows.
pub const SIZING_ROWS: usize = 1000;

/// The table written tick by tick: the first rows are held to size the columns, the rest are
/// written as they come, so memory does not grow with the trace.
pub struct Stream<'a> {
    p: &'a Program,
    views: &'a Views,
    prev: Option<Vec<i64>>,
    held: Vec<(String, String, String)>,
    hold: usize,
    widths: Option<(usize, usize)>,
}

impl<'a> Stream<'a> {
    /// A table that sizes its columns on the first `hold` rows.
    pub fn new(p: &'a Program, views: &'a Views, hold: usize) -> Self {
        Stream {
            p,
            views,
            prev: None,
            held: Vec::new(),
            hold,
            widths: None,
        }
    }

    /// The next tick; returns the text ready to write (possibly empty).
    pub fn tick(&mut self, tick: u64, slots: &[i64]) -> String {
        let (p, views) = (self.p, self.views);
        let active: Vec<String> = (0..views.instances.len())
            .map(|i| {
                let a = views.active(p, i, slots, true).join(", ");
                if views.instances.len() == 1 {
                    a
                } else {
                    format!("{}: {a}", views.instances[i].name)
                }
            })
            .collect();
        let mut changes: Vec<String> = views
            .present_events(slots)
            .into_iter()
            .map(|e| format!("{}!", short(views, &e)))
            .collect();
        for v in &views.vars {
            let now = slots[v.slot as usize];
            if self
                .prev
                .as_ref()
                .is_none_or(|pv| pv[v.slot as usize] != now)
            {
                changes.push(format!(
                    "{}={}",
                    short(views, &v.name),
                    v.display.format(now)
                ));
            }
        }
        match &mut self.prev {
            Some(pv) => pv.copy_from_slice(slots),
            None => self.prev = Some(slots.to_vec()),
        }
        let row = (tick.to_string(), active.join("; "), changes.join(" "));
        if self.widths.is_none() {
            self.held.push(row);
            if self.held.len() < self.hold {
                return String::new();
            }
            return self.flush();
        }
        self.line(&row)
    }

    /// The rows still held (call once after the last tick; a table is printed even when empty).
    pub fn finish(&mut self) -> String {
        if self.widths.is_none() {
            self.flush()
        } else {
            String::new()
        }
    }

    /// Size the columns on the held rows, and write the header and them.
    fn flush(&mut self) -> String {
        let rows = std::mem::take(&mut self.held);
        let w0 = rows.iter().map(|r| r.0.len()).max().unwrap_or(0).max(4);
        let w1 = rows
            .iter()
            .map(|r| r.1.chars().count())
            .max()
            .unwrap_or(0)
            .clamp(6, 60);
        self.widths = Some((w0, w1));
        let mut out = String::new();
        let _ = writeln!(out, "{:>w0$}  {:<w1$}  changes", "tick", "active");
        for r in &rows {
            out.push_str(&self.line(r));
        }
        out
    }

    fn line(&self, (t, a, c): &(String, String, String)) -> String {
        let (w0, w1) = self.widths.unwrap_or((4, 6));
        let line = format!("{t:>w0$}  {a:<w1$}  {c}");
        format!("{}\n", line.trim_end())
    }
}

/// One line describing a state: the active leaf states and every variable's value.
pub fn state_line(p: &Program, views: &Views, slots: &[i64]) -> String {
    let mut parts: Vec<String> = (0..views.instances.len())
        .map(|i| {
            let a = views.active(p, i, slots, true).join(", ");
            format!("{} in {a}", views.instances[i].name)
        })
        .collect();
    for v in &views.vars {
        parts.push(format!(
            "{}={}",
            v.name,
            v.display.format(slots[v.slot as usize])
        ));
    }
    parts.join(", ")
}

/// Drop the instance prefix when there is only one instance.
fn short<'a>(views: &Views, name: &'a str) -> &'a str {
    if views.instances.len() == 1 {
        name.split_once('.').map_or(name, |(_, v)| v)
    } else {
        name
    }
}
