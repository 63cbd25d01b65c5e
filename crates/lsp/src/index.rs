//! A document's symbols and every occurrence of each, from its syntax tree.
//!
//! This is name lookup for the editor, not for the checker: it follows the language's
//! scoping (`docs/language.md`) closely enough to navigate — chart variables and events, states
//! (a target name is looked up among the children of the source's enclosing states, innermost
//! first, then anywhere in the chart), regions, junctions, constants, enums and their
//! literals, functions and their parameters, charts, systems, instances and their ports — and
//! never decides whether a model is valid (the checker's diagnostics do).

use statecheck_base::Span;
use statecheck_syntax::ast::{
    Block, Branch, Chart, Component, Delay, Expr, File, Index as Idx, Item, Path, PropertyKind,
    RequirementKind, StateBody, Stmt, System, Target, Trigger, TypeExpr, VarKind,
};

/// What a symbol is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SymKind {
    /// `const`
    Const,
    /// `enum`
    Enum,
    /// An enum literal.
    Variant,
    /// `fn`
    Fn,
    /// A function parameter or `let`.
    Param,
    /// `chart` (or an observer).
    Chart,
    /// `system`
    System,
    /// A variable (input, output or local).
    Var(VarKind),
    /// An event (input, output or local).
    Event(VarKind),
    /// A state.
    State,
    /// A parallel region.
    Region,
    /// A junction.
    Junction,
    /// An instance of a system.
    Instance,
    /// A property.
    Property,
}

/// One declared name.
#[derive(Clone, Debug)]
pub struct Symbol {
    /// The name.
    pub name: String,
    /// What it is.
    pub kind: SymKind,
    /// The name where it is declared.
    pub decl: Span,
    /// The whole declaration.
    pub full: Span,
    /// The enclosing symbol (chart, state, system, function), if any.
    pub parent: Option<usize>,
    /// For an instance: the chart it instantiates (by name).
    pub of_chart: Option<String>,
}

/// Every symbol and every occurrence (declarations included) of a document.
#[derive(Debug, Default)]
pub struct Index {
    /// Symbols in textual order of declaration.
    pub symbols: Vec<Symbol>,
    /// Occurrences: (span of the name, symbol).
    pub occurrences: Vec<(Span, usize)>,
}

impl Index {
    /// Index a parsed file.
    pub fn new(file: &File) -> Index {
        let mut b = Builder::default();
        b.declare_file(file);
        b.resolve_file(file);
        b.ix.occurrences.sort_by_key(|(s, _)| (s.start, s.end));
        b.ix
    }

    /// The occurrence at byte `offset` (touching its end counts), if any.
    pub fn at(&self, offset: u32) -> Option<(Span, usize)> {
        self.occurrences
            .iter()
            .find(|(s, _)| s.start <= offset && offset <= s.end)
            .copied()
    }

    /// Every occurrence of symbol `sym`, in textual order.
    pub fn occurrences_of(&self, sym: usize) -> Vec<Span> {
        self.occurrences
            .iter()
            .filter(|(_, s)| *s == sym)
            .map(|(sp, _)| *sp)
            .collect()
    }

    /// The chart whose declaration contains `offset`, if any.
    pub fn chart_at(&self, offset: u32) -> Option<usize> {
        self.symbols.iter().position(|s| {
            s.kind == SymKind::Chart && s.full.start <= offset && offset <= s.full.end
        })
    }

    /// True if `sym` is (transitively) inside `ancestor`.
    pub fn is_inside(&self, sym: usize, ancestor: usize) -> bool {
        let mut cur = self.symbols.get(sym).and_then(|s| s.parent);
        let mut steps = 0;
        while let Some(p) = cur {
            if p == ancestor {
                return true;
            }
            steps += 1;
            if steps > self.symbols.len() {
                return false;
            }
            cur = self.symbols.get(p).and_then(|s| s.parent);
        }
        false
    }
}

#[derive(Default)]
struct Builder {
    ix: Index,
}

