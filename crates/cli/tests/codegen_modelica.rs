//! `statecheck gen modelica`: snapshots, CLI behaviour, structure, and behaviour.
//!
//! No Modelica tool is installable here, so the generated models are checked three ways:
//! - snapshots (insta) of the linear drive (with and without `--coverage`) and of the
//!   hierarchy/history, parallel and conversion models of `tests/semantics`;
//! - structure: every model of the repository parses in the subset of Modelica the generator
//!   emits (balanced `if`/`when`/`while`/`for`/`function`/`model` blocks, `end NAME;`,
//!   arithmetic without a unary minus after an operator, every name declared), every
//!   hierarchy level has an enumeration of exactly its states plus `InActive`, every IR
//!   transition is one `if`/`elseif` branch, every slot is declared once;
//! - behaviour: a strict interpreter of that subset (typed: Integer, Boolean, enumerations;
//!   `and`/`or` evaluated on both sides, as a Modelica tool may) runs the `when` clause once
//!   per tick on the inputs of every scenario and of random runs, and every slot, every
//!   level's state variable, every coverage counter and how the run ends must equal the
//!   simulator's.

use statecheck_base::Diagnostic;
use statecheck_codegen::modelica::{generate, ModelicaOptions};
use statecheck_codegen::Source;
use statecheck_ir::{CoverKind, Machine, Program, SlotRole};
use statecheck_model::{Model, NodeKind};
use statecheck_sim::random::RandomInputs;
use statecheck_sim::{ScenarioInputs, Stop};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

fn repo_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// A loaded system: its model, lowered program and source.
struct Loaded {
    model: Model,
    program: Program,
    src: Source,
}

/// A model file of the repository, its imports followed (spans are offsets into the text of
/// all its files, as the CLI reads them).
fn load(rel: &str, system: Option<&str>) -> Loaded {
    let path = repo_root().join(rel);
    let text = std::fs::read_to_string(&path).expect("model file");
    let program = statecheck_model::imports::load_with(&path.to_string_lossy(), text, |k| {
        std::fs::read_to_string(k).ok()
    });
    assert!(
        !program.diags.iter().any(Diagnostic::is_error),
        "{rel}: syntax or import errors"
    );
    checked(rel, &program.file, &program.sources.text, system)
}

fn load_text(rel: &str, text: &str, system: Option<&str>) -> Loaded {
    let (file, diags) = statecheck_syntax::parse(text);
    assert!(
        !diags.iter().any(Diagnostic::is_error),
        "{rel}: syntax errors"
    );
    checked(rel, &file, text, system)
}

fn checked(
    rel: &str,
    file: &statecheck_syntax::ast::File,
    text: &str,
    system: Option<&str>,
) -> Loaded {
    let (model, diags) = statecheck_model::check(file);
    assert!(
        !diags.iter().any(Diagnostic::is_error),
        "{rel}: model errors"
    );
    let sys = match system {
        Some(n) => model.system(n).expect("system"),
        None => {
            let explicit: Vec<_> = model.systems.iter().filter(|s| !s.implicit).collect();
            match explicit.as_slice() {
                [one] => one,
                _ => &model.systems[0],
            }
        }
    };
    let program = statecheck_ir::lower(&model, sys).expect("lowers");
    let src = Source::new(rel, text);
    Loaded {
        model,
        program,
        src,
    }
}

fn modelica(l: &Loaded, coverage: bool) -> String {
    generate(&l.program, &l.model, &l.src, &ModelicaOptions { coverage }).expect("generates")
}

fn cli(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_statecheck"))
        .current_dir(repo_root())
        .args(args)
        .output()
        .expect("statecheck runs")
}

