//! The native successor generator against the interpreter: on every system of the test and
//! example models, both backends must give the same verdicts, depths, counterexamples,
//! run-time errors, state and transition counts and dead-design items. The interpreter is the
//! reference, so any difference is a bug of the code generator or of the native path.
//!
//! Needs a C compiler (`cc`, or `$CC`), as the C code generation tests do.

use statecheck_explicit::{verify, Backend, Options, Report};
use statecheck_native::CCompiler;
use std::path::Path;
use std::sync::Arc;

/// Every `.sc` file the comparison runs on, relative to the workspace root.
const DIRS: [&str; 4] = [
    "tests/verify",
    "tests/semantics",
    "examples/linear_drive",
    "examples/synthesis",
];

/// FAM models small enough to explore (the closed loops are left to the SAT engines).
const FILES: [&str; 2] = [
    "examples/fam/bug_modulus.sc",
    "examples/fam/bug_short_timeout.sc",
];

fn sc_files() -> Vec<std::path::PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut files: Vec<_> = DIRS
        .iter()
        .flat_map(|d| std::fs::read_dir(root.join(d)).expect("dir").flatten())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "sc"))
        .chain(FILES.iter().map(|f| root.join(f)))
        .collect();
    files.sort();
    files
}

fn run(p: &statecheck_ir::Program, backend: Backend) -> Report {
    verify(
        p,
        &Options {
            threads: 2,
            depth: Some(40),
            max_states: Some(30_000),
            backend,
            compiler: Some(Arc::new(CCompiler)),
            // The native code alone: no state is also expanded by the interpreter.
            native_sample: 0,
            // Wider input spaces are compared by the benchmark and the FAM tests' runs.
            max_branching: 4096,
            ..Options::default()
        },
        None,
    )
    .expect("runs")
}

/// Everything a report says about the model (not timings, not the backend).
fn digest(r: &Report) -> String {
    let s = &r.stats;
    let mut out = format!(
        "states {} transitions {} depth {} complete {} limit {:?} dead {:?}\n",
        s.states, s.transitions, s.depth, s.complete, s.limit, s.dead
    );
    for p in &r.results {
        out.push_str(&format!(
            "{} {} {} depth {} cex {:?} error {:?}\n",
            p.kind.as_str(),
            p.name,
            p.verdict.as_str(),
            p.depth,
            p.counterexample,
            p.error
        ));
    }
    out
}

#[test]
fn native_and_interpreter_agree_on_every_model() {
    let mut compared = 0;
    for path in sc_files() {
        let text = std::fs::read_to_string(&path).expect("read");
        // Follow imports (examples/fam's models import lib/).
        let program = statecheck_model::imports::load_with(&path.to_string_lossy(), text, |k| {
            std::fs::read_to_string(k).ok()
        });
        let (model, diags) = statecheck_model::check(&program.file);
        if program.diags.iter().chain(&diags).any(|d| d.is_error()) {
            continue;
        }
        for sys in &model.systems {
            let Ok(p) = statecheck_ir::lower(&model, sys) else {
                continue;
            };
            let vm = run(&p, Backend::Interpreter);
            if vm
                .stats
                .limit
                .as_ref()
                .is_some_and(|l| l.name() == "branching")
            {
                continue;
            }
            let native = run(&p, Backend::Native);
            let at = format!("{} system {}", path.display(), sys.name);
            assert_eq!(
                native.stats.backend, "native",
                "{at}: {:?}",
                native.stats.native_note
            );
            assert_eq!(digest(&vm), digest(&native), "{at}");
            compared += 1;
        }
    }
    // tests/verify alone has five models with a system each; the examples add more.
    assert!(compared >= 10, "only {compared} systems compared");
}

