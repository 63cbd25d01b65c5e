//! The terminal table: per tick, the time (when the model declares its tick length), the
//! active leaf states and what changed. Variables and events are the view's columns: a
//! connected signal once, named by its connection (`a.out->b.in`), and only those chosen by
//! `--show`. On a terminal, long rows wrap their changes under the changes column.

use statecheck_ir::view::TraceView as Views;
use statecheck_ir::Program;
use statecheck_sim::TickRecord;

/// Render a trace as a table of active states and changed variables per tick; `width`: the
/// terminal's width to wrap long rows to (`None`: never wrap).
pub fn render(p: &Program, views: &Views, trace: &[TickRecord], width: Option<usize>) -> String {
    let mut t = Stream::new(p, views, usize::MAX);
    t.width = width;
    let mut out = String::new();
    for rec in trace {
        out.push_str(&t.tick(rec.tick, &rec.slots));
    }
    out.push_str(&t.finish());
    out
}

/// The width of the terminal standard output is, when it is one (`None` when the output is a
/// pipe or a file: such output is never wrapped).
pub fn terminal_width() -> Option<usize> {
    use std::io::IsTerminal;
    if !std::io::stdout().is_terminal() {
        return None;
    }
    console::Term::stdout()
        .size_checked()
        .map(|(_, cols)| usize::from(cols))
        .filter(|w| *w > 0)
}

/// Apply `--show` patterns to a view: an error (a usage error) names a pattern that matches
/// no variable or event.
pub fn show(views: &mut Views, patterns: &[String]) -> anyhow::Result<()> {
    if patterns.is_empty() {
        return Ok(());
    }
    let unmatched = views.select(patterns);
    if let Some(u) = unmatched.first() {
        let mut names: Vec<&str> = views
            .vars
            .iter()
            .map(|v| v.name.as_str())
            .chain(views.events.iter().map(|(n, _)| n.as_str()))
            .take(8)
            .collect();
        if views.vars.len() + views.events.len() > 8 {
            names.push("…");
        }
        anyhow::bail!(
            "--show `{u}` matches no variable or event (they are named `instance.name`: {})",
            names.join(", ")
        );
    }
    Ok(())
}

/// One row: tick, time (empty without a declared tick length), active states, changes.
type Row = (String, String, String, String);

/// Ticks a streamed table holds back to size its columns: a trace of up to this many ticks
/// looks exactly as [`render`] draws it; longer ones keep the widths of these first rows.
pub const SIZING_ROWS: usize = 1000;

