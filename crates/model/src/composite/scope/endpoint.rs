//! A connection endpoint inside a component that names neither an instance nor a port of the
//! component: reported where it is written, with a suggestion among the component's names.

use super::Flattener;
use statecheck_base::Diagnostic;
use statecheck_syntax::ast;

impl Flattener<'_, '_> {
    /// Whether a connection endpoint inside a component starts with a name the component
    /// declares (an instance or a port); otherwise E0101 with a suggestion among those names,
    /// once per span however many times the component is instantiated. The system's own
    /// endpoints are left to the system checker, which suggests among the system's instances.
    pub(super) fn endpoint_declared(&mut self, id: usize, path: &ast::Path) -> bool {
        let (Some(c), Some(first)) = (self.scopes[id].comp, path.segments.first()) else {
            return true;
        };
        let name = &first.name.name;
        // The component's text, not the scope: an instance cut from the scope (a component
        // cycle, E0170; past the instance limit, E0173) is already reported.
        let declared = c.body.instances.iter().any(|i| i.name.name == *name);
        if declared || super::port(c, name).is_some() {
            return true;
        }
        let span = first.name.span;
        // The diagnostics added since the last call, then a set lookup: scanning them all for
        // each copy of the component was copies × diagnostics (5 s on a 6 KB file whose
        // component with a bad endpoint is flattened thousands of times).
        let from = if self.scanned > self.diags.len() {
            0
        } else {
            self.scanned
        };
        for d in &self.diags[from..] {
            if d.code == "E0101" {
                self.unknown_spans.insert(d.span);
            }
        }
        self.scanned = self.diags.len();
        if self.unknown_spans.contains(&span) {
            return false;
        }
        let candidates = c
            .ports
            .iter()
            .map(|p| p.name.name.as_str())
            .chain(c.body.instances.iter().map(|i| i.name.name.as_str()));
        let mut d = Diagnostic::error(
            "E0101",
            format!("unknown instance `{name}` in component `{}`", c.name.name),
            span,
        )
        .with_label("no instance or port of this name")
        .with_secondary(c.name.span, "component declared here");
        if let Some(n) = crate::suggest::closest(name, candidates) {
            d = d.with_hint(format!("did you mean `{n}`?"));
        }
        self.diags.push(d);
        false
    }
}
