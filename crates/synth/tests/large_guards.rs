//! A supervisor whose guard is a parity function over ten automata — 512 DNF clauses of ten
//! atoms, which no two-level minimisation shortens — is emitted, re-read by the parser (no
//! E0013: long chains are balanced), lowered and checked in the closed loop, with both
//! engines.

use statecheck_synth::problem::{Automaton, Event, Kind, Pred, NONE};
use statecheck_synth::{check, emit, synthesize, Engine, Outcome, Problem};

const K: usize = 10;

/// Switches `a0..a9` (Off/On, toggled by uncontrollable `t_i`, both states marked) and a
/// gate `g` (Idle -go-> Done -back-> Idle, `go` controllable, `back` uncontrollable; the
/// toggles are in its alphabet as self-loops of Idle, so nothing toggles while it is Done).
/// Requirement: never Done with an odd number of switches On.
///
/// By hand: every switch vector is reachable in Idle (2^10 = 1024 states, each with 10 toggle
/// transitions); `go` is allowed exactly where the parity is even (512 states and
/// transitions) and leads to Done with the same vector (512 states, each with `back`). A
/// Done state with odd parity is forbidden, and it can only be entered by `go`, which is
/// controllable, so nothing else is removed. Supervisor: 1024 + 512 = 1536 states,
/// 10240 + 512 + 512 = 11264 transitions.
fn parity_problem() -> Problem {
    let mut events: Vec<Event> = (0..K)
        .map(|i| Event {
            name: format!("t{i}"),
            controllable: false,
        })
        .collect();
    events.push(Event {
        name: "go".into(),
        controllable: true,
    });
    events.push(Event {
        name: "back".into(),
        controllable: false,
    });
    let n = events.len();
    let (go, back) = (K as u32, K as u32 + 1);
    let mut automata = Vec::new();
    for i in 0..K {
        let mut next = vec![NONE; 2 * n];
        next[i] = 1;
        next[n + i] = 0;
        automata.push(Automaton {
            name: format!("a{i}"),
            chart: format!("Switch{i}"),
            kind: Kind::Plant,
            locs: vec!["Off".into(), "On".into()],
            marked: vec![true, true],
            initial: 0,
            alphabet: vec![i as u32],
            next,
            n_events: n,
        });
    }
    let mut next = vec![NONE; 2 * n];
    next[..K].fill(0);
    next[go as usize] = 1;
    next[n + back as usize] = 0;
    let mut alphabet: Vec<u32> = (0..K as u32).collect();
    alphabet.extend([go, back]);
    automata.push(Automaton {
        name: "g".into(),
        chart: "Gate".into(),
        kind: Kind::Plant,
        locs: vec!["Idle".into(), "Done".into()],
        marked: vec![true, true],
        initial: 0,
        alphabet,
        next,
        n_events: n,
    });
    // Odd parity as a balanced tree of XORs: x ^ y = (x && !y) || (!x && y).
    let xor = |x: Pred, y: Pred| {
        Pred::Or(
            Box::new(Pred::And(
                Box::new(x.clone()),
                Box::new(Pred::Not(Box::new(y.clone()))),
            )),
            Box::new(Pred::And(Box::new(Pred::Not(Box::new(x))), Box::new(y))),
        )
    };
    let mut level: Vec<Pred> = (0..K as u32).map(|i| Pred::At(i, 1)).collect();
    while level.len() > 1 {
        let mut next = Vec::new();
        let mut it = level.into_iter();
        while let Some(a) = it.next() {
            next.push(match it.next() {
                Some(b) => xor(a, b),
                None => a,
            });
        }
        level = next;
    }
    let odd = level.pop().expect("ten switches");
    Problem {
        name: "Parity".into(),
        events,
        automata,
        never: vec![Pred::And(Box::new(Pred::At(K as u32, 1)), Box::new(odd))],
        needs: Vec::new(),
    }
}

