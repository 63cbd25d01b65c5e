//! Shared checks of the formatter tests.

#![allow(dead_code)] // reason: each test binary uses a different part of this module

use statecheck_syntax::format::format;
use std::path::PathBuf;

/// Every `.sc` file of the repository (`examples/`, `tests/`, the crates' test data, docs),
/// sorted; build output and hidden directories are skipped.
pub fn sc_files() -> Vec<PathBuf> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut out = Vec::new();
    walk(&root, &mut out);
    out.sort();
    out
}

fn walk(dir: &std::path::Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    for e in rd.flatten() {
        let p = e.path();
        let name = e.file_name();
        let name = name.to_string_lossy();
        if p.is_dir() {
            if !(name.starts_with('.') || name.starts_with("target") || name == "node_modules") {
                walk(&p, out);
            }
        } else if p.extension().is_some_and(|x| x == "sc") {
            out.push(p);
        }
    }
}

/// The `Debug` form of a parsed tree with every span erased, so that two texts that differ
/// only in layout compare equal.
pub fn tree_without_spans(src: &str) -> String {
    let (file, _) = statecheck_syntax::parse(src);
    erase_spans(&format!("{file:?}"))
}

fn erase_spans(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut rest = s;
    while let Some(i) = rest.find("Span {") {
        out.push_str(&rest[..i]);
        out.push_str("Span");
        let after = &rest[i..];
        let close = after.find('}').map_or(after.len(), |j| j + 1);
        rest = &after[close..];
    }
    out.push_str(rest);
    out
}

/// The comments of a text in order (from the lexer's point of view: `//` to end of line,
/// `/* … */`), trimmed at the end.
pub fn comments(src: &str) -> Vec<String> {
    let mut v = Vec::new();
    let b = src.as_bytes();
    let mut i = 0;
    // A tiny lexer: the language has no string literals, so `//` and `/*` always start comments.
    while i < b.len() {
        if b[i] == b'/' && b.get(i + 1) == Some(&b'/') {
            let end = src[i..].find('\n').map_or(src.len(), |j| i + j);
            v.push(src[i..end].trim_end().to_string());
            i = end;
        } else if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
            let end = src[i + 2..].find("*/").map_or(src.len(), |j| i + 2 + j + 2);
            v.push(src[i..end].trim_end().to_string());
            i = end;
        } else {
            i += 1;
        }
    }
    v
}

/// Format `src` (which must parse) and check: the result parses without errors, has the same
/// tree and the same comments, and formatting it again changes nothing. Returns it.
pub fn check_preserved(name: &str, src: &str) -> String {
    let once = match format(src) {
        Ok(f) => f,
        Err(e) => panic!("{name}: not formatted: {e}"),
    };
    let (_, diags) = statecheck_syntax::parse(&once);
    let errors: Vec<_> = diags.iter().filter(|d| d.is_error()).collect();
    assert!(
        errors.is_empty(),
        "{name}: formatted text has errors {errors:?}\n{once}"
    );
    assert_eq!(
        tree_without_spans(src),
        tree_without_spans(&once),
        "{name}: the tree changed\n--- formatted:\n{once}"
    );
    assert_eq!(
        comments(src),
        comments(&once),
        "{name}: comments changed\n{once}"
    );
    let twice = format(&once).unwrap_or_else(|e| panic!("{name}: second run: {e}"));
    assert_eq!(once, twice, "{name}: not idempotent");
    once
}

pub mod gen;

/// Run the preservation checks on the random files of `seeds`; returns (files, bytes).
pub fn fuzz(seeds: std::ops::Range<u64>) -> (usize, usize) {
    let mut bytes = 0;
    let mut n = 0;
    for seed in seeds {
        let src = gen::random_file(seed);
        let (_, diags) = statecheck_syntax::parse(&src);
        let errors: Vec<_> = diags.iter().filter(|d| d.is_error()).collect();
        assert!(
            errors.is_empty(),
            "seed {seed}: generated text does not parse: {errors:?}\n{src}"
        );
        check_preserved(&format!("seed {seed}"), &src);
        bytes += src.len();
        n += 1;
    }
    (n, bytes)
}
