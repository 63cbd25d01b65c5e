//! The body of the `when` clause: the inputs' ranges and the `assume`s are asserted, the IR's
//! step runs, each level's state variable is updated, and the properties are asserted, in the
//! order `statecheck sim` checks them.

use super::expr::Emit;
use super::names::Ty;
use super::text::{int_lit, string_lit, strip};
use statecheck_ir::{Goal, Node};

/// The body of the `when` clause: input checks, assumptions, the step, the levels' state
/// variables, the properties.
pub(crate) fn tick(em: &mut Emit<'_>) {
    let p = em.p;
    let n = em.n;
    let ranged: Vec<_> = p
        .inputs
        .iter()
        .filter(|i| n.tys[i.slot as usize] == Ty::Int)
        .collect();
    if !ranged.is_empty() {
        em.line("// Inputs must lie in their declared ranges.");
    }
    for i in ranged {
        let s = &p.slots[i.slot as usize];
        let v = &n.vars[i.slot as usize];
        let msg = string_lit(&format!("input `{}` outside {}..{}", i.name, s.lo, s.hi));
        em.line(&format!(
            "assert({v} >= {} and {v} <= {}, {msg});",
            int_lit(s.lo),
            int_lit(s.hi)
        ));
    }
    if !p.assumes.is_empty() {
        em.line("// Assumptions on the inputs, checked before the tick as `statecheck sim` does.");
    }
    for (k, a) in p.assumes.iter().enumerate() {
        let c = em.expr_as(*a, Ty::Bool);
        let msg = string_lit(&format!("assume #{} of `{}` violated", k + 1, p.name));
        em.line(&format!("assert({}, {msg});", strip(&c)));
    }
    em.line("// The tick (docs/semantics.md): tick 0 enters the initial states (R1), later");
    em.line("// ticks walk every instance (R2-R9).");
    em.block(&p.step);
    if !n.levels.is_empty() {
        em.line("// The state variable of each hierarchy level (InActive when the level is not).");
    }
    for l in &n.levels {
        let sel = &n.vars[l.slot as usize];
        let Some(active) = p
            .instances
            .get(l.instance as usize)
            .and_then(|i| i.active.get(l.node as usize))
        else {
            continue;
        };
        if matches!(p.nodes[*active as usize], Node::Const(v) if v != 0) {
            em.line(&format!("{} := {sel};", l.view));
            continue;
        }
        let c = em.expr_as(*active, Ty::Bool);
        let inactive = n
            .enums
            .get(l.ty)
            .and_then(|e| e.literals.last().map(|x| format!("{}.{x}", e.name)))
            .unwrap_or_default();
        em.line(&format!(
            "{} := if {} then {sel} else {inactive};",
            l.view,
            strip(&c)
        ));
    }
    properties(em);
}

/// `assert`s of the invariant, respond and observer properties, after the tick.
fn properties(em: &mut Emit<'_>) {
    let p = em.p;
    if !p.properties.is_empty() {
        em.line("// Properties, checked after the tick as `statecheck sim` does.");
    }
    for prop in &p.properties {
        let msg = string_lit(&format!(
            "property `{}` violated ({})",
            prop.name,
            em.src.at(prop.span)
        ));
        match prop.goal {
            Goal::Always { when, holds } => {
                let opened = match when {
                    Some(a) => {
                        let c = em.expr_as(a, Ty::Bool);
                        em.line(&format!("if {} then", strip(&c)));
                        em.depth += 1;
                        true
                    }
                    None => false,
                };
                let c = em.expr_as(holds, Ty::Bool);
                em.line(&format!("assert({}, {msg});", strip(&c)));
                if opened {
                    em.depth -= 1;
                    em.line("end if;");
                }
            }
            Goal::Reach { .. } => {
                em.line(&format!(
                    "// reachable `{}`: a question for `statecheck verify`, not asserted",
                    prop.name
                ));
            }
        }
    }
}
