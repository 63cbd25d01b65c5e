//! Time in the user's units (issue 18): with `tick` declared, every output that shows a run
//! shows the time of its ticks (tick × tick length, exact), and `respond … within` takes a
//! duration; without `tick` the outputs have no time. The expected values are derived by hand
//! in the models' comments (`tests/time/`).

use serde_json::Value;
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

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("statecheck-time-units-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

const STATION: &str = "tests/time/station.sc";
const STATION_SCN: &str = "tests/time/station.scn";
const LAMP: &str = "tests/dot/lamp.sc";
const LAMP_SCN: &str = "tests/dot/lamp.scn";
const RESPOND: &str = "tests/time/respond.sc";

#[test]
fn sim_shows_the_violation_at_tick_95_as_118_75_s() {
    // station.sc: ticks of 1.25 s; the feeder reaches its end in tick 95 = 118.75 s.
    let out = statecheck(&["sim", STATION, "--scenario", STATION_SCN]);
    assert_eq!(out.status.code(), Some(4), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    assert!(
        stderr.contains("property `never_at_end` violated at tick 95 (118.75 s)"),
        "{stderr}"
    );
    let stdout = text(&out.stdout);
    let lines: Vec<&str> = stdout.lines().collect();
    assert!(lines[0].starts_with("tick  time (s)"), "{stdout}");
    // Ticks of 1250 ms need two decimals: tick 1 is 1.25 s, tick 95 is 118.75 s.
    assert!(lines[2].starts_with("   1      1.25  Pushing"), "{stdout}");
    assert!(lines[96].starts_with("  95    118.75  End"), "{stdout}");

    let out = statecheck(&["sim", STATION, "--scenario", STATION_SCN, "--json"]);
    assert_eq!(out.status.code(), Some(4));
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let ticks = v["ticks"].as_array().expect("ticks");
    assert_eq!(ticks.len(), 96);
    assert_eq!(ticks[0]["time"], serde_json::json!(0.0));
    assert_eq!(ticks[1]["time"], serde_json::json!(1.25));
    assert_eq!(ticks[95]["tick"], 95);
    assert_eq!(ticks[95]["time"], serde_json::json!(118.75));
    assert_eq!(v["result"]["tick"], 95);
    assert_eq!(v["result"]["time"], serde_json::json!(118.75));
    // The number is written as the exact decimal, not as a float product.
    assert!(text(&out.stdout).contains("\"time\":118.75"));
}

#[test]
fn csv_has_a_time_column_after_the_tick() {
    // lamp.sc: ticks of 100 ms; press in tick 1 (On), after(3 s) = 30 ticks: Off in tick 31.
    let out = statecheck(&["sim", LAMP, "--scenario", LAMP_SCN, "--csv"]);
    assert_eq!(out.status.code(), Some(0));
    let csv = text(&out.stdout);
    let lines: Vec<&str> = csv.lines().collect();
    assert!(lines[0].starts_with("tick,time,lamp.active,"), "{csv}");
    assert!(lines[1].starts_with("0,0.0,Off,"), "{csv}");
    assert!(lines[2].starts_with("1,0.1,On,"), "{csv}");
    assert!(lines[32].starts_with("31,3.1,Off,"), "{csv}");
}

/// The timescale and the timestamps of a VCD file, read by an independent parser.
fn vcd_times(path: &Path) -> (Option<(u32, vcd::TimescaleUnit)>, Vec<u64>) {
    let bytes = std::fs::read(path).expect("vcd written");
    let mut parser = vcd::Parser::new(&bytes[..]);
    let header = parser.parse_header().expect("valid VCD header");
    let stamps = parser
        .filter_map(|c| match c.expect("valid VCD body") {
            vcd::Command::Timestamp(t) => Some(t),
            _ => None,
        })
        .collect();
    (header.timescale, stamps)
}

#[test]
fn vcd_timescale_matches_the_tick() {
    // 100 ms ticks: a `100ms` timescale, one unit per tick. The lamp changes in ticks 0, 1
    // (press, On) and 31 (Off); the scenario has 33 ticks, so the trace ends at 33.
    let f = temp("lamp.vcd");
    let out = statecheck(&[
        "sim",
        LAMP,
        "--scenario",
        LAMP_SCN,
        "--vcd",
        f.to_str().expect("utf-8"),
        "--quiet",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let (scale, stamps) = vcd_times(&f);
    assert_eq!(scale, Some((100, vcd::TimescaleUnit::MS)));
    assert_eq!(stamps.first(), Some(&0));
    assert!(stamps.contains(&1) && stamps.contains(&31), "{stamps:?}");
    assert_eq!(stamps.last(), Some(&33));

    // 1250 ms ticks: the largest unit dividing them is 10 ms, 125 units per tick; tick 95
    // (118.75 s) is at 11875 and the run (stopped at tick 95) ends at 96 × 125 = 12000.
    let f = temp("station.vcd");
    let out = statecheck(&[
        "sim",
        STATION,
        "--scenario",
        STATION_SCN,
        "--vcd",
        f.to_str().expect("utf-8"),
        "--quiet",
    ]);
    assert_eq!(out.status.code(), Some(4));
    let (scale, stamps) = vcd_times(&f);
    assert_eq!(scale, Some((10, vcd::TimescaleUnit::MS)));
    assert_eq!(stamps, vec![0, 125, 250, 11875, 12000]);
}

#[test]
fn verify_reports_the_time_of_the_violation() {
    let out = statecheck(&["verify", STATION]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(stdout.contains("decided at tick 95 (118.75 s)"), "{stdout}");
    assert!(stdout.contains("  95    118.75  End"), "{stdout}");
    let out = statecheck(&["verify", STATION, "--json", "--property", "never_at_end"]);
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let r = &v["results"][0];
    assert_eq!(r["verdict"], "violated");
    assert_eq!(r["depth"], 96);
    assert_eq!(r["tick"], 95);
    assert_eq!(r["time"], serde_json::json!(118.75));
}

/// The verdicts of `verify --json` by property name.
fn verdicts(system: &str) -> Vec<(String, String, Option<u64>)> {
    let out = statecheck(&["verify", RESPOND, "--system", system, "--json"]);
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let mut rows: Vec<_> = v["results"]
        .as_array()
        .expect("results")
        .iter()
        .filter(|r| r["kind"] == "respond")
        .map(|r| {
            (
                r["property"].as_str().unwrap_or_default().to_string(),
                r["verdict"].as_str().unwrap_or_default().to_string(),
                r["tick"].as_u64(),
            )
        })
        .collect();
    rows.sort();
    rows
}

#[test]
fn within_in_seconds_is_within_in_ticks() {
    // respond.sc: the answer takes exactly 20 ticks of 100 ms, so 2 s and 2000 ms hold and
    // 1900 ms (19 ticks) is violated at tick 1 + 19 = 20 (go in tick 1).
    let expected = vec![
        ("in_1900ms".to_string(), "violated".to_string(), Some(20)),
        ("in_2000ms".to_string(), "proved".to_string(), None),
        ("in_2s".to_string(), "proved".to_string(), None),
    ];
    assert_eq!(verdicts("InSeconds"), expected);
    // The same bounds written in ticks give the same verdicts.
    assert_eq!(verdicts("InTicks"), expected);
    let out = statecheck(&["verify", RESPOND, "--system", "InSeconds", "--json"]);
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let r = v["results"]
        .as_array()
        .expect("results")
        .iter()
        .find(|r| r["property"] == "in_1900ms")
        .cloned()
        .expect("in_1900ms");
    assert_eq!(r["time"], serde_json::json!(2.0));
}

#[test]
fn a_bound_that_is_not_a_whole_number_of_ticks_is_rejected() {
    // 150 ms with 100 ms ticks: E0120, the error of `after(150 ms)`.
    let out = statecheck(&["check", "tests/diagnostics/e0120_within.sc"]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = text(&out.stderr);
    assert!(stderr.contains("E0120"), "{stderr}");
    assert!(
        stderr.contains("150 ms is not a whole number of 100 ms ticks"),
        "{stderr}"
    );
}

#[test]
fn without_a_tick_nothing_shows_a_time() {
    let order = "tests/semantics/order.sc";
    let scn = "tests/semantics/order.scn";
    let json = statecheck(&["sim", order, "--scenario", scn, "--json"]);
    let v: Value = serde_json::from_slice(&json.stdout).expect("JSON");
    for t in v["ticks"].as_array().expect("ticks") {
        assert!(t.get("time").is_none(), "{t}");
    }
    let table = text(&statecheck(&["sim", order, "--scenario", scn]).stdout);
    assert!(table.starts_with("tick  active"), "{table}");
    // One tick is one unit of 1 ms, as before.
    let f = temp("order.vcd");
    statecheck(&[
        "sim",
        order,
        "--scenario",
        scn,
        "--vcd",
        f.to_str().expect("utf-8"),
        "--quiet",
    ]);
    let (scale, stamps) = vcd_times(&f);
    assert_eq!(scale, Some((1, vcd::TimescaleUnit::MS)));
    assert_eq!(stamps.last(), Some(&6));
}

#[test]
fn the_configuration_matrix_gives_each_violation_its_time() {
    // feeders.sc: the light stroke ends in tick 39 (39 × 1.25 s = 48.75 s), the heavy one in
    // tick 95 (118.75 s).
    let model = "tests/time/feeders.sc";
    let out = statecheck(&["verify", model, "--all-configs", "--engine", "explicit"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out.stderr));
    let table = text(&out.stdout);
    let row = |c: &str| {
        table
            .lines()
            .find(|l| l.starts_with(c))
            .unwrap_or_default()
            .to_string()
    };
    assert!(row("light").contains("violated (48.75 s)"), "{table}");
    assert!(row("heavy").contains("violated (118.75 s)"), "{table}");
    let out = statecheck(&[
        "verify",
        model,
        "--all-configs",
        "--engine",
        "explicit",
        "--json",
    ]);
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let cell = |k: usize| v["configurations"][k]["results"][0].clone();
    assert_eq!(
        (&cell(0)["tick"], &cell(0)["time"]),
        (&serde_json::json!(39), &serde_json::json!(48.75))
    );
    assert_eq!(
        (&cell(1)["tick"], &cell(1)["time"]),
        (&serde_json::json!(95), &serde_json::json!(118.75))
    );
    // A proved property has no tick.
    assert!(v["configurations"][0]["results"][1].get("tick").is_none());
}
