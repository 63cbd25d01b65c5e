//! CaDiCaL doubles its per-variable tables when the variables pass their room (hundreds of MB
//! at once on a large unrolling, between two readings of the resident set): the solver asks
//! the memory limit with the bytes about to be allocated first, and stops growing when they
//! would pass it. (The probe is the process's: these tests have a binary of their own.)

use statecheck_symbolic::aig::{Aig, Lit};
use statecheck_symbolic::check::Engine;
use statecheck_symbolic::engine::{set_memory_probe, Limits, Outcome, MEMORY_LIMIT};
use statecheck_symbolic::sat::Solver;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Bytes per variable of room the solver announces (`sat::BYTES_PER_VAR`).
const PER_VAR: u64 = 192;

/// One test (the probe is the process's, and tests of one binary run on parallel threads).
#[test]
fn solvers_and_engines_grow_only_with_the_memory_limits_consent() {
    the_tables_grow_only_with_the_memory_limits_consent();
    every_engine_stops_at_the_memory_limit_before_its_solver_grows_past_it();
}

fn the_tables_grow_only_with_the_memory_limits_consent() {
    // The probe refuses any growth of 1 MiB or more and records what it was asked. By hand:
    // CaDiCaL's room starts at one more than the first variable count (1 variable, the
    // constant, so 2) and doubles: 2 → 4 → … → 8192, each step announcing the added room
    // times 192 bytes (2·192 for the first, then 2, 4, …, 4096 times 192). The doubling from
    // 8192 to 16384 announces 8192·192 = 1.5 MiB: refused when the 8192nd variable is
    // declared, i.e. the clause on variable index 8191 (index 0 is the constant).
    let asked = Arc::new(Mutex::new(Vec::new()));
    let seen = Arc::clone(&asked);
    set_memory_probe(Some(Arc::new(move |extra: u64| {
        if extra > 0 {
            seen.lock().unwrap_or_else(|e| e.into_inner()).push(extra);
        }
        extra >= 1 << 20
    })));
    let mut s = Solver::new();
    let mut refused_at = None;
    for k in 1..20_000u32 {
        let v = s.fresh();
        assert_eq!(v.var(), k);
        s.add(&[v]);
        if s.over() {
            refused_at = Some(k);
            break;
        }
    }
    assert_eq!(refused_at, Some(8191));
    assert_eq!(
        s.solve(&[]),
        None,
        "a solver over the limit answers unknown"
    );
    let mut want = vec![2 * PER_VAR];
    let mut room = 2u64;
    while room <= 8192 {
        want.push(room * PER_VAR);
        room *= 2;
    }
    assert_eq!(*asked.lock().unwrap_or_else(|e| e.into_inner()), want);

    // Without a limit the same clauses are declared and satisfiable.
    set_memory_probe(None);
    let mut s = Solver::new();
    for _ in 1..20_000u32 {
        let v = s.fresh();
        s.add(&[v]);
    }
    assert!(!s.over());
    assert_eq!(s.solve(&[]), Some(true));
}

/// The pigeonhole formula with 12 pigeons and 11 holes as a circuit without latches (the one
/// of `sat_limits.rs`): 132 inputs and over 800 AND gates, so its encoding passes 512
/// variables, whose doubling to 1024 announces 512·192 = 96 KiB.
fn pigeonhole() -> Aig {
    let mut g = Aig::new();
    let p: Vec<Vec<Lit>> = (0..12)
        .map(|_| (0..11).map(|_| g.input(None)).collect())
        .collect();
    let mut all = Vec::new();
    for row in &p {
        let some = g.or_all(row.iter().copied());
        all.push(some);
    }
    for h in 0..11 {
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

fn every_engine_stops_at_the_memory_limit_before_its_solver_grows_past_it() {
    // A limit of 64 KiB of growth: every engine's first solver needs more, so each ends with
    // the memory limit before its first SAT call (which on this formula would outlast the
    // test; the deadline is only a safety net, its reason would fail the assertion).
    for engine in [Engine::Bmc, Engine::Kind, Engine::Ic3] {
        // Like the CLI's, the probe keeps answering "over" once it has (the run is stopped).
        let over = Arc::new(AtomicBool::new(false));
        set_memory_probe(Some(Arc::new(move |extra: u64| {
            if extra >= 64 << 10 {
                over.store(true, Ordering::Relaxed);
            }
            over.load(Ordering::Relaxed)
        })));
        let lim = Limits {
            deadline: Some(Instant::now() + Duration::from_secs(60)),
            ..Limits::default()
        };
        match engine.run(&pigeonhole(), &lim) {
            Outcome::Unknown { why, .. } => assert_eq!(why, MEMORY_LIMIT, "{}", engine.as_str()),
            other => panic!("{}: expected unknown, got {other:?}", engine.as_str()),
        }
    }
    set_memory_probe(None);
}
