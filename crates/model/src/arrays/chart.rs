//! One chart's arrays: declarations split into elements, loops unrolled, constant indices
//! turned into element names.

use super::{constant, element, MAX_LEN, MAX_UNROLLED};
use crate::expr::ExprChecker;
use crate::params::{Literal, Subst};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;
use statecheck_syntax::ast::visit_mut::{walk_expr, VisitMut};
use std::collections::{HashMap, HashSet};

/// Expand `c` in place; returns its array variables and their lengths. `quiet` (a copy with
/// placeholder parameter values): lengths below 1 become 1 and indices out of range name
/// element 0, so nothing spurious is reported later.
pub(super) fn expand(
    c: &mut ast::Chart,
    quiet: bool,
    ck: &mut ExprChecker<'_>,
) -> HashMap<String, usize> {
    let mut arrays = HashMap::new();
    let mut vars = Vec::with_capacity(c.vars.len());
    for v in std::mem::take(&mut c.vars) {
        let Some(len) = &v.len else {
            vars.push(v);
            continue;
        };
        let n = match constant(ck, len) {
            Some(n) if (1..=MAX_LEN).contains(&n) => n,
            _ if quiet => 1,
            Some(n) => {
                ck.sink.push(
                    Diagnostic::error(
                        "E0184",
                        format!("array `{}` has length {n}", v.name.name),
                        len.span(),
                    )
                    .with_label(format!("must be within 1..{MAX_LEN}"))
                    .with_hint("an array of variables has at least one element"),
                );
                continue;
            }
            None => {
                ck.sink.push(
                    Diagnostic::error(
                        "E0184",
                        format!("the length of array `{}` is not a constant", v.name.name),
                        len.span(),
                    )
                    .with_label("not a compile-time constant")
                    .with_hint(
                        "use literals, constants and the chart's parameters: `input rm[N]: …;` in `chart Bus(N: int[1..8])`",
                    ),
                );
                continue;
            }
        };
        arrays.insert(v.name.name.clone(), n as usize);
        for k in 0..n {
            let mut e = v.clone();
            e.len = None;
            e.name.name = element(&v.name.name, k);
            vars.push(e);
        }
    }
    c.vars = vars;
    let names = c.vars.iter().map(|v| v.name.name.clone()).collect();
    let mut x = Expander {
        arrays: &arrays,
        names,
        loops: Vec::new(),
        emitted: 0,
        exhausted: false,
        quiet,
        reported: HashSet::new(),
        ck,
    };
    x.visit_chart(c);
    arrays
}

/// The rewrite of one chart (or observer).
pub(super) struct Expander<'a, 'c, 'g> {
    /// Array variables and their lengths.
    pub arrays: &'a HashMap<String, usize>,
    /// Every variable name (elements included), for loop variables that would hide one.
    pub names: HashSet<String>,
    /// The enclosing loops' variables.
    pub loops: Vec<String>,
    /// Statements produced by unrolling so far.
    pub emitted: u64,
    /// The unrolling budget was exceeded (reported once; later loops are dropped).
    pub exhausted: bool,
    /// A placeholder copy: indices out of range name element 0.
    pub quiet: bool,
    /// Loops already reported (a loop inside another is unrolled once per outer value).
    pub reported: HashSet<Span>,
    /// For constants and diagnostics.
    pub ck: &'c mut ExprChecker<'g>,
}

