//! Readable traces: `--show` chooses the table's variables and events (sim and verify), a
//! time column when the model declares its tick length, usage errors for patterns that match
//! nothing. (A connected signal shown once is pinned by `tests/semantics/connect_*`; wrapping
//! at a terminal's width by the unit tests of `output/table.rs`.)

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn statecheck(args: &[&str]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(root())
        .env("NO_COLOR", "1")
        .args(args)
        .output()
        .expect("statecheck runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    out
}

const LAMP: &str = "tests/dot/lamp.sc";
const LAMP_SCN: &str = "tests/dot/lamp.scn";

#[test]
fn show_chooses_columns_and_time_follows_the_tick_length() {
    // `tick 100 ms;`: tick t ends at t/10 s. The scenario sets `enabled` in tick 0 and gives
    // `press` in tick 1 (Off -> On); `after(3 s)` = 30 ticks, so On -> Off in tick 31. `count`
    // is not shown: only `lamp.press` and `lamp.en*` are. Two patterns in one argument.
    let out = statecheck(&[
        "sim",
        LAMP,
        "--scenario",
        LAMP_SCN,
        "--show",
        "lamp.press,lamp.en*",
    ]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).expect("utf-8");
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(
        lines[..3],
        [
            "tick  time (s)  active                     changes",
            "   0       0.0  lamp: Off; bounded: watch  lamp.enabled=true",
            "   1       0.1  lamp: On; bounded: watch   lamp.press!",
        ]
    );
    // lines[0] is the header: tick t is lines[t + 1].
    assert_eq!(lines[32], "  31       3.1  lamp: Off; bounded: watch");
    assert!(!text.contains("count"), "{text}");
    // The same chosen by repeating the flag.
    let again = statecheck(&[
        "sim",
        LAMP,
        "--scenario",
        LAMP_SCN,
        "--show",
        "lamp.press",
        "--show",
        "lamp.en*",
    ]);
    assert_eq!(again.stdout, text.as_bytes());
    // JSON is the contract: every variable stays.
    let json = statecheck(&[
        "sim",
        LAMP,
        "--scenario",
        LAMP_SCN,
        "--show",
        "lamp.press",
        "--json",
    ]);
    assert!(String::from_utf8_lossy(&json.stdout).contains("lamp.count"));
}

#[test]
fn a_pattern_that_matches_nothing_is_a_usage_error() {
    let out = statecheck(&["sim", LAMP, "--scenario", LAMP_SCN, "--show", "lamp.nope*"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--show `lamp.nope*` matches no variable or event"),
        "{err}"
    );
    let out = statecheck(&[
        "verify",
        "tests/verify/counter.sc",
        "--system",
        "Observed",
        "--show",
        "x",
    ]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn verify_counterexample_tables_take_show() {
    // counter.sc: `over6` enters `error` when k.c first exceeds 6, in tick 7 (c counts 0, 1,
    // ... from tick 0). With `--show 'k.*'` the table shows k.c; no tick length: no time.
    let out = statecheck(&[
        "verify",
        "tests/verify/counter.sc",
        "--system",
        "Observed",
        "--engine",
        "explicit",
        "--show",
        "k.*",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    let table: Vec<&str> = text
        .lines()
        .skip_while(|l| !l.starts_with("counterexample for `over6`"))
        .skip(1)
        .take(9)
        .collect();
    let mut want = vec!["tick  active                changes".to_string()];
    for t in 0..7 {
        want.push(format!("   {t}  k: Run; over6: Watch  k.c={t}"));
    }
    want.push("   7  k: Run; over6: error  k.c=7".to_string());
    assert_eq!(table, want, "{text}");
}
