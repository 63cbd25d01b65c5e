//! Continuous plant variables, discretized (`docs/hybrid.md`).
//!
//! Before anything else is checked, every chart that declares `continuous x` is rewritten in
//! the file's syntax tree into an ordinary chart: `x` becomes an integer output holding the
//! last grid point the motion reached, plus a mode and a timer; a chart-level `during` moves
//! `x` from grid point to grid point after the exact clock readings (`modes.rs`) and keeps the
//! sensors equal to their range predicates. The rest of the checker, the IR and every engine
//! see only that chart. The generated code is written once, as text (`emit.rs`): it is parsed
//! into the tree here and printed in place by [`discretized_source`].

pub mod analyse;
mod critical;
mod emit;
mod modes;
mod plan;
mod rational;
mod respan;

pub use plan::{crossing, Mode, Plan};
pub use rational::Ratio;

use crate::expr::{ExprChecker, Sink};
use crate::scope::{Globals, Scope};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast::{self, HybridElem};

/// The continuous variables of one chart.
#[derive(Clone, Debug)]
pub struct ChartPlans {
    /// The chart's name.
    pub chart: String,
    /// One plan per continuous variable, in declaration order.
    pub plans: Vec<Plan>,
}

/// The discretized file and what was discretized.
pub(crate) struct Discretized {
    /// The file with every hybrid chart rewritten.
    pub file: ast::File,
    /// The plans of the charts discretized with their motion (not after an error, not the
    /// copies with placeholder values).
    pub plans: Vec<ChartPlans>,
}

/// The working context: constants, the tick, the file and the diagnostics.
pub(crate) struct Cx<'g, 'f> {
    ck: ExprChecker<'g>,
    file: &'f ast::File,
    /// The tick length in seconds.
    tick: Option<Ratio>,
    /// Diagnostics built whole (with hints) by the passes.
    file_diags: Vec<Diagnostic>,
}

impl Cx<'_, '_> {
    /// A constant integer expression (reports E0105 when it is not).
    fn konst(&mut self, e: &ast::Expr) -> Option<i64> {
        let scope = Scope::constants(self.ck.globals.fns.len());
        self.ck.const_value(&scope, e)
    }

    fn error(
        &mut self,
        span: Span,
        code: &'static str,
        msg: impl Into<String>,
        hint: impl Into<String>,
    ) {
        self.file_diags
            .push(Diagnostic::error(code, msg, span).with_hint(hint));
    }
}

fn has_hybrid(body: &ast::StateBody) -> bool {
    !body.hybrid.is_empty()
        || body.states.iter().any(|s| has_hybrid(&s.body))
        || body.regions.iter().any(|r| has_hybrid(&r.body))
}

/// What a pass does with a chart.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Treat {
    /// Discretize it.
    Discretize,
    /// Leave it as written (a parameterised chart, discretized per copy after expansion).
    Leave,
    /// Declare its variables only, without diagnostics (a copy with placeholder values).
    DeclareOnly,
}

/// The first pass, on the file as written: charts with parameters wait for their copies.
pub(crate) fn before_expansion(c: &ast::Chart, _index: usize) -> Treat {
    if c.params.is_empty() {
        Treat::Discretize
    } else {
        Treat::Leave
    }
}

/// The plans of one chart: its item index, its plans, and how it was treated.
type ChartEntry = (usize, Vec<Plan>, Treat);

