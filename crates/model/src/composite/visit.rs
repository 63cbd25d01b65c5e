//! Every instance path of a system's expressions, properties, assumptions and rates, visited
//! mutably (on the one AST walk, `statecheck_syntax::ast::visit_mut`): the flattening
//! rewrites each one through the hierarchy of components.

use statecheck_syntax::ast;
use statecheck_syntax::ast::visit_mut::{walk_path, VisitMut};

/// Calls `f` on every path that names an instance's variable, event or state (`a.x`,
/// `in(a.S)`, `storage.feeder.pos`), after rewriting the paths inside its indices.
pub(super) struct Paths<'f> {
    pub f: &'f mut dyn FnMut(&mut ast::Path),
}

impl VisitMut for Paths<'_> {
    fn visit_path(&mut self, p: &mut ast::Path) {
        walk_path(self, p);
        (self.f)(p);
    }
}

impl Paths<'_> {
    /// Every path of an expression.
    pub fn expr(&mut self, e: &mut ast::Expr) {
        self.visit_expr(e);
    }

    /// Every path of a property.
    pub fn property(&mut self, p: &mut ast::Property) {
        self.visit_property(p);
    }

    /// Every path of an observer chart: types, initial values, actions, guards, delays,
    /// choices and its properties.
    pub fn chart(&mut self, c: &mut ast::Chart) {
        self.visit_chart(c);
    }
}
