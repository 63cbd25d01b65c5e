//! `.sc` names for a problem read from Supremica XML, whose labels (`land.0`, `Cat(0)`,
//! `take & go`) need not be identifiers. The `.sc` language has no quoted identifiers, so
//! [`sc_names`] maps every name that is not one to an identifier deterministically: each
//! character that is not an ASCII letter, digit or `_` becomes `_`, a leading digit (or an
//! empty name, or a keyword) gets an `x_` prefix, and a name already taken in its namespace
//! gets `_2`, `_3`, …. The renamings are returned so that the emitted file can list them.

use crate::problem::Problem;
use std::collections::HashSet;

/// One renamed name.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Renamed {
    /// What it names: `event`, `automaton`, or `state of AUT` (AUT's original name).
    pub what: String,
    /// The label in the XML file.
    pub from: String,
    /// The `.sc` identifier.
    pub to: String,
}

/// Map `names` to distinct identifiers in order; `is_ident` says whether the language
/// accepts a name as it is (not a keyword). `taken` holds names reserved in the namespace.
fn map_names(
    names: &[String],
    is_ident: &dyn Fn(&str) -> bool,
    mut taken: HashSet<String>,
    what: &str,
    out: &mut Vec<Renamed>,
) -> Vec<String> {
    // Names that are already identifiers keep them; the others take what is left.
    for n in names.iter().filter(|n| is_ident(n)) {
        taken.insert(n.clone());
    }
    names
        .iter()
        .map(|n| {
            if is_ident(n) {
                return n.clone();
            }
            let mut base: String = n
                .chars()
                .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
                .collect();
            if base.is_empty() || base.starts_with(|c: char| c.is_ascii_digit()) || !is_ident(&base)
            {
                base = format!("x_{base}");
            }
            let mut cand = base.clone();
            let mut k = 2;
            while taken.contains(&cand) {
                cand = format!("{base}_{k}");
                k += 1;
            }
            taken.insert(cand.clone());
            out.push(Renamed {
                what: what.to_string(),
                from: n.clone(),
                to: cand.clone(),
            });
            cand
        })
        .collect()
}

/// A copy of `p` whose event, automaton and state names are all `.sc` identifiers, with the
/// list of names that changed (empty when every name already was one). `none` is reserved
/// for events (it means "no event" in the emitted supervisor).
pub fn sc_names(p: &Problem, is_ident: &dyn Fn(&str) -> bool) -> (Problem, Vec<Renamed>) {
    let mut q = p.clone();
    let mut renamed = Vec::new();
    let ev_ok = |s: &str| s != "none" && is_ident(s);
    let events: Vec<String> = p.events.iter().map(|e| e.name.clone()).collect();
    let new = map_names(
        &events,
        &ev_ok,
        HashSet::from(["none".to_string()]),
        "event",
        &mut renamed,
    );
    for (e, n) in q.events.iter_mut().zip(new) {
        e.name = n;
    }
    let auts: Vec<String> = p.automata.iter().map(|a| a.name.clone()).collect();
    let new = map_names(&auts, is_ident, HashSet::new(), "automaton", &mut renamed);
    for (a, n) in q.automata.iter_mut().zip(new) {
        a.name = n.clone();
        a.chart = n;
    }
    for (a, orig) in q.automata.iter_mut().zip(&p.automata) {
        let what = format!("state of {}", orig.name);
        a.locs = map_names(&orig.locs, is_ident, HashSet::new(), &what, &mut renamed);
    }
    (q, renamed)
}
