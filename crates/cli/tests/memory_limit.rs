//! `--max-memory` bounds every engine: with a cap far below what the FAM closed loop needs,
//! `verify` (explicit, BMC, k-induction, IC3) and `synth` (explicit, symbolic) stop with
//! `unknown` (exit 3), say that the memory limit was the reason, and still report their
//! partial statistics; a verdict decided before the limit must be the thesis's.

use serde_json::Value;
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn example(path: &str) -> String {
    format!("{}/../../examples/{path}", env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn verify_stops_with_unknown_at_a_small_memory_cap_on_every_engine() {
    let expected: Value = serde_json::from_str(
        &std::fs::read_to_string(example("fam/expected.json")).expect("expected.json"),
    )
    .expect("json");
    for engine in ["explicit", "bmc", "kind", "ic3"] {
        let out = Command::new(BIN)
            .args(["verify", &example("fam/fam_system.sc")])
            .args(["--engine", engine, "--max-memory", "24M", "--json"])
            // A safety net only: the memory cap, not the time, must stop the run.
            .args(["--timeout", "600"])
            .output()
            .expect("runs");
        let v: Value = serde_json::from_slice(&out.stdout).expect("json");
        // Exit 3 (unknown), or 1 when a violation was found before the cap (it outranks).
        let violated = v["results"]
            .as_array()
            .is_some_and(|r| r.iter().any(|r| r["verdict"] == "violated"));
        let want = if violated { 1 } else { 3 };
        assert_eq!(out.status.code(), Some(want), "{engine}: {v}");
        assert_eq!(v["stats"]["limit"]["kind"], "memory", "{engine}: {v}");
        assert!(
            v["stats"]["time_s"].is_number(),
            "{engine}: partial statistics"
        );
        let results = v["results"].as_array().expect("results");
        assert!(
            results.iter().any(|r| r["verdict"] == "unknown"),
            "{engine}: {v}"
        );
        // What was decided before the cap agrees with the verdicts the case study derived.
        for r in results {
            let name = r["property"].as_str().unwrap_or_default();
            let verdict = r["verdict"].as_str().unwrap_or_default();
            // The thesis's table reads e.g. "possible (reachable)" or "proved".
            let want = expected["thesis"].get(name).and_then(Value::as_str);
            if let (Some(want), false) = (want, verdict == "unknown") {
                assert!(
                    want.contains(verdict),
                    "{engine}: {name} {verdict}, thesis {want}"
                );
            }
        }
    }
}

#[test]
fn synth_stops_with_unknown_at_a_small_memory_cap_on_both_engines() {
    let dir = std::env::temp_dir().join(format!("statecheck-memcap-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    // Explicit synthesis of the 12-machine line needs far more than 24 MiB (its product has
    // millions of states); the symbolic engine needs about 9 MiB in all, so it gets 8M.
    for (engine, cap) in [("explicit", "24M"), ("symbolic", "8M")] {
        let out = Command::new(BIN)
            .args(["synth", &example("synthesis/line_12.sc")])
            .args(["--engine", engine, "--max-memory", cap, "-o"])
            .arg(dir.join(format!("sup_{engine}.sc")))
            .output()
            .expect("runs");
        let text = String::from_utf8_lossy(&out.stdout).to_string()
            + &String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(3), "{engine}: {text}");
        assert!(text.contains("memory limit"), "{engine}: {text}");
        assert!(text.contains("product states so far"), "{engine}: {text}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
