//! Name resolution: paths to variables, constants, enum literals, instance elements and
//! states, with "did you mean" suggestions.

use super::{error_expr, ExprChecker};
use crate::model::{Expr, ExprKind, StateRef, VarRef};
use crate::scope::Scope;
use crate::types::Type;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast;

impl<'g> ExprChecker<'g> {
    pub(super) fn check_path(&mut self, scope: &Scope, p: &ast::Path) -> Expr {
        let span = p.span;
        let segs = &p.segments;
        let first = &segs[0];
        if segs.len() == 1 && first.index.is_none() {
            let name = first.name.name.as_str();
            if let Some((_, e)) = scope.locals.iter().rev().find(|(n, _)| n == name) {
                let mut e = e.clone();
                e.span = span;
                return e;
            }
            if let Some(v) = scope.own_var(name) {
                let chart = scope.chart.expect("own_var implies a chart");
                return Expr {
                    kind: ExprKind::Var(VarRef {
                        instance: None,
                        var: v,
                    }),
                    ty: chart.vars[v as usize].ty,
                    span,
                };
            }
            if let Some((ty, v, _)) = self.globals.consts.get(name) {
                return Expr {
                    kind: ExprKind::Const(*v),
                    ty: if ty.is_int() {
                        Type::Int { lo: *v, hi: *v }
                    } else {
                        *ty
                    },
                    span,
                };
            }
            if let Some(owners) = self.globals.literal_owners.get(name) {
                if owners.len() == 1 {
                    let e = owners[0];
                    let idx = self.globals.enums[e as usize]
                        .variants
                        .iter()
                        .position(|v| v == name)
                        .unwrap_or(0);
                    return Expr {
                        kind: ExprKind::Const(idx as i64),
                        ty: Type::Enum(e),
                        span,
                    };
                }
                let names: Vec<String> = owners
                    .iter()
                    .map(|e| format!("{}.{name}", self.globals.enums[*e as usize].name))
                    .collect();
                self.sink.push(
                    Diagnostic::error("E0101", format!("ambiguous enum literal `{name}`"), span)
                        .with_label("several enums declare it")
                        .with_hint(format!("qualify it: {}", names.join(" or "))),
                );
                return error_expr(span);
            }
        }
        // `Enum.LITERAL`
        if segs.len() == 2 && first.index.is_none() && segs[1].index.is_none() {
            if let Some(&e) = self.globals.enum_ids.get(&first.name.name) {
                let lit = &segs[1].name.name;
                if let Some(idx) = self.globals.enums[e as usize]
                    .variants
                    .iter()
                    .position(|v| v == lit)
                {
                    return Expr {
                        kind: ExprKind::Const(idx as i64),
                        ty: Type::Enum(e),
                        span,
                    };
                }
                self.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!("enum `{}` has no literal `{lit}`", first.name.name),
                        segs[1].name.span,
                    )
                    .with_label("unknown literal")
                    .with_hint(format!(
                        "its literals are {}",
                        self.globals.enums[e as usize].variants.join(", ")
                    )),
                );
                return error_expr(span);
            }
        }
        // `inst.var` / `inst[i].var` in a system scope.
        if let Some(groups) = scope.instances {
            if let Some(g) = groups.get(&first.name.name) {
                if let Some(inst) = self.instance_index(scope, g, first) {
                    let chart = &scope.charts[g.chart as usize];
                    if segs.len() == 2 && segs[1].index.is_none() {
                        let vname = &segs[1].name.name;
                        if let Some(v) = chart.var(vname) {
                            return Expr {
                                kind: ExprKind::Var(VarRef {
                                    instance: Some(inst),
                                    var: v,
                                }),
                                ty: chart.vars[v as usize].ty,
                                span,
                            };
                        }
                        let mut d = Diagnostic::error(
                            "E0101",
                            format!("chart `{}` has no variable `{vname}`", chart.name),
                            segs[1].name.span,
                        )
                        .with_label("unknown variable");
                        if chart.state_by_path(vname).is_some() {
                            d = d.with_hint(format!(
                                "`{vname}` is a state: test it with `in({}.{vname})`",
                                first.name.name
                            ));
                        } else if let Some(c) = crate::suggest::closest(
                            vname,
                            chart.vars.iter().map(|v| v.name.as_str()),
                        ) {
                            d = d.with_hint(format!("did you mean `{c}`?"));
                        }
                        self.sink.push(d);
                        return error_expr(span);
                    }
                    self.sink.push(
                        Diagnostic::error("E0101", "expected `instance.variable`", span)
                            .with_hint("use `in(instance.state)` to test a state"),
                    );
                    return error_expr(span);
                }
                return error_expr(span);
            }
        }
        let name = &first.name.name;
        if segs.len() == 1 {
            if let Some(decl) = self.globals.declared_consts.get(name) {
                self.sink.push(
                    Diagnostic::error("E0101", format!("constant `{name}` is used before its declaration"), first.name.span)
                        .with_label("not declared yet")
                        .with_secondary(*decl, "declared here")
                        .with_hint(format!("move `const {name}` above this use: a constant sees only the constants declared before it")),
                );
                return error_expr(span);
            }
        }
        let mut d = Diagnostic::error("E0101", format!("unknown name `{name}`"), first.name.span)
            .with_label("not found in this scope");
        if let Some(s) = self.suggest(scope, name) {
            d = d.with_hint(format!("did you mean `{s}`?"));
        }
        self.sink.push(d);
        error_expr(span)
    }

    pub(super) fn suggest(&self, scope: &Scope, name: &str) -> Option<String> {
        let mut cands: Vec<String> = Vec::new();
        if let Some(c) = scope.chart {
            cands.extend(c.vars.iter().map(|v| v.name.clone()));
        }
        cands.extend(self.globals.consts.keys().cloned());
        cands.extend(self.globals.literal_owners.keys().cloned());
        cands.extend(scope.locals.iter().map(|(n, _)| n.clone()));
        if let Some(g) = scope.instances {
            cands.extend(g.keys().cloned());
        }
        crate::suggest::closest(name, cands.iter().map(String::as_str))
    }

    /// The flat instance index of `fam` / `fam[2]`, reporting index errors.
    pub(super) fn instance_index(
        &mut self,
        scope: &Scope,
        g: &crate::scope::InstanceGroup,
        seg: &ast::PathSegment,
    ) -> Option<u32> {
        match (&seg.index, g.len) {
            (None, None) => Some(g.first),
            (Some(ast::Index::At(e)), Some(len)) => {
                let i = self.const_value(scope, e)?;
                if i < 0 || i >= len as i64 {
                    self.sink.push(
                        Diagnostic::error(
                            "E0104",
                            format!(
                                "index {i} out of range for `{}` (length {len})",
                                seg.name.name
                            ),
                            e.span(),
                        )
                        .with_label(format!("must be within 0..{}", len - 1)),
                    );
                    return None;
                }
                Some(g.first + i as u32)
            }
            (None, Some(len)) => {
                self.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!("`{}` is an array of {len} instances", seg.name.name),
                        seg.name.span,
                    )
                    .with_label("needs an index")
                    .with_hint(format!("write `{}[0]`", seg.name.name)),
                );
                None
            }
            (Some(ast::Index::All(span)), _) => {
                self.sink.push(
                    Diagnostic::error("E0101", "`[*]` is only allowed in `connect`", *span)
                        .with_label("not allowed here"),
                );
                None
            }
            (Some(ast::Index::At(e)), None) => {
                self.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!("`{}` is not an instance array", seg.name.name),
                        e.span(),
                    )
                    .with_label("remove the index"),
                );
                None
            }
        }
    }

    /// Resolve `in(path)`: a state of this chart (from its root), or `inst.path` in a system.
    pub fn resolve_state(&mut self, scope: &Scope, p: &ast::Path) -> Option<StateRef> {
        let names: Vec<&str> = p.segments.iter().map(|s| s.name.name.as_str()).collect();
        if let Some(chart) = scope.chart {
            if p.segments.iter().all(|s| s.index.is_none()) {
                if let Some(s) = Scope::state_in(chart, &names) {
                    return Some(StateRef {
                        instance: None,
                        state: s,
                    });
                }
            }
        }
        if let Some(groups) = scope.instances {
            if let Some(g) = groups.get(names[0]) {
                let inst = self.instance_index(scope, g, &p.segments[0])?;
                let chart = &scope.charts[g.chart as usize];
                if let Some(s) = Scope::state_in(chart, &names[1..]) {
                    return Some(StateRef {
                        instance: Some(inst),
                        state: s,
                    });
                }
                self.sink.push(
                    Diagnostic::error(
                        "E0101",
                        format!(
                            "chart `{}` has no state `{}`",
                            chart.name,
                            names[1..].join(".")
                        ),
                        p.span,
                    )
                    .with_label("unknown state")
                    .with_hint(
                        "state paths start at the chart's top level, e.g. `in(inst.Go.Pause)`",
                    ),
                );
                return None;
            }
        }
        let mut d = Diagnostic::error(
            "E0101",
            format!("unknown state `{}`", names.join(".")),
            p.span,
        )
        .with_label("no such state")
        .with_hint("state paths start at the chart's top level, e.g. `in(Go.Pause)`");
        if let Some(chart) = scope.chart {
            let paths = chart.states.iter().map(|s| s.path.as_str());
            if let Some(s) = crate::suggest::closest(&names.join("."), paths) {
                d = d.with_hint(format!("did you mean `in({s})`?"));
            }
        }
        self.sink.push(d);
        None
    }
}
