//! Continuous plant variables end to end (docs/hybrid.md): the closed-loop feeder of
//! `tests/hybrid/feeder_loop.sc` verified by the explicit engine and a SAT engine against the
//! verdicts and ticks derived by hand in its comments; the `show --discretized` text checked
//! and verified again to the same answers; `analyse` against hand-computed times.

use serde_json::Value;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn path(name: &str) -> String {
    format!("{}/../../tests/hybrid/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(BIN)
        .args(args)
        .output()
        .expect("statecheck runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// (property, verdict, tick) of `verify --json` with one engine on system `Loop`.
fn verdicts(file: &str, engine: &str, props: &[&str]) -> Vec<(String, String, Option<u64>)> {
    verdicts_of(file, "Loop", engine, props)
}

fn verdicts_of(
    file: &str,
    system: &str,
    engine: &str,
    props: &[&str],
) -> Vec<(String, String, Option<u64>)> {
    let mut args = vec![
        "verify", file, "--system", system, "--engine", engine, "--json",
    ];
    for p in props {
        args.extend(["--property", p]);
    }
    let (code, out, err) = run(&args);
    assert!(code == 0 || code == 1, "exit {code}: {err}");
    let v: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"));
    v["results"]
        .as_array()
        .expect("results")
        .iter()
        .map(|r| {
            (
                r["property"].as_str().unwrap_or("").to_string(),
                r["verdict"].as_str().unwrap_or("").to_string(),
                r["tick"].as_u64(),
            )
        })
        .collect()
}

fn expected() -> Vec<(String, String, Option<u64>)> {
    // tests/hybrid/feeder_loop.sc: at_home and at_end are disjoint; at_end first in tick 39
    // (pos 95 = 19 cells of 2 ticks after Push is entered in tick 1); pos 100 in tick 41.
    vec![
        ("not_both".into(), "proved".into(), None),
        ("never_end".into(), "violated".into(), Some(39)),
        ("full".into(), "reachable".into(), Some(41)),
    ]
}

#[test]
fn explicit_and_sat_engines_agree_with_the_hand_derivation() {
    let file = path("feeder_loop.sc");
    let props = ["not_both", "never_end", "full"];
    assert_eq!(verdicts(&file, "explicit", &props), expected());
    assert_eq!(verdicts(&file, "kind", &props), expected());
}

#[test]
fn discretized_text_checks_and_verifies_alike() {
    let file = path("feeder_loop.sc");
    let (code, text, err) = run(&["show", "--discretized", &file]);
    assert_eq!(code, 0, "{err}");
    // No hybrid element is left but as a comment; the grid and the motion are plain code.
    assert!(text.contains("output pos: int[0..100] = 0;"), "{text}");
    assert!(text.contains("/* der(pos) = 2; */"), "{text}");
    assert!(text.contains("if in(Push)"), "{text}");
    let dir = std::env::temp_dir().join(format!("statecheck-hybrid-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let out = dir.join("feeder_discretized.sc");
    std::fs::write(&out, &text).expect("write");
    let out = out.to_string_lossy().into_owned();
    let (code, _, err) = run(&["check", &out]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        verdicts(&out, "explicit", &["not_both", "never_end", "full"]),
        expected()
    );
    // Discretizing the discretized text changes nothing (it has no continuous variable).
    let (code, again, err) = run(&["show", "--discretized", &out]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(again, text);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn analyse_gives_the_papers_clock_readings() {
    // §VI: D = 100, N = 4, Speed = 5: 25, 50, 75, 100 at 5, 10, 15, 20 s (1 s ticks).
    let (code, out, err) = run(&["analyse", &path("paper_vi.sc"), "--json"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).expect("JSON");
    let m = &v["variables"][0]["modes"][0];
    assert_eq!(m["state"], "Forward");
    let got: Vec<(i64, String, String)> = m["readings"]
        .as_array()
        .expect("readings")
        .iter()
        .map(|r| {
            (
                r["point"].as_i64().unwrap_or(-1),
                r["seconds"].as_str().unwrap_or("").to_string(),
                r["ticks"].as_str().unwrap_or("").to_string(),
            )
        })
        .collect();
    let want: Vec<(i64, String, String)> = [(25, "5"), (50, "10"), (75, "15"), (100, "20")]
        .into_iter()
        .map(|(p, t)| (p, t.to_string(), t.to_string()))
        .collect();
    assert_eq!(got, want);
}

#[test]
fn analyse_follows_a_scenario_exactly() {
    // tests/hybrid/push.scn derives each time by hand.
    let (code, out, err) = run(&[
        "analyse",
        &path("feeder_loop.sc"),
        "--system",
        "Loop",
        "--scenario",
        &path("push.scn"),
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).expect("JSON");
    let got: Vec<(i64, String, String, u64, String)> = v["events"]
        .as_array()
        .expect("events")
        .iter()
        .map(|e| {
            (
                e["point"].as_i64().unwrap_or(-1),
                e["state"].as_str().unwrap_or("").to_string(),
                e["seconds"].as_str().unwrap_or("").to_string(),
                e["model_tick"].as_u64().unwrap_or(0),
                e["status"].as_str().unwrap_or("").to_string(),
            )
        })
        .collect();
    let want = [
        (5, "Push", "3.75", 3),
        (95, "Push", "48.75", 39),
        (100, "Push", "51.25", 41),
        (95, "Back", "53.75", 43),
        (5, "Back", "76.25", 61),
        (0, "Back", "77.5", 62),
    ];
    let want: Vec<(i64, String, String, u64, String)> = want
        .into_iter()
        .map(|(p, s, t, k)| (p, s.to_string(), t.to_string(), k, "exact".to_string()))
        .collect();
    assert_eq!(got, want);
}

#[test]
fn speeds_from_chart_parameters() {
    // tests/hybrid/params.sc: light at_end in tick 39, heavy in tick 96.
    let got = verdicts_of(
        &path("params.sc"),
        "Pair",
        "explicit",
        &["light_end", "heavy_end"],
    );
    assert_eq!(
        got,
        vec![
            ("light_end".to_string(), "violated".to_string(), Some(39)),
            ("heavy_end".to_string(), "violated".to_string(), Some(96)),
        ]
    );
    let (code, _, err) = run(&["check", &path("params.sc")]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("Warning"), "{err}");
}
