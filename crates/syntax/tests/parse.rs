//! Parse tests: every `tests/data/parse/*.sc` file must parse without diagnostics, and its AST
//! (in the compact rendering of `common::render_file`) is pinned by an insta snapshot.

#![allow(clippy::unwrap_used)] // tests may unwrap

mod common;

use statecheck_syntax::ast::{Expr, Item, Stmt};
use statecheck_syntax::parse;

#[test]
fn parse_data_files() {
    let files = common::data_files("parse");
    assert!(files.len() >= 10, "parse data files are missing");
    for (name, src) in files {
        let (file, diags) = parse(&src);
        assert!(
            diags.is_empty(),
            "{name}.sc should parse cleanly:\n{}",
            common::render_diags(&src, &diags)
        );
        insta::assert_snapshot!(name.clone(), common::render_file(&file));
    }
}

/// The full `Debug` form of a small file, pinning every span.
#[test]
fn spans_of_a_small_file() {
    let src =
        "const A: int[0..3] = -x + 1;\nchart C { on go [a] / { n += 1; } -> B.C priority 2; }\n";
    let (file, diags) = parse(src);
    assert!(diags.is_empty());
    insta::assert_debug_snapshot!(file);
}

/// Whole-construct spans cover exactly the construct's text.
#[test]
fn item_spans_cover_their_text() {
    let src = "  const A = 1 + 2;  enum E { X }\nfn f() -> int = 0;\ntick 3 s;\nchart C { }\nsystem S { }\n";
    let (file, diags) = parse(src);
    assert!(diags.is_empty());
    let texts: Vec<&str> = file
        .items
        .iter()
        .map(|i| {
            let span = match i {
                Item::Const(c) => c.span,
                Item::Enum(e) => e.span,
                Item::Fn(f) => f.span,
                Item::Tick(t) => t.span,
                Item::Import(i) => i.span,
                Item::Chart(c) => c.span,
                Item::Interface(i) => i.span,
                Item::Component(c) => c.span,
                Item::System(s) => s.span,
            };
            &src[span.range()]
        })
        .collect();
    assert_eq!(
        texts,
        [
            "const A = 1 + 2;",
            "enum E { X }",
            "fn f() -> int = 0;",
            "tick 3 s;",
            "chart C { }",
            "system S { }"
        ]
    );
}

/// `x += e` desugars to `x = x + e`, spanning `x += e`.
#[test]
fn compound_assignment_desugars() {
    let src = "chart C { entry { n += 2 * k; m -= 1; } }";
    let (file, diags) = parse(src);
    assert!(diags.is_empty());
    let Item::Chart(c) = &file.items[0] else {
        panic!("not a chart")
    };
    let stmts = &c.body.entry[0].stmts;
    let Stmt::Assign {
        target,
        value,
        span,
        ..
    } = &stmts[0]
    else {
        panic!("not an assignment")
    };
    assert_eq!(target.name, "n");
    assert_eq!(common::expr(value), "(+ n (* 2 k))");
    assert_eq!(&src[value.span().range()], "n += 2 * k");
    assert_eq!(&src[span.range()], "n += 2 * k;");
    let Stmt::Assign { value, .. } = &stmts[1] else {
        panic!("not an assignment")
    };
    assert_eq!(common::expr(value), "(- m 1)");
}

/// Binary expression spans run from the first to the last operand.
#[test]
fn expression_spans() {
    let src = "const A = (a + b) * -c;";
    let (file, _) = parse(src);
    let Item::Const(c) = &file.items[0] else {
        panic!("not a const")
    };
    let Expr::Binary(_, lhs, rhs, span) = &c.value else {
        panic!("not binary")
    };
    assert_eq!(&src[span.range()], "a + b) * -c");
    assert_eq!(&src[lhs.span().range()], "a + b");
    assert_eq!(&src[rhs.span().range()], "-c");
}
