//! Modelica generation in the structure of Donath, Haufe, Blochwitz and Neidhold, "A new
//! Approach for Modeling and Verification of Discrete Control Components within a Modelica
//! Environment" (§2.4, §3.2, §4.2): one `model` per system with
//!
//! - a state variable per hierarchy level whose type is an enumeration of the level's states
//!   plus `InActive` (`ctrl_goState` of type `Controller_GoStateT`), beside the IR's selector
//!   that keeps a composite's child while it is inactive (history and the IR's canonical
//!   state need it);
//! - input signals as `input` connectors, chart outputs as `output` variables, the IR's other
//!   slots as variables with `start` values (the paper's initialisation section);
//! - one `when sample(0, period)` clause: every sample instant is one tick of
//!   docs/semantics.md, translated statement by statement from the IR. Transitions are
//!   `if`-clauses on the level's state (`if ctrl_Go_active == Controller_GoStateT.GoLeft then
//!   if ctrl_Halt then ...`); entry activities are written where the IR runs them, marked
//!   `// entry of S`;
//! - on request, coverage counters (§3.2): an Integer vector counting the entries of each
//!   state and one counting the firings of each transition (and choice branch).
//!
//! The paper gathers entry activities in `when` clauses on a level's state variable. That
//! cannot reproduce the step semantics — a self-transition re-enters a state without changing
//! the variable, and entry actions run between the transition action and the next instance's
//! step — so the tick keeps the IR's order (docs/codegen.md lists every difference).
//! Run-time errors are `assert`s with the interpreter's site numbers; the system's `assume`s
//! are asserted before the tick and its properties after it, as `statecheck sim` checks them.

mod binary;
mod decl;
mod expr;
mod names;
mod runtime;
mod stmt;
mod text;
mod tick;

use crate::common::{area, Area, Source};
use decl::{declarations, period_ms, seconds};
use expr::{Emit, Used};
use names::Names;
use statecheck_ir::{CoverKind, Node, Program, Stmt};
use statecheck_model::Model;
use std::collections::BTreeSet;
use std::fmt::Write;

/// What the generated model contains beyond the step.
#[derive(Clone, Debug, Default)]
pub struct ModelicaOptions {
    /// Emit coverage counters (the paper's §3.2): `stateCoverage[i]` counts the entries of
    /// each state, `transitionCoverage[j]` the firings of each transition and choice branch.
    pub coverage: bool,
}

/// Why a program cannot be translated to Modelica.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ModelicaError(pub String);

impl std::fmt::Display for ModelicaError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ModelicaError {}

