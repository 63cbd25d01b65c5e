//! `verify --collapse` on the FAM closed loop (213-bit states): the same states, transitions,
//! verdicts and decision ticks as the plain visited set, in fewer bytes per state, and the
//! distinct halves reported in `stats.collapse_leaves`.

mod common;

use common::{run, summary_of};
use serde_json::Value;

#[test]
fn collapse_explores_the_fam_closed_loop_as_the_plain_set() {
    let args = [
        "verify",
        "examples/fam/fam_system.sc",
        "--engine",
        "explicit",
        "--depth",
        "40",
        "--json",
    ];
    let (code, plain, err) = run(&args);
    // fam_cof_with_notcalib is violated within 40 ticks (exit 1).
    assert_eq!(code, 1, "{err}");
    let (code, collapsed, err) = run(&[&args[..], &["--collapse"]].concat());
    assert_eq!(code, 1, "{err}");
    assert_eq!(summary_of(&plain), summary_of(&collapsed));
    let stats = |out: &str| -> Value {
        let v: Value = serde_json::from_str(out).expect("json");
        v["stats"].clone()
    };
    let (p, c) = (stats(&plain), stats(&collapsed));
    assert_eq!(p["collapse_leaves"], Value::Null);
    let leaves: Vec<u64> = c["collapse_leaves"]
        .as_array()
        .map(|a| a.iter().filter_map(Value::as_u64).collect())
        .unwrap_or_default();
    let states = c["states"].as_u64().unwrap_or(0);
    assert_eq!(leaves.len(), 2, "{c}");
    assert!(leaves[0] * leaves[1] >= states && leaves.iter().all(|&l| l <= states));
    let bps = |s: &Value| s["bytes_per_state"].as_f64().unwrap_or(0.0);
    assert!(bps(&c) < bps(&p), "{} against {}", bps(&c), bps(&p));
}
