//! Rendering diagnostics for people: `file:line:col`, the span underlined, the hint.
//!
//! A program may consist of several files (imports); every span is an offset into the
//! [`Sources`] text of all of them, and each diagnostic and label is shown in the file that
//! contains it, named as the resolver named it.

use ariadne::{Color, Config, IndexType, Label, Report, ReportKind};
use statecheck_base::{Diagnostic, LineIndex, Severity, Span};
use statecheck_model::imports::{SourceFile, Sources};
use std::io::IsTerminal;

/// Render diagnostics of one source file to a string.
#[cfg(test)]
pub fn render(path: &str, source: &str, diags: &[Diagnostic], color: bool) -> String {
    render_sources(&single(path, source), diags, color)
}

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
        let text = sources.file_text(f);
        let len = text.len();
        let mut s = at.min(len);
        while !text.is_char_boundary(s) {
            s -= 1;
        }
        let mut e = (span.end as usize).saturating_sub(f.start).clamp(s, len);
        while !text.is_char_boundary(e) {
            e += 1;
        }
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
    // One line table per file for all diagnostics (per diagnostic, thousands of warnings
    // were quadratic).
    let mut srcs = ariadne::sources(cache.iter().map(|(n, t)| (n.clone(), t.clone())));
    let indexes: Vec<LineIndex> = cache.iter().map(|(_, t)| LineIndex::new(t)).collect();
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
        let fi = sources.files.partition_point(|f| f.start < file.start);
        let Some(idx) = indexes.get(fi) else {
            continue;
        };
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
        let _ = b.finish().write(&mut srcs, &mut out);
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

/// `text` with control characters (ANSI escapes, carriage returns, ...) shown as `\u{..}`
/// escapes, for printing names and lines that come from files to a terminal.
pub fn escape_controls(text: &str) -> std::borrow::Cow<'_, str> {
    if !text.chars().any(char::is_control) {
        return std::borrow::Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for c in text.chars() {
        if c.is_control() {
            out.extend(c.escape_unicode());
        } else {
            out.push(c);
        }
    }
    std::borrow::Cow::Owned(out)
}

/// Errors of one scenario shown in all (one per line); the rest are counted.
pub const MAX_SCENARIO_ERRORS: usize = 50;

/// The scenario errors worth printing: the first error of each line (a line with many bad
/// names would otherwise be echoed once per name), at most [`MAX_SCENARIO_ERRORS`] in all;
/// and the notes that count the rest, per line and after the last line shown.
pub fn cap_scenario_errors(
    errs: &[statecheck_sim::ScenarioError],
) -> (Vec<statecheck_sim::ScenarioError>, String) {
    use std::fmt::Write;
    let mut kept = Vec::new();
    let mut notes = String::new();
    let mut k = 0;
    while k < errs.len() {
        let line_no = errs[k].line;
        let end = errs[k..]
            .iter()
            .position(|e| e.line != line_no)
            .map_or(errs.len(), |p| k + p);
        if kept.len() == MAX_SCENARIO_ERRORS {
            let _ = writeln!(
                notes,
                "  … and {} more error(s) on later lines",
                errs.len() - k
            );
            break;
        }
        kept.push(errs[k].clone());
        if end - k > 1 {
            let _ = writeln!(
                notes,
                "  … and {} more error(s) on line {line_no}",
                end - k - 1
            );
        }
        k = end;
    }
    (kept, notes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use statecheck_sim::ScenarioError;

    fn err(line: usize, col: usize) -> ScenarioError {
        ScenarioError {
            code: "E0801",
            line,
            col,
            len: 1,
            message: "unknown input `x`".into(),
            hint: None,
        }
    }

    #[test]
    fn many_errors_on_one_scenario_line_print_the_line_once() {
        // 1,000 unknown names on one line once printed the whole line 1,000 times.
        let text = "x, ".repeat(1000);
        let errs: Vec<ScenarioError> = (0..1000).map(|k| err(1, 1 + 3 * k)).collect();
        let (kept, notes) = cap_scenario_errors(&errs);
        assert_eq!(kept.len(), 1);
        assert_eq!(kept[0].col, 1);
        assert_eq!(notes, "  … and 999 more error(s) on line 1\n");
        let _ = text;
    }

    #[test]
    fn errors_on_many_lines_stop_after_the_cap() {
        let text = "x\n".repeat(100);
        let errs: Vec<ScenarioError> = (1..=100).map(|l| err(l, 1)).collect();
        let (kept, notes) = cap_scenario_errors(&errs);
        assert_eq!(kept.len(), MAX_SCENARIO_ERRORS);
        assert_eq!(notes, "  … and 50 more error(s) on later lines\n");
        let _ = text;
    }

    #[test]
    fn thousands_of_diagnostics_render_each_once() {
        // 4,000 unused inputs once took a minute to render (the line table was rebuilt for
        // every diagnostic). Each is rendered with its own line number.
        let mut source = String::new();
        let mut diags = Vec::new();
        for k in 0..4000 {
            let start = source.len() + 6;
            source.push_str(&format!("input x{k};\n"));
            diags.push(Diagnostic::warning(
                "W0308",
                "never used",
                statecheck_base::Span::new(start, start + 2),
            ));
        }
        let out = render("m.sc", &source, &diags, false);
        assert_eq!(out.matches("W0308").count(), 4000);
        assert!(out.contains("(m.sc:4000:7)"));
    }

    #[test]
    fn control_characters_are_escaped() {
        assert_eq!(escape_controls("a\u{1b}[2Jb"), "a\\u{1b}[2Jb");
        assert_eq!(escape_controls("plain"), "plain");
    }
}
