//! Rendering a verification report: the branching notice, the JSON contract, and the text
//! (verdict table, statistics, dead design, counterexample tables).

use super::cex::Cex;
use crate::load::Loaded;
use crate::output::table;
use serde_json::{json, Value};
use statecheck_base::LineIndex;
use statecheck_explicit::{human_bytes, InputSpace, Options, PropResult, Report, Stats, Verdict};
use statecheck_ir::view::TraceView as Views;
use statecheck_ir::{CoverKind, Program};
use statecheck_model::imports::Sources;
use std::fmt::Write;

/// Above this many input vectors per tick, suggest `assume`s even when the run goes ahead.
const LARGE_BRANCHING: u128 = 10_000;

/// Print the branching factor up front (stderr) and advise when it is large.
pub fn announce_branching(p: &Program, opts: &Options, quiet: bool) {
    let mut space = InputSpace::new(p);
    space.solve_static(p);
    let n = space.effective().unwrap_or(space.count);
    let after = match space.effective() {
        Some(e) if e != space.count => format!(" ({e} allowed by the assumes)"),
        _ if space.too_many => " (too many allowed by the assumes to list)".to_string(),
        _ => String::new(),
    };
    if !quiet {
        eprintln!("branching: {} input vector(s) per tick{after}", space.count);
    }
    if n > opts.max_branching && !opts.force {
        eprintln!(
            "error: {n} input vectors per tick is too many to enumerate in every state; constrain the inputs with `assume` (e.g. `assume fam.targetPos == 0 || fam.targetPos == 4095;`), use --engine ic3, or use --force to explore anyway"
        );
    } else if n > LARGE_BRANCHING && !quiet {
        eprintln!("warning: {n} input vectors per tick make every state expensive; consider `assume` constraints on the widest inputs");
    }
}

fn num(v: u128) -> Value {
    u64::try_from(v).map_or_else(|_| json!(v.to_string()), |x| json!(x))
}

pub use statecheck_verify::Meta;

/// The JSON object of `statecheck verify --json`.
pub fn json(
    p: &Program,
    source: &Sources,
    rep: &Report,
    cexs: &[Option<Cex>],
    meta: &[Meta],
) -> Value {
    let results: Vec<Value> = rep
        .results
        .iter()
        .zip(cexs)
        .enumerate()
        .map(|(i, (r, c))| result_json(p, r, c.as_ref(), meta.get(i), &rep.stats))
        .collect();
    json!({
        "results": results,
        "stats": stats_json(p, source, &rep.stats),
    })
}

/// One entry of `results` (and one line of `--json-lines`).
pub fn result_json(
    p: &Program,
    r: &PropResult,
    c: Option<&Cex>,
    m: Option<&Meta>,
    s: &Stats,
) -> Value {
    let mut o = json!({
        "property": r.name,
        "kind": r.kind.as_str(),
        "verdict": r.verdict.as_str(),
        "engine": m.map_or("explicit", |m| m.engine),
        "depth": r.depth,
        "states": s.states,
        "transitions": s.transitions,
        "time_s": m.and_then(|m| m.time_s).unwrap_or(s.time.as_secs_f64()),
        "counterexample": c.and_then(|c| c.path.clone()),
    });
    if let Some(at) = m.and_then(|m| m.decided_at_s) {
        o["decided_at_s"] = json!(at);
    }
    if let Some(of) = m.and_then(|m| m.symmetry_of.as_deref()) {
        o["symmetry_of"] = json!(of);
    }
    if let Some(c) = c {
        o["tick"] = json!(c.tick);
        if let Some(t) = p.seconds(c.tick) {
            o["time"] = json!(t);
        }
        if let Some(m) = &c.mismatch {
            o["replay_note"] = json!(m);
        }
        if !c.replayed {
            o["replayed"] = json!(false);
        }
    }
    if let Some(k) = r.loop_start {
        o["loop_start"] = json!(k);
    }
    if let Some(e) = &r.error {
        o["message"] = json!(p.describe_error(e));
    }
    if let Some(n) = &r.note {
        o["note"] = json!(n);
    }
    if let Some(why) = m.and_then(|m| m.reason.clone()) {
        o["reason"] = json!(why);
    } else if r.verdict == Verdict::Unknown {
        o["reason"] = json!(s.limit.as_ref().map_or_else(
            || "every other property was decided first".to_string(),
            |l| l.describe()
        ));
    }
    o
}

