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

fn load(rel: &str, system: Option<&str>) -> Loaded {
    let path = repo_root().join(rel);
    let text = std::fs::read_to_string(&path).expect("model file");
    load_text(rel, &text, system)
}

fn load_text(rel: &str, text: &str, system: Option<&str>) -> Loaded {
    let (file, diags) = statecheck_syntax::parse(text);
    assert!(
        !diags.iter().any(Diagnostic::is_error),
        "{rel}: syntax errors"
    );
    let (model, diags) = statecheck_model::check(&file);
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
            if systems.is_empty() {
                out.push((rel, None));
            } else {
                out.extend(systems.into_iter().map(|s| (rel.clone(), Some(s))));
            }
        }
    }
    out
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
        for &(k, x) in sc.ticks.get(t).map_or(&[][..], |c| &c[..]) {
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
            out.push((model, system, f));
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
                &mut RandomInputs::new(seed, ticks),
                statecheck_sim::Options {
                    coverage: true,
                    no_trace: false,
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
                &mut RandomInputs::new(seed, 30),
                statecheck_sim::Options {
                    coverage: true,
                    no_trace: false,
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

mod mini {
    //! The subset of Modelica that `gen modelica` emits: one model with enumeration types, a
    //! `Real` parameter, declarations with modifiers, functions with `while`/`for`, and one
    //! algorithm section holding one `when` clause. Parsing follows Modelica's grammar for
    //! expressions (a unary minus only at the start of an arithmetic expression); evaluation is
    //! typed and strict.

    use std::collections::BTreeMap;

    #[derive(Clone, Debug, PartialEq)]
    enum Tok {
        Id(String),
        Int(i64),
        Real,
        Str(String),
        Sym(&'static str),
    }

    const SYMS: &[&str] = &[
        ":=", "==", "<>", "<=", ">=", "<", ">", "+", "-", "*", "/", "(", ")", "[", "]", ",", ";",
        "=", ".", ":",
    ];

    fn lex(src: &str) -> Result<Vec<(Tok, usize)>, String> {
        let mut out = Vec::new();
        let b = src.as_bytes();
        let (mut i, mut line) = (0, 1);
        while i < b.len() {
            let c = b[i] as char;
            if c == '\n' {
                line += 1;
                i += 1;
            } else if c.is_whitespace() {
                i += 1;
            } else if src[i..].starts_with("//") {
                while i < b.len() && b[i] != b'\n' {
                    i += 1;
                }
            } else if c.is_ascii_alphabetic() || c == '_' {
                let s = i;
                while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                    i += 1;
                }
                out.push((Tok::Id(src[s..i].to_string()), line));
            } else if c.is_ascii_digit() {
                let s = i;
                while i < b.len() && b[i].is_ascii_digit() {
                    i += 1;
                }
                if i + 1 < b.len() && b[i] == b'.' && b[i + 1].is_ascii_digit() {
                    i += 1;
                    while i < b.len() && b[i].is_ascii_digit() {
                        i += 1;
                    }
                    out.push((Tok::Real, line));
                } else {
                    let v = src[s..i]
                        .parse()
                        .map_err(|_| format!("line {line}: number"))?;
                    out.push((Tok::Int(v), line));
                }
            } else if c == '"' {
                let mut s = String::new();
                i += 1;
                loop {
                    match b.get(i) {
                        None => return Err(format!("line {line}: unterminated string")),
                        Some(b'"') => break,
                        Some(b'\\') => {
                            s.push(*b.get(i + 1).ok_or("bad escape")? as char);
                            i += 2;
                        }
                        Some(b'\n') => return Err(format!("line {line}: newline in string")),
                        Some(_) => {
                            let ch = src[i..].chars().next().ok_or("char")?;
                            s.push(ch);
                            i += ch.len_utf8();
                        }
                    }
                }
                i += 1;
                out.push((Tok::Str(s), line));
            } else {
                let sym = SYMS
                    .iter()
                    .find(|s| src[i..].starts_with(**s))
                    .ok_or_else(|| format!("line {line}: unexpected `{c}`"))?;
                out.push((Tok::Sym(sym), line));
                i += sym.len();
            }
        }
        Ok(out)
    }

    /// An expression.
    #[derive(Clone, Debug)]
    pub enum Expr {
        Int(i64),
        Bool(bool),
        Str(String),
        Name(String),
        Lit(String, String),
        Index(String, Box<Expr>),
        Call(String, Vec<Expr>),
        Neg(Box<Expr>),
        Not(Box<Expr>),
        Bin(&'static str, Box<Expr>, Box<Expr>),
        If(Vec<(Expr, Expr)>, Box<Expr>),
    }

    /// A statement.
    #[derive(Clone, Debug)]
    pub enum Stmt {
        Assign(String, Option<Expr>, Expr),
        If(Vec<(Expr, Vec<Stmt>)>, Vec<Stmt>),
        Assert(Expr, Expr),
        While(Expr, Vec<Stmt>),
        For(String, Expr, Expr, Vec<Stmt>),
    }

    /// A component declaration.
    #[derive(Clone, Debug)]
    pub struct Decl {
        pub prefix: Option<String>,
        pub ty: String,
        pub name: String,
        pub size: Option<usize>,
        pub mods: Vec<(String, Expr)>,
        pub binding: Option<Expr>,
        pub desc: Option<String>,
    }

    /// A function.
    #[derive(Clone, Debug)]
    pub struct Function {
        pub inputs: Vec<(String, String)>,
        pub output: (String, String),
        pub locals: Vec<(String, String)>,
        pub body: Vec<Stmt>,
    }

    /// A parsed model.
    #[derive(Clone, Debug)]
    pub struct Model {
        pub name: String,
        pub types: BTreeMap<String, Vec<String>>,
        pub params: Vec<String>,
        pub decls: Vec<Decl>,
        pub functions: BTreeMap<String, Function>,
        pub tick: Vec<Stmt>,
    }

    impl Model {
        /// The declaration of `name`.
        pub fn decl(&self, name: &str) -> Option<&Decl> {
            self.decls.iter().find(|d| d.name == name)
        }
    }

    struct P {
        toks: Vec<(Tok, usize)>,
        at: usize,
    }

    type R<T> = Result<T, String>;

    impl P {
        fn peek(&self) -> Option<&Tok> {
            self.toks.get(self.at).map(|t| &t.0)
        }
        fn err<T>(&self, what: &str) -> R<T> {
            let line = self.toks.get(self.at).map_or(0, |t| t.1);
            Err(format!(
                "line {line}: expected {what}, found {:?}",
                self.peek()
            ))
        }
        fn is_id(&self, w: &str) -> bool {
            matches!(self.peek(), Some(Tok::Id(x)) if x == w)
        }
        fn is_sym(&self, s: &str) -> bool {
            matches!(self.peek(), Some(Tok::Sym(x)) if *x == s)
        }
        fn kw(&mut self, w: &str) -> R<()> {
            if self.is_id(w) {
                self.at += 1;
                Ok(())
            } else {
                self.err(w)
            }
        }
        fn sym(&mut self, s: &str) -> R<()> {
            if self.is_sym(s) {
                self.at += 1;
                Ok(())
            } else {
                self.err(s)
            }
        }
        fn id(&mut self) -> R<String> {
            match self.peek() {
                Some(Tok::Id(x)) if !KEYWORDS.split_whitespace().any(|w| w == x) => {
                    let x = x.clone();
                    self.at += 1;
                    Ok(x)
                }
                _ => self.err("identifier"),
            }
        }
        fn string(&mut self) -> Option<String> {
            if let Some(Tok::Str(s)) = self.peek() {
                let s = s.clone();
                self.at += 1;
                Some(s)
            } else {
                None
            }
        }

        fn model(&mut self) -> R<Model> {
            self.kw("model")?;
            let name = self.id()?;
            self.string();
            let mut m = Model {
                name,
                types: BTreeMap::new(),
                params: Vec::new(),
                decls: Vec::new(),
                functions: BTreeMap::new(),
                tick: Vec::new(),
            };
            while !self.is_id("algorithm") {
                if self.is_id("protected") {
                    self.at += 1;
                } else if self.is_id("type") {
                    self.at += 1;
                    let t = self.id()?;
                    self.sym("=")?;
                    self.kw("enumeration")?;
                    self.sym("(")?;
                    let mut lits = vec![self.id()?];
                    while self.is_sym(",") {
                        self.at += 1;
                        lits.push(self.id()?);
                    }
                    self.sym(")")?;
                    self.string();
                    self.sym(";")?;
                    m.types.insert(t, lits);
                } else if self.is_id("parameter") {
                    self.at += 1;
                    self.kw("Real")?;
                    let n = self.id()?;
                    self.sym("=")?;
                    if self.peek() != Some(&Tok::Real) {
                        return self.err("a Real literal");
                    }
                    self.at += 1;
                    self.string();
                    self.sym(";")?;
                    m.params.push(n);
                } else if self.is_id("function") {
                    self.at += 1;
                    let (n, f) = self.function()?;
                    m.functions.insert(n, f);
                } else {
                    m.decls.push(self.decl()?);
                }
            }
            self.kw("algorithm")?;
            self.kw("when")?;
            self.kw("sample")?;
            self.sym("(")?;
            if self.peek() != Some(&Tok::Int(0)) {
                return self.err("0");
            }
            self.at += 1;
            self.sym(",")?;
            let period = self.id()?;
            if !m.params.contains(&period) {
                return Err(format!("sample period `{period}` is not a parameter"));
            }
            self.sym(")")?;
            self.kw("then")?;
            m.tick = self.stmts()?;
            self.kw("end")?;
            self.kw("when")?;
            self.sym(";")?;
            self.kw("annotation")?;
            self.sym("(")?;
            let mut depth = 1;
            while depth > 0 {
                match self.peek() {
                    Some(Tok::Sym("(")) => depth += 1,
                    Some(Tok::Sym(")")) => depth -= 1,
                    None => return self.err(")"),
                    _ => {}
                }
                self.at += 1;
            }
            self.sym(";")?;
            self.kw("end")?;
            let end = self.id()?;
            if end != m.name {
                return Err(format!("`end {end};` closes model `{}`", m.name));
            }
            self.sym(";")?;
            if self.peek().is_some() {
                return self.err("end of file");
            }
            Ok(m)
        }

        fn decl(&mut self) -> R<Decl> {
            let prefix = if self.is_id("input") || self.is_id("output") {
                let p = self.id_any();
                Some(p)
            } else {
                None
            };
            let ty = self.id_any();
            let name = self.id()?;
            let size = if self.is_sym("[") {
                self.at += 1;
                let n = match self.peek() {
                    Some(Tok::Int(n)) => *n as usize,
                    _ => return self.err("array size"),
                };
                self.at += 1;
                self.sym("]")?;
                Some(n)
            } else {
                None
            };
            let mut mods = Vec::new();
            if self.is_sym("(") {
                self.at += 1;
                loop {
                    let each = self.is_id("each");
                    if each {
                        self.at += 1;
                    }
                    if each != size.is_some() {
                        return self.err("`each` exactly on arrays");
                    }
                    let k = self.id()?;
                    self.sym("=")?;
                    mods.push((k, self.expr()?));
                    if self.is_sym(",") {
                        self.at += 1;
                    } else {
                        break;
                    }
                }
                self.sym(")")?;
            }
            let binding = if self.is_sym("=") {
                self.at += 1;
                Some(self.expr()?)
            } else {
                None
            };
            let desc = self.string();
            self.sym(";")?;
            Ok(Decl {
                prefix,
                ty,
                name,
                size,
                mods,
                binding,
                desc,
            })
        }

        fn id_any(&mut self) -> String {
            let s = match self.peek() {
                Some(Tok::Id(x)) => x.clone(),
                _ => String::new(),
            };
            self.at += 1;
            s
        }

        fn function(&mut self) -> R<(String, Function)> {
            let name = self.id()?;
            self.string();
            let mut f = Function {
                inputs: Vec::new(),
                output: (String::new(), String::new()),
                locals: Vec::new(),
                body: Vec::new(),
            };
            let mut protected = false;
            while !self.is_id("algorithm") {
                if self.is_id("protected") {
                    self.at += 1;
                    protected = true;
                    continue;
                }
                let d = self.decl()?;
                let v = (d.ty.clone(), d.name.clone());
                match (d.prefix.as_deref(), protected) {
                    (Some("input"), false) => f.inputs.push(v),
                    (Some("output"), false) if f.output.1.is_empty() => f.output = v,
                    (None, true) => f.locals.push(v),
                    _ => {
                        return Err(format!(
                            "function {name}: unexpected declaration {}",
                            d.name
                        ))
                    }
                }
            }
            self.kw("algorithm")?;
            f.body = self.stmts()?;
            self.kw("end")?;
            let end = self.id()?;
            if end != name {
                return Err(format!("`end {end};` closes function `{name}`"));
            }
            self.sym(";")?;
            Ok((name, f))
        }

        fn stmts(&mut self) -> R<Vec<Stmt>> {
            let mut out = Vec::new();
            while !(self.is_id("end") || self.is_id("else") || self.is_id("elseif")) {
                out.push(self.stmt()?);
            }
            Ok(out)
        }

        fn stmt(&mut self) -> R<Stmt> {
            if self.is_id("if") {
                self.at += 1;
                let mut arms = Vec::new();
                let c = self.expr()?;
                self.kw("then")?;
                arms.push((c, self.stmts()?));
                let mut otherwise = Vec::new();
                loop {
                    if self.is_id("elseif") {
                        self.at += 1;
                        let c = self.expr()?;
                        self.kw("then")?;
                        arms.push((c, self.stmts()?));
                    } else if self.is_id("else") {
                        self.at += 1;
                        otherwise = self.stmts()?;
                    } else {
                        break;
                    }
                }
                self.kw("end")?;
                self.kw("if")?;
                self.sym(";")?;
                return Ok(Stmt::If(arms, otherwise));
            }
            if self.is_id("while") {
                self.at += 1;
                let c = self.expr()?;
                self.kw("loop")?;
                let body = self.stmts()?;
                self.kw("end")?;
                self.kw("while")?;
                self.sym(";")?;
                return Ok(Stmt::While(c, body));
            }
            if self.is_id("for") {
                self.at += 1;
                let v = self.id()?;
                self.kw("in")?;
                let a = self.arith()?;
                self.sym(":")?;
                let b = self.arith()?;
                self.kw("loop")?;
                let body = self.stmts()?;
                self.kw("end")?;
                self.kw("for")?;
                self.sym(";")?;
                return Ok(Stmt::For(v, a, b, body));
            }
            if self.is_id("assert") {
                self.at += 1;
                self.sym("(")?;
                let c = self.expr()?;
                self.sym(",")?;
                let m = self.expr()?;
                self.sym(")")?;
                self.sym(";")?;
                return Ok(Stmt::Assert(c, m));
            }
            let name = self.id()?;
            let idx = if self.is_sym("[") {
                self.at += 1;
                let e = self.expr()?;
                self.sym("]")?;
                Some(e)
            } else {
                None
            };
            self.sym(":=")?;
            let e = self.expr()?;
            self.sym(";")?;
            Ok(Stmt::Assign(name, idx, e))
        }

        fn expr(&mut self) -> R<Expr> {
            if !self.is_id("if") {
                return self.or();
            }
            self.at += 1;
            let mut arms = Vec::new();
            let c = self.expr()?;
            self.kw("then")?;
            arms.push((c, self.expr()?));
            while self.is_id("elseif") {
                self.at += 1;
                let c = self.expr()?;
                self.kw("then")?;
                arms.push((c, self.expr()?));
            }
            self.kw("else")?;
            let e = self.expr()?;
            Ok(Expr::If(arms, Box::new(e)))
        }

        fn or(&mut self) -> R<Expr> {
            let mut a = self.and()?;
            while self.is_id("or") {
                self.at += 1;
                a = Expr::Bin("or", Box::new(a), Box::new(self.and()?));
            }
            Ok(a)
        }

        fn and(&mut self) -> R<Expr> {
            let mut a = self.not()?;
            while self.is_id("and") {
                self.at += 1;
                a = Expr::Bin("and", Box::new(a), Box::new(self.not()?));
            }
            Ok(a)
        }

        fn not(&mut self) -> R<Expr> {
            if self.is_id("not") {
                self.at += 1;
                return Ok(Expr::Not(Box::new(self.relation()?)));
            }
            self.relation()
        }

        fn relation(&mut self) -> R<Expr> {
            let a = self.arith()?;
            for op in ["==", "<>", "<=", ">=", "<", ">"] {
                if self.is_sym(op) {
                    self.at += 1;
                    let b = self.arith()?;
                    return Ok(Expr::Bin(op, Box::new(a), Box::new(b)));
                }
            }
            Ok(a)
        }

        fn arith(&mut self) -> R<Expr> {
            let neg = self.is_sym("-");
            if neg {
                self.at += 1;
            }
            let mut a = self.term()?;
            if neg {
                a = Expr::Neg(Box::new(a));
            }
            loop {
                let op = if self.is_sym("+") {
                    "+"
                } else if self.is_sym("-") {
                    "-"
                } else {
                    return Ok(a);
                };
                self.at += 1;
                a = Expr::Bin(op, Box::new(a), Box::new(self.term()?));
            }
        }

        fn term(&mut self) -> R<Expr> {
            let mut a = self.primary()?;
            while self.is_sym("*") {
                self.at += 1;
                a = Expr::Bin("*", Box::new(a), Box::new(self.primary()?));
            }
            Ok(a)
        }

        fn primary(&mut self) -> R<Expr> {
            match self.peek().cloned() {
                Some(Tok::Int(v)) => {
                    self.at += 1;
                    Ok(Expr::Int(v))
                }
                Some(Tok::Str(s)) => {
                    self.at += 1;
                    Ok(Expr::Str(s))
                }
                Some(Tok::Sym("(")) => {
                    self.at += 1;
                    let e = self.expr()?;
                    self.sym(")")?;
                    Ok(e)
                }
                Some(Tok::Id(x)) if x == "true" || x == "false" => {
                    self.at += 1;
                    Ok(Expr::Bool(x == "true"))
                }
                Some(Tok::Id(x)) if x == "Integer" || x == "String" => {
                    self.at += 1;
                    self.call(x)
                }
                Some(Tok::Id(_)) => {
                    let n = self.id()?;
                    if self.is_sym(".") {
                        self.at += 1;
                        let l = self.id()?;
                        Ok(Expr::Lit(n, l))
                    } else if self.is_sym("[") {
                        self.at += 1;
                        let e = self.expr()?;
                        self.sym("]")?;
                        Ok(Expr::Index(n, Box::new(e)))
                    } else if self.is_sym("(") {
                        self.call(n)
                    } else {
                        Ok(Expr::Name(n))
                    }
                }
                _ => self.err("an expression"),
            }
        }

        fn call(&mut self, f: String) -> R<Expr> {
            self.sym("(")?;
            let mut args = vec![self.expr()?];
            while self.is_sym(",") {
                self.at += 1;
                args.push(self.expr()?);
            }
            self.sym(")")?;
            Ok(Expr::Call(f, args))
        }
    }

    /// Modelica keywords: never a name.
    const KEYWORDS: &str = "\
        algorithm and annotation block break class connect connector constant constrainedby \
        der discrete each else elseif elsewhen encapsulated end enumeration equation \
        expandable extends external false final flow for function if import impure in \
        initial inner input loop model not operator or outer output package parameter \
        partial protected public pure record redeclare replaceable return stream then true \
        type when while within";

    const BUILTINS: &[&str] = &[
        "min", "max", "abs", "div", "rem", "mod", "Integer", "String",
    ];

    /// Parse a generated model.
    pub fn parse(text: &str) -> Result<Model, String> {
        let toks = lex(text)?;
        P { toks, at: 0 }.model()
    }

    /// Every name used is declared (as a variable, function, enumeration literal or built-in),
    /// every declared type exists, and no name is declared twice.
    pub fn check_names(m: &Model) -> Result<(), String> {
        let mut seen = std::collections::BTreeSet::new();
        for n in m
            .decls
            .iter()
            .map(|d| &d.name)
            .chain(m.types.keys())
            .chain(m.functions.keys())
            .chain(m.params.iter())
        {
            if !seen.insert(n.clone()) {
                return Err(format!("`{n}` declared twice"));
            }
        }
        for d in &m.decls {
            if !matches!(d.ty.as_str(), "Integer" | "Boolean") && !m.types.contains_key(&d.ty) {
                return Err(format!("`{}` has unknown type `{}`", d.name, d.ty));
            }
        }
        let globals: Vec<&String> = m.decls.iter().map(|d| &d.name).collect();
        let check = |stmts: &[Stmt], locals: &[&String]| -> Result<(), String> {
            let known = |n: &String| globals.contains(&n) || locals.contains(&n);
            let (mut used, mut targets) = (Vec::new(), Vec::new());
            walk_stmts(stmts, &mut |e| used.push(e.clone()), &mut |t| {
                targets.push(t.clone())
            });
            for t in &targets {
                if !known(t) {
                    return Err(format!("assignment to undeclared `{t}`"));
                }
            }
            for e in &used {
                let bad = match e {
                    Expr::Name(n) | Expr::Index(n, _) => (!known(n)).then(|| n.clone()),
                    Expr::Lit(t, l) => m
                        .types
                        .get(t)
                        .is_none_or(|ls| !ls.contains(l))
                        .then(|| format!("{t}.{l}")),
                    Expr::Call(f, _) => (!m.functions.contains_key(f)
                        && !BUILTINS.contains(&f.as_str()))
                    .then(|| f.clone()),
                    _ => None,
                };
                if let Some(b) = bad {
                    return Err(format!("undeclared `{b}`"));
                }
            }
            Ok(())
        };
        check(&m.tick, &[])?;
        for (n, f) in &m.functions {
            let locals: Vec<&String> = f
                .inputs
                .iter()
                .chain(std::iter::once(&f.output))
                .chain(f.locals.iter())
                .map(|(_, n)| n)
                .collect();
            check(&f.body, &locals).map_err(|e| format!("function {n}: {e}"))?;
        }
        Ok(())
    }

    fn walk_stmts(stmts: &[Stmt], f: &mut dyn FnMut(&Expr), t: &mut dyn FnMut(&String)) {
        for s in stmts {
            match s {
                Stmt::Assign(n, i, e) => {
                    t(n);
                    if let Some(i) = i {
                        walk_expr(i, f);
                    }
                    walk_expr(e, f);
                }
                Stmt::If(arms, o) => {
                    for (c, b) in arms {
                        walk_expr(c, f);
                        walk_stmts(b, f, t);
                    }
                    walk_stmts(o, f, t);
                }
                Stmt::Assert(c, m) => {
                    walk_expr(c, f);
                    walk_expr(m, f);
                }
                Stmt::While(c, b) => {
                    walk_expr(c, f);
                    walk_stmts(b, f, t);
                }
                Stmt::For(_, a, b, body) => {
                    walk_expr(a, f);
                    walk_expr(b, f);
                    walk_stmts(body, f, t);
                }
            }
        }
    }

    fn walk_expr(e: &Expr, f: &mut dyn FnMut(&Expr)) {
        f(e);
        match e {
            Expr::Index(_, i) | Expr::Neg(i) | Expr::Not(i) => walk_expr(i, f),
            Expr::Call(_, args) => args.iter().for_each(|a| walk_expr(a, f)),
            Expr::Bin(_, a, b) => {
                walk_expr(a, f);
                walk_expr(b, f);
            }
            Expr::If(arms, e) => {
                for (c, v) in arms {
                    walk_expr(c, f);
                    walk_expr(v, f);
                }
                walk_expr(e, f);
            }
            _ => {}
        }
    }

    /// A value.
    #[derive(Clone, Debug, PartialEq)]
    pub enum Val {
        Int(i64),
        Bool(bool),
        Enum(String, usize),
        Str(String),
    }

    /// Why a tick stopped.
    #[derive(Clone, Debug)]
    pub enum Fail {
        /// An `assert` failed, with its message.
        Assert(String),
        /// The model did something a Modelica tool would reject.
        Error(String),
    }

    fn error<T>(msg: String) -> Result<T, Fail> {
        Err(Fail::Error(msg))
    }

    /// The model's variables and a way to run one tick.
    pub struct Machine<'m> {
        m: &'m Model,
        vars: BTreeMap<String, Vec<Val>>,
    }

    impl<'m> Machine<'m> {
        /// Every variable at its `start` value or binding.
        pub fn new(m: &'m Model) -> Result<Machine<'m>, Fail> {
            let mut mm = Machine {
                m,
                vars: BTreeMap::new(),
            };
            for d in &m.decls {
                let init = d
                    .mods
                    .iter()
                    .find(|(k, _)| k == "start")
                    .map(|(_, e)| e)
                    .or(d.binding.as_ref());
                let Some(init) = init else {
                    return error(format!("`{}` has no start value", d.name));
                };
                let v = mm.eval(init, &mut None)?;
                mm.check_type(&d.ty, &v, &d.name)?;
                let fixed = d.mods.iter().any(|(k, _)| k == "fixed");
                if d.prefix.as_deref() != Some("input") && d.binding.is_none() && !fixed {
                    return error(format!("`{}` has no fixed start value", d.name));
                }
                mm.vars.insert(d.name.clone(), vec![v; d.size.unwrap_or(1)]);
            }
            Ok(mm)
        }

        fn check_type(&self, ty: &str, v: &Val, what: &str) -> Result<(), Fail> {
            let ok = match (ty, v) {
                ("Integer", Val::Int(_)) | ("Boolean", Val::Bool(_)) => true,
                (t, Val::Enum(e, _)) => t == e,
                _ => false,
            };
            if ok {
                Ok(())
            } else {
                error(format!("{what}: a {ty} cannot hold {v:?}"))
            }
        }

        /// Set an input from its IR value.
        pub fn set_input(&mut self, name: &str, v: i64) -> Result<(), Fail> {
            let Some(d) = self.m.decl(name) else {
                return error(format!("no input `{name}`"));
            };
            if d.prefix.as_deref() != Some("input") {
                return error(format!("`{name}` is not an input"));
            }
            let val = match d.ty.as_str() {
                "Integer" => Val::Int(v),
                "Boolean" => Val::Bool(v != 0),
                t => Val::Enum(t.to_string(), v as usize),
            };
            self.vars.insert(name.to_string(), vec![val]);
            Ok(())
        }

        /// A scalar variable or array element (`a[3]`) as an IR value.
        pub fn value(&self, name: &str) -> Result<i64, Fail> {
            let (n, i) = match name.split_once('[') {
                Some((n, i)) => (n, i.trim_end_matches(']').parse::<usize>().unwrap_or(0)),
                None => (name, 1),
            };
            match self.vars.get(n).and_then(|v| v.get(i.wrapping_sub(1))) {
                Some(Val::Int(x)) => Ok(*x),
                Some(Val::Bool(b)) => Ok(i64::from(*b)),
                Some(Val::Enum(_, k)) => Ok(*k as i64),
                other => error(format!("`{name}` is {other:?}")),
            }
        }

        /// Run the `when` clause once (one tick).
        pub fn tick(&mut self) -> Result<(), Fail> {
            let body = &self.m.tick;
            self.exec(body, &mut None)
        }

        fn exec(&mut self, stmts: &[Stmt], fr: &mut Frame) -> Result<(), Fail> {
            for s in stmts {
                match s {
                    Stmt::Assign(n, idx, e) => {
                        let v = self.eval(e, fr)?;
                        let i = match idx {
                            Some(i) => match self.eval(i, fr)? {
                                Val::Int(i) => Some(i),
                                x => return error(format!("index {x:?}")),
                            },
                            None => None,
                        };
                        self.assign(n, i, v, fr)?;
                    }
                    Stmt::If(arms, otherwise) => {
                        let mut done = false;
                        for (c, body) in arms {
                            if self.cond(c, fr)? {
                                self.exec(body, fr)?;
                                done = true;
                                break;
                            }
                        }
                        if !done {
                            self.exec(otherwise, fr)?;
                        }
                    }
                    Stmt::Assert(c, msg) => {
                        if !self.cond(c, fr)? {
                            return match self.eval(msg, fr)? {
                                Val::Str(s) => Err(Fail::Assert(s)),
                                x => error(format!("assert message {x:?}")),
                            };
                        }
                    }
                    Stmt::While(c, body) => {
                        let mut n = 0;
                        while self.cond(c, fr)? {
                            self.exec(body, fr)?;
                            n += 1;
                            if n > 10_000 {
                                return error("endless while loop".into());
                            }
                        }
                    }
                    Stmt::For(v, a, b, body) => {
                        let (Val::Int(a), Val::Int(b)) = (self.eval(a, fr)?, self.eval(b, fr)?)
                        else {
                            return error("for range".into());
                        };
                        for k in a..=b {
                            if let Some(f) = fr.as_mut() {
                                f.insert(v.clone(), (String::from("Integer"), Some(Val::Int(k))));
                            }
                            self.exec(body, fr)?;
                        }
                    }
                }
            }
            Ok(())
        }

        fn assign(
            &mut self,
            n: &str,
            idx: Option<i64>,
            v: Val,
            fr: &mut Frame,
        ) -> Result<(), Fail> {
            if let Some(f) = fr.as_mut() {
                if let Some((ty, slot)) = f.get_mut(n) {
                    self.check_type(ty, &v, n)?;
                    *slot = Some(v);
                    return Ok(());
                }
            }
            let Some(d) = self.m.decl(n) else {
                return error(format!("assignment to undeclared `{n}`"));
            };
            if d.prefix.as_deref() == Some("input") || d.binding.is_some() {
                return error(format!("assignment to `{n}`, which is not a variable"));
            }
            self.check_type(&d.ty, &v, n)?;
            if let Val::Int(x) = v {
                for (k, e) in &d.mods {
                    let bound = match self.eval(e, &mut None)? {
                        Val::Int(b) => b,
                        _ => continue,
                    };
                    if (k == "min" && x < bound) || (k == "max" && x > bound) {
                        return error(format!("`{n}` = {x} violates {k} = {bound}"));
                    }
                }
            }
            let i = match (idx, d.size) {
                (None, None) => 0,
                (Some(i), Some(s)) if i >= 1 && (i as usize) <= s => i as usize - 1,
                _ => return error(format!("bad index {idx:?} of `{n}`")),
            };
            if let Some(cell) = self.vars.get_mut(n).and_then(|a| a.get_mut(i)) {
                *cell = v;
            }
            Ok(())
        }

        fn cond(&mut self, e: &Expr, fr: &mut Frame) -> Result<bool, Fail> {
            match self.eval(e, fr)? {
                Val::Bool(b) => Ok(b),
                x => error(format!("condition {x:?} is not Boolean")),
            }
        }

        fn int(&mut self, e: &Expr, fr: &mut Frame) -> Result<i64, Fail> {
            match self.eval(e, fr)? {
                Val::Int(x) => Ok(x),
                x => error(format!("{x:?} is not an Integer")),
            }
        }

        fn eval(&mut self, e: &Expr, fr: &mut Frame) -> Result<Val, Fail> {
            Ok(match e {
                Expr::Int(v) => Val::Int(*v),
                Expr::Bool(b) => Val::Bool(*b),
                Expr::Str(s) => Val::Str(s.clone()),
                Expr::Lit(t, l) => match self
                    .m
                    .types
                    .get(t)
                    .and_then(|ls| ls.iter().position(|x| x == l))
                {
                    Some(k) => Val::Enum(t.clone(), k),
                    None => return error(format!("no literal {t}.{l}")),
                },
                Expr::Name(n) => {
                    if let Some(f) = fr.as_ref() {
                        if let Some((_, v)) = f.get(n) {
                            return v.clone().ok_or_else(|| {
                                Fail::Error(format!("`{n}` read before assignment"))
                            });
                        }
                    }
                    match self.vars.get(n) {
                        Some(a)
                            if a.len() == 1 && self.m.decl(n).is_some_and(|d| d.size.is_none()) =>
                        {
                            a[0].clone()
                        }
                        _ => return error(format!("no scalar `{n}`")),
                    }
                }
                Expr::Index(n, i) => {
                    let i = self.int(i, fr)?;
                    match self.vars.get(n).and_then(|a| a.get((i - 1) as usize)) {
                        Some(v) if i >= 1 => v.clone(),
                        _ => return error(format!("bad index {n}[{i}]")),
                    }
                }
                Expr::Neg(a) => Val::Int(
                    self.int(a, fr)?
                        .checked_neg()
                        .ok_or(Fail::Error("overflow".into()))?,
                ),
                Expr::Not(a) => Val::Bool(!self.cond(a, fr)?),
                Expr::If(arms, otherwise) => {
                    let mut ty = None;
                    let mut out = None;
                    for (c, v) in arms {
                        if out.is_none() && self.cond(c, fr)? {
                            out = Some(self.eval(v, fr)?);
                        }
                        ty = Some(self.type_of(v, fr)?);
                    }
                    let t2 = self.type_of(otherwise, fr)?;
                    if ty.as_ref().is_some_and(|t| *t != t2) {
                        return error(format!("if-expression branches of types {ty:?} and {t2}"));
                    }
                    match out {
                        Some(v) => v,
                        None => self.eval(otherwise, fr)?,
                    }
                }
                Expr::Bin(op, a, b) => {
                    // Both sides are evaluated: a Modelica tool need not short-circuit.
                    let (x, y) = (self.eval(a, fr)?, self.eval(b, fr)?);
                    binary(op, x, y)?
                }
                Expr::Call(f, args) => {
                    let mut vals = Vec::new();
                    for a in args {
                        vals.push(self.eval(a, fr)?);
                    }
                    self.call(f, vals)?
                }
            })
        }

        /// The type of an expression without evaluating it (for if-expression branches).
        fn type_of(&mut self, e: &Expr, fr: &mut Frame) -> Result<String, Fail> {
            Ok(match e {
                Expr::Int(_) | Expr::Neg(_) => "Integer".into(),
                Expr::Bool(_) | Expr::Not(_) => "Boolean".into(),
                Expr::Str(_) => "String".into(),
                Expr::Lit(t, _) => t.clone(),
                Expr::Name(n) | Expr::Index(n, _) => match fr.as_ref().and_then(|f| f.get(n)) {
                    Some((t, _)) => t.clone(),
                    None => self.m.decl(n).map_or(String::new(), |d| d.ty.clone()),
                },
                Expr::Bin(op, a, _) => match *op {
                    "+" => self.type_of(a, fr)?,
                    "-" | "*" => "Integer".into(),
                    _ => "Boolean".into(),
                },
                Expr::If(_, o) => self.type_of(o, fr)?,
                Expr::Call(f, _) => match self.m.functions.get(f) {
                    Some(func) => func.output.0.clone(),
                    None if f == "String" => "String".into(),
                    None => "Integer".into(),
                },
            })
        }

        fn call(&mut self, f: &str, args: Vec<Val>) -> Result<Val, Fail> {
            let ints = |args: &[Val]| -> Result<Vec<i64>, Fail> {
                args.iter()
                    .map(|a| match a {
                        Val::Int(x) => Ok(*x),
                        x => error(format!("{f}: argument {x:?}")),
                    })
                    .collect()
            };
            let two = |args: &[Val]| -> Result<(i64, i64), Fail> {
                match ints(args)?.as_slice() {
                    [a, b] => Ok((*a, *b)),
                    _ => error(format!("{f}: two arguments")),
                }
            };
            Ok(match f {
                "min" => {
                    let (a, b) = two(&args)?;
                    Val::Int(a.min(b))
                }
                "max" => {
                    let (a, b) = two(&args)?;
                    Val::Int(a.max(b))
                }
                "abs" => match ints(&args)?.as_slice() {
                    [a] => Val::Int(a.checked_abs().ok_or(Fail::Error("overflow".into()))?),
                    _ => return error("abs".into()),
                },
                "div" | "rem" | "mod" => {
                    let (a, b) = two(&args)?;
                    if b == 0 {
                        return error(format!("{f}({a}, 0)"));
                    }
                    Val::Int(match f {
                        "div" => a / b,
                        "rem" => a % b,
                        _ => a.rem_euclid(b),
                    })
                }
                "Integer" => match args.as_slice() {
                    [Val::Enum(_, k)] => Val::Int(*k as i64 + 1),
                    _ => return error(format!("Integer({args:?})")),
                },
                "String" => match args.as_slice() {
                    [Val::Int(x)] => Val::Str(x.to_string()),
                    _ => return error(format!("String({args:?})")),
                },
                _ => {
                    let Some(func) = self.m.functions.get(f) else {
                        return error(format!("no function `{f}`"));
                    };
                    if func.inputs.len() != args.len() {
                        return error(format!("{f}: {} arguments", args.len()));
                    }
                    let mut frame = BTreeMap::new();
                    for ((ty, n), v) in func.inputs.iter().zip(args) {
                        self.check_type(ty, &v, n)?;
                        frame.insert(n.clone(), (ty.clone(), Some(v)));
                    }
                    for (ty, n) in func.locals.iter().chain(std::iter::once(&func.output)) {
                        frame.insert(n.clone(), (ty.clone(), None));
                    }
                    let mut fr = Some(frame);
                    let body = func.body.clone();
                    self.exec(&body, &mut fr)?;
                    let out = fr
                        .and_then(|mut f| f.remove(&func.output.1))
                        .and_then(|(_, v)| v);
                    out.ok_or_else(|| Fail::Error(format!("{f}: output not assigned")))?
                }
            })
        }
    }

    /// Locals of a function call: name -> (type, value once assigned).
    type Frame = Option<BTreeMap<String, (String, Option<Val>)>>;

    fn binary(op: &str, x: Val, y: Val) -> Result<Val, Fail> {
        let overflow = || Fail::Error("overflow".into());
        Ok(match (op, x, y) {
            ("+", Val::Int(a), Val::Int(b)) => Val::Int(a.checked_add(b).ok_or_else(overflow)?),
            ("+", Val::Str(a), Val::Str(b)) => Val::Str(a + &b),
            ("-", Val::Int(a), Val::Int(b)) => Val::Int(a.checked_sub(b).ok_or_else(overflow)?),
            ("*", Val::Int(a), Val::Int(b)) => Val::Int(a.checked_mul(b).ok_or_else(overflow)?),
            ("and", Val::Bool(a), Val::Bool(b)) => Val::Bool(a && b),
            ("or", Val::Bool(a), Val::Bool(b)) => Val::Bool(a || b),
            (op, x, y) => {
                let ord = match (&x, &y) {
                    (Val::Int(a), Val::Int(b)) => a.cmp(b),
                    (Val::Bool(a), Val::Bool(b)) if op == "==" || op == "<>" => a.cmp(b),
                    (Val::Enum(s, a), Val::Enum(t, b)) if s == t => a.cmp(b),
                    _ => return error(format!("`{op}` on {x:?} and {y:?}")),
                };
                use std::cmp::Ordering::*;
                Val::Bool(match op {
                    "==" => ord == Equal,
                    "<>" => ord != Equal,
                    "<" => ord == Less,
                    "<=" => ord != Greater,
                    ">" => ord == Greater,
                    ">=" => ord != Less,
                    _ => return error(format!("operator `{op}`")),
                })
            }
        })
    }
}
