//! The checked model of a `.sc` file.
//!
//! This crate turns the parser's AST into a [`Model`]: names resolved, expressions typed with
//! integer bounds, function calls inlined, the state hierarchy built, transitions resolved to
//! their targets, systems flattened (instance arrays expanded, connections and execution order
//! fixed) — and it reports every problem as a [`Diagnostic`] with a stable code, continuing
//! past errors so one run shows them all. Design-rule checks (the Modelica paper's §3.1) live in
//! [`lint`]. It decides nothing about *how* a step executes: that is the `ir` crate's job.

mod arrays;
mod cascade;
mod chart;
pub mod components;
mod composite;
mod duration;
mod expr;
pub mod formula;
pub mod hybrid;
pub mod imports;
mod interleave;
pub mod lint;
pub mod model;
pub mod ops;
mod params;
mod property;
mod rate;
mod rebase;
mod scope;
mod suggest;
mod system;
pub mod types;

pub use interleave::SCHED;
pub use model::*;
pub use types::{EnumId, Type};

use expr::{ExprChecker, Sink};
use scope::{Globals, Scope};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;
use std::collections::HashMap;

/// Runs `f` with an expression checker of its own over the globals (the expansions before
/// checking type their arguments with it) and returns its result and the diagnostics it
/// collected.
fn with_scratch_checker<R>(
    globals: &Globals,
    f: impl FnOnce(&mut ExprChecker) -> R,
) -> (R, Vec<Diagnostic>) {
    let mut sub = ExprChecker {
        globals,
        sink: Sink {
            diags: Vec::new(),
            muted: 0,
            once: Default::default(),
        },
        next_local: 0,
    };
    let r = f(&mut sub);
    (r, sub.sink.diags)
}

/// Numbers the charts of `file` afresh, in order (after an expansion added or replaced
/// charts); the first chart of a name keeps the name.
fn number_charts(globals: &mut Globals, file: &ast::File) {
    globals.chart_ids.clear();
    let charts = file.items.iter().filter_map(|i| match i {
        ast::Item::Chart(c) => Some(c),
        _ => None,
    });
    for (id, c) in charts.enumerate() {
        globals
            .chart_ids
            .entry(c.name.name.clone())
            .or_insert(id as ChartId);
    }
}

