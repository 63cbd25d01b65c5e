//! Read Supremica's automata XML (`<Automata><Automaton …>…</Automaton></Automata>`) into a
//! [`Problem`], as Supremica means it:
//!
//! - `type="Plant"` → [`Kind::Plant`]; `Specification` and `Supervisor` → [`Kind::Requirement`];
//!   `Property` automata take no part in synthesis and are skipped; other types are an error.
//! - Events are declared per automaton (`<Event id= label= controllable=/>`, controllable unless
//!   `controllable="false"`) and synchronise by **label** (the `id` only names the event inside
//!   its automaton); an automaton's alphabet is its declared events, with or without transitions.
//! - States: `<State id= name= initial= accepting= forbidden=/>` (the name is `name`, else `id`;
//!   transitions refer to `id`). Exactly one initial state. Marked = `accepting="true"`; an
//!   automaton with **no** accepting state marks nothing (Supremica's definition: its marked
//!   language is empty), unlike a `.sc` chart with no `marked` state.
//! - `forbidden="true"` states become `never` predicates (`in(aut.state)`).
//!
//! Errors carry a stable code (E0720–E0725) and the line:column of the offending element.

use crate::problem::{Automaton, Event, EventId, Kind, Pred, Problem, NONE};
use statecheck_base::Span;
use std::collections::HashMap;
use std::fmt;

/// A reading error: code, position (1-based line and column) and message.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct XmlError {
    /// The stable diagnostic code (`E0720`…).
    pub code: &'static str,
    /// 1-based line of the offending element.
    pub line: u32,
    /// 1-based column of the offending element.
    pub col: u32,
    /// What is wrong.
    pub message: String,
    /// The bytes of the file it points at (the element's start tag, or one character).
    pub span: Span,
}

impl fmt::Display for XmlError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{}:{}: error[{}]: {}",
            self.line, self.col, self.code, self.message
        )
    }
}

impl std::error::Error for XmlError {}

/// Largest number of states or transitions read in total (bounds memory on hostile input).
pub const MAX_ITEMS: usize = 10_000_000;

struct Reader<'d, 'i> {
    doc: &'d roxmltree::Document<'i>,
}

type R<T> = Result<T, XmlError>;

impl<'d, 'i> Reader<'d, 'i> {
    fn err(&self, code: &'static str, node: roxmltree::Node, msg: impl Into<String>) -> XmlError {
        let r = node.range();
        let pos = self.doc.text_pos_at(r.start);
        let head = 1 + node.tag_name().name().len();
        XmlError {
            code,
            line: pos.row,
            col: pos.col,
            message: msg.into(),
            span: Span::new(r.start, r.end.min(r.start + head).max(r.start)),
        }
    }

    fn attr<'a>(&self, node: roxmltree::Node<'a, 'i>, name: &str) -> R<&'a str> {
        node.attribute(name).ok_or_else(|| {
            self.err(
                "E0721",
                node,
                format!("<{}> has no `{name}` attribute", node.tag_name().name()),
            )
        })
    }

    fn flag(&self, node: roxmltree::Node, name: &str, default: bool) -> R<bool> {
        match node.attribute(name) {
            None => Ok(default),
            Some(v) if v.eq_ignore_ascii_case("true") => Ok(true),
            Some(v) if v.eq_ignore_ascii_case("false") => Ok(false),
            Some(v) => Err(self.err(
                "E0721",
                node,
                format!("`{name}` must be `true` or `false`, not `{v}`"),
            )),
        }
    }
}

fn elements<'a, 'i>(
    node: roxmltree::Node<'a, 'i>,
) -> impl Iterator<Item = roxmltree::Node<'a, 'i>> {
    node.children().filter(|n| n.is_element())
}

