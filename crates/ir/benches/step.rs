//! Interpreter throughput: chart steps per second on one core with random inputs.
//!
//! `cargo bench -p statecheck-ir --bench step [-- MODEL.sc [SYSTEM] [STEPS]]` (default: the FAM
//! plant, 20 million steps). Inputs are drawn in advance (4096 random vectors within the input
//! ranges, reused cyclically) so the figure measures `Machine::step` alone. A run-time error
//! restarts the machine from its initial state, as a random simulation would.
//!
//! Wall-clock figures need an idle machine. Instruction counts are steadier: run the built
//! binary under `valgrind --tool=callgrind` with two step counts (say 100000 and 200000) and
//! divide the difference of the totals by the difference of the counts.

use statecheck_ir::{lower, Machine};
use std::time::Instant;

fn splitmix(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let path = args
        .first()
        .cloned()
        .unwrap_or_else(|| format!("{root}/examples/fam/fam.sc"));
    let source = std::fs::read_to_string(&path).expect("model file readable");
    // Follow the model's imports (fam.sc imports lib/).
    let program =
        statecheck_model::imports::load_with(&path, source, |k| std::fs::read_to_string(k).ok());
    assert!(
        !program.diags.iter().any(|d| d.is_error()),
        "{path} has syntax or import errors"
    );
    let (model, diags) = statecheck_model::check(&program.file);
    assert!(!diags.iter().any(|d| d.is_error()), "{path} has errors");
    let sys = match args.get(1) {
        Some(name) => model.system(name).expect("system exists"),
        None => model
            .systems
            .iter()
            .find(|s| !s.implicit)
            .unwrap_or(&model.systems[0]),
    };
    let steps: u64 = args
        .get(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(20_000_000);
    let program = lower(&model, sys).expect("lowers");
    let mut rng = 42u64;
    let vectors: Vec<Vec<i64>> = (0..4096)
        .map(|_| {
            program
                .inputs
                .iter()
                .map(|i| {
                    let s = &program.slots[i.slot as usize];
                    s.lo + (splitmix(&mut rng) % ((s.hi - s.lo + 1) as u64)) as i64
                })
                .collect()
        })
        .collect();
    let mut m = Machine::new(&program);
    let mut errors = 0u64;
    let start = Instant::now();
    for k in 0..steps {
        let v = &vectors[(k & 4095) as usize];
        for (inp, x) in program.inputs.iter().zip(v) {
            m.set(inp.slot, *x);
        }
        if m.step().is_err() {
            errors += 1;
            m = Machine::new(&program);
        }
    }
    let secs = start.elapsed().as_secs_f64();
    println!(
        "model: {path} system: {} | state slots: {} ({} bits) | inputs: {} | IR nodes: {} procs: {}",
        program.name,
        program.n_state,
        program.state_bits(),
        program.inputs.len(),
        program.nodes.len(),
        program.procs.len()
    );
    println!(
        "steps: {steps} in {secs:.3} s = {:.2} M steps/s (one core); run-time errors (restarts): {errors}",
        steps as f64 / secs / 1e6
    );
}