/// `N` modulo counters `int[0..M]`, at most one incremented per tick: (M+1)^N states.
fn counters(n: usize, m: usize) -> statecheck_ir::Program {
    let pairs: Vec<String> = (0..n)
        .flat_map(|i| (i + 1..n).map(move |j| format!("!(k[{i}].inc && k[{j}].inc)")))
        .collect();
    let text = format!(
        "chart Counter {{\n  input event inc;\n  output c: int[0..{m}] = 0;\n  initial Run;\n  state Run {{\n    on inc [c < {m}] / {{ c += 1; }};\n    on inc / {{ c = 0; }};\n  }}\n}}\nsystem Bench {{\n  instance k[{n}]: Counter;\n  assume {};\n  invariant bounded: k[0].c <= {m};\n  reachable all_top: k[0].c == {m} && k[{}].c == {m};\n}}\n",
        pairs.join(" && "),
        n - 1
    );
    let (file, _) = statecheck_syntax::parse(&text);
    let (model, _) = statecheck_model::check(&file);
    let sys = model.system("Bench").expect("system");
    statecheck_ir::lower(&model, sys).expect("lowers")
}

#[test]
fn auto_switches_to_native_code_without_changing_the_answer() {
    // 32^4 = 1,048,576 states plus the initial one: long enough (well over the 0.3 s after
    // which `auto` starts the compiler) that the search switches backends midway.
    let p = counters(4, 31);
    let vm = run_unbounded(&p, Backend::Interpreter);
    let auto = run_unbounded(&p, Backend::Auto);
    assert_eq!(vm.stats.states, 1_048_577);
    // `all_top` needs 31 increments of each of the two counters, one per tick, after tick 0
    // (which starts the charts): a shortest witness has 63 ticks.
    assert_eq!(vm.results[1].depth, 63);
    assert_eq!(digest(&vm), digest(&auto));
    // Whether the compiler finished before the search did depends on the machine's load;
    // when it did, the answer above came partly from native code.
    eprintln!("auto ended on {}", auto.stats.backend);
}

fn run_unbounded(p: &statecheck_ir::Program, backend: Backend) -> Report {
    verify(
        p,
        &Options {
            threads: 2,
            backend,
            compiler: Some(Arc::new(CCompiler)),
            ..Options::default()
        },
        None,
    )
    .expect("runs")
}

#[test]
fn a_property_reading_inputs_is_checked_on_native_successors() {
    // `w` latches a free input (256 values) every tick, so layers hold hundreds of states and
    // most are expanded by the native code (the interpreter samples one in 64).
    let text = "chart T {\n  input event a;\n  output x: int[0..3] = 0;\n  initial S;\n  state S {\n    on a [x < 3] / { x += 1; };\n  }\n}\nchart W {\n  input v: int[0..255];\n  output y: int[0..255] = 0;\n  initial S;\n  state S {\n    on [true] / { y = v; };\n  }\n}\nsystem Sys {\n  instance t: T;\n  instance w: W;\n  invariant quiet_at_top: !(t.a && t.x == 3);\n}\n";
    let (file, _) = statecheck_syntax::parse(text);
    let (model, diags) = statecheck_model::check(&file);
    assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
    let p = statecheck_ir::lower(&model, model.system("Sys").expect("system")).expect("lowers");
    let vm = run_unbounded(&p, Backend::Interpreter);
    // Every state by the native code alone (no sampled comparison with the interpreter).
    let native = verify(
        &p,
        &Options {
            backend: Backend::Native,
            compiler: Some(Arc::new(CCompiler)),
            native_sample: 0,
            ..Options::default()
        },
        None,
    )
    .expect("runs");
    assert_eq!(
        native.stats.backend, "native",
        "{:?}",
        native.stats.native_note
    );
    // Tick 0 starts the charts; `a` at ticks 1, 2 and 3 counts x up to 3, and `a` is still
    // present at tick 3: the violation is at tick 3, a counterexample of 4 ticks.
    for r in [&vm, &native] {
        assert_eq!(r.results[0].name, "quiet_at_top");
        assert_eq!(r.results[0].depth, 4);
    }
    assert_eq!(digest(&vm), digest(&native));
}
