//! Supremica automata XML: every example of `examples/synthesis/` written as XML and read back
//! gives the same problem and the same supervisor sizes (the known answers of
//! `benchmarks.rs`); a hand-written Supremica file of the small factory; Supremica's marking;
//! labels that are not `.sc` identifiers; coded errors with positions.

mod common;
use common::{example, problem_of, sizes};

use statecheck_synth::problem::Kind;
use statecheck_synth::supremica::{read::read, write::write};
use statecheck_synth::{Engine, Problem};

/// `q` (read back) has `p`'s events and automata, by name, plus possibly requirement
/// observers after them.
fn assert_same_automata(p: &Problem, q: &Problem) {
    let ev = |x: &Problem| {
        x.events
            .iter()
            .map(|e| (e.name.clone(), e.controllable))
            .collect::<Vec<_>>()
    };
    assert_eq!(ev(p), ev(q));
    assert!(q.automata.len() >= p.automata.len());
    for (a, b) in p.automata.iter().zip(&q.automata) {
        assert_eq!(a.name, b.name);
        assert_eq!(a.kind, b.kind);
        assert_eq!(a.locs, b.locs);
        assert_eq!(a.marked, b.marked, "{}", a.name);
        assert_eq!(a.initial, b.initial);
        assert_eq!(a.alphabet, b.alphabet);
        assert_eq!(
            a.transitions().collect::<Vec<_>>(),
            b.transitions().collect::<Vec<_>>()
        );
    }
    for extra in &q.automata[p.automata.len()..] {
        assert_eq!(extra.kind, Kind::Requirement);
    }
}

/// Round trip one example; returns the problem read back.
fn round_trip(file: &str, system: Option<&str>) -> (Problem, Problem) {
    let p = problem_of(&example(file), system);
    let xml = write(&p).expect("export");
    let q = read(&xml).unwrap_or_else(|e| panic!("{e}\n{xml}"));
    assert_same_automata(&p, &q);
    if q.automata.len() == p.automata.len() {
        // Single-automaton `never`s became forbidden states: the same product states are
        // forbidden (checked over the whole product where it is small).
        if p.product_size() <= 1e5 {
            let dims: Vec<u32> = p.automata.iter().map(|a| a.locs.len() as u32).collect();
            let mut v = vec![0u32; dims.len()];
            'all: loop {
                assert_eq!(p.is_forbidden(&v), q.is_forbidden(&v), "{v:?}");
                for i in 0..v.len() {
                    v[i] += 1;
                    if v[i] < dims[i] {
                        continue 'all;
                    }
                    v[i] = 0;
                }
                break;
            }
        }
    }
    (p, q)
}

#[test]
fn examples_round_trip_with_the_known_answers() {
    // Known answers from benchmarks.rs (Wonham's, the published cat and mouse, hand-derived).
    let known: &[(&str, Option<&str>, (u128, u128))] = &[
        ("small_factory.sc", Some("SmallFactory"), (12, 25)),
        ("small_factory.sc", Some("SmallFactoryRepair"), (12, 24)),
        ("cat_mouse.sc", None, (6, 9)),
        ("transfer_line.sc", None, (28, 65)),
    ];
    for &(file, system, answer) in known {
        let (p, q) = round_trip(file, system);
        for engine in [Engine::Explicit, Engine::Symbolic] {
            assert_eq!(
                sizes(&q, engine),
                Some(answer),
                "{file} {system:?} {engine:?}"
            );
        }
        assert_eq!(sizes(&p, Engine::Explicit), Some(answer));
    }
    // The line family: 3 * 4^(n-1) supervisor states (families::line); line_4 has 192.
    let (_, q) = round_trip("line_4.sc", None);
    assert_eq!(sizes(&q, Engine::Explicit).map(|s| s.0), Some(192));
    // line_12: 3 * 4^11 states, by the symbolic engine.
    let (_, q) = round_trip("line_12.sc", None);
    assert_eq!(
        sizes(&q, Engine::Symbolic).map(|s| s.0),
        Some(3 * 4u128.pow(11))
    );
    // Philosophers: no published figure here; the XML must give what the .sc gives.
    let (p, q) = round_trip("philosophers_5.sc", None);
    assert_eq!(sizes(&q, Engine::Explicit), sizes(&p, Engine::Explicit));
}

#[test]
fn hand_written_small_factory() {
    let q = read(&example("small_factory.xml")).expect("reads");
    assert_eq!(q.automata.len(), 3);
    assert_eq!(q.events.len(), 8);
    assert!(!q.events[1].controllable, "finish1 is uncontrollable");
    // 12 states (small_factory.sc's derivation: 18 - 3 - 3), 25 transitions (benchmarks.rs).
    for engine in [Engine::Explicit, Engine::Symbolic] {
        assert_eq!(sizes(&q, engine), Some((12, 25)));
    }
    // The same automata as the .sc model.
    assert_same_automata(
        &problem_of(&example("small_factory.sc"), Some("SmallFactory")),
        &q,
    );
}

#[test]
fn no_accepting_state_marks_nothing() {
    // Supremica: an automaton with no accepting state has an empty marked language, so no
    // state of the product is marked, every state is blocking, and no supervisor exists.
    let xml = example("small_factory.xml").replace(
        r#"name="Empty" initial="true" accepting="true""#,
        r#"name="Empty" initial="true""#,
    );
    let q = read(&xml).expect("reads");
    assert_eq!(q.automata[2].marked, vec![false, false]);
    assert_eq!(sizes(&q, Engine::Explicit), None);
    assert_eq!(sizes(&q, Engine::Symbolic), None);
}

