//! Parameterised components and arrays of components (`docs/components.md`), before the
//! flattening: `component Storage(n: int) { instance f: Feeder(n); … }` instantiated as
//! `instance s: Storage(3);` becomes a copy `Storage(3)` with each use of `n` replaced by `3`
//! (the copy's own instances are expanded in turn), and the length of `instance cells[3]:
//! Cell;` becomes a literal. The flattening then sees components without parameters.
//!
//! The binding of arguments is the charts' (`crate::params`): the same diagnostics for a
//! missing (E0151), extra or unknown (E0150) or out-of-range argument.

use crate::expr::ExprChecker;
use crate::params::{bind, literal, named_copy, refuse_arguments, value_of, Decl, Subst, Value};
use crate::types::Type;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast;
use statecheck_syntax::ast::visit_mut::VisitMut;
use std::collections::{HashMap, HashSet};

/// At most this many copies of parameterised components (E0175): a component instantiating
/// itself with other arguments would otherwise copy without end.
const MAX_COPIES: usize = 256;

/// The longest array of components (like a chart instance array).
const MAX_LEN: i64 = 4096;

type Sig = Vec<(Type, Option<Value>)>;

/// The file with parameterised components replaced by their copies and arrays of components
/// given literal lengths; `None` when there is nothing to do.
pub(crate) fn expand(file: &ast::File, ck: &mut ExprChecker<'_>) -> Option<ast::File> {
    let mut comps: HashMap<&str, &ast::Component> = HashMap::new();
    for item in &file.items {
        if let ast::Item::Component(c) = item {
            comps.entry(c.name.name.as_str()).or_insert(c);
        }
    }
    let uses = |s: &ast::System| {
        s.instances.iter().any(|i| {
            comps.contains_key(i.chart.name.as_str()) && (!i.args.is_empty() || i.count.is_some())
        })
    };
    let any = file.items.iter().any(|i| match i {
        ast::Item::Component(c) => !c.params.is_empty() || uses(&c.body),
        ast::Item::System(s) => uses(s),
        _ => false,
    });
    if !any {
        return None;
    }
    let mut sigs: HashMap<&str, Sig> = HashMap::new();
    for c in comps.values() {
        if !c.params.is_empty() {
            sigs.insert(c.name.name.as_str(), signature(&c.params, ck));
        }
    }
    let mut ex = Expander {
        comps: &comps,
        sigs: &sigs,
        made: HashSet::new(),
        queue: Vec::new(),
        reported: false,
    };
    let mut out = ast::File::default();
    for item in &file.items {
        match item {
            ast::Item::System(s) => {
                let mut s = s.clone();
                ex.body(&mut s, ck);
                out.items.push(ast::Item::System(s));
            }
            ast::Item::Component(c) if c.params.is_empty() => {
                let mut c = c.clone();
                ex.body(&mut c.body, ck);
                out.items.push(ast::Item::Component(c));
            }
            ast::Item::Component(c) => {
                // With a default for every parameter, the component keeps its plain name with
                // the defaults; otherwise only its instantiations exist.
                let defaults: Option<Vec<Value>> = sigs
                    .get(c.name.name.as_str())
                    .and_then(|sig| sig.iter().map(|(_, d)| *d).collect());
                if let Some(d) = defaults {
                    let mut plain = specialise(c, &d, c.name.name.clone(), ck);
                    ex.made.insert(plain.name.name.clone());
                    ex.body(&mut plain.body, ck);
                    out.items.push(ast::Item::Component(plain));
                }
            }
            other => out.items.push(other.clone()),
        }
    }
    while let Some(mut c) = ex.queue.pop() {
        ex.body(&mut c.body, ck);
        out.items.push(ast::Item::Component(c));
    }
    Some(out)
}

/// Each parameter's type and default value.
fn signature(params: &[ast::ChartParam], ck: &mut ExprChecker<'_>) -> Sig {
    params
        .iter()
        .map(|p| {
            let ty = ck.resolve_type(&p.ty);
            let what = format!("the default of parameter `{}`", p.name.name);
            let d = p.default.as_ref().and_then(|e| value_of(ck, e, ty, &what));
            (ty, d)
        })
        .collect()
}

