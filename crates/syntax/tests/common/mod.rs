//! Shared helpers for the syntax tests: a compact AST printer, a diagnostics printer and the
//! data-file loader.

#![allow(dead_code)] // reason: each test binary that includes this module uses only some of it

use statecheck_base::{Diagnostic, LineIndex};
use statecheck_syntax::ast::*;
use std::fmt::Write;
use std::path::{Path as FsPath, PathBuf};

/// The `.sc` files of `tests/data/<dir>`, sorted by name, as `(stem, text)`.
pub fn data_files(dir: &str) -> Vec<(String, String)> {
    let root: PathBuf = [env!("CARGO_MANIFEST_DIR"), "tests", "data", dir]
        .iter()
        .collect();
    let mut names: Vec<PathBuf> = std::fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "sc"))
        .collect();
    names.sort();
    names
        .into_iter()
        .map(|p| (stem(&p), std::fs::read_to_string(&p).unwrap()))
        .collect()
}

fn stem(p: &FsPath) -> String {
    p.file_stem().unwrap().to_string_lossy().into_owned()
}

/// Diagnostics as `CODE line:col-line:col: message` lines with label, secondary labels and hint.
pub fn render_diags(src: &str, diags: &[Diagnostic]) -> String {
    let idx = LineIndex::new(src);
    let pos = |o: u32| {
        let (l, c) = idx.line_col(o);
        format!("{l}:{c}")
    };
    let mut out = String::new();
    for d in diags {
        let span = if d.span.is_empty() {
            pos(d.span.start)
        } else {
            format!("{}-{}", pos(d.span.start), pos(d.span.end))
        };
        let _ = writeln!(out, "{} {}: {}", d.code, span, d.message);
        if !d.label.is_empty() {
            let _ = writeln!(out, "    label: {}", d.label);
        }
        for s in &d.secondary {
            let _ = writeln!(out, "    at {}: {}", pos(s.span.start), s.message);
        }
        if let Some(h) = &d.hint {
            let _ = writeln!(out, "    hint: {h}");
        }
    }
    out
}

/// A compact, indented rendering of a file; expressions are fully parenthesised prefix forms.
pub fn render_file(f: &File) -> String {
    let mut p = Printer::default();
    for item in &f.items {
        p.item(item);
    }
    p.out
}

#[derive(Default)]
struct Printer {
    out: String,
    indent: usize,
}

pub fn expr(e: &Expr) -> String {
    match e {
        Expr::Int(v, _) => v.to_string(),
        Expr::Bool(b, _) => b.to_string(),
        Expr::Path(p) => path(p),
        Expr::In(p, _) => format!("in({})", path(p)),
        Expr::Call { func, args, .. } => {
            let a: Vec<String> = args.iter().map(expr).collect();
            format!("{}({})", func.name, a.join(", "))
        }
        Expr::Unary(op, e, _) => {
            let o = match op {
                UnOp::Neg => "neg",
                UnOp::Not => "not",
                UnOp::BitNot => "bitnot",
            };
            format!("({o} {})", expr(e))
        }
        Expr::Binary(op, a, b, _) => format!("({} {} {})", binop(*op), expr(a), expr(b)),
        Expr::If(c, a, b, _) => format!("(if {} {} {})", expr(c), expr(a), expr(b)),
        Expr::Error(_) => "<error>".into(),
    }
}

fn binop(op: BinOp) -> &'static str {
    match op {
        BinOp::Or => "||",
        BinOp::And => "&&",
        BinOp::Eq => "==",
        BinOp::Ne => "!=",
        BinOp::Lt => "<",
        BinOp::Le => "<=",
        BinOp::Gt => ">",
        BinOp::Ge => ">=",
        BinOp::BitOr => "|",
        BinOp::BitXor => "^",
        BinOp::BitAnd => "&",
        BinOp::Shl => "<<",
        BinOp::Shr => ">>",
        BinOp::Add => "+",
        BinOp::Sub => "-",
        BinOp::Mul => "*",
        BinOp::Div => "/",
        BinOp::Rem => "%",
    }
}

