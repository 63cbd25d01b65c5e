//! Arrays of variables and compile-time loops (`docs/language.md` §5, §8, §14): compile-time
//! sugar expanded in the AST before checking, like parameters and components, so the checker,
//! the IR, the engines, the simulator and the code generators see only scalars.
//!
//! - `input rm[N]: RunMode = STOP_STALL;` declares `N` ordinary variables named `rm[0]` …
//!   `rm[N-1]` (the name with its index is the variable's name in traces, properties and
//!   scenarios). `N` is a constant expression; a chart's parameters are already values here.
//! - `for k in lo..hi { … }` is unrolled: the body once per value of `k`, with `k` replaced
//!   by the value (at most [`MAX_UNROLLED`] statements per chart).
//! - `rm[k]` in an expression or as an assignment target, with `k` a compile-time constant,
//!   becomes the element's name. A non-constant index is refused (E0186) with the loop that
//!   writes the selection out as a hint: a conditional chain would hide an out-of-range index.
//! - In systems, `connect` endpoints and paths into instances (`bus.rm[0]`) name elements;
//!   `[*]` on an array variable or an instance array on both sides connects element by
//!   element (`system.rs`).
//!
//! Codes: E0184 (bad array declaration), E0185 (index out of range or on a scalar), E0186
//! (index not constant), E0187 (bad loop), E0188 (connection lengths or shape), E0189 (array
//! without index).

mod chart;
mod system;

use crate::expr::ExprChecker;
use crate::scope::Scope;
use statecheck_syntax::ast;
use std::collections::HashMap;

/// The longest array of variables.
pub(crate) const MAX_LEN: i64 = 4096;
/// The most statements loops may unroll to in one chart (and the most iterations).
pub(crate) const MAX_UNROLLED: u64 = 65_536;

/// The arrays of each chart of the file: chart name → array variable → length.
pub(crate) type Arrays = HashMap<String, HashMap<String, usize>>;

/// The name of element `k` of array `name`: `rm[2]`.
pub(crate) fn element(name: &str, k: i64) -> String {
    format!("{name}[{k}]")
}

/// The value of a constant expression, or `None` (nothing reported: the caller says why).
pub(crate) fn constant(ck: &mut ExprChecker<'_>, e: &ast::Expr) -> Option<i64> {
    let empty = Scope::constants(usize::MAX);
    ck.sink.muted += 1;
    let v = ck.const_value(&empty, e);
    ck.sink.muted -= 1;
    v
}

/// E0184 for every array among the ports of components and the members of interfaces: a
/// port is one variable (an array port would need element-wise wiring through the
/// flattening; connect the inner instances' arrays instead).
pub(crate) fn refuse_port_arrays(file: &ast::File, diags: &mut Vec<statecheck_base::Diagnostic>) {
    let ports = file.items.iter().flat_map(|i| match i {
        ast::Item::Component(c) => c.ports.iter().map(|p| (p, "a component")).collect(),
        ast::Item::Interface(d) => d.members.iter().map(|p| (p, "an interface")).collect(),
        _ => Vec::new(),
    });
    for (p, what) in ports {
        if let Some(n) = &p.len {
            diags.push(
                statecheck_base::Diagnostic::error(
                    "E0184",
                    format!("port `{}` of {what} is an array", p.name.name),
                    n.span(),
                )
                .with_label("a port is one variable")
                .with_hint(
                    "declare one port per element, or wire the inner instances' arrays inside the component",
                ),
            );
        }
    }
}

/// Expand the arrays and loops of `file`; `placeholder[i]` says the `i`-th chart is a copy
/// with placeholder parameter values (checked for names and types only: its array problems
/// are not reported). `None` when the file uses none of them.
pub(crate) fn expand(
    file: &ast::File,
    placeholder: &dyn Fn(usize) -> bool,
    ck: &mut ExprChecker<'_>,
) -> Option<ast::File> {
    if !uses_arrays(file) {
        return None;
    }
    let mut out = file.clone();
    let mut arrays: Arrays = HashMap::new();
    let mut id = 0;
    for item in &mut out.items {
        if let ast::Item::Chart(c) = item {
            let quiet = placeholder(id);
            id += 1;
            if quiet {
                ck.sink.muted += 1;
            }
            let found = chart::expand(c, quiet, ck);
            if quiet {
                ck.sink.muted -= 1;
            }
            arrays.entry(c.name.name.clone()).or_insert(found);
        }
    }
    for item in &mut out.items {
        if let ast::Item::System(s) = item {
            for o in &mut s.observers {
                let found = chart::expand(o, false, ck);
                if !found.is_empty() {
                    arrays.insert(o.name.name.clone(), found);
                }
            }
            system::expand(s, &arrays, ck);
        }
    }
    Some(out)
}

/// Whether anything in `file` is an array declaration, an index after a variable, a loop,
/// or an indexed assignment (a cheap scan that keeps files without arrays untouched).
fn uses_arrays(file: &ast::File) -> bool {
    struct Scan(bool);
    impl ast::visit_mut::VisitMut for Scan {
        fn visit_var(&mut self, v: &mut ast::VarDecl) {
            self.0 |= v.len.is_some();
        }
        fn visit_block(&mut self, b: &mut ast::Block) {
            self.0 |= b.stmts.iter().any(|s| {
                matches!(
                    s,
                    ast::Stmt::For { .. } | ast::Stmt::Assign { index: Some(_), .. }
                )
            });
            ast::visit_mut::walk_block(self, b);
        }
        fn visit_path(&mut self, p: &mut ast::Path) {
            // An index after the first segment (`bus.rm[0]`) or on a lone name (`rm[0]`).
            self.0 |= p.segments.iter().skip(1).any(|s| s.index.is_some())
                || (p.segments.len() == 1 && p.segments[0].index.is_some());
        }
    }
    let mut scan = Scan(false);
    // The scan needs `&mut`; a clone per file is cheap next to checking it.
    let mut copy = file.clone();
    for item in &mut copy.items {
        match item {
            ast::Item::Chart(c) => scan.visit_chart(c),
            ast::Item::System(s) => {
                for c in &s.connections {
                    scan.0 |= c.from.segments.iter().skip(1).any(|s| s.index.is_some())
                        || c.to.segments.iter().skip(1).any(|s| s.index.is_some())
                        || c.from
                            .segments
                            .iter()
                            .any(|s| matches!(s.index, Some(ast::Index::All(_))));
                }
                for o in &mut s.observers {
                    scan.visit_chart(o);
                }
                for p in &mut s.properties {
                    scan.visit_property(p);
                }
                for a in &mut s.assumes {
                    scan.visit_expr(&mut a.expr);
                }
            }
            _ => {}
        }
        if scan.0 {
            return true;
        }
    }
    false
}

use ast::visit_mut::VisitMut as _;
