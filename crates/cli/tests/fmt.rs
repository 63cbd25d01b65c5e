//! `statecheck fmt` end to end, and the formatter's meaning preservation on every model of
//! the repository: the formatted text checks with the same diagnostics (codes, severities,
//! messages) and every system lowers to the same IR program (its `Debug` form, spans
//! erased, since only positions may move).

#![allow(clippy::unwrap_used)] // tests may unwrap

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_statecheck"))
}

fn sc_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        let name = e.file_name().to_string_lossy().into_owned();
        if p.is_dir() {
            if !(name.starts_with('.') || name.starts_with("target")) {
                sc_files(&p, out);
            }
        } else if name.ends_with(".sc") {
            out.push(p);
        }
    }
}

/// `Debug` text with every `Span { start: .., end: .. }` replaced by `Span`.
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

/// What the checker and the lowering make of a text read as the file `path` (its imports
/// followed), positions aside: the diagnostics (code, severity, message) and each system's
/// lowered program or lowering diagnostics.
fn meaning(path: &Path, src: &str) -> (Vec<String>, Vec<String>) {
    let program =
        statecheck_model::imports::load_with(&path.to_string_lossy(), src.to_string(), |k| {
            std::fs::read_to_string(k).ok()
        });
    let mut diags = program.diags;
    let (model, more) = statecheck_model::check(&program.file);
    diags.extend(more);
    let mut d: Vec<String> = diags
        .iter()
        .map(|d| format!("{} {:?} {}", d.code, d.severity, d.message))
        .collect();
    d.sort();
    let mut programs = Vec::new();
    if !diags.iter().any(|d| d.is_error()) {
        for sys in &model.systems {
            let p = match statecheck_ir::lower(&model, sys) {
                Ok(p) => format!("{p:?}"),
                Err(ds) => ds
                    .iter()
                    .map(|d| format!("{} {}\n", d.code, d.message))
                    .collect(),
            };
            programs.push(erase_spans(&p));
        }
    }
    (d, programs)
}

#[test]
fn formatting_every_repository_model_keeps_its_diagnostics_and_its_ir() {
    let mut files = Vec::new();
    sc_files(&repo_root(), &mut files);
    files.sort();
    let (mut same_ir, mut programs) = (0, 0);
    for path in &files {
        let src = std::fs::read_to_string(path).unwrap();
        let Ok(formatted) = statecheck_syntax::format::format(&src) else {
            continue; // syntax-error tests; crates/syntax/tests/format.rs checks they are all
        };
        let (d0, p0) = meaning(path, &src);
        let (d1, p1) = meaning(path, &formatted);
        assert_eq!(d0, d1, "{}: diagnostics changed", path.display());
        assert_eq!(p0.len(), p1.len(), "{}", path.display());
        for (a, b) in p0.iter().zip(&p1) {
            assert!(a == b, "{}: the lowered program changed", path.display());
        }
        programs += p0.len();
        same_ir += 1;
    }
    // 106 models parse; most lower to at least one program.
    assert!(same_ir >= 100, "{same_ir}");
    assert!(programs >= 80, "{programs}");
}

fn temp_copy(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("statecheck-fmt-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join("m.sc");
    std::fs::write(&p, text).unwrap();
    p
}

const MESSY: &str = "chart C{input event go;local n:int[0..3]=0;initial A;\nstate A{on go[n<3]/{n+=1;}->B;}   // back\nstate B{on go->A;}}\n";

/// By hand: two-space indentation, one element per line, a state with at most three one-line
/// elements on one line, the trailing comment kept after its state.
const TIDY: &str = "chart C {
  input event go;
  local n: int[0..3] = 0;
  initial A;
  state A { on go [n < 3] / { n += 1; } -> B; } // back
  state B { on go -> A; }
}
";

#[test]
fn fmt_rewrites_in_place_and_check_reports_without_writing() {
    let p = temp_copy("inplace", MESSY);
    let out = bin().arg("fmt").arg("--check").arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(1), "would change");
    assert_eq!(
        String::from_utf8_lossy(&out.stdout).trim(),
        p.display().to_string()
    );
    assert_eq!(
        std::fs::read_to_string(&p).unwrap(),
        MESSY,
        "--check writes nothing"
    );

    let out = bin().arg("fmt").arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(std::fs::read_to_string(&p).unwrap(), TIDY);

    let out = bin().arg("fmt").arg("--check").arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(0), "formatted: nothing to do");
    assert!(out.stdout.is_empty());
}

#[test]
fn fmt_dash_reads_standard_input_and_writes_standard_output() {
    let mut child = bin()
        .args(["fmt", "-"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    use std::io::Write;
    child
        .stdin
        .take()
        .unwrap()
        .write_all(MESSY.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(String::from_utf8_lossy(&out.stdout), TIDY);
}

#[test]
fn fmt_refuses_a_file_with_syntax_errors_and_leaves_it_alone() {
    let bad = "chart C { state A { on go -> } }\n";
    let p = temp_copy("bad", bad);
    let out = bin().arg("fmt").arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("E0010"), "{err}");
    assert_eq!(std::fs::read_to_string(&p).unwrap(), bad);
}
