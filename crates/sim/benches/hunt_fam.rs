//! Benchmark: how soon the lasso hunt (`statecheck_sim::hunt`) finds the FAM closed loop's
//! liveness counterexamples (examples/fam/liveness, docs/case-studies/temporal.md), over
//! several seeds and bus sizes. Figures, never a timed test: for each (N, seed) the seconds to
//! each property's lasso, or `-` when none was found by the deadline; then per N how many
//! seeds found each property and the median time of those that did.
//!
//! ```text
//! cargo bench -p statecheck-sim --bench hunt_fam
//! HUNT_N="1 2" HUNT_SEEDS=8 HUNT_FIRST_SEED=0 HUNT_TIMEOUT=60 HUNT_THREADS=2 \
//!   HUNT_PROPS="stall_procedure_completes" cargo bench -p statecheck-sim --bench hunt_fam
//! ```
//!
//! One hunt per thread (`HUNT_THREADS`, default 2), each hunting every property of
//! `HUNT_PROPS` at once, as `verify --engine auto` does (one hunt for the open LTL rows).

use statecheck_sim::hunt::{hunt, HuntOptions};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// Per property: the seconds to its lasso and the lasso's ticks, when one was found.
type Row = Vec<Option<(f64, usize)>>;

fn env(name: &str, default: &str) -> String {
    std::env::var(name).unwrap_or_else(|_| default.to_string())
}

fn program(n: usize) -> statecheck_ir::Program {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../../examples/fam/liveness");
    let (file, system) = if n == 1 {
        (format!("{root}/fam_live.sc"), "FamLive".to_string())
    } else {
        (format!("{root}/fam_live{n}.sc"), format!("FamLive{n}"))
    };
    let text = std::fs::read_to_string(&file).expect("the FAM liveness example");
    let loaded =
        statecheck_model::imports::load_with(&file, text, |k| std::fs::read_to_string(k).ok());
    let (model, diags) = statecheck_model::check(&loaded.file);
    assert!(
        loaded.diags.iter().chain(&diags).all(|d| !d.is_error()),
        "{file} has errors"
    );
    let sys = model
        .systems
        .iter()
        .find(|s| s.name == system)
        .expect("the system");
    statecheck_ir::lower(&model, sys).expect("lowers")
}

fn main() {
    let ns: Vec<usize> = env("HUNT_N", "1 2 3 4 5")
        .split_whitespace()
        .filter_map(|x| x.parse().ok())
        .collect();
    let seeds: u64 = env("HUNT_SEEDS", "4").parse().unwrap_or(4);
    let first_seed: u64 = env("HUNT_FIRST_SEED", "0").parse().unwrap_or(0);
    let timeout: f64 = env("HUNT_TIMEOUT", "60").parse().unwrap_or(60.0);
    let threads: usize = env("HUNT_THREADS", "2").parse().unwrap_or(2);
    let props: Vec<String> = env(
        "HUNT_PROPS",
        "stall_procedure_completes recalibrates_after_failure reaches_target \
         stall_procedure_completes_unless_permanent recalibrates_with_end_stops \
         reaches_target_with_end_stops",
    )
    .split_whitespace()
    .map(String::from)
    .collect();
    println!(
        "lasso hunt on the FAM closed loop: N = {ns:?}, {seeds} seeds, {timeout} s each, {threads} threads"
    );
    for &n in &ns {
        let p = program(n);
        let targets: Vec<usize> = props
            .iter()
            .map(|name| {
                p.temporal
                    .iter()
                    .position(|t| &t.name == name)
                    .expect("property in the example")
            })
            .collect();
        // found[seed][k]: seconds to property k's lasso (and its ticks), if found.
        let found: Mutex<Vec<Row>> = Mutex::new(vec![vec![None; targets.len()]; seeds as usize]);
        let next = AtomicUsize::new(0);
        std::thread::scope(|s| {
            for _ in 0..threads {
                s.spawn(|| loop {
                    let seed = next.fetch_add(1, Ordering::Relaxed);
                    if seed >= seeds as usize {
                        break;
                    }
                    let start = Instant::now();
                    let opts = HuntOptions {
                        seed: first_seed + seed as u64,
                        deadline: Some(start + Duration::from_secs_f64(timeout)),
                        ..HuntOptions::default()
                    };
                    let mine: Mutex<Row> = Mutex::new(vec![None; targets.len()]);
                    let open = |t: usize| {
                        let k = targets.iter().position(|&u| u == t);
                        k.is_some_and(|k| mine.lock().map(|m| m[k].is_none()).unwrap_or(false))
                    };
                    hunt(&p, &targets, &opts, &open, &mut |f| {
                        if let Some(k) = targets.iter().position(|&u| u == f.property) {
                            if let Ok(mut m) = mine.lock() {
                                m[k] = Some((start.elapsed().as_secs_f64(), f.inputs.len()));
                            }
                        }
                    });
                    let row = mine.into_inner().unwrap_or_default();
                    let cells: Vec<String> = row
                        .iter()
                        .map(|c| match c {
                            Some((t, ticks)) => format!("{t:6.1} s ({ticks} ticks)"),
                            None => "     -".to_string(),
                        })
                        .collect();
                    let shown = first_seed + seed as u64;
                    println!("N = {n} seed {shown:2}: {}", cells.join("  "));
                    if let Ok(mut f) = found.lock() {
                        f[seed] = row;
                    }
                });
            }
        });
        let found = found.into_inner().unwrap_or_default();
        for (k, name) in props.iter().enumerate() {
            let mut times: Vec<f64> = found.iter().filter_map(|r| r[k].map(|x| x.0)).collect();
            times.sort_by(f64::total_cmp);
            let median = times
                .get(times.len() / 2)
                .map_or("-".to_string(), |t| format!("{t:.1} s"));
            println!(
                "N = {n}: {name}: found by {} of {seeds} seeds within {timeout} s, median {median}",
                times.len()
            );
        }
    }
}
