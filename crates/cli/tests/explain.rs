//! `statecheck explain` and the one table of codes (`crates/base/src/codes.rs`): every code
//! emitted anywhere in the sources has an entry, and `docs/diagnostics.md` is generated from
//! the table (`UPDATE_EXPECT=1` rewrites it).

#![allow(clippy::unwrap_used)] // tests may unwrap

use statecheck_base::codes::{lookup, markdown_index, CODES};
use std::path::{Path, PathBuf};
use std::process::Command;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// Every string literal of the form `"E1234"` or `"W1234"` in the crates' `src/` folders.
fn emitted_codes() -> Vec<String> {
    let mut files = Vec::new();
    for e in std::fs::read_dir(root().join("crates")).unwrap().flatten() {
        let src = e.path().join("src");
        if src.is_dir() {
            rust_files(&src, &mut files);
        }
    }
    let mut codes = std::collections::BTreeSet::new();
    for f in files {
        let text = std::fs::read_to_string(&f).unwrap();
        let b = text.as_bytes();
        for i in 0..b.len().saturating_sub(6) {
            let lit = &b[i..i + 7];
            if lit[0] == b'"'
                && (lit[1] == b'E' || lit[1] == b'W')
                && lit[2..6].iter().all(u8::is_ascii_digit)
                && lit[6] == b'"'
            {
                codes.insert(String::from_utf8(lit[1..6].to_vec()).unwrap());
            }
        }
    }
    codes.into_iter().collect()
}

#[test]
fn every_emitted_code_has_an_entry() {
    let codes = emitted_codes();
    // 61 distinct codes at the time of writing (grep -rhoE '"[EW][0-9]{4}"' crates/*/src).
    assert!(codes.len() >= 61, "{codes:?}");
    let missing: Vec<&String> = codes.iter().filter(|c| lookup(c).is_none()).collect();
    assert!(
        missing.is_empty(),
        "codes without an entry in crates/base/src/codes.rs: {missing:?}"
    );
    let mut seen = std::collections::BTreeSet::new();
    for c in CODES {
        assert!(seen.insert(c.code), "{} twice in the table", c.code);
        assert!(
            root().join("docs").join(c.doc).is_file(),
            "{}: no docs/{}",
            c.code,
            c.doc
        );
    }
}

#[test]
fn docs_index_is_generated_from_the_table() {
    let path = root().join("docs/diagnostics.md");
    let want = markdown_index();
    if std::env::var_os("UPDATE_EXPECT").is_some() {
        std::fs::write(&path, &want).unwrap();
    }
    let have = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(have == want, "docs/diagnostics.md is stale: run UPDATE_EXPECT=1 cargo test -p statecheck-cli --test explain");
}

#[test]
fn explain_prints_the_page_of_a_code() {
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .args(["explain", "e0111"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.starts_with("E0111: unknown transition target\n"),
        "{text}"
    );
    assert!(
        text.contains("right.B") && text.contains("docs/language.md"),
        "{text}"
    );
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .args(["explain", "E9999"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .arg("explain")
        .output()
        .unwrap();
    let list = String::from_utf8_lossy(&out.stdout);
    assert_eq!(list.lines().count(), CODES.len());
    assert!(list.contains("W0304  transition that can never fire"));
}
