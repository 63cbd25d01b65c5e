//! `statecheck dot`: labels with real line breaks, triggers, guards and actions as written,
//! timers in the model's units, observer `error` states not drawn or reported as gaps, and
//! `--svg` through Graphviz (installed by scripts/test.sh) or error E0901 without it.
//!
//! The model is `tests/dot/lamp.sc`, its run `tests/dot/lamp.scn`: tick 0 enters `Off`;
//! `press` (with `enabled`) in tick 1 fires `Off -> On` (count 1); `after(3 s)` with 100 ms
//! ticks is 30 ticks, so `On -> Off` fires in tick 31; the scenario ends in tick 32. So `Off`
//! is entered twice, `On` once, each Lamp transition fires once, and the observer stays in
//! `watch` (entered once): `in(lamp.On) && lamp.count == 0` never holds since `On` is only
//! entered with count 1 or more.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn statecheck(args: &[&str], env: &[(&str, &str)]) -> Output {
    let out = Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(root())
        .env("NO_COLOR", "1")
        .envs(env.iter().copied())
        .args(args)
        .output()
        .expect("statecheck runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    out
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("statecheck-dot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

const LAMP: &str = "tests/dot/lamp.sc";
const LAMP_SCN: &str = "tests/dot/lamp.scn";

/// The coverage file of the scenario run, and the run's stderr summary.
fn coverage(name: &str) -> (String, String) {
    let c = temp(name);
    let c = c.to_str().expect("utf-8 path").to_string();
    let out = statecheck(
        &["sim", LAMP, "--scenario", LAMP_SCN, "--coverage", &c],
        &[],
    );
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let mut summary = String::from_utf8_lossy(&out.stdout).into_owned();
    summary.push_str(&String::from_utf8_lossy(&out.stderr));
    (c, summary)
}

#[test]
fn labels_have_line_breaks_and_the_text_as_written() {
    let (c, _) = coverage("lamp-labels.json");
    let out = statecheck(&["dot", LAMP, "--coverage", &c], &[]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let text = String::from_utf8(out.stdout).expect("utf-8");
    // Each expected line derived by hand from the model and the counts above. In the DOT
    // file a line break is one backslash and `n`; `\\n` would make Graphviz show `\n`.
    // The guard is 45 characters: cut to 39 and `…`.
    for line in [
        r#"    i0_s1 [label="Off\n×2"];"#,
        r#"    i0_s2 [label="On\n×1"];"#,
        r#"  i0_s1 -> i0_s2 [label="press [enabled && count < 3 && count >= 0 && e…]\n/ count += 1;\n×1"];"#,
        r#"  i0_s2 -> i0_s1 [label="after(3 s)\n×1"];"#,
        r#"    i1_s1 [label="watch\n×1"];"#,
        // The observer's `error` state and the transition into it: never entered, as meant,
        // so not red; the state has a double border.
        r#"    i1_s2 [label="error\n×0", peripheries=2];"#,
        r#"  i1_s1 -> i1_s2 [label="[in(lamp.On) && lamp.count == 0]\n×0"];"#,
    ] {
        assert!(
            text.lines().any(|l| l == line),
            "missing {line}\nin:\n{text}"
        );
    }
    assert!(!text.contains("\\\\n"), "no doubled backslash: {text}");
    assert!(!text.contains("[..]"), "guards are written out: {text}");
    assert!(!text.contains("red"), "nothing is a coverage gap: {text}");
}

#[test]
fn observer_error_is_not_a_coverage_gap_nor_dead_design() {
    let (_, summary) = coverage("lamp-summary.json");
    // States Off, On, watch (error left out); transitions Off -> On, On -> Off (the one into
    // error left out): all covered.
    assert!(
        summary.contains("coverage: states 3/3 (100.0%), transitions 2/2 (100.0%)"),
        "{summary}"
    );
    assert!(!summary.contains("never"), "{summary}");
    // The explicit engine explores everything: every Lamp state and transition is reachable
    // (above), the observer's `error` and its transition are not, and are not reported.
    let out = statecheck(&["verify", LAMP, "--engine", "explicit", "--json"], &[]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(v["stats"]["complete"], true, "{v}");
    assert_eq!(v["stats"]["dead"], serde_json::json!([]), "{v}");
    let out = statecheck(&["verify", LAMP, "--engine", "explicit"], &[]);
    let text =
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert!(!text.contains("dead design"), "{text}");
}

#[test]
fn svg_is_drawn_by_graphviz() {
    let out = statecheck(&["dot", LAMP, "--svg"], &[]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "Graphviz is required (scripts/test.sh installs it): {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = String::from_utf8(out.stdout).expect("utf-8");
    assert!(svg.contains("<svg"), "{svg}");
    // Graphviz draws each line of a label as its own <text>: the action is on a line of its
    // own, and no literal `\n` is drawn.
    assert!(svg.contains(">/ count += 1;</text>"), "{svg}");
    assert!(svg.contains(">after(3 s)</text>"), "{svg}");
    assert!(!svg.contains("\\n"), "{svg}");
}

#[test]
fn svg_without_graphviz_is_error_e0901() {
    let missing = temp("no-such-dir/dot");
    let missing = missing.to_str().expect("utf-8 path");
    let out = statecheck(&["dot", LAMP, "--svg"], &[("STATECHECK_DOT", missing)]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("error[E0901]"), "{err}");
    assert!(err.contains("install the `graphviz` package"), "{err}");
    assert!(out.stdout.is_empty());
}

#[test]
fn a_timer_in_ticks_also_shows_its_time() {
    // With `tick 100 ms;`, `after(30)` is 30 × 0.1 s = 3.0 s (one decimal, as every time of
    // a 100 ms tick); `after(2 s)` is already in units and stays as written.
    let file = temp("timers.sc");
    std::fs::write(
        &file,
        "tick 100 ms;\nchart Lamp {\n  input event press;\n  initial Off;\n  state Off { on press -> On; }\n  state On { on after(30) -> Dim; }\n  state Dim { on after(2 s) -> Off; }\n}\n",
    )
    .expect("write");
    let out = statecheck(&["dot", &file.to_string_lossy()], &[]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("[label=\"after(30) = 3.0 s\"]"), "{text}");
    assert!(text.contains("[label=\"after(2 s)\"]"), "{text}");
}
