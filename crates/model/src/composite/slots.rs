//! Slots inside component instances: a configuration binds them by path
//! (`storage.feeder.home = FaultySensor;`) once the system is flat, since only then do they
//! have their path names.

use statecheck_base::Diagnostic;
use statecheck_syntax::ast;
use std::collections::HashMap;

/// Apply the bindings by path that `components::expand` left in `s.configurations` (one
/// configuration at most: the one `s` was built for), then report the slots inside component
/// instances that stay open (E0157).
pub(super) fn bind_paths(s: &mut ast::System, file: &ast::File, diags: &mut Vec<Diagnostic>) {
    let mut interfaces: HashMap<&str, &ast::InterfaceDecl> = HashMap::new();
    let mut charts: HashMap<&str, &ast::Chart> = HashMap::new();
    let mut comps: HashMap<&str, &ast::Component> = HashMap::new();
    for item in &file.items {
        match item {
            ast::Item::Interface(i) => {
                interfaces.entry(i.name.name.as_str()).or_insert(i);
            }
            ast::Item::Chart(c) => {
                charts.entry(c.name.name.as_str()).or_insert(c);
            }
            ast::Item::Component(c) => {
                comps.entry(c.name.name.as_str()).or_insert(c);
            }
            _ => {}
        }
    }
    let is_slot = |chart: &str| !charts.contains_key(chart) && interfaces.contains_key(chart);
    for cfg in std::mem::take(&mut s.configurations) {
        for b in &cfg.bindings {
            let Some(inst) = s
                .instances
                .iter_mut()
                .find(|i| i.name.name == b.instance.name)
            else {
                diags.push(
                    Diagnostic::error(
                        "E0101",
                        format!("no instance `{}` in the flattened system", b.instance.name),
                        b.instance.span,
                    )
                    .with_label("not an instance path")
                    .with_hint("a path names a chart instance inside component instances: `storage.feeder.home`"),
                );
                continue;
            };
            let Some(itf) = interfaces
                .get(inst.chart.name.as_str())
                .filter(|_| is_slot(&inst.chart.name))
            else {
                if b.chart.name != inst.chart.name {
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
                        .with_secondary(inst.chart.span, "declared here"),
                    );
                    continue;
                }
                inst.args = b.args.clone();
                continue;
            };
            if comps.contains_key(b.chart.name.as_str()) {
                diags.push(
                    Diagnostic::error(
                        "E0173",
                        format!(
                            "slot `{}` inside a component takes a chart, not component `{}`",
                            b.instance.name, b.chart.name
                        ),
                        b.chart.span,
                    )
                    .with_label("a component here")
                    .with_hint("declare the slot in the system to swap components"),
                );
                continue;
            }
            if let Some(ch) = charts.get(b.chart.name.as_str()) {
                if !ch.implements.iter().any(|i| i.name == itf.name.name) {
                    diags.push(
                        Diagnostic::error(
                            "E0156",
                            format!(
                                "chart `{}` does not implement interface `{}` of slot `{}`",
                                b.chart.name, itf.name.name, b.instance.name
                            ),
                            b.chart.span,
                        )
                        .with_label(format!("not declared `implements {}`", itf.name.name))
                        .with_secondary(ch.name.span, "chart declared here"),
                    );
                    continue;
                }
            }
            inst.chart = b.chart.clone();
            inst.args = b.args.clone();
        }
    }
    for i in &s.instances {
        if i.name.name.contains('.') && is_slot(&i.chart.name) {
            diags.push(
                Diagnostic::error(
                    "E0157",
                    format!(
                        "slot `{}` of interface `{}` gets no chart",
                        i.name.name, i.chart.name
                    ),
                    i.chart.span,
                )
                .with_label("an interface, not a chart")
                .with_hint(format!(
                    "add `{} = ChartImplementing{};` to each configuration of the system",
                    i.name.name, i.chart.name
                )),
            );
        }
    }
}
