//! A limit that expires inside a SAT call is reported as that limit, not as a failure of the
//! solver: BMC, k-induction and IC3 on a circuit whose very first query is the pigeonhole
//! formula with 12 pigeons and 11 holes (unsatisfiable, and exponential for resolution, so
//! CaDiCaL is still inside that first call when the limit expires, however fast the machine).
//! Whether the limit expires before or inside the call, the reason must name it; before the
//! fix an expiry inside the call read "the SAT solver failed".

use statecheck_symbolic::aig::{Aig, Lit};
use statecheck_symbolic::check::Engine;
use statecheck_symbolic::engine::{Limits, Outcome, MEMORY_LIMIT, SOLVER_FAILED};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Pigeons and holes of the formula.
const PIGEONS: usize = 12;
const HOLES: usize = 11;

/// A circuit without latches whose bad output is "the inputs put every pigeon in a hole and
/// no two pigeons in one hole": never true (there are more pigeons than holes), so no engine
/// may report it reached, and deciding it takes CaDiCaL far longer than these tests wait.
fn pigeonhole() -> Aig {
    let mut g = Aig::new();
    let p: Vec<Vec<Lit>> = (0..PIGEONS)
        .map(|_| (0..HOLES).map(|_| g.input(None)).collect())
        .collect();
    let mut all = Vec::new();
    for row in &p {
        let some = g.or_all(row.iter().copied());
        all.push(some);
    }
    for h in 0..HOLES {
        for (a, pa) in p.iter().enumerate() {
            for pb in &p[a + 1..] {
                let both = g.and(pa[h], pb[h]);
                all.push(!both);
            }
        }
    }
    let bad = g.and_all(all);
    g.bad.push(bad);
    g
}

const ENGINES: [Engine; 3] = [Engine::Bmc, Engine::Kind, Engine::Ic3];

fn reason(out: Outcome, engine: Engine) -> String {
    match out {
        Outcome::Unknown { why, .. } => why,
        other => panic!("{}: expected unknown, got {other:?}", engine.as_str()),
    }
}

#[test]
fn a_deadline_inside_a_sat_call_is_reported_as_the_time_limit() {
    let g = pigeonhole();
    for engine in ENGINES {
        let lim = Limits {
            deadline: Some(Instant::now() + Duration::from_millis(300)),
            ..Limits::default()
        };
        let why = reason(engine.run(&g, &lim), engine);
        assert_eq!(why, "time limit reached", "{}", engine.as_str());
    }
}

#[test]
fn an_attempt_budget_inside_a_sat_call_is_reported_as_that_budget() {
    let g = pigeonhole();
    for engine in ENGINES {
        let lim = Limits {
            attempt_deadline: Some(Instant::now() + Duration::from_millis(300)),
            ..Limits::default()
        };
        let why = reason(engine.run(&g, &lim), engine);
        assert_eq!(
            why,
            "time budget of this attempt used up",
            "{}",
            engine.as_str()
        );
    }
}

#[test]
fn a_stop_flag_raised_during_a_sat_call_is_reported_as_the_stop() {
    let g = pigeonhole();
    for engine in ENGINES {
        let flag = Arc::new(AtomicBool::new(false));
        let raiser = {
            let flag = Arc::clone(&flag);
            std::thread::spawn(move || {
                std::thread::sleep(Duration::from_millis(300));
                flag.store(true, Ordering::Relaxed);
            })
        };
        let lim = Limits {
            stop: Some(flag),
            ..Limits::default()
        };
        let why = reason(engine.run(&g, &lim), engine);
        let _ = raiser.join();
        assert_ne!(why, SOLVER_FAILED, "{}", engine.as_str());
        assert_eq!(why, "another engine answered first", "{}", engine.as_str());
    }
}

#[test]
fn the_memory_probe_stops_every_engine_inside_a_sat_call() {
    // The probe is the process's; it answers "over" only on this test's thread (the other
    // tests of this file run beside it) and only once a flag is raised 300 ms in, while the
    // engine is inside its first SAT call: no watchdog thread, no stop flag.
    let g = pigeonhole();
    let me = std::thread::current().id();
    let over = Arc::new(AtomicBool::new(false));
    let probe_over = Arc::clone(&over);
    statecheck_symbolic::engine::set_memory_probe(Some(Arc::new(move |_extra: u64| {
        std::thread::current().id() == me && probe_over.load(Ordering::Relaxed)
    })));
    for engine in ENGINES {
        over.store(false, Ordering::Relaxed);
        let raiser = {
            let over = Arc::clone(&over);
            std::thread::spawn(move || {
                std::thread::sleep(Duration::from_millis(300));
                over.store(true, Ordering::Relaxed);
            })
        };
        let why = reason(engine.run(&g, &Limits::default()), engine);
        let _ = raiser.join();
        assert_eq!(why, MEMORY_LIMIT, "{}", engine.as_str());
    }
    statecheck_symbolic::engine::set_memory_probe(None);
}
