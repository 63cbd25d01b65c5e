//! The short runs of the fuzzers that are part of the test suite (the long runs are
//! `scripts/fuzz.sh`): a bounded count of mutated inputs per target with no failure, the
//! runner's detection of every kind of failure on its self-test target, and a few random
//! models through the differential fuzzer.

use statecheck_fuzz::runner::{self, Config};
use statecheck_fuzz::targets::{self, Target};
use std::path::{Path, PathBuf};
use std::time::Duration;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

#[test]
fn every_target_survives_a_short_run() {
    for t in targets::ALL {
        let s = runner::run_in_process(t, &root(), 7, 300);
        assert_eq!(s.executions, 300);
        assert!(s.failures.is_empty(), "{}: {:?}", t.name(), s.failures);
    }
}

#[test]
fn the_seeds_are_loaded() {
    // At least ten seeds per target (the repository's models, scenarios, AIGER exports).
    for t in targets::ALL {
        let (_, seeds) = statecheck_fuzz::corpus::load(t, &root());
        assert!(seeds.len() >= 10, "{}: {} seeds", t.name(), seeds.len());
    }
    let (ctx, seeds) = statecheck_fuzz::corpus::load(Target::Scenario, &root());
    // The 26 scenarios of examples/ and tests/ when this test was written (27 files but
    // tests/imports/app/run.scn, whose model imports files: the corpus does not resolve
    // imports); more as scenarios are added.
    assert!(seeds.len() >= 26, "{} scenario seeds", seeds.len());
    // Every seed scenario reads against the model it was paired with.
    for s in &seeds {
        let text = String::from_utf8_lossy(&s.bytes);
        assert!(statecheck_sim::scenario::parse(&text, &ctx.programs[s.ctx]).is_ok());
    }
}