/// The plans of every chart of `file` with continuous variables (`treat` gets each chart and
/// its index among the charts), and the diagnostics.
fn plan_file(
    file: &ast::File,
    globals: &Globals,
    treat: &dyn Fn(&ast::Chart, usize) -> Treat,
) -> (Vec<ChartEntry>, Vec<Diagnostic>) {
    let mut cx = Cx {
        ck: ExprChecker {
            globals,
            sink: Sink {
                diags: Vec::new(),
                muted: 0,
                once: Default::default(),
            },
            next_local: 0,
        },
        file,
        tick: globals.tick_ms.and_then(|ms| Ratio::new(ms as i128, 1000)),
        file_diags: Vec::new(),
    };
    let mut out = Vec::new();
    let mut chart_index = 0;
    for (i, item) in file.items.iter().enumerate() {
        if let ast::Item::Chart(_) = item {
            chart_index += 1;
        }
        match item {
            ast::Item::Chart(c) if has_hybrid(&c.body) => {
                let how = treat(c, chart_index - 1);
                if how == Treat::Leave {
                    continue;
                }
                let before = cx.file_diags.len();
                let sink_before = cx.ck.sink.diags.len();
                let plans = cx.plan_chart(c);
                for p in &plans {
                    cx.names_free(c, p);
                }
                if how == Treat::DeclareOnly {
                    cx.file_diags.truncate(before);
                    cx.ck.sink.diags.truncate(sink_before);
                }
                out.push((i, plans, how));
            }
            ast::Item::System(s) => {
                for o in &s.observers {
                    if has_hybrid(&o.body) {
                        let span = o.body.hybrid.first().map_or(o.span, HybridElem::span);
                        cx.error(
                            span,
                            "E0182",
                            "an observer cannot declare continuous variables",
                            "declare them in a plant chart",
                        );
                    }
                }
            }
            _ => {}
        }
    }
    let mut diags = cx.ck.sink.diags;
    diags.extend(cx.file_diags);
    (out, diags)
}

impl Cx<'_, '_> {
    /// The generated names must not clash with the chart's own.
    fn names_free(&mut self, c: &ast::Chart, p: &Plan) {
        let n = emit::Names::of(&p.var);
        for name in [&p.var, &n.ticks, &n.mode, &n.from] {
            if let Some(v) = c.vars.iter().find(|v| &v.name.name == name) {
                self.error(
                    v.name.span,
                    "E0182",
                    format!(
                        "`{name}` is declared, but the discretization of `{}` needs the name",
                        p.var
                    ),
                    "rename this variable",
                );
            }
        }
    }
}

/// Rewrite every hybrid chart of `file`; `None` when there is none. Diagnostics go to `diags`;
/// after an error the chart keeps its hybrid elements removed and nothing generated.
pub(crate) fn discretize(
    file: &ast::File,
    globals: &Globals,
    treat: &dyn Fn(&ast::Chart, usize) -> Treat,
    diags: &mut Vec<Diagnostic>,
) -> Option<Discretized> {
    let any = file.items.iter().any(|i| match i {
        ast::Item::Chart(c) => {
            has_hybrid(&c.body) && (c.params.is_empty() || treat(c, 0) != Treat::Leave)
        }
        ast::Item::System(s) => s.observers.iter().any(|o| has_hybrid(&o.body)),
        _ => false,
    });
    if !any {
        return None;
    }
    let (plans, ds) = plan_file(file, globals, treat);
    let failed = ds.iter().any(Diagnostic::is_error);
    diags.extend(ds);
    // A copy with placeholder values gets the whole discretization when its values allow it
    // (its diagnostics were dropped), so that it reads like the real copies.
    let placeholder_ok = {
        let mut probe = Vec::new();
        let (_, ds) = plan_file(file, globals, &|c, i| match treat(c, i) {
            Treat::DeclareOnly => Treat::Discretize,
            _ => Treat::Leave,
        });
        probe.extend(ds);
        !probe.iter().any(Diagnostic::is_error)
    };
    let mut out = file.clone();
    let mut kept = Vec::new();
    for (i, ps, how) in plans {
        let Some(ast::Item::Chart(c)) = out.items.get_mut(i) else {
            continue;
        };
        let motion = match how {
            Treat::Discretize => !failed,
            _ => placeholder_ok,
        };
        if how == Treat::Discretize && motion {
            kept.push(ChartPlans {
                chart: c.name.name.clone(),
                plans: ps.clone(),
            });
        }
        for p in &ps {
            apply(c, p, motion);
        }
        strip(&mut c.body);
    }
    for item in &mut out.items {
        if let ast::Item::System(s) = item {
            for o in &mut s.observers {
                strip(&mut o.body);
            }
        }
    }
    Some(Discretized {
        file: out,
        plans: kept,
    })
}

