//! The differential fuzzer: random well-typed models ([`crate::gen`]) through every consumer
//! of the IR, which must agree.
//!
//! For each model: no panic anywhere; the explicit engine's definitive verdicts equal BMC's,
//! k-induction's, IC3's and CEGAR's (same verdict, counterexamples of the same shortest length); every
//! counterexample of every engine replays in the interpreter to the violation it claims; the
//! generated Promela is accepted by `spin -a` (when SPIN is installed). For each batch of
//! models: one C program (gcc `-std=c99 -Wall -Wextra -Werror`) and, for one batch in
//! `rust_every`, one Rust program replay random inputs and print every slot after every tick,
//! which must equal the interpreter's trace line for line.

use crate::gen::Gen;
use statecheck_codegen::common::{slot_fields, Source};
use statecheck_explicit::{Options, PropKind, Verdict};
use statecheck_ir::{Machine, Program, PropertyKind, RuntimeErrorKind};
use statecheck_symbolic::check::{decide, problems, Engine, Reductions};
use statecheck_symbolic::engine::Limits;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// Runs per model in the code comparison.
const RUNS: usize = 4;
/// Ticks per run.
const TICKS: usize = 16;
/// States above which the explicit engine's answer is not used as the reference.
const MAX_STATES: u64 = 20_000;
/// Input vectors per tick (after the input-only assumes) above which the explicit engine
/// refuses the model: every state is stepped with every vector (or one per combination of
/// the inputs a tick reads), so a system of two charts and a component array with free
/// inputs (420,000 vectors) took minutes for one model. Such models are counted as
/// `explicit skipped (too wide)`; the other oracles (no panic, replays of the SAT engines'
/// counterexamples, C/Rust traces, SPIN) still run on them.
const MAX_BRANCHING: u128 = 50_000;
/// Wall time after which the explicit reference gives up (counted with the models bounded
/// by [`MAX_STATES`]): a safety net under the two caps above.
const EXPLICIT_TIME: Duration = Duration::from_secs(10);

/// The figures of a differential run.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// Models generated.
    pub models: u64,
    /// Models the checker rejected (only `E0104`, a constant out of range, is expected).
    pub rejected: u64,
    /// Checked models whose explicit exploration stopped at its bound of states (or of
    /// time) without deciding every property (their undecided verdicts are not compared).
    pub incomplete: u64,
    /// Checked models the explicit reference refused as too wide (more than
    /// `MAX_BRANCHING` input vectors per tick): no verdicts compared.
    pub too_wide: u64,
    /// The explicit engine returned an error (each is also a failure).
    pub explicit_errors: u64,
    /// Verdict pairs compared (explicit vs a SAT engine).
    pub verdicts: u64,
    /// SAT engine runs (BMC, k-induction, IC3, CEGAR) that ended `unknown` (a limit), not compared.
    pub unknown: [u64; 4],
    /// Counterexamples replayed.
    pub replays: u64,
    /// Models whose traces were compared with the generated C / Rust.
    pub c_models: u64,
    /// See `c_models`.
    pub rust_models: u64,
    /// Promela files SPIN accepted.
    pub spin_ok: u64,
    /// Disagreements and failures, each with the model text.
    pub failures: Vec<String>,
    /// Compile failures (gcc, rustc, spin), each with the model text.
    pub compile_failures: Vec<String>,
    /// Where the time went (wall time of each phase, summed over models and batches).
    pub times: Times,
}

/// Wall time per phase of a differential run (the figures of `statecheck-fuzz diff`, to see
/// where a model's cost goes).
#[derive(Clone, Debug, Default)]
pub struct Times {
    /// Generating, parsing, checking and lowering the models.
    pub lower: Duration,
    /// The explicit engine and the replays of its counterexamples.
    pub explicit: Duration,
    /// BMC, k-induction and IC3 and the replays of their counterexamples.
    pub sat: Duration,
    /// Of `sat`: each engine's `decide` calls (BMC, k-induction, IC3, CEGAR).
    pub engines: [Duration; 4],
    /// Exporting Promela and `spin -a`.
    pub spin: Duration,
    /// Generating C and Rust and the interpreter's expected traces.
    pub codegen: Duration,
    /// `gcc` on the batch's C program.
    pub gcc: Duration,
    /// `rustc` on the batch's Rust program.
    pub rustc: Duration,
    /// Running the compiled drivers and comparing their traces.
    pub run: Duration,
}

