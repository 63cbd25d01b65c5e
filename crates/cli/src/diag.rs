//! Rendering diagnostics for people: `file:line:col`, the span underlined, the hint.

use ariadne::{Color, Config, IndexType, Label, Report, ReportKind, Source};
use statecheck_base::{Diagnostic, LineIndex, Severity};
use std::io::IsTerminal;

/// Render diagnostics of one source file to a string.
pub fn render(path: &str, source: &str, diags: &[Diagnostic], color: bool) -> String {
    let mut out = Vec::new();
    let idx = LineIndex::new(source);
    // One line table for all diagnostics: building it per diagnostic made a file with
    // thousands of warnings quadratic (4,000 unused inputs took a minute).
    let src = Source::from(source);
    for d in diags {
        let kind = match d.severity {
            Severity::Error => ReportKind::Error,
            Severity::Warning => ReportKind::Warning,
            Severity::Note => ReportKind::Advice,
        };
        let range = clamp(d.span.range(), source);
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
                Label::new((path.to_string(), clamp(l.span.range(), source)))
                    .with_message(&l.message)
                    .with_color(Color::Blue),
            );
        }
        if let Some(h) = &d.hint {
            b = b.with_help(h);
        }
        let _ = b.finish().write((path.to_string(), &src), &mut out);
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// `r` inside `source` and on character boundaries (the renderer slices the text there).
fn clamp(r: std::ops::Range<usize>, source: &str) -> std::ops::Range<usize> {
    let len = source.len();
    let mut s = r.start.min(len);
    while !source.is_char_boundary(s) {
        s -= 1;
    }
    let mut e = r.end.clamp(s, len);
    while !source.is_char_boundary(e) {
        e += 1;
    }
    s..e
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
