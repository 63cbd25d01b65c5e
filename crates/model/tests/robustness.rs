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

/// A chart whose state `S` has a transition into a chain of `n` junctions, the last one
/// leading to `T`; with `fan`, every junction reaches the next by two branches.
fn junction_chain(n: usize, fan: bool) -> String {
    let mut s = String::from("chart J {\n  input x: int[0..9] = 0;\n  initial S;\n  state S {\n");
    s.push_str("    on [x > 0] -> j0;\n");
    for k in 0..n {
        let next = if k + 1 == n {
            "T".to_string()
        } else {
            format!("j{}", k + 1)
        };
        if fan {
            s.push_str(&format!(
                "    junction j{k} {{ [x > 1] -> {next}; else -> {next}; }}\n"
            ));
        } else {
            s.push_str(&format!("    junction j{k} {{ [x > 0] -> {next}; }}\n"));
        }
    }
    s.push_str("  }\n  state T;\n}\n");
    s
}

#[test]
fn long_junction_chain_is_a_diagnostic_not_a_stack_overflow() {
    // 6,000 chained junctions once overflowed the stack. The path from `S` passes j0..j99
    // (100 junctions, the limit) and is stopped at the reference to j100 on line 105
    // (line 5 holds `on ... -> j0`, junction jk is on line 6 + k).
    let errs = errors(&junction_chain(6000, false));
    assert_eq!(errs, [("E0124", 105)]);
    // A chain of exactly 100 junctions is accepted.
    assert_eq!(errors(&junction_chain(100, false)), []);
}

#[test]
fn junctions_reached_by_many_paths_do_not_expand_exponentially() {
    // 30 junctions with two branches each to the next: 2^30 paths. The expansion budget
    // (10,000 junctions per transition) stops it with one diagnostic instead of running out
    // of memory.
    let errs = errors(&junction_chain(30, true));
    assert!(
        !errs.is_empty() && errs.iter().all(|e| e.0 == "E0124"),
        "{errs:?}"
    );
    assert_eq!(errs.len(), 1);
}

#[test]
fn very_long_unknown_identifier_gets_no_suggestion() {
    // A 100,000-character unknown name once spent 36 s in the "did you mean" search. Names
    // longer than MAX_SUGGEST_LEN (128) are not compared: one E0101 error without a hint.
    let name = "a".repeat(100_000);
    let src = format!(
        "chart M {{ output aa: int[0..1] = 0; initial S; state S {{ during {{ aa = {name}; }} }} }}\n"
    );
    let (file, parse) = statecheck_syntax::parse(&src);
    assert!(parse.is_empty());
    let (_, diags) = statecheck_model::check(&file);
    let errs: Vec<&Diagnostic> = diags.iter().filter(|d| d.is_error()).collect();
    assert_eq!(errs.len(), 1, "{errs:#?}");
    assert_eq!(errs[0].code, "E0101");
    assert!(errs[0]
        .hint
        .as_deref()
        .is_none_or(|h| !h.contains("did you mean")));
    // A short typo still gets its suggestion.
    let src =
        "chart M { output level: int[0..1] = 0; initial S; state S { during { levle = 1; } } }\n";
    let (file, _) = statecheck_syntax::parse(src);
    let (_, diags) = statecheck_model::check(&file);
    assert!(diags
        .iter()
        .any(|d| d.hint.as_deref().is_some_and(|h| h.contains("`level`"))));
}

#[test]
fn suggestions_for_unknown_targets_in_deep_nesting_have_bounded_cost() {
    // Found by `crates/fuzz` (a mutated history model, 29 KB): every unknown target's
    // "did you mean" search once compared every state's every suffix from every enclosing
    // state, states × depth³ per diagnostic; 120 nested states each with an unknown target
    // took minutes (debug build). Every unknown target still gets its E0111, one per line.
    let n = 120;
    let mut src = String::from("chart M {\n  input event e;\n  initial S0;\n");
    for k in 0..n {
        src.push_str(&format!(
            "  state S{k} {{ on e -> nowhere{k};\n  initial S{};\n",
            k + 1
        ));
    }
    src.push_str(&format!("  state S{n};\n"));
    for _ in 0..n {
        src.push_str("  }\n");
    }
    src.push_str("}\n");
    let errs = errors(&src);
    let want: Vec<(&str, usize)> = (0..n).map(|k| ("E0111", 4 + 2 * k)).collect();
    assert_eq!(errs, want);
}

#[test]
fn tick_hint_for_a_very_slow_motion_has_bounded_cost() {
    // Found by the `check` fuzz target (a mutated tests/hybrid/params.sc): a rate of 20/2^40 %
    // per second makes the crossing of one 5 % cell take 5 / (20 / 2^40) = 2^38 s, i.e.
    // 2^38 / 1.25 = 219,902,325,555.2 ticks: not a whole number, so E0181 at the `der` line.
    // Its hint searched every tick length g/m for m from 2.2e11 down to 1 (hours); it is
    // now a bounded search.
    let src = "tick 1250 ms;
plant chart Mover {
  input go: bool = false;
  continuous pos: [0 .. 100] = 0;
  grid pos 20;
  initial Home;
  state Home { on [go] -> Move; }
  state Move {
    der(pos) = 20 / 1099511627776;
    on [pos >= 100] -> Home;
  }
}
";
    assert_eq!(errors(src), vec![("E0181", 9)]);
}

#[test]
fn a_parameterised_chart_named_like_an_earlier_chart_is_a_duplicate_not_a_panic() {
    // Found by the `check` fuzz target: the second `A` has a parameter, the first has none;
    // the parameter expansion looked the second up in the first's (absent) signature and
    // panicked. It is one error: E0102, the duplicate name, at the second declaration.
    let src = "chart A { initial S; state S; }
chart A(k: int[0..3]) { initial S; state S; }
";
    assert_eq!(errors(src), vec![("E0102", 2)]);
}

#[test]
fn thousands_of_copies_of_a_component_with_bad_names_are_checked_in_linear_time() {
    // `statecheck-fuzz show --target check --seed 12021250 --index 98689` (a mutation of the
    // component-size family) took 5.2 s in `check` (56 s in a debug build): each of the
    // thousands of flattened copies of a component with an unknown endpoint scanned every
    // diagnostic so far, and the cascade suppression made a pass over the diagnostics per
    // instance of an unknown chart. Here L0 holds an instance of the unknown chart `Missing`
    // and a connection from the unknown instance `nope`; L11 doubles it 11 times (2048
    // copies of L0, 4095 instances: under the limit of 4096) and three systems flatten it:
    // 6144 copies, which the quadratic passes made tens of millions of message scans.
    // Every problem is reported once, at its span in L0's line: the unknown chart, the two
    // connections through the missing instance `x`, and `nope`.
    let mut src = String::from("component L0 { input a: bool; output b: bool; instance x: Missing; connect a -> x.a; connect x.b -> b; connect a -> nope.a; }\n");
    for k in 1..=11 {
        src.push_str(&format!(
            "component L{k} {{ input a: bool; output b: bool; instance x: L{j}; instance y: L{j}; connect a -> x.a; connect x.b -> y.a; connect y.b -> b; }}\n",
            j = k - 1
        ));
    }
    for i in 0..3 {
        src.push_str(&format!("system T{i} {{ instance t: L11; }}\n"));
    }
    assert_eq!(errors(&src), vec![("E0101", 1); 4]);
}