impl Builder {
    fn add(
        &mut self,
        name: &str,
        kind: SymKind,
        decl: Span,
        full: Span,
        parent: Option<usize>,
    ) -> usize {
        self.ix.symbols.push(Symbol {
            name: name.to_string(),
            kind,
            decl,
            full,
            parent,
            of_chart: None,
        });
        let id = self.ix.symbols.len() - 1;
        self.ix.occurrences.push((decl, id));
        id
    }

    fn declare_file(&mut self, file: &File) {
        for item in &file.items {
            match item {
                Item::Const(c) => {
                    self.add(&c.name.name, SymKind::Const, c.name.span, c.span, None);
                }
                Item::Enum(e) => {
                    let id = self.add(&e.name.name, SymKind::Enum, e.name.span, e.span, None);
                    for v in &e.variants {
                        self.add(&v.name, SymKind::Variant, v.span, v.span, Some(id));
                    }
                }
                Item::Fn(f) => {
                    let id = self.add(&f.name.name, SymKind::Fn, f.name.span, f.span, None);
                    for p in &f.params {
                        self.add(
                            &p.name.name,
                            SymKind::Param,
                            p.name.span,
                            p.name.span.to(p.ty.span()),
                            Some(id),
                        );
                    }
                    for (x, e) in &f.lets {
                        self.add(
                            &x.name,
                            SymKind::Param,
                            x.span,
                            x.span.to(e.span()),
                            Some(id),
                        );
                    }
                }
                Item::Chart(c) => self.declare_chart(c, None),
                Item::System(s) | Item::Component(Component { body: s, .. }) => {
                    let id = self.add(&s.name.name, SymKind::System, s.name.span, s.span, None);
                    for i in &s.instances {
                        let iid = self.add(
                            &i.name.name,
                            SymKind::Instance,
                            i.name.span,
                            i.span,
                            Some(id),
                        );
                        self.ix.symbols[iid].of_chart = Some(i.chart.name.clone());
                    }
                    for o in &s.observers {
                        self.declare_chart(o, Some(id));
                    }
                    for p in &s.properties {
                        self.add(
                            &p.name.name,
                            SymKind::Property,
                            p.name.span,
                            p.span,
                            Some(id),
                        );
                    }
                }
                // Interfaces are not navigable yet (docs/components.md).
                Item::Tick(_) | Item::Import(_) | Item::Interface(_) => {}
            }
        }
    }

    fn declare_chart(&mut self, c: &Chart, parent: Option<usize>) {
        let id = self.add(&c.name.name, SymKind::Chart, c.name.span, c.span, parent);
        for p in &c.params {
            self.add(&p.name.name, SymKind::Param, p.name.span, p.span, Some(id));
        }
        for v in &c.vars {
            let kind = if v.is_event {
                SymKind::Event(v.kind)
            } else {
                SymKind::Var(v.kind)
            };
            self.add(&v.name.name, kind, v.name.span, v.span, Some(id));
        }
        for p in &c.properties {
            self.add(
                &p.name.name,
                SymKind::Property,
                p.name.span,
                p.span,
                Some(id),
            );
        }
        self.declare_body(&c.body, id);
    }

    fn declare_body(&mut self, body: &StateBody, parent: usize) {
        for s in &body.states {
            let id = self.add(
                &s.name.name,
                SymKind::State,
                s.name.span,
                s.span,
                Some(parent),
            );
            self.declare_body(&s.body, id);
        }
        for r in &body.regions {
            let id = self.add(
                &r.name.name,
                SymKind::Region,
                r.name.span,
                r.span,
                Some(parent),
            );
            self.declare_body(&r.body, id);
        }
        for j in &body.junctions {
            self.add(
                &j.name.name,
                SymKind::Junction,
                j.name.span,
                j.span,
                Some(parent),
            );
        }
    }

    // ----- lookup -------------------------------------------------------------------------

