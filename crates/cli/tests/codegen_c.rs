//! Differential test of the generated C on the examples: for every scenario of the FAM, the
//! linear drive and the semantics models (one with a parameterised chart, `params`),
//! `statecheck gen c --harness` compiled with
//! `gcc -std=c99 -Wall -Wextra -Wpedantic -Werror` prints the same JSON trace (ticks, how the
//! run ended, reached properties) as `statecheck sim --json`. Everything is compiled in a
//! fresh temporary directory.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "statecheck-{tag}-{}-{:?}",
        std::process::id(),
        std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_nanos())
            .unwrap_or(0)
    ));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// (model, system, scenarios) triples.
fn cases() -> Vec<(PathBuf, Option<&'static str>, Vec<PathBuf>)> {
    let root = repo_root();
    let scns = |dir: &Path, pred: &dyn Fn(&str) -> bool| -> Vec<PathBuf> {
        let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
            .expect("scenario dir")
            .map(|e| e.expect("entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "scn"))
            .filter(|p| pred(p.file_stem().and_then(|s| s.to_str()).unwrap_or("")))
            .collect();
        v.sort();
        v
    };
    let mut out = vec![
        (
            root.join("examples/fam/fam.sc"),
            Some("FamAlone"),
            scns(&root.join("examples/fam/scenarios"), &|_| true),
        ),
        (
            root.join("examples/linear_drive/linear_drive.sc"),
            None,
            scns(&root.join("examples/linear_drive/scenarios"), &|_| true),
        ),
    ];
    // A model of composite components: flattened before lowering, so the C is that of the
    // flat system, with instances named by path.
    out.push((
        root.join("tests/components/cell.sc"),
        None,
        vec![root.join("tests/components/cell.scn")],
    ));
    // Arrays of variables: elements named `go[0]` in the model, mangled in the C.
    out.push((
        root.join("tests/components/arrays.sc"),
        None,
        vec![root.join("tests/components/arrays.scn")],
    ));
    // A parameterised component and an array of components; an interleaved system (the
    // scheduler is an input of the C step like any other).
    out.push((
        root.join("tests/components/bank.sc"),
        None,
        vec![root.join("tests/components/bank.scn")],
    ));
    out.push((
        root.join("tests/components/interleaved.sc"),
        Some("Async"),
        vec![root.join("tests/components/interleaved.scn")],
    ));
    let sem = root.join("tests/semantics");
    for name in [
        "choice", "history", "order", "parallel", "params", "priority", "runtime", "timers",
    ] {
        out.push((
            sem.join(format!("{name}.sc")),
            None,
            scns(&sem, &|s| s == name),
        ));
    }
    out
}

fn sim_json(model: &Path, system: Option<&str>, scn: &Path) -> Value {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_statecheck"));
    cmd.arg("sim")
        .arg(model)
        .arg("--json")
        .arg("--scenario")
        .arg(scn);
    if let Some(s) = system {
        cmd.arg("--system").arg(s);
    }
    let out = cmd.output().expect("statecheck sim runs");
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| {
        panic!(
            "sim JSON for {}: {e}\n{}",
            scn.display(),
            String::from_utf8_lossy(&out.stderr)
        )
    })
}

/// The parts of a run both sides must agree on (the message wording may differ).
fn comparable(v: &Value) -> Value {
    let mut r = v["result"].clone();
    if let Some(m) = r.as_object_mut() {
        m.remove("message");
        // The time is the tick times the declared tick length, written by the simulator's
        // JSON only (the C harness prints ticks): not part of what the code computes.
        m.remove("time");
    }
    let mut ticks = v["ticks"].clone();
    for t in ticks.as_array_mut().into_iter().flatten() {
        if let Some(m) = t.as_object_mut() {
            m.remove("time");
        }
    }
    serde_json::json!({"ticks": ticks, "result": r, "reached": v["reached"]})
}

#[test]
fn generated_c_replays_every_example_scenario_like_the_simulator() {
    let dir = temp_dir("gen-c");
    let mut compared = 0;
    for (k, (model, system, scenarios)) in cases().into_iter().enumerate() {
        assert!(
            !scenarios.is_empty(),
            "no scenarios for {}",
            model.display()
        );
        let out = dir.join(format!("m{k}"));
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_statecheck"));
        cmd.arg("gen")
            .arg("c")
            .arg(&model)
            .arg("-o")
            .arg(&out)
            .arg("--harness");
        if let Some(s) = system {
            cmd.arg("--system").arg(s);
        }
        let st = cmd.output().expect("statecheck gen runs");
        assert!(
            st.status.success(),
            "{}",
            String::from_utf8_lossy(&st.stderr)
        );
        let mut sources: Vec<PathBuf> = std::fs::read_dir(&out)
            .expect("generated dir")
            .map(|e| e.expect("entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "c"))
            .collect();
        sources.sort();
        let exe = out.join("harness");
        let cc = Command::new("gcc")
            .args([
                "-std=c99",
                "-Wall",
                "-Wextra",
                "-Wpedantic",
                "-Werror",
                "-O1",
            ])
            .args(&sources)
            .arg("-o")
            .arg(&exe)
            .output()
            .expect("gcc runs");
        assert!(
            cc.status.success(),
            "gcc failed for {}:\n{}",
            model.display(),
            String::from_utf8_lossy(&cc.stderr)
        );
        for scn in &scenarios {
            let want = sim_json(&model, system, scn);
            let run = Command::new(&exe).arg(scn).output().expect("harness runs");
            let got: Value = serde_json::from_slice(&run.stdout).unwrap_or_else(|e| {
                panic!(
                    "harness JSON for {}: {e}\n{}",
                    scn.display(),
                    String::from_utf8_lossy(&run.stdout)
                )
            });
            let (w, g) = (comparable(&want), comparable(&got));
            if w != g {
                let wt = w["ticks"].as_array().map_or(0, Vec::len);
                let gt = g["ticks"].as_array().map_or(0, Vec::len);
                let first = (0..wt.min(gt)).find(|&t| w["ticks"][t] != g["ticks"][t]);
                panic!(
                    "{}: C differs from the simulator (ticks {wt} vs {gt}, first differing tick {first:?})\nsim: {}\nC:   {}\nsim result {}\nC result {}",
                    scn.display(),
                    first.map(|t| w["ticks"][t].to_string()).unwrap_or_default(),
                    first.map(|t| g["ticks"][t].to_string()).unwrap_or_default(),
                    w["result"],
                    g["result"]
                );
            }
            compared += 1;
        }
    }
    assert!(compared >= 20, "only {compared} scenarios compared");
    let _ = std::fs::remove_dir_all(&dir);
}
