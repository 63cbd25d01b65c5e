//! Flattening one system: each component instance's scope (its names, where its ports lead),
//! connections rewired through ports, paths rewritten, the execution order spliced.

use super::visit::Paths;
use super::{PortLink, MAX_DEPTH, MAX_INSTANCES};
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast;
use std::collections::{HashMap, HashSet};

mod endpoint;

/// What a name declared in a scope denotes.
#[derive(Clone)]
enum Local {
    /// A chart instance (or array), by its full name in the flat system.
    Leaf(String),
    /// A component instance: the index of its scope.
    Composite(usize),
    /// An array of component instances: each element's scope.
    Array(Vec<usize>),
}

/// The scope of the system or of one component instance.
struct Scope<'a> {
    /// The component (`None` for the system itself).
    comp: Option<&'a ast::Component>,
    /// The instance's full name (`""` for the system).
    prefix: String,
    /// Its instances' names.
    names: HashMap<String, Local>,
    /// Component instances in declaration order.
    children: Vec<usize>,
    /// Each input port: the leaf inputs it feeds.
    inputs: HashMap<String, Vec<ast::Path>>,
    /// Each output port: the leaf output that drives it.
    outputs: HashMap<String, ast::Path>,
    /// Input ports connected from the enclosing scope.
    driven: HashSet<String>,
    /// Its leaf instances (groups) in execution order.
    order: Vec<ast::Ident>,
}

/// What a path names in a scope.
enum Res {
    /// A leaf instance's variable, event or state: the path rewritten to the flat name.
    Path(ast::Path),
    /// An input port of the scope's own component.
    InPort(String),
    /// An output port of the scope's own component.
    OutPort(String),
    /// An input port of a component instance in the scope.
    ChildIn(usize, String),
}

/// Flattens the systems of one file.
pub(super) struct Flattener<'a, 'd> {
    comps: &'a HashMap<&'a str, &'a ast::Component>,
    known: &'a HashSet<&'a str>,
    diags: &'d mut Vec<Diagnostic>,
    system: String,
    /// Port-to-variable wirings, for the type check after checking.
    pub links: Vec<PortLink>,
    scopes: Vec<Scope<'a>>,
    chain: Vec<String>,
    leaves: usize,
    out: ast::System,
    /// Spans with an E0101 among `diags[..scanned]` (`endpoint.rs`: one diagnostic per span
    /// however many copies of a component are flattened, found without rescanning `diags`).
    unknown_spans: HashSet<Span>,
    scanned: usize,
}

fn full(prefix: &str, name: &str) -> String {
    if prefix.is_empty() {
        name.to_string()
    } else {
        format!("{prefix}.{name}")
    }
}

fn port<'c>(c: &'c ast::Component, name: &str) -> Option<&'c ast::VarDecl> {
    c.ports.iter().find(|p| p.name.name == name)
}

impl<'a, 'd> Flattener<'a, 'd> {
    pub fn new(
        comps: &'a HashMap<&'a str, &'a ast::Component>,
        known: &'a HashSet<&'a str>,
        diags: &'d mut Vec<Diagnostic>,
        system: &str,
    ) -> Self {
        Flattener {
            comps,
            known,
            diags,
            system: system.to_string(),
            links: Vec::new(),
            scopes: Vec::new(),
            chain: Vec::new(),
            leaves: 0,
            unknown_spans: HashSet::new(),
            scanned: 0,
            out: ast::System {
                name: ast::Ident {
                    name: system.to_string(),
                    span: Span::default(),
                },
                instances: Vec::new(),
                connections: Vec::new(),
                order: Vec::new(),
                assumes: Vec::new(),
                rates: Vec::new(),
                properties: Vec::new(),
                observers: Vec::new(),
                requirements: Vec::new(),
                configurations: Vec::new(),
                interleaved: false,
                span: Span::default(),
            },
        }
    }

