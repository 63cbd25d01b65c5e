//! The supervisor as a `.sc` system in the tick semantics (the bridge of `docs/synthesis.md`).
//!
//! The emitted file holds:
//! - `enum Event { none, e1, … }` — the product alphabet; `none` is "no event this tick";
//! - one `enum Loc_<inst>` per automaton (its states);
//! - `chart Supervisor`: input `ev: Event` (the event the environment proposes this tick),
//!   output `fire: Event` (the event that occurs: `ev` if the plant can do it and, when
//!   controllable, the supervisor allows it, else `none`), outputs `at_<inst>` mirroring every
//!   automaton's location (requirement automata are the supervisor's memory), and outputs
//!   `allow_<e>` (the enabled controllable events, after this tick's event);
//! - one `chart Plant_<inst>` per plant automaton, moving on `fire`;
//! - `system Supervised`: the supervisor first, then the plants (which read `fire` in the same
//!   tick, rule R2), with invariants (mirrors agree with the plant charts; the `never`
//!   requirements) and a `reachable` property for the marked states.

use crate::encode::chain;
use crate::problem::{Kind, Pred, Problem};
use crate::Supervisor;
use std::fmt::Write;

/// The `.sc` text of the supervised system. `source` names the model it came from.
pub fn emit(p: &Problem, sup: &Supervisor, source: &str) -> String {
    let mut o = String::new();
    let sup_name = if p.automata.iter().any(|a| a.name == "sup") {
        "supervisor"
    } else {
        "sup"
    };
    let _ = writeln!(
        o,
        "// Supervisor synthesized by `statecheck synth` from {source}, system {}.\n\
         // {} states, {} transitions in the controlled behaviour. Generated: do not edit.\n\
         // Bridge (docs/synthesis.md): each tick the environment proposes one event `{sup_name}.ev`;\n\
         // it occurs (`{sup_name}.fire`) if the plant can do it and, if controllable, the guard allows it.\n",
        p.name, sup.states, sup.transitions
    );
    let events: Vec<&str> = p.events.iter().map(|e| e.name.as_str()).collect();
    let _ = writeln!(o, "enum Event {{ none, {} }}", events.join(", "));
    for a in &p.automata {
        let _ = writeln!(o, "enum Loc_{} {{ {} }}", a.name, a.locs.join(", "));
    }
    o.push('\n');
    let at = |a: u32, l: u32| {
        let aut = &p.automata[a as usize];
        format!(
            "at_{} == Loc_{}.{}",
            aut.name, aut.name, aut.locs[l as usize]
        )
    };
    let sizes: Vec<u32> = p.automata.iter().map(|a| a.locs.len() as u32).collect();
    let init = p.initial();
    // The supervisor chart.
    o.push_str("chart Supervisor {\n    input ev: Event;\n    output fire: Event = Event.none;\n");
    for a in &p.automata {
        let _ = writeln!(
            o,
            "    output at_{0}: Loc_{0} = Loc_{0}.{1};",
            a.name, a.locs[a.initial as usize]
        );
    }
    for g in &sup.guards {
        let e = g.event;
        let v = g.allow.eval(&init) && p.enabled_by(Kind::Plant, &init, e) && p.allowed(&init, e);
        let _ = writeln!(
            o,
            "    output allow_{}: bool = {v};",
            p.events[e as usize].name
        );
    }
    o.push_str(
        "    initial Run;\n    state Run {\n        during {\n            fire = Event.none;\n",
    );
    for (e, ev) in p.events.iter().enumerate() {
        let e = e as u32;
        let cond = if ev.controllable {
            format!("allow_{}", ev.name)
        } else {
            enabled(p, Kind::Plant, e, &at)
        };
        let _ = writeln!(o, "            if ev == Event.{} && {cond} {{", ev.name);
        let _ = writeln!(o, "                fire = Event.{};", ev.name);
        for a in p.automata.iter().filter(|a| a.has(e)) {
            let ts: Vec<(u32, u32)> = (0..a.locs.len() as u32)
                .filter_map(|l| a.step(l, e).map(|t| (l, t)))
                .collect();
            let cases: Vec<(String, String)> = ts
                .iter()
                .map(|(s, t)| {
                    (
                        format!("at_{0} == Loc_{0}.{1}", a.name, a.locs[*s as usize]),
                        format!("at_{0} = Loc_{0}.{1};", a.name, a.locs[*t as usize]),
                    )
                })
                .collect();
            if !cases.is_empty() {
                let _ = writeln!(o, "                {}", branch_tree(&cases));
            }
        }
        o.push_str("            }\n");
    }
    for g in &sup.guards {
        let e = g.event;
        let mut parts = vec![
            enabled(p, Kind::Plant, e, &at),
            enabled(p, Kind::Requirement, e, &at),
        ];
        for n in p.needs.iter().filter(|n| n.event == e) {
            parts.push(n.cond.render(&|a, l| format!("({})", at(a, l))));
        }
        parts.push(format!("({})", g.allow.render(&sizes, &at)));
        parts.retain(|s| s != "true");
        let _ = writeln!(
            o,
            "            allow_{} = {};",
            p.events[e as usize].name,
            if parts.is_empty() {
                "true".to_string()
            } else {
                chain(&parts, " && ")
            }
        );
    }
    o.push_str("        }\n    }\n}\n\n");
    // Plant charts.
    for a in p.automata.iter().filter(|a| a.kind == Kind::Plant) {
        let _ = writeln!(o, "chart Plant_{} {{\n    input fire: Event;", a.name);
        let _ = writeln!(o, "    initial {};", a.locs[a.initial as usize]);
        for (l, name) in a.locs.iter().enumerate() {
            let ts: Vec<String> = a
                .alphabet
                .iter()
                .filter_map(|&e| {
                    a.step(l as u32, e).map(|t| {
                        format!(
                            "on [fire == Event.{}] -> {};",
                            p.events[e as usize].name, a.locs[t as usize]
                        )
                    })
                })
                .collect();
            if ts.is_empty() {
                let _ = writeln!(o, "    state {name};");
            } else {
                let _ = writeln!(o, "    state {name} {{ {} }}", ts.join(" "));
            }
        }
        o.push_str("}\n\n");
    }
    // The system.
    let _ = writeln!(
        o,
        "system Supervised {{\n    instance {sup_name}: Supervisor;"
    );
    for a in p.automata.iter().filter(|a| a.kind == Kind::Plant) {
        let _ = writeln!(o, "    instance {0}: Plant_{0};", a.name);
    }
    for a in p.automata.iter().filter(|a| a.kind == Kind::Plant) {
        let _ = writeln!(o, "    connect {sup_name}.fire -> {}.fire;", a.name);
    }
    let sys_at = |a: u32, l: u32| {
        let aut = &p.automata[a as usize];
        match aut.kind {
            Kind::Plant => format!("in({}.{})", aut.name, aut.locs[l as usize]),
            Kind::Requirement => format!(
                "{sup_name}.at_{0} == Loc_{0}.{1}",
                aut.name, aut.locs[l as usize]
            ),
        }
    };
    for a in p.automata.iter().filter(|a| a.kind == Kind::Plant) {
        let alts: Vec<String> = a
            .locs
            .iter()
            .map(|l| format!("(in({0}.{l}) && {sup_name}.at_{0} == Loc_{0}.{l})", a.name))
            .collect();
        let _ = writeln!(
            o,
            "    invariant mirror_{}: {};",
            a.name,
            chain(&alts, " || ")
        );
    }
    for (i, n) in p.never.iter().enumerate() {
        let text = n.render(&|a, l| format!("({})", sys_at(a, l)));
        let _ = writeln!(o, "    invariant never_{}: !{};", i + 1, paren(&text));
    }
    let marked: Vec<String> = p
        .automata
        .iter()
        .enumerate()
        .filter(|(_, a)| a.marked.iter().any(|m| !m))
        .map(|(ai, a)| {
            let alts: Vec<String> = (0..a.locs.len() as u32)
                .filter(|l| a.marked[*l as usize])
                .map(|l| format!("({})", sys_at(ai as u32, l)))
                .collect();
            paren(&chain(&alts, " || "))
        })
        .collect();
    let marked = if marked.is_empty() {
        "true".to_string()
    } else {
        chain(&marked, " && ")
    };
    let _ = writeln!(o, "    reachable all_marked: {marked};");
    o.push_str("}\n");
    o
}