/// Check a parsed file. Always returns a model (possibly incomplete) and all diagnostics,
/// including design-rule warnings; the model is usable only if no diagnostic is an error.
pub fn check(file: &ast::File) -> (Model, Vec<Diagnostic>) {
    let original = file;
    let mut globals = Globals::default();
    let mut early = Vec::new();
    collect_globals(file, &mut globals, &mut early);
    check_consts_and_fns(file, &mut globals, &mut early);
    arrays::refuse_port_arrays(file, &mut early);
    // Continuous variables become grid variables, modes and timers (`hybrid/`).
    let discretized = hybrid::discretize(file, &globals, &hybrid::before_expansion, &mut early);
    let file = match &discretized {
        Some(d) => &d.file,
        None => file,
    };
    // Systems with configurations become one system per configuration (`components.rs`).
    let configured = components::expand(file, &mut early);
    let (file, sys_origins) = match &configured {
        Some(c) => (&c.file, c.origins.as_slice()),
        None => (file, &[][..]),
    };
    // Parameterised components become one component per argument list, arrays of
    // components get literal lengths (`composite/params.rs`).
    let comp_params = {
        let (e, diags) = with_scratch_checker(&globals, |sub| composite::expand_params(file, sub));
        early.extend(diags);
        e
    };
    let file = comp_params.as_ref().unwrap_or(file);
    // Component instances become their inner instances, systems flat (`composite/`).
    let flattened = composite::flatten(file, &mut early);
    let (file, sys_origins) = match &flattened {
        Some(f) => (&f.file, sys_origins),
        None => (file, sys_origins),
    };
    // Interleaved systems get their scheduler input (`interleave.rs`).
    let interleaved =
        with_scratch_checker(&globals, |sub| interleave::expand(file, sub, &mut early)).0;
    let file = interleaved.as_ref().unwrap_or(file);
    // Parameterised charts become one ordinary chart per argument list (`params.rs`).
    let expanded = {
        let (e, diags) = with_scratch_checker(&globals, |sub| params::expand(file, sub));
        early.extend(diags);
        e
    };
    let (file, origins) = match &expanded {
        Some(e) => {
            number_charts(&mut globals, &e.file);
            (&e.file, e.origins.as_slice())
        }
        None => {
            // The scheduler charts of interleaved systems are new charts.
            if interleaved.is_some() {
                number_charts(&mut globals, file);
            }
            (file, &[][..])
        }
    };
    // Copies of parameterised charts with continuous variables are discretized now, each
    // with its arguments; a copy with placeholder values only declares the variables.
    let copies = expanded.as_ref().and_then(|_| {
        let treat = |_: &ast::Chart, id: usize| match origins.get(id) {
            Some(params::Origin::Placeholder) => hybrid::Treat::DeclareOnly,
            _ => hybrid::Treat::Discretize,
        };
        let mut ds = Vec::new();
        let d = hybrid::discretize(file, &globals, &treat, &mut ds);
        early.extend(ds);
        d
    });
    let file = match &copies {
        Some(d) => &d.file,
        None => file,
    };
    // Arrays of variables become their elements, loops are unrolled (`arrays/`).
    let unrolled = {
        let placeholder = |id: usize| origins.get(id) == Some(&params::Origin::Placeholder);
        let (e, diags) =
            with_scratch_checker(&globals, |sub| arrays::expand(file, &placeholder, sub));
        early.extend(diags);
        e
    };
    let file = unrolled.as_ref().unwrap_or(file);
    let origin = |id: usize| origins.get(id).unwrap_or(&params::Origin::Plain);
    let globals_ref = &globals;
    let consts_snapshot = globals_ref.const_order.clone();
    let mut ck = ExprChecker {
        globals: globals_ref,
        sink: Sink {
            diags: early,
            muted: 0,
            once: Default::default(),
        },
        next_local: 1 << 20,
    };

    // Charts: hierarchy first (so `in()` can see every state), then actions and transitions.
    let chart_asts: Vec<&ast::Chart> = file
        .items
        .iter()
        .filter_map(|i| match i {
            ast::Item::Chart(c) => Some(c),
            _ => None,
        })
        .collect();
    let mut skeletons = Vec::new();
    for (id, c) in chart_asts.iter().enumerate() {
        let before = ck.sink.diags.len();
        skeletons.push(chart::skeleton(&mut ck, c, model::ChartRole::of(c)));
        params::annotate(&mut ck.sink.diags, before, origin(id), &c.name.name);
    }
    let mut charts: Vec<Chart> = Vec::new();
    for (id, (sk, c)) in skeletons.into_iter().zip(&chart_asts).enumerate() {
        let before = ck.sink.diags.len();
        let filled = chart::fill(&mut ck, sk, c, None, &[]);
        params::annotate(&mut ck.sink.diags, before, origin(id), &c.name.name);
        charts.push(filled);
    }
    for (id, c) in chart_asts.iter().enumerate() {
        if *origin(id) != params::Origin::Placeholder {
            let before = ck.sink.diags.len();
            components::conformance(file, c, &charts[id], &mut ck);
            params::annotate(&mut ck.sink.diags, before, origin(id), &c.name.name);
        }
    }
    if let Some(f) = &flattened {
        composite::conformance(file, &f.components, &mut ck);
        composite::check_ports(file, &f.links, &charts, &mut ck);
    }

    let mut systems = Vec::new();
    let mut system_names: HashMap<String, Span> = HashMap::new();
    let mut sys_index = 0;
    for item in &file.items {
        if let ast::Item::System(s) = item {
            let sys_origin = sys_origins.get(sys_index).cloned().flatten();
            sys_index += 1;
            if let Some(prev) = system_names.insert(s.name.name.clone(), s.name.span) {
                ck.sink.push(
                    Diagnostic::error(
                        "E0102",
                        format!("system `{}` is declared twice", s.name.name),
                        s.name.span,
                    )
                    .with_label("second declaration")
                    .with_secondary(prev, "first declared here"),
                );
                continue;
            }
            let before = ck.sink.diags.len();
            systems.push(system::check_system(&mut ck, s, &mut charts));
            if let Some((config, at)) = sys_origin {
                for d in &mut ck.sink.diags[before..] {
                    *d = d
                        .clone()
                        .with_secondary(at, format!("in configuration `{config}`"));
                }
            }
        }
    }
    if let Some(f) = &flattened {
        for s in &mut systems {
            s.implicit |= f.standalone.contains(&s.name);
        }
    }
    // Every top-level chart can also run alone, as a system of one instance named like it.
    for (id, c) in chart_asts.iter().enumerate() {
        // (The scheduler chart of an interleaved system, `sched(k)`, does not run alone.)
        if system_names.contains_key(&c.name.name)
            || c.name.name.starts_with("sched(")
            || !matches!(origin(id), params::Origin::Plain | params::Origin::Defaults)
        {
            continue;
        }
        let mut properties = charts[id].properties.clone();
        for p in &mut properties {
            rebase::property(p, 0);
        }
        systems.push(System {
            name: c.name.name.clone(),
            interleaved: None,
            implicit: true,
            instances: vec![Instance {
                name: c.name.name.clone(),
                chart: id as ChartId,
                index: None,
                renames: Vec::new(),
                span: c.name.span,
            }],
            connections: Vec::new(),
            order: vec![0],
            assumes: Vec::new(),
            rates: Vec::new(),
            properties,
            requirements: Vec::new(),
            span: c.name.span,
        });
    }

    let model = Model {
        enums: globals_ref.enums.clone(),
        consts: consts_snapshot
            .iter()
            .filter_map(|n| {
                globals_ref.consts.get(n).map(|(ty, v, _)| ConstDef {
                    name: n.clone(),
                    ty: *ty,
                    value: *v,
                })
            })
            .collect(),
        charts,
        systems,
        tick_ms: globals_ref.tick_ms,
        hybrid: discretized
            .iter()
            .chain(copies.iter())
            .flat_map(|d| d.plans.iter().cloned())
            .collect(),
    };
    let mut diags = ck.sink.diags;
    cascade::suppress(file, &mut diags);
    if !diags.iter().any(Diagnostic::is_error) {
        let generated = hybrid::generated_spans(original);
        diags.extend(
            lint::lint(&model)
                .into_iter()
                .filter(|d| !generated.contains(&d.span)),
        );
    }
    diags.sort_by_key(|d| (d.span.start, d.span.end));
    if expanded.is_some() || configured.is_some() || flattened.is_some() {
        params::dedup(&mut diags);
        components::suppress_slot_cascades(file, &mut diags);
        composite::suppress_cascades(&mut diags);
    }
    (model, diags)
}

