//! Temporal declarations: `ltl`, `ctl`, `nonblocking`, `fair` and unbounded `respond`, with
//! the precedence of formula operators written out by hand in the expected renderings.

#![allow(clippy::unwrap_used)] // tests may unwrap

mod common;

use statecheck_syntax::ast::{Item, PropertyKind};
use statecheck_syntax::parse;

/// The properties of the file's only system, rendered.
fn props(body: &str) -> (Vec<String>, Vec<String>) {
    let src = format!("system S {{\n{body}\n}}\n");
    let (file, diags) = parse(&src);
    let codes = diags.iter().map(|d| d.code.to_string()).collect();
    let Some(Item::System(sys)) = file.items.first() else {
        return (Vec::new(), codes);
    };
    let out = sys
        .properties
        .iter()
        .map(|p| match &p.kind {
            PropertyKind::Ltl { formula } => {
                format!("ltl {}: {}", p.name.name, common::formula_text(formula))
            }
            PropertyKind::Ctl { formula } => {
                format!("ctl {}: {}", p.name.name, common::formula_text(formula))
            }
            PropertyKind::RespondEventually { trigger, response } => format!(
                "respond {}: {} => {}",
                p.name.name,
                common::expr(trigger),
                common::expr(response)
            ),
            PropertyKind::Fair { trigger, expr } => format!(
                "fair {}: {:?} {}",
                p.name.name,
                trigger.as_ref().map(common::expr),
                common::expr(expr)
            ),
            PropertyKind::Nonblocking { expr } => {
                format!("nonblocking {}: {}", p.name.name, common::expr(expr))
            }
            _ => "other".into(),
        })
        .collect();
    (out, codes)
}

fn one(body: &str) -> String {
    let (p, codes) = props(body);
    assert!(codes.is_empty(), "{body}: {codes:?}");
    assert_eq!(p.len(), 1, "{body}");
    p[0].clone()
}

#[test]
fn ltl_precedence() {
    // `=>` is loosest and right-associative; `U` binds tighter than `&&`.
    assert_eq!(
        one("ltl a: G(fam.stall => F !fam.stall);"),
        "ltl a: G ({fam.stall} => F {(not fam.stall)})"
    );
    assert_eq!(
        one("ltl b: p && q U r || s => t => u;"),
        "ltl b: ((({p} && ({q} U {r})) || {s}) => ({t} => {u}))"
    );
    assert_eq!(one("ltl c: a U b U c;"), "ltl c: ({a} U ({b} U {c}))");
    assert_eq!(one("ltl d: G F x > 3;"), "ltl d: G F {(> x 3)}");
    assert_eq!(one("ltl e: !(F p) W X q;"), "ltl e: (!F {p} W X {q})");
    // Parentheses without temporal operators are part of the atom.
    assert_eq!(
        one("ltl f: F (a + 1) * 2 == b;"),
        "ltl f: F {(== (* (+ a 1) 2) b)}"
    );
    // `in(...)` atoms; a path starting with an operator letter is a path, so the group has
    // no temporal operator and is one atom.
    assert_eq!(
        one("ltl g: G(in(c.Idle) || F.x == 1);"),
        "ltl g: G {(|| in(c.Idle) (== F.x 1))}"
    );
}

#[test]
fn ctl_operators() {
    assert_eq!(one("ctl r: AG EF in(c.Idle);"), "ctl r: AG EF {in(c.Idle)}");
    assert_eq!(
        one("ctl u: A[p U E[q U r]] && EX !s;"),
        "ctl u: (A[{p} U E[{q} U {r}]] && EX {(not s)})"
    );
    let (_, codes) = props("ctl v: A[p W q];");
    assert!(codes.contains(&"E0030".to_string()), "{codes:?}");
}

#[test]
fn other_declarations() {
    assert_eq!(one("respond r: a => b;"), "respond r: a => b");
    assert_eq!(one("fair j: go;"), "fair j: None go");
    assert_eq!(one("fair c: p => q;"), "fair c: Some(\"p\") q");
    assert_eq!(
        one("nonblocking n: in(c.Idle);"),
        "nonblocking n: in(c.Idle)"
    );
}

#[test]
fn words_stay_usable_as_names() {
    // `fair` and `ltl` are contextual: elsewhere they are ordinary identifiers.
    let src = "chart C { local fair: bool; local ltl: int[0..3]; state A { on [fair] / { ltl = 1; } -> A; } }\n";
    let (_, diags) = parse(src);
    assert!(diags.is_empty(), "{diags:?}");
}

#[test]
fn recovery_after_a_bad_formula() {
    // A broken formula is reported and the following property still parses.
    let (p, codes) = props("ltl a: G (p => );\nltl b: F q;");
    assert!(!codes.is_empty());
    assert!(p.iter().any(|s| s == "ltl b: F {q}"), "{p:?}");
}
