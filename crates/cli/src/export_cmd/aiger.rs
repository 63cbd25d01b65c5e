//! `statecheck export aiger`: one property of a system as an AIGER 1.9 file (bad-state output,
//! invariant constraint, symbol table), for ABC and other hardware model checkers; an `ltl`
//! property (or unbounded `respond`) as a justice property (the step in product with the
//! Büchi automaton of its negation, the `fair` constraints among the justice literals).

use crate::load;
use anyhow::{bail, Result};
use clap::Args;

/// Arguments of `statecheck export aiger`.
#[derive(Args)]
pub struct AigerArgs {
    /// The `.sc` model file.
    model: String,
    /// The system (or chart).
    #[arg(long)]
    system: Option<String>,
    /// The property (built-ins may be named too).
    #[arg(long, value_name = "NAME")]
    property: String,
    /// The output file: `.aag` (ASCII) or `.aig` (binary).
    #[arg(short, long, value_name = "FILE")]
    output: String,
    /// For a temporal property: write it in ABC's own liveness convention instead of AIGER
    /// 1.9's justice section (outputs `assume_fair_K` and `assert_fair_0`, the constraint
    /// folded into a latch; binary `.aig` only), for ABC builds that do not read justice
    /// sections: `berkeley-abc -c "read F.aig; l2s; logic; undc; strash; zero; pdr"`.
    #[arg(long)]
    abc_liveness: bool,
    /// For a temporal property: write it for ABC's k-liveness command `kcs` (one output
    /// `csLiveTarget_0`, false exactly at the accepting ticks, the justice and fairness
    /// literals merged into one, the constraint folded into a latch; binary `.aig` only):
    /// `berkeley-abc -c "read F.aig; kcs"` prints "Property proved" when the property holds.
    #[arg(long, conflicts_with = "abc_liveness")]
    abc_kcs: bool,
}

/// Run the command; returns the exit code.
pub fn run(a: AigerArgs) -> Result<u8> {
    let binary = if a.output.ends_with(".aig") {
        true
    } else if a.output.ends_with(".aag") {
        false
    } else {
        bail!("the output file must end in .aag (ASCII) or .aig (binary)");
    };
    let loaded = load::load(&a.model, false)?;
    let sys = loaded.system(a.system.as_deref())?;
    let program = loaded.lower(sys)?;
    if program.temporal.iter().any(|t| t.name == a.property) {
        if (a.abc_liveness || a.abc_kcs) && !binary {
            bail!(
                "--{} writes binary AIGER: name the output file .aig",
                abc_flag(&a)
            );
        }
        return justice(&a, &loaded.path, &program, binary);
    }
    if a.abc_liveness || a.abc_kcs {
        bail!(
            "--{} is for temporal properties; `{}` is a safety property (export it without the flag)",
            abc_flag(&a),
            a.property
        );
    }
    let (bl, idx) =
        statecheck_symbolic::check::problems(&program, std::slice::from_ref(&a.property))
            .map_err(|e| anyhow::anyhow!(e))?;
    let Some(&(pi, kind)) = idx.first() else {
        bail!("no property named `{}`", a.property);
    };
    let aig = bl.problem(pi);
    let meaning = if bl.props[pi].reachable {
        "the bad output is the target: reachable = witness exists"
    } else {
        "the bad output is a violation: unreachable = the property holds"
    };
    let comment = format!(
        "statecheck export of {} system {} property {} ({})\n{meaning}\none AIGER step = one tick; constraint = assumes hold and no other run-time error",
        loaded.path,
        program.name,
        a.property,
        kind.as_str()
    );
    let bytes = if binary {
        statecheck_symbolic::aiger::binary(&aig, &comment)
    } else {
        statecheck_symbolic::aiger::ascii(&aig, &comment)
    };
    crate::outpath::write(std::path::Path::new(&a.output), &bytes)?;
    eprintln!(
        "wrote {}: {} inputs, {} latches, {} AND gates, 1 bad output, {} constraint(s)",
        a.output,
        aig.inputs.len(),
        aig.latches.len(),
        aig.num_ands(),
        aig.constraints.len()
    );
    Ok(0)
}

/// Write temporal property `a.property` as one AIGER justice property.
fn justice(
    a: &AigerArgs,
    path: &str,
    program: &statecheck_ir::Program,
    binary: bool,
) -> Result<u8> {
    let bl = statecheck_symbolic::blast::blast(program);
    let j = match statecheck_symbolic::live::justice_of(program, &bl, &a.property) {
        Some(Ok(j)) => j,
        Some(Err(why)) => bail!("`{}` cannot be exported to AIGER: {why}", a.property),
        None => bail!("no property named `{}`", a.property),
    };
    let Some(aig) = j.to_aiger(&a.property) else {
        bail!(
            "`{}` cannot be exported to AIGER: the system has compassion constraints \
             (`fair p => q`), which AIGER 1.9 cannot state",
            a.property
        );
    };
    let comment = format!(
        "statecheck export of {path} system {} property {} (temporal)\n\
         justice property 0: a run on which each of its literals holds infinitely often violates it\n\
         one AIGER step = one tick; inputs after the model's choose the Büchi automaton's state; \
         constraint = assumes hold, no run-time error, the automaton reads the position",
        program.name, a.property
    );
    let bytes = if a.abc_liveness {
        let comment = format!(
            "{comment}\nin ABC's liveness convention: outputs assume_fair_K hold infinitely often and assert_fair_0 not on a counterexample; latch `ok`: every step so far met the constraint"
        );
        match statecheck_symbolic::aiger::abc_liveness(&aig, &comment) {
            Some(b) => b,
            None => bail!("`{}` has no justice property to write", a.property),
        }
    } else if a.abc_kcs {
        let comment = format!(
            "{comment}\nfor ABC's kcs: output csLiveTarget_0 is false exactly at the accepting ticks (the literals merged by latches seen_K); the property holds iff it is eventually always true; latch `ok`: every step so far met the constraint"
        );
        match statecheck_symbolic::aiger::abc_kcs(&aig, &comment) {
            Some(b) => b,
            None => bail!("`{}` has no justice property to write", a.property),
        }
    } else if binary {
        statecheck_symbolic::aiger::binary(&aig, &comment)
    } else {
        statecheck_symbolic::aiger::ascii(&aig, &comment)
    };
    crate::outpath::write(std::path::Path::new(&a.output), &bytes)?;
    eprintln!(
        "wrote {}: {} inputs, {} latches, {} AND gates, 1 justice property of {} literal(s), {} constraint(s)",
        a.output,
        aig.inputs.len(),
        aig.latches.len(),
        aig.num_ands(),
        aig.justice.first().map_or(0, Vec::len),
        aig.constraints.len()
    );
    Ok(0)
}

/// The ABC convention flag given, for messages.
fn abc_flag(a: &AigerArgs) -> &'static str {
    if a.abc_kcs {
        "abc-kcs"
    } else {
        "abc-liveness"
    }
}
