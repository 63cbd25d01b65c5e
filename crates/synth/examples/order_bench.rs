//! Measure the symbolic engine's variable order on one family instance:
//! `order_bench tl|dp|cm|at|bw|ta N K` prints, for the instance order and for FORCE
//! (`statecheck_synth::order`), the hyperedge span, the wall time of the
//! symbolic fixpoint, the reachable product and the supervisor size; then the explicit engine.
use statecheck_synth::{explicit, extract, families, order, symbolic, Budget, Limits};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [family, n, k] = args.as_slice() else {
        eprintln!("order_bench tl|dp|cm|at|bw|ta N K");
        std::process::exit(2);
    };
    let (Ok(n), Ok(k)) = (n.parse(), k.parse()) else {
        eprintln!("N and K are numbers");
        std::process::exit(2);
    };
    let Some(text) = families::scaled::generate(family, n, k) else {
        eprintln!("unknown family or parameters out of range");
        std::process::exit(2);
    };
    let (file, _) = statecheck_syntax::parse(&text);
    let (model, _) = statecheck_model::check(&file);
    let Ok(sys) = extract::find_system(&model, None) else {
        eprintln!("no system");
        std::process::exit(1);
    };
    let p = match extract::extract(&model, sys) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e:?}");
            std::process::exit(1);
        }
    };
    let budget = Budget::new(&Limits::default());
    let force = order::force(&p);
    let id: Vec<usize> = (0..p.automata.len()).collect();
    for (name, ord) in [("instance", &id), ("force", &force)] {
        let (_, span) = order::spans(&p, ord);
        let t = Instant::now();
        match symbolic::run_ordered(&p, &budget, ord) {
            Ok(s) => println!(
                "{family}({n},{k}) symbolic {name:8} span {span:5} {:8.3}s product {} supervisor {} rounds {}",
                t.elapsed().as_secs_f64(),
                s.product.cardinality(),
                s.reach.cardinality(),
                s.rounds
            ),
            Err(e) => println!("{family}({n},{k}) symbolic {name}: {e:?}"),
        }
    }
    let t = Instant::now();
    match explicit::run(&p, &budget) {
        Ok(x) => println!(
            "{family}({n},{k}) explicit                  {:8.3}s product {} supervisor {}",
            t.elapsed().as_secs_f64(),
            x.product_states,
            x.size()
        ),
        Err(e) => println!("{family}({n},{k}) explicit: {e:?}"),
    }
}