/// The file's constants, enums, functions and tick, with their diagnostics dropped (for
/// passes that run outside [`check`]).
pub(crate) fn globals_of(file: &ast::File) -> Globals {
    let mut globals = Globals::default();
    let mut sink = Vec::new();
    collect_globals(file, &mut globals, &mut sink);
    check_consts_and_fns(file, &mut globals, &mut sink);
    globals
}

fn collect_globals(file: &ast::File, g: &mut Globals, diags: &mut Vec<Diagnostic>) {
    let mut names: HashMap<String, Span> = HashMap::new();
    let mut declare = |name: &ast::Ident, diags: &mut Vec<Diagnostic>| -> bool {
        if let Some(prev) = names.insert(name.name.clone(), name.span) {
            diags.push(
                Diagnostic::error(
                    "E0102",
                    format!("`{}` is declared twice", name.name),
                    name.span,
                )
                .with_label("second declaration")
                .with_secondary(prev, "first declared here"),
            );
            return false;
        }
        true
    };
    let mut chart_count = 0;
    let mut tick_seen: Option<Span> = None;
    // Each literal name: where it is first declared, and by which enum.
    let mut literals: HashMap<String, (Span, String)> = HashMap::new();
    for item in &file.items {
        match item {
            ast::Item::Enum(e) => {
                if !declare(&e.name, diags) {
                    continue;
                }
                let id = g.enums.len() as EnumId;
                let mut seen: HashMap<&str, Span> = HashMap::new();
                for v in &e.variants {
                    if let Some(prev) = seen.insert(&v.name, v.span) {
                        diags.push(
                            Diagnostic::error(
                                "E0102",
                                format!("literal `{}` is declared twice", v.name),
                                v.span,
                            )
                            .with_label("second declaration")
                            .with_secondary(prev, "first declared here"),
                        );
                    }
                    g.literal_owners.entry(v.name.clone()).or_default().push(id);
                    literals
                        .entry(v.name.clone())
                        .or_insert((v.span, e.name.name.clone()));
                }
                if e.variants.is_empty() {
                    diags.push(Diagnostic::error(
                        "E0114",
                        format!("enum `{}` has no literals", e.name.name),
                        e.name.span,
                    ));
                }
                g.enum_ids.insert(e.name.name.clone(), id);
                g.enums.push(EnumDef {
                    name: e.name.name.clone(),
                    variants: if e.variants.is_empty() {
                        vec!["_".into()]
                    } else {
                        e.variants.iter().map(|v| v.name.clone()).collect()
                    },
                });
            }
            ast::Item::Chart(c) => {
                if declare(&c.name, diags) {
                    g.chart_ids.insert(c.name.name.clone(), chart_count);
                }
                chart_count += 1;
            }
            ast::Item::Const(c) => {
                if declare(&c.name, diags) {
                    g.declared_consts.insert(c.name.name.clone(), c.name.span);
                }
            }
            ast::Item::Fn(f) => {
                if declare(&f.name, diags) {
                    let index = g.fns.len();
                    g.fns.insert(f.name.name.clone(), (index, f.clone()));
                }
            }
            ast::Item::Interface(i) => {
                declare(&i.name, diags);
            }
            ast::Item::Component(c) => {
                declare(&c.name, diags);
            }
            ast::Item::System(_) | ast::Item::Import(_) => {}
            ast::Item::Tick(t) => {
                if let Some(prev) = tick_seen {
                    diags.push(
                        Diagnostic::error("E0108", "the tick length is declared twice", t.span)
                            .with_secondary(prev, "first declared here"),
                    );
                }
                tick_seen = Some(t.span);
            }
        }
    }
    const_literal_clashes(file, &literals, diags);
}

