//! Arrays of variables, `for` loops and element-wise connections through the binary
//! (docs/language.md §5, §8, §14): `tests/components/arrays.sc` gives the same verdicts,
//! state counts and traces as `arrays_flat.sc`, the same system written with scalars by hand,
//! once an element `x.go[1]` is read as `x.go_1`; the state count (12) and the verdicts are
//! derived by hand in the model's comment.

mod common;

use common::{run, summary_of, Summary};
use serde_json::Value;

const ARRAYS: &str = "tests/components/arrays.sc";
const FLAT: &str = "tests/components/arrays_flat.sc";

/// `m.go[1]` → `m.go_1`: an array element after a `.` read as the flat twin's scalar
/// (instance arrays such as `s[1]` are written alike in both files).
fn flat_name(name: &str) -> String {
    let mut out = String::with_capacity(name.len());
    let mut after_dot = false;
    let mut in_index = false;
    for c in name.chars() {
        match c {
            '[' if after_dot => {
                out.push('_');
                in_index = true;
            }
            ']' if in_index => in_index = false,
            '.' => {
                after_dot = true;
                out.push(c);
            }
            _ => out.push(c),
        }
    }
    out
}

/// (states, transitions, [(property, verdict, tick)]) of `verify --json`.
fn summary(file: &str, engine: &str) -> Summary {
    let (code, out, err) = run(&["verify", "--engine", engine, "--json", file]);
    // The verdicts are read from the JSON (the exit code of an unreachable `reachable`
    // differs between engines); the run must not be a usage error.
    assert!(matches!(code, 0 | 1 | 3), "{file}: {err}");
    summary_of(&out)
}

#[test]
fn arrays_verify_like_the_hand_written_scalar_twin() {
    let arrays = summary(ARRAYS, "explicit");
    assert_eq!(arrays, summary(FLAT, "explicit"));
    // By hand (arrays.sc): 12 states; every state has the 2 * 3 input vectors (req, sel).
    assert_eq!((arrays.0, arrays.1), (12, 72));
    let verdict = |n: &str| {
        arrays
            .2
            .iter()
            .find(|r| r.0 == n)
            .map(|r| (r.1.clone(), r.2))
            .unwrap_or(("missing".into(), None))
    };
    assert_eq!(verdict("at_most_one").0, "proved");
    assert_eq!(verdict("two_busy").0, "unreachable");
    assert_eq!(verdict("back_to_back"), ("reachable".into(), Some(2)));
    assert_eq!(verdict("probes_copy").0, "proved");
    // The SAT engines see the same scalars.
    let bmc = summary(ARRAYS, "bmc");
    let row = bmc.2.iter().find(|r| r.0 == "back_to_back");
    assert_eq!(
        row.map(|r| (r.1.as_str(), r.2)),
        Some(("reachable", Some(2)))
    );
    for engine in ["ic3", "kind"] {
        let s = summary(ARRAYS, engine);
        let v = |n: &str| s.2.iter().find(|r| r.0 == n).map(|r| r.1.clone());
        assert_eq!(v("at_most_one").as_deref(), Some("proved"), "{engine}");
        assert_eq!(v("probes_copy").as_deref(), Some("proved"), "{engine}");
    }
}

/// Each tick's variables, names read as the flat twin's.
fn ticks(file: &str, args: &[&str]) -> Vec<Vec<(String, Value)>> {
    let mut all = vec!["sim", file, "--json"];
    all.extend_from_slice(args);
    let (code, out, err) = run(&all);
    assert_eq!(code, 0, "{file}: {err}");
    let v: Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"));
    v["ticks"]
        .as_array()
        .expect("ticks")
        .iter()
        .map(|t| {
            let mut vars: Vec<(String, Value)> = t["vars"]
                .as_object()
                .expect("vars")
                .iter()
                .map(|(k, v)| (flat_name(k), v.clone()))
                .collect();
            vars.sort_by(|a, b| a.0.cmp(&b.0));
            vars
        })
        .collect()
}

#[test]
fn arrays_simulate_like_the_twin_and_name_elements() {
    // The scenario's free inputs are the same in both files.
    let scn = ["--scenario", "tests/components/arrays.scn"];
    let a = ticks(ARRAYS, &scn);
    assert_eq!(a, ticks(FLAT, &scn));
    // By hand (arrays.scn): slave 2 is busy after tick 2, slave 1 after tick 4, and n counts
    // the slave busy in the tick before: 1 in ticks 2, 3 and 5.
    let get = |t: usize, n: &str| {
        a[t].iter()
            .find(|(k, _)| k == n)
            .map(|(_, v)| v.clone())
            .unwrap_or(Value::Null)
    };
    assert_eq!(get(2, "s[2].busy"), Value::Bool(true));
    assert_eq!(get(4, "s[1].busy"), Value::Bool(true));
    let n: Vec<Value> = (0..6).map(|t| get(t, "m.n")).collect();
    assert_eq!(n, [0, 0, 1, 1, 0, 1].map(Value::from));
    // Random inputs too.
    let random = ["--random", "40", "--seed", "9"];
    assert_eq!(ticks(ARRAYS, &random), ticks(FLAT, &random));
    // The elements are named with their index in traces.
    let (_, out, _) = run(&["sim", ARRAYS, "--json", "--scenario", scn[1]]);
    assert!(out.contains("\"m.go[1]\""), "{out}");
}

#[test]
fn formatting_keeps_arrays_and_loops() {
    let (code, out, err) = run(&["fmt", "--check", ARRAYS]);
    assert_eq!(code, 0, "{out}{err}");
}

#[test]
fn generated_code_mangles_element_names() {
    let dir = std::env::temp_dir().join(format!("statecheck-arrays-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let c = dir.join("c");
    let (code, _, err) = run(&["gen", "c", ARRAYS, "-o", c.to_str().expect("utf-8")]);
    assert_eq!(code, 0, "{err}");
    let (code, modelica, err) = run(&["gen", "modelica", ARRAYS]);
    assert_eq!(code, 0, "{err}");
    let rs = dir.join("rust");
    let (code, _, err) = run(&["gen", "rust", ARRAYS, "-o", rs.to_str().expect("utf-8")]);
    assert_eq!(code, 0, "{err}");
    let rust = std::fs::read_to_string(rs.join("bus.rs")).expect("rust");
    let pml = dir.join("a.pml");
    let (code, _, err) = run(&[
        "export",
        "promela",
        ARRAYS,
        "-o",
        pml.to_str().expect("utf-8"),
    ]);
    assert_eq!(code, 0, "{err}");
    let header = std::fs::read_to_string(c.join("bus.h")).expect("header");
    let promela = std::fs::read_to_string(&pml).expect("promela");
    // Element `m.go[1]` is the identifier `m_go_1` in every target (a bracket in an
    // identifier would not compile; a clash with a scalar `go_1` would be numbered by
    // `codegen::common::slot_fields`); the name as written stays in comments and strings.
    assert!(header.contains("m_go_1;"), "{header}");
    assert!(rust.contains("pub m_go_1: u8,"), "{rust}");
    assert!(modelica.contains("m_go_1("), "{modelica}");
    assert!(promela.contains("m_go_1 = 0;"), "{promela}");
    let _ = std::fs::remove_dir_all(&dir);
}
