//! Signal correspondence on an AIGER file: sizes before and after, then IC3 on both.
//!
//! `cargo run --release -p statecheck-symbolic --example reduce -- FILE.aig [TIMEOUT_S [ic3|kind|bmc]]`

use statecheck_symbolic::engine::{Limits, Outcome};
use std::time::{Duration, Instant};

fn verdict(o: &Outcome) -> String {
    match o {
        Outcome::Reached(t) => format!("violated ({} frames)", t.inputs.len()),
        Outcome::Proved(inv) => format!(
            "proved ({})",
            inv.as_ref().map_or("no invariant".to_string(), |i| format!(
                "{} clauses",
                i.len()
            ))
        ),
        Outcome::Bounded(k) => format!("bounded {k}"),
        Outcome::Unknown { why: w, .. } => format!("unknown: {w}"),
    }
}

/// This thread's user plus system CPU seconds (Linux `/proc`; 0 elsewhere).
fn thread_cpu() -> f64 {
    let Ok(text) = std::fs::read_to_string("/proc/thread-self/stat") else {
        return 0.0;
    };
    let rest = text.rsplit_once(')').map_or("", |(_, r)| r);
    let f: Vec<&str> = rest.split_whitespace().collect();
    let tick = |i: usize| f.get(i).and_then(|x| x.parse::<f64>().ok()).unwrap_or(0.0);
    (tick(11) + tick(12)) / 100.0
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(path) = args.first() else {
        eprintln!("usage: reduce FILE.aig [TIMEOUT_S]");
        std::process::exit(2);
    };
    let secs: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(60);
    let bytes = std::fs::read(path).unwrap_or_else(|e| {
        eprintln!("{path}: {e}");
        std::process::exit(2)
    });
    let aig = match statecheck_symbolic::aiger::parse(&bytes) {
        Ok(a) => a.reduced(),
        Err(e) => {
            eprintln!("{path}: {e}");
            std::process::exit(2)
        }
    };
    let mut only_c = aig.clone();
    only_c.bad.clear();
    let cone = only_c.cone();
    let c_ands = (0..aig.nodes.len())
        .filter(|&v| cone[v] && matches!(aig.nodes[v], statecheck_symbolic::aig::Node::And(..)))
        .count();
    println!(
        "circuit: {} inputs, {} latches, {} ands, {} constraints (cone: {c_ands} ands)",
        aig.inputs.len(),
        aig.latches.len(),
        aig.num_ands(),
        aig.constraints.len()
    );
    let lim = || Limits {
        deadline: Some(Instant::now() + Duration::from_secs(secs)),
        ..Limits::default()
    };
    let cpu0 = thread_cpu();
    let r = match statecheck_symbolic::scorr::reduce(&aig, &lim()) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("reduction stopped: {e}");
            std::process::exit(3)
        }
    };
    let s = &r.stats;
    println!(
        "scorr: latches {} -> {}, ands {} -> {}, merged {}, rounds {}, SAT calls {}, refuted {}, {:.2} s",
        s.latches.0, s.latches.1, s.ands.0, s.ands.1, s.merged, s.rounds, s.calls, s.refuted,
        s.time.as_secs_f64()
    );
    let t = Instant::now();
    let cpu1 = thread_cpu();
    println!("scorr cpu {:.2} s", cpu1 - cpu0);
    if let Some(out) = std::env::var_os("REDUCED_AIG") {
        let bytes = statecheck_symbolic::aiger::binary(&r.aig, "reduced by scorr");
        if let Err(e) = std::fs::write(&out, bytes) {
            eprintln!("cannot write the reduced circuit: {e}");
        }
    }
    let engine = args.get(2).map_or("ic3", String::as_str);
    let out = match engine {
        "kind" => statecheck_symbolic::kind::kind(&r.aig, &lim()),
        "bmc" => statecheck_symbolic::bmc::bmc(&r.aig, &lim()),
        _ => {
            let (out, st) = statecheck_symbolic::ic3::ic3_with_stats(&r.aig, &lim());
            println!("ic3: {st:?}");
            out
        }
    };
    let out = r.lift(&aig, out);
    println!(
        "{engine} on reduced: {} in {:.2} s (cpu {:.2} s)",
        verdict(&out),
        t.elapsed().as_secs_f64(),
        thread_cpu() - cpu1
    );
}