    /// A global (top-level) symbol by name and kind filter.
    fn global(&self, name: &str, ok: fn(SymKind) -> bool) -> Option<usize> {
        self.ix.symbols.iter().position(|s| {
            s.name == name && ok(s.kind) && (s.parent.is_none() || s.kind == SymKind::Variant)
        })
    }

    fn child_of(&self, parent: usize, name: &str, ok: fn(SymKind) -> bool) -> Option<usize> {
        self.ix
            .symbols
            .iter()
            .position(|s| s.parent == Some(parent) && s.name == name && ok(s.kind))
    }

    /// A state-like name seen from `scope` (a state or the chart): children of `scope`, then
    /// of its ancestors up to the chart, then anywhere in the chart.
    fn state_from(&self, chart: usize, scope: usize, name: &str) -> Option<usize> {
        let state_like =
            |k: SymKind| matches!(k, SymKind::State | SymKind::Region | SymKind::Junction);
        let mut cur = Some(scope);
        let mut steps = 0;
        while let Some(c) = cur {
            if let Some(s) = self.child_of(c, name, state_like) {
                return Some(s);
            }
            if c == chart || steps > self.ix.symbols.len() {
                break;
            }
            steps += 1;
            cur = self.ix.symbols[c].parent;
        }
        (0..self.ix.symbols.len()).find(|&i| {
            let s = &self.ix.symbols[i];
            s.name == name && state_like(s.kind) && self.ix.is_inside(i, chart)
        })
    }

    fn chart_named(&self, name: &str) -> Option<usize> {
        self.ix
            .symbols
            .iter()
            .position(|s| s.name == name && s.kind == SymKind::Chart)
    }

    fn hit(&mut self, span: Span, sym: Option<usize>) {
        if let Some(s) = sym {
            self.ix.occurrences.push((span, s));
        }
    }

    // ----- resolution ---------------------------------------------------------------------

    fn resolve_file(&mut self, file: &File) {
        for item in &file.items {
            match item {
                Item::Const(c) => {
                    if let Some(t) = &c.ty {
                        self.ty(t, None);
                    }
                    self.expr(&c.value, &Ctx::default());
                }
                // Components are declared (navigable by name) but their bodies not resolved yet.
                Item::Enum(_)
                | Item::Tick(_)
                | Item::Import(_)
                | Item::Interface(_)
                | Item::Component(_) => {}
                Item::Fn(f) => {
                    let id = self.global(&f.name.name, |k| k == SymKind::Fn);
                    let cx = Ctx {
                        func: id,
                        ..Ctx::default()
                    };
                    for p in &f.params {
                        self.ty(&p.ty, None);
                    }
                    self.ty(&f.ret, None);
                    for (_, e) in &f.lets {
                        self.expr(e, &cx);
                    }
                    self.expr(&f.body, &cx);
                }
                Item::Chart(c) => {
                    let id = self.chart_named(&c.name.name);
                    self.chart(c, id);
                }
                Item::System(s) => self.system(s),
            }
        }
    }

    fn chart(&mut self, c: &Chart, id: Option<usize>) {
        let Some(id) = id else { return };
        let cx = Ctx {
            chart: Some(id),
            scope: Some(id),
            ..Ctx::default()
        };
        for v in &c.vars {
            if let Some(t) = &v.ty {
                self.ty(t, Some(id));
            }
            if let Some(e) = &v.init {
                self.expr(e, &cx);
            }
        }
        for p in &c.properties {
            self.property(&p.kind, &cx);
        }
        self.body(&c.body, &cx);
    }