impl Times {
    fn add(&mut self, o: &Times) {
        self.lower += o.lower;
        self.explicit += o.explicit;
        self.sat += o.sat;
        for (a, b) in self.engines.iter_mut().zip(o.engines) {
            *a += b;
        }
        self.spin += o.spin;
        self.codegen += o.codegen;
        self.gcc += o.gcc;
        self.rustc += o.rustc;
        self.run += o.run;
    }
}

impl Report {
    /// Add `o`'s figures to these.
    pub fn add(&mut self, o: Report) {
        self.models += o.models;
        self.rejected += o.rejected;
        self.incomplete += o.incomplete;
        self.too_wide += o.too_wide;
        self.explicit_errors += o.explicit_errors;
        self.verdicts += o.verdicts;
        for (a, b) in self.unknown.iter_mut().zip(o.unknown) {
            *a += b;
        }
        self.replays += o.replays;
        self.c_models += o.c_models;
        self.rust_models += o.rust_models;
        self.spin_ok += o.spin_ok;
        self.failures.extend(o.failures);
        self.compile_failures.extend(o.compile_failures);
        self.times.add(&o.times);
    }
}

/// Parse, check and lower a model; `Err` carries the diagnostics.
pub fn lower(text: &str) -> Result<Program, String> {
    let (file, d1) = statecheck_syntax::parse(text);
    let msgs = |d: &[statecheck_base::Diagnostic]| {
        d.iter()
            .filter(|d| d.is_error())
            .map(|d| format!("{} {}", d.code, d.message))
            .collect::<Vec<_>>()
            .join("; ")
    };
    if d1.iter().any(|d| d.is_error()) {
        return Err(msgs(&d1));
    }
    let (model, d2) = statecheck_model::check(&file);
    if d2.iter().any(|d| d.is_error()) {
        return Err(msgs(&d2));
    }
    let sys = model
        .systems
        .iter()
        .find(|s| !s.implicit)
        .or_else(|| model.systems.first())
        .ok_or("no system")?;
    statecheck_ir::lower(&model, sys).map_err(|d| msgs(&d))
}

fn holds(m: &mut Machine, e: u32) -> bool {
    matches!(m.eval(e), Ok(v) if v != 0)
}

/// Replay `vectors`: assumes hold, no error before the last tick, and the last tick shows
/// the violation (or the witness) of `name`. A `deadlock_free` counterexample ends in the
/// state it deadlocks in: every tick replays without error and then no input vector
/// satisfies the `assume`s (checked by enumerating them, independently of the engines).
pub fn replays(p: &Program, name: &str, kind: PropKind, vectors: &[Vec<i64>]) -> bool {
    if kind == PropKind::Builtin && name == statecheck_explicit::ltl::DEADLOCK_FREE {
        return replays_deadlock(p, vectors);
    }
    let mut m = Machine::new(p);
    for (t, v) in vectors.iter().enumerate() {
        for (k, inp) in p.inputs.iter().enumerate() {
            let Some(&x) = v.get(k) else { return false };
            let sl = &p.slots[inp.slot as usize];
            if x < sl.lo || x > sl.hi {
                return false;
            }
            m.set(inp.slot, x);
        }
        if !p.assumes.iter().all(|a| holds(&mut m, *a)) {
            return false;
        }
        let last = t + 1 == vectors.len();
        match m.step() {
            Err(e) => {
                return last && kind == PropKind::Builtin && e.kind.builtin_property() == name
            }
            Ok(()) if !last => {}
            Ok(()) => {
                let Some(prop) = p.properties.iter().find(|x| x.name == name) else {
                    return false;
                };
                return match &prop.kind {
                    PropertyKind::Invariant { expr, assuming } => {
                        assuming.is_none_or(|a| holds(&mut m, a)) && !holds(&mut m, *expr)
                    }
                    PropertyKind::Reachable { expr } => holds(&mut m, *expr),
                    PropertyKind::Respond { ok, .. } | PropertyKind::Observer { ok, .. } => {
                        !holds(&mut m, *ok)
                    }
                };
            }
        }
    }
    false
}

