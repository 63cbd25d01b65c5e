//! Liveness verdicts equal ABC's: every `ltl` property of `tests/verify/temporal.sc` (but the
//! system with compassion, which AIGER cannot state), exported as an AIGER justice property (what `statecheck
//! export aiger` writes), read back, decided by our SAT engines (liveness-to-safety with IC3
//! and BMC, k-liveness) and by ABC's `l2s` then `pdr` — an independent implementation of the
//! Biere–Artho–Schuppan reduction and of IC3.
//!
//! This ABC version does not read AIGER's justice sections, so the test hands it the same
//! circuit in ABC's own liveness convention (`aiger::abc_liveness`, what `statecheck export
//! aiger --abc-liveness` writes): the justice literals as outputs named `assume_fair_K`, a
//! constant-false `assert_fair_0`, and the invariant constraint folded into a latch.
//!
//! The same properties also go to ABC's k-liveness, `kcs` (`aiger::abc_kcs`, what `statecheck
//! export aiger --abc-kcs` writes: one output `csLiveTarget_0`, false at the accepting ticks).
//! `kcs` only proves: every property that holds must be proved by it, and no violated one may
//! be, however many k it tries in its time (it reports "DISPROVED" for each).
//!
//! Needs `berkeley-abc`; without it the tests print why and pass.

use statecheck_symbolic::aig::Aig;
use statecheck_symbolic::aiger::{abc_kcs, abc_liveness, binary, parse};
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
    // k-liveness only proves: on a violated property it counts up until its deadline.
    let short = Limits {
        deadline: Some(Instant::now() + Duration::from_secs(3)),
        ..Limits::default()
    };
    let by_klive = check_justice(&j, Method::KLive, &short);
    match (&by_l2s, &by_bmc, &by_klive) {
        (LiveOutcome::Proved, LiveOutcome::Bounded(_), LiveOutcome::Proved) => Some(true),
        (LiveOutcome::Lasso { .. }, LiveOutcome::Lasso { .. }, LiveOutcome::Unknown(_)) => {
            Some(false)
        }
        other => panic!("our engines disagree or give up: {other:?}"),
    }
}

/// Every `ltl` property of [`MODELS`] AIGER can state, exported as a justice property and read
/// back through our binary AIGER: `(system.property, circuit)`.
fn exported() -> Vec<(String, Aig)> {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../..");
    let mut all = Vec::new();
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
                all.push((format!("{}.{}", sys.name, t.name), back));
            }
        }
    }
    all
}

fn abc_missing() -> bool {
    let missing = Command::new("berkeley-abc").arg("-h").output().is_err();
    if missing {
        eprintln!("SKIPPED: berkeley-abc is not installed (apt-get install berkeley-abc)");
    }
    missing
}

fn scratch(tag: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("statecheck-abc-{tag}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

#[test]
fn liveness_verdicts_equal_abc_l2s_pdr() {
    if abc_missing() {
        return;
    }
    let dir = scratch("live");
    let (mut agreed, mut holds, mut fails) = (0, 0, 0);
    for (name, back) in exported() {
        let path = dir.join(format!("{name}.aig"));
        let abc_form = abc_liveness(&back, "").expect("a justice property");
        std::fs::write(&path, abc_form).expect("write");
        let Some(abc) = abc_verdict(&path.to_string_lossy()) else {
            panic!("{name}: ABC gave no verdict");
        };
        let ours = ours(&back);
        assert_eq!(ours, Some(abc), "{name}: ours vs ABC");
        eprintln!("{name}: {}", if abc { "holds" } else { "violated" });
        agreed += 1;
        if abc {
            holds += 1;
        } else {
            fails += 1;
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    eprintln!("{agreed} liveness verdicts equal ABC's ({holds} hold, {fails} violated)");
    assert!(
        holds >= 3 && fails >= 3,
        "too few of each: {holds} hold, {fails} violated"
    );
}

/// What ABC's `kcs` printed in `secs` seconds (line-buffered, so a run ended by the timeout
/// keeps its lines): `(proved, disproved k's)`.
fn kcs(file: &str, secs: u32) -> (bool, usize) {
    let out = Command::new("timeout")
        .arg(secs.to_string())
        .args(["stdbuf", "-oL", "berkeley-abc", "-c"])
        .arg(format!("read {file}; kcs"))
        .output()
        .expect("timeout, stdbuf and berkeley-abc run");
    let text = String::from_utf8_lossy(&out.stdout);
    (
        text.contains("Property proved"),
        text.matches("Property DISPROVED").count(),
    )
}

#[test]
fn liveness_proofs_equal_abc_kcs() {
    if abc_missing() {
        return;
    }
    let dir = scratch("kcs");
    let (mut proved, mut refused) = (0, 0);
    for (name, back) in exported() {
        let path = dir.join(format!("{name}.aig"));
        std::fs::write(&path, abc_kcs(&back, "").expect("a justice property")).expect("write");
        let holds = ours(&back).expect("our engines decide it");
        // A proof comes at a small k on these models (at most k = 4); a violated property is
        // given 4 s, in which kcs tries dozens of k.
        let (abc_proved, disproved) = kcs(&path.to_string_lossy(), if holds { 60 } else { 4 });
        assert_eq!(
            abc_proved, holds,
            "{name}: kcs proved = {abc_proved}, ours holds = {holds}"
        );
        if holds {
            proved += 1;
        } else {
            assert!(disproved >= 10, "{name}: kcs tried only {disproved} k");
            refused += 1;
        }
        eprintln!("{name}: holds = {holds}, kcs: proved = {abc_proved}, {disproved} k disproved");
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        proved >= 3 && refused >= 3,
        "too few of each: {proved} proved, {refused} violated"
    );
}
