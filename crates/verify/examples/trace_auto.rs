//! The auto schedule as it runs: every event of [`statecheck_verify::verify`] with the wall
//! clock, the process's CPU time and (for a SAT engine's events, which come from its own
//! thread) that engine's thread CPU time, so that one can see which engine spends the cores
//! on which property.
//!
//! `cargo run --release -p statecheck-verify --example trace_auto -- MODEL.sc [SYSTEM [ENGINE [TIMEOUT_S]]]`

use statecheck_verify::{verify, Engine, Event, ExplicitOptions, Options};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// User plus system CPU seconds from a `/proc` stat file (Linux; 0 elsewhere), in clock
/// ticks of 1/100 s.
fn cpu(stat: &str) -> f64 {
    let Ok(text) = std::fs::read_to_string(stat) else {
        return 0.0;
    };
    // Fields after the command name (which may hold spaces) in parentheses.
    let rest = text.rsplit_once(')').map_or("", |(_, r)| r);
    let f: Vec<&str> = rest.split_whitespace().collect();
    let tick = |i: usize| f.get(i).and_then(|x| x.parse::<f64>().ok()).unwrap_or(0.0);
    (tick(11) + tick(12)) / 100.0
}

fn process_cpu() -> f64 {
    cpu("/proc/self/stat")
}

fn thread_cpu() -> f64 {
    cpu("/proc/thread-self/stat")
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(path) = args.first() else {
        eprintln!("usage: trace_auto MODEL.sc [SYSTEM [ENGINE [TIMEOUT_S]]]");
        std::process::exit(2);
    };
    let src = std::fs::read_to_string(path).unwrap_or_else(|e| {
        eprintln!("{path}: {e}");
        std::process::exit(2)
    });
    let file = statecheck_model::imports::load_with(path, src, |k| std::fs::read_to_string(k).ok());
    let (model, diags) = statecheck_model::check(&file.file);
    if file.diags.iter().chain(&diags).any(|d| d.is_error()) {
        eprintln!("{path}: does not check");
        std::process::exit(1);
    }
    let sys = match args.get(1).filter(|s| s.as_str() != "-") {
        Some(name) => model.systems.iter().find(|s| &s.name == name),
        // As the CLI chooses: the one system written as such.
        None => model.systems.iter().find(|s| !s.implicit),
    };
    let Some(sys) = sys else {
        eprintln!("{path}: no such system");
        std::process::exit(1);
    };
    let program = statecheck_ir::lower(&model, sys).unwrap_or_else(|e| {
        eprintln!("{path}: {e:?}");
        std::process::exit(1)
    });
    let engine = match args.get(2).map(String::as_str) {
        Some("explicit") => Engine::Explicit,
        Some("bmc") => Engine::Bmc,
        Some("kind") => Engine::Kind,
        Some("ic3") => Engine::Ic3,
        _ => Engine::Auto,
    };
    let check = ExplicitOptions {
        timeout: args
            .get(3)
            .and_then(|s| s.parse().ok())
            .map(Duration::from_secs),
        ..ExplicitOptions::default()
    };
    let names: Vec<String> = statecheck_verify::row_names(&program, &[]);
    let t0 = Instant::now();
    let last_depth = AtomicU64::new(u64::MAX);
    let stamp = || {
        format!(
            "{:7.2}s cpu {:7.2}s",
            t0.elapsed().as_secs_f64(),
            process_cpu()
        )
    };
    let events = |e: Event| match e {
        Event::Decided {
            index,
            result,
            meta,
        } => println!(
            "{} DECIDED {:<45} {:<10} by {:<8} attempt {:.2}s {}",
            stamp(),
            names.get(index).map_or("?", String::as_str),
            format!("{:?}", result.verdict),
            meta.engine,
            meta.time_s.unwrap_or(0.0),
            meta.reason.as_deref().unwrap_or("")
        ),
        Event::Working {
            engine,
            index,
            budget,
        } => println!(
            "{} {:<4} (thread cpu {:7.2}s) works on {} budget {:?}",
            stamp(),
            engine,
            thread_cpu(),
            names.get(index).map_or("?", String::as_str),
            budget
        ),
        Event::Idle { engine } => println!(
            "{} {:<4} (thread cpu {:7.2}s) idle",
            stamp(),
            engine,
            thread_cpu()
        ),
        Event::Progress(p) if last_depth.swap(p.depth, Ordering::Relaxed) != p.depth => {
            println!("{} explicit depth {} states {}", stamp(), p.depth, p.states);
        }
        _ => {}
    };
    match verify(&program, &Options::new(engine, check), &events) {
        Ok(_) => println!("{} end", stamp()),
        Err(e) => println!("{} error {e}", stamp()),
    }
}
