//! Steps per second of the generated C (gcc -O2) vs the simulator's step engine (the IR
//! `Machine`) on the same model and the same random input vectors, in one run. Both restart
//! from the initial state after a run-time error; neither monitors properties or records a
//! trace. Both figures are wall-clock (the C one includes process start-up). Prints
//! figures; not a timed test.
//!
//! `cargo bench -p statecheck-codegen --bench step_c [-- MODEL SYSTEM]` (default: the FAM plant).

use rand::{RngExt, SeedableRng};
use statecheck_codegen::common::slot_fields;
use statecheck_ir::{Machine, Program};
use std::fmt::Write;
use std::process::Command;
use std::time::Instant;

const VECTORS: usize = 100_000;
const ROUNDS: usize = 20;

fn lower(path: &str, system: &str) -> Program {
    let text = std::fs::read_to_string(path).expect("model readable");
    // Follow the model's imports (fam.sc imports lib/).
    let program =
        statecheck_model::imports::load_with(path, text, |k| std::fs::read_to_string(k).ok());
    let (model, diags) = statecheck_model::check(&program.file);
    assert!(!diags.iter().any(|d| d.is_error()), "model has errors");
    let sys = model.system(system).expect("system exists");
    statecheck_ir::lower(&model, sys).expect("lowers")
}

fn main() {
    let args: Vec<String> = std::env::args().filter(|a| a != "--bench").collect();
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let default_model = format!("{root}/examples/fam/fam.sc");
    let model = args.get(1).cloned().unwrap_or(default_model);
    let system = args.get(2).cloned().unwrap_or_else(|| "FamAlone".into());
    let p = lower(&model, &system);
    let mut rng = rand::rngs::StdRng::seed_from_u64(1);
    let inputs: Vec<i64> = (0..VECTORS)
        .flat_map(|_| {
            p.inputs
                .iter()
                .map(|i| {
                    let s = &p.slots[i.slot as usize];
                    rng.random_range(s.lo..=s.hi)
                })
                .collect::<Vec<_>>()
        })
        .collect();
    let ni = p.inputs.len().max(1);
    // The simulator's engine.
    let start = Instant::now();
    let mut m = Machine::new(&p);
    let mut errors = 0u64;
    for _ in 0..ROUNDS {
        for v in inputs.chunks(ni) {
            for (inp, x) in p.inputs.iter().zip(v) {
                m.set(inp.slot, *x);
            }
            if m.step().is_err() {
                errors += 1;
                m = Machine::new(&p);
            }
        }
    }
    let sim_s = start.elapsed().as_secs_f64();
    let steps = (ROUNDS * VECTORS) as f64;
    // The generated C.
    let dir = std::env::temp_dir().join(format!("statecheck-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let files =
        statecheck_codegen::c::generate(&p, &statecheck_codegen::Source::new(&model, ""), "b");
    std::fs::write(dir.join("b.h"), &files.header).expect("write");
    std::fs::write(dir.join("b.c"), &files.source).expect("write");
    let f = slot_fields(&p);
    let mut set = String::new();
    for (j, inp) in p.inputs.iter().enumerate() {
        let ty = statecheck_codegen::c::c_type(&p.slots[inp.slot as usize]);
        let _ = writeln!(
            set,
            "            i.{} = ({ty})x[{j}];",
            f[inp.slot as usize]
        );
    }
    let vals: Vec<String> = inputs.iter().map(|v| format!("INT64_C({v})")).collect();
    let driver = format!(
        "#include <stdio.h>\n#include <time.h>\n#include \"b.h\"\nstatic const int64_t IN[] = {{{}, 0}};\nint main(void) {{\n    b_state s; b_inputs i; b_outputs o; long r, k, errors = 0;\n    clock_t t0 = clock();\n    b_init(&s, &i, &o);\n    for (r = 0; r < {ROUNDS}; r++) {{\n        for (k = 0; k < {VECTORS}; k++) {{\n            const int64_t *x = &IN[k * {ni}];\n            (void)x;\n{set}            if (b_step(&s, &i, &o) != SC_OK) {{ errors++; b_init(&s, &i, &o); }}\n        }}\n    }}\n    printf(\"%ld %f\\n\", errors, (double)(clock() - t0) / CLOCKS_PER_SEC);\n    return 0;\n}}\n",
        vals.join(",")
    );
    std::fs::write(dir.join("main.c"), driver).expect("write");
    let cc = Command::new("gcc")
        .args(["-std=c99", "-O2", "-o"])
        .arg(dir.join("bench"))
        .arg(dir.join("main.c"))
        .arg(dir.join("b.c"))
        .output()
        .expect("gcc runs");
    assert!(
        cc.status.success(),
        "{}",
        String::from_utf8_lossy(&cc.stderr)
    );
    let t0 = Instant::now();
    let out = Command::new(dir.join("bench"))
        .output()
        .expect("bench runs");
    let c_wall = t0.elapsed().as_secs_f64();
    let text = String::from_utf8_lossy(&out.stdout);
    let mut it = text.split_whitespace();
    let c_errors: u64 = it.next().and_then(|s| s.parse().ok()).unwrap_or(u64::MAX);
    let c_cpu: f64 = it.next().and_then(|s| s.parse().ok()).unwrap_or(f64::NAN);
    // Wall time of the whole process (start-up included), like the simulator's figure.
    let c_s = c_wall;
    let _ = std::fs::remove_dir_all(&dir);
    println!("model {model}, system {system}: {steps} steps of random inputs");
    println!(
        "simulator engine (IR Machine): {sim_s:.3} s = {:.0} steps/s, {errors} run-time errors",
        steps / sim_s
    );
    println!(
        "generated C (gcc -O2):         {c_s:.3} s wall ({c_cpu:.3} s CPU in the loop) = {:.0} steps/s, {c_errors} run-time errors",
        steps / c_s
    );
    assert_eq!(
        errors, c_errors,
        "the two disagree on the number of run-time errors"
    );
    println!("ratio generated C / simulator = {:.1}", sim_s / c_s);
}
