//! One misspelt chart name reports once: the uses of its instance in the system are not
//! reported again (they follow from the first error), other errors still are.

use statecheck_base::LineIndex;

const MODEL: &str = "chart Lamp {
  input event go;
  output x: bool = false;
  input y: bool = false;
  initial A;
  state A { on go -> A; }
}
system S {
  instance l: Lmap;
  instance k: Lamp;
  connect l.x -> k.y;
  order l, k;
  invariant p: l.x || in(l.A);
  reachable q: in(l.A) && zz;
}
";

#[test]
fn an_unknown_chart_name_reports_once() {
    let (file, parse) = statecheck_syntax::parse(MODEL);
    assert!(parse.is_empty(), "{parse:?}");
    let (_, diags) = statecheck_model::check(&file);
    let idx = LineIndex::new(MODEL);
    let found: Vec<(&str, usize, usize, &str)> = diags
        .iter()
        .filter(|d| d.is_error())
        .map(|d| {
            let (l, c) = idx.line_col(d.span.start);
            (d.code, l, c, d.message.as_str())
        })
        .collect();
    // Line 9 `  instance l: Lmap;`: `Lmap` at column 15. Line 14: `zz` (column 27) is a
    // separate mistake and is still reported. Lines 11-14's uses of `l` are not.
    assert_eq!(
        found,
        [
            ("E0101", 9, 15, "unknown chart `Lmap`"),
            ("E0101", 14, 27, "unknown name `zz`")
        ]
    );
}

/// A component whose connection names an unknown instance, flattened into 2^12 copies (the
/// component `C12` runs alone: C0 holds one chart, Ck two Ck-1, so C12 holds 4096 copies of
/// C0's connection). The error is reported once and searched for a suggestion once: before,
/// every copy searched the 4096 flattened instance names (a fuzzed input like this one took
/// 40 s in `check`).
#[test]
fn an_error_in_a_component_copied_4096_times_is_found_once() {
    let mut src = String::from(
        "chart Leaf { input a: bool = false; output b: bool = false; initial S; \
         state S { during { b = a; } } }\n\
         component C0 { input a: bool; output b: bool; instance sensor: Leaf; \
         connect a -> sensro.a; connect sensor.b -> b; }\n",
    );
    for k in 1..=12 {
        let p = k - 1;
        src.push_str(&format!(
            "component C{k} {{ input a: bool; output b: bool; instance x: C{p}; \
             instance y: C{p}; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }}\n"
        ));
    }
    let (file, parse) = statecheck_syntax::parse(&src);
    assert!(parse.is_empty(), "{parse:?}");
    let (_, diags) = statecheck_model::check(&file);
    let unknown: Vec<_> = diags
        .iter()
        .filter(|d| d.is_error() && d.message == "unknown instance `sensro` in component `C0`")
        .collect();
    assert_eq!(unknown.len(), 1, "{diags:?}");
    // The suggestion comes from the component's own names, as written inside it.
    assert_eq!(unknown[0].hint.as_deref(), Some("did you mean `sensor`?"));
}
