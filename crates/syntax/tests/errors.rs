//! Error tests: every `tests/data/errors/*.sc` file is malformed. The snapshot holds the
//! diagnostics (code, position, message, label, hint) followed by the AST that error recovery
//! kept, so both the messages and the recovery are pinned.

#![allow(clippy::unwrap_used)] // tests may unwrap

mod common;

use statecheck_syntax::parse;

/// How much of the recovered AST an error snapshot shows.
const MAX_AST_LINES: usize = 40;

#[test]
fn error_data_files() {
    let files = common::data_files("errors");
    assert!(files.len() >= 20, "expected at least 20 malformed inputs");
    for (name, src) in files {
        let (file, diags) = parse(&src);
        assert!(
            diags.iter().any(|d| d.is_error()),
            "{name}.sc should produce at least one error"
        );
        for d in &diags {
            assert!(
                d.code.starts_with("E00"),
                "{name}: unexpected code {}",
                d.code
            );
            assert!(
                d.span.end as usize <= src.len(),
                "{name}: span out of bounds"
            );
            assert!(!d.message.is_empty());
        }
        // Deeply nested recoveries would make huge snapshots: keep the first lines.
        let ast = common::render_file(&file);
        let mut lines: Vec<&str> = ast.lines().take(MAX_AST_LINES).collect();
        if ast.lines().count() > MAX_AST_LINES {
            lines.push("…");
        }
        let out = format!(
            "{}\n--- recovered AST ---\n{}\n",
            common::render_diags(&src, &diags),
            lines.join("\n")
        );
        insta::assert_snapshot!(name.clone(), out);
    }
}

/// Every error code the parser documents is produced by at least one error data file.
#[test]
fn every_code_is_exercised() {
    let mut seen = std::collections::BTreeSet::new();
    for (_, src) in common::data_files("errors") {
        for d in parse(&src).1 {
            seen.insert(d.code);
        }
    }
    for code in [
        "E0001", "E0002", "E0003", "E0004", "E0010", "E0011", "E0012", "E0013", "E0014", "E0015",
        "E0016", "E0017", "E0018", "E0019", "E0020",
    ] {
        assert!(seen.contains(code), "no error data file produces {code}");
    }
}

/// A "missing X" diagnostic points at an empty span right after the previous token.
#[test]
fn missing_semicolon_points_after_previous_token() {
    let src = "chart C { entry { n = 1 } }";
    let (_, diags) = parse(src);
    assert_eq!(diags.len(), 1);
    let d = &diags[0];
    assert_eq!(d.code, "E0011");
    assert_eq!(d.message, "expected `;` after assignment, found `}`");
    assert!(d.span.is_empty());
    assert_eq!(d.span.start as usize, src.find("1 }").unwrap() + 1);
}