/// The `stats` object of `--json` (and the last line of `--json-lines`).
pub fn stats_json(p: &Program, source: &Sources, s: &Stats) -> Value {
    let dead = s.dead.as_ref().map(|d| dead_json(p, source, d));
    json!({
        "states": s.states,
        "transitions": s.transitions,
        "depth": s.depth,
        "time_s": s.time.as_secs_f64(),
        "cex_time_s": s.cex_time.as_secs_f64(),
        "peak_memory_bytes": s.peak_memory_bytes,
        "peak_rss_bytes": peak_rss(),
        "table_bytes": s.table_bytes,
        "bytes_per_state": s.bytes_per_state(),
        "states_per_s": s.states_per_s(),
        "branching": num(s.branching),
        "branching_after_assumes": s.branching_after_assumes.map(num),
        "threads": s.threads,
        "state_bits": s.state_bits,
        "complete": s.complete,
        "limit": s.limit.as_ref().map(|l| json!({"kind": l.name(), "message": l.describe()})),
        "dead": dead,
        "backend": s.backend,
        "native_build_s": s.native_build_time.map(|t| t.as_secs_f64()),
        "native_note": s.native_note,
        "symmetry": s.symmetry,
        "symmetry_note": s.symmetry_note,
        "collapse_leaves": s.collapse_leaves,
        "collapse_from": s.collapse_from,
        "bitstate": s.bitstate.as_ref().map(|b| json!({
            "bytes": b.bytes,
            "hashes": b.hashes,
            "set_bits": b.set_bits,
            "fill": b.fill,
            "bits_per_state": b.bits_per_state,
            "expected_omitted": b.expected_omitted,
        })),
    })
}

/// The dead items, each with the file it is in and its line and column in that file.
fn dead_json(p: &Program, sources: &Sources, dead: &[u32]) -> Value {
    dead.iter()
        .filter_map(|&c| p.covers.get(c as usize))
        .filter(|c| !c.expected_unreached)
        .map(|c| {
            let (file, line, col) = file_line_col(sources, c.span.start);
            json!({"instance": p.instances[c.instance as usize].name, "kind": cover_kind(&c.kind), "label": c.label, "file": file, "line": line, "col": col})
        })
        .collect()
}

/// The file containing a byte offset of the merged text, and the 1-based line and column in it.
fn file_line_col(sources: &Sources, offset: u32) -> (String, usize, usize) {
    match sources.locate(offset as usize) {
        Some((f, at)) => {
            let (l, c) = LineIndex::new(sources.file_text(f)).line_col(at as u32);
            (f.name.clone(), l, c)
        }
        None => {
            let (l, c) = LineIndex::new(&sources.text).line_col(offset);
            (String::new(), l, c)
        }
    }
}

fn cover_kind(k: &CoverKind) -> &'static str {
    match k {
        CoverKind::State(_) => "state",
        CoverKind::Transition(_) => "transition",
        CoverKind::Branch(..) => "branch",
    }
}

/// Peak resident set size of this process (Linux), in bytes.
fn peak_rss() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    line.split_whitespace()
        .nth(1)?
        .parse::<u64>()
        .ok()
        .map(|k| k * 1024)
}

/// The columns of the verdict table: the explicit engine's (no engine or time) or the
/// portfolio's.
#[derive(Clone, Copy)]
pub struct Columns {
    /// Width of the property column.
    pub width: usize,
    /// With engine and time columns.
    pub engines: bool,
}

impl Columns {
    /// Columns for these property names.
    pub fn new<'a>(names: impl Iterator<Item = &'a str>, engines: bool) -> Columns {
        let width = names.map(str::len).max().unwrap_or(8).max(8);
        Columns { width, engines }
    }

    /// The header line.
    pub fn header(&self) -> String {
        let w = self.width;
        if self.engines {
            format!(
                "{:<w$}  {:<11}  {:<11}  {:<8}  {:>5}  time\n",
                "property", "kind", "verdict", "engine", "depth"
            )
        } else {
            format!(
                "{:<w$}  {:<11}  {:<11}  depth\n",
                "property", "kind", "verdict"
            )
        }
    }

    /// The row of one result.
    pub fn row(&self, r: &PropResult, m: &Meta) -> String {
        let w = self.width;
        if self.engines {
            format!(
                "{:<w$}  {:<11}  {:<11}  {:<8}  {:>5}  {:.3} s{}{}\n",
                r.name,
                r.kind.as_str(),
                r.verdict.as_str(),
                m.engine,
                r.depth,
                m.time_s.unwrap_or(0.0),
                m.reason
                    .as_ref()
                    .map(|x| format!("  ({x})"))
                    .unwrap_or_default(),
                m.symmetry_of
                    .as_ref()
                    .map(|x| format!("  (by symmetry from `{x}`)"))
                    .unwrap_or_default()
            )
        } else {
            format!(
                "{:<w$}  {:<11}  {:<11}  {}{}\n",
                r.name,
                r.kind.as_str(),
                r.verdict.as_str(),
                r.depth,
                m.reason
                    .as_ref()
                    .map(|x| format!("  ({x})"))
                    .unwrap_or_default()
            )
        }
    }
}

