//! Where `statecheck sim` writes a run while it is computed: the trace on standard output
//! (table, JSON or CSV), a VCD file and a scenario file, each written tick by tick through a
//! buffer. Nothing grows with the number of ticks: a renderer keeps at most the previous tick
//! (the table also holds its first rows to size its columns).

use crate::output;
use anyhow::{anyhow, Result};
use statecheck_ir::view::TraceView as Views;
use statecheck_ir::Program;
use statecheck_sim::{ScenarioWriter, Sink};
use std::fs::File;
use std::io::{BufWriter, Write};

/// The trace format on standard output.
pub enum Format {
    /// The table (unless quiet).
    Table,
    /// One JSON document: `{"ticks":[…], "result": …}`, one tick per line.
    Json,
    /// CSV with a header row.
    Csv,
    /// Nothing.
    Quiet,
}

/// A file written as the run goes, and its path (for messages).
struct Out {
    path: String,
    w: BufWriter<File>,
}

impl Out {
    fn create(path: &str) -> Result<Out> {
        let f = File::create(path).map_err(|e| anyhow!("cannot write `{path}`: {e}"))?;
        Ok(Out {
            path: path.to_string(),
            w: BufWriter::with_capacity(1 << 16, f),
        })
    }
}

/// The sink of a `sim` run.
pub struct SimSink<'a> {
    p: &'a Program,
    views: &'a Views,
    format: Format,
    stdout: BufWriter<std::io::Stdout>,
    /// Standard output was closed (e.g. `| head`): stop writing to it, silently.
    stdout_closed: bool,
    table: Option<output::table::Stream<'a>>,
    vcd: Option<(output::vcd::Stream<'a>, Out)>,
    scenario: Option<(ScenarioWriter<'a>, Out)>,
    /// The slots after the last tick (the state a deadlock is reported in).
    pub last: Option<Vec<i64>>,
    ticks: u64,
    error: Option<anyhow::Error>,
}

impl<'a> SimSink<'a> {
    /// Open the requested files and write the headers.
    pub fn new(
        p: &'a Program,
        views: &'a Views,
        format: Format,
        vcd: Option<&str>,
        scenario: Option<&str>,
    ) -> Result<SimSink<'a>> {
        let mut s = SimSink {
            p,
            views,
            table: matches!(format, Format::Table).then(|| {
                let mut t = output::table::Stream::new(p, views, output::table::SIZING_ROWS);
                t.width = output::table::terminal_width();
                t
            }),
            format,
            stdout: BufWriter::with_capacity(1 << 16, std::io::stdout()),
            stdout_closed: false,
            vcd: None,
            scenario: None,
            last: None,
            ticks: 0,
            error: None,
        };
        if let Some(path) = vcd {
            let (stream, header) = output::vcd::Stream::new(p, views);
            let mut out = Out::create(path)?;
            write_file(&mut out, &header, &mut s.error);
            s.vcd = Some((stream, out));
        }
        if let Some(path) = scenario {
            let w = ScenarioWriter::new(p);
            let mut out = Out::create(path)?;
            write_file(&mut out, w.header(), &mut s.error);
            s.scenario = Some((w, out));
        }
        match s.format {
            Format::Json => s.print("{\"ticks\":["),
            Format::Csv => {
                let h = output::csv::header(p, views);
                s.print(&h);
            }
            Format::Table | Format::Quiet => {}
        }
        Ok(s)
    }

    fn print(&mut self, text: &str) {
        if !self.stdout_closed
            && !text.is_empty()
            && self.stdout.write_all(text.as_bytes()).is_err()
        {
            self.stdout_closed = true;
        }
    }

    /// Write what is left after the run; `json_tail` is the rest of the JSON document after
    /// the ticks (`"result": …` and the other members, without braces).
    pub fn finish(mut self, json_tail: &str) -> Result<()> {
        match self.format {
            Format::Json => {
                let text = format!("\n],{json_tail}}}\n");
                self.print(&text);
            }
            Format::Table => {
                let text = self.table.as_mut().map(|t| t.finish()).unwrap_or_default();
                self.print(&text);
            }
            Format::Csv | Format::Quiet => {}
        }
        if !self.stdout_closed {
            let _ = self.stdout.flush();
        }
        if let Some((mut v, mut out)) = self.vcd.take() {
            let text = v.finish();
            write_file(&mut out, &text, &mut self.error);
            flush_file(&mut out, &mut self.error);
        }
        if let Some((mut w, mut out)) = self.scenario.take() {
            let text = w.finish();
            write_file(&mut out, &text, &mut self.error);
            flush_file(&mut out, &mut self.error);
        }
        match self.error {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }
}

fn write_file(out: &mut Out, text: &str, error: &mut Option<anyhow::Error>) {
    if error.is_none() {
        if let Err(e) = out.w.write_all(text.as_bytes()) {
            *error = Some(anyhow!("cannot write `{}`: {e}", out.path));
        }
    }
}

fn flush_file(out: &mut Out, error: &mut Option<anyhow::Error>) {
    if error.is_none() {
        if let Err(e) = out.w.flush() {
            *error = Some(anyhow!("cannot write `{}`: {e}", out.path));
        }
    }
}

impl Sink for SimSink<'_> {
    fn inputs(&mut self, _tick: u64, inputs: &[i64]) {
        if let Some((w, out)) = &mut self.scenario {
            let text = w.push_vector(inputs);
            write_file(out, &text, &mut self.error);
        }
    }

    fn tick(&mut self, tick: u64, slots: &[i64]) {
        match &mut self.last {
            Some(l) => l.copy_from_slice(slots),
            None => self.last = Some(slots.to_vec()),
        }
        if let Some((v, out)) = &mut self.vcd {
            let text = v.tick(tick, slots);
            write_file(out, &text, &mut self.error);
        }
        if self.stdout_closed {
            self.ticks += 1;
            return;
        }
        let text = match self.format {
            Format::Table => self
                .table
                .as_mut()
                .map(|t| t.tick(tick, slots))
                .unwrap_or_default(),
            Format::Json => {
                let obj = output::json::tick_of(self.p, self.views, tick, slots);
                let sep = if self.ticks == 0 { "\n" } else { ",\n" };
                format!("{sep}{obj}")
            }
            Format::Csv => output::csv::row(self.p, self.views, tick, slots),
            Format::Quiet => String::new(),
        };
        self.ticks += 1;
        self.print(&text);
    }
}