#[test]
fn the_runner_catches_panics_aborts_overflows_and_timeouts() {
    // The self-test inputs cycle through: ok, panic, abort, hang, deep (a stack overflow),
    // broken (an `Err`). Twelve inputs over two workers: each kind twice.
    let out = std::env::temp_dir().join(format!("statecheck-fuzz-selftest-{}", std::process::id()));
    let cfg = Config {
        target: Target::SelfTest,
        seed: 1,
        executions: 12,
        duration: None,
        jobs: 2,
        timeout: Duration::from_millis(700),
        out: out.clone(),
        root: root(),
        exe: PathBuf::from(env!("CARGO_BIN_EXE_statecheck-fuzz")),
    };
    let s = runner::run(&cfg);
    assert_eq!(s.executions, 12);
    assert_eq!(s.panics, 2);
    assert_eq!(
        s.aborts, 4,
        "two aborts and two stack overflows: {:?}",
        s.failures
    );
    assert_eq!(s.timeouts, 2);
    assert_eq!(s.violations, 2);
    let mut blamed: Vec<u64> = s.failures.iter().map(|f| f.0).collect();
    blamed.sort();
    assert_eq!(blamed, vec![1, 2, 3, 4, 5, 7, 8, 9, 10, 11]);
    // Each failing input is saved with its rebuild command.
    let saved = std::fs::read_dir(out.join("crashes"))
        .map(|d| d.count())
        .unwrap_or(0)
        + std::fs::read_dir(out.join("timeouts"))
            .map(|d| d.count())
            .unwrap_or(0);
    assert_eq!(saved, 20);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn random_models_agree_everywhere() {
    // Eight random models: verdicts, replays, C traces (and SPIN when installed).
    let spin = statecheck_fuzz::diff::spin_available();
    let dir = statecheck_fuzz::diff::temp_dir("test");
    let r = statecheck_fuzz::diff::batch(11, 0, 8, false, spin, &dir);
    assert!(r.failures.is_empty(), "{}", r.failures.join("\n----\n"));
    assert!(
        r.compile_failures.is_empty(),
        "{}",
        r.compile_failures.join("\n----\n")
    );
    assert_eq!(r.models, 8);
    assert!(r.c_models + r.rejected == 8, "{r:?}");
}

#[test]
fn generated_models_with_parameters_and_time_units_are_accepted() {
    // The generator's newer constructs: a chart parameter fixed per instance and durations in
    // milliseconds under `tick 100 ms;`. Every generated model is accepted by the checker
    // (only E0104, a constant out of range, may reject one), and both constructs occur (each
    // is drawn with chance 1/4, so 200 models without one has probability (3/4)^200).
    let (mut params, mut times, mut checked) = (0, 0, 0);
    for seed in 0..200u64 {
        let text = statecheck_fuzz::gen::Gen::new(seed).model_with(true);
        params += usize::from(text.contains("chart C(k: int[0..3] = 1)"));
        times += usize::from(text.starts_with("tick 100 ms;"));
        match statecheck_fuzz::diff::lower(&text) {
            Ok(_) => checked += 1,
            Err(e) => assert!(e.contains("E0104"), "{e}\n{text}"),
        }
    }
    assert!(
        params > 0 && times > 0 && checked > 100,
        "{params} {times} {checked}"
    );
}

#[test]
fn generated_components_plants_and_interleaved_systems_are_accepted() {
    // The constructs lowered before the IR: a composite component (drawn with chance 1/5),
    // a hybrid plant with a continuous variable (3/20) and an interleaved system (3/20).
    // Each occurs in 300 models (missing one has probability at most (17/20)^300), and every
    // model with one is accepted by the checker (only E0104, a constant out of range, may
    // reject one).
    let (mut comps, mut plants, mut inter, mut checked) = (0, 0, 0, 0);
    for seed in 0..300u64 {
        let text = statecheck_fuzz::gen::Gen::new(seed).model_with(true);
        let c = text.contains("component K(");
        let h = text.contains("continuous z:");
        let i = text.contains(" interleaved {");
        comps += usize::from(c);
        plants += usize::from(h);
        inter += usize::from(i);
        if !(c || h || i) {
            continue;
        }
        match statecheck_fuzz::diff::lower(&text) {
            Ok(_) => checked += 1,
            Err(e) => assert!(e.contains("E0104"), "{e}\n{text}"),
        }
    }
    assert!(
        comps > 0 && plants > 0 && inter > 0 && checked > 40,
        "{comps} {plants} {inter} {checked}"
    );
}

#[test]
fn inputs_that_once_failed_pass_their_target() {
    // crates/fuzz/corpus/<target>/ holds inputs a target once failed on (found by
    // `scripts/fuzz.sh targets`): for `check` a panic in the parameter expansion and an E0181
    // hint that looped ~10^18 times; for `aiger` a symbol line whose first character is two
    // bytes long (a panic slicing inside it). Each now runs through its target without a
    // failure (they are also seeds of every run).
    for (target, at_least) in [(Target::Check, 2), (Target::Aiger, 1)] {
        let dir = root().join("crates/fuzz/corpus").join(target.name());
        let mut n = 0;
        for e in std::fs::read_dir(&dir).expect("corpus dir") {
            let path = e.expect("entry").path();
            let bytes = std::fs::read(&path).expect("read");
            let ctx = targets::Context::default();
            let r = runner::execute(target, &ctx, 0, &bytes);
            assert!(r.is_ok(), "{}: {r:?}", path.display());
            n += 1;
        }
        assert!(n >= at_least, "{n} saved {} inputs", target.name());
    }
}

#[test]
fn generated_arrays_loops_and_element_connections_are_accepted() {
    // Arrays of variables (`input r[2]`, `output g[2]`, drawn with chance 1/4), read and
    // written by constant index and in `for j in 0..2` loops, and between two instances
    // (chance 3/10 each) connected element by element (`[*]`) or one element to another.
    // In 300 models each construct occurs (missing the rarest, both arrays and two
    // instances with a `[*]`, has probability at most (1 - 1/4 · 3/10 · 3/5)^300 < 10^-5),
    // and the checker accepts every model with arrays (only E0104, a constant out of range,
    // may reject one).
    let (mut arrays, mut loops, mut star, mut checked) = (0, 0, 0, 0);
    for seed in 0..300u64 {
        let text = statecheck_fuzz::gen::Gen::new(seed).model_with(true);
        if !text.contains("input r[2]: int[0..3]") {
            continue;
        }
        arrays += 1;
        loops += usize::from(text.contains("for j in 0..2 {"));
        star += usize::from(text.contains("connect p.g[*] -> q.r[*];"));
        match statecheck_fuzz::diff::lower(&text) {
            Ok(_) => checked += 1,
            Err(e) => assert!(e.contains("E0104"), "{e}\n{text}"),
        }
    }
    assert!(
        arrays > 40 && loops > 0 && star > 0 && checked > 20,
        "{arrays} {loops} {star} {checked}"
    );
}

#[test]
fn a_deadlock_counterexample_replays_into_a_state_where_no_input_is_allowed() {
    // Found by the long differential run (seed 1): a `deadlock_free` counterexample was
    // reported as not replaying because the replay treated it as a runtime error. By hand:
    // tick 0 enters `A` with n = 0 whatever `go` is; each later tick with `go` true adds 1
    // to `n`; the assume forbids every input vector once n = 2. So the shortest deadlock is
    // three ticks, the last two with go = 1, and a trace ending at n = 1 is no deadlock. (`deadlock_free` is checked when the system has a temporal property.)
    let text = "chart C {\n  input go: bool = false;\n  output n: int[0..3] = 0;\n  initial A;\n  \
                state A { on [go] / { n += 1; } ; }\n}\n\
                system S {\n  instance c: C;\n  assume c.n < 2;\n  ltl bounded: G c.n <= 3;\n}\n";
    let p = statecheck_fuzz::diff::lower(text).expect("the model is valid");
    let ex = statecheck_explicit::verify(&p, &statecheck_explicit::Options::default(), None)
        .expect("explicit");
    let r = ex
        .results
        .iter()
        .find(|r| r.name == "deadlock_free")
        .expect("deadlock_free is checked");
    assert_eq!(r.verdict, statecheck_explicit::Verdict::Violated);
    let cex = r.counterexample.clone().expect("a counterexample");
    assert_eq!(cex.len(), 3);
    assert_eq!(cex[1..], [vec![1], vec![1]]);
    let replays = |v: &[Vec<i64>]| statecheck_fuzz::diff::replays(&p, "deadlock_free", r.kind, v);
    assert!(replays(&cex));
    assert!(
        !replays(&[vec![0], vec![1], vec![0]]),
        "n = 1 allows inputs"
    );
    assert!(
        !replays(&[vec![0], vec![1], vec![1], vec![0]]),
        "the fourth tick breaks the assume"
    );
}

#[test]
fn generated_slots_at_the_top_and_inside_components_are_accepted() {
    // The slot extra is drawn with chance 1/5, and then inside a component with chance 2/5
    // (so a model has a slot inside a component with chance 2/25): in 400 models both kinds
    // occur (missing one has probability at most (23/25)^400), and every such model is
    // accepted by the checker (only E0104, a constant out of range, may reject one).
    let (mut top, mut inside, mut checked) = (0, 0, 0);
    for seed in 0..400u64 {
        let text = statecheck_fuzz::gen::Gen::new(seed).model_with(true);
        let i = text.contains("instance s: Holder;");
        let t = text.contains("instance s: Cnt;");
        top += usize::from(t);
        inside += usize::from(i);
        if !(i || t) {
            continue;
        }
        if i {
            assert!(text.contains("s.t = Ea;"), "{text}");
        }
        match statecheck_fuzz::diff::lower(&text) {
            Ok(_) => checked += 1,
            Err(e) => assert!(e.contains("E0104"), "{e}\n{text}"),
        }
    }
    assert!(
        top > 0 && inside > 0 && checked > 20,
        "{top} {inside} {checked}"
    );
}

#[test]
fn help_is_shown_and_an_unknown_option_is_refused() {
    // `diff --help` once started a default run of 1,000 models; a misspelt flag did too.
    let exe = env!("CARGO_BIN_EXE_statecheck-fuzz");
    let help = std::process::Command::new(exe)
        .args(["diff", "--help"])
        .output()
        .expect("run statecheck-fuzz");
    assert_eq!(help.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&help.stdout).contains("statecheck-fuzz diff [--models N]"));
    let bad = std::process::Command::new(exe)
        .args(["diff", "--modles", "3"])
        .output()
        .expect("run statecheck-fuzz");
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&bad.stderr).contains("unknown option `--modles`"));
}
