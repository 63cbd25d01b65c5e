//! Write a [`Problem`] as Supremica automata XML (the format [`super::read`] reads).
//!
//! Plants are written as `type="Plant"`, requirement automata as `type="Specification"`.
//! Every automaton's states are all `accepting="true"` when it marks all of them (a `.sc` chart
//! that marks no state marks every state, which Supremica spells out). State requirements
//! have no direct counterpart in the format, so they become automata with the same answer:
//!
//! - `never (P)` whose atoms all name one automaton: that automaton's states where `P` holds
//!   are `forbidden="true"`;
//! - any other `never (P)`: a `Specification` automaton `never_K` that is the synchronous
//!   product of copies of the automata `P` names (it follows them exactly, so it adds no
//!   reachable states), with the states where `P` holds forbidden;
//! - `e needs (C)`: a `Specification` `needs_K` built the same way, whose `e` transitions exist
//!   only in the states where `C` holds (a self-loop when `e` is not an event of the copies).
//!
//! Observers larger than [`MAX_OBSERVER`] states are refused (E0727).

use crate::problem::{EventId, Kind, Pred, Problem};
use std::collections::BTreeSet;
use std::fmt::{self, Write};

/// Largest product of copies written for one state requirement.
pub const MAX_OBSERVER: usize = 100_000;

/// A requirement that cannot be written (too large an observer).
#[derive(Clone, Debug)]
pub struct ExportError {
    /// The stable code (`E0727`).
    pub code: &'static str,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for ExportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "error[{}]: {}", self.code, self.message)
    }
}

impl std::error::Error for ExportError {}

/// Escape text for an XML attribute value.
pub fn escape(s: &str) -> String {
    let mut o = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => o.push_str("&amp;"),
            '<' => o.push_str("&lt;"),
            '>' => o.push_str("&gt;"),
            '"' => o.push_str("&quot;"),
            '\'' => o.push_str("&apos;"),
            c => o.push(c),
        }
    }
    o
}

fn atoms(p: &Pred, out: &mut BTreeSet<u32>) {
    match p {
        Pred::Const(_) => {}
        Pred::At(a, _) => {
            out.insert(*a);
        }
        Pred::Not(x) => atoms(x, out),
        Pred::And(a, b) | Pred::Or(a, b) => {
            atoms(a, out);
            atoms(b, out);
        }
    }
}

/// An automaton as written: names, states, transitions by index.
struct Out {
    name: String,
    kind: Kind,
    events: Vec<EventId>,
    states: Vec<String>,
    initial: usize,
    accepting: Vec<bool>,
    forbidden: Vec<bool>,
    /// Index-based ids (`0`, `1`, …) with a `name`, instead of the name as the id.
    numbered: bool,
    trans: Vec<(usize, EventId, usize)>,
}

