//! A system's side of arrays: connections element by element and paths into instances'
//! arrays (`bus.rm[0]`), after components are flattened and parameters expanded.

use super::{constant, element, Arrays};
use crate::expr::ExprChecker;
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;
use statecheck_syntax::ast::visit_mut::{walk_expr, VisitMut};
use std::collections::HashMap;

/// An instance of the system: its array length (`None` for one instance) and its chart.
struct Inst {
    count: Option<usize>,
    chart: String,
}

/// Rewrite `s`'s connections and paths.
pub(super) fn expand(s: &mut ast::System, arrays: &Arrays, ck: &mut ExprChecker<'_>) {
    let mut insts = HashMap::new();
    for i in &s.instances {
        let count = match &i.count {
            Some(e) => match constant(ck, e) {
                Some(n) if n >= 1 => Some(n as usize),
                _ => continue, // reported by the system checker
            },
            None => None,
        };
        insts.insert(
            i.name.name.clone(),
            Inst {
                count,
                chart: i.chart.name.clone(),
            },
        );
    }
    let mut x = Paths {
        insts: &insts,
        arrays,
        ck,
    };
    let mut connections = Vec::with_capacity(s.connections.len());
    for c in std::mem::take(&mut s.connections) {
        x.connection(c, &mut connections);
    }
    s.connections = connections;
    for p in &mut s.properties {
        x.visit_property(p);
    }
    for a in &mut s.assumes {
        x.visit_expr(&mut a.expr);
    }
    for r in &mut s.rates {
        x.path(&mut r.target, false);
    }
    for o in &mut s.observers {
        x.visit_chart(o);
    }
    for r in &mut s.requirements {
        match &mut r.kind {
            ast::RequirementKind::Never(e) => x.visit_expr(e),
            ast::RequirementKind::Needs { cond, .. } => x.visit_expr(cond),
        }
    }
}

/// Where a `[*]` of an endpoint is.
#[derive(Clone, Copy, PartialEq)]
enum Star {
    /// No `[*]`.
    None,
    /// On the instance array (`fam[*].x`).
    Instance,
    /// On the array variable (`env.stallNow[*]`).
    Var,
}

struct Paths<'a, 'c, 'g> {
    insts: &'a HashMap<String, Inst>,
    arrays: &'a Arrays,
    ck: &'c mut ExprChecker<'g>,
}