/// The spans of the `continuous` declarations of `file`: generated code carries them, and a
/// design-rule warning about generated code is no use to the user (it is dropped).
pub(crate) fn generated_spans(file: &ast::File) -> Vec<Span> {
    let mut out = Vec::new();
    for item in &file.items {
        if let ast::Item::Chart(c) = item {
            for h in &c.body.hybrid {
                if let HybridElem::Continuous { span, .. } = h {
                    out.push(*span);
                }
            }
        }
    }
    out
}

/// Remove every hybrid element under `body`.
fn strip(body: &mut ast::StateBody) {
    body.hybrid.clear();
    for s in &mut body.states {
        strip(&mut s.body);
    }
    for r in &mut body.regions {
        strip(&mut r.body);
    }
}

/// Parse generated declarations and statements (their text from `emit.rs`) into trees whose
/// spans are all `at`.
fn parse_generated(decls: &str, during: &str, at: Span) -> (Vec<ast::VarDecl>, Vec<ast::Stmt>) {
    let text = format!("chart G {{\n{decls}during {{\n{during}}}\n}}\n");
    let (f, diags) = statecheck_syntax::parse(&text);
    // The generated text is built to parse (no deep nesting: see `emit.rs`); if it ever did
    // not, nothing is generated rather than something partial.
    if diags.iter().any(Diagnostic::is_error) {
        return (Vec::new(), Vec::new());
    }
    let Some(ast::Item::Chart(mut c)) = f.items.into_iter().next() else {
        return (Vec::new(), Vec::new());
    };
    let mut stmts = c.body.during.pop().map(|b| b.stmts).unwrap_or_default();
    for v in &mut c.vars {
        respan::var_decl(v, at);
    }
    for s in &mut stmts {
        respan::stmt(s, at);
    }
    (c.vars, stmts)
}

/// Put the discretization of `p` into chart `c` (only its declarations, so that uses of the
/// variable still resolve, when `motion` is false after an error).
fn apply(c: &mut ast::Chart, p: &Plan, motion: bool) {
    let during = if motion {
        emit::during(p)
    } else {
        String::new()
    };
    let (vars, stmts) = parse_generated(&emit::decls(p), &during, p.span);
    c.vars.extend(vars);
    for (out, lo, hi) in &p.sensors {
        if let Some(v) = c.vars.iter_mut().find(|v| &v.name.name == out) {
            v.init = Some(ast::Expr::Bool(
                emit::sensor_at(p.init, *lo, *hi),
                v.name.span,
            ));
        }
    }
    match c.body.during.first_mut() {
        _ if stmts.is_empty() => {}
        Some(b) => {
            let mut all = stmts;
            all.append(&mut b.stmts);
            b.stmts = all;
        }
        None => c.body.during.push(ast::Block {
            stmts,
            span: p.span,
        }),
    }
}

/// The plans of every chart with continuous variables, for `statecheck analyse`; `Err` with
/// the diagnostics when the file's hybrid elements have errors.
pub fn plans(file: &ast::File) -> Result<Vec<ChartPlans>, Vec<Diagnostic>> {
    let globals = crate::globals_of(file);
    let (plans, diags) = plan_file(file, &globals, &before_expansion);
    if diags.iter().any(Diagnostic::is_error) {
        return Err(diags);
    }
    Ok(plans
        .into_iter()
        .filter_map(|(i, ps, _)| match file.items.get(i) {
            Some(ast::Item::Chart(c)) => Some(ChartPlans {
                chart: c.name.name.clone(),
                plans: ps,
            }),
            _ => None,
        })
        .collect())
}

