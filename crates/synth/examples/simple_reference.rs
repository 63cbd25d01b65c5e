//! A simple reference implementation of monolithic Ramadge–Wonham synthesis in Rust, kept
//! beside the benchmark (`examples/synthesis/bench.sh`) as the peer of the explicit engine:
//! the textbook algorithm written the obvious way, with none of the engine's data structures.
//! States are `Vec<u32>` location vectors in a `std::collections::HashMap` (SipHash), successors
//! and predecessors `Vec<Vec<(event, state)>>`, and the fixpoint repeats whole sweeps
//! (nonblocking: a backward search from the marked states; controllability: remove every state
//! with an uncontrollable edge into a removed one) until nothing changes. It uses only the
//! per-state queries of [`Problem`] (`successor`, `enabled_by`, `allowed`, `is_marked`,
//! `is_forbidden`), not the engines' code.
//!
//! `simple_reference FILE.sc [SYSTEM]` prints `simple-ref CPU_SECONDS product N supervisor S
//! states T transitions` (CPU seconds of the synthesis, after parsing, like `reference.py`).
use statecheck_synth::{extract, Kind, Problem};
use std::collections::HashMap;
use std::time::Instant;

/// Seconds of CPU time of this process (Linux), or `None`.
fn cpu() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    let rest = stat.rsplit_once(')')?.1;
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

/// Reachable product, supervisor states and transitions.
fn synthesize(p: &Problem) -> (usize, usize, usize) {
    let unc: Vec<bool> = p.events.iter().map(|e| !e.controllable).collect();
    let mut index: HashMap<Vec<u32>, usize> = HashMap::new();
    let mut states: Vec<Vec<u32>> = vec![p.initial()];
    index.insert(p.initial(), 0);
    let mut succ: Vec<Vec<(usize, usize)>> = Vec::new();
    let mut bad: Vec<bool> = Vec::new();
    let mut i = 0;
    while i < states.len() {
        let s = states[i].clone();
        let mut out = Vec::new();
        // `never` states are bad and not expanded.
        let mut is_bad = p.is_forbidden(&s);
        if !is_bad {
            for e in 0..p.events.len() as u32 {
                if !p.enabled_by(Kind::Plant, &s, e) {
                    continue;
                }
                let next = if p.allowed(&s, e) {
                    p.successor(&s, e)
                } else {
                    None
                };
                let Some(next) = next else {
                    // The plant can do it, a requirement forbids it.
                    is_bad |= unc[e as usize];
                    continue;
                };
                let j = match index.get(&next) {
                    Some(&j) => j,
                    None => {
                        let j = states.len();
                        index.insert(next.clone(), j);
                        states.push(next);
                        j
                    }
                };
                out.push((e as usize, j));
            }
        }
        succ.push(out);
        bad.push(is_bad);
        i += 1;
    }
    let n = states.len();
    let mut pred: Vec<Vec<(usize, usize)>> = vec![Vec::new(); n];
    for (s, out) in succ.iter().enumerate() {
        for &(e, t) in out {
            pred[t].push((s, e));
        }
    }
    let marked: Vec<bool> = states.iter().map(|s| p.is_marked(s)).collect();
    let mut alive: Vec<bool> = bad.iter().map(|b| !b).collect();
    loop {
        let before = alive.iter().filter(|a| **a).count();
        let mut co = vec![false; n];
        let mut stack: Vec<usize> = (0..n).filter(|&s| alive[s] && marked[s]).collect();
        for &s in &stack {
            co[s] = true;
        }
        while let Some(t) = stack.pop() {
            for &(s, _) in &pred[t] {
                if alive[s] && !co[s] {
                    co[s] = true;
                    stack.push(s);
                }
            }
        }
        for s in 0..n {
            alive[s] &= co[s];
        }
        let mut work: Vec<usize> = (0..n).filter(|&s| !alive[s]).collect();
        while let Some(t) = work.pop() {
            for &(s, e) in &pred[t] {
                if alive[s] && unc[e] {
                    alive[s] = false;
                    work.push(s);
                }
            }
        }
        if alive.iter().filter(|a| **a).count() == before {
            break;
        }
    }
    let mut kept = vec![false; n];
    if alive[0] {
        kept[0] = true;
        let mut stack = vec![0];
        while let Some(s) = stack.pop() {
            for &(_, t) in &succ[s] {
                if alive[t] && !kept[t] {
                    kept[t] = true;
                    stack.push(t);
                }
            }
        }
    }
    let trans = (0..n)
        .filter(|&s| kept[s])
        .map(|s| succ[s].iter().filter(|&&(_, t)| kept[t]).count())
        .sum();
    (n, kept.iter().filter(|k| **k).count(), trans)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(path) = args.first() else {
        eprintln!("simple_reference FILE.sc [SYSTEM]");
        std::process::exit(2);
    };
    let Ok(text) = std::fs::read_to_string(path) else {
        eprintln!("cannot read {path}");
        std::process::exit(2);
    };
    let (file, _) = statecheck_syntax::parse(&text);
    let (model, _) = statecheck_model::check(&file);
    let p = extract::find_system(&model, args.get(1).map(String::as_str))
        .ok()
        .and_then(|sys| extract::extract(&model, sys).ok());
    let Some(p) = p else {
        eprintln!("{path}: not a synthesis problem");
        std::process::exit(1);
    };
    let (t, c) = (Instant::now(), cpu());
    let (product, sup, trans) = synthesize(&p);
    let secs = match (c, cpu()) {
        (Some(a), Some(b)) => b - a,
        _ => t.elapsed().as_secs_f64(),
    };
    println!("simple-ref {secs:.3}s product {product} supervisor {sup} states {trans} transitions");
}
