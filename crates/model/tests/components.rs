//! Parameterised charts, interfaces and configurations at the model level
//! (`docs/components.md`): which charts and systems the expansion makes, which diagnostics it
//! keeps, and conformance of each instantiation. Expected codes, lines and names are read off
//! the texts below by hand.

use statecheck_base::{Diagnostic, LineIndex};

/// (code, line) of every error, in order (design-rule warnings are not the point here), and
/// the model's chart and system names.
fn check(src: &str) -> (Vec<(&'static str, usize)>, Vec<String>, Vec<String>) {
    let (file, parse) = statecheck_syntax::parse(src);
    assert!(parse.is_empty(), "{parse:#?}");
    let (model, diags) = statecheck_model::check(&file);
    let idx = LineIndex::new(src);
    let codes = diags
        .iter()
        .filter(|d| d.is_error())
        .map(|d: &Diagnostic| (d.code, idx.line_col(d.span.start).0))
        .collect();
    let charts = model.charts.iter().map(|c| c.name.clone()).collect();
    let systems = model.systems.iter().map(|s| s.name.clone()).collect();
    (codes, charts, systems)
}

#[test]
fn one_chart_per_distinct_argument_list_and_defaults_under_the_plain_name() {
    let src = "chart C(k: int[0..9] = 1) { output v: int[0..9] = k; initial S; state S; }
system Sys {
  instance a: C(2);
  instance b: C(k = 2);
  instance c: C;
  instance d[3]: C(3);
}
";
    let (codes, charts, systems) = check(src);
    assert_eq!(codes, vec![]);
    // C with its default (1), then C(2) for a and b, then C(3) for d.
    assert_eq!(charts, vec!["C", "C(2)", "C(3)"]);
    // Only the copy with the defaults runs alone, under the chart's name.
    assert_eq!(systems, vec!["Sys", "C"]);
}

#[test]
fn a_chart_with_a_required_parameter_never_runs_alone_and_is_checked_for_names_only() {
    // Line 2: `after(k)` with the placeholder k = 0 would be a bad delay, which depends on
    // the value and is not reported; line 3's unknown name `nope` does not depend on it.
    let src = "chart C(k: int[0..9]) { initial S;
  state S { on after(k) -> T; }
  state T { entry { nope = 1; } }
}
";
    let (codes, charts, systems) = check(src);
    assert_eq!(codes, vec![("E0101", 3)]);
    assert_eq!(charts, vec!["C"]);
    assert_eq!(systems, Vec::<String>::new());
}

#[test]
fn a_problem_of_one_argument_list_is_reported_once_with_the_instance() {
    // v: int[0..k] = 5 is out of range for k = 3 (twice: a and b) but not for k = 7.
    let src = "chart C(k: int[0..9]) { output v: int[0..k] = 5; initial S; state S; }
system Sys {
  instance a: C(3);
  instance b: C(3);
  instance c: C(7);
}
";
    let (file, _) = statecheck_syntax::parse(src);
    let (_, diags) = statecheck_model::check(&file);
    let errors: Vec<&Diagnostic> = diags.iter().filter(|d| d.is_error()).collect();
    assert_eq!(errors.len(), 1, "{errors:#?}");
    assert_eq!(errors[0].code, "E0104");
    // The second label points at `C` of line 3 (instance a), the first with these arguments.
    let idx = LineIndex::new(src);
    let at: Vec<usize> = errors[0]
        .secondary
        .iter()
        .map(|l| idx.line_col(l.span.start).0)
        .collect();
    assert_eq!(at, vec![3]);
}

#[test]
fn conformance_is_checked_for_each_instantiation() {
    // `output v: int[0..k]` fits the interface's int[0..5] for k = 3, not for k = 8.
    let src = "interface Out { output v: int[0..5]; }
chart C(k: int[0..9] = 3) implements Out { output v: int[0..k] = 0; initial S; state S; }
system Sys {
  instance a: C;
  instance b: C(8);
}
";
    let (codes, charts, _) = check(src);
    assert_eq!(codes, vec![("E0154", 2)]);
    assert_eq!(charts, vec!["C", "C(8)"]);
}

#[test]
fn configurations_make_one_system_each_and_the_plain_name_is_the_first() {
    let src = "interface Src { output v: int[0..3]; }
chart A implements Src { output v: int[0..3] = 1; initial S; state S; }
chart B implements Src { output v: int[0..3] = 2; initial S; state S; }
chart Sink { input v: int[0..3] = 0; initial S; state S; }
system Sys {
  instance s: Src;
  instance k: Sink;
  connect s.v -> k.v;
  configuration one { s = A; }
  configuration two { s = B; }
}
";
    let (file, _) = statecheck_syntax::parse(src);
    let (model, diags) = statecheck_model::check(&file);
    assert!(diags.iter().all(|d| !d.is_error()), "{diags:#?}");
    let names: Vec<&str> = model
        .systems
        .iter()
        .filter(|s| !s.implicit)
        .map(|s| s.name.as_str())
        .collect();
    assert_eq!(names, vec!["Sys", "Sys:one", "Sys:two"]);
    // The chart of slot `s` in each: A, A, B.
    let chart_of_s = |sys: &str| {
        let s = model.system(sys).expect("system");
        let i = s.instances.iter().find(|i| i.name == "s").expect("slot");
        model.charts[i.chart as usize].name.clone()
    };
    assert_eq!(chart_of_s("Sys"), "A");
    assert_eq!(chart_of_s("Sys:one"), "A");
    assert_eq!(chart_of_s("Sys:two"), "B");
}