/// A constant named like an enum literal: a bare use of the name could mean either, so it is a
/// duplicate declaration (E0102) wherever the two are declared, whichever comes first.
fn const_literal_clashes(
    file: &ast::File,
    literals: &HashMap<String, (Span, String)>,
    diags: &mut Vec<Diagnostic>,
) {
    for item in &file.items {
        let ast::Item::Const(c) = item else { continue };
        let Some((lit_span, owner)) = literals.get(&c.name.name) else {
            continue;
        };
        let name = &c.name.name;
        diags.push(
            Diagnostic::error(
                "E0102",
                format!("constant `{name}` has the same name as a literal of enum `{owner}`"),
                c.name.span,
            )
            .with_label("clashes with an enum literal")
            .with_secondary(*lit_span, "literal declared here")
            .with_hint(format!(
                "rename the constant: a bare `{name}` would be ambiguous (`{owner}.{name}` names the literal)"
            )),
        );
    }
}

fn check_consts_and_fns(file: &ast::File, g: &mut Globals, diags: &mut Vec<Diagnostic>) {
    // Constants and functions are checked in textual order; each sees only earlier constants
    // and may call only earlier functions.
    let mut fns_before = 0;
    for item in &file.items {
        let view = g.clone();
        let mut sub = ExprChecker {
            globals: &view,
            sink: Sink {
                diags: Vec::new(),
                muted: 0,
                once: Default::default(),
            },
            next_local: 0,
        };
        let empty = Scope::constants(fns_before);
        match item {
            ast::Item::Const(c) => {
                let x = sub.check(&empty, &c.value);
                let ty = match &c.ty {
                    Some(t) => sub.resolve_type(t),
                    None => x.ty,
                };
                let x = sub.coerce(x, ty, "constant");
                let value = match x.kind {
                    ExprKind::Const(v) => v,
                    _ => {
                        sub.sink.push(
                            Diagnostic::error(
                                "E0105",
                                "a constant needs a constant value",
                                c.value.span(),
                            )
                            .with_label("depends on variables"),
                        );
                        0
                    }
                };
                let ty = if ty.is_int() { Type::UNBOUNDED } else { ty };
                g.consts
                    .insert(c.name.name.clone(), (ty, value, c.name.span));
                g.const_order.push(c.name.name.clone());
            }
            ast::Item::Fn(f) => {
                // The index entered by `collect_globals` (a duplicate keeps the first one's).
                let index = g.fns.get(&f.name.name).map_or(fns_before, |(i, _)| *i);
                fns_before = fns_before.max(index + 1);
                // Check the body once with opaque parameters, to report its errors here.
                let mut scope = Scope::constants(index);
                for (i, p) in f.params.iter().enumerate() {
                    let ty = sub.resolve_type(&p.ty);
                    scope.locals.push((
                        p.name.name.clone(),
                        Expr {
                            kind: ExprKind::Var(VarRef {
                                instance: Some(u32::MAX),
                                var: i as VarId,
                            }),
                            ty,
                            span: p.name.span,
                        },
                    ));
                }
                for (name, e) in &f.lets {
                    let v = sub.check(&scope, e);
                    scope.locals.push((name.name.clone(), v));
                }
                let body = sub.check(&scope, &f.body);
                let rty = sub.resolve_type(&f.ret);
                let _ = sub.coerce(body, rty, "function result");
            }
            ast::Item::Tick(t) => {
                if let Some(v) = sub.const_value(&empty, &t.duration.amount) {
                    let ms = match t.duration.unit {
                        ast::TimeUnit::Ms => v,
                        ast::TimeUnit::S => v.saturating_mul(1000),
                        ast::TimeUnit::Min => v.saturating_mul(60_000),
                    };
                    if ms <= 0 {
                        sub.sink.push(Diagnostic::error(
                            "E0104",
                            "the tick length must be positive",
                            t.span,
                        ));
                    } else {
                        g.tick_ms = Some(ms);
                    }
                }
            }
            _ => {}
        }
        diags.extend(sub.sink.diags);
    }
}
