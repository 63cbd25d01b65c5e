//! Regression tests for inputs that once crashed or stalled the checker (issue 20), each named
//! after what it guards. Every test parses and checks a model built in the test and asserts
//! the diagnostics it must give; none of them may panic.

use statecheck_base::Diagnostic;

/// Parse and check `src`; the error codes with their 1-based line, in order.
fn errors(src: &str) -> Vec<(&'static str, usize)> {
    let (file, parse) = statecheck_syntax::parse(src);
    assert!(parse.is_empty(), "parse diagnostics: {parse:#?}");
    let (_, diags) = statecheck_model::check(&file);
    let index = statecheck_base::LineIndex::new(src);
    diags
        .iter()
        .filter(|d| d.is_error())
        .map(|d: &Diagnostic| (d.code, index.line_col(d.span.start).0))
        .collect()
}

#[test]
fn constant_min_divided_by_minus_one_is_a_constant_error_not_a_panic() {
    // i64::MIN / -1 = 2^63, which has no 64-bit value: E0104 ("this constant expression fails").
    assert_eq!(
        errors("const C = (-9223372036854775807 - 1) / -1;\n"),
        [("E0104", 1)]
    );
    // abs(i64::MIN) = 2^63 likewise.
    assert_eq!(
        errors("const D = abs(-9223372036854775807 - 1);\n"),
        [("E0104", 1)]
    );
}

#[test]
fn division_bounds_of_an_input_reaching_i64_min_do_not_overflow() {
    // `i / -1` over i in [i64::MIN, 0] is [0, 2^63]; its bound saturates and the division is
    // checked at run time, so the model is valid.
    let src = "chart M {
  input i: int[-9223372036854775807 - 1..0] = 0;
  output o: int[-10..10] = 0;
  output p: int[0..10] = 0;
  initial S;
  state S { during { o = min(i / -1, 1); p = min(abs(i), 1); } }
}
";
    assert_eq!(errors(src), []);
}