/// The component with its parameters replaced by `values`, named `name`.
fn specialise(
    c: &ast::Component,
    values: &[Value],
    name: String,
    ck: &ExprChecker<'_>,
) -> ast::Component {
    let mut out = c.clone();
    let mut s = Subst {
        names: c
            .params
            .iter()
            .zip(values)
            .map(|(p, v)| (p.name.name.clone(), literal(*v, ck)))
            .collect(),
    };
    out.params.clear();
    out.name.name = name.clone();
    out.body.name.name = name;
    for p in &mut out.ports {
        s.visit_var(p);
    }
    let b = &mut out.body;
    for i in &mut b.instances {
        if let Some(n) = &mut i.count {
            s.visit_expr(n);
        }
        for a in &mut i.args {
            s.visit_expr(&mut a.value);
        }
    }
    for c in &mut b.connections {
        s.visit_path(&mut c.from);
        s.visit_path(&mut c.to);
    }
    for a in &mut b.assumes {
        s.visit_expr(&mut a.expr);
    }
    for r in &mut b.rates {
        s.visit_path(&mut r.target);
    }
    for p in &mut b.properties {
        s.visit_property(p);
    }
    out
}

struct Expander<'a> {
    comps: &'a HashMap<&'a str, &'a ast::Component>,
    sigs: &'a HashMap<&'a str, Sig>,
    /// Names of the copies made (and of parameterised components kept with defaults).
    made: HashSet<String>,
    /// Copies whose own instances are still to expand.
    queue: Vec<ast::Component>,
    /// E0175 was reported.
    reported: bool,
}

impl Expander<'_> {
    /// The component instances of a system or component body: lengths made literal,
    /// arguments bound and the instance pointed at the copy.
    fn body(&mut self, body: &mut ast::System, ck: &mut ExprChecker<'_>) {
        // An instance whose arguments are wrong (reported) is dropped, not left to be
        // reported again as an unknown chart.
        let mut failed = Vec::new();
        for (at, inst) in body.instances.iter_mut().enumerate() {
            let Some(c) = self.comps.get(inst.chart.name.as_str()).copied() else {
                continue;
            };
            if let Some(n) = &mut inst.count {
                let what = format!("the length of the array `{}`", inst.name.name);
                let ty = Type::Int { lo: 1, hi: MAX_LEN };
                let len = match value_of(ck, n, ty, &what) {
                    Some(Value::Int(k)) => k,
                    _ => 1, // reported
                };
                *n = ast::Expr::Int(len, n.span());
            }
            let args = std::mem::take(&mut inst.args);
            if c.params.is_empty() {
                let decl = Decl {
                    kind: "component",
                    name: &c.name,
                    params: &c.params,
                };
                refuse_arguments(&decl, &inst.name, &args, ck);
                continue;
            }
            let Some(sig) = self.sigs.get(c.name.name.as_str()) else {
                continue;
            };
            let decl = Decl {
                kind: "component",
                name: &c.name,
                params: &c.params,
            };
            let Some(values) = bind(&decl, sig, &args, inst, ck) else {
                failed.push(at);
                continue;
            };
            let defaults: Option<Vec<Value>> = sig.iter().map(|(_, d)| *d).collect();
            if defaults.as_ref() == Some(&values) {
                continue;
            }
            let name = named_copy(&c.name.name, &values, ck);
            if !self.made.contains(&name) {
                if self.made.len() >= MAX_COPIES {
                    if !self.reported {
                        self.reported = true;
                        ck.sink.push(
                            Diagnostic::error(
                                "E0175",
                                format!(
                                    "more than {MAX_COPIES} different argument lists of components"
                                ),
                                inst.chart.span,
                            )
                            .with_label("one too many")
                            .with_hint(
                                "a component that instantiates itself with other arguments \
                                 never ends: nest a fixed number of levels",
                            ),
                        );
                    }
                    continue;
                }
                self.made.insert(name.clone());
                self.queue.push(specialise(c, &values, name.clone(), ck));
            }
            inst.chart.name = name;
        }
        for at in failed.into_iter().rev() {
            body.instances.remove(at);
        }
    }
}
