//! Import resolution through an in-memory resolver: relative paths, lists, diamonds, cycles,
//! missing files, duplicates and name clashes, each with the file its diagnostic points into.

use statecheck_base::Diagnostic;
use statecheck_model::imports::{load, FileText, MemoryResolver, Program};
use statecheck_syntax::ast::Item;

const SENSORS: &str = "const MAXR = 9;
chart Sensor { input raw: int[0..MAXR] = 0; output present: bool = false; initial S;
  state S { during { present = raw > 3; } } }
chart SensorWithFault { input raw: int[0..MAXR] = 0; output present: bool = false; initial S;
  state S; }
system SensorAlone { instance s: Sensor; }
";

fn program(files: &[(&str, &str)]) -> Program {
    let mut r = MemoryResolver::default();
    for (k, t) in files {
        r.files.insert((*k).to_string(), (*t).to_string());
    }
    let (k, t) = files[0];
    load(
        FileText {
            key: k.into(),
            name: k.into(),
            text: t.into(),
        },
        &mut r,
    )
}

/// The names of the merged items, in order.
fn names(p: &Program) -> Vec<String> {
    p.file
        .items
        .iter()
        .filter_map(|i| match i {
            Item::Const(c) => Some(c.name.name.clone()),
            Item::Chart(c) => Some(c.name.name.clone()),
            Item::System(s) => Some(s.name.name.clone()),
            _ => None,
        })
        .collect()
}

/// `code @ file:line:col` of every diagnostic.
fn where_(p: &Program, ds: &[Diagnostic]) -> Vec<String> {
    ds.iter()
        .map(|d| format!("{} @ {}", d.code, p.sources.position(d.span)))
        .collect()
}

#[test]
fn relative_import_with_a_list_brings_in_the_listed_charts_and_the_constants() {
    let p = program(&[
        (
            "app/main.sc",
            "import \"../lib/sensors.sc\" { Sensor };\nsystem Main { instance s: Sensor; }\n",
        ),
        ("lib/sensors.sc", SENSORS),
    ]);
    assert!(p.diags.is_empty(), "{:?}", p.diags);
    // SensorWithFault and SensorAlone are not listed; MAXR always comes along.
    assert_eq!(names(&p), ["MAXR", "Sensor", "Main"]);
    let (_, diags) = statecheck_model::check(&p.file);
    assert!(!diags.iter().any(Diagnostic::is_error), "{diags:?}");
}

#[test]
fn a_listed_system_brings_its_charts() {
    let p = program(&[
        ("main.sc", "import \"sensors.sc\" { SensorAlone };\n"),
        ("sensors.sc", SENSORS),
    ]);
    assert_eq!(names(&p), ["MAXR", "Sensor", "SensorAlone"]);
}

#[test]
fn a_diamond_loads_the_shared_file_once() {
    let p = program(&[
        ("m.sc", "import \"b.sc\";\nimport \"c.sc\";\n"),
        ("b.sc", "import \"d.sc\";\nconst B = D;\n"),
        ("c.sc", "import \"d.sc\";\nconst C = D;\n"),
        ("d.sc", "const D = 1;\n"),
    ]);
    assert!(p.diags.is_empty(), "{:?}", p.diags);
    assert_eq!(names(&p), ["D", "B", "C"]);
    assert_eq!(p.sources.files.len(), 4);
}

#[test]
fn a_cycle_is_reported_where_it_closes() {
    let p = program(&[
        ("a.sc", "import \"b.sc\";\nconst A = 1;\n"),
        ("b.sc", "const B = 2;\nimport \"a.sc\";\n"),
    ]);
    assert_eq!(where_(&p, &p.diags), ["E0141 @ b.sc:2:8"]);
    assert_eq!(p.diags[0].label, "imports a.sc -> b.sc -> a.sc");
}

#[test]
fn a_file_importing_itself_is_a_cycle() {
    let p = program(&[("a.sc", "import \"./a.sc\";\n")]);
    assert_eq!(where_(&p, &p.diags), ["E0141 @ a.sc:1:8"]);
}

