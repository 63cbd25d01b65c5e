//! Throughput benchmark of the explicit engine on a scalable model: `N` independent modulo
//! counters `int[0..M]`, each incremented by its own input event, with an `assume` that at most
//! one event is present per tick (so N + 1 transitions per state, (M+1)^N states).
//!
//! `cargo bench -p statecheck-explicit --bench explore -- [N] [M] [THREADS] [BACKEND]`
//! (defaults 4 63 0 native; 0 threads = all cores; BACKEND `native`, `interpreter` or
//! `auto`). Prints states/s and bytes stored per state.

mod common;

use statecheck_explicit::{verify, Options};

fn model(n: usize, m: usize) -> String {
    let mut pairs = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            pairs.push(format!("!(k[{i}].inc && k[{j}].inc)"));
        }
    }
    let assume = if pairs.is_empty() {
        String::new()
    } else {
        format!("  assume {};\n", pairs.join(" && "))
    };
    format!(
        "chart Counter {{\n  input event inc;\n  output c: int[0..{m}] = 0;\n  initial Run;\n  state Run {{\n    on inc [c < {m}] / {{ c += 1; }};\n    on inc / {{ c = 0; }};\n  }}\n}}\nsystem Bench {{\n  instance k[{n}]: Counter;\n{assume}  invariant bounded: k[0].c <= {m};\n}}\n"
    )
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let arg = |i: usize, d: usize| args.get(i).and_then(|s| s.parse().ok()).unwrap_or(d);
    let (n, m, threads) = (arg(0, 4), arg(1, 63), arg(2, 0));
    let backend = common::backend(args.get(3));
    let text = model(n, m);
    let program = common::bench_program("bench.sc", &text);
    let opts = Options {
        threads,
        backend,
        compiler: Some(std::sync::Arc::new(statecheck_native::CCompiler)),
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
    let expected = ((m + 1) as u64).pow(n as u32) + 1;
    println!(
        "model: {n} counters int[0..{m}], branching {} (N+1 after assume), {} state bits",
        s.branching, s.state_bits
    );
    println!(
        "states: {} (expected {expected}), transitions: {}, depth: {}",
        s.states, s.transitions, s.depth
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
    println!(
        "peak memory estimate: {}",
        statecheck_explicit::human_bytes(s.peak_memory_bytes)
    );
    for r in &report.results {
        println!("  {} {}: {}", r.kind.as_str(), r.name, r.verdict.as_str());
    }
    if s.states != expected {
        eprintln!("state count mismatch");
        std::process::exit(1);
    }
}
