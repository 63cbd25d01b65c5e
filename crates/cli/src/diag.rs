//! Rendering diagnostics for people: `file:line:col`, the span underlined, the hint.
//!
//! A program may consist of several files (imports); every span is an offset into the
//! [`Sources`] text of all of them, and each diagnostic and label is shown in the file that
//! contains it, named as the resolver named it.

use ariadne::{Color, Config, IndexType, Label, Report, ReportKind};
use statecheck_base::{Diagnostic, LineIndex, Severity, Span};
use statecheck_model::imports::{SourceFile, Sources};
use std::io::IsTerminal;

/// One file as [`Sources`].
pub fn single(path: &str, source: &str) -> Sources {
    Sources {
        text: source.to_string(),
        files: vec![SourceFile {
            key: path.to_string(),
            name: path.to_string(),
            start: 0,
            end: source.len(),
        }],
    }
}

/// Where a span is: its file (the last one if it is in none) and its range in that file.
fn place(sources: &Sources, span: Span) -> Option<(&SourceFile, std::ops::Range<usize>)> {
    if let Some((f, at)) = sources.locate(span.start as usize) {
        let len = f.end - f.start;
        let s = at.min(len);
        let e = (span.end as usize).saturating_sub(f.start).clamp(s, len);
        return Some((f, s..e));
    }
    let f = sources.files.last()?;
    let len = f.end - f.start;
    Some((f, len..len))
}

/// Render diagnostics of a program of one or more files to a string.
pub fn render_sources(sources: &Sources, diags: &[Diagnostic], color: bool) -> String {
    let mut out = Vec::new();
    let cache: Vec<(String, String)> = sources
        .files
        .iter()
        .map(|f| (f.name.clone(), sources.file_text(f).to_string()))
        .collect();
    for d in diags {
        let kind = match d.severity {
            Severity::Error => ReportKind::Error,
            Severity::Warning => ReportKind::Warning,
            Severity::Note => ReportKind::Advice,
        };
        let Some((file, range)) = place(sources, d.span) else {
            continue;
        };
        let path = file.name.clone();
        let idx = LineIndex::new(sources.file_text(file));
        let (line, col) = idx.line_col(range.start as u32);
        let mut b = Report::build(kind, (path.clone(), range.clone()))
            .with_config(
                Config::default()
                    .with_color(color)
                    .with_index_type(IndexType::Byte),
            )
            .with_code(d.code)
            .with_message(format!("{} ({path}:{line}:{col})", d.message))
            .with_label(
                Label::new((path.clone(), range))
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
            let Some((f, r)) = place(sources, l.span) else {
                continue;
            };
            b = b.with_label(
                Label::new((f.name.clone(), r))
                    .with_message(&l.message)
                    .with_color(Color::Blue),
            );
        }
        if let Some(h) = &d.hint {
            b = b.with_help(h);
        }
        let srcs = ariadne::sources(cache.iter().map(|(n, t)| (n.clone(), t.clone())));
        let _ = b.finish().write(srcs, &mut out);
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// Print diagnostics to stderr, in color on a terminal (as JSON lines with
/// `--message-format json`).
pub fn eprint(path: &str, source: &str, diags: &[Diagnostic]) {
    eprint_sources(&single(path, source), diags);
}

/// A diagnostic with its spans made relative to the file of its primary span (secondary
/// labels in other files are dropped), and that file.
fn localise<'s>(sources: &'s Sources, d: &Diagnostic) -> Option<(&'s SourceFile, Diagnostic)> {
    let (f, r) = place(sources, d.span)?;
    let mut local = d.clone();
    local.span = Span::new(r.start, r.end);
    local.secondary = d
        .secondary
        .iter()
        .filter_map(|l| {
            let (g, r) = place(sources, l.span)?;
            (g.start == f.start).then(|| statecheck_base::Label {
                span: Span::new(r.start, r.end),
                message: l.message.clone(),
            })
        })
        .collect();
    Some((f, local))
}

/// Print diagnostics of a program of one or more files to stderr, in color on a terminal
/// (as JSON lines, each naming its file, with `--message-format json`).
pub fn eprint_sources(sources: &Sources, diags: &[Diagnostic]) {
    if crate::diag_json::is_json() {
        let mut out = String::new();
        for d in diags {
            if let Some((f, local)) = localise(sources, d) {
                let text = sources.file_text(f);
                out.push_str(&crate::diag_json::to_json(&f.name, text, &local).to_string());
                out.push('\n');
            }
        }
        eprint!("{out}");
        return;
    }
    let color = std::io::stderr().is_terminal() && std::env::var_os("NO_COLOR").is_none();
    eprint!("{}", render_sources(sources, diags, color));
}
