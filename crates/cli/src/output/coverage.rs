//! Coverage reports (the Modelica paper §3.2): state entries and transition firings.

use serde_json::{json, Value};
use statecheck_ir::{CoverKind, Program};
use statecheck_model::imports::Sources;

/// Covered and total counts of one kind of item.
pub struct Tally {
    /// Items hit at least once.
    pub covered: usize,
    /// All items.
    pub total: usize,
}

impl Tally {
    /// Percentage covered (100 when there is nothing to cover).
    pub fn percent(&self) -> f64 {
        if self.total == 0 {
            100.0
        } else {
            100.0 * self.covered as f64 / self.total as f64
        }
    }
}

fn tally(p: &Program, counts: &[u64], states: bool) -> Tally {
    let mut t = Tally {
        covered: 0,
        total: 0,
    };
    for (c, n) in p.covers.iter().zip(counts) {
        // An observer's `error` state (and what leads only to it) is meant never to be
        // covered: it is left out of the figures.
        if matches!(c.kind, CoverKind::State(_)) == states && !c.expected_unreached {
            t.total += 1;
            t.covered += usize::from(*n > 0);
        }
    }
    t
}

fn kind_name(k: &CoverKind) -> &'static str {
    match k {
        CoverKind::State(_) => "state",
        CoverKind::Transition(_) => "transition",
        CoverKind::Branch(..) => "branch",
    }
}

/// A human-readable summary with the never-covered items.
pub fn summary(p: &Program, counts: &[u64], sources: &Sources) -> String {
    let s = tally(p, counts, true);
    let t = tally(p, counts, false);
    let mut out = format!(
        "coverage: states {}/{} ({:.1}%), transitions {}/{} ({:.1}%)\n",
        s.covered,
        s.total,
        s.percent(),
        t.covered,
        t.total,
        t.percent()
    );
    for (c, n) in p.covers.iter().zip(counts) {
        if *n == 0 && !c.expected_unreached {
            let (file, line, col) = place(sources, c.span.start);
            let root = sources.files.first().is_none_or(|f| f.name == file);
            let at = if root {
                format!("line {line}:{col}")
            } else {
                format!("{file}:{line}:{col}")
            };
            let inst = &p.instances[c.instance as usize].name;
            out.push_str(&format!(
                "  never {}: {inst}: {} ({at})\n",
                if matches!(c.kind, CoverKind::State(_)) {
                    "entered"
                } else {
                    "fired"
                },
                c.label
            ));
        }
    }
    out
}

/// The coverage report as JSON (read back by `statecheck dot --coverage`).
pub fn to_json(p: &Program, counts: &[u64], sources: &Sources) -> Value {
    let s = tally(p, counts, true);
    let t = tally(p, counts, false);
    let items: Vec<Value> = p
        .covers
        .iter()
        .zip(counts)
        .enumerate()
        .map(|(id, (c, n))| {
            let (file, line, col) = place(sources, c.span.start);
            json!({"id": id, "instance": p.instances[c.instance as usize].name, "kind": kind_name(&c.kind), "label": c.label, "count": n, "file": file, "line": line, "col": col, "expected_unreached": c.expected_unreached})
        })
        .collect();
    json!({
        "system": p.name,
        "states": {"covered": s.covered, "total": s.total, "percent": s.percent()},
        "transitions": {"covered": t.covered, "total": t.total, "percent": t.percent()},
        "items": items,
    })
}

/// Read counts back from a coverage JSON file, checking it matches the program.
pub fn from_json(p: &Program, v: &Value) -> Result<Vec<u64>, String> {
    let items = v
        .get("items")
        .and_then(Value::as_array)
        .ok_or("not a statecheck coverage file (no `items`)")?;
    if items.len() != p.covers.len() {
        return Err(format!("the coverage file has {} items but the model has {}; was it written for another model or system?", items.len(), p.covers.len()));
    }
    let mut counts = vec![0; items.len()];
    for (k, it) in items.iter().enumerate() {
        let label = it.get("label").and_then(Value::as_str).unwrap_or("");
        if label != p.covers[k].label {
            return Err(format!("coverage item {k} is `{label}` but the model's is `{}`; the model changed since the coverage was recorded", p.covers[k].label));
        }
        counts[k] = it.get("count").and_then(Value::as_u64).unwrap_or(0);
    }
    Ok(counts)
}

/// The file, 1-based line and column of a byte offset of a program's text.
fn place(sources: &Sources, offset: u32) -> (String, usize, usize) {
    match sources.locate(offset as usize) {
        Some((f, at)) => {
            let (l, c) = statecheck_base::LineIndex::new(sources.file_text(f)).line_col(at as u32);
            (f.name.clone(), l, c)
        }
        None => (String::new(), 0, 0),
    }
}