/// The most input vectors [`replays_deadlock`] enumerates; the explicit reference gives
/// up on wider models ([`MAX_BRANCHING`]), so it never reports a deadlock past this.
const MAX_DEADLOCK_VECTORS: u128 = 1_000_000;

/// Replay a deadlock: every vector satisfies the `assume`s and steps without error, and in
/// the state reached no vector of the inputs' ranges satisfies them.
fn replays_deadlock(p: &Program, vectors: &[Vec<i64>]) -> bool {
    let mut m = Machine::new(p);
    for v in vectors {
        for (k, inp) in p.inputs.iter().enumerate() {
            let Some(&x) = v.get(k) else { return false };
            let sl = &p.slots[inp.slot as usize];
            if x < sl.lo || x > sl.hi {
                return false;
            }
            m.set(inp.slot, x);
        }
        if !p.assumes.iter().all(|a| holds(&mut m, *a)) || m.step().is_err() {
            return false;
        }
    }
    let ranges: Vec<(u32, i64, i64)> = p
        .inputs
        .iter()
        .map(|inp| {
            let sl = &p.slots[inp.slot as usize];
            (inp.slot, sl.lo, sl.hi)
        })
        .collect();
    let count = ranges.iter().try_fold(1u128, |n, &(_, lo, hi)| {
        n.checked_mul((hi as i128 - lo as i128 + 1) as u128)
            .filter(|&n| n <= MAX_DEADLOCK_VECTORS)
    });
    if count.is_none() {
        return false;
    }
    // Odometer over the input ranges: is any vector allowed?
    let mut current: Vec<i64> = ranges.iter().map(|r| r.1).collect();
    loop {
        for (&(slot, _, _), &x) in ranges.iter().zip(&current) {
            m.set(slot, x);
        }
        if p.assumes.iter().all(|a| holds(&mut m, *a)) {
            return false;
        }
        let mut k = 0;
        loop {
            let Some(&(_, lo, hi)) = ranges.get(k) else {
                return true;
            };
            if current[k] < hi {
                current[k] += 1;
                break;
            }
            current[k] = lo;
            k += 1;
        }
    }
}

/// How long each SAT engine may take on one property. k-induction proves a property only
/// at the length of the longest simple path of the circuit (unreachable states included),
/// which on a model with counters is long: it used 88 % of the SAT engines' time with a
/// budget of 20 s, mostly on properties it then decided after seconds. Its answers within
/// the shorter budget are compared as before; the rest count as `unknown` (a limit is not
/// an answer).
fn engine_time(engine: Engine) -> Duration {
    match engine {
        Engine::Kind => Duration::from_secs(2),
        _ => Duration::from_secs(20),
    }
}

/// Check one lowered model's verdicts: explicit against BMC, k-induction, IC3 and CEGAR.
fn verdicts(p: &Program, text: &str, rep: &mut Report) {
    let began = Instant::now();
    verdicts_inner(p, text, rep, began);
}

