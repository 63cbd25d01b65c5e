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

/// Print diagnostics to stderr, in color on a terminal.
pub fn eprint(path: &str, source: &str, diags: &[Diagnostic]) {
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

/// Errors on one scenario line shown in full; the rest are counted.
pub const MAX_SCENARIO_ERRORS_PER_LINE: usize = 3;
/// Errors of one scenario shown in all; the rest are counted.
pub const MAX_SCENARIO_ERRORS: usize = 50;
/// Characters of a scenario line echoed under its error.
const MAX_ECHO: usize = 200;

/// Render scenario errors: the first error of a line with the line and an underline, further
/// errors on the same line without repeating it, at most [`MAX_SCENARIO_ERRORS_PER_LINE`] per
/// line and [`MAX_SCENARIO_ERRORS`] in all (then a count of the rest). The cost is linear in
/// the text and the number of errors.
pub fn render_scenario_errors(
    path: &str,
    text: &str,
    errs: &[statecheck_sim::ScenarioError],
) -> String {
    use std::fmt::Write;
    let lines: Vec<&str> = text.lines().collect();
    let mut out = String::new();
    let mut shown = 0;
    let mut k = 0;
    while k < errs.len() {
        let line_no = errs[k].line;
        let end = errs[k..]
            .iter()
            .position(|e| e.line != line_no)
            .map_or(errs.len(), |p| k + p);
        let on_line = &errs[k..end];
        let line = lines.get(line_no.wrapping_sub(1)).copied().unwrap_or("");
        for (n, e) in on_line.iter().enumerate() {
            if n == MAX_SCENARIO_ERRORS_PER_LINE || shown == MAX_SCENARIO_ERRORS {
                let _ = writeln!(
                    out,
                    "  … and {} more error(s) on line {line_no}",
                    on_line.len() - n
                );
                break;
            }
            shown += 1;
            let _ = writeln!(
                out,
                "error: {} ({path}:{}:{})",
                escape_controls(&e.message),
                e.line,
                e.col
            );
            if n == 0 {
                let echo: String = line.chars().take(MAX_ECHO).collect();
                let _ = writeln!(out, "  | {}", escape_controls(&echo));
                if e.col <= MAX_ECHO && !echo.chars().any(char::is_control) {
                    let room = echo.len().saturating_sub(e.col - 1);
                    let _ = writeln!(
                        out,
                        "  | {}{}",
                        " ".repeat(e.col - 1),
                        "^".repeat(e.len.min(room).max(1))
                    );
                }
            }
            if let Some(h) = &e.hint {
                let _ = writeln!(out, "  = help: {}", escape_controls(h));
            }
        }
        if shown == MAX_SCENARIO_ERRORS && end < errs.len() {
            let rest = errs.len() - end;
            let _ = writeln!(out, "  … and {rest} more error(s) on later lines");
            break;
        }
        k = end;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use statecheck_sim::ScenarioError;

    fn err(line: usize, col: usize) -> ScenarioError {
        ScenarioError {
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
        let out = render_scenario_errors("s.scn", &text, &errs);
        assert_eq!(out.matches("  | x, x,").count(), 1);
        assert_eq!(out.matches("error: ").count(), MAX_SCENARIO_ERRORS_PER_LINE);
        assert!(out.contains("… and 997 more error(s) on line 1"));
    }

    #[test]
    fn errors_on_many_lines_stop_after_the_cap() {
        let text = "x\n".repeat(100);
        let errs: Vec<ScenarioError> = (1..=100).map(|l| err(l, 1)).collect();
        let out = render_scenario_errors("s.scn", &text, &errs);
        assert_eq!(out.matches("error: ").count(), MAX_SCENARIO_ERRORS);
        assert!(out.contains("… and 50 more error(s) on later lines"));
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
