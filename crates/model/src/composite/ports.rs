//! Checks on the checked charts: each component port against the inner variable it is wired
//! to (E0172), and each component against the interfaces it implements (E0152–E0154).

use super::PortLink;
use crate::components::fits;
use crate::expr::{type_name, ExprChecker};
use crate::model::Chart;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast::{self, VarKind};
use std::collections::HashSet;

fn what(is_event: bool, kind: VarKind) -> String {
    let k = match kind {
        VarKind::Input => "input",
        VarKind::Output => "output",
        VarKind::Local => "local",
    };
    format!("{k} {}", if is_event { "event" } else { "variable" })
}

/// E0172 for every wiring of a port to an inner variable of another kind or an incompatible
/// type (an input port's values must all be accepted by the inner input; an inner output's
/// values must all lie in the output port's type). Reported once per component and port.
pub(crate) fn check(
    file: &ast::File,
    links: &[PortLink],
    charts: &[Chart],
    ck: &mut ExprChecker<'_>,
) {
    let mut done: HashSet<(String, String, String, String)> = HashSet::new();
    for l in links {
        let key = (
            l.component.clone(),
            l.port.name.name.clone(),
            l.instance.clone(),
            l.var.clone(),
        );
        let Some(inst) = file.items.iter().find_map(|i| match i {
            ast::Item::System(s) if s.name.name == l.system => {
                s.instances.iter().find(|i| i.name.name == l.instance)
            }
            _ => None,
        }) else {
            continue;
        };
        let Some(&id) = ck.globals.chart_ids.get(&inst.chart.name) else {
            continue;
        };
        let Some(v) = charts
            .get(id as usize)
            .and_then(|c| c.vars.iter().find(|v| v.name == l.var))
        else {
            continue;
        };
        if !done.insert(key) {
            continue;
        }
        let p = &l.port;
        let kind_ok = v.is_event == p.is_event
            && match p.kind {
                VarKind::Input => v.kind == VarKind::Input,
                _ => v.kind != VarKind::Local,
            };
        if !kind_ok {
            ck.sink.push(
                Diagnostic::error(
                    "E0172",
                    format!(
                        "port `{}` of component `{}` is an {} but is wired to `{}.{}`, an {}",
                        p.name.name,
                        l.component,
                        what(p.is_event, p.kind),
                        inst.name.name.rsplit('.').next().unwrap_or(&inst.name.name),
                        v.name,
                        what(v.is_event, v.kind)
                    ),
                    l.at,
                )
                .with_label("wires ports of different kinds")
                .with_secondary(p.span, "the port"),
            );
            continue;
        }
        if p.is_event {
            continue;
        }
        let Some(t) = &p.ty else { continue };
        let want = ck.resolve_type(t);
        if let Err(rule) = fits(p.kind, want, v.ty) {
            let (wn, vn) = (type_name(ck.globals, want), type_name(ck.globals, v.ty));
            ck.sink.push(
                Diagnostic::error(
                    "E0172",
                    format!(
                        "port `{}` of component `{}` is `{wn}` but is wired to `{}.{}`, a `{vn}`",
                        p.name.name,
                        l.component,
                        inst.name.name.rsplit('.').next().unwrap_or(&inst.name.name),
                        v.name
                    ),
                    l.at,
                )
                .with_label(format!("`{vn}` here"))
                .with_secondary(p.span, format!("the port says `{wn}`"))
                .with_hint(rule.replace("interface", "port")),
            );
        }
    }
}

/// Every component that says `implements I` against `I`: each port of `I` declared by the
/// component with the same direction and kind and a conforming type.
pub(crate) fn conformance(file: &ast::File, comps: &[ast::Component], ck: &mut ExprChecker<'_>) {
    for c in comps {
        for name in &c.implements {
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
                if seen.insert(m.name.name.as_str()) {
                    member(itf, m, c, name.span, ck);
                }
            }
        }
    }
}

fn member(
    itf: &ast::InterfaceDecl,
    m: &ast::VarDecl,
    c: &ast::Component,
    at: statecheck_base::Span,
    ck: &mut ExprChecker<'_>,
) {
    let Some(p) = c.ports.iter().find(|p| p.name.name == m.name.name) else {
        let decl = if m.is_event {
            format!(
                "{} event {};",
                what(false, m.kind).replace(" variable", ""),
                m.name.name
            )
        } else {
            format!(
                "{} {}: …;",
                what(false, m.kind).replace(" variable", ""),
                m.name.name
            )
        };
        ck.sink.push(
            Diagnostic::error(
                "E0152",
                format!(
                    "component `{}` does not declare `{}` of interface `{}`",
                    c.name.name, m.name.name, itf.name.name
                ),
                at,
            )
            .with_label(format!("`{}` is missing", m.name.name))
            .with_secondary(m.span, "required by the interface")
            .with_hint(format!("declare the port in the component: `{decl}`")),
        );
        return;
    };
    if p.kind != m.kind || p.is_event != m.is_event {
        ck.sink.push(
            Diagnostic::error(
                "E0153",
                format!(
                    "`{}` is an {} in interface `{}` but an {} in component `{}`",
                    m.name.name,
                    what(m.is_event, m.kind),
                    itf.name.name,
                    what(p.is_event, p.kind),
                    c.name.name
                ),
                p.span,
            )
            .with_label("declared differently from the interface")
            .with_secondary(m.span, "the interface's port"),
        );
        return;
    }
    let (Some(mt), Some(pt)) = (&m.ty, &p.ty) else {
        return;
    };
    let (want, got) = (ck.resolve_type(mt), ck.resolve_type(pt));
    if let Err(rule) = fits(m.kind, want, got) {
        let (wn, gn) = (type_name(ck.globals, want), type_name(ck.globals, got));
        ck.sink.push(
            Diagnostic::error(
                "E0154",
                format!(
                    "`{}` is `{wn}` in interface `{}` but `{gn}` in component `{}`",
                    m.name.name, itf.name.name, c.name.name
                ),
                p.span,
            )
            .with_label(format!("this is `{gn}`"))
            .with_secondary(m.span, format!("the interface says `{wn}`"))
            .with_hint(rule.to_string()),
        );
    }
}