#[test]
fn parity_guard_reloads_and_checks() {
    let p = parity_problem();
    for engine in [Engine::Explicit, Engine::Symbolic] {
        let s = synthesize(&p, engine).expect("synthesis");
        let Outcome::Supervisor(sup) = s.outcome else {
            panic!("{engine:?}: no supervisor");
        };
        assert_eq!((sup.states, sup.transitions), (1536, 11264), "{engine:?}");
        // The guard of `go` has 512 clauses (or its negation does): parity has no shorter DNF.
        let go = &sup.guards[0];
        assert_eq!(go.allow.clauses.len(), 512, "{engine:?}");
        let text = emit::emit(&p, &sup, "parity");
        assert!(text.len() > 50_000, "{}", text.len());
        let (file, diags) = statecheck_syntax::parse(&text);
        assert!(
            diags.is_empty(),
            "{engine:?}: {:?}",
            &diags[..diags.len().min(3)]
        );
        let (model, diags) = statecheck_model::check(&file);
        assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
        let sys = model.systems.iter().find(|s| !s.implicit).expect("system");
        let program = statecheck_ir::lower(&model, sys).expect("lower");
        let r = check::check(&p, &model, &program).expect("check runs");
        assert!(r.violations.is_empty(), "{engine:?}: {:?}", r.violations);
        assert_eq!(r.plant_states, 1536, "{engine:?}");
    }
}

/// Guards honour the budget: with the stop flag raised after the fixpoint, building the
/// parity guard (512 clauses, so the optimised DNF runs) ends with a limit in phase `guards`
/// instead of running on; without limits the same call gives the guard.
#[test]
fn guard_building_stops_at_the_limit() {
    use statecheck_synth::{encode::Encoding, explicit, guards, Budget, ErrorKind, Limits};
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::Arc;
    let p = parity_problem();
    let stop = Arc::new(AtomicBool::new(false));
    let budget = Budget::new(&Limits {
        stop: Some(stop.clone()),
        ..Limits::default()
    });
    let x = explicit::run(&p, &budget).expect("no limit hit yet");
    assert_eq!(x.size(), 1536);
    let enc = Encoding::new(&p);
    assert_eq!(
        guards::explicit_guards(&p, &x, &enc, &budget)
            .map(|g| g.len())
            .ok(),
        Some(1)
    );
    stop.store(true, Ordering::Relaxed);
    match guards::explicit_guards(&p, &x, &enc, &budget) {
        Err(e) => match e.kind {
            ErrorKind::Limit { partial, .. } => assert_eq!(partial.phase, "guards"),
            other => panic!("not a limit: {other:?}"),
        },
        Ok(_) => panic!("the raised stop flag was ignored"),
    }
}

/// A ring of `L` = 600 locations: uncontrollable `adv` moves l → l+1 (mod L), controllable
/// `home` moves every location to 0; every location marked, no requirement.
///
/// By hand: all L locations are reachable (adv) and marked, nothing is forbidden, so the
/// supervisor is the plant: L states, 2·L transitions (one `adv` and one `home` each).
/// The emitted supervisor updates the mirror `at_ring` on each event with one branch per
/// source location: 600 mutually exclusive cases, which used to be one `else if` chain 600
/// levels deep — more nesting than the parser accepts (E0013 above 256).
#[test]
fn an_automaton_with_hundreds_of_transitions_on_one_event_reloads() {
    const L: u32 = 600;
    let events = vec![
        Event {
            name: "adv".into(),
            controllable: false,
        },
        Event {
            name: "home".into(),
            controllable: true,
        },
    ];
    let n = events.len();
    let mut next = vec![NONE; L as usize * n];
    for l in 0..L {
        next[(l as usize) * n] = (l + 1) % L;
        next[(l as usize) * n + 1] = 0;
    }
    let p = Problem {
        name: "Ring".into(),
        events,
        automata: vec![Automaton {
            name: "ring".into(),
            chart: "Ring".into(),
            kind: Kind::Plant,
            locs: (0..L).map(|l| format!("L{l}")).collect(),
            marked: vec![true; L as usize],
            initial: 0,
            alphabet: vec![0, 1],
            next,
            n_events: n,
        }],
        never: Vec::new(),
        needs: Vec::new(),
    };
    let s = synthesize(&p, Engine::Explicit).expect("synthesis");
    let Outcome::Supervisor(sup) = s.outcome else {
        panic!("no supervisor");
    };
    assert_eq!((sup.states, sup.transitions), (600, 1200));
    let text = emit::emit(&p, &sup, "ring");
    let (file, diags) = statecheck_syntax::parse(&text);
    assert!(diags.is_empty(), "{:?}", &diags[..diags.len().min(3)]);
    let (model, diags) = statecheck_model::check(&file);
    assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
    let sys = model.systems.iter().find(|s| !s.implicit).expect("system");
    let program = statecheck_ir::lower(&model, sys).expect("lower");
    let r = check::check(&p, &model, &program).expect("check runs");
    assert!(r.violations.is_empty(), "{:?}", r.violations);
    assert_eq!(r.plant_states, 600);
}