impl Expander<'_, '_, '_> {
    /// The element `name[index]` names, or `None` after reporting why none.
    fn index(&mut self, name: &ast::Ident, index: &ast::Expr, whole: Span) -> Option<String> {
        let Some(&len) = self.arrays.get(&name.name) else {
            self.ck.sink.push(
                Diagnostic::error(
                    "E0185",
                    format!("`{}` is not an array", name.name),
                    index.span(),
                )
                .with_label("index of a scalar")
                .with_hint(format!(
                    "declare it as an array, `output {}[N]: …;`, or remove the index",
                    name.name
                )),
            );
            return None;
        };
        let Some(k) = constant(self.ck, index) else {
            self.ck.sink.push(
                Diagnostic::error(
                    "E0186",
                    format!("the index of `{}` is not a compile-time constant", name.name),
                    index.span(),
                )
                .with_label("not a literal, constant, parameter or loop variable")
                .with_hint(format!(
                    "select the element with a loop: `for k in 0..{len} {{ if i == k {{ … {}[k] … }} }}`",
                    name.name
                )),
            );
            return None;
        };
        if k < 0 || k >= len as i64 {
            if self.quiet {
                return Some(element(&name.name, 0));
            }
            self.ck.sink.push(
                Diagnostic::error(
                    "E0185",
                    format!(
                        "index {k} is out of range: `{}` has {len} element{}",
                        name.name,
                        if len == 1 { "" } else { "s" }
                    ),
                    whole,
                )
                .with_label(format!("must be within 0..{}", len - 1)),
            );
            return None;
        }
        Some(element(&name.name, k))
    }

    /// E0189: an array named without an index.
    fn bare(&mut self, name: &ast::Ident) {
        let n = self.arrays.get(&name.name).copied().unwrap_or(1);
        self.ck.sink.push(
            Diagnostic::error(
                "E0189",
                format!("`{}` is an array: name one element", name.name),
                name.span,
            )
            .with_label("an array, not one variable")
            .with_hint(format!(
                "write `{0}[0]` … `{0}[{1}]`, or loop: `for k in 0..{n} {{ … {0}[k] … }}`",
                name.name,
                n.saturating_sub(1)
            )),
        );
    }

    /// Statements a body adds per iteration (loops inside counted once: they are checked
    /// again when they unroll).
    fn size(b: &ast::Block) -> u64 {
        b.stmts
            .iter()
            .map(|s| match s {
                ast::Stmt::If {
                    then, otherwise, ..
                } => 1 + Self::size(then) + otherwise.as_ref().map_or(0, Self::size),
                ast::Stmt::For { body, .. } => 1 + Self::size(body),
                _ => 1,
            })
            .sum()
    }

    /// `for var in lo..hi { body }` unrolled into `out`.
    fn unroll(&mut self, s: ast::Stmt, out: &mut Vec<ast::Stmt>) {
        let ast::Stmt::For {
            var,
            lo,
            hi,
            body,
            span,
        } = s
        else {
            return;
        };
        if self.exhausted {
            return;
        }
        let bad = |msg: String, at: Span, label: &str| {
            Diagnostic::error("E0187", msg, at).with_label(label.to_string())
        };
        let first = self.reported.insert(span);
        if self.loops.contains(&var.name)
            || self.names.contains(&var.name)
            || self.arrays.contains_key(&var.name)
        {
            let what = if self.loops.contains(&var.name) {
                "an enclosing loop's variable"
            } else {
                "a variable of the chart"
            };
            if !first {
                return;
            }
            self.ck.sink.push(
                bad(
                    format!("loop variable `{}` hides {what}", var.name),
                    var.span,
                    "rename the loop variable",
                )
                .with_hint("choose a name the chart does not use"),
            );
            return;
        }
        let (Some(a), Some(b)) = (constant(self.ck, &lo), constant(self.ck, &hi)) else {
            if !first {
                return;
            }
            self.ck.sink.push(
                bad(
                    "the bounds of a `for` loop must be compile-time constants".to_string(),
                    lo.span().to(hi.span()),
                    "not constant",
                )
                .with_hint(
                    "use literals, constants, the chart's parameters or an enclosing loop's variable",
                ),
            );
            return;
        };
        let iterations = b.saturating_sub(a).max(0) as u64;
        let cost = iterations.saturating_mul(Self::size(&body).max(1));
        if self.emitted.saturating_add(cost) > MAX_UNROLLED {
            self.exhausted = true;
            self.ck.sink.push(
                bad(
                    format!(
                        "loops unroll to more than {MAX_UNROLLED} statements in this chart (this one: {iterations} iterations)"
                    ),
                    span,
                    "too many iterations",
                )
                .with_hint("loops are unrolled before checking: keep them small"),
            );
            return;
        }
        for k in a..b.max(a) {
            let mut copy = body.clone();
            let mut subst = Subst {
                names: HashMap::from([(var.name.clone(), Literal::Int(k))]),
            };
            subst.visit_block(&mut copy);
            self.loops.push(var.name.clone());
            self.visit_block(&mut copy);
            self.loops.pop();
            out.extend(copy.stmts);
        }
    }
}

impl VisitMut for Expander<'_, '_, '_> {
    fn visit_block(&mut self, b: &mut ast::Block) {
        let mut out = Vec::with_capacity(b.stmts.len());
        for mut s in std::mem::take(&mut b.stmts) {
            match &mut s {
                ast::Stmt::For { .. } => {
                    self.unroll(s, &mut out);
                    continue;
                }
                ast::Stmt::Assign {
                    target,
                    index,
                    value,
                    ..
                } => {
                    match index.take() {
                        Some(i) => {
                            let mut i = *i;
                            self.visit_expr(&mut i);
                            let whole = target.span.to(i.span());
                            match self.index(target, &i, whole) {
                                Some(n) => target.name = n,
                                None => continue,
                            }
                        }
                        None if self.arrays.contains_key(&target.name) => {
                            self.bare(target);
                            continue;
                        }
                        None => {}
                    }
                    // `x[k] += e` repeats the target, indexed, as the left operand.
                    self.visit_expr(value);
                }
                ast::Stmt::If {
                    cond,
                    then,
                    otherwise,
                    ..
                } => {
                    self.visit_expr(cond);
                    self.visit_block(then);
                    if let Some(o) = otherwise {
                        self.visit_block(o);
                    }
                }
                ast::Stmt::Raise { .. } => {}
            }
            self.emitted += 1;
            out.push(s);
        }
        b.stmts = out;
    }

    fn visit_expr(&mut self, e: &mut ast::Expr) {
        match e {
            // A state path names states, not variables.
            ast::Expr::In(..) => {}
            ast::Expr::Path(p) if p.segments.len() == 1 => {
                let seg = &mut p.segments[0];
                match seg.index.take() {
                    Some(ast::Index::At(mut i)) => {
                        self.visit_expr(&mut i);
                        match self.index(&seg.name, &i, p.span) {
                            Some(n) => seg.name.name = n,
                            None => *e = ast::Expr::Error(p.span),
                        }
                    }
                    Some(ast::Index::All(at)) => {
                        self.ck.sink.push(
                            Diagnostic::error(
                                "E0189",
                                format!("`{}[*]` is not a value", seg.name.name),
                                at,
                            )
                            .with_label("`[*]` is for connections")
                            .with_hint("name one element, or loop over them with `for`"),
                        );
                        *e = ast::Expr::Error(p.span);
                    }
                    None if self.arrays.contains_key(&seg.name.name) => {
                        let name = seg.name.clone();
                        self.bare(&name);
                        *e = ast::Expr::Error(p.span);
                    }
                    None => {}
                }
            }
            _ => walk_expr(self, e),
        }
    }
}
