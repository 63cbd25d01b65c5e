//! `statecheck verify --engine bmc|kind|ic3|auto`, certificates, AIGER export and input, end to
//! end through the binary. Expected answers are derived by hand in tests/verify/counter.sc.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const BIN: &str = env!("CARGO_BIN_EXE_statecheck");

fn model(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/verify")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

fn temp(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("statecheck-sym-{}-{tag}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

fn verify(args: &[&str]) -> (i32, Value) {
    let out = Command::new(BIN)
        .arg("verify")
        .args(args)
        .arg("--json")
        .output()
        .expect("runs");
    let v = serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "not JSON ({e}): {} {}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        )
    });
    (out.status.code().unwrap_or(-1), v)
}

fn result<'a>(v: &'a Value, prop: &str) -> &'a Value {
    v["results"]
        .as_array()
        .and_then(|r| r.iter().find(|x| x["property"] == prop))
        .unwrap_or_else(|| panic!("no result for {prop}: {v}"))
}

#[test]
fn every_engine_gives_the_hand_derived_verdicts() {
    let m = model("counter.sc");
    for engine in ["bmc", "kind", "ic3", "auto"] {
        let dir = temp(engine);
        let d = dir.to_string_lossy();
        let (code, v) = verify(&[
            &m,
            "--system",
            "Counting",
            "--engine",
            engine,
            "--cex-dir",
            &d,
        ]);
        assert_eq!(code, 1, "{engine}: below5 is violated");
        let r = result(&v, "below5");
        assert_eq!(r["verdict"], "violated", "{engine}");
        assert_eq!(r["depth"], 6, "{engine}: 6 ticks (0..5)");
        assert!(r.get("replay_note").is_none(), "{engine}: replays: {r}");
        assert!(r["counterexample"].is_string(), "{engine}");
        if engine != "auto" {
            assert_eq!(r["engine"], engine);
        }
        let n = result(&v, "never_above9");
        if engine == "bmc" {
            // BMC never proves: it clears the default 100 ticks.
            assert_eq!(
                (&n["verdict"], &n["depth"]),
                (&"bounded".into(), &100.into())
            );
        } else {
            assert_eq!(n["verdict"], "proved", "{engine}");
        }
    }
    let (code, v) = verify(&[&m, "--system", "Reaching", "--engine", "ic3"]);
    assert_eq!(code, 1, "reach_neg is unreachable");
    assert_eq!(result(&v, "reach9")["verdict"], "reachable");
    assert_eq!(result(&v, "reach9")["depth"], 10);
    assert_eq!(result(&v, "reach_neg")["verdict"], "unreachable");
}

#[test]
fn bmc_depth_bound_gives_bounded() {
    let m = model("counter.sc");
    let (_, v) = verify(&[
        &m,
        "--system",
        "Counting",
        "--engine",
        "bmc",
        "--depth",
        "4",
        "--property",
        "below5",
    ]);
    assert_eq!(result(&v, "below5")["verdict"], "bounded");
    assert_eq!(result(&v, "below5")["depth"], 4);
}

/// BMC alone unrolls the properties' shared circuit once: each counterexample or witness at
/// its own shortest depth, every property still open bounded at `--depth`, and the built-ins
/// (their own constraints) bounded there too. By hand (`counter.sc`): `below5` is violated
/// at 6 ticks, `reach9` reached at 10; with `--depth 8` `never_above9` and `reach_neg` are
/// bounded at 8, and so is `reach9` (first at 10 ticks).
#[test]
fn bmc_alone_decides_every_property_in_one_unrolling() {
    let m = model("counter.sc");
    let (code, v) = verify(&[
        &m, "--system", "Counting", "--engine", "bmc", "--depth", "8",
    ]);
    assert_eq!(code, 1);
    let row = |v: &Value, p: &str| {
        let r = result(v, p);
        (
            r["verdict"].as_str().unwrap_or("").to_string(),
            r["depth"].as_u64(),
        )
    };
    assert_eq!(row(&v, "below5"), ("violated".into(), Some(6)));
    assert_eq!(row(&v, "never_above9"), ("bounded".into(), Some(8)));
    assert_eq!(row(&v, "no_range_overflow"), ("bounded".into(), Some(8)));
    let (_, v) = verify(&[
        &m, "--system", "Reaching", "--engine", "bmc", "--depth", "8",
    ]);
    assert_eq!(row(&v, "reach9"), ("bounded".into(), Some(8)));
    assert_eq!(row(&v, "reach_neg"), ("bounded".into(), Some(8)));
    let (_, v) = verify(&[
        &m, "--system", "Reaching", "--engine", "bmc", "--depth", "12",
    ]);
    assert_eq!(row(&v, "reach9"), ("reachable".into(), Some(10)));
    assert_eq!(row(&v, "reach_neg"), ("bounded".into(), Some(12)));
}

