//! Liveness verdicts equal ABC's: every `ltl` property of `tests/verify/temporal.sc` (but the
//! system with compassion, which AIGER cannot state), exported as an AIGER justice property (what `statecheck
//! export aiger` writes), read back, decided by our SAT engines (liveness-to-safety with IC3
//! and BMC, k-liveness) and by ABC's `l2s` then `pdr` — an independent implementation of the
//! Biere–Artho–Schuppan reduction and of IC3.
//!
//! This ABC version does not read AIGER's justice sections, so the test hands it the same
//! circuit in ABC's own liveness convention: the justice literals as outputs named
//! `assume_fair_K`, a constant-false `assert_fair_0` (a loop on which every `assume_fair`
//! signal holds and the `assert_fair` one does not is a counterexample), and the invariant
//! constraint folded into a latch "every step so far was allowed" that gates the signals.
//!
//! Needs `berkeley-abc`; without it the test prints why and passes.

use statecheck_symbolic::aig::{Aig, Lit};
use statecheck_symbolic::aiger::{binary, parse};
use statecheck_symbolic::blast::blast;
use statecheck_symbolic::check::Engine;
use statecheck_symbolic::engine::Limits;
use statecheck_symbolic::live::{check_justice, justice_of, Justice, LiveOutcome, Method};
use std::process::Command;
use std::time::{Duration, Instant};

/// The models and systems compared.
const MODELS: &[(&str, &[&str])] = &[(
    "tests/verify/temporal.sc",
    &["Free", "FairInc", "NoReset", "NoCompassion", "Deadlock"],
)];

/// Justice property 0 of `j` in ABC's liveness convention (module doc), as binary AIGER.
fn abc_form(j: &Aig) -> Vec<u8> {
    let mut g = j.clone();
    let cons = g.constraints.clone();
    let c = g.and_all(cons);
    let ok = g.latch(Some(true), Some("ok".into()));
    let ok_now = g.and(ok, c);
    let oi = g.latches.len() - 1;
    g.set_next(oi, ok_now);
    g.constraints.clear();
    let mut outs = Vec::new();
    let mut names = Vec::new();
    let signals: Vec<Lit> = j.justice[0].iter().chain(&j.fairness).copied().collect();
    for (k, l) in signals.into_iter().enumerate() {
        outs.push(g.and(l, ok_now));
        names.push(Some(format!("assume_fair_{k}")));
    }
    outs.push(Lit::FALSE);
    names.push(Some("assert_fair_0".to_string()));
    g.bad = outs;
    g.bad_names = vec![None; names.len()];
    g.input_names = vec![None; g.inputs.len()];
    g.latch_names = vec![None; g.latches.len()];
    g.justice.clear();
    g.justice_names.clear();
    g.fairness.clear();
    // This ABC reads binary AIGER only, and names outputs, not bad states: our writer puts
    // bad outputs where AIGER 1.0 puts outputs, so only the header's counts change, and the
    // symbols are appended after the AND gates.
    let bytes = binary(&g, "");
    let nl = bytes.iter().position(|&b| b == b'\n').expect("header");
    let h: Vec<u64> = std::str::from_utf8(&bytes[..nl])
        .expect("header")
        .split(' ')
        .skip(1)
        .map(|x| x.parse().expect("number"))
        .collect();
    let mut out = format!("aig {} {} {} {} {}", h[0], h[1], h[2], h[5], h[4]).into_bytes();
    out.extend_from_slice(&bytes[nl..]);
    for (k, n) in names.iter().enumerate() {
        out.extend_from_slice(format!("o{k} {}\n", n.as_deref().unwrap_or("")).as_bytes());
    }
    out
}

fn abc_verdict(file: &str) -> Option<bool> {
    let out = Command::new("timeout")
        .args(["60", "berkeley-abc", "-c"])
        .arg(format!("read {file}; l2s; logic; undc; strash; zero; pdr"))
        .output()
        .ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    if text.contains("Property proved") {
        Some(true)
    } else if text.contains("was asserted in frame") {
        Some(false)
    } else {
        eprintln!("{text}");
        None
    }
}

/// Our verdict on the justice property of a file: `true` = holds.
fn ours(g: &Aig) -> Option<bool> {
    let j = Justice::from_aiger(g, 0);
    let lim = || Limits {
        deadline: Some(Instant::now() + Duration::from_secs(30)),
        max_depth: Some(60),
        ..Limits::default()
    };
    let by_l2s = check_justice(&j, Method::L2s(Engine::Ic3), &lim());
    let by_bmc = check_justice(&j, Method::L2s(Engine::Bmc), &lim());
    let by_klive = check_justice(&j, Method::KLive, &lim());
    match (&by_l2s, &by_bmc, &by_klive) {
        (LiveOutcome::Proved, LiveOutcome::Bounded(_), LiveOutcome::Proved) => Some(true),
        (LiveOutcome::Lasso { .. }, LiveOutcome::Lasso { .. }, LiveOutcome::Unknown(_)) => {
            Some(false)
        }
        other => panic!("our engines disagree or give up: {other:?}"),
    }
}

#[test]
fn liveness_verdicts_equal_abc_l2s_pdr() {
    if Command::new("berkeley-abc").arg("-h").output().is_err() {
        eprintln!("SKIPPED: berkeley-abc is not installed (apt-get install berkeley-abc)");
        return;
    }
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let dir = std::env::temp_dir().join(format!("statecheck-abc-live-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let (mut agreed, mut holds, mut fails) = (0, 0, 0);
    for (file, systems) in MODELS {
        let src = std::fs::read_to_string(format!("{root}/{file}")).expect("model");
        let (f, _) = statecheck_syntax::parse(&src);
        let (model, _) = statecheck_model::check(&f);
        for sys in &model.systems {
            if !systems.contains(&sys.name.as_str()) {
                continue;
            }
            let p = statecheck_ir::lower(&model, sys).expect("lowers");
            let bl = blast(&p);
            for t in &p.temporal {
                let Some(Ok(j)) = justice_of(&p, &bl, &t.name) else {
                    continue;
                };
                let Some(g) = j.to_aiger(&t.name) else {
                    continue;
                };
                // Through the file format both ways.
                let back = parse(&binary(&g, "")).expect("our binary AIGER reads back");
                assert_eq!(back.justice.len(), 1);
                let path = dir.join(format!("{}_{}.aig", sys.name, t.name));
                std::fs::write(&path, abc_form(&back)).expect("write");
                let Some(abc) = abc_verdict(&path.to_string_lossy()) else {
                    panic!("{file}: {}.{}: ABC gave no verdict", sys.name, t.name);
                };
                let ours = ours(&back);
                assert_eq!(
                    ours,
                    Some(abc),
                    "{file}: {}.{}: ours vs ABC",
                    sys.name,
                    t.name
                );
                eprintln!(
                    "{}.{}: {}",
                    sys.name,
                    t.name,
                    if abc { "holds" } else { "violated" }
                );
                agreed += 1;
                if abc {
                    holds += 1;
                } else {
                    fails += 1;
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    eprintln!("{agreed} liveness verdicts equal ABC's ({holds} hold, {fails} violated)");
    assert!(
        holds >= 3 && fails >= 3,
        "too few of each: {holds} hold, {fails} violated"
    );
}