/// Read the text of a Supremica automata file into a synthesis problem.
pub fn read(text: &str) -> Result<Problem, XmlError> {
    let opts = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..Default::default()
    };
    let doc = roxmltree::Document::parse_with_options(text, opts).map_err(|e| {
        let pos = e.pos();
        let at = offset(text, pos.row, pos.col);
        let next = text[at..].chars().next().map_or(0, char::len_utf8);
        XmlError {
            code: "E0720",
            line: pos.row,
            col: pos.col,
            message: format!("malformed XML: {e}"),
            span: Span::new(at, at + next),
        }
    })?;
    let rd = Reader { doc: &doc };
    let root = doc.root_element();
    if root.tag_name().name() != "Automata" {
        return Err(rd.err(
            "E0721",
            root,
            format!(
                "the root element is <{}>; a Supremica automata file has <Automata>",
                root.tag_name().name()
            ),
        ));
    }
    let mut events: Vec<Event> = Vec::new();
    let mut event_ids: HashMap<String, EventId> = HashMap::new();
    let mut automata = Vec::new();
    let mut never = Vec::new();
    let mut items = 0usize;
    // First pass: the product alphabet (labels, in order of first declaration).
    for aut in elements(root) {
        if aut.tag_name().name() != "Automaton" || skipped(&rd, aut)? {
            continue;
        }
        for ev in elements(aut)
            .filter(|n| n.tag_name().name() == "Events")
            .flat_map(elements)
        {
            let label = ev
                .attribute("label")
                .map_or_else(|| rd.attr(ev, "id"), Ok)?;
            let controllable = rd.flag(ev, "controllable", true)?;
            match event_ids.get(label) {
                Some(&id) if events[id as usize].controllable != controllable => {
                    return Err(rd.err(
                        "E0725",
                        ev,
                        format!("event `{label}` is controllable in one automaton and uncontrollable in another"),
                    ))
                }
                Some(_) => {}
                None => {
                    event_ids.insert(label.to_string(), events.len() as EventId);
                    events.push(Event {
                        name: label.to_string(),
                        controllable,
                    });
                }
            }
        }
    }
    let n_events = events.len();
    for aut in elements(root) {
        match aut.tag_name().name() {
            "Automaton" => {}
            other => {
                return Err(rd.err(
                    "E0721",
                    aut,
                    format!("unexpected <{other}> in <Automata> (expected <Automaton>)"),
                ))
            }
        }
        if skipped(&rd, aut)? {
            continue;
        }
        let name = rd.attr(aut, "name")?;
        let kind = match aut.attribute("type").unwrap_or("Undefined") {
            "Plant" => Kind::Plant,
            _ => Kind::Requirement,
        };
        let section = |tag: &'static str| elements(aut).filter(move |n| n.tag_name().name() == tag);
        // Events: local id → global label id.
        let mut local: HashMap<&str, EventId> = HashMap::new();
        let mut alphabet = Vec::new();
        for ev in section("Events").flat_map(elements) {
            let id = rd.attr(ev, "id")?;
            let label = ev.attribute("label").unwrap_or(id);
            let Some(&g) = event_ids.get(label) else {
                return Err(rd.err("E0722", ev, format!("event `{label}` was not collected")));
            };
            if local.insert(id, g).is_some() {
                return Err(rd.err(
                    "E0722",
                    ev,
                    format!("event id `{id}` declared twice in `{name}`"),
                ));
            }
            alphabet.push(g);
        }
        alphabet.sort_unstable();
        alphabet.dedup();
        // States.
        let mut locs = Vec::new();
        let mut marked = Vec::new();
        let mut state_ids: HashMap<&str, u32> = HashMap::new();
        let mut initial = None;
        for st in section("States").flat_map(elements) {
            let id = rd.attr(st, "id")?;
            let l = locs.len() as u32;
            if state_ids.insert(id, l).is_some() {
                return Err(rd.err(
                    "E0722",
                    st,
                    format!("state id `{id}` declared twice in `{name}`"),
                ));
            }
            items += 1;
            if items > MAX_ITEMS {
                return Err(rd.err(
                    "E0721",
                    st,
                    format!("more than {MAX_ITEMS} states and transitions"),
                ));
            }
            locs.push(st.attribute("name").unwrap_or(id).to_string());
            marked.push(rd.flag(st, "accepting", false)?);
            if rd.flag(st, "initial", false)? {
                if initial.is_some() {
                    return Err(rd.err(
                        "E0724",
                        st,
                        format!("`{name}` has a second initial state"),
                    ));
                }
                initial = Some(l);
            }
            if rd.flag(st, "forbidden", false)? {
                never.push(Pred::At(automata.len() as u32, l));
            }
        }
        let Some(initial) = initial else {
            return Err(rd.err(
                "E0724",
                aut,
                format!("automaton `{name}` has no initial state"),
            ));
        };
        let mut next = vec![NONE; locs.len() * n_events];
        for tr in section("Transitions").flat_map(elements) {
            let get = |attr: &str| -> R<u32> {
                let v = rd.attr(tr, attr)?;
                state_ids.get(v).copied().ok_or_else(|| {
                    rd.err(
                        "E0722",
                        tr,
                        format!("`{attr}` names no state of `{name}`: `{v}`"),
                    )
                })
            };
            let (src, dst) = (get("source")?, get("dest")?);
            let ev = rd.attr(tr, "event")?;
            let Some(&e) = local.get(ev) else {
                return Err(rd.err(
                    "E0722",
                    tr,
                    format!("`event` names no event of `{name}`: `{ev}`"),
                ));
            };
            items += 1;
            if items > MAX_ITEMS {
                return Err(rd.err(
                    "E0721",
                    tr,
                    format!("more than {MAX_ITEMS} states and transitions"),
                ));
            }
            let slot = &mut next[src as usize * n_events + e as usize];
            if *slot != NONE && *slot != dst {
                return Err(rd.err(
                    "E0723",
                    tr,
                    format!(
                        "`{name}` is nondeterministic: two transitions on `{}` leave state `{}`",
                        events[e as usize].name, locs[src as usize]
                    ),
                ));
            }
            *slot = dst;
        }
        automata.push(Automaton {
            name: name.to_string(),
            chart: name.to_string(),
            kind,
            locs,
            marked,
            initial,
            alphabet,
            next,
            n_events,
        });
    }
    if !automata.iter().any(|a| a.kind == Kind::Plant) {
        return Err(rd.err("E0726", root, "the file has no automaton of type `Plant`"));
    }
    Ok(Problem {
        name: root.attribute("name").unwrap_or("Automata").to_string(),
        events,
        automata,
        never,
        needs: Vec::new(),
    })
}

/// True for automata that take no part in synthesis (`Property`); an error for unknown types.
fn skipped(rd: &Reader, aut: roxmltree::Node) -> R<bool> {
    match aut.attribute("type") {
        Some("Plant" | "Specification" | "Supervisor") => Ok(false),
        Some("Property") => Ok(true),
        Some(t) => Err(rd.err(
            "E0726",
            aut,
            format!("automaton type `{t}` is not used in synthesis (Plant, Specification, Supervisor, Property)"),
        )),
        None => Err(rd.err(
            "E0726",
            aut,
            "the automaton has no `type` (Plant, Specification, Supervisor, Property)",
        )),
    }
}

/// The byte offset of 1-based `row`, `col` (in characters) in `text`, clamped to its end.
fn offset(text: &str, row: u32, col: u32) -> usize {
    let mut at = 0;
    for _ in 1..row {
        match text[at..].find('\n') {
            Some(i) => at += i + 1,
            None => return text.len(),
        }
    }
    let line_end = text[at..].find('\n').map_or(text.len(), |i| at + i);
    text[at..line_end]
        .char_indices()
        .nth(col.saturating_sub(1) as usize)
        .map_or(line_end, |(i, _)| at + i)
}