    /// The flat system of `s` (a component's body running alone when `comp` is given).
    pub fn system(&mut self, s: &'a ast::System, comp: Option<&'a ast::Component>) -> ast::System {
        if let Some(c) = comp {
            self.chain.push(c.name.name.clone());
        }
        let top = self.scope(s, comp, String::new());
        if comp.is_some() {
            self.fan_out(top);
        }
        let mut out = std::mem::replace(&mut self.out, Flattener::empty_system());
        out.name = s.name.clone();
        out.span = s.span;
        out.observers = s.observers.clone();
        out.requirements = s.requirements.clone();
        out.configurations = s.configurations.clone();
        out.interleaved = s.interleaved && comp.is_none();
        if comp.is_some() {
            out.observers.clear();
            out.requirements.clear();
            out.configurations.clear();
        }
        out.order = vec![ast::OrderDecl {
            instances: std::mem::take(&mut self.scopes[top].order),
            span: s.order.first().map_or(s.name.span, |o| o.span),
        }];
        // Observers read instances by path through the components, like the properties.
        for o in &mut out.observers {
            let mut paths: Vec<ast::Path> = Vec::new();
            let mut collect = |x: &mut ast::Path| paths.push(x.clone());
            Paths { f: &mut collect }.chart(o);
            let mut rewritten = paths.iter().map(|x| self.read(top, x)).collect::<Vec<_>>();
            rewritten.reverse();
            let mut put = |x: &mut ast::Path| {
                if let Some(Some(n)) = rewritten.pop() {
                    *x = n;
                }
            };
            Paths { f: &mut put }.chart(o);
        }
        for r in &mut out.requirements {
            let mut e = match &mut r.kind {
                ast::RequirementKind::Never(e) => e.clone(),
                ast::RequirementKind::Needs { cond, .. } => cond.clone(),
            };
            self.rewrite_expr(top, &mut e);
            match &mut r.kind {
                ast::RequirementKind::Never(x) => *x = e,
                ast::RequirementKind::Needs { cond, .. } => *cond = e,
            }
        }
        out
    }

    /// A system with nothing in it.
    pub fn empty_system() -> ast::System {
        ast::System {
            name: ast::Ident {
                name: String::new(),
                span: Span::default(),
            },
            instances: Vec::new(),
            connections: Vec::new(),
            order: Vec::new(),
            assumes: Vec::new(),
            rates: Vec::new(),
            properties: Vec::new(),
            observers: Vec::new(),
            requirements: Vec::new(),
            configurations: Vec::new(),
            interleaved: false,
            span: Span::default(),
        }
    }