#[test]
fn a_missing_file_is_reported_at_its_import() {
    let p = program(&[("a.sc", "const A = 1;\nimport \"nope.sc\";\n")]);
    assert_eq!(where_(&p, &p.diags), ["E0140 @ a.sc:2:8"]);
}

#[test]
fn one_file_imported_twice_by_one_file() {
    let p = program(&[
        (
            "a.sc",
            "import \"s.sc\" { Sensor };\nimport \"x/../s.sc\";\n",
        ),
        ("s.sc", SENSORS),
    ]);
    assert_eq!(where_(&p, &p.diags), ["E0143 @ a.sc:2:8"]);
}

#[test]
fn an_unknown_listed_name_suggests_a_declared_one() {
    let p = program(&[("a.sc", "import \"s.sc\" { Sensr };\n"), ("s.sc", SENSORS)]);
    assert_eq!(where_(&p, &p.diags), ["E0142 @ a.sc:1:17"]);
    assert_eq!(p.diags[0].hint.as_deref(), Some("did you mean `Sensor`?"));
}

#[test]
fn a_name_clash_across_files_points_into_both() {
    let p = program(&[
        (
            "a.sc",
            "import \"s.sc\";\nchart Sensor { initial S; state S; }\n",
        ),
        ("s.sc", SENSORS),
    ]);
    assert!(p.diags.is_empty());
    let (_, diags) = statecheck_model::check(&p.file);
    let dup: Vec<_> = diags.iter().filter(|d| d.code == "E0102").collect();
    assert_eq!(dup.len(), 1, "{diags:?}");
    let d = dup[0];
    let mut places = vec![p.sources.position(d.span)];
    places.extend(d.secondary.iter().map(|l| p.sources.position(l.span)));
    places.sort();
    assert_eq!(places, ["a.sc:2:7", "s.sc:2:7"]);
}

#[test]
fn syntax_errors_of_an_imported_file_point_into_it() {
    let p = program(&[("a.sc", "import \"b.sc\";\n"), ("b.sc", "\nconst X = ;\n")]);
    let w = where_(&p, &p.diags);
    assert_eq!(w.len(), 1, "{w:?}");
    // The missing expression is the empty span right after `=`, at column 10.
    assert_eq!(w[0], "E0010 @ b.sc:2:10");
}

/// `load_with` joins relative imports to the importing file's directory with the leading `/`
/// kept (file-system paths), folds `..`, and reports an unreadable file at its import.
#[test]
fn read_resolver_keeps_absolute_paths() {
    let files = [
        ("/m/lib/consts.sc", "const N = 3;"),
        (
            "/m/lib/c.sc",
            "chart C { output x: int[0..N] = 0; initial S; state S; }",
        ),
    ];
    let mut asked = Vec::new();
    let p = statecheck_model::imports::load_with(
        "/m/top.sc",
        "import \"lib/consts.sc\"; import \"lib/../lib/c.sc\"; system T { instance c: C; }".into(),
        |k| {
            asked.push(k.to_string());
            files
                .iter()
                .find(|(f, _)| *f == k)
                .map(|(_, t)| t.to_string())
        },
    );
    assert!(p.diags.is_empty(), "{:?}", p.diags);
    assert_eq!(asked, ["/m/lib/consts.sc", "/m/lib/c.sc"]);
    assert_eq!(names(&p), ["N", "C", "T"]);
    let (_, diags) = statecheck_model::check(&p.file);
    assert!(!diags.iter().any(Diagnostic::is_error), "{diags:?}");

    let p =
        statecheck_model::imports::load_with("/m/top.sc", "import \"gone.sc\";".into(), |_| None);
    assert_eq!(p.diags.len(), 1);
    assert_eq!(p.diags[0].code, "E0140");
    assert!(
        format!("{:?}", p.diags[0]).contains("/m/gone.sc"),
        "{:?}",
        p.diags[0]
    );
}