/// Generate the Modelica model of `p`, a lowered system of `model`.
///
/// Fails when a slot or constant does not fit a 32-bit Integer (the smallest Integer a
/// Modelica tool must provide) or when the program's shape is not translatable (a procedure
/// calling itself, an input written by the step).
pub fn generate(
    p: &Program,
    model: &Model,
    src: &Source,
    opts: &ModelicaOptions,
) -> Result<String, ModelicaError> {
    check_fits(p)?;
    let n = Names::new(p, model);
    let assigned = assigned_slots(p);
    if let Some(s) = assigned
        .iter()
        .find(|s| area(p, **s) == Area::Input)
        .and_then(|s| p.slots.get(*s as usize))
    {
        return Err(ModelicaError(format!(
            "the step writes the input `{}`; a Modelica input cannot be assigned",
            s.name
        )));
    }
    let counters = opts.coverage.then(|| counters(p, &n));
    let mut em = Emit {
        p,
        n: &n,
        src,
        counters: counters.as_deref(),
        out: String::new(),
        depth: 2,
        n_tmp: 0,
        n_tmpb: 0,
        used: Used::default(),
        stack: Vec::new(),
        error: None,
        written: 0,
    };
    tick::tick(&mut em);
    if let Some(e) = em.error.take() {
        return Err(ModelicaError(e));
    }
    let body = std::mem::take(&mut em.out);
    let mut o = String::new();
    declarations(&mut o, p, model, src, &n, &assigned, opts);
    let (n_tmp, n_tmpb) = (em.n_tmp, em.n_tmpb);
    if n_tmp + n_tmpb + p.n_locals > 0 {
        o.push_str("protected\n");
    }
    for (name, count, ty, what) in [
        (&n.tmp, n_tmp, "Integer", "intermediate values of a tick"),
        (
            &n.tmpb,
            n_tmpb,
            "Boolean",
            "short-circuit results of a tick",
        ),
        (&n.loc, p.n_locals, "Integer", "locals of inlined functions"),
    ] {
        let start = if ty == "Boolean" { "false" } else { "0" };
        if count > 0 {
            let _ = writeln!(
                o,
                "  {ty} {name}[{count}](each start = {start}, each fixed = true) \"{what}\";"
            );
        }
    }
    let helpers = runtime::helpers(&n, &em.used);
    if !helpers.is_empty() {
        if n_tmp + n_tmpb + p.n_locals == 0 {
            o.push_str("protected\n");
        }
        o.push('\n');
        o.push_str(helpers.trim_end());
        o.push('\n');
    }
    o.push_str("algorithm\n");
    let _ = writeln!(
        o,
        "  // One tick per sample instant: tick k runs at time k * {}.",
        n.period
    );
    let _ = writeln!(o, "  when sample(0, {}) then", n.period);
    o.push_str(&body);
    o.push_str("  end when;\n");
    let _ = writeln!(
        o,
        "  annotation(experiment(StopTime = {}, Interval = {}));",
        seconds(period_ms(model) * 100),
        seconds(period_ms(model))
    );
    let _ = writeln!(o, "end {};", n.model);
    Ok(o)
}

/// Every slot and constant must fit a 32-bit Integer.
fn check_fits(p: &Program) -> Result<(), ModelicaError> {
    let fits = |v: i64| i32::try_from(v).is_ok();
    if let Some(s) = p
        .slots
        .iter()
        .find(|s| !fits(s.lo) || !fits(s.hi) || !fits(s.init))
    {
        return Err(ModelicaError(format!(
            "slot `{}` has range {}..{}, wider than a 32-bit Modelica Integer",
            s.name, s.lo, s.hi
        )));
    }
    if let Some(v) = p.nodes.iter().find_map(|n| match n {
        Node::Const(v) if !fits(*v) => Some(*v),
        _ => None,
    }) {
        return Err(ModelicaError(format!(
            "the constant {v} does not fit a 32-bit Modelica Integer"
        )));
    }
    Ok(())
}

/// Every slot the step or a procedure assigns.
fn assigned_slots(p: &Program) -> BTreeSet<u32> {
    fn walk(stmts: &[Stmt], acc: &mut BTreeSet<u32>) {
        for s in stmts {
            match s {
                Stmt::Assign { slot, .. } => {
                    acc.insert(*slot);
                }
                Stmt::If {
                    then, otherwise, ..
                } => {
                    walk(then, acc);
                    walk(otherwise, acc);
                }
                Stmt::Switch { cases, .. } => cases.iter().for_each(|c| walk(c, acc)),
                Stmt::Call(_) | Stmt::Cover(_) => {}
            }
        }
    }
    let mut acc = BTreeSet::new();
    walk(&p.step, &mut acc);
    for pr in &p.procs {
        walk(&pr.body, &mut acc);
    }
    acc
}

/// The counter (array, 1-based index) of each cover item.
fn counters(p: &Program, n: &Names) -> Vec<(String, usize)> {
    let (mut s, mut t) = (0, 0);
    p.covers
        .iter()
        .map(|c| match c.kind {
            CoverKind::State(_) => {
                s += 1;
                (n.state_cov.clone(), s)
            }
            CoverKind::Transition(_) | CoverKind::Branch(..) => {
                t += 1;
                (n.trans_cov.clone(), t)
            }
        })
        .collect()
}