    /// Flatten one scope: its instances (component instances recursively), connections,
    /// order, assumptions, rates and properties.
    fn scope(
        &mut self,
        body: &'a ast::System,
        comp: Option<&'a ast::Component>,
        prefix: String,
    ) -> usize {
        let id = self.scopes.len();
        self.scopes.push(Scope {
            comp,
            prefix: prefix.clone(),
            names: HashMap::new(),
            children: Vec::new(),
            inputs: HashMap::new(),
            outputs: HashMap::new(),
            driven: HashSet::new(),
            order: Vec::new(),
        });
        for inst in &body.instances {
            let name = full(&prefix, &inst.name.name);
            let local = if let Some(c) = self.comps.get(inst.chart.name.as_str()).copied() {
                self.diags.extend(super::renames::refuse_on_component(inst));
                match &inst.count {
                    // Its length is a literal by now (`params.rs`): elements `cells[0]`, ….
                    Some(ast::Expr::Int(n, _)) => {
                        let mut ids = Vec::new();
                        for k in 0..*n {
                            match self.child(inst, c, format!("{name}[{k}]")) {
                                Some(ch) => ids.push(ch),
                                None => break,
                            }
                        }
                        if ids.len() as i64 != *n {
                            continue;
                        }
                        self.scopes[id].children.extend(ids.iter().copied());
                        Local::Array(ids)
                    }
                    _ => match self.child(inst, c, name) {
                        Some(ch) => {
                            self.scopes[id].children.push(ch);
                            Local::Composite(ch)
                        }
                        None => continue,
                    },
                }
            } else {
                self.leaves += 1;
                if self.leaves == MAX_INSTANCES + 1 {
                    self.diags.push(
                        Diagnostic::error(
                            "E0173",
                            format!(
                                "system `{}` flattens to more than {MAX_INSTANCES} instances",
                                self.system
                            ),
                            inst.span,
                        )
                        .with_label("this instance is one too many"),
                    );
                }
                if self.leaves > MAX_INSTANCES {
                    continue;
                }
                let mut leaf = inst.clone();
                leaf.name.name = name.clone();
                self.out.instances.push(leaf);
                Local::Leaf(name)
            };
            let names = &mut self.scopes[id].names;
            if names.contains_key(&inst.name.name) {
                if matches!(local, Local::Composite(_) | Local::Array(_)) {
                    self.diags.push(
                        Diagnostic::error(
                            "E0102",
                            format!("instance `{}` is declared twice", inst.name.name),
                            inst.name.span,
                        )
                        .with_label("second declaration"),
                    );
                }
                continue;
            }
            names.insert(inst.name.name.clone(), local);
        }
        for c in &body.connections {
            self.connect(id, c);
        }
        if let Some(c) = comp {
            self.unconnected_ports(id, c);
        }
        for ch in self.scopes[id].children.clone() {
            self.fan_out(ch);
        }
        self.order(id, body);
        for a in &body.assumes {
            let mut a = a.clone();
            self.rewrite_expr(id, &mut a.expr);
            self.out.assumes.push(a);
        }
        for r in &body.rates {
            let mut r = r.clone();
            if let Some(p) = self.read(id, &r.target) {
                r.target = p;
            }
            self.out.rates.push(r);
        }
        for p in &body.properties {
            let mut p = p.clone();
            p.name.name = full(&prefix, &p.name.name);
            let mut paths: Vec<ast::Path> = Vec::new();
            let mut collect = |x: &mut ast::Path| paths.push(x.clone());
            Paths { f: &mut collect }.property(&mut p);
            let mut rewritten = paths.iter().map(|x| self.read(id, x)).collect::<Vec<_>>();
            rewritten.reverse();
            let mut put = |x: &mut ast::Path| {
                if let Some(Some(n)) = rewritten.pop() {
                    *x = n;
                }
            };
            Paths { f: &mut put }.property(&mut p);
            self.out.properties.push(p);
        }
        id
    }

    /// The scope of the component instance `inst` of `c` (or of one element of an array of
    /// them); `None` (reported) for recursion, nesting too deep and arguments.
    fn child(
        &mut self,
        inst: &'a ast::Instance,
        c: &'a ast::Component,
        name: String,
    ) -> Option<usize> {
        if let Some(count) = inst
            .count
            .as_ref()
            .filter(|n| !matches!(n, ast::Expr::Int(..)))
        {
            self.diags.push(
                Diagnostic::error(
                    "E0173",
                    format!("an array of component `{}` is not supported", c.name.name),
                    count.span(),
                )
                .with_label("component instances are single")
                .with_hint("declare one instance per element"),
            );
            return None;
        }
        if let Some(a) = inst.args.first() {
            self.diags.push(
                Diagnostic::error(
                    "E0173",
                    format!("component `{}` takes no arguments", c.name.name),
                    a.span,
                )
                .with_label("components have no parameters")
                .with_hint("give the arguments to the chart instances inside the component"),
            );
            return None;
        }
        if let Some(k) = self.chain.iter().position(|n| *n == c.name.name) {
            let mut cycle: Vec<&str> = self.chain[k..].iter().map(String::as_str).collect();
            cycle.push(&c.name.name);
            self.diags.push(
                Diagnostic::error(
                    "E0170",
                    format!(
                        "component `{}` contains itself: {}",
                        c.name.name,
                        cycle.join(" -> ")
                    ),
                    inst.chart.span,
                )
                .with_label("instantiated inside itself")
                .with_secondary(c.name.span, "component declared here")
                .with_hint("components nest finitely: break the cycle"),
            );
            return None;
        }
        // Components nested a few levels deep multiply: bound the instances visited, not
        // only the leaves kept, so that the flattening's time and memory stay bounded.
        // (The chart instances a system flattens to are counted before flattening, E0174;
        // this bounds component instances without any chart inside.)
        if self.scopes.len() >= MAX_INSTANCES {
            if self.leaves <= MAX_INSTANCES {
                self.leaves = MAX_INSTANCES + 1;
                self.diags.push(
                    Diagnostic::error(
                        "E0173",
                        format!(
                            "system `{}` flattens to more than {MAX_INSTANCES} instances",
                            self.system
                        ),
                        inst.span,
                    )
                    .with_label("this instance is one too many"),
                );
            }
            return None;
        }
        if self.chain.len() >= MAX_DEPTH {
            self.diags.push(
                Diagnostic::error(
                    "E0170",
                    format!("components nested deeper than {MAX_DEPTH} levels"),
                    inst.chart.span,
                )
                .with_label("too deep"),
            );
            return None;
        }
        self.chain.push(c.name.name.clone());
        let ch = self.scope(&c.body, Some(c), name);
        self.chain.pop();
        Some(ch)
    }

