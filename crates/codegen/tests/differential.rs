//! Differential testing: for random well-formed models and random input sequences, the IR
//! interpreter (what the simulator and checkers run), the generated C and the generated Rust
//! produce identical traces — every slot after every tick, and the same run-time error (kind,
//! site, value) on the same tick. All models are compiled into one C program (gcc with
//! `-std=c99 -Wall -Wextra -Wpedantic -Werror`) and one Rust program (rustc), in a temp dir.

mod gen;

use statecheck_codegen::common::{slot_fields, Source};
use statecheck_ir::{Machine, Program, RuntimeErrorKind};
use std::fmt::Write;
use std::path::PathBuf;
use std::process::Command;

const MODELS: u64 = 200;
const RUNS: usize = 8;
const TICKS: usize = 24;

fn temp_dir(tag: &str) -> PathBuf {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map(|d| d.as_nanos())
        .unwrap_or(0);
    let d = std::env::temp_dir().join(format!("statecheck-{tag}-{}-{nanos}", std::process::id()));
    std::fs::create_dir_all(&d).expect("temp dir");
    d
}

/// Parse, check and lower a model; `Err` carries the diagnostics' messages.
fn lower(text: &str) -> Result<Program, String> {
    let (file, diags) = statecheck_syntax::parse(text);
    let msgs = |d: &[statecheck_base::Diagnostic]| {
        d.iter()
            .filter(|d| d.is_error())
            .map(|d| format!("{} {}", d.code, d.message))
            .collect::<Vec<_>>()
            .join("; ")
    };
    if diags.iter().any(|d| d.is_error()) {
        return Err(msgs(&diags));
    }
    let (model, diags) = statecheck_model::check(&file);
    if diags.iter().any(|d| d.is_error()) {
        return Err(msgs(&diags));
    }
    let sys = model
        .systems
        .iter()
        .find(|s| !s.implicit)
        .or_else(|| model.systems.first())
        .ok_or("no system")?;
    statecheck_ir::lower(&model, sys).map_err(|d| msgs(&d))
}

fn kind_code(k: &RuntimeErrorKind) -> (u32, i64) {
    match k {
        RuntimeErrorKind::Range { value, .. } => (1, *value),
        RuntimeErrorKind::DivisionByZero => (2, 0),
        RuntimeErrorKind::BadShift => (3, 0),
        RuntimeErrorKind::Overflow => (4, 0),
    }
}