    fn body(&mut self, body: &StateBody, cx: &Ctx) {
        let Some(scope) = cx.scope else { return };
        for b in body.entry.iter().chain(&body.during).chain(&body.exit) {
            self.block(b, cx);
        }
        for i in &body.initial {
            let s = self.child_of(scope, &i.target.name, |k| {
                matches!(k, SymKind::State | SymKind::Junction)
            });
            self.hit(i.target.span, s);
            if let Some(b) = &i.action {
                self.block(b, cx);
            }
        }
        for t in &body.transitions {
            match &t.trigger {
                Some(Trigger::Event(e)) => {
                    let s = self.var(cx, &e.name);
                    self.hit(e.span, s);
                }
                Some(Trigger::After { delay, .. }) => match delay {
                    Delay::Ticks(e) => self.expr(e, cx),
                    Delay::Time(d) => self.expr(&d.amount, cx),
                },
                None => {}
            }
            if let Some(g) = &t.guard {
                self.expr(g, cx);
            }
            if let Some(b) = &t.action {
                self.block(b, cx);
            }
            if let Some(tg) = &t.target {
                self.target(tg, cx);
            }
        }
        for j in &body.junctions {
            self.branches(&j.branches, cx);
        }
        for s in &body.states {
            let id = self.child_of(scope, &s.name.name, |k| k == SymKind::State);
            let inner = Ctx {
                scope: id,
                ..cx.clone()
            };
            self.body(&s.body, &inner);
        }
        for r in &body.regions {
            let id = self.child_of(scope, &r.name.name, |k| k == SymKind::Region);
            let inner = Ctx {
                scope: id,
                ..cx.clone()
            };
            self.body(&r.body, &inner);
        }
    }

    fn branches(&mut self, bs: &[Branch], cx: &Ctx) {
        for b in bs {
            if let Some(g) = &b.guard {
                self.expr(g, cx);
            }
            if let Some(a) = &b.action {
                self.block(a, cx);
            }
            self.target(&b.target, cx);
        }
    }

    fn target(&mut self, t: &Target, cx: &Ctx) {
        match t {
            Target::Path(p) => self.state_path(p, cx),
            Target::Choice { branches, .. } => self.branches(branches, cx),
        }
    }

    /// A dotted state path (`A.B`) seen from the context's state.
    fn state_path(&mut self, p: &Path, cx: &Ctx) {
        let (Some(chart), Some(scope)) = (cx.chart, cx.scope) else {
            return;
        };
        let mut cur: Option<usize> = None;
        for (i, seg) in p.segments.iter().enumerate() {
            let s = if i == 0 {
                self.state_from(chart, scope, &seg.name.name)
            } else {
                cur.and_then(|c| {
                    self.child_of(c, &seg.name.name, |k| {
                        matches!(k, SymKind::State | SymKind::Region | SymKind::Junction)
                    })
                })
            };
            self.hit(seg.name.span, s);
            cur = s;
        }
    }

    fn block(&mut self, b: &Block, cx: &Ctx) {
        for s in &b.stmts {
            match s {
                Stmt::Assign {
                    target,
                    index,
                    value,
                    ..
                } => {
                    let v = self.var(cx, &target.name);
                    self.hit(target.span, v);
                    if let Some(i) = index {
                        self.expr(i, cx);
                    }
                    // `x += e` repeats the target with its span: counted once.
                    if let Expr::Binary(_, l, r, _) = value {
                        if matches!(&**l, Expr::Path(p) if p.span == target.span) {
                            self.expr(r, cx);
                            continue;
                        }
                    }
                    self.expr(value, cx);
                }
                Stmt::Raise { event, .. } => {
                    let v = self.var(cx, &event.name);
                    self.hit(event.span, v);
                }
                Stmt::If {
                    cond,
                    then,
                    otherwise,
                    ..
                } => {
                    self.expr(cond, cx);
                    self.block(then, cx);
                    if let Some(o) = otherwise {
                        self.block(o, cx);
                    }
                }
                Stmt::For { lo, hi, body, .. } => {
                    self.expr(lo, cx);
                    self.expr(hi, cx);
                    self.block(body, cx);
                }
            }
        }
    }

    fn var(&self, cx: &Ctx, name: &str) -> Option<usize> {
        let chart = cx.chart?;
        self.child_of(chart, name, |k| {
            matches!(k, SymKind::Var(_) | SymKind::Event(_))
        })
    }