/// Most cases written as one flat `if … else if …` chain by [`branch_tree`].
const FLAT_BRANCHES: usize = 16;

/// `if c1 { b1 } else if c2 { b2 } …` for mutually exclusive conditions (one automaton's
/// source locations), nested so that the parser's limits hold at any size: more than
/// [`FLAT_BRANCHES`] cases are split in halves, `if (conditions of the first half) { … } else
/// { … }`, so n cases nest about log₂(n / 16) levels plus one flat chain, instead of n (an
/// automaton with more than 256 transitions on one event used to give an `else if` chain
/// deeper than E0013 allows). The conditions of a half are balanced by [`chain`]. Each case
/// is tested once per level, so the text is O(n log n).
fn branch_tree(cases: &[(String, String)]) -> String {
    if cases.len() <= FLAT_BRANCHES {
        return cases
            .iter()
            .map(|(c, b)| format!("if {c} {{ {b} }}"))
            .collect::<Vec<_>>()
            .join(" else ");
    }
    let (first, second) = cases.split_at(cases.len() / 2);
    let conds: Vec<String> = first.iter().map(|(c, _)| c.clone()).collect();
    format!(
        "if {} {{ {} }} else {{ {} }}",
        paren(&chain(&conds, " || ")),
        branch_tree(first),
        branch_tree(second)
    )
}