fn verdicts_inner(p: &Program, text: &str, rep: &mut Report, began: Instant) {
    let opts = Options {
        threads: 1,
        max_states: Some(MAX_STATES),
        max_branching: MAX_BRANCHING,
        timeout: Some(EXPLICIT_TIME),
        backend: statecheck_explicit::Backend::Interpreter,
        ..Options::default()
    };
    let ex = match statecheck_explicit::verify(p, &opts, None) {
        Ok(ex) => ex,
        Err(e) => {
            rep.explicit_errors += 1;
            rep.failures
                .push(format!("the explicit engine failed: {e}\n{text}"));
            return;
        }
    };
    if ex.stats.states == 0 && ex.results.iter().all(|r| r.verdict == Verdict::Unknown) {
        rep.too_wide += 1;
        rep.times.explicit += began.elapsed();
        return;
    }
    for r in &ex.results {
        if let Some(c) = &r.counterexample {
            if r.loop_start.is_none()
                && matches!(
                    r.kind,
                    PropKind::Invariant
                        | PropKind::Reachable
                        | PropKind::Respond
                        | PropKind::Observer
                        | PropKind::Builtin
                )
            {
                if replays(p, &r.name, r.kind, c) {
                    rep.replays += 1;
                } else {
                    rep.failures.push(format!(
                        "explicit counterexample of {} does not replay: {c:?}\n{text}",
                        r.name
                    ));
                }
            }
        }
    }
    let sat_began = Instant::now();
    rep.times.explicit += sat_began - began;
    if sat_began - began > Duration::from_secs(2) {
        // The explicit reference's slow models, to see what makes them slow.
        eprintln!(
            "slow explicit reference: {:.1} s, {} states, {} transitions, branching {}, complete {}",
            (sat_began - began).as_secs_f64(),
            ex.stats.states,
            ex.stats.transitions,
            ex.stats.branching,
            ex.stats.complete
        );
    }
    if !ex.stats.complete && !ex.stats.all_decided {
        rep.incomplete += 1;
        return;
    }
    sat_verdicts(p, text, &ex, rep);
    rep.times.sat += sat_began.elapsed();
}

/// BMC's, k-induction's, IC3's and CEGAR's (IC3 on a localization abstraction) verdicts against the explicit engine's `ex`.
fn sat_verdicts(p: &Program, text: &str, ex: &statecheck_explicit::Report, rep: &mut Report) {
    let Ok((bl, idx)) = problems(p, &[]) else {
        rep.failures
            .push(format!("problems() refused the properties\n{text}"));
        return;
    };
    let reds = Reductions::new(bl.props.len());
    for &(pi, kind) in &idx {
        let name = &bl.props[pi].name;
        let Some(r) = ex.results.iter().find(|r| &r.name == name) else {
            continue;
        };
        if r.verdict == Verdict::Unknown {
            continue;
        }
        for engine in [Engine::Bmc, Engine::Kind, Engine::Ic3, Engine::Cegar] {
            if engine == Engine::Bmc && matches!(r.verdict, Verdict::Proved | Verdict::Unreachable)
            {
                continue;
            }
            if engine != Engine::Bmc && r.depth > 40 && r.counterexample.is_some() {
                continue;
            }
            let lim = Limits {
                deadline: Some(Instant::now() + engine_time(engine)),
                ..Limits::default()
            };
            let began = Instant::now();
            let s = decide(p, &bl, pi, kind, engine, &lim, &reds);
            rep.times.engines[engine as usize] += began.elapsed();
            if s.result.verdict == Verdict::Unknown {
                // k-induction may give up; a limit is not an answer
                rep.unknown[engine as usize] += 1;
                continue;
            }
            rep.verdicts += 1;
            if s.result.verdict != r.verdict {
                rep.failures.push(format!(
                    "{name}: explicit {} but {} {}\n{text}",
                    r.verdict.as_str(),
                    engine.as_str(),
                    s.result.verdict.as_str()
                ));
                continue;
            }
            if let Some(c) = &s.result.counterexample {
                if s.result.depth != r.depth {
                    rep.failures.push(format!(
                        "{name}: {} counterexample of length {} but explicit {}\n{text}",
                        engine.as_str(),
                        s.result.depth,
                        r.depth
                    ));
                } else if !replays(p, name, kind, c) {
                    rep.failures.push(format!(
                        "{name}: {} counterexample does not replay: {c:?}\n{text}",
                        engine.as_str()
                    ));
                } else {
                    rep.replays += 1;
                }
            }
        }
    }
}