    /// E0171: an input port that feeds no inner instance, an output port no inner instance
    /// drives.
    fn unconnected_ports(&mut self, id: usize, c: &ast::Component) {
        for p in &c.ports {
            let s = &self.scopes[id];
            let (missing, hint) = match p.kind {
                ast::VarKind::Input => (
                    !s.inputs.contains_key(&p.name.name),
                    format!(
                        "connect it inside the component: `connect {} -> inst.port;`",
                        p.name.name
                    ),
                ),
                ast::VarKind::Output => (
                    !s.outputs.contains_key(&p.name.name),
                    format!(
                        "drive it inside the component: `connect inst.port -> {};`",
                        p.name.name
                    ),
                ),
                ast::VarKind::Local => continue,
            };
            if missing {
                let what = if p.kind == ast::VarKind::Input {
                    "feeds no inner instance"
                } else {
                    "is driven by no inner instance"
                };
                self.diags.push(
                    Diagnostic::error(
                        "E0171",
                        format!(
                            "port `{}` of component `{}` {what}",
                            p.name.name, c.name.name
                        ),
                        p.name.span,
                    )
                    .with_label("unconnected port")
                    .with_hint(hint),
                );
            }
        }
    }

    /// An input port not connected from outside that feeds several inner inputs: they all
    /// read the first one, which stays a free input (so they see one value, as the port).
    fn fan_out(&mut self, ch: usize) {
        let Some(c) = self.scopes[ch].comp else {
            return;
        };
        for p in &c.ports {
            if p.kind != ast::VarKind::Input || self.scopes[ch].driven.contains(&p.name.name) {
                continue;
            }
            let Some(dests) = self.scopes[ch].inputs.get(&p.name.name) else {
                continue;
            };
            if let [first, rest @ ..] = dests.as_slice() {
                for d in rest {
                    self.out.connections.push(ast::Connection {
                        from: first.clone(),
                        to: d.clone(),
                        span: p.span,
                    });
                }
            }
        }
    }