/// The table written tick by tick: the first rows are held to size the columns, the rest are
/// written as they come, so memory does not grow with the trace.
pub struct Stream<'a> {
    p: &'a Program,
    views: &'a Views,
    prev: Option<Vec<i64>>,
    held: Vec<Row>,
    hold: usize,
    widths: Option<(usize, usize, usize)>,
    /// The terminal's width: changes past it wrap onto continuation lines (`None`: never).
    pub width: Option<usize>,
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
            width: None,
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
            .event_columns
            .iter()
            .filter(|c| {
                views
                    .events
                    .get(c.index)
                    .is_some_and(|(_, s)| slots.get(*s as usize).is_some_and(|v| *v != 0))
            })
            .map(|c| format!("{}!", short(views, &c.name)))
            .collect();
        for c in &views.var_columns {
            let v = &views.vars[c.index];
            let now = slots[v.slot as usize];
            if self
                .prev
                .as_ref()
                .is_none_or(|pv| pv[v.slot as usize] != now)
            {
                changes.push(format!(
                    "{}={}",
                    short(views, &c.name),
                    v.display.format(now)
                ));
            }
        }
        match &mut self.prev {
            Some(pv) => pv.copy_from_slice(slots),
            None => self.prev = Some(slots.to_vec()),
        }
        let time = p.time_text(tick).unwrap_or_default();
        let row = (tick.to_string(), time, active.join("; "), changes.join(" "));
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
        let wt = if self.p.tick_ms.is_some() {
            rows.iter().map(|r| r.1.len()).max().unwrap_or(0).max(8)
        } else {
            0
        };
        let w1 = rows
            .iter()
            .map(|r| r.2.chars().count())
            .max()
            .unwrap_or(0)
            .clamp(6, 60);
        self.widths = Some((w0, wt, w1));
        let mut out = String::new();
        let head = (
            "tick".to_string(),
            "time (s)".to_string(),
            "active".to_string(),
            "changes".to_string(),
        );
        out.push_str(&self.line(&head));
        for r in &rows {
            out.push_str(&self.line(r));
        }
        out
    }

    fn line(&self, (t, time, a, c): &Row) -> String {
        let (w0, wt, w1) = self.widths.unwrap_or((4, 0, 6));
        let lead = if wt > 0 {
            format!("{t:>w0$}  {time:>wt$}  {a:<w1$}  ")
        } else {
            format!("{t:>w0$}  {a:<w1$}  ")
        };
        let indent = lead.chars().count();
        // The changes wrap at the terminal's width, word by word, under their column (at
        // least 20 characters of them per line).
        let room = self.width.map(|w| w.saturating_sub(indent).max(20));
        let mut lines = vec![lead];
        let mut used = 0;
        for word in c.split(' ').filter(|w| !w.is_empty()) {
            let n = word.chars().count();
            if let Some(room) = room {
                if used > 0 && used + 1 + n > room {
                    lines.push(" ".repeat(indent));
                    used = 0;
                }
            }
            if let Some(last) = lines.last_mut() {
                if used > 0 {
                    last.push(' ');
                    used += 1;
                }
                last.push_str(word);
                used += n;
            }
        }
        let mut out = String::new();
        for l in lines {
            out.push_str(l.trim_end());
            out.push('\n');
        }
        out
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

/// Drop the instance prefix when there is only one instance (from every name of a
/// connection's column: `w.o->w.i` is `o->i`).
fn short(views: &Views, name: &str) -> String {
    match views.instances.as_slice() {
        [only] => {
            let prefix = format!("{}.", only.name);
            name.split("->")
                .map(|side| {
                    side.split(',')
                        .map(|n| n.strip_prefix(&prefix).unwrap_or(n))
                        .collect::<Vec<_>>()
                        .join(",")
                })
                .collect::<Vec<_>>()
                .join("->")
        }
        _ => name.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use statecheck_sim::{scenario, Options, ScenarioInputs};

    /// A chart whose changes are long: four variables written in tick 1.
    const MODEL: &str = "chart W {
  input event go;
  output alpha_value: int[0..9] = 0;
  output beta_value: int[0..9] = 0;
  output gamma_value: int[0..9] = 0;
  output delta_value: int[0..9] = 0;
  initial A;
  state A { on go / { alpha_value = 1; beta_value = 2; gamma_value = 3; delta_value = 4; } -> B; }
  state B;
}";

    fn table(width: Option<usize>) -> String {
        let (file, d) = statecheck_syntax::parse(MODEL);
        assert!(d.is_empty(), "{d:?}");
        let (model, d) = statecheck_model::check(&file);
        assert!(!d.iter().any(|d| d.is_error()), "{d:?}");
        let p = statecheck_ir::lower(&model, &model.systems[0]).expect("lowers");
        let views = Views::new(&model, &p);
        let sc = scenario::parse("-\ngo\n", &p).expect("scenario");
        let run = statecheck_sim::run(
            &p,
            &mut ScenarioInputs::new(&sc),
            Options {
                coverage: false,
                no_trace: false,
                keep_going: false,
            },
        );
        render(&p, &views, &run.trace, width)
    }

    #[test]
    fn long_changes_wrap_under_their_column_on_a_narrow_terminal() {
        // The lead is "tick" (4) + 2 + "active" (6) + 2 = 14 characters; at width 40 the
        // changes get 26 per line: `go! alpha_value=1` (17) + ` beta_value=2` (13) would be
        // 30, so each change after the first pair goes on its own line.
        let want = "\
tick  active  changes
   0  A       alpha_value=0 beta_value=0
              gamma_value=0
              delta_value=0
   1  B       go! alpha_value=1
              beta_value=2 gamma_value=3
              delta_value=4
";
        assert_eq!(table(Some(40)), want);
        // Not on a terminal (no width): one line per tick, however long.
        let flat = "\
tick  active  changes
   0  A       alpha_value=0 beta_value=0 gamma_value=0 delta_value=0
   1  B       go! alpha_value=1 beta_value=2 gamma_value=3 delta_value=4
";
        assert_eq!(table(None), flat);
    }
}