/// Whether `spin` runs here.
pub fn spin_available() -> bool {
    Command::new("spin")
        .arg("-V")
        .output()
        .is_ok_and(|o| o.status.success())
}

fn spin_accepts(p: &Program, dir: &Path, k: usize) -> Result<(), String> {
    let src = Source::new("random.sc", "");
    let opts = statecheck_codegen::promela::PromelaOptions {
        properties: Vec::new(),
    };
    let pml = match statecheck_codegen::promela::export(p, &src, &opts) {
        Ok(t) => t,
        Err(_) => return Ok(()), // a documented refusal (e.g. too large), not a failure
    };
    let d = dir.join(format!("spin{k}"));
    std::fs::create_dir_all(&d).map_err(|e| e.to_string())?;
    std::fs::write(d.join("m.pml"), pml).map_err(|e| e.to_string())?;
    let out = Command::new("spin")
        .arg("-a")
        .arg("m.pml")
        .current_dir(&d)
        .output()
        .map_err(|e| e.to_string())?;
    let _ = std::fs::remove_dir_all(&d);
    let text =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    if !out.status.success() || text.contains("error") {
        return Err(text.chars().take(2000).collect());
    }
    Ok(())
}

/// A run-time error as the drivers print it: (kind code, value).
pub fn kind_code(k: &RuntimeErrorKind) -> (u32, i64) {
    match k {
        RuntimeErrorKind::Range { value, .. } => (1, *value),
        RuntimeErrorKind::DivisionByZero => (2, 0),
        RuntimeErrorKind::BadShift => (3, 0),
        RuntimeErrorKind::Overflow => (4, 0),
    }
}

/// The interpreter's trace lines of run `r` of model `k` (`k r t ok SLOTS…` after every tick,
/// `k r t err CODE SITE VALUE` at a run-time error, which ends the run), appended to `out`.
pub fn expected(k: usize, r: usize, p: &Program, inputs: &[Vec<i64>], out: &mut String) {
    let mut m = Machine::new(p);
    for (t, vals) in inputs.iter().enumerate() {
        for (inp, v) in p.inputs.iter().zip(vals) {
            m.set(inp.slot, *v);
        }
        match m.step() {
            Ok(()) => {
                let _ = write!(out, "{k} {r} {t} ok");
                for v in m.slots() {
                    let _ = write!(out, " {v}");
                }
                out.push('\n');
            }
            Err(e) => {
                let (code, value) = kind_code(&e.kind);
                let _ = writeln!(out, "{k} {r} {t} err {code} {} {value}", e.site);
                return;
            }
        }
    }
}

/// One model of a code-generation batch: its text, its lowered program and its input runs
/// (`runs[r][t][k]`: input `k` at tick `t` of run `r`; every run has the same length).
pub struct Case {
    /// The model's text (quoted in failure reports).
    pub text: String,
    /// The lowered program.
    pub p: Program,
    /// The input vectors of every run.
    pub runs: Vec<Vec<Vec<i64>>>,
}

impl Case {
    /// `runs` runs of `ticks` random input vectors for `p`, drawn from `seed`.
    pub fn random(text: String, p: Program, seed: u64, runs: usize, ticks: usize) -> Case {
        let mut g = Gen::new(seed);
        let runs = (0..runs)
            .map(|_| {
                (0..ticks)
                    .map(|_| {
                        p.inputs
                            .iter()
                            .map(|i| g.value(&p.slots[i.slot as usize]))
                            .collect()
                    })
                    .collect()
            })
            .collect();
        Case { text, p, runs }
    }

    fn ticks(&self) -> usize {
        self.runs.first().map_or(0, Vec::len)
    }
}

