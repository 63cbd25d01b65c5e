//! Composite components (`docs/components.md`): a `component` declares ports and contains
//! instances and connections; systems and other components instantiate it like a chart.
//!
//! Before checking, every system is **flattened** ([`flatten`]): an instance of a component
//! becomes the component's instances, named by their path (`storage.feeder`), connections to
//! and from its ports are rewired to the inner instances' ports, paths through it in
//! expressions (`storage.feeder.pos`, `storage.pos`) are rewritten to the leaf instance, and
//! the execution order is the order declared inside each component, at the component's place.
//! The checker, the IR and every engine see one flat system of chart instances, so a tick is
//! still one synchronous step, lowered once. Each component also runs alone as an implicit
//! system named like it (its unconnected input ports are free inputs).

mod params;
mod ports;
mod renames;
mod scope;
mod size;
mod slots;
mod visit;

pub(crate) use params::expand as expand_params;
pub(crate) use ports::{check as check_ports, conformance};

use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;
use std::collections::{HashMap, HashSet};

/// Components nested deeper than this are reported (E0170), which also bounds recursion.
const MAX_DEPTH: usize = 32;
/// A system flattened to more instances than this is reported (E0173): a few components
/// nested a few levels deep multiply.
const MAX_INSTANCES: usize = 4096;

/// The file with its systems flattened.
pub(crate) struct Flattened {
    /// The rewritten file: components removed, systems flat, one implicit system per
    /// component appended.
    pub file: ast::File,
    /// Names of the systems that are components running alone (implicit systems).
    pub standalone: HashSet<String>,
    /// Each port of a component instance and the inner variable it is wired to, for the
    /// type check after the charts are checked ([`check_ports`]).
    pub links: Vec<PortLink>,
    /// The components, for their conformance to interfaces ([`conformance`]).
    pub components: Vec<ast::Component>,
}

/// A component port wired to a leaf instance's variable inside it.
#[derive(Clone, Debug)]
pub(crate) struct PortLink {
    /// The flattened system it belongs to.
    pub system: String,
    /// The component declaring the port.
    pub component: String,
    /// The port.
    pub port: ast::VarDecl,
    /// The leaf instance (group) name in the flattened system.
    pub instance: String,
    /// The variable of that instance.
    pub var: String,
    /// The connection inside the component that wires them.
    pub at: Span,
}

/// Flatten every system of `file`; `None` when the file declares no component.
pub(crate) fn flatten(file: &ast::File, diags: &mut Vec<Diagnostic>) -> Option<Flattened> {
    let mut comps: HashMap<&str, &ast::Component> = HashMap::new();
    for item in &file.items {
        if let ast::Item::Component(c) = item {
            comps.entry(c.name.name.as_str()).or_insert(c);
        }
    }
    if comps.is_empty() {
        return None;
    }
    let known: HashSet<&str> = file
        .items
        .iter()
        .filter_map(|i| match i {
            ast::Item::Chart(c) => Some(c.name.name.as_str()),
            ast::Item::Interface(d) => Some(d.name.name.as_str()),
            _ => None,
        })
        .collect();
    let interfaces: HashSet<&str> = file
        .items
        .iter()
        .filter_map(|i| match i {
            ast::Item::Interface(d) => Some(d.name.name.as_str()),
            _ => None,
        })
        .filter(|n| {
            !file
                .items
                .iter()
                .any(|i| matches!(i, ast::Item::Chart(c) if c.name.name == *n))
        })
        .collect();
    let mut out = ast::File::default();
    let mut links = Vec::new();
    let mut standalone = HashSet::new();
    let mut extra = Vec::new();
    let mut components = Vec::new();
    let mut sizes = HashMap::new();
    // A component too big to run alone is reported only in a file without systems (in a
    // file with systems, the systems that instantiate it are).
    let report_alone = !file.items.iter().any(|i| matches!(i, ast::Item::System(_)));
    for item in &file.items {
        match item {
            ast::Item::System(s) => {
                if size::too_big(s, &comps, &mut sizes, Some(&mut *diags)) {
                    // Refused before any work: an empty system keeps the systems' order.
                    let mut empty = scope::Flattener::empty_system();
                    empty.name = s.name.clone();
                    empty.span = s.span;
                    out.items.push(ast::Item::System(empty));
                    continue;
                }
                let mut f = scope::Flattener::new(&comps, &known, diags, &s.name.name);
                let mut flat = f.system(s, None);
                links.extend(f.links);
                slots::bind_paths(&mut flat, file, diags);
                out.items.push(ast::Item::System(flat));
            }
            ast::Item::Component(c) => {
                components.push(c.clone());
                component_rules(c, diags);
                if comps
                    .get(c.name.name.as_str())
                    .is_some_and(|k| std::ptr::eq(*k, c))
                    // A copy with arguments (`Storage(3)`) runs only where instantiated.
                    && !c.name.name.contains('(')
                    && !size::too_big(
                        &c.body,
                        &comps,
                        &mut sizes,
                        report_alone.then_some(&mut *diags),
                    )
                {
                    let mut f = scope::Flattener::new(&comps, &known, diags, &c.name.name);
                    let flat = f.system(&c.body, Some(c));
                    links.extend(f.links);
                    // A component with slots inside runs only in a system that binds them.
                    let open = flat
                        .instances
                        .iter()
                        .any(|i| interfaces.contains(i.chart.name.as_str()));
                    if !open {
                        standalone.insert(c.name.name.clone());
                        extra.push(ast::Item::System(flat));
                    }
                }
            }
            other => out.items.push(other.clone()),
        }
    }
    out.items.extend(extra);
    Some(Flattened {
        file: out,
        standalone,
        links,
        components,
    })
}