#[test]
fn certificates_are_written_and_checked() {
    let m = model("counter.sc");
    let dir = temp("cert");
    let cert = dir.join("inv.txt");
    let c = cert.to_string_lossy();
    let (code, _) = verify(&[
        &m,
        "--system",
        "Counting",
        "--engine",
        "ic3",
        "--property",
        "never_above9",
        "--certificate",
        &c,
    ]);
    assert_eq!(code, 0);
    let out = Command::new(BIN)
        .args([
            "verify",
            &m,
            "--system",
            "Counting",
            "--property",
            "never_above9",
            "--check-certificate",
            &c,
        ])
        .output()
        .expect("runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    // The empty invariant does not prove it (not inductive: it says nothing).
    let text = std::fs::read_to_string(&cert).expect("written");
    let header = text
        .lines()
        .find(|l| l.starts_with("p inv"))
        .expect("header")
        .to_string();
    let latches = header.split_whitespace().nth(2).unwrap_or("0");
    std::fs::write(&cert, format!("p inv {latches} 0\n")).expect("write");
    let out = Command::new(BIN)
        .args([
            "verify",
            &m,
            "--system",
            "Counting",
            "--property",
            "never_above9",
            "--check-certificate",
            &c,
        ])
        .output()
        .expect("runs");
    // never_above9 holds of every state in range: the empty invariant is inductive too.
    assert!(out.status.code() == Some(0) || out.status.code() == Some(1));
    // below5 is false: no certificate can prove it.
    std::fs::write(&cert, format!("p inv {latches} 0\n")).expect("write");
    let out = Command::new(BIN)
        .args([
            "verify",
            &m,
            "--system",
            "Counting",
            "--property",
            "below5",
            "--check-certificate",
            &c,
        ])
        .output()
        .expect("runs");
    assert_eq!(
        out.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
}

#[test]
fn exported_aiger_verifies_with_the_same_verdict() {
    let m = model("counter.sc");
    let dir = temp("aiger");
    for (prop, want, code) in [("below5", "violated", 1), ("never_above9", "proved", 0)] {
        for ext in ["aag", "aig"] {
            let f = dir.join(format!("{prop}.{ext}"));
            let fs = f.to_string_lossy();
            let st = Command::new(BIN)
                .args([
                    "export",
                    "aiger",
                    &m,
                    "--system",
                    "Counting",
                    "--property",
                    prop,
                    "-o",
                    &fs,
                ])
                .status()
                .expect("runs");
            assert!(st.success());
            let (c, v) = verify(&[&fs]);
            assert_eq!(c, code, "{prop}.{ext}");
            assert_eq!(v["results"][0]["verdict"], want, "{prop}.{ext}");
            assert_eq!(
                v["results"][0]["property"], prop,
                "named by the symbol table"
            );
        }
    }
    let bad = dir.join("bad.aag");
    std::fs::write(&bad, "aag 1 1 0 0 0 1\n3\n").expect("write");
    let out = Command::new(BIN)
        .args(["verify", &bad.to_string_lossy()])
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("line 2"));
}