/// The interpreter's trace lines for one run.
fn expected(k: usize, r: usize, p: &Program, inputs: &[Vec<i64>], out: &mut String) {
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

struct Case {
    p: Program,
    runs: Vec<Vec<Vec<i64>>>,
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
    let mut s = format!(
        "#include \"m{k}.c\"\nstatic const int64_t in_{k}[] = {{{}, 0}};\nstatic void run_{k}(void) {{\n    int r, t, st;\n    for (r = 0; r < {RUNS}; r++) {{\n        m{k}_state s; m{k}_inputs i; m{k}_outputs o; int64_t v[M{k}_N_SLOTS]; unsigned j;\n        m{k}_init(&s, &i, &o);\n        for (t = 0; t < {TICKS}; t++) {{\n            const int64_t *x = &in_{k}[(r * {TICKS} + t) * {}];\n            (void)x;\n",
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
    let mut s = format!(
        "#[path = \"m{k}.rs\"]\nmod m{k};\nfn run_{k}(out: &mut String) {{\n    const IN: &[i64] = &[{}, 0];\n    for r in 0..{RUNS} {{\n        let (mut s, mut i, mut o) = (m{k}::State::default(), m{k}::Inputs::default(), m{k}::Outputs::default());\n        let mut v = [0i64; m{k}::N_SLOTS];\n        m{k}::init(&mut s, &mut i, &mut o);\n        for t in 0..{TICKS} {{\n            let x = &IN[(r * {TICKS} + t) * {}..];\n            let _ = x;\n",
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

fn first_diff(want: &str, got: &str) -> Option<(usize, String, String)> {
    let (w, g): (Vec<&str>, Vec<&str>) = (want.lines().collect(), got.lines().collect());
    (0..w.len().max(g.len()))
        .find(|&i| w.get(i) != g.get(i))
        .map(|i| {
            (
                i,
                w.get(i).unwrap_or(&"<end>").to_string(),
                g.get(i).unwrap_or(&"<end>").to_string(),
            )
        })
}

#[test]
fn interpreter_c_and_rust_agree_on_random_models() {
    let dir = temp_dir("diff");
    let src = Source::new("random.sc", "");
    let mut cases: Vec<(String, Case)> = Vec::new();
    let mut rejected = Vec::new();
    for seed in 0..MODELS * 4 {
        if cases.len() as u64 == MODELS {
            break;
        }
        // Some random texts are rightly rejected (e.g. a constant out of range): skip them.
        let text = gen::Gen::new(seed).model();
        let p = match lower(&text) {
            Ok(p) => p,
            Err(e) => {
                rejected.push(format!("seed {seed}: {e}\n{text}"));
                continue;
            }
        };
        let mut rng = gen::Gen::new(seed ^ 0xA5A5_0000);
        let runs = (0..RUNS)
            .map(|_| {
                (0..TICKS)
                    .map(|_| {
                        p.inputs
                            .iter()
                            .map(|inp| rng.value(&p.slots[inp.slot as usize]))
                            .collect()
                    })
                    .collect()
            })
            .collect();
        cases.push((text, Case { p, runs }));
    }
    assert!(
        cases.len() as u64 == MODELS && rejected.iter().all(|r| r.contains("E0104")),
        "{} random models were rejected; first:\n{}",
        rejected.len(),
        rejected
            .iter()
            .find(|r| !r.contains("E0104"))
            .cloned()
            .unwrap_or_default()
    );
    let mut want = String::new();
    let (mut c_main, mut rs_main) = (
        String::from("#include <stdio.h>\n"),
        String::from("use std::io::Write;\n"),
    );
    for (k, (_, c)) in cases.iter().enumerate() {
        for (r, run) in c.runs.iter().enumerate() {
            expected(k, r, &c.p, run, &mut want);
        }
        let files = statecheck_codegen::c::generate(&c.p, &src, &format!("m{k}"));
        std::fs::write(dir.join(format!("m{k}.h")), &files.header).expect("write");
        std::fs::write(dir.join(format!("m{k}.c")), &files.source).expect("write");
        std::fs::write(
            dir.join(format!("m{k}.rs")),
            statecheck_codegen::rust::generate(&c.p, &src),
        )
        .expect("write");
        c_main.push_str(&c_driver(k, c));
        rs_main.push_str(&rust_driver(k, c));
    }
    c_main.push_str("int main(void) {\n");
    rs_main.push_str("fn main() {\n    let mut out = String::new();\n");
    for k in 0..cases.len() {
        let _ = writeln!(c_main, "    run_{k}();");
        let _ = writeln!(rs_main, "    run_{k}(&mut out);");
    }
    c_main.push_str("    return 0;\n}\n");
    rs_main.push_str("    let _ = std::io::stdout().write_all(out.as_bytes());\n}\n");
    std::fs::write(dir.join("driver.c"), c_main).expect("write");
    std::fs::write(dir.join("main.rs"), rs_main).expect("write");
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
        .output()
        .expect("gcc runs");
    assert!(
        cc.status.success(),
        "gcc: {}",
        String::from_utf8_lossy(&cc.stderr)
            .chars()
            .take(4000)
            .collect::<String>()
    );
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
        .output()
        .expect("rustc runs");
    assert!(
        rc.status.success(),
        "rustc: {}",
        String::from_utf8_lossy(&rc.stderr)
            .chars()
            .take(4000)
            .collect::<String>()
    );
    // The generated modules are `no_std`-compatible: one compiles in a `#![no_std]` library.
    std::fs::write(
        dir.join("nostd.rs"),
        "#![no_std]\n#[path = \"m0.rs\"]\nmod m0;\npub use m0::step;\n",
    )
    .expect("write");
    let ns = Command::new(std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into()))
        .args([
            "--edition",
            "2021",
            "--crate-type",
            "lib",
            "--emit",
            "metadata",
            "-o",
        ])
        .arg(dir.join("libnostd.rmeta"))
        .arg(dir.join("nostd.rs"))
        .output()
        .expect("rustc runs");
    assert!(
        ns.status.success(),
        "no_std: {}",
        String::from_utf8_lossy(&ns.stderr)
    );
    for (exe, lang) in [("drv_c", "C"), ("drv_rs", "Rust")] {
        let out = Command::new(dir.join(exe)).output().expect("driver runs");
        let got = String::from_utf8_lossy(&out.stdout);
        if let Some((line, w, g)) = first_diff(&want, &got) {
            let k: usize = w
                .split(' ')
                .next()
                .and_then(|s| s.parse().ok())
                .unwrap_or(0);
            panic!(
                "{lang} differs from the interpreter at line {line}:\n  interp: {w}\n  {lang}: {g}\nmodel {k}:\n{}",
                cases.get(k).map(|c| c.0.as_str()).unwrap_or("")
            );
        }
    }
    let errors = want.lines().filter(|l| l.contains(" err ")).count();
    let runs = cases.len() * RUNS;
    assert!(runs >= 1000, "only {runs} runs");
    assert!(
        errors * 20 > runs,
        "too few run-time errors exercised: {errors} of {runs} runs"
    );
    assert!(
        errors * 10 < runs * 9,
        "almost every run fails at once: {errors} of {runs}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
