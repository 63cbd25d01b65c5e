//! Parameterised chart types (`docs/components.md`): `chart Sensor(lo: int, hi: int = 5)`,
//! instantiated as `instance home: Sensor(0, hi = 9);`.
//!
//! Before anything else is checked, every parameterised chart is replaced, in the file's AST,
//! by one copy per distinct list of argument values its instances use, with each use of a
//! parameter replaced by the value (a literal at the use's span). The rest of the checker, the
//! IR and every engine see ordinary charts. A copy is named like the instantiation,
//! `Sensor(0, 9)`; the copy with the default values (or, when a parameter has no default, a
//! copy with placeholder values that is checked for names and types only) keeps the plain name.

use crate::expr::{is_placeholder, ExprChecker};
use crate::model::ExprKind;
use crate::scope::Scope;
use crate::types::Type;
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;
use statecheck_syntax::ast::visit_mut::{walk_expr, VisitMut};
use std::collections::HashMap;

/// E0150 on the first of `args` given to `instance`, whose chart or component declares no
/// parameters.
pub(crate) fn refuse_arguments(
    decl: &Decl,
    instance: &ast::Ident,
    args: &[ast::Arg],
    ck: &mut ExprChecker,
) {
    let Some(a) = args.first() else { return };
    let kind = decl.kind;
    ck.sink.push(
        Diagnostic::error(
            "E0150",
            format!("{kind} `{}` has no parameters", decl.name.name),
            a.span,
        )
        .with_label(format!("argument to a {kind} without parameters"))
        .with_secondary(decl.name.span, format!("{kind} declared here"))
        .with_hint(format!(
            "write `instance {}: {};`",
            instance.name, decl.name.name
        )),
    );
}

/// What declares parameters: a chart or a component.
pub(crate) struct Decl<'x> {
    /// `"chart"` or `"component"`, for the messages.
    pub kind: &'static str,
    /// Its name.
    pub name: &'x ast::Ident,
    /// Its parameters.
    pub params: &'x [ast::ChartParam],
}

/// Why a chart of the expanded file exists.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Origin {
    /// A chart without parameters, as written.
    Plain,
    /// A parameterised chart with its default arguments, under its plain name.
    Defaults,
    /// A parameterised chart with placeholder values (some parameter has no default): checked
    /// for names and types only, never run alone.
    Placeholder,
    /// A parameterised chart with an instance's arguments; `at` is that instance's chart name.
    Args {
        /// Where the first instance with these arguments names the chart.
        at: Span,
    },
}

/// The file with parameterised charts replaced by their copies.
pub(crate) struct Expanded {
    /// The rewritten file.
    pub file: ast::File,
    /// For each chart of `file`, in order, why it exists.
    pub origins: Vec<Origin>,
}

/// A parameter's value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Value {
    Int(i64),
    Bool(bool),
    Enum(u32, i64),
}