pub fn path(p: &Path) -> String {
    let segs: Vec<String> = p
        .segments
        .iter()
        .map(|s| match &s.index {
            None => s.name.name.clone(),
            Some(Index::All(_)) => format!("{}[*]", s.name.name),
            Some(Index::At(e)) => format!("{}[{}]", s.name.name, expr(e)),
        })
        .collect();
    segs.join(".")
}

fn ty(t: &TypeExpr) -> String {
    match t {
        TypeExpr::Bool(_) => "bool".into(),
        TypeExpr::Int(_) => "int".into(),
        TypeExpr::Range { lo, hi, .. } => format!("int[{}..{}]", expr(lo), expr(hi)),
        TypeExpr::Named(i) => i.name.clone(),
    }
}

fn duration(d: &Duration) -> String {
    let u = match d.unit {
        TimeUnit::Ms => "ms",
        TimeUnit::S => "s",
        TimeUnit::Min => "min",
    };
    format!("{} {u}", expr(&d.amount))
}

impl Printer {
    fn line(&mut self, s: impl AsRef<str>) {
        for _ in 0..self.indent {
            self.out.push_str("  ");
        }
        self.out.push_str(s.as_ref());
        self.out.push('\n');
    }

    fn nested(&mut self, f: impl FnOnce(&mut Self)) {
        self.indent += 1;
        f(self);
        self.indent -= 1;
    }

    fn item(&mut self, item: &Item) {
        match item {
            Item::Const(c) => {
                let t =
                    c.ty.as_ref()
                        .map(|t| format!(": {}", ty(t)))
                        .unwrap_or_default();
                self.line(format!("const {}{t} = {}", c.name.name, expr(&c.value)));
            }
            Item::Enum(e) => {
                let v: Vec<&str> = e.variants.iter().map(|v| v.name.as_str()).collect();
                self.line(format!("enum {} {{ {} }}", e.name.name, v.join(", ")));
            }
            Item::Fn(f) => {
                let ps: Vec<String> = f
                    .params
                    .iter()
                    .map(|p| format!("{}: {}", p.name.name, ty(&p.ty)))
                    .collect();
                self.line(format!(
                    "fn {}({}) -> {}",
                    f.name.name,
                    ps.join(", "),
                    ty(&f.ret)
                ));
                self.nested(|p| {
                    for (n, e) in &f.lets {
                        p.line(format!("let {} = {}", n.name, expr(e)));
                    }
                    p.line(format!("return {}", expr(&f.body)));
                });
            }
            Item::Tick(t) => self.line(format!("tick {}", duration(&t.duration))),
            Item::Import(i) => {
                let names = i.names.as_ref().map(|ns| {
                    let ns: Vec<&str> = ns.iter().map(|n| n.name.as_str()).collect();
                    format!(" {{ {} }}", ns.join(", "))
                });
                self.line(format!("import {:?}{}", i.path, names.unwrap_or_default()))
            }
            Item::Chart(c) => self.chart(c),
            Item::System(s) => self.system(s),
            Item::Component(c) => {
                let imps: Vec<&str> = c.implements.iter().map(|i| i.name.as_str()).collect();
                self.line(format!(
                    "component {} implements [{}]",
                    c.name.name,
                    imps.join(", ")
                ));
                self.nested(|p| {
                    for m in &c.ports {
                        p.line(format!("{:?} {} event={}", m.kind, m.name.name, m.is_event));
                    }
                    p.system(&c.body);
                });
            }
            Item::Interface(i) => {
                self.line(format!("interface {}", i.name.name));
                self.nested(|p| {
                    for m in &i.members {
                        p.line(format!("{:?} {} event={}", m.kind, m.name.name, m.is_event));
                    }
                });
            }
        }
    }

