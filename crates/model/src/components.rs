//! Interfaces, slots and configurations (`docs/components.md`).
//!
//! - An `interface` lists ports; a chart that says `implements` it is checked for conformance
//!   ([`conformance`]: every port declared, same direction and kind, a compatible type).
//! - In a system, an instance whose type is an interface is a *slot*: connections to it may
//!   use only the interface's ports, and each `configuration` chooses its chart.
//! - A system with configurations becomes, before checking, one ordinary system per
//!   configuration, named `System:configuration`, plus the system itself in its first
//!   configuration ([`expand`]); the rest of the checker and the IR see plain systems.

use crate::expr::ExprChecker;
use crate::model::Chart;
use crate::types::Type;
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;
use statecheck_syntax::ast::VarKind;
use std::collections::{HashMap, HashSet};

/// The separator between a system's name and its configuration's, `Plant:faulty`.
pub const CONFIG_SEP: char = ':';

/// The file with systems expanded per configuration; for each system of the result, in order,
/// the span of its configuration's name (`None` for a system without configurations).
pub(crate) struct Expanded {
    /// The rewritten file.
    pub file: ast::File,
    /// Per system of `file`: the configuration it was built for.
    pub origins: Vec<Option<(String, Span)>>,
}

/// Expand configurations and check slots; `None` when the file has neither.
pub(crate) fn expand(file: &ast::File, diags: &mut Vec<Diagnostic>) -> Option<Expanded> {
    let mut interfaces: HashMap<&str, &ast::InterfaceDecl> = HashMap::new();
    // Charts and composite components: what an instance or a slot binding may name.
    let mut charts: HashMap<&str, Impl<'_>> = HashMap::new();
    for item in &file.items {
        match item {
            ast::Item::Interface(i) => {
                interfaces.entry(i.name.name.as_str()).or_insert(i);
            }
            ast::Item::Chart(c) => {
                charts.entry(c.name.name.as_str()).or_insert(Impl {
                    name: &c.name,
                    implements: &c.implements,
                    kind: "chart",
                });
            }
            ast::Item::Component(c) => {
                charts.entry(c.name.name.as_str()).or_insert(Impl {
                    name: &c.name,
                    implements: &c.implements,
                    kind: "component",
                });
            }
            _ => {}
        }
    }
    let any = file.items.iter().any(|i| match i {
        ast::Item::System(s) => {
            !s.configurations.is_empty()
                || s.instances.iter().any(|i| {
                    !charts.contains_key(i.chart.name.as_str())
                        && interfaces.contains_key(i.chart.name.as_str())
                })
        }
        _ => false,
    });
    if !any {
        return None;
    }
    let mut out = ast::File::default();
    let mut origins = Vec::new();
    for item in &file.items {
        let ast::Item::System(s) = item else {
            out.items.push(item.clone());
            continue;
        };
        let slots: HashMap<&str, &ast::InterfaceDecl> = s
            .instances
            .iter()
            .filter(|i| !charts.contains_key(i.chart.name.as_str()))
            .filter_map(|i| {
                let itf = interfaces.get(i.chart.name.as_str())?;
                Some((i.name.name.as_str(), *itf))
            })
            .collect();
        slot_connections(s, &slots, diags);
        if s.configurations.is_empty() {
            for i in &s.instances {
                if let Some(itf) = slots.get(i.name.name.as_str()) {
                    diags.push(
                        Diagnostic::error(
                            "E0157",
                            format!(
                                "slot `{}` of interface `{}` gets no chart",
                                i.name.name, itf.name.name
                            ),
                            i.chart.span,
                        )
                        .with_label("an interface, not a chart")
                        .with_hint(format!(
                            "add `configuration NAME {{ {} = ChartImplementing{}; }}` to the system",
                            i.name.name, itf.name.name
                        )),
                    );
                }
            }
            let mut plain = s.clone();
            plain.configurations.clear();
            out.items.push(ast::Item::System(plain));
            origins.push(None);
            continue;
        }
        let mut seen: HashMap<&str, Span> = HashMap::new();
        for (k, c) in s.configurations.iter().enumerate() {
            if let Some(prev) = seen.insert(c.name.name.as_str(), c.name.span) {
                diags.push(
                    Diagnostic::error(
                        "E0102",
                        format!("configuration `{}` is declared twice", c.name.name),
                        c.name.span,
                    )
                    .with_label("second declaration")
                    .with_secondary(prev, "first declared here"),
                );
                continue;
            }
            let built = configure(s, c, &slots, &charts, diags);
            if k == 0 {
                let mut first = built.clone();
                first.name = s.name.clone();
                out.items.push(ast::Item::System(first));
                origins.push(Some((c.name.name.clone(), c.name.span)));
            }
            out.items.push(ast::Item::System(built));
            origins.push(Some((c.name.name.clone(), c.name.span)));
        }
    }
    Some(Expanded { file: out, origins })
}

