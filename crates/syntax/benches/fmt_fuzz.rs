//! The formatter on many random texts (the generator of `tests/format_common/gen.rs`):
//! idempotent, same tree, same comments. Prints figures; not a timed test.
//!
//! `cargo bench -p statecheck-syntax --bench fmt_fuzz` (10 000 cases; `FMT_FUZZ_CASES=N`
//! for another count, `FMT_FUZZ_FIRST=S` for another first seed).

#[path = "../tests/format_common/mod.rs"]
mod format_common;

fn main() {
    let env = |k: &str, d: u64| {
        std::env::var(k)
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(d)
    };
    let n = env("FMT_FUZZ_CASES", 10_000);
    let first = env("FMT_FUZZ_FIRST", 1_000_000);
    let t = std::time::Instant::now();
    let (files, bytes) = format_common::fuzz(first..first + n);
    let secs = t.elapsed().as_secs_f64();
    println!(
        "fmt_fuzz: {files} random files ({bytes} bytes, seeds {first}..{}) formatted, \
         idempotent, same tree and comments, in {secs:.2} s",
        first + n
    );
}
