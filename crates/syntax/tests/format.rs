//! The formatter on every `.sc` file of the repository: idempotent, and the formatted text
//! parses to the same tree (spans aside) with the same comments in the same order.
//! (`crates/cli/tests/fmt.rs` checks the same files end to end: same diagnostics, same IR.)

mod format_common;

use format_common::{check_preserved, sc_files};

#[test]
fn every_repository_model_formats_idempotently_and_keeps_its_tree_and_comments() {
    let files = sc_files();
    let mut formatted = 0;
    for path in &files {
        let name = path.display().to_string();
        let src = std::fs::read_to_string(path).expect("readable");
        let has_errors = statecheck_syntax::parse(&src)
            .1
            .iter()
            .any(|d| d.is_error());
        match statecheck_syntax::format::format(&src) {
            Ok(_) => {
                assert!(!has_errors, "{name}: formatted despite syntax errors");
                check_preserved(&name, &src);
                formatted += 1;
            }
            Err(_) => {
                assert!(has_errors, "{name}: refused without syntax errors");
                // Files with syntax errors are kept only as diagnostics tests and as the
                // fuzz targets' inputs (`crates/fuzz/corpus/`: mutated texts, malformed on
                // purpose).
                assert!(
                    name.contains("/errors/")
                        || name.contains("/diagnostics/")
                        || name.contains("/fuzz/corpus/"),
                    "{name}: refused"
                );
            }
        }
    }
    // 151 files at the time of writing, 45 of them syntax-error tests (`find -name '*.sc'`).
    assert!(
        formatted >= 100,
        "formatted only {formatted} of {}",
        files.len()
    );
}

#[test]
fn random_texts_format_idempotently_and_keep_their_tree_and_comments() {
    // 10^4 and more run in `cargo bench -p statecheck-syntax --bench fmt_fuzz`.
    let (n, _) = format_common::fuzz(0..400);
    assert_eq!(n, 400);
}

/// Temporal formulas whose operands are chains of the same operator or looser operators
/// under tighter ones. The parser reads a parenthesised group without temporal operators as
/// one atom, so a needless pair of parentheses changes the tree: `a && b && G c` is
/// `And(And(a, b), G c)`, and `(a && b) && G c` would be `And(atom a && b, G c)` (found by the
/// `fmt` fuzz target on a mutated `fam_live4.sc`). Each text below is its own canonical form.
#[test]
fn temporal_formulas_keep_their_grouping() {
    let formulas = [
        "a && b && G c",
        "a || b || F c",
        "a && b || c && G d",
        "(a || G b) && c",
        "a || b => G c",
        "(a => G b) => c",
        "G a => F b => c",
        "a U b U c",
        "(a U b) U c",
        "a && b U c",
        "A[a && b || c U d && e]",
        "A[(a U b) && c U d]",
        "!(a U b) && c",
        "F G (a && b) => G (c => F !d)",
    ];
    for f in formulas {
        let src = format!("system S {{\n  ltl p: {f};\n}}\n");
        let once = check_preserved(f, &src);
        assert!(
            once.contains(&format!("ltl p: {f};")),
            "{f}: printed as\n{once}"
        );
    }
}

/// A block comment over two lines, trailing a statement, with the next statement on the
/// comment's last line. Formatting moves that statement to its own line; the line break
/// inside the comment must not then count as a blank line before it, or a second run adds
/// one (found by the `fmt` fuzz target on a mutated chart).
#[test]
fn a_trailing_comment_over_two_lines_is_formatted_once() {
    let src =
        "chart C {\n  initial A;\n  state A {\n    initial B;/* one\n  two*/ state B;\n  }\n}\n";
    let once = check_preserved("trailing block comment", src);
    assert!(
        once.contains("initial B; /* one\n  two*/\n    state B;"),
        "{once}"
    );
}