fn c_driver(k: usize, c: &Case) -> String {
    let p = &c.p;
    let f = slot_fields(p);
    let flat: Vec<String> = c
        .runs
        .iter()
        .flatten()
        .flatten()
        .map(|v| format!("INT64_C({v})"))
        .collect();
    let (runs, ticks) = (c.runs.len(), c.ticks());
    let mut s = format!(
        "#include \"m{k}.c\"\nstatic const int64_t in_{k}[] = {{{}, 0}};\nstatic void run_{k}(void) {{\n    int r, t, st;\n    for (r = 0; r < {runs}; r++) {{\n        m{k}_state s; m{k}_inputs i; m{k}_outputs o; int64_t v[M{k}_N_SLOTS]; unsigned j;\n        m{k}_init(&s, &i, &o);\n        for (t = 0; t < {ticks}; t++) {{\n            const int64_t *x = &in_{k}[(r * {ticks} + t) * {}];\n            (void)x;\n",
        flat.join(","),
        p.inputs.len()
    );
    for (j, inp) in p.inputs.iter().enumerate() {
        let sl = &p.slots[inp.slot as usize];
        let _ = writeln!(
            s,
            "            i.{} = ({})x[{j}];",
            f[inp.slot as usize],
            statecheck_codegen::c::c_type(sl)
        );
    }
    let _ = write!(
        s,
        "            st = m{k}_step(&s, &i, &o);\n            if (st != SC_OK) {{ printf(\"{k} %d %d err %d %lu %lld\\n\", r, t, st, (unsigned long)o.error_site, (long long)(st == SC_ERR_RANGE ? o.error_value : 0)); break; }}\n            m{k}_slots(&s, &i, &o, v);\n            printf(\"{k} %d %d ok\", r, t);\n            for (j = 0; j < M{k}_N_SLOTS; j++) printf(\" %lld\", (long long)v[j]);\n            putchar('\\n');\n        }}\n    }}\n}}\n"
    );
    s
}

fn rust_driver(k: usize, c: &Case) -> String {
    let p = &c.p;
    let f = slot_fields(p);
    let flat: Vec<String> = c
        .runs
        .iter()
        .flatten()
        .flatten()
        .map(|v| v.to_string())
        .collect();
    let (runs, ticks) = (c.runs.len(), c.ticks());
    let mut s = format!(
        "#[path = \"m{k}.rs\"]\nmod m{k};\nfn run_{k}(out: &mut String) {{\n    const IN: &[i64] = &[{}, 0];\n    for r in 0..{runs} {{\n        let (mut s, mut i, mut o) = (m{k}::State::default(), m{k}::Inputs::default(), m{k}::Outputs::default());\n        let mut v = [0i64; m{k}::N_SLOTS];\n        m{k}::init(&mut s, &mut i, &mut o);\n        for t in 0..{ticks} {{\n            let x = &IN[(r * {ticks} + t) * {}..];\n            let _ = x;\n",
        flat.join(","),
        p.inputs.len()
    );
    for (j, inp) in p.inputs.iter().enumerate() {
        let sl = &p.slots[inp.slot as usize];
        let _ = writeln!(
            s,
            "            i.{} = x[{j}] as {};",
            f[inp.slot as usize],
            statecheck_codegen::rust::rust_type(sl)
        );
    }
    let _ = write!(
        s,
        "            match m{k}::step(&mut s, &i, &mut o) {{\n                Err(e) => {{\n                    let code = match e.kind {{ m{k}::ErrorKind::Range => 1, m{k}::ErrorKind::DivisionByZero => 2, m{k}::ErrorKind::BadShift => 3, m{k}::ErrorKind::Overflow => 4 }};\n                    out.push_str(&format!(\"{k} {{r}} {{t}} err {{code}} {{}} {{}}\\n\", e.site, e.value));\n                    break;\n                }}\n                Ok(()) => {{\n                    m{k}::slots(&s, &i, &o, &mut v);\n                    out.push_str(&format!(\"{k} {{r}} {{t}} ok\"));\n                    for x in v.iter() {{ out.push_str(&format!(\" {{x}}\")); }}\n                    out.push('\\n');\n                }}\n            }}\n        }}\n    }}\n}}\n"
    );
    s
}

