//! Rendering diagnostics for people: `file:line:col`, the span underlined, the hint.

use ariadne::{Color, Config, IndexType, Label, Report, ReportKind, Source};
use statecheck_base::{Diagnostic, LineIndex, Severity};
use std::io::IsTerminal;

/// Render diagnostics of one source file to a string.
pub fn render(path: &str, source: &str, diags: &[Diagnostic], color: bool) -> String {
    let mut out = Vec::new();
    let idx = LineIndex::new(source);
    for d in diags {
        let kind = match d.severity {
            Severity::Error => ReportKind::Error,
            Severity::Warning => ReportKind::Warning,
            Severity::Note => ReportKind::Advice,
        };
        let range = clamp(d.span.range(), source.len());
        let (line, col) = idx.line_col(range.start as u32);
        let mut b = Report::build(kind, (path.to_string(), range.clone()))
            .with_config(
                Config::default()
                    .with_color(color)
                    .with_index_type(IndexType::Byte),
            )
            .with_code(d.code)
            .with_message(format!("{} ({path}:{line}:{col})", d.message))
            .with_label(
                Label::new((path.to_string(), range))
                    .with_message(if d.label.is_empty() {
                        "here".to_string()
                    } else {
                        d.label.clone()
                    })
                    .with_color(if d.is_error() {
                        Color::Red
                    } else {
                        Color::Yellow
                    }),
            );
        for l in &d.secondary {
            b = b.with_label(
                Label::new((path.to_string(), clamp(l.span.range(), source.len())))
                    .with_message(&l.message)
                    .with_color(Color::Blue),
            );
        }
        if let Some(h) = &d.hint {
            b = b.with_help(h);
        }
        let _ = b
            .finish()
            .write((path.to_string(), Source::from(source)), &mut out);
    }
    String::from_utf8_lossy(&out).into_owned()
}

fn clamp(r: std::ops::Range<usize>, len: usize) -> std::ops::Range<usize> {
    let s = r.start.min(len);
    s..r.end.clamp(s, len)
}

/// Print diagnostics to stderr, in color on a terminal (as JSON lines with
/// `--message-format json`).
pub fn eprint(path: &str, source: &str, diags: &[Diagnostic]) {
    if crate::diag_json::is_json() {
        eprint!("{}", crate::diag_json::render(path, source, diags));
        return;
    }
    let color = std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none();
    eprint!("{}", render(path, source, diags, color));
}