/// Rewrite `file` when it declares a parameterised chart or an instance gives arguments;
/// `None` when there is nothing to do.
pub(crate) fn expand(file: &ast::File, ck: &mut ExprChecker<'_>) -> Option<Expanded> {
    let any = file.items.iter().any(|i| match i {
        ast::Item::Chart(c) => !c.params.is_empty(),
        ast::Item::System(s) => s.instances.iter().any(|i| !i.args.is_empty()),
        _ => false,
    });
    if !any {
        return None;
    }
    let mut charts: HashMap<&str, &ast::Chart> = HashMap::new();
    for item in &file.items {
        if let ast::Item::Chart(c) = item {
            charts.entry(c.name.name.as_str()).or_insert(c);
        }
    }
    // Parameter types and defaults of each parameterised chart.
    let mut sigs: HashMap<&str, Vec<(Type, Option<Value>)>> = HashMap::new();
    for c in charts.values() {
        if c.params.is_empty() {
            continue;
        }
        check_param_names(c, ck);
        let sig = c
            .params
            .iter()
            .map(|p| {
                let ty = ck.resolve_type(&p.ty);
                let what = format!("the default of parameter `{}`", p.name.name);
                let d = p.default.as_ref().and_then(|e| value_of(ck, e, ty, &what));
                (ty, d)
            })
            .collect();
        sigs.insert(c.name.name.as_str(), sig);
    }

    // Each instance's specialisation, in order of first use per chart.
    let mut uses: HashMap<&str, Vec<(Vec<Value>, Span)>> = HashMap::new();
    let mut systems: Vec<ast::System> = Vec::new();
    for item in &file.items {
        let ast::Item::System(s) = item else { continue };
        let mut s = s.clone();
        for inst in &mut s.instances {
            let args = std::mem::take(&mut inst.args);
            let Some(c) = charts.get(inst.chart.name.as_str()) else {
                continue; // the system checker reports the unknown chart
            };
            if c.params.is_empty() {
                let decl = Decl {
                    kind: "chart",
                    name: &c.name,
                    params: &c.params,
                };
                refuse_arguments(&decl, &inst.name, &args, ck);
                continue;
            }
            let sig = &sigs[c.name.name.as_str()];
            let decl = Decl {
                kind: "chart",
                name: &c.name,
                params: &c.params,
            };
            let Some(values) = bind(&decl, sig, &args, inst, ck) else {
                continue; // reported; the instance keeps the plain (placeholder) copy
            };
            let defaults: Option<Vec<Value>> = sig.iter().map(|(_, d)| *d).collect();
            if defaults.as_ref() == Some(&values) {
                continue;
            }
            let list = uses.entry(c.name.name.as_str()).or_default();
            if !list.iter().any(|(v, _)| *v == values) {
                list.push((values.clone(), inst.chart.span));
            }
            inst.chart.name = copy_name(c, &values, ck);
        }
        systems.push(s);
    }

    let mut out = ast::File::default();
    let mut origins = Vec::new();
    let mut systems = systems.into_iter();
    for item in &file.items {
        match item {
            ast::Item::Chart(c) if !c.params.is_empty() => {
                let first = charts
                    .get(c.name.name.as_str())
                    .is_some_and(|f| std::ptr::eq(*f, c));
                let sig = match sigs.get(c.name.name.as_str()) {
                    Some(sig) if first => sig.clone(),
                    // A second chart of the same name (E0102, reported later) whose first has
                    // no parameters or others: its own placeholders, no defaults evaluated.
                    _ => c
                        .params
                        .iter()
                        .map(|p| (ck.resolve_type(&p.ty), None))
                        .collect(),
                };
                let defaults: Option<Vec<Value>> = sig.iter().map(|(_, d)| *d).collect();
                let (plain, origin) = match defaults {
                    Some(d) => (d, Origin::Defaults),
                    None => (
                        sig.iter()
                            .map(|(ty, d)| d.unwrap_or_else(|| placeholder(*ty)))
                            .collect(),
                        Origin::Placeholder,
                    ),
                };
                out.items.push(ast::Item::Chart(specialise(
                    c,
                    &plain,
                    c.name.name.clone(),
                    ck,
                )));
                origins.push(origin);
                let uses_here = if first {
                    uses.get(c.name.name.as_str())
                } else {
                    None
                };
                for (values, at) in uses_here.into_iter().flatten() {
                    let name = copy_name(c, values, ck);
                    out.items
                        .push(ast::Item::Chart(specialise(c, values, name, ck)));
                    origins.push(Origin::Args { at: *at });
                }
            }
            ast::Item::Chart(c) => {
                out.items.push(ast::Item::Chart(c.clone()));
                origins.push(Origin::Plain);
            }
            ast::Item::System(_) => {
                if let Some(s) = systems.next() {
                    out.items.push(ast::Item::System(s));
                }
            }
            other => out.items.push(other.clone()),
        }
    }
    Some(Expanded { file: out, origins })
}