    fn ty(&mut self, t: &TypeExpr, chart: Option<usize>) {
        match t {
            TypeExpr::Named(n) => {
                let s = self.global(&n.name, |k| k == SymKind::Enum);
                self.hit(n.span, s);
            }
            TypeExpr::Range { lo, hi, .. } => {
                let cx = Ctx {
                    chart,
                    ..Ctx::default()
                };
                self.expr(lo, &cx);
                self.expr(hi, &cx);
            }
            _ => {}
        }
    }

    fn property(&mut self, k: &PropertyKind, cx: &Ctx) {
        match k {
            PropertyKind::Invariant { expr, assuming } => {
                self.expr(expr, cx);
                if let Some(a) = assuming {
                    self.expr(a, cx);
                }
            }
            PropertyKind::Reachable { expr } => self.expr(expr, cx),
            PropertyKind::Respond {
                trigger,
                response,
                within,
            } => {
                self.expr(trigger, cx);
                self.expr(response, cx);
                match within {
                    Delay::Ticks(e) => self.expr(e, cx),
                    Delay::Time(d) => self.expr(&d.amount, cx),
                }
            }
            PropertyKind::RespondEventually { trigger, response } => {
                self.expr(trigger, cx);
                self.expr(response, cx);
            }
            PropertyKind::Ltl { formula } | PropertyKind::Ctl { formula } => {
                self.formula(formula, cx)
            }
            PropertyKind::Nonblocking { expr } => self.expr(expr, cx),
            PropertyKind::Fair { trigger, expr } => {
                if let Some(t) = trigger {
                    self.expr(t, cx);
                }
                self.expr(expr, cx);
            }
        }
    }

    /// The atoms of a temporal formula (an explicit stack: formulas may be deep).
    fn formula(&mut self, f: &statecheck_syntax::ast::Formula, cx: &Ctx) {
        use statecheck_syntax::ast::Formula;
        let mut stack = vec![f];
        while let Some(f) = stack.pop() {
            match f {
                Formula::Atom(e) => self.expr(e, cx),
                Formula::Not(a, _) | Formula::Unary(_, a, _) => stack.push(a),
                Formula::And(a, b, _)
                | Formula::Or(a, b, _)
                | Formula::Implies(a, b, _)
                | Formula::Binary(_, a, b, _)
                | Formula::QuantUntil(_, a, b, _) => {
                    stack.push(b);
                    stack.push(a);
                }
            }
        }
    }

    fn expr(&mut self, e: &Expr, cx: &Ctx) {
        // An explicit stack: expressions may be hundreds of operators deep.
        let mut stack = vec![e];
        while let Some(e) = stack.pop() {
            match e {
                Expr::Int(..) | Expr::Bool(..) | Expr::Error(_) => {}
                Expr::Path(p) => self.value_path(p, cx),
                Expr::In(p, _) => {
                    if cx.chart.is_some() {
                        self.state_path(
                            p,
                            &Ctx {
                                scope: cx.chart,
                                ..cx.clone()
                            },
                        );
                    } else {
                        self.instance_path(p, cx, true);
                    }
                }
                Expr::Call { func, args, .. } => {
                    let s = self.global(&func.name, |k| k == SymKind::Fn);
                    self.hit(func.span, s);
                    stack.extend(args.iter());
                }
                Expr::Unary(_, x, _) => stack.push(x),
                Expr::Binary(_, l, r, _) => {
                    stack.push(r);
                    stack.push(l);
                }
                Expr::If(c, a, b, _) => {
                    stack.push(b);
                    stack.push(a);
                    stack.push(c);
                }
            }
        }
    }