    /// The scope's leaf instances in execution order: its `order` (component instances
    /// spliced in their own order), else declaration order.
    fn order(&mut self, id: usize, body: &ast::System) {
        let mut order = Vec::new();
        let prefix = self.scopes[id].prefix.clone();
        let splice = |order: &mut Vec<ast::Ident>,
                      scopes: &[Scope<'_>],
                      local: &Local,
                      at: Span| {
            match local {
                Local::Leaf(n) => order.push(ast::Ident {
                    name: n.clone(),
                    span: at,
                }),
                Local::Composite(ch) => order.extend(scopes[*ch].order.iter().cloned()),
                Local::Array(ids) => {
                    for ch in ids {
                        order.extend(scopes[*ch].order.iter().cloned());
                    }
                }
            }
        };
        match body.order.as_slice() {
            [] => {
                for inst in &body.instances {
                    let known = self.known.contains(inst.chart.name.as_str())
                        || self.comps.contains_key(inst.chart.name.as_str());
                    if let (true, Some(l)) = (known, self.scopes[id].names.get(&inst.name.name)) {
                        splice(&mut order, &self.scopes, l, inst.name.span);
                    }
                }
            }
            [o, rest @ ..] => {
                if self.scopes[id].comp.is_some() {
                    for extra in rest {
                        self.diags.push(
                            Diagnostic::error(
                                "E0108",
                                "only one `order` declaration is allowed",
                                extra.span,
                            )
                            .with_secondary(o.span, "first one here"),
                        );
                    }
                }
                for n in &o.instances {
                    match self.scopes[id].names.get(&n.name) {
                        Some(l) => splice(&mut order, &self.scopes, l, n.span),
                        None => order.push(ast::Ident {
                            name: full(&prefix, &n.name),
                            span: n.span,
                        }),
                    }
                }
            }
        }
        self.scopes[id].order = order;
    }

    /// One connection of scope `id`: rewired through ports, or recorded as a port's wiring.
    fn connect(&mut self, id: usize, c: &ast::Connection) {
        if !self.endpoint_declared(id, &c.from) | !self.endpoint_declared(id, &c.to) {
            return;
        }
        let (Some(from), Some(to)) = (self.resolve(id, &c.from), self.resolve(id, &c.to)) else {
            return;
        };
        let comp_name = self.scopes[id]
            .comp
            .map_or(String::new(), |k| k.name.name.clone());
        enum Src {
            Path(ast::Path),
            Port(String),
        }
        let src = match from {
            Res::Path(p) => Src::Path(p),
            Res::InPort(a) => Src::Port(a),
            Res::ChildIn(ch, x) => match self.scopes[ch].inputs.get(&x).and_then(|d| d.first()) {
                Some(p) => Src::Path(p.clone()),
                None => return,
            },
            Res::OutPort(o) => {
                self.diags.push(
                    Diagnostic::error(
                        "E0172",
                        format!("output port `{o}` of component `{comp_name}` is read inside it"),
                        c.from.span,
                    )
                    .with_label("an output port is a destination inside its component")
                    .with_hint("connect from the inner instance that drives the port"),
                );
                return;
            }
        };
        let dests = match to {
            Res::Path(p) => vec![p],
            Res::ChildIn(ch, x) => {
                self.scopes[ch].driven.insert(x.clone());
                self.scopes[ch].inputs.get(&x).cloned().unwrap_or_default()
            }
            Res::InPort(a) => {
                self.diags.push(
                    Diagnostic::error(
                        "E0172",
                        format!("input port `{a}` of component `{comp_name}` is written inside it"),
                        c.to.span,
                    )
                    .with_label("an input port is a source inside its component")
                    .with_hint(format!(
                        "write `connect {a} -> inst.port;` to feed an inner instance"
                    )),
                );
                return;
            }
            Res::OutPort(o) => {
                let p = match src {
                    Src::Path(p) => p,
                    Src::Port(a) => {
                        self.diags.push(
                            Diagnostic::error(
                                "E0172",
                                format!("input port `{a}` connected straight to output port `{o}`"),
                                c.span,
                            )
                            .with_label("a port must lead to an instance")
                            .with_hint("connect both ports to an inner instance's ports"),
                        );
                        return;
                    }
                };
                if self.scopes[id].outputs.contains_key(&o) {
                    self.diags.push(
                        Diagnostic::error(
                            "E0172",
                            format!("output port `{o}` of component `{comp_name}` is driven twice"),
                            c.span,
                        )
                        .with_label("second driver"),
                    );
                    return;
                }
                self.link(id, &o, &p, c.span);
                self.scopes[id].outputs.insert(o, p);
                return;
            }
        };
        match src {
            Src::Port(a) => {
                for d in &dests {
                    self.link(id, &a, d, c.span);
                }
                self.scopes[id].inputs.entry(a).or_default().extend(dests);
            }
            Src::Path(p) => {
                for d in dests {
                    self.out.connections.push(ast::Connection {
                        from: p.clone(),
                        to: d,
                        span: c.span,
                    });
                }
            }
        }
    }

    fn link(&mut self, id: usize, port_name: &str, leaf: &ast::Path, at: Span) {
        let Some(c) = self.scopes[id].comp else {
            return;
        };
        let (Some(p), [inst, var]) = (port(c, port_name), leaf.segments.as_slice()) else {
            return;
        };
        self.links.push(PortLink {
            system: self.system.clone(),
            component: c.name.name.clone(),
            port: p.clone(),
            instance: inst.name.name.clone(),
            // An array element (`cyl.x[2]`) by the name it has once arrays are expanded.
            var: match &var.index {
                Some(ast::Index::At(e)) => match **e {
                    ast::Expr::Int(k, _) => crate::arrays::element(&var.name.name, k),
                    _ => var.name.name.clone(),
                },
                _ => var.name.name.clone(),
            },
            at,
        });
    }

    /// The path a read of `path` in scope `id` becomes (ports read through to the inner
    /// variable); `None` when it stays as written or was reported.
    fn read(&mut self, id: usize, path: &ast::Path) -> Option<ast::Path> {
        let p = match self.resolve(id, path)? {
            Res::Path(p) => p,
            Res::InPort(a) => self.scopes[id].inputs.get(&a)?.first()?.clone(),
            Res::OutPort(o) => self.scopes[id].outputs.get(&o)?.clone(),
            Res::ChildIn(ch, x) => self.scopes[ch].inputs.get(&x)?.first()?.clone(),
        };
        Some(ast::Path {
            span: path.span,
            ..p
        })
    }

    fn rewrite_expr(&mut self, id: usize, e: &mut ast::Expr) {
        let mut paths: Vec<ast::Path> = Vec::new();
        let mut collect = |x: &mut ast::Path| paths.push(x.clone());
        Paths { f: &mut collect }.expr(e);
        let mut rewritten = paths.iter().map(|x| self.read(id, x)).collect::<Vec<_>>();
        rewritten.reverse();
        let mut put = |x: &mut ast::Path| {
            if let Some(Some(n)) = rewritten.pop() {
                *x = n;
            }
        };
        Paths { f: &mut put }.expr(e);
    }

    /// What `path` names in scope `id`; `None` after a reported error. A path whose first
    /// name the scope does not declare is returned unchanged (a constant, an enum literal,
    /// or an unknown name the checker reports).
    fn resolve(&mut self, id: usize, path: &ast::Path) -> Option<Res> {
        let segs = &path.segments;
        let first = segs.first()?;
        if let Some(c) = self.scopes[id].comp {
            if let Some(p) = port(c, &first.name.name) {
                if segs.len() > 1 || first.index.is_some() {
                    self.diags.push(
                        Diagnostic::error(
                            "E0172",
                            format!("port `{}` has no members", p.name.name),
                            path.span,
                        )
                        .with_label("a port is one variable or event"),
                    );
                    return None;
                }
                return match p.kind {
                    ast::VarKind::Input => Some(Res::InPort(p.name.name.clone())),
                    ast::VarKind::Output => Some(Res::OutPort(p.name.name.clone())),
                    ast::VarKind::Local => None,
                };
            }
        }
        match self.scopes[id].names.get(&first.name.name).cloned() {
            None => Some(Res::Path(path.clone())),
            Some(Local::Leaf(n)) => {
                let mut p = path.clone();
                p.segments[0].name.name = n;
                Some(Res::Path(p))
            }
            Some(Local::Composite(ch)) => self.through(ch, path),
            Some(Local::Array(ids)) => {
                let (ch, rest) = self.element(&ids, path)?;
                self.through(ch, &rest)
            }
        }
    }

    /// The element of a component array that `path` (starting `cells[1]`) names, and the
    /// path with the index dropped; `None` after E0176 (no index, `[*]`, not a literal, out
    /// of range).
    fn element(&mut self, ids: &[usize], path: &ast::Path) -> Option<(usize, ast::Path)> {
        let seg = path.segments.first()?;
        let bad = |msg: String, label: &str, span| {
            Diagnostic::error("E0176", msg, span)
                .with_label(label.to_string())
                .with_hint(format!(
                    "name one element: `{}[0]` … `{}[{}]`",
                    seg.name.name,
                    seg.name.name,
                    ids.len().saturating_sub(1)
                ))
        };
        let d = match &seg.index {
            None => bad(
                format!("`{}` is an array of components: index it", seg.name.name),
                "an array, not one component",
                path.span,
            ),
            Some(ast::Index::All(_)) => bad(
                format!("`{}[*]`: an array of components is named one element at a time", seg.name.name),
                "`[*]` is for chart instance arrays",
                path.span,
            ),
            Some(ast::Index::At(e)) => match **e {
                ast::Expr::Int(k, _) if k >= 0 && (k as usize) < ids.len() => {
                    let mut rest = path.clone();
                    rest.segments[0].index = None;
                    return Some((ids[k as usize], rest));
                }
                ast::Expr::Int(k, _) => bad(
                    format!(
                        "index {k} is out of range: `{}` has {} elements",
                        seg.name.name,
                        ids.len()
                    ),
                    "out of range",
                    path.span,
                ),
                _ => bad(
                    format!(
                        "the index of the component array `{}` must be an integer literal (or a parameter)",
                        seg.name.name
                    ),
                    "not a literal",
                    path.span,
                ),
            },
        };
        self.diags.push(d);
        None
    }

    /// A path that starts with the component instance of scope `ch`.
    fn through(&mut self, ch: usize, path: &ast::Path) -> Option<Res> {
        let segs = &path.segments;
        let c = self.scopes[ch].comp?;
        let bad = |msg: String, label: &str| {
            Diagnostic::error("E0172", msg, path.span).with_label(label.to_string())
        };
        if segs[0].index.is_some() {
            let d = bad(
                format!(
                    "`{}` is a component instance, not an array",
                    segs[0].name.name
                ),
                "no index here",
            );
            self.diags.push(d);
            return None;
        }
        let Some(next) = segs.get(1) else {
            let d = bad(
                format!(
                    "`{}` is an instance of component `{}`: name one of its ports",
                    segs[0].name.name, c.name.name
                ),
                "a component instance, not a port",
            );
            self.diags.push(d);
            return None;
        };
        if let Some(p) = port(c, &next.name.name) {
            if segs.len() > 2 || next.index.is_some() {
                let d = bad(
                    format!("port `{}` has no members", p.name.name),
                    "a port is one variable or event",
                );
                self.diags.push(d);
                return None;
            }
            return match p.kind {
                ast::VarKind::Input => Some(Res::ChildIn(ch, p.name.name.clone())),
                ast::VarKind::Output => {
                    let src = self.scopes[ch].outputs.get(&p.name.name)?.clone();
                    Some(Res::Path(ast::Path {
                        span: path.span,
                        ..src
                    }))
                }
                ast::VarKind::Local => None,
            };
        }
        let rest = ast::Path {
            segments: segs[1..].to_vec(),
            span: path.span,
        };
        match self.scopes[ch].names.get(&next.name.name).cloned() {
            Some(Local::Leaf(n)) => {
                let mut p = rest;
                p.segments[0].name.name = n;
                Some(Res::Path(p))
            }
            Some(Local::Composite(g)) => self.through(g, &rest),
            Some(Local::Array(ids)) => {
                let (g, rest) = self.element(&ids, &rest)?;
                self.through(g, &rest)
            }
            None => {
                let names = c
                    .ports
                    .iter()
                    .map(|p| p.name.name.as_str())
                    .chain(c.body.instances.iter().map(|i| i.name.name.as_str()));
                let mut d = Diagnostic::error(
                    "E0172",
                    format!(
                        "component `{}` has no port or instance `{}`",
                        c.name.name, next.name.name
                    ),
                    next.name.span,
                )
                .with_label("not a port of the component")
                .with_secondary(c.name.span, "component declared here");
                if let Some(n) = crate::suggest::closest(&next.name.name, names) {
                    d = d.with_hint(format!("did you mean `{n}`?"));
                }
                self.diags.push(d);
                None
            }
        }
    }
}