/// The Supremica XML text of `p`.
pub fn write(p: &Problem) -> Result<String, ExportError> {
    let mut outs: Vec<Out> = p
        .automata
        .iter()
        .map(|a| Out {
            name: a.name.clone(),
            kind: a.kind,
            events: a.alphabet.clone(),
            states: a.locs.clone(),
            initial: a.initial as usize,
            accepting: a.marked.clone(),
            forbidden: vec![false; a.locs.len()],
            numbered: false,
            trans: a
                .transitions()
                .map(|(f, e, t)| (f as usize, e, t as usize))
                .collect(),
        })
        .collect();
    for (k, pred) in p.never.iter().enumerate() {
        let mut s = BTreeSet::new();
        atoms(pred, &mut s);
        if s.len() == 1 {
            let a = *s.iter().next().unwrap_or(&0) as usize;
            let mut v = p.initial();
            for l in 0..p.automata[a].locs.len() {
                v[a] = l as u32;
                if pred.eval(&v) {
                    outs[a].forbidden[l] = true;
                }
            }
        } else {
            outs.push(observer(p, &s, format!("never_{k}"), pred, None)?);
        }
    }
    for (k, n) in p.needs.iter().enumerate() {
        let mut s = BTreeSet::new();
        atoms(&n.cond, &mut s);
        outs.push(observer(
            p,
            &s,
            format!("needs_{k}"),
            &n.cond,
            Some(n.event),
        )?);
    }
    let mut o = String::new();
    let _ = writeln!(o, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
    let _ = writeln!(
        o,
        "<Automata name=\"{}\" major=\"0\" minor=\"9\">",
        escape(&p.name)
    );
    for a in &outs {
        let ty = match a.kind {
            Kind::Plant => "Plant",
            Kind::Requirement => "Specification",
        };
        let _ = writeln!(o, "<Automaton name=\"{}\" type=\"{ty}\">", escape(&a.name));
        o.push_str("\t<Events>\n");
        for &e in &a.events {
            let ev = &p.events[e as usize];
            let n = escape(&ev.name);
            let c = if ev.controllable {
                ""
            } else {
                " controllable=\"false\""
            };
            let _ = writeln!(o, "\t\t<Event id=\"{n}\" label=\"{n}\"{c}/>");
        }
        o.push_str("\t</Events>\n\t<States>\n");
        let id = |l: usize| {
            if a.numbered {
                l.to_string()
            } else {
                escape(&a.states[l])
            }
        };
        for (l, s) in a.states.iter().enumerate() {
            let mut attrs = format!("id=\"{}\"", id(l));
            if a.numbered {
                let _ = write!(attrs, " name=\"{}\"", escape(s));
            }
            if l == a.initial {
                attrs.push_str(" initial=\"true\"");
            }
            if a.accepting[l] {
                attrs.push_str(" accepting=\"true\"");
            }
            if a.forbidden[l] {
                attrs.push_str(" forbidden=\"true\"");
            }
            let _ = writeln!(o, "\t\t<State {attrs}/>");
        }
        o.push_str("\t</States>\n\t<Transitions>\n");
        for &(f, e, t) in &a.trans {
            let _ = writeln!(
                o,
                "\t\t<Transition source=\"{}\" dest=\"{}\" event=\"{}\"/>",
                id(f),
                id(t),
                escape(&p.events[e as usize].name)
            );
        }
        o.push_str("\t</Transitions>\n</Automaton>\n");
    }
    o.push_str("</Automata>\n");
    Ok(o)
}

/// The synchronous product of copies of the automata `s`, as a specification: `forbidden`
/// where `pred` holds (for `never`), or `event` only where `pred` holds (for `needs`).
fn observer(
    p: &Problem,
    s: &BTreeSet<u32>,
    name: String,
    pred: &Pred,
    event: Option<EventId>,
) -> Result<Out, ExportError> {
    let auts: Vec<usize> = s.iter().map(|&a| a as usize).collect();
    let size = auts
        .iter()
        .try_fold(1usize, |acc, &a| acc.checked_mul(p.automata[a].locs.len()))
        .filter(|&n| n <= MAX_OBSERVER)
        .ok_or_else(|| ExportError {
            code: "E0727",
            message: format!(
                "requirement `{name}` spans automata whose product exceeds {MAX_OBSERVER} states; Supremica XML cannot state it more compactly"
            ),
        })?;
    let mut events: BTreeSet<EventId> = auts
        .iter()
        .flat_map(|&a| p.automata[a].alphabet.iter().copied())
        .collect();
    if let Some(e) = event {
        events.insert(e);
    }
    // State index ↔ location vector (mixed radix over `auts`).
    let decode = |mut i: usize| {
        let mut v = p.initial();
        for &a in auts.iter().rev() {
            let n = p.automata[a].locs.len();
            v[a] = (i % n) as u32;
            i /= n;
        }
        v
    };
    let encode = |v: &[u32]| {
        auts.iter().fold(0usize, |acc, &a| {
            acc * p.automata[a].locs.len() + v[a] as usize
        })
    };
    let mut states = Vec::with_capacity(size);
    let mut forbidden = Vec::with_capacity(size);
    let mut trans = Vec::new();
    for i in 0..size {
        let v = decode(i);
        let names: Vec<&str> = auts
            .iter()
            .map(|&a| p.automata[a].locs[v[a] as usize].as_str())
            .collect();
        states.push(if names.is_empty() {
            "any".to_string()
        } else {
            names.join(".")
        });
        let holds = pred.eval(&v);
        forbidden.push(event.is_none() && holds);
        for &e in &events {
            if Some(e) == event && !holds {
                continue;
            }
            let mut w = v.clone();
            let ok = auts.iter().all(|&a| {
                let aut = &p.automata[a];
                if !aut.has(e) {
                    return true;
                }
                match aut.step(v[a], e) {
                    Some(t) => {
                        w[a] = t;
                        true
                    }
                    None => false,
                }
            });
            if ok {
                trans.push((i, e, encode(&w)));
            }
        }
    }
    Ok(Out {
        name,
        kind: Kind::Requirement,
        events: events.into_iter().collect(),
        initial: encode(&p.initial()),
        accepting: vec![true; size],
        forbidden,
        states,
        numbered: true,
        trans,
    })
}