/// A chart or composite component, as a configuration may bind it.
struct Impl<'a> {
    name: &'a ast::Ident,
    implements: &'a [ast::Ident],
    /// `chart` or `component`, for messages.
    kind: &'static str,
}

/// The system `s` in configuration `c`: each bound instance gets the chosen chart and
/// arguments. Reports unknown instances, slots left unbound and charts a slot cannot take.
fn configure(
    s: &ast::System,
    c: &ast::Configuration,
    slots: &HashMap<&str, &ast::InterfaceDecl>,
    charts: &HashMap<&str, Impl<'_>>,
    diags: &mut Vec<Diagnostic>,
) -> ast::System {
    let mut out = s.clone();
    out.configurations.clear();
    out.name = ast::Ident {
        name: format!("{}{CONFIG_SEP}{}", s.name.name, c.name.name),
        span: c.name.span,
    };
    let mut bound: HashMap<&str, Span> = HashMap::new();
    // A binding by path (`storage.feeder.home = …`) names a slot inside a component instance:
    // it waits for the flattening (`composite::bind_paths`).
    let mut by_path = Vec::new();
    for b in &c.bindings {
        if b.instance.name.contains('.') {
            by_path.push(b.clone());
            continue;
        }
        let Some(inst) = out
            .instances
            .iter_mut()
            .find(|i| i.name.name == b.instance.name)
        else {
            let names = s.instances.iter().map(|i| i.name.name.as_str());
            let mut d = Diagnostic::error(
                "E0101",
                format!(
                    "system `{}` has no instance `{}`",
                    s.name.name, b.instance.name
                ),
                b.instance.span,
            )
            .with_label("not an instance of the system");
            if let Some(n) = crate::suggest::closest(&b.instance.name, names) {
                d = d.with_hint(format!("did you mean `{n}`?"));
            }
            diags.push(d);
            continue;
        };
        if let Some(prev) = bound.insert(b.instance.name.as_str(), b.span) {
            diags.push(
                Diagnostic::error(
                    "E0102",
                    format!(
                        "instance `{}` is bound twice in configuration `{}`",
                        b.instance.name, c.name.name
                    ),
                    b.span,
                )
                .with_label("second binding")
                .with_secondary(prev, "first bound here"),
            );
            continue;
        }
        let chosen = charts.get(b.chart.name.as_str());
        match slots.get(b.instance.name.as_str()) {
            Some(itf) => {
                if let Some(ch) = chosen {
                    if !ch.implements.iter().any(|i| i.name == itf.name.name) {
                        diags.push(
                            Diagnostic::error(
                                "E0156",
                                format!(
                                    "{} `{}` does not implement interface `{}` of slot `{}`",
                                    ch.kind, b.chart.name, itf.name.name, b.instance.name
                                ),
                                b.chart.span,
                            )
                            .with_label(format!("not declared `implements {}`", itf.name.name))
                            .with_secondary(ch.name.span, format!("{} declared here", ch.kind))
                            .with_hint(format!(
                                "write `{} {} implements {} {{ … }}` (the checker then verifies that it conforms)",
                                ch.kind, b.chart.name, itf.name.name
                            )),
                        );
                    }
                }
            }
            None => {
                if chosen.is_some() && b.chart.name != inst.chart.name {
                    diags.push(
                        Diagnostic::error(
                            "E0156",
                            format!(
                                "instance `{}` is a `{}`; a configuration may change its arguments, not its chart",
                                b.instance.name, inst.chart.name
                            ),
                            b.chart.span,
                        )
                        .with_label(format!("not `{}`", inst.chart.name))
                        .with_secondary(inst.chart.span, "declared here")
                        .with_hint(format!(
                            "to swap charts, declare the instance by an interface both implement: `instance {}: SomeInterface;`",
                            b.instance.name
                        )),
                    );
                    continue;
                }
            }
        }
        inst.chart = b.chart.clone();
        inst.args = b.args.clone();
    }
    if !by_path.is_empty() {
        out.configurations = vec![ast::Configuration {
            name: c.name.clone(),
            bindings: by_path,
            span: c.span,
        }];
    }
    for i in &s.instances {
        if let Some(itf) = slots.get(i.name.name.as_str()) {
            if !bound.contains_key(i.name.name.as_str()) {
                diags.push(
                    Diagnostic::error(
                        "E0157",
                        format!(
                            "configuration `{}` chooses no chart for slot `{}`",
                            c.name.name, i.name.name
                        ),
                        c.name.span,
                    )
                    .with_label(format!("`{}` is left open", i.name.name))
                    .with_secondary(i.span, format!("slot of interface `{}`", itf.name.name))
                    .with_hint(format!(
                        "add `{} = ChartImplementing{};`",
                        i.name.name, itf.name.name
                    )),
                );
            }
        }
    }
    out
}

