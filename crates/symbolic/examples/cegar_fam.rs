//! Figures of the localization engine on one model: `cargo run --release -p
//! statecheck-symbolic --example cegar_fam -- FILE [PROPERTY...] [--timeout S]`. For each own
//! property: the verdict, the latches of the reduced circuit and of the last abstraction, the
//! refinements and the time (the signal-correspondence reduction, shared, is timed once).

use statecheck_symbolic::engine::{Limits, Outcome};
use std::time::{Duration, Instant};

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let mut timeout = 300u64;
    if let Some(i) = args.iter().position(|a| a == "--timeout") {
        timeout = args.get(i + 1).and_then(|s| s.parse().ok()).unwrap_or(300);
        args.drain(i..(i + 2).min(args.len()));
    }
    // `--blasted`: localize the circuit as blasted instead of its reduction.
    let blasted = args.iter().any(|a| a == "--blasted");
    args.retain(|a| a != "--blasted");
    // `--retimed`: localize each property's retimed problem, reducing each abstraction (what
    // `--engine cegar` does), instead of the whole circuit's reduction.
    let retimed = args.iter().any(|a| a == "--retimed");
    args.retain(|a| a != "--retimed");
    let Some(file) = args.first().cloned() else {
        eprintln!("usage: cegar_fam FILE [PROPERTY...] [--timeout S]");
        std::process::exit(2);
    };
    let wanted: Vec<String> = args[1..].to_vec();
    let src = std::fs::read_to_string(&file).unwrap_or_default();
    let loaded =
        statecheck_model::imports::load_with(&file, src, |k| std::fs::read_to_string(k).ok());
    let (model, diags) = statecheck_model::check(&loaded.file);
    for d in loaded.diags.iter().chain(&diags).filter(|d| d.is_error()) {
        eprintln!("{file}: {d:?}");
    }
    // The system the entry file declares (imports may declare others).
    let root = std::fs::read_to_string(&file).unwrap_or_default();
    let declared = |name: &str| root.contains(&format!("system {name} "));
    let Some(sys) = model.systems.iter().rev().find(|s| declared(&s.name)) else {
        eprintln!("{file}: no system");
        std::process::exit(1);
    };
    let Ok(p) = statecheck_ir::lower(&model, sys) else {
        eprintln!("{file}: does not lower");
        std::process::exit(1);
    };
    let bl = statecheck_symbolic::blast::blast(&p);
    let shared = bl.shared_problem();
    println!(
        "{file}: system {}, {} properties, {} latches blasted",
        sys.name,
        bl.props.len(),
        shared.aig.latches.len()
    );
    if retimed {
        for (i, prop) in bl.props.iter().enumerate() {
            if !wanted.is_empty() && !wanted.contains(&prop.name) {
                continue;
            }
            let Some((g, _)) = bl.retimed_problem(i) else {
                continue;
            };
            let lim = Limits {
                deadline: Some(Instant::now() + Duration::from_secs(timeout)),
                ..Limits::default()
            };
            let t = Instant::now();
            let mut progress = Default::default();
            let (out, st) = statecheck_symbolic::localize::cegar_reducing(&g, &lim, &mut progress);
            println!(
                "{:45} {:25} {:6.1} s  kept {}/{} (reduced {}, reductions {:.1} s)  refinements {} depths {:?}",
                prop.name,
                verdict(out),
                t.elapsed().as_secs_f64(),
                st.kept,
                st.latches,
                st.reduced,
                st.reduce_time.as_secs_f64(),
                st.refinements,
                st.depths
            );
        }
        return;
    }
    let t = Instant::now();
    let lim = Limits::default();
    let red = if blasted {
        None
    } else {
        statecheck_symbolic::scorr::reduce(&shared.aig, &lim).ok()
    };
    if !blasted && red.is_none() {
        eprintln!("reduction stopped");
        std::process::exit(1);
    }
    if let Some(red) = &red {
        println!(
            "{file}: latches {} -> {} after scorr ({:.1} s)",
            red.stats.latches.0,
            red.stats.latches.1,
            t.elapsed().as_secs_f64()
        );
    }
    for (i, prop) in bl.props.iter().enumerate() {
        if !wanted.is_empty() && !wanted.contains(&prop.name) {
            continue;
        }
        let Some(k) = shared.bad_index[i] else {
            continue;
        };
        let g = match &red {
            Some(red) => red.with_bad(k).aig,
            None => shared.with_bad(k),
        };
        let lim = Limits {
            deadline: Some(Instant::now() + Duration::from_secs(timeout)),
            ..Limits::default()
        };
        let t = Instant::now();
        let (out, st) = statecheck_symbolic::localize::cegar_with_lemmas(&g, &lim, &Vec::new());
        let verdict = verdict(out);
        println!(
            "{:45} {:25} {:6.1} s  kept {}/{}  refinements {} depths {:?}",
            prop.name,
            verdict,
            t.elapsed().as_secs_f64(),
            st.kept,
            st.latches,
            st.refinements,
            st.depths
        );
    }
}

fn verdict(out: Outcome) -> String {
    match out {
        Outcome::Proved(_) => "proved".to_string(),
        Outcome::Reached(t) => format!("reached at {} frames", t.inputs.len()),
        Outcome::Bounded(k) => format!("bounded {k}"),
        Outcome::Unknown { why: w, .. } => format!("unknown ({w})"),
    }
}
