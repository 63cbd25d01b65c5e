//! Interleaved composition (`system S interleaved { … }`, `docs/components.md`): in each tick
//! one **unit** steps — one top-level instance of the system (a chart instance, a component
//! instance with everything inside it, one element of an instance array) — chosen by the
//! implicit free input `sched.unit`. The choice is an ordinary input: this pass adds the
//! instance `sched` of a one-state chart with that input, and the lowering (`crates/ir`)
//! runs a unit's step only when `sched.unit` names it, so every engine, the simulator and
//! the code generators handle interleaving unchanged.

use crate::expr::ExprChecker;
use crate::params::{value_of, Value};
use crate::types::Type;
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;

/// The scheduler instance's name.
pub const SCHED: &str = "sched";

/// The unit an instance (by its flat name) belongs to: its name up to the first `.` (a
/// component instance's path), or itself.
pub(crate) fn unit_key(name: &str) -> &str {
    name.split('.').next().unwrap_or(name)
}

/// The file with a scheduler added to every interleaved system; `None` when there is none.
pub(crate) fn expand(
    file: &ast::File,
    ck: &mut ExprChecker<'_>,
    diags: &mut Vec<Diagnostic>,
) -> Option<ast::File> {
    if !file
        .items
        .iter()
        .any(|i| matches!(i, ast::Item::System(s) if s.interleaved))
    {
        return None;
    }
    let mut out = ast::File::default();
    let mut made: Vec<i64> = Vec::new();
    let mut charts = Vec::new();
    for item in &file.items {
        let ast::Item::System(s) = item else {
            out.items.push(item.clone());
            continue;
        };
        let mut s = s.clone();
        if s.interleaved {
            if let Some(i) = s.instances.iter().find(|i| i.name.name == SCHED) {
                diags.push(
                    Diagnostic::error(
                        "E0177",
                        format!("an interleaved system cannot have an instance named `{SCHED}`"),
                        i.name.span,
                    )
                    .with_label("the scheduler's name")
                    .with_hint(format!(
                        "`{SCHED}.unit` is the implicit input choosing which unit steps: rename the instance"
                    )),
                );
                s.interleaved = false;
            } else {
                let k = units(&s, ck);
                if k > 0 {
                    let name = format!("{SCHED}({k})");
                    if !made.contains(&k) {
                        made.push(k);
                        charts.push(ast::Item::Chart(scheduler(&name, k, s.name.span)));
                    }
                    add(&mut s, &name);
                } else {
                    s.interleaved = false;
                }
            }
        }
        out.items.push(ast::Item::System(s));
    }
    out.items.extend(charts);
    Some(out)
}

/// The number of units of a flat system: one per distinct [`unit_key`], an array of chart
/// instances one per element.
fn units(s: &ast::System, ck: &mut ExprChecker<'_>) -> i64 {
    let mut keys: Vec<&str> = Vec::new();
    let mut n = 0i64;
    for inst in &s.instances {
        let key = unit_key(&inst.name.name);
        if keys.contains(&key) {
            continue;
        }
        keys.push(key);
        n += match &inst.count {
            Some(e) if key == inst.name.name => {
                let ty = Type::Int { lo: 1, hi: 4096 };
                match value_of(ck, e, ty, "the length of an instance array") {
                    Some(Value::Int(k)) => k,
                    _ => return 0, // reported by the system checker too
                }
            }
            _ => 1,
        };
    }
    n
}

/// `sched: sched(k)` first in the instances and the order.
fn add(s: &mut ast::System, chart: &str) {
    let at = s.name.span;
    let ident = |name: &str| ast::Ident {
        name: name.to_string(),
        span: at,
    };
    s.instances.insert(
        0,
        ast::Instance {
            name: ident(SCHED),
            count: None,
            chart: ident(chart),
            args: Vec::new(),
            renames: Vec::new(),
            span: at,
        },
    );
    if let Some(o) = s.order.first_mut() {
        o.instances.insert(0, ident(SCHED));
    }
}

/// `chart sched(k) { input unit: int[0..k-1] = 0; initial Run; state Run; }`
fn scheduler(name: &str, k: i64, at: Span) -> ast::Chart {
    let ident = |name: &str| ast::Ident {
        name: name.to_string(),
        span: at,
    };
    ast::Chart {
        name: ident(name),
        role: None,
        params: Vec::new(),
        implements: Vec::new(),
        vars: vec![ast::VarDecl {
            kind: ast::VarKind::Input,
            is_event: false,
            name: ident("unit"),
            len: None,
            ty: Some(ast::TypeExpr::Range {
                lo: Box::new(ast::Expr::Int(0, at)),
                hi: Box::new(ast::Expr::Int(k - 1, at)),
                span: at,
            }),
            init: Some(ast::Expr::Int(0, at)),
            control: None,
            span: at,
        }],
        body: ast::StateBody {
            initial: vec![ast::Initial {
                target: ident("Run"),
                action: None,
                span: at,
            }],
            states: vec![ast::State {
                name: ident("Run"),
                marked: false,
                body: ast::StateBody::default(),
                span: at,
            }],
            ..ast::StateBody::default()
        },
        properties: Vec::new(),
        span: at,
    }
}
