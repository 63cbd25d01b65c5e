//! Top-level items, charts, systems, declarations and properties.

use super::{Printer, WIDTH};
use crate::ast::{
    BinOp, Chart, Control, Expr, File, FnDecl, Formula, Item, Property, PropertyKind, Quant,
    RequirementKind, System, VarDecl, VarKind,
};
use statecheck_base::Span;

/// One element of a system, for printing in textual order.
enum SysMember<'t> {
    Line(Span, String),
    Assume(&'t crate::ast::Assume),
    Property(&'t Property),
    Observer(&'t Chart),
    Config(&'t crate::ast::Configuration),
}

impl Printer<'_> {
    /// The whole file; ends with exactly one newline (nothing for an empty file without
    /// comments).
    pub(super) fn file(&mut self, file: &File) {
        let mut prev_big = false;
        for (i, item) in file.items.iter().enumerate() {
            let big = match item {
                Item::Chart(_) | Item::System(_) | Item::Component(_) => true,
                Item::Fn(f) => !f.lets.is_empty(),
                _ => false,
            };
            if i > 0 && (big || prev_big) {
                self.force_blank = true;
            }
            self.item(item);
            self.at_block_start = false;
            prev_big = big;
        }
        let end = self.src.len() as u32 + 1;
        self.comments_before(end);
        if self.out.is_empty() {
            return;
        }
        while self.out.ends_with("\n\n") {
            self.out.pop();
        }
    }

    fn item(&mut self, item: &Item) {
        match item {
            Item::Import(i) => {
                let names = i.names.as_ref().map(|ns| {
                    let ns: Vec<&str> = ns.iter().map(|n| n.name.as_str()).collect();
                    format!(" {{ {} }}", ns.join(", "))
                });
                let text = format!("import \"{}\"{};", i.path, names.unwrap_or_default());
                self.line(i.span, &text);
            }
            Item::Const(c) => {
                let ty =
                    c.ty.as_ref()
                        .map(|t| format!(": {}", self.ty(t)))
                        .unwrap_or_default();
                let head = format!("const {}{ty} =", c.name.name);
                self.line_expr(c.span, &head, &c.value, ";");
            }
            Item::Enum(e) => {
                let names: Vec<&str> = e.variants.iter().map(|v| v.name.as_str()).collect();
                let one = format!("enum {} {{ {} }}", e.name.name, names.join(", "));
                let inside = Span {
                    start: self.lbrace_after(e.name.span.end),
                    end: e.span.end,
                };
                if one.len() <= WIDTH && !self.has_comment_in(inside) {
                    self.line(e.span, &one);
                } else {
                    // One variant per line, each keeping the comments around it.
                    self.comments_before(e.name.span.end);
                    self.start_line(e.span.start);
                    self.out.push_str(&format!("enum {} {{", e.name.name));
                    let brace = self.lbrace_after(e.name.span.end);
                    self.open(brace);
                    for v in &e.variants {
                        let end = self
                            .tok_after(v.span.end)
                            .filter(|t| t.kind == crate::lexer::Tok::Comma)
                            .map_or(v.span.end, |t| t.span.end);
                        self.line(
                            Span {
                                start: v.span.start,
                                end,
                            },
                            &format!("{},", v.name),
                        );
                    }
                    self.close(e.span.end, "", e.span.end);
                }
            }
            Item::Fn(f) => self.fn_decl(f),
            Item::Tick(t) => {
                let text = format!("tick {};", self.duration(&t.duration));
                self.line(t.span, &text);
            }
            Item::Chart(c) => self.chart(c),
            Item::System(s) => self.system(s),
            Item::Component(c) => self.component(c),
            Item::Interface(i) => {
                self.comments_before(i.name.span.end);
                self.start_line(i.span.start);
                self.out.push_str(&format!("interface {} {{", i.name.name));
                let brace = self.lbrace_after(i.name.span.end);
                self.open(brace);
                for m in &i.members {
                    let t = self.var_decl(m);
                    self.line(m.span, &t);
                }
                self.close(i.span.end, "", i.span.end);
            }
        }
    }

    /// `configuration NAME { inst = Chart(args); … }`, one binding per line.
    fn configuration(&mut self, c: &crate::ast::Configuration) {
        self.comments_before(c.name.span.end);
        self.start_line(c.span.start);
        self.out
            .push_str(&format!("configuration {} {{", c.name.name));
        let brace = self.lbrace_after(c.name.span.end);
        self.open(brace);
        for b in &c.bindings {
            let t = format!(
                "{} = {}{};",
                b.instance.name,
                b.chart.name,
                self.args(&b.args)
            );
            self.line(b.span, &t);
        }
        self.close(c.span.end, "", c.span.end);
    }

    /// `(a, name = b)`, or nothing without arguments.
    fn args(&self, args: &[crate::ast::Arg]) -> String {
        if args.is_empty() {
            return String::new();
        }
        let a: Vec<String> = args
            .iter()
            .map(|a| match &a.name {
                Some(n) => format!("{} = {}", n.name, self.expr(&a.value)),
                None => self.expr(&a.value),
            })
            .collect();
        format!("({})", a.join(", "))
    }

    fn fn_decl(&mut self, f: &FnDecl) {
        let params: Vec<String> = f
            .params
            .iter()
            .map(|p| format!("{}: {}", p.name.name, self.ty(&p.ty)))
            .collect();
        let head = format!(
            "fn {}({}) -> {}",
            f.name.name,
            params.join(", "),
            self.ty(&f.ret)
        );
        if f.lets.is_empty() {
            self.line_expr(f.span, &format!("{head} ="), &f.body, ";");
            return;
        }
        // Comments in the head move before the function.
        let first = f.lets.first().map_or(f.span.end, |(x, _)| x.span.start);
        self.comments_before(first.min(self.lbrace_after(f.ret.span().end)));
        self.start_line(f.span.start);
        self.out.push_str(&head);
        self.out.push_str(" {");
        let brace = self.lbrace_after(f.ret.span().end);
        self.open(brace);
        for (x, e) in &f.lets {
            let start = self
                .tok_before(x.span.start)
                .map_or(x.span.start, |t| t.span.start);
            let end = self.semi_after(e.span().end);
            self.line_expr(Span { start, end }, &format!("let {} =", x.name), e, ";");
        }
        // The `return` keyword: the last one before the expression (which may start with `(`).
        let body_start = f.body.span().start;
        let upto = self.toks.partition_point(|t| t.span.end <= body_start);
        let start = self.toks[..upto]
            .iter()
            .rev()
            .find(|t| t.kind == crate::lexer::Tok::Kw(crate::lexer::Kw::Return))
            .map_or(body_start, |t| t.span.start);
        let end = self.semi_after(f.body.span().end);
        self.line_expr(Span { start, end }, "return", &f.body, ";");
        self.close(f.span.end, "", f.span.end);
    }

    /// A chart (`role` is `plant`, `requirement`, or `observer` inside a system).
    fn chart(&mut self, c: &Chart) {
        let mut head = match &c.role {
            Some(r) if r.name == "observer" => format!("observer {}", c.name.name),
            Some(r) => format!("{} chart {}", r.name, c.name.name),
            None => format!("chart {}", c.name.name),
        };
        head.push_str(&self.params(&c.params));
        if !c.implements.is_empty() {
            let names: Vec<&str> = c.implements.iter().map(|i| i.name.as_str()).collect();
            head.push_str(&format!(" implements {}", names.join(", ")));
        }
        let ms = self.members(&c.body, &c.vars, &c.properties, true);
        self.comments_before(c.name.span.start);
        self.start_line(c.span.start);
        self.out.push_str(&head);
        self.out.push_str(" {");
        let head_end = match (c.implements.last(), c.params.last()) {
            (Some(i), _) => i.span.end,
            (None, Some(p)) => p.span.end,
            (None, None) => c.name.span.end,
        };
        let brace = self.lbrace_after(head_end);
        self.open(brace);
        self.print_members(&ms);
        self.close(c.span.end, "", c.span.end);
    }

    fn system(&mut self, s: &System) {
        let mut head = format!("system {}", s.name.name);
        if s.interleaved {
            head.push_str(" interleaved");
        }
        self.system_like(s, &head, &[]);
    }

    /// `(p: T [= default], …)` of a chart or component; empty without parameters.
    fn params(&mut self, params: &[crate::ast::ChartParam]) -> String {
        if params.is_empty() {
            return String::new();
        }
        let ps: Vec<String> = params
            .iter()
            .map(|p| {
                let default = p
                    .default
                    .as_ref()
                    .map(|e| format!(" = {}", self.expr(e)))
                    .unwrap_or_default();
                format!("{}: {}{default}", p.name.name, self.ty(&p.ty))
            })
            .collect();
        format!("({})", ps.join(", "))
    }

    /// `component NAME[(params)] [implements I, …] { ports; members }`.
    fn component(&mut self, c: &crate::ast::Component) {
        let mut head = format!("component {}", c.name.name);
        head.push_str(&self.params(&c.params));
        if !c.implements.is_empty() {
            let names: Vec<&str> = c.implements.iter().map(|i| i.name.as_str()).collect();
            head.push_str(&format!(" implements {}", names.join(", ")));
        }
        self.system_like(&c.body, &head, &c.ports);
    }

    /// A system or component body (`ports` only for a component), members in textual order.
    fn system_like(&mut self, s: &System, head: &str, ports: &[VarDecl]) {
        let mut ms: Vec<(u32, SysMember<'_>)> = Vec::new();
        for p in ports {
            let t = self.var_decl(p);
            ms.push((p.span.start, SysMember::Line(p.span, t)));
        }
        for i in &s.instances {
            let count = i
                .count
                .as_ref()
                .map(|e| format!("[{}]", self.expr(e)))
                .unwrap_or_default();
            let args = self.args(&i.args);
            let end = if i.renames.is_empty() {
                ";".to_string()
            } else {
                let rs: Vec<String> = i
                    .renames
                    .iter()
                    .map(|r| format!("{} -> {};", r.event.name, r.to.name))
                    .collect();
                format!(" {{ {} }}", rs.join(" "))
            };
            let t = format!(
                "instance {}{count}: {}{args}{end}",
                i.name.name, i.chart.name
            );
            ms.push((i.span.start, SysMember::Line(i.span, t)));
        }
        for c in &s.connections {
            let t = format!("connect {} -> {};", self.path(&c.from), self.path(&c.to));
            ms.push((c.span.start, SysMember::Line(c.span, t)));
        }
        for o in &s.order {
            let names: Vec<&str> = o.instances.iter().map(|i| i.name.as_str()).collect();
            let t = format!("order {};", names.join(", "));
            ms.push((o.span.start, SysMember::Line(o.span, t)));
        }
        for a in &s.assumes {
            ms.push((a.span.start, SysMember::Assume(a)));
        }
        for r in &s.rates {
            let t = format!("rate {} = {};", self.path(&r.target), r.value);
            ms.push((r.span.start, SysMember::Line(r.span, t)));
        }
        for p in &s.properties {
            ms.push((p.span.start, SysMember::Property(p)));
        }
        for r in &s.requirements {
            let t = match &r.kind {
                RequirementKind::Never(e) => format!("requirement never ({});", self.expr(e)),
                RequirementKind::Needs { event, cond } => {
                    format!("requirement {} needs ({});", event.name, self.expr(cond))
                }
            };
            ms.push((r.span.start, SysMember::Line(r.span, t)));
        }
        for o in &s.observers {
            ms.push((o.span.start, SysMember::Observer(o)));
        }
        for c in &s.configurations {
            ms.push((c.span.start, SysMember::Config(c)));
        }
        ms.sort_by_key(|(k, _)| *k);
        self.comments_before(s.name.span.start);
        self.start_line(s.span.start);
        self.out.push_str(&format!("{head} {{"));
        let brace = self.lbrace_after(s.name.span.end);
        self.open(brace);
        for (_, m) in &ms {
            match m {
                SysMember::Line(span, t) => self.line(*span, t),
                SysMember::Assume(a) => self.line_expr(a.span, "assume", &a.expr, ";"),
                SysMember::Property(p) => self.property_line(p),
                SysMember::Observer(c) => self.chart(c),
                SysMember::Config(c) => self.configuration(c),
            }
        }
        self.close(s.span.end, "", s.span.end);
    }

    /// A variable or event declaration as one line.
    pub(super) fn var_decl(&self, v: &VarDecl) -> String {
        if let Some(c) = v.control {
            let kw = match c {
                Control::Controllable => "controllable",
                Control::Uncontrollable => "uncontrollable",
            };
            return format!("{kw} event {};", v.name.name);
        }
        let kind = match v.kind {
            VarKind::Input => "input",
            VarKind::Output => "output",
            VarKind::Local => "local",
        };
        if v.is_event {
            return format!("{kind} event {};", v.name.name);
        }
        let ty =
            v.ty.as_ref()
                .map(|t| format!(": {}", self.ty(t)))
                .unwrap_or_default();
        let init = v
            .init
            .as_ref()
            .map(|e| format!(" = {}", self.expr(e)))
            .unwrap_or_default();
        let len = v
            .len
            .as_ref()
            .map(|n| format!("[{}]", self.expr(n)))
            .unwrap_or_default();
        format!("{kind} {}{len}{ty}{init};", v.name.name)
    }

    /// A property: on one line, or with its main expression broken (see
    /// [`Printer::line_expr`]).
    pub(super) fn property_line(&mut self, p: &Property) {
        let n = &p.name.name;
        match &p.kind {
            PropertyKind::Invariant { expr, assuming } => {
                let a = assuming
                    .as_ref()
                    .map(|e| format!(" assuming {}", self.expr(e)))
                    .unwrap_or_default();
                self.line_expr(p.span, &format!("invariant {n}:"), expr, &format!("{a};"));
            }
            PropertyKind::Reachable { expr } => {
                self.line_expr(p.span, &format!("reachable {n}:"), expr, ";");
            }
            PropertyKind::Respond { .. }
            | PropertyKind::RespondEventually { .. }
            | PropertyKind::Ltl { .. }
            | PropertyKind::Ctl { .. }
            | PropertyKind::Nonblocking { .. }
            | PropertyKind::Fair { .. } => {
                let t = self.property(p);
                self.line(p.span, &t);
            }
        }
    }

    /// A property as one line.
    pub(super) fn property(&self, p: &Property) -> String {
        let n = &p.name.name;
        match &p.kind {
            PropertyKind::Invariant { expr, assuming } => {
                let a = assuming
                    .as_ref()
                    .map(|e| format!(" assuming {}", self.expr(e)))
                    .unwrap_or_default();
                format!("invariant {n}: {}{a};", self.expr(expr))
            }
            PropertyKind::Reachable { expr } => format!("reachable {n}: {};", self.expr(expr)),
            PropertyKind::Respond {
                trigger,
                response,
                within,
            } => format!(
                "respond {n}: {} => {} within {};",
                self.expr(trigger),
                self.expr(response),
                self.delay(within)
            ),
            PropertyKind::RespondEventually { trigger, response } => format!(
                "respond {n}: {} => {};",
                self.expr(trigger),
                self.expr(response)
            ),
            PropertyKind::Ltl { formula } => format!("ltl {n}: {};", self.formula(formula)),
            PropertyKind::Ctl { formula } => format!("ctl {n}: {};", self.formula(formula)),
            PropertyKind::Nonblocking { expr } => {
                format!("nonblocking {n}: {};", self.expr(expr))
            }
            PropertyKind::Fair { trigger, expr } => match trigger {
                Some(t) => format!("fair {n}: {} => {};", self.expr(t), self.expr(expr)),
                None => format!("fair {n}: {};", self.expr(expr)),
            },
        }
    }

    /// A temporal formula, parenthesised exactly where the parser's grouping needs it
    /// (`parser/temporal.rs`: `=>` loosest and right-associative, then `||` and `&&`
    /// left-associative, `U R W` right-associative, prefix operators tightest), so the text
    /// parses back to the same tree. Needless parentheses would change it: the parser reads a
    /// parenthesised group without temporal operators as one atom, so `a && b && G c` printed
    /// as `(a && b) && G c` would come back with the atom `a && b`.
    fn formula(&self, f: &Formula) -> String {
        self.formula_at(f, 1, false)
    }

    /// `f` where the parser reads an operand of binding level `ctx` (1 `=>`, 2 `||`, 3 `&&`,
    /// 4 `U R W`, 5 prefix), in parentheses when it binds more loosely. `in_quant` is the left
    /// operand of `A[.. U ..]`, read without infix `U R W`, which must be parenthesised there.
    fn formula_at(&self, f: &Formula, ctx: u8, in_quant: bool) -> String {
        let level = match f {
            Formula::Implies(..) => 1,
            Formula::Or(..) => 2,
            Formula::And(..) => 3,
            Formula::Binary(..) if in_quant => 0,
            Formula::Binary(..) => 4,
            Formula::Atom(_) | Formula::Not(..) | Formula::Unary(..) | Formula::QuantUntil(..) => 5,
        };
        if level < ctx {
            return format!("({})", self.formula_at(f, 1, false));
        }
        match f {
            Formula::Atom(e) => {
                let text = self.expr(e);
                if matches!(e, Expr::Binary(BinOp::And | BinOp::Or, ..)) {
                    format!("({text})")
                } else {
                    text
                }
            }
            Formula::Not(a, _) => format!("!{}", self.formula_at(a, 5, in_quant)),
            Formula::And(a, b, _) => format!(
                "{} && {}",
                self.formula_at(a, 3, in_quant),
                self.formula_at(b, 4, in_quant)
            ),
            Formula::Or(a, b, _) => format!(
                "{} || {}",
                self.formula_at(a, 2, in_quant),
                self.formula_at(b, 3, in_quant)
            ),
            Formula::Implies(a, b, _) => {
                format!(
                    "{} => {}",
                    self.formula_at(a, 2, false),
                    self.formula_at(b, 1, false)
                )
            }
            Formula::Unary(op, a, _) => {
                format!("{} {}", op.as_str(), self.formula_at(a, 5, in_quant))
            }
            Formula::Binary(op, a, b, _) => format!(
                "{} {} {}",
                self.formula_at(a, 5, false),
                op.as_str(),
                self.formula_at(b, 4, false)
            ),
            Formula::QuantUntil(q, a, b, _) => {
                let q = match q {
                    Quant::All => "A",
                    Quant::Exists => "E",
                };
                format!(
                    "{q}[{} U {}]",
                    self.formula_at(a, 2, true),
                    self.formula_at(b, 2, false)
                )
            }
        }
    }
}
