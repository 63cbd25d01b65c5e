//! Differential testing: for random well-formed models and random input sequences, the IR
//! interpreter (what the simulator and checkers run), the generated C and the generated Rust
//! produce identical traces — every slot after every tick, and the same run-time error (kind,
//! site, value) on the same tick. All models are compiled into one C program (gcc with
//! `-std=c99 -Wall -Wextra -Wpedantic -Werror`) and one Rust program (rustc), in a temp dir.
//! The generator, the drivers and the comparison are the differential fuzzer's
//! (`statecheck-fuzz`, `crates/fuzz/src/{gen,diff}.rs`): one generator for both.

use statecheck_fuzz::diff::{self, Case};
use statecheck_fuzz::gen;
use std::path::PathBuf;
use std::process::Command;

const MODELS: u64 = 200;
const RUNS: usize = 8;
const TICKS: usize = 24;

fn temp_dir(tag: &str) -> PathBuf {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos())
        .unwrap_or(0);
    let d = std::env::temp_dir().join(format!("statecheck-{tag}-{}-{nanos}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

#[test]
fn interpreter_c_and_rust_agree_on_random_models() {
    let dir = temp_dir("diff");
    let mut cases: Vec<Case> = Vec::new();
    let mut rejected = Vec::new();
    for seed in 0..MODELS * 4 {
        if cases.len() as u64 == MODELS {
            break;
        }
        // Some random texts are rightly rejected (e.g. a constant out of range): skip them.
        let text = gen::Gen::new(seed).model();
        let p = match diff::lower(&text) {
            Ok(p) => p,
            Err(e) => {
                rejected.push(format!("seed {seed}: {e}\n{text}"));
                continue;
            }
        };
        cases.push(Case::random(text, p, seed ^ 0xA5A5_0000, RUNS, TICKS));
    }
    assert!(
        cases.len() as u64 == MODELS && rejected.iter().all(|r| r.contains("E0104")),
        "{} random models were rejected; first:\n{}",
        rejected.len(),
        rejected
            .iter()
            .find(|r| !r.contains("E0104"))
            .cloned()
            .unwrap_or_default()
    );
    let mut rep = diff::Report::default();
    diff::codegen_batch(&cases, &dir, true, &mut rep);
    assert!(
        rep.compile_failures.is_empty() && rep.failures.is_empty(),
        "{}",
        rep.compile_failures
            .iter()
            .chain(&rep.failures)
            .map(|f| f.chars().take(4000).collect::<String>())
            .collect::<Vec<_>>()
            .join("\n----\n")
    );
    assert_eq!(rep.c_models, MODELS);
    assert_eq!(rep.rust_models, MODELS);
    // The generated modules are `no_std`-compatible: one compiles in a `#![no_std]` library.
    std::fs::write(
        dir.join("nostd.rs"),
        "#![no_std]\n#[path = \"m0.rs\"]\nmod m0;\npub use m0::step;\n",
    )
    .expect("write");
    let ns = Command::new(std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into()))
        .args([
            "--edition",
            "2021",
            "--crate-type",
            "lib",
            "--emit",
            "metadata",
            "-o",
        ])
        .arg(dir.join("libnostd.rmeta"))
        .arg(dir.join("nostd.rs"))
        .output()
        .expect("rustc runs");
    assert!(
        ns.status.success(),
        "no_std: {}",
        String::from_utf8_lossy(&ns.stderr)
    );
    let mut want = String::new();
    for (k, c) in cases.iter().enumerate() {
        for (r, run) in c.runs.iter().enumerate() {
            diff::expected(k, r, &c.p, run, &mut want);
        }
    }
    let errors = want.lines().filter(|l| l.contains(" err ")).count();
    let runs = cases.len() * RUNS;
    assert!(runs >= 1000, "only {runs} runs");
    assert!(
        errors * 20 > runs,
        "too few run-time errors exercised: {errors} of {runs} runs"
    );
    assert!(
        errors * 10 < runs * 9,
        "almost every run fails at once: {errors} of {runs}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