fn first_diff(want: &str, got: &str) -> Option<(String, String)> {
    let (w, g): (Vec<&str>, Vec<&str>) = (want.lines().collect(), got.lines().collect());
    (0..w.len().max(g.len()))
        .find(|&i| w.get(i) != g.get(i))
        .map(|i| {
            (
                w.get(i).unwrap_or(&"<end>").to_string(),
                g.get(i).unwrap_or(&"<end>").to_string(),
            )
        })
}

fn model_of_line(cases: &[Case], line: &str) -> String {
    let k: usize = line
        .split(' ')
        .next()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0);
    cases.get(k).map(|c| c.text.clone()).unwrap_or_default()
}

/// Compile a batch into one C program (gcc `-std=c99 -Wall -Wextra -Wpedantic -Werror`) and,
/// if `rust`, one Rust program, in `dir`, run both and compare their traces with the
/// interpreter's line for line; what differs or does not compile goes to `rep`.
pub fn codegen_batch(cases: &[Case], dir: &Path, rust: bool, rep: &mut Report) {
    let mut clock = Instant::now();
    let mut lap = || {
        let now = Instant::now();
        let d = now - clock;
        clock = now;
        d
    };
    let src = Source::new("random.sc", "");
    let mut want = String::new();
    let (mut c_main, mut rs_main) = (
        String::from("#include <stdio.h>\n"),
        String::from("use std::io::Write;\n"),
    );
    for (k, c) in cases.iter().enumerate() {
        for (r, run) in c.runs.iter().enumerate() {
            expected(k, r, &c.p, run, &mut want);
        }
        let files = statecheck_codegen::c::generate(&c.p, &src, &format!("m{k}"));
        let _ = std::fs::write(dir.join(format!("m{k}.h")), &files.header);
        let _ = std::fs::write(dir.join(format!("m{k}.c")), &files.source);
        if rust {
            let _ = std::fs::write(
                dir.join(format!("m{k}.rs")),
                statecheck_codegen::rust::generate(&c.p, &src),
            );
            rs_main.push_str(&rust_driver(k, c));
        }
        c_main.push_str(&c_driver(k, c));
    }
    c_main.push_str("int main(void) {\n");
    rs_main.push_str("fn main() {\n    let mut out = String::new();\n");
    for k in 0..cases.len() {
        let _ = writeln!(c_main, "    run_{k}();");
        let _ = writeln!(rs_main, "    run_{k}(&mut out);");
    }
    c_main.push_str("    return 0;\n}\n");
    rs_main.push_str("    let _ = std::io::stdout().write_all(out.as_bytes());\n}\n");
    let _ = std::fs::write(dir.join("driver.c"), c_main);
    rep.times.codegen += lap();
    let mut langs = Vec::new();
    let cc = Command::new("gcc")
        .args([
            "-std=c99",
            "-Wall",
            "-Wextra",
            "-Wpedantic",
            "-Werror",
            "-O0",
            "-o",
        ])
        .arg(dir.join("drv_c"))
        .arg(dir.join("driver.c"))
        .output();
    match cc {
        Ok(o) if o.status.success() => langs.push(("drv_c", "C")),
        Ok(o) => {
            let err = String::from_utf8_lossy(&o.stderr)
                .chars()
                .take(3000)
                .collect::<String>();
            let culprit = err
                .split("m")
                .nth(1)
                .and_then(|s| s.split('.').next())
                .and_then(|s| s.parse::<usize>().ok())
                .and_then(|k| cases.get(k))
                .map(|c| c.text.clone())
                .unwrap_or_default();
            rep.compile_failures.push(format!("gcc: {err}\n{culprit}"));
        }
        Err(e) => rep.compile_failures.push(format!("gcc does not run: {e}")),
    }
    rep.times.gcc += lap();
    if rust {
        let _ = std::fs::write(dir.join("main.rs"), rs_main);
        let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
        let rc = Command::new(rustc)
            .args([
                "--edition",
                "2021",
                "-C",
                "opt-level=0",
                "-C",
                "debuginfo=0",
                "-o",
            ])
            .arg(dir.join("drv_rs"))
            .arg(dir.join("main.rs"))
            .output();
        match rc {
            Ok(o) if o.status.success() => langs.push(("drv_rs", "Rust")),
            Ok(o) => rep.compile_failures.push(format!(
                "rustc: {}",
                String::from_utf8_lossy(&o.stderr)
                    .chars()
                    .take(3000)
                    .collect::<String>()
            )),
            Err(e) => rep
                .compile_failures
                .push(format!("rustc does not run: {e}")),
        }
    }
    rep.times.rustc += lap();
    for (exe, lang) in langs {
        let Ok(out) = Command::new(dir.join(exe)).output() else {
            rep.failures.push(format!("{lang} driver does not run"));
            continue;
        };
        let got = String::from_utf8_lossy(&out.stdout);
        if let Some((w, g)) = first_diff(&want, &got) {
            rep.failures.push(format!(
                "{lang} differs from the interpreter:\n  interp: {w}\n  {lang}: {g}\n{}",
                model_of_line(cases, &w)
            ));
        } else if lang == "C" {
            rep.c_models += cases.len() as u64;
        } else {
            rep.rust_models += cases.len() as u64;
        }
    }
    rep.times.run += lap();
}