const ODD: &str = r#"<Automata name="odd">
<Automaton name="Cat(0)" type="Plant">
  <Events><Event id="a" label="land.0"/><Event id="b" label="take &amp; go" controllable="false"/></Events>
  <States><State id="s0" initial="true" accepting="true"/><State id="s 1"/></States>
  <Transitions>
    <Transition source="s0" dest="s 1" event="a"/>
    <Transition source="s 1" dest="s0" event="b"/>
  </Transitions>
</Automaton>
<Automaton name="spec" type="Supervisor">
  <Events><Event id="0" label="land.0"/></Events>
  <States><State id="0" name="q" initial="true" accepting="true" forbidden="false"/></States>
  <Transitions><Transition source="0" dest="0" event="0"/></Transitions>
</Automaton>
<Automaton name="ignored" type="Property">
  <Events><Event id="0" label="other"/></Events>
  <States><State id="0" initial="true"/></States>
</Automaton>
</Automata>"#;

#[test]
fn external_labels_keep_their_names() {
    let q = read(ODD).expect("reads");
    let names: Vec<&str> = q.events.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(names, ["land.0", "take & go"]);
    assert_eq!(q.automata[0].name, "Cat(0)");
    assert_eq!(q.automata[0].locs, ["s0", "s 1"]);
    assert_eq!(q.automata[1].kind, Kind::Requirement);
    assert_eq!(q.automata.len(), 2, "the Property automaton is skipped");
    // And back: written and read again, the same problem.
    let r = read(&write(&q).expect("export")).expect("reads back");
    assert_same_automata(&q, &r);
    assert_eq!(r.automata.len(), 2);
    // Both states marked-reachable, nothing forbidden: the supervisor is the plant (2, 2).
    assert_eq!(sizes(&q, Engine::Explicit), Some((2, 2)));
}

fn err(xml: &str) -> (String, u32, u32) {
    let e = read(xml).expect_err("must fail");
    (e.code.to_string(), e.line, e.col)
}

#[test]
fn errors_have_codes_and_positions() {
    // Not well-formed: the unclosed <States> is reported where the parser stops (line 3,
    // at the `</Automaton>` that does not match).
    let (code, line, _) =
        err("<Automata>\n<Automaton name=\"a\" type=\"Plant\">\n<States></Automaton></Automata>");
    assert_eq!((code.as_str(), line), ("E0720", 3));
    // Wrong root element, at 1:1.
    assert_eq!(err("<Project/>"), ("E0721".into(), 1, 1));
    // A transition to an undeclared state: the <Transition> at line 4, column 14.
    let xml = "<Automata><Automaton name=\"a\" type=\"Plant\">\n<Events><Event id=\"e\"/></Events>\n<States><State id=\"s\" initial=\"true\"/></States>\n<Transitions><Transition source=\"s\" dest=\"t\" event=\"e\"/></Transitions>\n</Automaton></Automata>";
    assert_eq!(err(xml), ("E0722".into(), 4, 14));
    // Nondeterministic.
    let xml = xml.replace(
        "<State id=\"s\" initial=\"true\"/>",
        "<State id=\"s\" initial=\"true\"/><State id=\"t\"/>",
    );
    let nondet = xml.replace(
        "</Transitions>",
        "<Transition source=\"s\" dest=\"s\" event=\"e\"/></Transitions>",
    );
    assert_eq!(err(&nondet).0, "E0723");
    // No initial state, at the <Automaton> (1:11).
    let no_init = xml.replace(" initial=\"true\"", "");
    assert_eq!(err(&no_init), ("E0724".into(), 1, 11));
    // Controllability conflict.
    let two = "<Automata><Automaton name=\"a\" type=\"Plant\"><Events><Event id=\"e\"/></Events><States><State id=\"s\" initial=\"true\"/></States></Automaton>\n<Automaton name=\"b\" type=\"Plant\"><Events><Event id=\"e\" controllable=\"false\"/></Events><States><State id=\"s\" initial=\"true\"/></States></Automaton></Automata>";
    assert_eq!(err(two).0, "E0725");
    // No plant; an unknown type.
    assert_eq!(err("<Automata/>").0, "E0726");
    assert_eq!(
        err("<Automata><Automaton name=\"a\" type=\"Interface\"/></Automata>"),
        ("E0726".into(), 1, 11)
    );
    // A bad flag.
    let bad = xml.replace("initial=\"true\"", "initial=\"yes\"");
    assert_eq!(err(&bad).0, "E0721");
}

#[test]
fn sc_names_are_identifiers_and_distinct() {
    use statecheck_synth::supremica::idents::sc_names;
    let is_ident = |s: &str| {
        s.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            && s != "state"
    };
    let mut q = read(ODD).expect("reads");
    q.events[1].name = "land_0".into(); // collides with the mapping of `land.0`
    q.automata[1].locs[0] = "state".into(); // a keyword
    let (r, renamed) = sc_names(&q, &is_ident);
    let ev: Vec<&str> = r.events.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(ev, ["land_0_2", "land_0"]);
    assert_eq!(r.automata[0].name, "Cat_0_");
    assert_eq!(r.automata[0].locs, ["s0", "s_1"]);
    assert_eq!(r.automata[1].locs, ["x_state"]);
    assert_eq!(renamed.len(), 4);
    assert_eq!(renamed[0].from, "land.0");
}