/// A parameter named like another parameter or like one of the chart's variables.
fn check_param_names(c: &ast::Chart, ck: &mut ExprChecker<'_>) {
    let mut seen: HashMap<&str, Span> = HashMap::new();
    for p in &c.params {
        if let Some(prev) = seen.insert(p.name.name.as_str(), p.name.span) {
            ck.sink.push(
                Diagnostic::error(
                    "E0102",
                    format!("parameter `{}` is declared twice", p.name.name),
                    p.name.span,
                )
                .with_label("second declaration")
                .with_secondary(prev, "first declared here"),
            );
        }
    }
    for v in &c.vars {
        if let Some(prev) = seen.get(v.name.name.as_str()) {
            ck.sink.push(
                Diagnostic::error(
                    "E0102",
                    format!(
                        "`{}` is declared both as a parameter and as a variable of chart `{}`",
                        v.name.name, c.name.name
                    ),
                    v.name.span,
                )
                .with_label("variable")
                .with_secondary(*prev, "parameter declared here")
                .with_hint("rename one of them"),
            );
        }
    }
}

/// The values of an instance's arguments, positional then named, with defaults for the rest;
/// `None` after reporting a missing, extra or bad argument (E0150, E0151).
pub(crate) fn bind(
    c: &Decl<'_>,
    sig: &[(Type, Option<Value>)],
    args: &[ast::Arg],
    inst: &ast::Instance,
    ck: &mut ExprChecker<'_>,
) -> Option<Vec<Value>> {
    let mut given: Vec<Option<(&ast::Arg, Span)>> = vec![None; c.params.len()];
    let mut ok = true;
    let mut positional = 0;
    for a in args {
        let slot = match &a.name {
            None => {
                positional += 1;
                if positional > c.params.len() {
                    ck.sink.push(
                        Diagnostic::error(
                            "E0150",
                            format!(
                                "{} `{}` takes {} parameter{}, this is argument {positional}",
                                c.kind,
                                c.name.name,
                                c.params.len(),
                                if c.params.len() == 1 { "" } else { "s" }
                            ),
                            a.span,
                        )
                        .with_label("extra argument")
                        .with_secondary(c.name.span, format!("{} declared here", c.kind)),
                    );
                    ok = false;
                    continue;
                }
                positional - 1
            }
            Some(n) => match c.params.iter().position(|p| p.name.name == n.name) {
                Some(i) => i,
                None => {
                    let names = c.params.iter().map(|p| p.name.name.as_str());
                    let hint = match crate::suggest::closest(&n.name, names) {
                        Some(s) => format!("did you mean `{s}`?"),
                        None => format!("the parameters are: {}", param_list(c.params)),
                    };
                    ck.sink.push(
                        Diagnostic::error(
                            "E0150",
                            format!("{} `{}` has no parameter `{}`", c.kind, c.name.name, n.name),
                            n.span,
                        )
                        .with_label("unknown parameter")
                        .with_secondary(c.name.span, format!("{} declared here", c.kind))
                        .with_hint(hint),
                    );
                    ok = false;
                    continue;
                }
            },
        };
        if let Some((_, prev)) = given[slot] {
            ck.sink.push(
                Diagnostic::error(
                    "E0150",
                    format!("parameter `{}` is given twice", c.params[slot].name.name),
                    a.span,
                )
                .with_label("second argument")
                .with_secondary(prev, "first given here"),
            );
            ok = false;
            continue;
        }
        given[slot] = Some((a, a.span));
    }
    let mut values = Vec::with_capacity(sig.len());
    for (i, p) in c.params.iter().enumerate() {
        let (ty, default) = sig[i];
        match given[i] {
            Some((a, _)) => {
                let what = format!("argument `{}` of {} `{}`", p.name.name, c.kind, c.name.name);
                match value_of(ck, &a.value, ty, &what) {
                    Some(v) => values.push(v),
                    None => ok = false,
                }
            }
            None => match default {
                Some(v) => values.push(v),
                None => {
                    if p.default.is_none() {
                        let at = args_span(inst, args);
                        ck.sink.push(
                            Diagnostic::error(
                                "E0151",
                                format!(
                                    "instance `{}` gives no value for parameter `{}` of {} `{}`",
                                    inst.name.name, p.name.name, c.kind, c.name.name
                                ),
                                at,
                            )
                            .with_label(format!("`{}` is missing", p.name.name))
                            .with_secondary(
                                p.name.span,
                                "parameter declared here without a default",
                            )
                            .with_hint(format!(
                                "give it: `{}({} = …)`; the parameters are: {}",
                                c.name.name,
                                p.name.name,
                                param_list(c.params)
                            )),
                        );
                    }
                    ok = false;
                }
            },
        }
    }
    ok.then_some(values)
}

