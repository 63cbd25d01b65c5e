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
