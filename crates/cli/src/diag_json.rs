//! Diagnostics for programs: `--message-format json` prints one JSON object per diagnostic,
//! one per line, on standard error (standard output keeps the command's own output).
//!
//! Fields: `code`, `severity` (`error`, `warning`, `note`), `message`, `file`, `line`, `col`
//! (1-based; the column counts characters), `end` (`{line, col}` just past the span), `label`
//! (the primary label's text), `labels` (secondary spans: `{line, col, end, message}`) and
//! `hint` (or null). Fields are a contract: extend, never rename.

use serde_json::{json, Value};
use statecheck_base::{Diagnostic, Severity};
use std::sync::atomic::{AtomicBool, Ordering};

static JSON: AtomicBool = AtomicBool::new(false);

/// Choose the format for every diagnostic printed from now on.
pub fn set_json(on: bool) {
    JSON.store(on, Ordering::Relaxed);
}

/// True when diagnostics are printed as JSON lines.
pub fn is_json() -> bool {
    JSON.load(Ordering::Relaxed)
}

/// 1-based line and character column of a byte offset (clamped to the text).
fn line_col(source: &str, offset: u32) -> (usize, usize) {
    let mut off = (offset as usize).min(source.len());
    while !source.is_char_boundary(off) {
        off -= 1;
    }
    let before = &source[..off];
    let line = before.matches('\n').count() + 1;
    let start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, source[start..off].chars().count() + 1)
}

/// One diagnostic as a JSON object.
pub fn to_json(path: &str, source: &str, d: &Diagnostic) -> Value {
    let (line, col) = line_col(source, d.span.start);
    let (eline, ecol) = line_col(source, d.span.end);
    let labels: Vec<Value> = d
        .secondary
        .iter()
        .map(|l| {
            let (a, b) = line_col(source, l.span.start);
            let (c, e) = line_col(source, l.span.end);
            json!({ "line": a, "col": b, "end": { "line": c, "col": e }, "message": l.message })
        })
        .collect();
    json!({
        "code": d.code,
        "severity": match d.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Note => "note",
        },
        "message": d.message,
        "file": path,
        "line": line,
        "col": col,
        "end": { "line": eline, "col": ecol },
        "label": d.label,
        "labels": labels,
        "hint": d.hint,
    })
}