/// E0155: a connection to a slot may use only its interface's ports, in their direction.
fn slot_connections(
    s: &ast::System,
    slots: &HashMap<&str, &ast::InterfaceDecl>,
    diags: &mut Vec<Diagnostic>,
) {
    for c in &s.connections {
        for (path, want, end) in [
            (&c.from, ast::VarKind::Output, "source"),
            (&c.to, ast::VarKind::Input, "destination"),
        ] {
            let [inst, port, ..] = path.segments.as_slice() else {
                continue;
            };
            let Some(itf) = slots.get(inst.name.name.as_str()) else {
                continue;
            };
            let member = itf.members.iter().find(|m| m.name.name == port.name.name);
            let problem = match member {
                None => Some(format!(
                    "interface `{}` of slot `{}` has no port `{}`",
                    itf.name.name, inst.name.name, port.name.name
                )),
                Some(m) if m.kind != want => Some(format!(
                    "`{}` is an {} of interface `{}`; a connection's {end} must be an {}",
                    port.name.name,
                    kind_word(m.kind),
                    itf.name.name,
                    kind_word(want)
                )),
                Some(_) => None,
            };
            if let Some(msg) = problem {
                let mut d = Diagnostic::error("E0155", msg, port.name.span)
                    .with_label("not a port of the slot's interface")
                    .with_secondary(itf.name.span, "interface declared here");
                if member.is_none() {
                    let names = itf.members.iter().map(|m| m.name.name.as_str());
                    if let Some(n) = crate::suggest::closest(&port.name.name, names) {
                        d = d.with_hint(format!("did you mean `{n}`?"));
                    }
                }
                diags.push(d);
            }
        }
    }
}

fn kind_word(k: ast::VarKind) -> &'static str {
    match k {
        ast::VarKind::Input => "input",
        ast::VarKind::Output => "output",
        ast::VarKind::Local => "local",
    }
}

/// Check that `chart` (checked from `ast`) conforms to every interface it implements: one
/// diagnostic per mismatch (E0101 unknown interface, E0152 missing port, E0153 direction or
/// kind, E0154 type).
pub(crate) fn conformance(
    file: &ast::File,
    ast: &ast::Chart,
    chart: &Chart,
    ck: &mut ExprChecker<'_>,
) {
    for name in &ast.implements {
        let itf = file.items.iter().find_map(|i| match i {
            ast::Item::Interface(d) if d.name.name == name.name => Some(d),
            _ => None,
        });
        let Some(itf) = itf else {
            ck.sink.push(
                Diagnostic::error(
                    "E0101",
                    format!("unknown interface `{}`", name.name),
                    name.span,
                )
                .with_label("no interface of this name")
                .with_hint("declare it with `interface NAME { input x: T; … }`"),
            );
            continue;
        };
        let mut seen = HashSet::new();
        for m in &itf.members {
            if !seen.insert(m.name.name.as_str()) {
                continue; // a duplicate port: reported once for the interface
            }
            member(itf, m, ast, chart, name.span, ck);
        }
    }
}