fn cli_ok(args: &[&str]) -> String {
    let out = cli(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

/// Every model of the repository (with its systems) the generator must translate.
fn all_models() -> Vec<(String, Option<String>)> {
    let root = repo_root();
    let mut out = Vec::new();
    for dir in [
        "tests/semantics",
        "examples/linear_drive",
        "examples/fam",
        "examples/synthesis",
    ] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(root.join(dir))
            .expect("dir")
            .map(|e| e.expect("entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "sc"))
            .collect();
        files.sort();
        for f in files {
            let rel = format!(
                "{dir}/{}",
                f.file_name().and_then(|s| s.to_str()).unwrap_or("")
            );
            let text = std::fs::read_to_string(&f).expect("model");
            let systems: Vec<String> = text
                .lines()
                .filter_map(|l| l.strip_prefix("system "))
                .filter_map(|l| l.split_whitespace().next())
                .map(|s| s.trim_end_matches('{').to_string())
                .collect();
            if WIDER_THAN_32_BITS.contains(&rel.as_str()) {
                continue;
            }
            if systems.is_empty() {
                out.push((rel, None));
            } else {
                out.extend(systems.into_iter().map(|s| (rel.clone(), Some(s))));
            }
        }
    }
    out
}

/// Models whose values need 64 bits: Modelica's `Integer` is 32-bit, so the generator refuses
/// them (docs/codegen.md) instead of translating them; `minrem.sc` pins `MIN % -1` for
/// MIN = -2^63.
const WIDER_THAN_32_BITS: [&str; 1] = ["tests/semantics/minrem.sc"];

#[test]
fn models_wider_than_32_bits_are_refused_with_the_reason() {
    for model in WIDER_THAN_32_BITS {
        let out = cli(&["gen", "modelica", model]);
        assert!(!out.status.success(), "{model}: generated");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("wider than a 32-bit Modelica Integer"),
            "{model}: {err}"
        );
    }
}

// ----- snapshots -------------------------------------------------------------------------------

fn snapshot(name: &str, args: &[&str]) {
    let text = cli_ok(args);
    insta::assert_snapshot!(name, text);
}

#[test]
fn snapshot_linear_drive() {
    snapshot(
        "linear_drive",
        &["gen", "modelica", "examples/linear_drive/linear_drive.sc"],
    );
}

#[test]
fn snapshot_linear_drive_with_coverage() {
    snapshot(
        "linear_drive_coverage",
        &[
            "gen",
            "modelica",
            "examples/linear_drive/linear_drive.sc",
            "--coverage",
        ],
    );
}

#[test]
fn snapshot_history() {
    snapshot(
        "history",
        &["gen", "modelica", "tests/semantics/history.sc"],
    );
}

#[test]
fn snapshot_parallel() {
    snapshot(
        "parallel",
        &["gen", "modelica", "tests/semantics/parallel.sc"],
    );
}

#[test]
fn snapshot_convert() {
    snapshot(
        "convert",
        &["gen", "modelica", "tests/semantics/convert.sc"],
    );
}

// ----- CLI -------------------------------------------------------------------------------------

#[test]
fn output_file_holds_what_standard_output_shows() {
    let dir = std::env::temp_dir().join(format!("statecheck-modelica-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("drive.mo");
    let f = file.to_str().expect("path");
    let model = "examples/linear_drive/linear_drive.sc";
    let out = cli(&["gen", "modelica", model, "--coverage", "-o", f]);
    assert!(out.status.success());
    assert!(out.stdout.is_empty(), "nothing on standard output with -o");
    let written = std::fs::read_to_string(&file).expect("written");
    assert_eq!(written, cli_ok(&["gen", "modelica", model, "--coverage"]));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn coverage_is_for_modelica_only() {
    let out = cli(&[
        "gen",
        "c",
        "tests/semantics/order.sc",
        "-o",
        "/tmp/x",
        "--coverage",
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--coverage"));
}

#[test]
fn system_is_chosen_with_system() {
    let out = cli(&["gen", "modelica", "tests/semantics/connect.sc"]);
    assert!(!out.status.success(), "connect.sc declares two systems");
    let text = cli_ok(&[
        "gen",
        "modelica",
        "tests/semantics/connect.sc",
        "--system",
        "Late",
    ]);
    assert!(text.starts_with("model Late "), "{}", &text[..40]);
}

#[test]
fn counters_only_on_request() {
    let l = load("examples/linear_drive/linear_drive.sc", None);
    let plain = modelica(&l, false);
    assert!(!plain.contains("Coverage"));
    let counted = modelica(&l, true);
    let states = l
        .program
        .covers
        .iter()
        .filter(|c| matches!(c.kind, CoverKind::State(_)))
        .count();
    let trans = l.program.covers.len() - states;
    assert!(counted.contains(&format!("Integer stateCoverage[{states}](each start = 0")));
    assert!(counted.contains(&format!(
        "Integer transitionCoverage[{trans}](each start = 0"
    )));
    // Without the counters, the two models are the same statement for statement.
    let stripped: Vec<&str> = counted
        .lines()
        .filter(|l| !l.contains("Coverage") && !l.is_empty())
        .collect();
    let plain_lines: Vec<&str> = plain.lines().filter(|l| !l.is_empty()).collect();
    assert_eq!(stripped, plain_lines);
}

// ----- structure -------------------------------------------------------------------------------

#[test]
fn every_model_has_the_papers_structure() {
    for (rel, sys) in all_models() {
        let l = load(&rel, sys.as_deref());
        for coverage in [false, true] {
            let text = modelica(&l, coverage);
            let what = format!("{rel} {sys:?} coverage={coverage}");
            let mo = mini::parse(&text).unwrap_or_else(|e| panic!("{what}: {e}"));
            assert_eq!(
                mo.name,
                statecheck_codegen::common::ident(&l.program.name),
                "{what}"
            );
            mini::check_names(&mo).unwrap_or_else(|e| panic!("{what}: {e}"));
            let vars = slot_vars(&mo, &l.program).unwrap_or_else(|e| panic!("{what}: {e}"));
            levels_are_enumerations(&l, &mo, &vars, &what);
            transitions_are_branches(&l, &text, coverage, &what);
        }
    }
}

/// The variable of every slot, found by its description (`"slot name: role"`), exactly once.
fn slot_vars(mo: &mini::Model, p: &Program) -> Result<Vec<String>, String> {
    p.slots
        .iter()
        .map(|s| {
            let prefix = format!("{}: ", s.name);
            let found: Vec<&mini::Decl> = mo
                .decls
                .iter()
                .filter(|d| d.desc.as_deref().is_some_and(|x| x.starts_with(&prefix)))
                .collect();
            match found.as_slice() {
                [d] => Ok(d.name.clone()),
                _ => Err(format!("slot `{}` declared {} times", s.name, found.len())),
            }
        })
        .collect()
}

/// Each level's selector and state variable have an enumeration of exactly the level's child
/// states, then `InActive`.
fn levels_are_enumerations(l: &Loaded, mo: &mini::Model, vars: &[String], what: &str) {
    let mut levels = 0;
    for (k, s) in l.program.slots.iter().enumerate() {
        let SlotRole::Region { instance, node } = s.role else {
            continue;
        };
        levels += 1;
        let inst = &l.program.instances[instance as usize];
        let chart = &l.model.charts[inst.chart as usize];
        let NodeKind::Or { children, .. } = &chart.states[node as usize].kind else {
            panic!("{what}: region slot of a non-exclusive node");
        };
        let mut expected: Vec<String> = children
            .iter()
            .map(|c| statecheck_codegen::common::ident(&chart.states[*c as usize].name))
            .collect();
        expected.push("InActive".into());
        let decl = mo
            .decl(&vars[k])
            .unwrap_or_else(|| panic!("{what}: no {}", vars[k]));
        let lits = mo
            .types
            .get(&decl.ty)
            .unwrap_or_else(|| panic!("{what}: type {}", decl.ty));
        assert_eq!(lits, &expected, "{what}: level of `{}`", s.name);
        // The level's state variable (the paper's `goState`) has the same type.
        let path = &chart.states[node as usize].path;
        let desc = if path.is_empty() {
            format!("active state of the top level of {}", inst.name)
        } else {
            format!("active state of the level {}.{path}", inst.name)
        };
        let view: Vec<&mini::Decl> = mo
            .decls
            .iter()
            .filter(|d| d.desc.as_deref() == Some(desc.as_str()))
            .collect();
        assert_eq!(view.len(), 1, "{what}: {desc}");
        assert_eq!(view[0].ty, decl.ty, "{what}: {desc}");
    }
    let views = mo
        .decls
        .iter()
        .filter(|d| {
            d.desc
                .as_deref()
                .is_some_and(|x| x.starts_with("active state of "))
        })
        .count();
    assert_eq!(views, levels, "{what}: one state variable per level");
}

/// Every transition of the IR is one `if`/`elseif` branch: its comment appears once, right
/// after the branch's condition, followed by its counter when counting.
fn transitions_are_branches(l: &Loaded, text: &str, coverage: bool, what: &str) {
    let lines: Vec<&str> = text.lines().map(str::trim).collect();
    let p = &l.program;
    let (mut s_idx, mut t_idx) = (0, 0);
    for c in &p.covers {
        let inst = if p.instances.len() > 1 {
            format!("{}: ", p.instances[c.instance as usize].name)
        } else {
            String::new()
        };
        let (word, counter) = match c.kind {
            CoverKind::State(_) => {
                s_idx += 1;
                ("entry of", format!("stateCoverage[{s_idx}]"))
            }
            CoverKind::Transition(_) => {
                t_idx += 1;
                ("transition", format!("transitionCoverage[{t_idx}]"))
            }
            CoverKind::Branch(..) => {
                t_idx += 1;
                ("via", format!("transitionCoverage[{t_idx}]"))
            }
        };
        let comment = format!("// {inst}{word} {} ({})", c.label, l.src.at(c.span));
        let at: Vec<usize> = (0..lines.len()).filter(|&i| lines[i] == comment).collect();
        if let CoverKind::Transition(_) = c.kind {
            // Two transitions can share a label (same source, target and line).
            let same = p
                .covers
                .iter()
                .filter(|d| {
                    matches!(d.kind, CoverKind::Transition(_))
                        && d.instance == c.instance
                        && d.label == c.label
                        && l.src.at(d.span) == l.src.at(c.span)
                })
                .count();
            assert_eq!(
                at.len(),
                same,
                "{what}: `{comment}` appears {} times",
                at.len()
            );
            for &i in &at {
                let before = lines[i - 1];
                assert!(
                    (before.starts_with("if ") || before.starts_with("elseif "))
                        && before.ends_with(" then"),
                    "{what}: `{comment}` follows `{before}`"
                );
            }
        }
        let own = format!("{counter} := {counter} + 1;");
        let mut own_seen = false;
        for &i in &at {
            let next = lines.get(i + 1).copied().unwrap_or("");
            let counted = next.ends_with("] + 1;") && next.contains("Coverage[");
            assert_eq!(counted, coverage, "{what}: after `{comment}`: `{next}`");
            own_seen |= next == own;
        }
        assert_eq!(
            own_seen,
            coverage && !at.is_empty(),
            "{what}: `{own}` after `{comment}`"
        );
    }
}

// ----- behaviour -------------------------------------------------------------------------------

/// Inputs of a scenario tick as the simulator applies them: events last one tick, other
/// inputs hold their value.
fn scenario_inputs(p: &Program, sc: &statecheck_sim::Scenario, upto: usize) -> Vec<i64> {
    let mut v: Vec<i64> = p
        .inputs
        .iter()
        .map(|i| p.slots[i.slot as usize].init)
        .collect();
    for t in 0..=upto {
        for (k, inp) in p.inputs.iter().enumerate() {
            if inp.is_event {
                v[k] = 0;
            }
        }
        for &(k, x) in sc.tick(t).unwrap_or(&[]) {
            v[k] = x;
        }
    }
    v
}

/// Run the generated model on `run`'s inputs and compare everything with the simulator.
fn compare(
    l: &Loaded,
    run: &statecheck_sim::Run,
    extra_inputs: Option<Vec<i64>>,
    what: &str,
) -> usize {
    let p = &l.program;
    let text = modelica(l, true);
    let mo = mini::parse(&text).unwrap_or_else(|e| panic!("{what}: {e}"));
    let vars = slot_vars(&mo, p).unwrap_or_else(|e| panic!("{what}: {e}"));
    let mut m = mini::Machine::new(&mo).unwrap_or_else(|e| panic!("{what}: {e:?}"));
    let mut ir = Machine::new(p);
    let (last, fail_at) = match &run.stop {
        Stop::Completed => (run.trace.len(), None),
        Stop::RuntimeError { tick, .. } | Stop::AssumeViolated { tick, .. } => {
            (*tick as usize, Some(*tick as usize))
        }
        Stop::Violation { tick, .. } => (*tick as usize + 1, Some(*tick as usize)),
    };
    assert!(run.trace.len() >= last, "{what}: trace length");
    let inputs_of = |t: usize| -> Option<Vec<i64>> {
        run.inputs.get(t).cloned().or_else(|| {
            if Some(t) == fail_at {
                extra_inputs.clone()
            } else {
                None
            }
        })
    };
    let ticks = fail_at.map_or(last, |f| f + 1);
    for t in 0..ticks {
        let Some(inputs) = inputs_of(t) else {
            break; // a random run that could not satisfy the assumptions
        };
        for (k, inp) in p.inputs.iter().enumerate() {
            m.set_input(&vars[inp.slot as usize], inputs[k])
                .unwrap_or_else(|e| panic!("{what}: tick {t}: {e:?}"));
        }
        let result = m.tick();
        if Some(t) == fail_at {
            let msg = match &result {
                Err(mini::Fail::Assert(msg)) => msg.clone(),
                Err(mini::Fail::Error(e)) => format!("interpreter: {e}"),
                Ok(()) => panic!("{what}: tick {t} should fail with {:?}", run.stop),
            };
            match &run.stop {
                Stop::RuntimeError { error, .. } => {
                    let overflow = matches!(error.kind, statecheck_ir::RuntimeErrorKind::Overflow);
                    assert!(
                        msg.contains(&format!("at site {}:", error.site))
                            || (overflow && msg.contains("overflow")),
                        "{what}: tick {t}: {msg} (expected {error:?})"
                    );
                }
                Stop::Violation { property, .. } => assert!(
                    msg.contains(&format!("property `{property}` violated")),
                    "{what}: tick {t}: {msg}"
                ),
                Stop::AssumeViolated { assume, .. } => assert!(
                    msg.contains(&format!("assume #{} ", assume + 1)),
                    "{what}: tick {t}: {msg}"
                ),
                Stop::Completed => {}
            }
            if !matches!(run.stop, Stop::Violation { .. }) {
                break;
            }
        } else if let Err(e) = result {
            panic!("{what}: tick {t} failed: {e:?}");
        }
        let expected = &run.trace[t].slots;
        for (k, s) in p.slots.iter().enumerate() {
            let got = m
                .value(&vars[k])
                .unwrap_or_else(|e| panic!("{what}: {e:?}"));
            assert_eq!(
                got, expected[k],
                "{what}: tick {t}: slot `{}` ({})",
                s.name, vars[k]
            );
            ir.set(k as u32, expected[k]);
        }
        check_levels(l, &mo, &m, &mut ir, &vars, &format!("{what}: tick {t}"));
    }
    if let (Some(cov), Stop::Completed | Stop::Violation { .. }) = (&run.coverage, &run.stop) {
        let (mut s, mut tr) = (0, 0);
        for (c, cv) in p.covers.iter().enumerate() {
            let name = match cv.kind {
                CoverKind::State(_) => {
                    s += 1;
                    format!("stateCoverage[{s}]")
                }
                _ => {
                    tr += 1;
                    format!("transitionCoverage[{tr}]")
                }
            };
            let got = m.value(&name).unwrap_or_else(|e| panic!("{what}: {e:?}"));
            assert_eq!(got, cov[c] as i64, "{what}: {name} ({})", cv.label);
        }
    }
    ticks
}

/// Each level's state variable is its selector while the level is active (the IR's `in()`),
/// `InActive` otherwise.
fn check_levels(
    l: &Loaded,
    mo: &mini::Model,
    m: &mini::Machine,
    ir: &mut Machine,
    vars: &[String],
    what: &str,
) {
    for (k, s) in l.program.slots.iter().enumerate() {
        let SlotRole::Region { instance, node } = s.role else {
            continue;
        };
        let inst = &l.program.instances[instance as usize];
        let path = &l.model.charts[inst.chart as usize].states[node as usize].path;
        let desc = if path.is_empty() {
            format!("active state of the top level of {}", inst.name)
        } else {
            format!("active state of the level {}.{path}", inst.name)
        };
        let Some(view) = mo
            .decls
            .iter()
            .find(|d| d.desc.as_deref() == Some(desc.as_str()))
        else {
            panic!("{what}: no `{desc}`");
        };
        let active = ir.eval(inst.active[node as usize]).expect("in()") != 0;
        let n_lits = mo.types.get(&view.ty).map_or(0, Vec::len) as i64;
        let expected = if active {
            m.value(&vars[k]).expect("selector")
        } else {
            n_lits - 1
        };
        assert_eq!(
            m.value(&view.name).expect("view"),
            expected,
            "{what}: {desc}"
        );
    }
}

/// (model, system, scenario) of every scenario in the repository.
fn scenarios() -> Vec<(String, Option<String>, PathBuf)> {
    let root = repo_root();
    let mut out = Vec::new();
    for (dir, model) in [
        ("tests/semantics", None),
        (
            "examples/linear_drive/scenarios",
            Some("examples/linear_drive/linear_drive.sc"),
        ),
        ("examples/fam/scenarios", Some("examples/fam/fam.sc")),
    ] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(root.join(dir))
            .expect("dir")
            .map(|e| e.expect("entry").path())
            .filter(|p| p.extension().is_some_and(|e| e == "scn"))
            .collect();
        files.sort();
        for f in files {
            let text = std::fs::read_to_string(&f).expect("scenario");
            let mut system = text
                .lines()
                .find_map(|l| l.strip_prefix("# args: --system "))
                .map(|s| s.trim().to_string());
            let model = match model {
                Some(m) => {
                    if m.ends_with("fam.sc") {
                        system = Some("FamAlone".into());
                    }
                    m.to_string()
                }
                None => {
                    let stem = f.file_stem().and_then(|s| s.to_str()).unwrap_or("");
                    let own = format!("{dir}/{stem}.sc");
                    if root.join(&own).exists() {
                        own
                    } else {
                        let base = stem.rsplit_once('_').map_or(stem, |(b, _)| b);
                        format!("{dir}/{base}.sc")
                    }
                }
            };
            if !WIDER_THAN_32_BITS.contains(&model.as_str()) {
                out.push((model, system, f));
            }
        }
    }
    out
}

#[test]
fn every_scenario_runs_as_in_the_simulator() {
    let mut checked = 0;
    let mut failures = 0;
    for (model, system, scn) in scenarios() {
        let l = load(&model, system.as_deref());
        let text = std::fs::read_to_string(&scn).expect("scenario");
        let sc = statecheck_sim::scenario::parse(&text, &l.program).expect("scenario parses");
        let run = statecheck_sim::run(
            &l.program,
            &mut ScenarioInputs::new(&sc),
            statecheck_sim::Options {
                coverage: true,
                no_trace: false,
                keep_going: false,
            },
        );
        if !matches!(run.stop, Stop::Completed) {
            failures += 1;
        }
        let extra = match run.stop {
            Stop::AssumeViolated { tick, .. } => {
                Some(scenario_inputs(&l.program, &sc, tick as usize))
            }
            _ => None,
        };
        checked += compare(&l, &run, extra, &format!("{}", scn.display()));
    }
    assert!(checked > 300, "{checked} ticks compared");
    assert!(
        failures >= 2,
        "runs that end in an error or a violation are compared too"
    );
}

#[test]
fn random_runs_run_as_in_the_simulator() {
    let mut checked = 0;
    for (rel, sys) in all_models() {
        let l = load(&rel, sys.as_deref());
        let ticks = if l.program.slots.len() > 200 { 12 } else { 40 };
        for seed in 1..=3 {
            let run = statecheck_sim::run(
                &l.program,
                &mut RandomInputs::new(&l.program, seed, ticks),
                statecheck_sim::Options {
                    coverage: true,
                    no_trace: false,
                    keep_going: false,
                },
            );
            checked += compare(&l, &run, None, &format!("{rel} {sys:?} seed {seed}"));
        }
    }
    assert!(checked > 1000, "{checked} ticks compared");
}

/// Every translation path the repository's models may miss: `&&`/`||` whose right operand
/// can fail (division guarded by the left operand), division and shifts by a variable, a
/// function with `let`, bitwise operators on negative values, `Enum(n)`, comparisons of a
/// Boolean with a constant, an enum-valued `if`, a self-transition, a local event, a variable
/// never assigned, an invariant with `assuming`; and a chart whose runs stop on division by
/// zero, bad shifts and range errors.
const SINK: &str = r#"
enum Mode { A, B, C }
fn pick(x: int[-20..20], y: int[-5..5]) -> int[-100..100] {
  let s = x * y;
  return if s > 50 then 50 else s;
}
chart Sink {
  input event e;
  input a: int[-20..20] = 0;
  input b: int[-5..5] = 0;
  input k: int[0..3] = 0;
  output flag: bool = false;
  output m: Mode = A;
  output q: int[-100..100] = 0;
  output bits: int[-64..63] = 0;
  output sh: int[-1000..1000] = 0;
  output n: int[0..3] = 0;
  local event ping;
  local never: int[0..9] = 7;
  initial S;
  state S {
    during {
      flag = (b != 0 && a / b > 1) || a == 0;
      q = pick(a, b);
      bits = (a & -8) ^ (b | 3) ^ ~k;
      sh = (a << k) + (a >> k) + never;
      m = Mode(k % 3);
      if flag == true { raise ping; }
      if b == 0 || 10 / b > 2 { q = -q; }
      m = if flag != false then m else Mode.C;
    }
    on ping -> T;
    on [a < -15] -> S;
  }
  state T {
    entry { q = abs(a); n = (n + 1) % 4; }
    on [flag == false && m != Mode.B] -> S;
    on e -> S;
  }
  invariant q_bounded: q <= 100 assuming m != Mode.C;
  reachable t_reached: in(T);
}
chart Fails {
  input d: int[-1..3] = 1;
  input s: int[-1..12] = 0;
  output x: int[-12..12] = 0;
  output y: int[0..1000] = 0;
  initial S;
  state S { during { x = 12 / d; y = (1 << s) + x % d; } }
}
"#;

#[test]
fn every_translation_path_runs_as_in_the_simulator() {
    let mut stops = BTreeMap::new();
    let mut checked = 0;
    for chart in ["Sink", "Fails"] {
        let l = load_text("sink.sc", SINK, Some(chart));
        for seed in 1..=40 {
            let run = statecheck_sim::run(
                &l.program,
                &mut RandomInputs::new(&l.program, seed, 30),
                statecheck_sim::Options {
                    coverage: true,
                    no_trace: false,
                    keep_going: false,
                },
            );
            let kind = match &run.stop {
                Stop::RuntimeError { error, .. } => format!("{:?}", error.kind)
                    .split([' ', '{'])
                    .next()
                    .unwrap_or("")
                    .to_string(),
                other => format!("{other:?}")
                    .split([' ', '{'])
                    .next()
                    .unwrap_or("")
                    .to_string(),
            };
            *stops.entry(kind).or_insert(0) += 1;
            checked += compare(&l, &run, None, &format!("{chart} seed {seed}"));
        }
    }
    assert!(checked > 1000, "{checked} ticks compared");
    for kind in ["Completed", "Range", "DivisionByZero", "BadShift"] {
        assert!(
            stops.contains_key(kind),
            "no run ended with {kind}: {stops:?}"
        );
    }
}

#[test]
fn the_interpreter_catches_what_it_should() {
    // The checks above are only as good as the interpreter's strictness: it must reject an
    // undeclared name, a type mix-up, an unary minus after an operator, an unbalanced block
    // and a value outside a variable's range.
    let ok = "model M\n  parameter Real period = 1.0;\n  Integer x(min = 0, max = 3, start = 0, fixed = true) \"x: v\";\nalgorithm\n  when sample(0, period) then\n    x := x + 1;\n  end when;\n  annotation(experiment(StopTime = 1.0));\nend M;\n";
    let mo = mini::parse(ok).expect("parses");
    let mut m = mini::Machine::new(&mo).expect("machine");
    for _ in 0..3 {
        m.tick().expect("in range");
    }
    assert!(
        matches!(m.tick(), Err(mini::Fail::Error(_))),
        "4 is outside 0..3"
    );
    for bad in [
        ok.replace("x := x + 1;", "x := y + 1;"),
        ok.replace("x := x + 1;", "x := x + true;"),
        ok.replace("x := x + 1;", "x := x + -1;"),
        ok.replace("x := x + 1;", "if x > 0 then x := 1;"),
        ok.replace("end M;", "end N;"),
    ] {
        let failed = match mini::parse(&bad) {
            Err(_) => true,
            Ok(mo) => {
                mini::check_names(&mo).is_err()
                    || mini::Machine::new(&mo).map_or(true, |mut m| m.tick().is_err())
            }
        };
        assert!(failed, "accepted:\n{bad}");
    }
}

// ----- a strict interpreter of the emitted subset of Modelica ------------------------------------

#[path = "modelica_mini/mod.rs"]
mod mini;