/// An instance's chart name and argument list, where a missing argument is reported.
fn args_span(inst: &ast::Instance, args: &[ast::Arg]) -> Span {
    let end = args
        .last()
        .map_or(inst.chart.span.end, |a| a.span.end.max(inst.chart.span.end));
    Span::new(inst.chart.span.start as usize, end as usize)
}

fn param_list(params: &[ast::ChartParam]) -> String {
    params
        .iter()
        .map(|p| format!("`{}`", p.name.name))
        .collect::<Vec<_>>()
        .join(", ")
}

/// A constant argument (or default) of type `ty`; `None` after reporting why not.
pub(crate) fn value_of(
    ck: &mut ExprChecker<'_>,
    e: &ast::Expr,
    ty: Type,
    what: &str,
) -> Option<Value> {
    let empty = Scope::constants(usize::MAX);
    let before = ck.sink.diags.len();
    let x = ck.check(&empty, e);
    if is_placeholder(&x) {
        return None;
    }
    if !matches!(x.kind, ExprKind::Const(_)) {
        ck.sink.push(
            Diagnostic::error("E0105", format!("{what} must be a constant"), x.span)
                .with_label("this depends on variables or states")
                .with_hint("use literals, constants and operators only"),
        );
        return None;
    }
    let x = ck.coerce(x, ty, what);
    if ck.sink.diags.len() > before {
        return None;
    }
    let ExprKind::Const(v) = x.kind else {
        return None;
    };
    Some(match ty {
        Type::Bool => Value::Bool(v != 0),
        Type::Int { .. } => Value::Int(v),
        Type::Enum(e) => Value::Enum(e, v),
    })
}

/// A value of `ty` for a parameter without a default, in a copy checked for names and types.
fn placeholder(ty: Type) -> Value {
    match ty {
        Type::Bool => Value::Bool(false),
        Type::Int { lo, hi } => Value::Int(0.clamp(lo, hi)),
        Type::Enum(e) => Value::Enum(e, 0),
    }
}

fn show(v: Value, ck: &ExprChecker<'_>) -> String {
    match v {
        Value::Int(n) => n.to_string(),
        Value::Bool(b) => b.to_string(),
        Value::Enum(e, i) => ck
            .globals
            .enums
            .get(e as usize)
            .and_then(|d| d.variants.get(i as usize))
            .cloned()
            .unwrap_or_else(|| i.to_string()),
    }
}

/// `Sensor(0, 9)`: the name of a copy (not an identifier, so it clashes with nothing).
fn copy_name(c: &ast::Chart, values: &[Value], ck: &ExprChecker<'_>) -> String {
    named_copy(&c.name.name, values, ck)
}

/// `Name(0, 9)`: a copy's name from its declaration's name and argument values.
pub(crate) fn named_copy(name: &str, values: &[Value], ck: &ExprChecker<'_>) -> String {
    let vs: Vec<String> = values.iter().map(|v| show(*v, ck)).collect();
    format!("{name}({})", vs.join(", "))
}

