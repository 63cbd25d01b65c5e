//! The run as it happens: each verdict's row (table or `--json-lines`) the moment it is
//! decided, its counterexample written at once, and the live progress display on a terminal.

use super::cex::{self, Cex};
use super::report::{self, Columns, Meta};
use crate::load::Loaded;
use indicatif::{MultiProgress, ProgressBar, ProgressDrawTarget, ProgressStyle};
use statecheck_explicit::{human_bytes, PropResult, Stats};
use statecheck_ir::Program;
use statecheck_verify::Event;
use std::io::Write;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// How rows are printed.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// The verdict table.
    Table,
    /// One JSON object per verdict.
    JsonLines,
    /// Nothing until the end (`--json`).
    Json,
}

/// Everything the event callback needs; shared by the engines' threads.
pub struct Live<'a> {
    loaded: &'a Loaded,
    program: &'a Program,
    names: Vec<String>,
    columns: Columns,
    format: Format,
    cex_dir: Option<&'a str>,
    write: cex::Write,
    started: Instant,
    /// Per result: its counterexample once written (or the error writing it).
    cexs: Mutex<Vec<Option<anyhow::Result<Option<Cex>>>>>,
    display: Option<Display>,
}

struct Display {
    multi: MultiProgress,
    header: ProgressBar,
    explicit: ProgressBar,
    engines: Vec<(&'static str, ProgressBar)>,
    decided: Mutex<usize>,
}

impl<'a> Live<'a> {
    /// A live run over the properties `names`; `show_progress` draws the display on stderr.
    #[allow(clippy::too_many_arguments)] // reason: one constructor of one struct, read once
    pub fn new(
        loaded: &'a Loaded,
        program: &'a Program,
        names: Vec<String>,
        engines: &[&'static str],
        columns: Columns,
        format: Format,
        cex_dir: Option<&'a str>,
        write: cex::Write,
        show_progress: bool,
    ) -> Live<'a> {
        let n = names.len();
        let display = show_progress.then(|| Display::new(engines, n));
        Live {
            loaded,
            program,
            names,
            columns,
            format,
            cex_dir,
            write,
            started: Instant::now(),
            cexs: Mutex::new((0..n).map(|_| None).collect()),
            display,
        }
    }

    /// The table header (printed before the run).
    pub fn start(&self) {
        if self.format == Format::Table {
            self.print(&self.columns.header());
        }
    }

    fn print(&self, text: &str) {
        let write = || {
            let mut out = std::io::stdout().lock();
            // A closed pipe (e.g. `| head`) is not an error worth reporting.
            let _ = out.write_all(text.as_bytes());
            let _ = out.flush();
        };
        match &self.display {
            Some(d) => d.multi.suspend(write),
            None => write(),
        }
    }

    /// The callback given to the portfolio.
    pub fn event(&self, e: Event) {
        match e {
            Event::Decided {
                index,
                result,
                meta,
            } => self.decided(index, result, meta),
            Event::Progress(p) => {
                if let Some(d) = &self.display {
                    let rate = p.states as f64 / p.elapsed.as_secs_f64().max(1e-9);
                    d.explicit.set_message(format!(
                        "explicit  depth {} · {} states · {:.0} states/s · {}",
                        p.depth,
                        p.states,
                        rate,
                        human_bytes(p.memory_bytes)
                    ));
                }
            }
            Event::Working {
                engine,
                index,
                budget,
            } => {
                if let Some((_, b)) = self
                    .display
                    .as_ref()
                    .and_then(|d| d.engines.iter().find(|(e, _)| *e == engine))
                {
                    let name = self.names.get(index).map_or("?", String::as_str);
                    let budget = budget.map_or_else(
                        || "until the end".to_string(),
                        |b| format!("budget {:.1} s", b.as_secs_f64()),
                    );
                    b.set_message(format!("{engine:<8}  on `{name}` ({budget})"));
                }
            }
            Event::Idle { engine } => {
                if let Some((_, b)) = self
                    .display
                    .as_ref()
                    .and_then(|d| d.engines.iter().find(|(e, _)| *e == engine))
                {
                    b.set_message(format!("{engine:<8}  done"));
                }
            }
            _ => {}
        }
    }

    fn decided(&self, index: usize, r: &PropResult, m: &Meta) {
        let c = cex::one(self.loaded, self.program, r, self.cex_dir, self.write);
        let line = match self.format {
            Format::Table => Some(self.columns.row(r, m)),
            Format::JsonLines => {
                let stats = Stats {
                    time: self.started.elapsed(),
                    ..Stats::default()
                };
                let cx = c.as_ref().ok().and_then(Option::as_ref);
                let mut v = report::result_json(self.program, r, cx, Some(m), &stats);
                if let Some(o) = v.as_object_mut() {
                    // The exploration's counts belong to the final `stats` line.
                    o.remove("states");
                    o.remove("transitions");
                }
                Some(format!("{v}\n"))
            }
            Format::Json => None,
        };
        if let Ok(mut all) = self.cexs.lock() {
            if let Some(slot) = all.get_mut(index) {
                *slot = Some(c);
            }
        }
        if let Some(l) = line {
            self.print(&l);
        }
        if let Some(d) = &self.display {
            if let Ok(mut k) = d.decided.lock() {
                *k += 1;
                d.header.set_position(*k as u64);
            }
        }
    }

    /// Clear the display.
    pub fn finish(&self) {
        if let Some(d) = &self.display {
            for (_, b) in &d.engines {
                b.finish_and_clear();
            }
            d.explicit.finish_and_clear();
            d.header.finish_and_clear();
            let _ = d.multi.clear();
        }
    }

    /// The counterexamples, index-aligned with `results` (written now for any result not
    /// reported through the callback).
    pub fn counterexamples(&self, results: &[PropResult]) -> anyhow::Result<Vec<Option<Cex>>> {
        let mut all = match self.cexs.lock() {
            Ok(mut g) => std::mem::take(&mut *g),
            Err(_) => anyhow::bail!("a thread of the run panicked"),
        };
        all.resize_with(results.len(), || None);
        results
            .iter()
            .zip(all)
            .map(|(r, c)| match c {
                Some(c) => c,
                None => cex::one(self.loaded, self.program, r, self.cex_dir, self.write),
            })
            .collect()
    }
}

impl Display {
    fn new(engines: &[&'static str], total: usize) -> Display {
        let multi = MultiProgress::with_draw_target(ProgressDrawTarget::stderr());
        let header = multi.add(ProgressBar::new(total as u64));
        header.set_style(
            ProgressStyle::with_template("{pos}/{len} properties decided · {elapsed}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        header.enable_steady_tick(Duration::from_millis(200));
        let line = |b: ProgressBar| {
            b.set_style(
                ProgressStyle::with_template("  {msg}")
                    .unwrap_or_else(|_| ProgressStyle::default_spinner()),
            );
            b
        };
        let explicit = if engines.contains(&"explicit") {
            let b = line(multi.add(ProgressBar::new_spinner()));
            b.set_message("explicit  starting");
            b
        } else {
            ProgressBar::hidden()
        };
        let engines = engines
            .iter()
            .filter(|e| **e != "explicit")
            .map(|&e| {
                let b = line(multi.add(ProgressBar::new_spinner()));
                b.set_message(format!("{e:<8}  waiting"));
                (e, b)
            })
            .collect();
        Display {
            multi,
            header,
            explicit,
            engines,
            decided: Mutex::new(0),
        }
    }
}
