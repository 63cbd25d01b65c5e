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
