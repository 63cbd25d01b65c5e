//! Design-rule checks: one model per lint that triggers it (exact codes and lines) and a clean
//! counterpart, plus a realistic model that must not trigger any warning.

use statecheck_base::{Diagnostic, LineIndex, Severity};
use std::path::PathBuf;

fn data(name: &str) -> String {
    let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "tests", "data", "lint", name]
        .iter()
        .collect();
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()))
}

/// Parse and check a data file; it must have no errors. Returns all diagnostics and the source.
fn check(name: &str) -> (Vec<Diagnostic>, String) {
    let src = data(name);
    let (file, parse_diags) = statecheck_syntax::parse(&src);
    assert!(
        parse_diags.is_empty(),
        "{name}: parse diagnostics: {parse_diags:#?}"
    );
    let (_, diags) = statecheck_model::check(&file);
    assert!(
        !diags.iter().any(Diagnostic::is_error),
        "{name}: errors: {diags:#?}"
    );
    (diags, src)
}

/// The design-rule findings (`W03xx`) of a data file as `(code, line)`, in source order.
fn lints(name: &str) -> Vec<(&'static str, usize)> {
    let (diags, src) = check(name);
    let index = LineIndex::new(&src);
    diags
        .iter()
        .filter(|d| d.code.starts_with("W03"))
        .inspect(|d| {
            assert_eq!(d.severity, Severity::Warning, "{name}: {d:#?}");
            assert!(
                !d.message.is_empty() && !d.label.is_empty(),
                "{name}: {d:#?}"
            );
            assert!(d.hint.is_some(), "{name}: lint without a hint: {d:#?}");
        })
        .map(|d| (d.code, index.line_col(d.span.start).0))
        .collect()
}

/// The line of the first secondary span of the finding with `code` at `line`.
fn secondary_line(name: &str, code: &str, line: usize) -> usize {
    let (diags, src) = check(name);
    let index = LineIndex::new(&src);
    let d = diags
        .iter()
        .find(|d| d.code == code && index.line_col(d.span.start).0 == line)
        .unwrap_or_else(|| panic!("{name}: no {code} at line {line}"));
    index.line_col(d.secondary[0].span.start).0
}

#[test]
fn w0301_state_without_incoming_transition() {
    assert_eq!(
        lints("w0301_no_incoming.sc"),
        [("W0301", 12), ("W0301", 16)]
    );
    assert_eq!(secondary_line("w0301_no_incoming.sc", "W0301", 12), 6);
    assert_eq!(lints("w0301_clean.sc"), []);
}

#[test]
fn w0302_isolated_sub_graph() {
    assert_eq!(lints("w0302_isolated.sc"), [("W0302", 11), ("W0302", 14)]);
    assert_eq!(secondary_line("w0302_isolated.sc", "W0302", 11), 5);
    assert_eq!(lints("w0302_clean.sc"), []);
}

#[test]
fn w0303_equal_priorities() {
    assert_eq!(lints("w0303_equal_priority.sc"), [("W0303", 8)]);
    assert_eq!(secondary_line("w0303_equal_priority.sc", "W0303", 8), 6);
    assert_eq!(lints("w0303_clean.sc"), []);
}

#[test]
fn w0304_shadowed_transitions() {
    assert_eq!(
        lints("w0304_shadowed.sc"),
        [("W0304", 8), ("W0304", 12), ("W0304", 15), ("W0304", 19)]
    );
    assert_eq!(secondary_line("w0304_shadowed.sc", "W0304", 8), 7);
    assert_eq!(secondary_line("w0304_shadowed.sc", "W0304", 15), 14);
    assert_eq!(secondary_line("w0304_shadowed.sc", "W0304", 19), 20);
    assert_eq!(lints("w0304_clean.sc"), []);
}

#[test]
fn w0305_constant_false_guard() {
    assert_eq!(lints("w0305_false_guard.sc"), [("W0305", 7), ("W0305", 12)]);
    assert_eq!(lints("w0305_clean.sc"), []);
}

#[test]
fn w0306_self_transition_on_composite_state() {
    assert_eq!(lints("w0306_composite_self.sc"), [("W0306", 8)]);
    assert_eq!(secondary_line("w0306_composite_self.sc", "W0306", 8), 6);
    assert_eq!(lints("w0306_clean.sc"), []);
}

#[test]
fn w0307_choice_that_can_fail() {
    assert_eq!(lints("w0307_choice_gap.sc"), [("W0307", 9), ("W0307", 17)]);
    assert_eq!(lints("w0307_clean.sc"), []);
}

#[test]
fn w0308_unused_declarations() {
    assert_eq!(
        lints("w0308_unused.sc"),
        [
            ("W0308", 4),
            ("W0308", 5),
            ("W0308", 6),
            ("W0308", 7),
            ("W0308", 8),
            ("W0308", 9)
        ]
    );
    assert_eq!(lints("w0308_clean.sc"), []);
}

#[test]
fn w0309_written_but_never_read() {
    assert_eq!(lints("w0309_write_only.sc"), [("W0309", 4), ("W0309", 5)]);
    assert_eq!(secondary_line("w0309_write_only.sc", "W0309", 4), 8);
    assert_eq!(secondary_line("w0309_write_only.sc", "W0309", 5), 9);
    assert_eq!(lints("w0309_clean.sc"), []);
}

#[test]
fn w0310_internal_transition_suppresses_during() {
    // Line 8: the chart's own `on reset / {..};` against the chart's `during` (line 7);
    // line 11: `A`'s `on bump [n < 9] / {..};` against `A`'s `during` (line 10); line 12
    // has a target and is not reported.
    assert_eq!(
        lints("w0310_during_suppressed.sc"),
        [("W0310", 8), ("W0310", 11)]
    );
    assert_eq!(secondary_line("w0310_during_suppressed.sc", "W0310", 11), 9);
    assert_eq!(lints("w0310_clean.sc"), []);
}

#[test]
fn realistic_model_is_clean() {
    let (diags, _) = check("realistic_clean.sc");
    assert!(diags.is_empty(), "{diags:#?}");
}

#[test]
fn examples_are_clean() {
    for example in ["fam/fam.sc", "linear_drive/linear_drive.sc"] {
        let path: PathBuf = [env!("CARGO_MANIFEST_DIR"), "..", "..", "examples", example]
            .iter()
            .collect();
        let Ok(src) = std::fs::read_to_string(&path) else {
            continue;
        };
        // fam.sc imports the FAM chart from lib/: follow its imports.
        let program = statecheck_model::imports::load_with(&path.to_string_lossy(), src, |k| {
            std::fs::read_to_string(k).ok()
        });
        assert!(program.diags.is_empty(), "{example}: {:#?}", program.diags);
        let (_, diags) = statecheck_model::check(&program.file);
        let lints: Vec<_> = diags.iter().filter(|d| d.code.starts_with("W03")).collect();
        assert!(lints.is_empty(), "{example}: {lints:#?}");
    }
}