/// One batch: models `first .. first + n` of `seed`'s sequence.
pub fn batch(seed: u64, first: u64, n: u64, rust: bool, spin: bool, dir: &Path) -> Report {
    let mut rep = Report::default();
    let _ = std::fs::create_dir_all(dir);
    let mut cases = Vec::new();
    for m in first..first + n {
        let model_seed = seed.wrapping_mul(1_000_003).wrapping_add(m);
        rep.models += 1;
        let began = Instant::now();
        let text = Gen::new(model_seed).model_with(true);
        let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            let mut r = Report::default();
            let lowered = lower(&text);
            r.times.lower += began.elapsed();
            let p = match lowered {
                Ok(p) => p,
                Err(e) => {
                    r.rejected += 1;
                    if !e.contains("E0104") {
                        r.failures.push(format!("rejected: {e}\n{text}"));
                    }
                    return (r, None);
                }
            };
            verdicts(&p, &text, &mut r);
            if spin {
                let began = Instant::now();
                match spin_accepts(&p, dir, m as usize) {
                    Ok(()) => r.spin_ok += 1,
                    Err(e) => r.compile_failures.push(format!("spin -a: {e}\n{text}")),
                }
                r.times.spin += began.elapsed();
            }
            let case = Case::random(text.clone(), p, model_seed ^ 0xA5A5_0000, RUNS, TICKS);
            (r, Some(case))
        }));
        match caught {
            Ok((r, case)) => {
                rep.add(r);
                cases.extend(case);
            }
            Err(e) => {
                let m = e
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| e.downcast_ref::<String>().cloned())
                    .unwrap_or_default();
                rep.failures.push(format!("panic: {m}\n{text}"));
            }
        }
    }
    if !cases.is_empty() {
        let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            let mut r = Report::default();
            codegen_batch(&cases, dir, rust, &mut r);
            r
        }));
        match caught {
            Ok(r) => rep.add(r),
            Err(_) => rep
                .failures
                .push("panic while generating code for a batch".into()),
        }
    }
    let _ = std::fs::remove_dir_all(dir);
    rep
}

/// A fresh temporary folder for a batch.
pub fn temp_dir(tag: &str) -> PathBuf {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos())
        .unwrap_or(0);
    std::env::temp_dir().join(format!(
        "statecheck-fuzz-{tag}-{}-{nanos}",
        std::process::id()
    ))
}