/// What follows the verdict table in the human-readable report: statistics, dead design
/// and counterexample tables (nothing under `--quiet`). `explicit`: the explicit engine ran
/// alone (its statistics are shown). `show`: the `--show` patterns choosing the columns.
pub fn tail(
    loaded: &Loaded,
    p: &Program,
    rep: &Report,
    cexs: &[Option<Cex>],
    quiet: bool,
    explicit: bool,
    show: &[String],
) -> String {
    let mut out = String::new();
    if quiet {
        return out;
    }
    if explicit {
        explicit_stats(&mut out, loaded, p, &rep.stats);
    }
    let mut views = Views::new(&loaded.model, p);
    // The patterns were checked before the run (`table::show`).
    let _unmatched = views.select(show);
    let width = table::terminal_width();
    // A configuration's system is `System:configuration` (docs/components.md).
    let config = p
        .name
        .split_once(statecheck_model::components::CONFIG_SEP)
        .map(|(_, c)| format!(" in configuration `{c}`"))
        .unwrap_or_default();
    for (r, c) in rep.results.iter().zip(cexs) {
        let what = if r.verdict == Verdict::Reachable {
            "witness"
        } else {
            "counterexample"
        };
        match c {
            Some(c) => {
                let at = match &c.path {
                    Some(f) => format!(": {f}"),
                    None => String::new(),
                };
                let _ = writeln!(
                    out,
                    "\n{what} for `{}`{config} ({}, {} ticks, decided at {}){at}",
                    r.name,
                    r.kind.as_str(),
                    r.depth,
                    p.tick_label(c.tick)
                );
                if c.replayed {
                    out.push_str(&table::render(p, &views, &c.trace, width));
                }
                if let Some(e) = &r.error {
                    let _ = writeln!(
                        out,
                        "{:>4}  run-time error: {}",
                        c.tick,
                        p.describe_error(e)
                    );
                }
                if let Some(m) = &c.mismatch {
                    let _ = writeln!(out, "note: {m}");
                }
                if !c.replayed {
                    let _ = writeln!(
                        out,
                        "note: not minimised or replayed: the time limit had passed (replay \
                         the scenario with `statecheck sim --scenario`)"
                    );
                }
            }
            // Under bitstate hashing the statistics say once why the other rows are unknown.
            None if explicit
                && !(rep.stats.bitstate.is_some() && r.verdict == Verdict::Unknown) =>
            {
                if let Some(n) = &r.note {
                    let _ = writeln!(out, "\n{what} for `{}`: {n}", r.name);
                }
            }
            None => {}
        }
    }
    out
}

fn explicit_stats(out: &mut String, loaded: &Loaded, p: &Program, s: &Stats) {
    out.push('\n');
    out.push_str(&stats_line(s));
    if let Some(l) = &s.limit {
        let _ = writeln!(
            out,
            "stopped: {} (the statistics are partial)",
            l.describe()
        );
    }
    if s.all_decided {
        let _ = writeln!(
            out,
            "stopped early: every property was decided (the statistics are partial)"
        );
    }
    if let Some(dead) = &s.dead {
        for &c in dead {
            let Some(c) = p.covers.get(c as usize).filter(|c| !c.expected_unreached) else {
                continue;
            };
            let (file, line, col) = file_line_col(&loaded.sources, c.span.start);
            let what = if matches!(c.kind, CoverKind::State(_)) {
                "state never entered"
            } else {
                "transition never fires"
            };
            let _ = writeln!(
                out,
                "warning: dead design: {what}: {}: {} ({file}:{line}:{col})",
                p.instances[c.instance as usize].name, c.label
            );
        }
    }
}

fn stats_line(s: &Stats) -> String {
    let after = s
        .branching_after_assumes
        .map(|b| format!(", {b} after assumes"))
        .unwrap_or_default();
    let native = match (s.native_build_time, &s.native_note) {
        (_, Some(note)) => format!("\nnative code not used: {note}"),
        (Some(t), None) => format!(", native code (built in {:.2} s)", t.as_secs_f64()),
        (None, None) => String::new(),
    };
    let native = match (s.symmetry, &s.symmetry_note) {
        (_, Some(note)) => format!("{native}\n{note}"),
        (true, None) => format!(
            "{native}\nsymmetry reduction: states are orbits of interchangeable array elements"
        ),
        (false, None) => native,
    };
    let native = match (&s.collapse_leaves, s.collapse_from) {
        (Some(l), from) => format!(
            "{native}\ncollapse compression{}: {} and {} distinct halves",
            match from {
                Some(n) if n > 1 => format!(" (from {n} states on)"),
                _ => String::new(),
            },
            l.first().copied().unwrap_or(0),
            l.get(1).copied().unwrap_or(0)
        ),
        (None, _) => native,
    };
    let native = match &s.bitstate {
        Some(b) => format!(
            "{native}\nbitstate hashing: {} bit array, {} bits per state, {:.2} % set, hash factor {:.1}, {} states omitted: the count is a lower bound of the reachable states, not an exhaustive search",
            human_bytes(b.bytes),
            b.hashes,
            b.fill * 100.0,
            b.bits_per_state,
            statecheck_explicit::bitstate::about(b.expected_omitted)
        ),
        None => native,
    };
    format!(
        "{} states, {} transitions, depth {}, {:.2} s ({:.0} states/s), {:.1} bytes/state, peak {}, {} thread(s), {}-bit states, branching {}{after}{native}\n",
        s.states,
        s.transitions,
        s.depth,
        s.time.as_secs_f64(),
        s.states_per_s(),
        s.bytes_per_state(),
        human_bytes(s.peak_memory_bytes),
        s.threads,
        s.state_bits,
        s.branching,
    )
}