/// The chart with every use of a parameter replaced by its value.
fn specialise(c: &ast::Chart, values: &[Value], name: String, ck: &ExprChecker<'_>) -> ast::Chart {
    let mut out = c.clone();
    out.params.clear();
    out.name.name = name;
    let mut s = Subst {
        names: c
            .params
            .iter()
            .zip(values)
            .map(|(p, v)| (p.name.name.clone(), literal(*v, ck)))
            .collect(),
    };
    s.visit_chart(&mut out);
    out
}

/// The value as an expression: a literal, or `Enum.LITERAL` for an enum.
pub(crate) fn literal(v: Value, ck: &ExprChecker<'_>) -> Literal {
    match v {
        Value::Int(n) => Literal::Int(n),
        Value::Bool(b) => Literal::Bool(b),
        Value::Enum(e, i) => {
            let def = ck.globals.enums.get(e as usize);
            let en = def.map(|d| d.name.clone()).unwrap_or_default();
            let lit = def
                .and_then(|d| d.variants.get(i as usize))
                .cloned()
                .unwrap_or_default();
            Literal::Enum(en, lit)
        }
    }
}

/// A parameter's value as the expression that replaces the parameter's uses.
#[derive(Clone)]
pub(crate) enum Literal {
    Int(i64),
    Bool(bool),
    Enum(String, String),
}

impl Literal {
    fn at(&self, span: Span) -> ast::Expr {
        let ident = |name: &str| ast::PathSegment {
            name: ast::Ident {
                name: name.to_string(),
                span,
            },
            index: None,
        };
        match self {
            Literal::Int(n) => ast::Expr::Int(*n, span),
            Literal::Bool(b) => ast::Expr::Bool(*b, span),
            Literal::Enum(e, l) => ast::Expr::Path(ast::Path {
                segments: vec![ident(e), ident(l)],
                span,
            }),
        }
    }
}

/// Replaces parameter names by their values throughout a chart (every expression the AST
/// walk visits: types, initial values, guards, actions, delays, hybrid bounds, properties).
pub(crate) struct Subst {
    /// Each parameter's value.
    pub names: HashMap<String, Literal>,
}

impl VisitMut for Subst {
    fn visit_expr(&mut self, e: &mut ast::Expr) {
        if let ast::Expr::Path(p) = e {
            if let [seg] = p.segments.as_slice() {
                if seg.index.is_none() {
                    if let Some(l) = self.names.get(&seg.name.name) {
                        *e = l.at(p.span);
                        return;
                    }
                }
            }
        }
        walk_expr(self, e);
    }
}

/// Diagnostics `diags[before..]` came from checking one chart of the expanded file: a copy with
/// placeholder values keeps only those that do not depend on values (names and types); a copy
/// with an instance's arguments says which arguments.
pub(crate) fn annotate(diags: &mut Vec<Diagnostic>, before: usize, origin: &Origin, name: &str) {
    match origin {
        Origin::Plain | Origin::Defaults => {}
        Origin::Placeholder => {
            let mut i = before;
            while i < diags.len() {
                if matches!(diags[i].code, "E0101" | "E0102" | "E0103") {
                    i += 1;
                } else {
                    diags.remove(i);
                }
            }
        }
        Origin::Args { at } => {
            for d in &mut diags[before..] {
                *d = d
                    .clone()
                    .with_secondary(*at, format!("in the chart `{name}` instantiated here"));
            }
        }
    }
}

/// Drop repeated diagnostics: copies of one chart report the same problem at the same place.
pub(crate) fn dedup(diags: &mut Vec<Diagnostic>) {
    let mut seen: std::collections::HashSet<(&'static str, u32, u32, String)> = Default::default();
    diags.retain(|d| seen.insert((d.code, d.span.start, d.span.end, d.message.clone())));
}
