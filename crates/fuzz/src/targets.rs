//! The fuzz targets. Each takes arbitrary bytes; a panic, an abort or a run longer than the
//! runner's timeout is a bug, and so is an `Err` (a broken promise of the target).

use statecheck_ir::{Machine, Program};

/// Which part of statecheck a target drives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// Parse, check, lower every system, and run two ticks of each lowered program.
    Check,
    /// Parse a scenario against a lowered model and replay its first ticks.
    Scenario,
    /// Read an AIGER file; when it parses, write it (ASCII and binary) and read it back.
    Aiger,
    /// Format a text that parses: the result parses to the same tree and formats to itself.
    Fmt,
    /// The runner's self-test: `panic`, `abort`, `hang` and `deep` (stack overflow) inputs.
    SelfTest,
}

/// The four real targets, in the order the runner visits them.
pub const ALL: [Target; 4] = [Target::Check, Target::Scenario, Target::Aiger, Target::Fmt];

impl Target {
    /// The target's name on the command line and in file names.
    pub fn name(self) -> &'static str {
        match self {
            Target::Check => "check",
            Target::Scenario => "scenario",
            Target::Aiger => "aiger",
            Target::Fmt => "fmt",
            Target::SelfTest => "selftest",
        }
    }

    /// The target named `s`.
    pub fn from_name(s: &str) -> Option<Target> {
        [
            Target::Check,
            Target::Scenario,
            Target::Aiger,
            Target::Fmt,
            Target::SelfTest,
        ]
        .into_iter()
        .find(|t| t.name() == s)
    }
}

/// Models the scenario target reads scenarios against (indexed by a seed's `ctx`).
#[derive(Default)]
pub struct Context {
    /// Lowered programs.
    pub programs: Vec<Program>,
}

/// Ticks of a scenario the target replays at most.
const REPLAY_TICKS: usize = 64;

/// Run `target` on `input`. `ctx` is the index of the context program (scenario target).
pub fn run(target: Target, input: &[u8], ctx: &Context, which: usize) -> Result<(), String> {
    match target {
        Target::Check => check(input),
        Target::Scenario => scenario(input, ctx, which),
        Target::Aiger => aiger(input),
        Target::Fmt => fmt(input),
        Target::SelfTest => selftest(input),
    }
}

fn text(input: &[u8]) -> std::borrow::Cow<'_, str> {
    String::from_utf8_lossy(input)
}

fn check(input: &[u8]) -> Result<(), String> {
    let src = text(input);
    let (file, d1) = statecheck_syntax::parse(&src);
    let (model, d2) = statecheck_model::check(&file);
    if d1.iter().chain(&d2).any(|d| d.is_error()) {
        return Ok(());
    }
    for sys in &model.systems {
        let Ok(p) = statecheck_ir::lower(&model, sys) else {
            continue;
        };
        let mut m = Machine::new(&p);
        for _ in 0..2 {
            if m.step().is_err() {
                break;
            }
        }
    }
    Ok(())
}

fn scenario(input: &[u8], ctx: &Context, which: usize) -> Result<(), String> {
    let Some(p) = ctx.programs.get(which) else {
        return Ok(());
    };
    let src = text(input);
    let Ok(s) = statecheck_sim::scenario::parse(&src, p) else {
        return Ok(());
    };
    let mut m = Machine::new(p);
    for tick in s.ticks().take(REPLAY_TICKS) {
        for &(i, v) in tick {
            let Some(inp) = p.inputs.get(i) else {
                return Err(format!("scenario names input {i} of {}", p.inputs.len()));
            };
            let sl = &p.slots[inp.slot as usize];
            if v < sl.lo || v > sl.hi {
                return Err(format!("scenario value {v} outside {}..{}", sl.lo, sl.hi));
            }
            m.set(inp.slot, v);
        }
        if m.step().is_err() {
            break;
        }
    }
    // What the reader accepted, written again, reads back the same.
    let again = statecheck_sim::scenario::format(&s, p);
    match statecheck_sim::scenario::parse(&again, p) {
        Ok(back) if back == s => Ok(()),
        Ok(_) => Err("a scenario written back reads differently".into()),
        Err(e) => Err(format!("a scenario written back does not read: {e:?}")),
    }
}

fn aiger(input: &[u8]) -> Result<(), String> {
    let Ok(g) = statecheck_symbolic::aiger::parse(input) else {
        return Ok(());
    };
    for (how, bytes) in [
        ("ascii", statecheck_symbolic::aiger::ascii(&g, "fuzz")),
        ("binary", statecheck_symbolic::aiger::binary(&g, "fuzz")),
    ] {
        let back = statecheck_symbolic::aiger::parse(&bytes)
            .map_err(|e| format!("written {how}, does not read back: {e}"))?;
        if back.inputs.len() != g.inputs.len()
            || back.latches.len() != g.latches.len()
            || back.bad.len() != g.bad.len()
            || back.constraints.len() != g.constraints.len()
        {
            return Err(format!("written {how}, reads back with other sizes"));
        }
    }
    let _ = g.reduced();
    Ok(())
}

/// The `Debug` form of a parsed tree with every span erased.
pub fn tree_without_spans(src: &str) -> String {
    let (file, _) = statecheck_syntax::parse(src);
    let s = format!("{file:?}");
    let mut out = String::with_capacity(s.len());
    let mut rest = s.as_str();
    while let Some(i) = rest.find("Span {") {
        out.push_str(&rest[..i]);
        out.push_str("Span");
        let after = &rest[i..];
        let close = after.find('}').map_or(after.len(), |j| j + 1);
        rest = &after[close..];
    }
    out.push_str(rest);
    out
}

fn fmt(input: &[u8]) -> Result<(), String> {
    let src = text(input);
    let Ok(once) = statecheck_syntax::format::format(&src) else {
        return Ok(());
    };
    let twice = statecheck_syntax::format::format(&once)
        .map_err(|e| format!("the formatted text does not parse: {e}"))?;
    if twice != once {
        return Err("formatting is not idempotent".into());
    }
    if tree_without_spans(&src) != tree_without_spans(&once) {
        return Err("formatting changed the syntax tree".into());
    }
    Ok(())
}

#[allow(clippy::only_used_in_recursion)] // reason: the recursion is the point (a stack overflow)
fn deep(n: u64, pad: [u64; 64]) -> u64 {
    if n == 0 {
        return pad[0];
    }
    deep(n - 1, std::hint::black_box(pad)).wrapping_add(1)
}

fn selftest(input: &[u8]) -> Result<(), String> {
    match input {
        b"panic" => panic!("self-test panic"),
        b"abort" => std::process::abort(),
        b"hang" => loop {
            std::thread::sleep(std::time::Duration::from_millis(50));
        },
        b"deep" => {
            let _ = std::hint::black_box(deep(u64::MAX, [1; 64]));
            Ok(())
        }
        b"broken" => Err("self-test broken promise".into()),
        _ => Ok(()),
    }
}