/// What a component may not contain, and its ports' own rules (E0173, E0102).
fn component_rules(c: &ast::Component, diags: &mut Vec<Diagnostic>) {
    let unsupported = |span: Span, what: &str| {
        Diagnostic::error(
            "E0173",
            format!("{what} inside component `{}` is not supported", c.name.name),
            span,
        )
        .with_label("not allowed in a component")
        .with_hint("declare it in the system that instantiates the component")
    };
    for o in &c.body.observers {
        diags.push(unsupported(o.name.span, "an observer"));
    }
    for r in &c.body.requirements {
        diags.push(unsupported(r.span, "a requirement"));
    }
    for k in &c.body.configurations {
        diags.push(unsupported(k.name.span, "a configuration"));
    }
    let mut seen: HashMap<&str, Span> = HashMap::new();
    for p in &c.ports {
        if let Some(prev) = seen.insert(p.name.name.as_str(), p.name.span) {
            diags.push(
                Diagnostic::error(
                    "E0102",
                    format!(
                        "port `{}` of component `{}` is declared twice",
                        p.name.name, c.name.name
                    ),
                    p.name.span,
                )
                .with_label("second declaration")
                .with_secondary(prev, "first declared here"),
            );
        }
        if let Some(init) = &p.init {
            diags.push(
                Diagnostic::error(
                    "E0173",
                    format!("port `{}` has an initial value", p.name.name),
                    init.span(),
                )
                .with_label("a port has no value of its own")
                .with_hint("the inner instance's variable wired to the port has the initial value"),
            );
        }
        if p.kind == ast::VarKind::Local {
            diags.push(
                Diagnostic::error(
                    "E0173",
                    format!(
                        "`{}`: a component declares only input and output ports",
                        p.name.name
                    ),
                    p.span,
                )
                .with_label("not a port"),
            );
        }
        if c.body.instances.iter().any(|i| i.name.name == p.name.name) {
            diags.push(
                Diagnostic::error(
                    "E0102",
                    format!(
                        "`{}` is both a port and an instance of component `{}`",
                        p.name.name, c.name.name
                    ),
                    p.name.span,
                )
                .with_label("port"),
            );
        }
    }
}

/// Drop "unknown name" errors (E0101) at a path already reported as a bad index of a
/// component array (E0176): the path stays as written, which the checker cannot resolve.
pub(crate) fn suppress_cascades(diags: &mut Vec<Diagnostic>) {
    let bad: HashSet<u32> = diags
        .iter()
        .filter(|d| d.code == "E0176")
        .map(|d| d.span.start)
        .collect();
    if bad.is_empty() {
        return;
    }
    diags.retain(|d| !(d.code == "E0101" && bad.contains(&d.span.start)));
}