    fn chart(&mut self, c: &Chart) {
        let role = c
            .role
            .as_ref()
            .map(|r| format!("{} ", r.name))
            .unwrap_or_default();
        self.line(format!("{role}chart {}", c.name.name));
        self.nested(|p| {
            for v in &c.vars {
                let kind = match v.kind {
                    VarKind::Input => "input",
                    VarKind::Output => "output",
                    VarKind::Local => "local",
                };
                if v.is_event {
                    p.line(format!("{kind} event {}", v.name.name));
                } else {
                    let t = v.ty.as_ref().map(ty).unwrap_or_default();
                    let init = v
                        .init
                        .as_ref()
                        .map(|e| format!(" = {}", expr(e)))
                        .unwrap_or_default();
                    let len = v
                        .len
                        .as_ref()
                        .map(|n| format!("[{}]", expr(n)))
                        .unwrap_or_default();
                    p.line(format!("{kind} {}{len}: {t}{init}", v.name.name));
                }
            }
            for prop in &c.properties {
                p.property(prop);
            }
            p.body(&c.body);
        });
    }

    fn property(&mut self, prop: &Property) {
        let n = &prop.name.name;
        match &prop.kind {
            PropertyKind::Invariant { expr: e, assuming } => {
                let a = assuming
                    .as_ref()
                    .map(|a| format!(" assuming {}", expr(a)))
                    .unwrap_or_default();
                self.line(format!("invariant {n}: {}{a}", expr(e)));
            }
            PropertyKind::Reachable { expr: e } => self.line(format!("reachable {n}: {}", expr(e))),
            PropertyKind::Respond {
                trigger,
                response,
                within,
            } => self.line(format!(
                "respond {n}: {} => {} within {}",
                expr(trigger),
                expr(response),
                match within {
                    Delay::Ticks(e) => expr(e),
                    Delay::Time(d) => duration(d),
                }
            )),
            PropertyKind::RespondEventually { trigger, response } => self.line(format!(
                "respond {n}: {} => {}",
                expr(trigger),
                expr(response)
            )),
            PropertyKind::Ltl { formula } => {
                self.line(format!("ltl {n}: {}", formula_text(formula)))
            }
            PropertyKind::Ctl { formula } => {
                self.line(format!("ctl {n}: {}", formula_text(formula)))
            }
            PropertyKind::Nonblocking { expr: e } => {
                self.line(format!("nonblocking {n}: {}", expr(e)))
            }
            PropertyKind::Fair { trigger, expr: e } => match trigger {
                Some(t) => self.line(format!("fair {n}: {} => {}", expr(t), expr(e))),
                None => self.line(format!("fair {n}: {}", expr(e))),
            },
        }
    }

    fn body(&mut self, b: &StateBody) {
        for i in &b.initial {
            self.line(format!("initial {}", i.target.name));
            if let Some(a) = &i.action {
                self.nested(|p| p.block("/", a));
            }
        }
        for h in &b.history {
            self.line(format!("history {:?}", h.kind));
        }
        for e in &b.entry {
            self.block("entry", e);
        }
        for e in &b.during {
            self.block("during", e);
        }
        for e in &b.exit {
            self.block("exit", e);
        }
        for t in &b.transitions {
            self.transition(t);
        }
        for j in &b.junctions {
            self.line(format!("junction {}", j.name.name));
            self.nested(|p| {
                for br in &j.branches {
                    p.branch(br);
                }
            });
        }
        for s in &b.states {
            self.line(format!("state {}", s.name.name));
            self.nested(|p| p.body(&s.body));
        }
        for r in &b.regions {
            self.line(format!("region {}", r.name.name));
            self.nested(|p| p.body(&r.body));
        }
    }

    /// Print `head [/ { action }] -> target` (or `(internal)` without target).
    fn arrow(&mut self, head: String, action: Option<&Block>, target: Option<&Target>) {
        let (tail, branches) = match target {
            None => (" (internal)".to_string(), None),
            Some(Target::Path(p)) => (format!(" -> {}", path(p)), None),
            Some(Target::Choice { branches, .. }) => (" -> choice".to_string(), Some(branches)),
        };
        match action {
            Some(a) => {
                self.line(format!("{head} / {{"));
                self.nested(|p| {
                    for s in &a.stmts {
                        p.stmt(s);
                    }
                });
                self.line(format!("}}{tail}"));
            }
            None => self.line(format!("{head}{tail}")),
        }
        if let Some(branches) = branches {
            self.nested(|p| {
                for b in branches {
                    p.branch(b);
                }
            });
        }
    }

