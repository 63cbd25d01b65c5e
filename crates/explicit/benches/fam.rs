//! Throughput benchmark of the explicit engine on a realistic model: `N` EATON FAM actuator
//! plants (examples/fam/fam_alone.sc: the `Fam` plant chart driven by its `FamEnv`
//! environment chart), side by side, with restricted inputs: per plant, run mode NORMAL_RUN or
//! STOP_STALL, no swap, near or far target, no fault or a stall (8 input vectors per plant,
//! 8^N per tick). The FAM's step is heavy (five parallel regions, position arithmetic), so this
//! measures the engine where the IR step dominates, unlike the counters of `explore`.
//!
//! The product space is far too large to exhaust for N >= 2, so the run stops at
//! `MAX_STATES` (an honest limit: everything before it is explored exactly as in a full run).
//!
//! `cargo bench -p statecheck-explicit --bench fam -- [N] [MAX_STATES] [THREADS] [BACKEND]`
//! (defaults 2 2000000 0 native; 0 threads = all cores; BACKEND `native`, `interpreter` or
//! `auto`). Prints states/s, transitions/s and bytes per state.

mod common;

use statecheck_explicit::{verify, Options};

/// Wiring of `FamEnv` to `Fam` (the outputs of the environment chart).
const WIRES: [&str; 10] = [
    "targetPos",
    "stallNow",
    "hslFault",
    "epmFault",
    "otFault",
    "cofNow",
    "fbfFault",
    "ccfFault",
    "powerLoss",
    "saveFails",
];

/// The model the benchmark's charts come from (it imports the FAM chart from lib/).
const FAM_ALONE: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../examples/fam/fam_alone.sc"
);

fn model(n: usize) -> Result<String, String> {
    let path = FAM_ALONE;
    let text = std::fs::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
    let charts = text
        .split("\nsystem ")
        .next()
        .ok_or("fam_alone.sc has no system")?;
    let mut sys = format!("{charts}\nsystem Bench {{\n  instance env[{n}]: FamEnv;\n  instance fam[{n}]: Fam;\n  order env, fam;\n");
    for i in 0..n {
        for w in WIRES {
            sys += &format!("  connect env[{i}].{w} -> fam[{i}].{w};\n");
        }
        sys += &format!(
            "  assume env[{i}].fault == NONE || env[{i}].fault == STALL;\n  assume !fam[{i}].swap;\n  assume fam[{i}].runMode == NORMAL_RUN || fam[{i}].runMode == STOP_STALL;\n  invariant stall_blocks_run_{i}: !(in(fam[{i}].stallHandler.stallMode) && in(fam[{i}].moveHandler.running)) assuming fam[{i}].runMode != FAILURE_RUN;\n  invariant pos_in_range_{i}: fam[{i}].actualPos >= 0 && fam[{i}].actualPos <= 4095;\n"
        );
    }
    sys += "}\n";
    Ok(sys)
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let arg = |i: usize, d: u64| args.get(i).and_then(|s| s.parse().ok()).unwrap_or(d);
    let (n, max_states, threads) = (arg(0, 2) as usize, arg(1, 2_000_000), arg(2, 0) as usize);
    let text = match model(n) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let program = common::bench_program(FAM_ALONE, &text);
    let backend = common::backend(args.get(3));
    let opts = Options {
        threads,
        backend,
        compiler: Some(std::sync::Arc::new(statecheck_native::CCompiler)),
        max_states: Some(max_states),
        ..Options::default()
    };
    let report = match verify(&program, &opts, None) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    let s = &report.stats;
    println!(
        "model: {n} FAM plants, branching {} ({:?} after assumes), {} state bits",
        s.branching, s.branching_after_assumes, s.state_bits
    );
    println!(
        "states: {}, transitions: {}, depth: {}, stopped by: {}",
        s.states,
        s.transitions,
        s.depth,
        s.limit
            .as_ref()
            .map_or("nothing (complete)".into(), |l| l.describe())
    );
    println!(
        "threads: {}, time: {:.3} s",
        s.threads,
        s.time.as_secs_f64()
    );
    println!("{}", common::backend_line(s, backend));
    println!("states/s: {:.0}", s.states_per_s());
    println!(
        "transitions/s: {:.0}",
        s.transitions as f64 / s.time.as_secs_f64().max(1e-9)
    );
    println!("bytes/state (visited set): {:.2}", s.bytes_per_state());
    for r in &report.results {
        println!("  {} {}: {}", r.kind.as_str(), r.name, r.verdict.as_str());
    }
}
