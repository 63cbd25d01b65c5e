//! `verify --bitstate SIZE` (docs/verification.md, "Bitstate hashing") on the FAM alone
//! (`FamAloneSmall`, exhausted by the exact search in 66,889 states; `expected.json` and
//! docs/case-studies/fam.md): with a 64 MiB array (over 8000 bits per state, so an omission
//! is all but impossible) it counts the same states and finds the same witnesses and
//! counterexample at the same ticks, but the properties the exact search proves are
//! `unknown` with the reason; the flags it cannot go with are refused.

mod common;

use common::{run, summary_of};
use serde_json::Value;

#[test]
fn bitstate_counts_the_fam_alone_and_proves_nothing() {
    let args = [
        "verify",
        "examples/fam/fam_alone.sc",
        "--engine",
        "explicit",
        "--json",
    ];
    let (code, exact, err) = run(&args);
    // fam_cof_with_notcalib is violated (exit 1).
    assert_eq!(code, 1, "{err}");
    let (code, bits, err) = run(&[&args[..], &["--bitstate", "64M"]].concat());
    assert_eq!(code, 1, "{err}");
    let stats = |out: &str| -> Value {
        let v: Value = serde_json::from_str(out).expect("json");
        v["stats"].clone()
    };
    let (e, b) = (stats(&exact), stats(&bits));
    assert_eq!(e["states"].as_u64(), Some(66_889));
    assert_eq!(b["states"], e["states"]);
    assert_eq!(b["transitions"], e["transitions"]);
    assert_eq!(e["complete"], Value::Bool(true));
    assert_eq!(b["complete"], Value::Bool(false));
    assert_eq!(e["bitstate"], Value::Null);
    assert_eq!(b["bitstate"]["bytes"].as_u64(), Some(64 << 20));
    assert_eq!(b["bitstate"]["hashes"].as_u64(), Some(3));
    let (e_states, _, e_rows) = summary_of(&exact);
    let (b_states, _, b_rows) = summary_of(&bits);
    assert_eq!(e_states, b_states);
    for (x, y) in e_rows.into_iter().zip(b_rows) {
        assert_eq!(x.0, y.0);
        match x.1.as_str() {
            "proved" => assert_eq!(y.1, "unknown", "{}", x.0),
            _ => assert_eq!(x, y),
        }
    }
    let v: Value = serde_json::from_str(&bits).expect("json");
    let note = v["results"][1]["note"].as_str().unwrap_or("");
    assert!(note.contains("not a proof"), "{note}");
}

#[test]
fn bitstate_refuses_what_it_cannot_go_with() {
    let model = "examples/fam/fam_alone.sc";
    for (extra, says) in [
        (&["--engine", "ic3"][..], "mode of the explicit engine"),
        (&["--max-memory", "512M"][..], "leaves no room"),
        (&["--bitstate-hashes", "0"][..], "between 1 and 32"),
        (&["--collapse"][..], "cannot be used with"),
    ] {
        let size = if says == "leaves no room" { "1G" } else { "1M" };
        let (code, _, err) = run(&[&["verify", model, "--bitstate", size][..], extra].concat());
        assert_eq!(code, 2, "{extra:?}: {err}");
        assert!(err.contains(says), "{extra:?}: {err}");
    }
}