/// The text of `source` (whose tree is `file`) with every hybrid chart discretized, as the
/// checker verifies it, in the formatter's layout; `Err` with the diagnostics when the hybrid
/// elements have errors. A file without continuous variables comes back formatted.
pub fn discretized_source(source: &str, file: &ast::File) -> Result<String, Vec<Diagnostic>> {
    let globals = crate::globals_of(file);
    let (plans, diags) = plan_file(file, &globals, &before_expansion);
    if diags.iter().any(Diagnostic::is_error) {
        return Err(diags);
    }
    let mut edits: Vec<(usize, usize, String)> = Vec::new();
    for (i, ps, _) in &plans {
        let Some(ast::Item::Chart(c)) = file.items.get(*i) else {
            continue;
        };
        splice_chart(source, c, ps, &mut edits);
    }
    edits.sort_by_key(|e| (e.0, e.1));
    let mut out = String::with_capacity(source.len() * 2);
    let mut at = 0;
    for (s, e, text) in edits {
        if s < at || e > source.len() {
            continue;
        }
        out.push_str(source.get(at..s).unwrap_or(""));
        out.push_str(&text);
        at = e;
    }
    out.push_str(source.get(at..).unwrap_or(""));
    Ok(statecheck_syntax::format::format(&out).unwrap_or(out))
}

/// The text edits that discretize chart `c`.
fn splice_chart(
    source: &str,
    c: &ast::Chart,
    plans: &[Plan],
    edits: &mut Vec<(usize, usize, String)>,
) {
    let mut during = String::new();
    for p in plans {
        during.push_str(&emit::during(p));
    }
    // Each `der` is kept as a comment that says which mode it became and its readings.
    let notes: Vec<(Span, String)> = plans
        .iter()
        .flat_map(|p| {
            p.modes
                .iter()
                .enumerate()
                .map(move |(i, m)| (m.span, emit::mode_note(p, i)))
        })
        .collect();
    fn comment_out(
        source: &str,
        body: &ast::StateBody,
        notes: &[(Span, String)],
        edits: &mut Vec<(usize, usize, String)>,
    ) {
        for h in &body.hybrid {
            if let HybridElem::Continuous { .. } = h {
                continue;
            }
            let s = h.span();
            let text = source.get(s.range()).unwrap_or("").replace("*/", "* /");
            let note = notes
                .iter()
                .find(|(at, _)| *at == s)
                .map(|(_, n)| format!(" ({n})"))
                .unwrap_or_default();
            edits.push((
                s.start as usize,
                s.end as usize,
                format!("/* {text}{note} */"),
            ));
        }
        for st in &body.states {
            comment_out(source, &st.body, notes, edits);
        }
        for r in &body.regions {
            comment_out(source, &r.body, notes, edits);
        }
    }
    comment_out(source, &c.body, &notes, edits);
    for p in plans {
        edits.push((
            p.span.start as usize,
            p.span.end as usize,
            format!("{}\n{}", emit::grid_comment(p), emit::decls(p)),
        ));
        for (out, lo, hi) in &p.sensors {
            let Some(v) = c.vars.iter().find(|v| &v.name.name == out) else {
                continue;
            };
            let start = v.span.start as usize;
            let Some(semi) = source.get(start..).and_then(|t| t.find(';')) else {
                continue;
            };
            let kind = match v.kind {
                ast::VarKind::Output => "output",
                _ => "local",
            };
            let init = emit::sensor_at(p.init, *lo, *hi);
            edits.push((
                start,
                start + semi + 1,
                format!("{kind} {out}: bool = {init};"),
            ));
        }
    }
    match c.body.during.first() {
        Some(b) => {
            let open = b.span.start as usize + 1;
            edits.push((open, open, format!("\n{during}")));
        }
        None => {
            let close = (c.span.end as usize).saturating_sub(1);
            edits.push((close, close, format!("during {{\n{during}}}\n")));
        }
    }
}
