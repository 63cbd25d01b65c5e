//! The examples' scenarios reproduce their hand-derived expectations.
//!
//! Every `examples/*/scenarios/*.scn` with `# expect` lines runs through
//! `statecheck sim --json` on the example's model (the only `.sc` of the example, or the one a
//! `# model: FILE` directive names; `# args: ...` adds CLI arguments), and each expectation
//! must hold in the trace:
//!
//! ```text
//! # expect 42: active ctrl Go.GoRight, ctrl.U=10, drive.x=-400
//! ```
//! `active INSTANCE PATH` means the state is active after that tick; `inst.var=value` compares
//! the variable's value (numbers, `true`/`false`, enum literals).

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn directive<'a>(text: &'a str, key: &str) -> Option<&'a str> {
    text.lines()
        .find_map(|l| l.strip_prefix(&format!("# {key}:")).map(str::trim))
}

fn render(v: &Value) -> String {
    match v {
        Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

fn check_expectation(trace: &[Value], tick: usize, item: &str) -> Result<(), String> {
    let t = trace
        .get(tick)
        .ok_or_else(|| format!("the trace has no tick {tick} (it has {})", trace.len()))?;
    if let Some(rest) = item.strip_prefix("active ") {
        let (inst, path) = rest
            .split_once(' ')
            .ok_or_else(|| format!("bad item `{item}`"))?;
        let active = t["active"][inst]
            .as_array()
            .ok_or_else(|| format!("no instance `{inst}`"))?;
        if active.iter().any(|a| a.as_str() == Some(path.trim())) {
            return Ok(());
        }
        return Err(format!(
            "tick {tick}: `{path}` not active in `{inst}`; active: {active:?}"
        ));
    }
    let (key, want) = item
        .split_once('=')
        .ok_or_else(|| format!("bad item `{item}`"))?;
    let got = t["vars"]
        .get(key.trim())
        .ok_or_else(|| format!("tick {tick}: no variable `{key}`"))?;
    if render(got) == want.trim() {
        Ok(())
    } else {
        Err(format!(
            "tick {tick}: {key} = {}, expected {}",
            render(got),
            want.trim()
        ))
    }
}

#[test]
fn example_scenarios_meet_their_expectations() {
    let root = repo_root();
    let mut checked = 0;
    let mut failures = Vec::new();
    let mut examples: Vec<PathBuf> = std::fs::read_dir(root.join("examples"))
        .expect("examples/ exists")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.join("scenarios").is_dir())
        .collect();
    examples.sort();
    for ex in examples {
        let mut scenarios: Vec<PathBuf> = std::fs::read_dir(ex.join("scenarios"))
            .expect("scenarios readable")
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|e| e == "scn"))
            .collect();
        scenarios.sort();
        for scn in scenarios {
            let text = std::fs::read_to_string(&scn).expect("readable");
            let expects: Vec<(usize, String)> = text
                .lines()
                .filter_map(|l| l.strip_prefix("# expect "))
                .filter_map(|l| {
                    let (t, items) = l.split_once(':')?;
                    Some((t.trim().parse().ok()?, items.to_string()))
                })
                .collect();
            if expects.is_empty() {
                continue;
            }
            let model = match directive(&text, "model") {
                Some(m) => ex.join(m),
                None => {
                    let models: Vec<PathBuf> = std::fs::read_dir(&ex)
                        .expect("example readable")
                        .filter_map(|e| e.ok().map(|e| e.path()))
                        .filter(|p| p.extension().is_some_and(|e| e == "sc"))
                        .collect();
                    assert_eq!(
                        models.len(),
                        1,
                        "{}: name the model with `# model:`",
                        scn.display()
                    );
                    models[0].clone()
                }
            };
            let mut cmd = Command::new(env!("CARGO_BIN_EXE_statecheck"));
            cmd.arg("sim")
                .arg(&model)
                .arg("--scenario")
                .arg(&scn)
                .arg("--json");
            if let Some(args) = directive(&text, "args") {
                cmd.args(args.split_whitespace());
            }
            let out = cmd.output().expect("statecheck runs");
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert!(!stderr.contains("panicked"), "{}: {stderr}", scn.display());
            let json: Value = match serde_json::from_slice(&out.stdout) {
                Ok(v) => v,
                Err(e) => {
                    failures.push(format!(
                        "{}: no JSON ({e}); stderr: {stderr}",
                        scn.display()
                    ));
                    continue;
                }
            };
            let trace = json["ticks"].as_array().cloned().unwrap_or_default();
            for (tick, items) in &expects {
                for item in items.split(',') {
                    if let Err(e) = check_expectation(&trace, *tick, item.trim()) {
                        failures.push(format!("{}: {e}", scn.display()));
                    }
                }
            }
            checked += 1;
        }
    }
    assert!(
        checked >= 5,
        "expected the linear_drive scenarios, checked {checked}"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