/// `s` as one parenthesised group: unchanged if its first `(` closes at its very end, else
/// wrapped. (`(a) || (b)` starts and ends with a parenthesis but is two groups.)
fn paren(s: &str) -> String {
    let mut depth = 0usize;
    let mut one_group = s.starts_with('(');
    for (i, c) in s.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth = depth.saturating_sub(1);
                if depth == 0 && i + 1 < s.len() {
                    one_group = false;
                }
            }
            _ => {}
        }
    }
    if one_group {
        s.to_string()
    } else {
        format!("({s})")
    }
}

/// "Every automaton of `kind` with `e` can take it", as `.sc` text over `at_…` variables.
fn enabled(p: &Problem, kind: Kind, e: u32, at: &dyn Fn(u32, u32) -> String) -> String {
    let mut conj = Vec::new();
    for (ai, a) in p.automata.iter().enumerate() {
        if a.kind != kind || !a.has(e) {
            continue;
        }
        let srcs: Vec<String> = (0..a.locs.len() as u32)
            .filter(|l| a.step(*l, e).is_some())
            .map(|l| at(ai as u32, l))
            .collect();
        if srcs.len() == a.locs.len() {
            continue;
        }
        conj.push(match srcs.len() {
            0 => "false".to_string(),
            1 => srcs[0].clone(),
            _ => format!("({})", chain(&srcs, " || ")),
        });
    }
    if conj.is_empty() {
        "true".into()
    } else {
        chain(&conj, " && ")
    }
}

/// A predicate rendered over the source model's names (`in(inst.State)`), for reports.
pub fn pred_text(p: &Problem, pred: &Pred) -> String {
    pred.render(&|a, l| {
        let aut = &p.automata[a as usize];
        format!("in({}.{})", aut.name, aut.locs[l as usize])
    })
}

/// A guard rendered over the source model's names, for reports.
pub fn guard_text(p: &Problem, f: &crate::Formula) -> String {
    let sizes: Vec<u32> = p.automata.iter().map(|a| a.locs.len() as u32).collect();
    f.render(&sizes, &|a, l| {
        let aut = &p.automata[a as usize];
        format!("in({}.{})", aut.name, aut.locs[l as usize])
    })
}

#[cfg(test)]
mod tests {
    use super::paren;

    #[test]
    fn paren_wraps_unless_one_group() {
        assert_eq!(paren("(a)"), "(a)");
        assert_eq!(paren("((a) || (b))"), "((a) || (b))");
        assert_eq!(paren("a || b"), "(a || b)");
        // Two groups: the `reachable all_marked` disjunction of an automaton with two marked
        // states was left unwrapped, so `&&` bound tighter than the disjunction.
        assert_eq!(paren("(a) || (b)"), "((a) || (b))");
        assert_eq!(paren("(a) && !(b)"), "((a) && !(b))");
    }
}