fn member(
    itf: &ast::InterfaceDecl,
    m: &ast::VarDecl,
    ast: &ast::Chart,
    chart: &Chart,
    at: Span,
    ck: &mut ExprChecker<'_>,
) {
    let what = |is_event: bool, kind: VarKind| {
        let k = match kind {
            VarKind::Input => "input",
            VarKind::Output => "output",
            VarKind::Local => "local",
        };
        format!("{k} {}", if is_event { "event" } else { "variable" })
    };
    let mkind = m.kind;
    let Some(v) = chart.vars.iter().find(|v| v.name == m.name.name) else {
        ck.sink.push(
            Diagnostic::error(
                "E0152",
                format!(
                    "chart `{}` does not declare `{}` of interface `{}`",
                    ast.name.name, m.name.name, itf.name.name
                ),
                at,
            )
            .with_label(format!("`{}` is missing", m.name.name))
            .with_secondary(m.span, "required by the interface")
            .with_hint(format!("declare it in the chart: `{}`", decl_text(m))),
        );
        return;
    };
    if v.kind != mkind || v.is_event != m.is_event {
        ck.sink.push(
            Diagnostic::error(
                "E0153",
                format!(
                    "`{}` is an {} in interface `{}` but an {} in chart `{}`",
                    m.name.name,
                    what(m.is_event, mkind),
                    itf.name.name,
                    what(v.is_event, v.kind),
                    ast.name.name
                ),
                v.span,
            )
            .with_label("declared differently from the interface")
            .with_secondary(m.span, "the interface's port"),
        );
        return;
    }
    if m.is_event {
        return;
    }
    let Some(t) = &m.ty else { return };
    let want = ck.resolve_type(t);
    if let Err(rule) = fits(mkind, want, v.ty) {
        let (wn, vn) = (
            crate::expr::type_name(ck.globals, want),
            crate::expr::type_name(ck.globals, v.ty),
        );
        ck.sink.push(
            Diagnostic::error(
                "E0154",
                format!(
                    "`{}` is `{wn}` in interface `{}` but `{vn}` in chart `{}`",
                    m.name.name, itf.name.name, ast.name.name
                ),
                v.span,
            )
            .with_label(format!("this is `{vn}`"))
            .with_secondary(m.span, format!("the interface says `{wn}`"))
            .with_hint(rule.to_string()),
        );
    }
}

/// Whether a port of type `got` conforms to a declared port `want` of direction `kind`;
/// otherwise the rule it breaks.
pub(crate) fn fits(kind: VarKind, want: Type, got: Type) -> Result<(), &'static str> {
    let ok = match (want, got) {
        (Type::Int { lo, hi }, Type::Int { lo: vl, hi: vh }) => match kind {
            // The chart must accept every value the interface lets others send it ...
            VarKind::Input => vl <= lo && hi <= vh,
            // ... and may send only values the interface promises.
            _ => lo <= vl && vh <= hi,
        },
        (a, b) => a == b,
    };
    if ok {
        return Ok(());
    }
    Err(match (want, kind) {
        (Type::Int { .. }, VarKind::Input) => "an input's range must contain the interface's range",
        (Type::Int { .. }, _) => "an output's range must lie within the interface's range",
        _ => "the types must be the same",
    })
}

/// The declaration of an interface port as a chart would write it.
fn decl_text(m: &ast::VarDecl) -> String {
    let kind = kind_word(m.kind);
    if m.is_event {
        format!("{kind} event {};", m.name.name)
    } else {
        format!("{kind} {}: …;", m.name.name)
    }
}

/// Drop "unknown chart `I`" where `I` is an interface: the slot's own diagnostic (E0157)
/// already says that it needs a chart from a configuration.
pub(crate) fn suppress_slot_cascades(file: &ast::File, diags: &mut Vec<Diagnostic>) {
    let names: Vec<String> = file
        .items
        .iter()
        .filter_map(|i| match i {
            ast::Item::Interface(d) => Some(format!("unknown chart `{}`", d.name.name)),
            _ => None,
        })
        .collect();
    if names.is_empty() {
        return;
    }
    diags.retain(|d| !(d.code == "E0101" && names.contains(&d.message)));
}
