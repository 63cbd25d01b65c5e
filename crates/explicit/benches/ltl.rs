//! Throughput of the explicit LTL check (position graph, then the product with each `ltl`
//! property's Büchi automaton and the fair-cycle search), on a model file's system `Bench`.
//!
//! `cargo bench -p statecheck-explicit --bench ltl -- FILE.sc`: one line per `ltl` property
//! with the graph's states and positions, the product's states, the times and the product
//! states per second (what SPIN's `pan -a` reports as "states, stored" per second of its
//! "elapsed time"). `scripts/bench_ltl_spin.sh` runs it next to SPIN on the same models.

use statecheck_explicit::ltl::{buchi, graph, product};
use statecheck_ir::temporal::TemporalFormula;
use statecheck_ir::Program;
use std::time::Instant;

/// Parse, check and lower system `Bench` of `text`; a model that fails is reported and
/// exited on.
fn bench_program(text: &str) -> Program {
    let (file, diags) = statecheck_syntax::parse(text);
    let (model, more) = statecheck_model::check(&file);
    if let Some(d) = diags.iter().chain(&more).find(|d| d.is_error()) {
        eprintln!("model does not check: {d:?}");
        std::process::exit(1);
    }
    let Some(sys) = model.system("Bench") else {
        eprintln!("no system Bench");
        std::process::exit(1);
    };
    match statecheck_ir::lower(&model, sys) {
        Ok(p) => p,
        Err(d) => {
            eprintln!("lowering failed: {d:?}");
            std::process::exit(1);
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let Some(path) = args.first() else {
        eprintln!("usage: cargo bench -p statecheck-explicit --bench ltl -- FILE.sc");
        std::process::exit(2);
    };
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("{path}: {e}");
            std::process::exit(2);
        }
    };
    let program = bench_program(&text);
    // One graph with the atoms of every property, as `verify` builds it.
    let mut atoms = Vec::new();
    let mut automata = Vec::new();
    for t in &program.temporal {
        if let TemporalFormula::Ltl(f) = &t.formula {
            match buchi::translate(&f.clone().negate(), &mut atoms) {
                Ok(a) => automata.push((t.name.clone(), a)),
                Err(e) => {
                    eprintln!("{}: automaton too large: {e:?}", t.name);
                    std::process::exit(1);
                }
            }
        }
    }
    let t0 = Instant::now();
    let g = match graph::build(&program, &atoms, graph::GraphLimits::default()) {
        Ok(g) => g,
        Err(why) => {
            eprintln!("graph not built: {why:?}");
            std::process::exit(1);
        }
    };
    let graph_s = t0.elapsed().as_secs_f64();
    println!(
        "graph: {} states, {} positions, {} transitions, {:.3} s, {:.1} bytes/state",
        g.n_states(),
        g.n_nodes(),
        g.transitions,
        graph_s,
        g.bytes() as f64 / g.n_states().max(1) as f64
    );
    for (name, a) in &automata {
        let t1 = Instant::now();
        let (r, n) = product::find_lasso_counted(&g, a, &product::FairBits::default(), u64::MAX);
        let prod_s = t1.elapsed().as_secs_f64();
        let verdict = match r {
            Ok(None) => "proved".to_string(),
            Ok(Some(l)) => format!("violated (lasso of {} ticks)", l.inputs.len()),
            Err(_) => "unknown".to_string(),
        };
        let total = graph_s + prod_s;
        println!(
            "ours {name}: {verdict}; automaton {} states; product {n} states; graph {graph_s:.3} s + product {prod_s:.3} s = {total:.3} s; {:.0} product states/s",
            a.states.len(),
            n as f64 / total.max(1e-9)
        );
    }
}