    fn branch(&mut self, b: &Branch) {
        let head = match &b.guard {
            Some(g) => format!("[{}]", expr(g)),
            None => "else".into(),
        };
        self.arrow(head, b.action.as_ref(), Some(&b.target));
    }

    fn transition(&mut self, t: &Transition) {
        let mut head = "on".to_string();
        match &t.trigger {
            None => {}
            Some(Trigger::Event(e)) => head += &format!(" {}", e.name),
            Some(Trigger::After {
                delay: Delay::Ticks(e),
                ..
            }) => head += &format!(" after({} ticks)", expr(e)),
            Some(Trigger::After {
                delay: Delay::Time(d),
                ..
            }) => head += &format!(" after({})", duration(d)),
        }
        if let Some(g) = &t.guard {
            head += &format!(" [{}]", expr(g));
        }
        if let Some((p, _)) = t.priority {
            head += &format!(" priority {p}");
        }
        self.arrow(head, t.action.as_ref(), t.target.as_ref());
    }

    fn block(&mut self, head: &str, b: &Block) {
        self.line(format!("{head} {{"));
        self.nested(|p| {
            for s in &b.stmts {
                p.stmt(s);
            }
        });
        self.line("}");
    }

    fn stmt(&mut self, s: &Stmt) {
        match s {
            Stmt::Assign {
                target,
                index,
                value,
                ..
            } => {
                let i = index
                    .as_ref()
                    .map(|i| format!("[{}]", expr(i)))
                    .unwrap_or_default();
                self.line(format!("{}{i} = {}", target.name, expr(value)))
            }
            Stmt::For {
                var, lo, hi, body, ..
            } => self.block(
                &format!("for {} in {}..{}", var.name, expr(lo), expr(hi)),
                body,
            ),
            Stmt::Raise { event, .. } => self.line(format!("raise {}", event.name)),
            Stmt::If {
                cond,
                then,
                otherwise,
                ..
            } => {
                self.block(&format!("if {}", expr(cond)), then);
                if let Some(o) = otherwise {
                    self.block("else", o);
                }
            }
        }
    }

    fn system(&mut self, s: &System) {
        self.line(format!("system {}", s.name.name));
        self.nested(|p| {
            for i in &s.instances {
                let c = i
                    .count
                    .as_ref()
                    .map(|e| format!("[{}]", expr(e)))
                    .unwrap_or_default();
                p.line(format!("instance {}{c}: {}", i.name.name, i.chart.name));
            }
            for c in &s.connections {
                p.line(format!("connect {} -> {}", path(&c.from), path(&c.to)));
            }
            for o in &s.order {
                let v: Vec<&str> = o.instances.iter().map(|i| i.name.as_str()).collect();
                p.line(format!("order {}", v.join(", ")));
            }
            for a in &s.assumes {
                p.line(format!("assume {}", expr(&a.expr)));
            }
            for prop in &s.properties {
                p.property(prop);
            }
            for o in &s.observers {
                p.chart(o);
            }
        });
    }
}

/// A formula, fully parenthesised.
pub fn formula_text(f: &statecheck_syntax::ast::Formula) -> String {
    use statecheck_syntax::ast::{Formula as F, Quant};
    match f {
        F::Atom(e) => format!("{{{}}}", expr(e)),
        F::Not(a, _) => format!("!{}", formula_text(a)),
        F::And(a, b, _) => format!("({} && {})", formula_text(a), formula_text(b)),
        F::Or(a, b, _) => format!("({} || {})", formula_text(a), formula_text(b)),
        F::Implies(a, b, _) => format!("({} => {})", formula_text(a), formula_text(b)),
        F::Unary(op, a, _) => format!("{} {}", op.as_str(), formula_text(a)),
        F::Binary(op, a, b, _) => {
            format!("({} {} {})", formula_text(a), op.as_str(), formula_text(b))
        }
        F::QuantUntil(q, a, b, _) => format!(
            "{}[{} U {}]",
            if *q == Quant::All { "A" } else { "E" },
            formula_text(a),
            formula_text(b)
        ),
    }
}