    /// A name or dotted path used as a value.
    fn value_path(&mut self, p: &Path, cx: &Ctx) {
        let Some(first) = p.segments.first() else {
            return;
        };
        let name = &first.name.name;
        for seg in &p.segments {
            if let Some(Idx::At(e)) = &seg.index {
                self.expr(e, cx);
            }
        }
        if let Some(f) = cx.func {
            if let Some(s) = self.child_of(f, name, |k| k == SymKind::Param) {
                self.hit(first.name.span, Some(s));
                return;
            }
        }
        if let Some(s) = self.var(cx, name) {
            self.hit(first.name.span, Some(s));
            return;
        }
        if cx.system.is_some() {
            self.instance_path(p, cx, false);
            return;
        }
        if let Some(s) = self.global(name, |k| matches!(k, SymKind::Const | SymKind::Variant)) {
            self.hit(first.name.span, Some(s));
            return;
        }
        if let Some(e) = self.global(name, |k| k == SymKind::Enum) {
            self.hit(first.name.span, Some(e));
            if let Some(v) = p.segments.get(1) {
                let s = self.child_of(e, &v.name.name, |k| k == SymKind::Variant);
                self.hit(v.name.span, s);
            }
        }
    }

    /// `inst.port` or `inst.State.Sub` in a system.
    fn instance_path(&mut self, p: &Path, cx: &Ctx, states: bool) {
        let Some(sys) = cx.system else { return };
        let Some(first) = p.segments.first() else {
            return;
        };
        let inst = self.child_of(sys, &first.name.name, |k| k == SymKind::Instance);
        if inst.is_none() {
            if let Some(s) = self.global(&first.name.name, |k| {
                matches!(k, SymKind::Const | SymKind::Variant)
            }) {
                self.hit(first.name.span, Some(s));
            }
            return;
        }
        self.hit(first.name.span, inst);
        let chart = inst
            .and_then(|i| self.ix.symbols[i].of_chart.clone())
            .and_then(|c| self.chart_named(&c));
        let Some(chart) = chart else { return };
        let mut cur = chart;
        for seg in &p.segments[1..] {
            let s = if states {
                self.child_of(cur, &seg.name.name, |k| {
                    matches!(k, SymKind::State | SymKind::Region | SymKind::Junction)
                })
            } else {
                self.child_of(cur, &seg.name.name, |k| {
                    matches!(k, SymKind::Var(_) | SymKind::Event(_))
                })
            };
            self.hit(seg.name.span, s);
            match s {
                Some(s) => cur = s,
                None => break,
            }
        }
    }

    fn system(&mut self, s: &System) {
        let Some(id) = self.global(&s.name.name, |k| k == SymKind::System) else {
            return;
        };
        let cx = Ctx {
            system: Some(id),
            ..Ctx::default()
        };
        for i in &s.instances {
            let c = self.chart_named(&i.chart.name);
            self.hit(i.chart.span, c);
            if let Some(n) = &i.count {
                self.expr(n, &cx);
            }
        }
        for c in &s.connections {
            self.instance_path(&c.from, &cx, false);
            self.instance_path(&c.to, &cx, false);
        }
        for o in &s.order {
            for i in &o.instances {
                let s = self.child_of(id, &i.name, |k| k == SymKind::Instance);
                self.hit(i.span, s);
            }
        }
        for a in &s.assumes {
            self.expr(&a.expr, &cx);
        }
        for p in &s.properties {
            self.property(&p.kind, &cx);
        }
        for r in &s.requirements {
            match &r.kind {
                RequirementKind::Never(e) => self.expr(e, &cx),
                RequirementKind::Needs { cond, .. } => self.expr(cond, &cx),
            }
        }
        for o in &s.observers {
            let oid = self.child_of(id, &o.name.name, |k| k == SymKind::Chart);
            if let Some(oid) = oid {
                let ocx = Ctx {
                    chart: Some(oid),
                    scope: Some(oid),
                    system: Some(id),
                    func: None,
                };
                for v in &o.vars {
                    if let Some(e) = &v.init {
                        self.expr(e, &ocx);
                    }
                }
                for p in &o.properties {
                    self.property(&p.kind, &ocx);
                }
                self.body(&o.body, &ocx);
            }
        }
    }
}

/// Where a name is looked up.
#[derive(Clone, Default)]
struct Ctx {
    chart: Option<usize>,
    /// The state (or chart) whose body is being read.
    scope: Option<usize>,
    system: Option<usize>,
    func: Option<usize>,
}