impl Paths<'_, '_, '_> {
    /// The array variable's length, if `inst.var` names one.
    fn array_len(&self, inst: &str, var: &str) -> Option<usize> {
        let i = self.insts.get(inst)?;
        self.arrays.get(&i.chart)?.get(var).copied()
    }

    /// Rewrite `inst.var[k]` in `p` to the element's name; with `all`, `inst.var[*]` stays
    /// (the connection expands it). Returns false after reporting an error.
    fn path(&mut self, p: &mut ast::Path, all: bool) -> bool {
        if p.segments.len() < 2 {
            return true;
        }
        let inst = p.segments[0].name.name.clone();
        let seg = &mut p.segments[1];
        let Some(len) = self.array_len(&inst, &seg.name.name) else {
            if self.insts.contains_key(&inst) && seg.index.is_some() {
                let at = match &seg.index {
                    Some(ast::Index::At(e)) => e.span(),
                    Some(ast::Index::All(s)) => *s,
                    None => p.span,
                };
                self.ck.sink.push(
                    Diagnostic::error(
                        "E0185",
                        format!("`{inst}.{}` is not an array", seg.name.name),
                        at,
                    )
                    .with_label("index of a scalar")
                    .with_hint("remove the index"),
                );
                return false;
            }
            return true;
        };
        let name = seg.name.name.clone();
        match &seg.index {
            None => {
                self.ck.sink.push(
                    Diagnostic::error(
                        "E0189",
                        format!("`{inst}.{name}` is an array: name one element"),
                        seg.name.span,
                    )
                    .with_label("an array, not one variable")
                    .with_hint(if all {
                        format!("write `{inst}.{name}[0]` for one element, or `{inst}.{name}[*]` for each")
                    } else {
                        format!("write `{inst}.{name}[0]` … `{inst}.{name}[{}]`", len - 1)
                    }),
                );
                false
            }
            Some(ast::Index::All(at)) if !all => {
                self.ck.sink.push(
                    Diagnostic::error("E0189", format!("`{inst}.{name}[*]` is not a value"), *at)
                        .with_label("`[*]` is for connections")
                        .with_hint(format!("name one element: `{inst}.{name}[0]`")),
                );
                false
            }
            Some(ast::Index::All(_)) => true,
            Some(ast::Index::At(e)) => {
                let Some(k) = constant(self.ck, e) else {
                    self.ck.sink.push(
                        Diagnostic::error(
                            "E0186",
                            format!("the index of `{inst}.{name}` is not a compile-time constant"),
                            e.span(),
                        )
                        .with_label("not a literal or constant")
                        .with_hint("a system names one element by a constant index"),
                    );
                    return false;
                };
                if k < 0 || k >= len as i64 {
                    self.ck.sink.push(
                        Diagnostic::error(
                            "E0185",
                            format!(
                                "index {k} is out of range: `{inst}.{name}` has {len} element{}",
                                if len == 1 { "" } else { "s" }
                            ),
                            e.span(),
                        )
                        .with_label(format!("must be within 0..{}", len - 1)),
                    );
                    return false;
                }
                seg.name.name = element(&name, k);
                seg.index = None;
                true
            }
        }
    }

    /// Where `p`'s `[*]` is and how many elements it stands for (after [`Paths::path`]);
    /// `Ok(None)` when the instance or variable is unknown (the system checker reports it),
    /// `Err` after reporting two `[*]`.
    fn star(&mut self, p: &ast::Path) -> Result<Option<(Star, usize)>, ()> {
        let (Some(first), Some(second)) = (p.segments.first(), p.segments.get(1)) else {
            return Ok(Some((Star::None, 0)));
        };
        let on_inst = matches!(first.index, Some(ast::Index::All(_)));
        let on_var = matches!(second.index, Some(ast::Index::All(_)));
        if on_inst && on_var {
            self.ck.sink.push(
                Diagnostic::error("E0188", "two `[*]` in one connection endpoint", p.span)
                    .with_label("an instance array and an array variable")
                    .with_hint("connect element by element along one of them"),
            );
            return Err(());
        }
        if on_var {
            let n = self.array_len(&first.name.name, &second.name.name);
            return Ok(n.map(|n| (Star::Var, n)));
        }
        if on_inst {
            // An unknown instance or a non-array is reported by the system checker.
            let n = self.insts.get(&first.name.name).and_then(|i| i.count);
            return Ok(n.map(|n| (Star::Instance, n)));
        }
        Ok(Some((Star::None, 0)))
    }

    /// `c` rewritten into `out`: element names, and one connection per element for `[*]`.
    fn connection(&mut self, mut c: ast::Connection, out: &mut Vec<ast::Connection>) {
        let ok_from = self.path(&mut c.from, true);
        let ok_to = self.path(&mut c.to, true);
        if !(ok_from && ok_to) {
            return;
        }
        let (Ok(from), Ok(to)) = (self.star(&c.from), self.star(&c.to)) else {
            return;
        };
        let (Some((fs, fl)), Some((ts, tl))) = (from, to) else {
            // An unknown instance the system checker reports as written.
            if self.star_free(&c) {
                out.push(c);
            }
            return;
        };
        match (fs, ts) {
            (Star::None, Star::None) | (Star::None, Star::Instance) => out.push(c),
            (Star::None, Star::Var) => {
                for k in 0..tl {
                    out.push(ast::Connection {
                        from: c.from.clone(),
                        to: at(&c.to, ts, k),
                        span: c.span,
                    });
                }
            }
            (_, Star::None) => {
                // (E0123 as before arrays: the connection checker's code for one sender.)
                self.ck.sink.push(
                    Diagnostic::error(
                        "E0123",
                        "`[*]` on the sending side needs `[*]` on the receiving side",
                        c.span,
                    )
                    .with_label(format!("{fl} outputs to one input"))
                    .with_hint("each input is connected once: connect element by element (`[*]` on both sides) or name one element (`[0]`)"),
                );
            }
            _ if fl != tl => {
                self.ck.sink.push(
                    Diagnostic::error(
                        "E0188",
                        format!("`[*]` connects {fl} elements to {tl}"),
                        c.span,
                    )
                    .with_label("lengths differ")
                    .with_secondary(c.from.span, format!("{fl} elements"))
                    .with_secondary(c.to.span, format!("{tl} elements"))
                    .with_hint("element by element needs two arrays of the same length"),
                );
            }
            _ => {
                for k in 0..fl {
                    out.push(ast::Connection {
                        from: at(&c.from, fs, k),
                        to: at(&c.to, ts, k),
                        span: c.span,
                    });
                }
            }
        }
    }

    /// Whether `c` has no `[*]` on its sending side (so the system checker may see it).
    fn star_free(&self, c: &ast::Connection) -> bool {
        !c.from
            .segments
            .iter()
            .any(|s| matches!(s.index, Some(ast::Index::All(_))))
    }
}

/// `p` with its `[*]` replaced by element `k`.
fn at(p: &ast::Path, star: Star, k: usize) -> ast::Path {
    let mut p = p.clone();
    match star {
        Star::Instance => {
            let span: Span = match &p.segments[0].index {
                Some(ast::Index::All(s)) => *s,
                _ => p.span,
            };
            p.segments[0].index = Some(ast::Index::At(Box::new(ast::Expr::Int(k as i64, span))));
        }
        Star::Var => {
            let seg = &mut p.segments[1];
            seg.name.name = element(&seg.name.name, k as i64);
            seg.index = None;
        }
        Star::None => {}
    }
    p
}

impl VisitMut for Paths<'_, '_, '_> {
    fn visit_expr(&mut self, e: &mut ast::Expr) {
        match e {
            ast::Expr::In(..) => {}
            ast::Expr::Path(p) => {
                if !self.path(p, false) {
                    *e = ast::Expr::Error(p.span);
                    return;
                }
                walk_expr(self, e);
            }
            _ => walk_expr(self, e),
        }
    }
}
