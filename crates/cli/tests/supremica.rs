//! `statecheck synth FILE.xml`, `statecheck export supremica` and `verify --plant FILE.xml`
//! end to end (Supremica automata XML, docs/synthesis.md).

use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_statecheck"))
}

fn example(name: &str) -> String {
    format!(
        "{}/../../examples/synthesis/{name}",
        env!("CARGO_MANIFEST_DIR")
    )
}

fn run(args: &[&str]) -> (Option<i32>, String, String) {
    let o = bin().args(args).output().expect("runs");
    (
        o.status.code(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

fn temp(name: &str) -> String {
    let dir = std::env::temp_dir().join(format!("statecheck-supremica-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name).to_string_lossy().into_owned()
}

#[test]
fn hand_written_small_factory() {
    // Wonham's answer (examples/synthesis/small_factory.sc): 12 states; 25 transitions as
    // counted by hand in crates/synth/tests/benchmarks.rs.
    let (code, out, err) = run(&["synth", &example("small_factory.xml"), "-q"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("supervisor 12 states 25 transitions"), "{out}");
}

#[test]
fn export_then_synth_then_verify() {
    // The repair requirement (a `needs`) is exported as an observer automaton; Wonham's
    // FACTSUPER has 12 states and 24 transitions.
    let xml = temp("factory.xml");
    let (code, _, err) = run(&[
        "export",
        "supremica",
        &example("small_factory.sc"),
        "--system",
        "SmallFactoryRepair",
        "-o",
        &xml,
    ]);
    assert_eq!(code, Some(0), "{err}");
    let text = std::fs::read_to_string(&xml).expect("written");
    assert!(text.contains("<Automaton name=\"needs_0\" type=\"Specification\">"));
    let sup = temp("factory_sup.sc");
    let (code, out, err) = run(&["synth", &xml, "--check", "-o", &sup]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("supervisor: 12 states, 24 transitions"),
        "{out}"
    );
    // The supervisor from the XML passes the check against the .sc plant and the XML plant.
    let (code, out, _) = run(&[
        "verify",
        &sup,
        "--plant",
        &example("small_factory.sc"),
        "--plant-system",
        "SmallFactoryRepair",
    ]);
    assert_eq!(code, Some(0), "{out}");
    assert!(
        out.contains("controllable, nonblocking, requirements hold"),
        "{out}"
    );
    let (code, out, _) = run(&["verify", &sup, "--plant", &xml]);
    assert_eq!(code, Some(0), "{out}");
    assert!(
        out.contains("controllable, nonblocking, requirements hold"),
        "{out}"
    );
}

#[test]
fn labels_that_are_not_identifiers() {
    let xml = temp("odd.xml");
    std::fs::write(
        &xml,
        r#"<Automata name="odd">
<Automaton name="Cat(0)" type="Plant">
  <Events><Event id="a" label="land.0"/><Event id="b" label="take &amp; go" controllable="false"/></Events>
  <States><State id="s0" initial="true" accepting="true"/><State id="s 1"/></States>
  <Transitions>
    <Transition source="s0" dest="s 1" event="a"/>
    <Transition source="s 1" dest="s0" event="b"/>
  </Transitions>
</Automaton>
</Automata>"#,
    )
    .expect("write");
    let sup = temp("odd_sup.sc");
    let (code, out, err) = run(&["synth", &xml, "--check", "-o", &sup]);
    assert_eq!(code, Some(0), "{err}");
    // The printed guards keep the labels; the file maps them and says so.
    assert!(out.contains("land.0: true"), "{out}");
    let text = std::fs::read_to_string(&sup).expect("written");
    assert!(text.contains("//   event `land.0` -> land_0"), "{text}");
    assert!(text.contains("//   automaton `Cat(0)` -> Cat_0_"), "{text}");
    let (code, out, _) = run(&["verify", &sup, "--plant", &xml]);
    assert_eq!(code, Some(0), "{out}");
}

#[test]
fn errors_point_at_the_element() {
    let xml = temp("bad.xml");
    std::fs::write(
        &xml,
        "<Automata>\n<Automaton name=\"a\" type=\"Plant\">\n<Events><Event id=\"e\"/></Events>\n<States><State id=\"s\" initial=\"true\"/></States>\n<Transitions><Transition source=\"s\" dest=\"t\" event=\"e\"/></Transitions>\n</Automaton></Automata>",
    )
    .expect("write");
    let (code, _, err) = run(&["synth", &xml]);
    assert_eq!(code, Some(1), "{err}");
    assert!(err.contains("E0722"), "{err}");
    assert!(err.contains("bad.xml:5:14"), "{err}");
    // --system does not apply to an XML file: a usage error.
    let (code, _, err) = run(&["synth", &example("small_factory.xml"), "--system", "X"]);
    assert_ne!(code, Some(0), "{err}");
}
