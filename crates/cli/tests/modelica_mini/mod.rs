//! The subset of Modelica that `gen modelica` emits: one model with enumeration types, a
//! `Real` parameter, declarations with modifiers, functions with `while`/`for`, and one
//! algorithm section holding one `when` clause. Parsing follows Modelica's grammar for
//! expressions (a unary minus only at the start of an arithmetic expression); evaluation is
//! typed and strict.

use std::collections::BTreeMap;

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Id(String),
    Int(i64),
    Real,
    Str(String),
    Sym(&'static str),
}

const SYMS: &[&str] = &[
    ":=", "==", "<>", "<=", ">=", "<", ">", "+", "-", "*", "/", "(", ")", "[", "]", ",", ";", "=",
    ".", ":",
];

fn lex(src: &str) -> Result<Vec<(Tok, usize)>, String> {
    let mut out = Vec::new();
    let b = src.as_bytes();
    let (mut i, mut line) = (0, 1);
    while i < b.len() {
        let c = b[i] as char;
        if c == '\n' {
            line += 1;
            i += 1;
        } else if c.is_whitespace() {
            i += 1;
        } else if src[i..].starts_with("//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if c.is_ascii_alphabetic() || c == '_' {
            let s = i;
            while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                i += 1;
            }
            out.push((Tok::Id(src[s..i].to_string()), line));
        } else if c.is_ascii_digit() {
            let s = i;
            while i < b.len() && b[i].is_ascii_digit() {
                i += 1;
            }
            if i + 1 < b.len() && b[i] == b'.' && b[i + 1].is_ascii_digit() {
                i += 1;
                while i < b.len() && b[i].is_ascii_digit() {
                    i += 1;
                }
                out.push((Tok::Real, line));
            } else {
                let v = src[s..i]
                    .parse()
                    .map_err(|_| format!("line {line}: number"))?;
                out.push((Tok::Int(v), line));
            }
        } else if c == '"' {
            let mut s = String::new();
            i += 1;
            loop {
                match b.get(i) {
                    None => return Err(format!("line {line}: unterminated string")),
                    Some(b'"') => break,
                    Some(b'\\') => {
                        s.push(*b.get(i + 1).ok_or("bad escape")? as char);
                        i += 2;
                    }
                    Some(b'\n') => return Err(format!("line {line}: newline in string")),
                    Some(_) => {
                        let ch = src[i..].chars().next().ok_or("char")?;
                        s.push(ch);
                        i += ch.len_utf8();
                    }
                }
            }
            i += 1;
            out.push((Tok::Str(s), line));
        } else {
            let sym = SYMS
                .iter()
                .find(|s| src[i..].starts_with(**s))
                .ok_or_else(|| format!("line {line}: unexpected `{c}`"))?;
            out.push((Tok::Sym(sym), line));
            i += sym.len();
        }
    }
    Ok(out)
}

/// An expression.
#[derive(Clone, Debug)]
pub enum Expr {
    Int(i64),
    Bool(bool),
    Str(String),
    Name(String),
    Lit(String, String),
    Index(String, Box<Expr>),
    Call(String, Vec<Expr>),
    Neg(Box<Expr>),
    Not(Box<Expr>),
    Bin(&'static str, Box<Expr>, Box<Expr>),
    If(Vec<(Expr, Expr)>, Box<Expr>),
}

/// A statement.
#[derive(Clone, Debug)]
pub enum Stmt {
    Assign(String, Option<Expr>, Expr),
    If(Vec<(Expr, Vec<Stmt>)>, Vec<Stmt>),
    Assert(Expr, Expr),
    While(Expr, Vec<Stmt>),
    For(String, Expr, Expr, Vec<Stmt>),
}

/// A component declaration.
#[derive(Clone, Debug)]
pub struct Decl {
    pub prefix: Option<String>,
    pub ty: String,
    pub name: String,
    pub size: Option<usize>,
    pub mods: Vec<(String, Expr)>,
    pub binding: Option<Expr>,
    pub desc: Option<String>,
}

/// A function.
#[derive(Clone, Debug)]
pub struct Function {
    pub inputs: Vec<(String, String)>,
    pub output: (String, String),
    pub locals: Vec<(String, String)>,
    pub body: Vec<Stmt>,
}

/// A parsed model.
#[derive(Clone, Debug)]
pub struct Model {
    pub name: String,
    pub types: BTreeMap<String, Vec<String>>,
    pub params: Vec<String>,
    pub decls: Vec<Decl>,
    pub functions: BTreeMap<String, Function>,
    pub tick: Vec<Stmt>,
}

impl Model {
    /// The declaration of `name`.
    pub fn decl(&self, name: &str) -> Option<&Decl> {
        self.decls.iter().find(|d| d.name == name)
    }
}

struct P {
    toks: Vec<(Tok, usize)>,
    at: usize,
}

type R<T> = Result<T, String>;

impl P {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.at).map(|t| &t.0)
    }
    fn err<T>(&self, what: &str) -> R<T> {
        let line = self.toks.get(self.at).map_or(0, |t| t.1);
        Err(format!(
            "line {line}: expected {what}, found {:?}",
            self.peek()
        ))
    }
    fn is_id(&self, w: &str) -> bool {
        matches!(self.peek(), Some(Tok::Id(x)) if x == w)
    }
    fn is_sym(&self, s: &str) -> bool {
        matches!(self.peek(), Some(Tok::Sym(x)) if *x == s)
    }
    fn kw(&mut self, w: &str) -> R<()> {
        if self.is_id(w) {
            self.at += 1;
            Ok(())
        } else {
            self.err(w)
        }
    }
    fn sym(&mut self, s: &str) -> R<()> {
        if self.is_sym(s) {
            self.at += 1;
            Ok(())
        } else {
            self.err(s)
        }
    }
    fn id(&mut self) -> R<String> {
        match self.peek() {
            Some(Tok::Id(x)) if !KEYWORDS.split_whitespace().any(|w| w == x) => {
                let x = x.clone();
                self.at += 1;
                Ok(x)
            }
            _ => self.err("identifier"),
        }
    }
    fn string(&mut self) -> Option<String> {
        if let Some(Tok::Str(s)) = self.peek() {
            let s = s.clone();
            self.at += 1;
            Some(s)
        } else {
            None
        }
    }

    fn model(&mut self) -> R<Model> {
        self.kw("model")?;
        let name = self.id()?;
        self.string();
        let mut m = Model {
            name,
            types: BTreeMap::new(),
            params: Vec::new(),
            decls: Vec::new(),
            functions: BTreeMap::new(),
            tick: Vec::new(),
        };
        while !self.is_id("algorithm") {
            if self.is_id("protected") {
                self.at += 1;
            } else if self.is_id("type") {
                self.at += 1;
                let t = self.id()?;
                self.sym("=")?;
                self.kw("enumeration")?;
                self.sym("(")?;
                let mut lits = vec![self.id()?];
                while self.is_sym(",") {
                    self.at += 1;
                    lits.push(self.id()?);
                }
                self.sym(")")?;
                self.string();
                self.sym(";")?;
                m.types.insert(t, lits);
            } else if self.is_id("parameter") {
                self.at += 1;
                self.kw("Real")?;
                let n = self.id()?;
                self.sym("=")?;
                if self.peek() != Some(&Tok::Real) {
                    return self.err("a Real literal");
                }
                self.at += 1;
                self.string();
                self.sym(";")?;
                m.params.push(n);
            } else if self.is_id("function") {
                self.at += 1;
                let (n, f) = self.function()?;
                m.functions.insert(n, f);
            } else {
                m.decls.push(self.decl()?);
            }
        }
        self.kw("algorithm")?;
        self.kw("when")?;
        self.kw("sample")?;
        self.sym("(")?;
        if self.peek() != Some(&Tok::Int(0)) {
            return self.err("0");
        }
        self.at += 1;
        self.sym(",")?;
        let period = self.id()?;
        if !m.params.contains(&period) {
            return Err(format!("sample period `{period}` is not a parameter"));
        }
        self.sym(")")?;
        self.kw("then")?;
        m.tick = self.stmts()?;
        self.kw("end")?;
        self.kw("when")?;
        self.sym(";")?;
        self.kw("annotation")?;
        self.sym("(")?;
        let mut depth = 1;
        while depth > 0 {
            match self.peek() {
                Some(Tok::Sym("(")) => depth += 1,
                Some(Tok::Sym(")")) => depth -= 1,
                None => return self.err(")"),
                _ => {}
            }
            self.at += 1;
        }
        self.sym(";")?;
        self.kw("end")?;
        let end = self.id()?;
        if end != m.name {
            return Err(format!("`end {end};` closes model `{}`", m.name));
        }
        self.sym(";")?;
        if self.peek().is_some() {
            return self.err("end of file");
        }
        Ok(m)
    }

    fn decl(&mut self) -> R<Decl> {
        let prefix = if self.is_id("input") || self.is_id("output") {
            let p = self.id_any();
            Some(p)
        } else {
            None
        };
        let ty = self.id_any();
        let name = self.id()?;
        let size = if self.is_sym("[") {
            self.at += 1;
            let n = match self.peek() {
                Some(Tok::Int(n)) => *n as usize,
                _ => return self.err("array size"),
            };
            self.at += 1;
            self.sym("]")?;
            Some(n)
        } else {
            None
        };
        let mut mods = Vec::new();
        if self.is_sym("(") {
            self.at += 1;
            loop {
                let each = self.is_id("each");
                if each {
                    self.at += 1;
                }
                if each != size.is_some() {
                    return self.err("`each` exactly on arrays");
                }
                let k = self.id()?;
                self.sym("=")?;
                mods.push((k, self.expr()?));
                if self.is_sym(",") {
                    self.at += 1;
                } else {
                    break;
                }
            }
            self.sym(")")?;
        }
        let binding = if self.is_sym("=") {
            self.at += 1;
            Some(self.expr()?)
        } else {
            None
        };
        let desc = self.string();
        self.sym(";")?;
        Ok(Decl {
            prefix,
            ty,
            name,
            size,
            mods,
            binding,
            desc,
        })
    }

    fn id_any(&mut self) -> String {
        let s = match self.peek() {
            Some(Tok::Id(x)) => x.clone(),
            _ => String::new(),
        };
        self.at += 1;
        s
    }

    fn function(&mut self) -> R<(String, Function)> {
        let name = self.id()?;
        self.string();
        let mut f = Function {
            inputs: Vec::new(),
            output: (String::new(), String::new()),
            locals: Vec::new(),
            body: Vec::new(),
        };
        let mut protected = false;
        while !self.is_id("algorithm") {
            if self.is_id("protected") {
                self.at += 1;
                protected = true;
                continue;
            }
            let d = self.decl()?;
            let v = (d.ty.clone(), d.name.clone());
            match (d.prefix.as_deref(), protected) {
                (Some("input"), false) => f.inputs.push(v),
                (Some("output"), false) if f.output.1.is_empty() => f.output = v,
                (None, true) => f.locals.push(v),
                _ => {
                    return Err(format!(
                        "function {name}: unexpected declaration {}",
                        d.name
                    ))
                }
            }
        }
        self.kw("algorithm")?;
        f.body = self.stmts()?;
        self.kw("end")?;
        let end = self.id()?;
        if end != name {
            return Err(format!("`end {end};` closes function `{name}`"));
        }
        self.sym(";")?;
        Ok((name, f))
    }

    fn stmts(&mut self) -> R<Vec<Stmt>> {
        let mut out = Vec::new();
        while !(self.is_id("end") || self.is_id("else") || self.is_id("elseif")) {
            out.push(self.stmt()?);
        }
        Ok(out)
    }

    fn stmt(&mut self) -> R<Stmt> {
        if self.is_id("if") {
            self.at += 1;
            let mut arms = Vec::new();
            let c = self.expr()?;
            self.kw("then")?;
            arms.push((c, self.stmts()?));
            let mut otherwise = Vec::new();
            loop {
                if self.is_id("elseif") {
                    self.at += 1;
                    let c = self.expr()?;
                    self.kw("then")?;
                    arms.push((c, self.stmts()?));
                } else if self.is_id("else") {
                    self.at += 1;
                    otherwise = self.stmts()?;
                } else {
                    break;
                }
            }
            self.kw("end")?;
            self.kw("if")?;
            self.sym(";")?;
            return Ok(Stmt::If(arms, otherwise));
        }
        if self.is_id("while") {
            self.at += 1;
            let c = self.expr()?;
            self.kw("loop")?;
            let body = self.stmts()?;
            self.kw("end")?;
            self.kw("while")?;
            self.sym(";")?;
            return Ok(Stmt::While(c, body));
        }
        if self.is_id("for") {
            self.at += 1;
            let v = self.id()?;
            self.kw("in")?;
            let a = self.arith()?;
            self.sym(":")?;
            let b = self.arith()?;
            self.kw("loop")?;
            let body = self.stmts()?;
            self.kw("end")?;
            self.kw("for")?;
            self.sym(";")?;
            return Ok(Stmt::For(v, a, b, body));
        }
        if self.is_id("assert") {
            self.at += 1;
            self.sym("(")?;
            let c = self.expr()?;
            self.sym(",")?;
            let m = self.expr()?;
            self.sym(")")?;
            self.sym(";")?;
            return Ok(Stmt::Assert(c, m));
        }
        let name = self.id()?;
        let idx = if self.is_sym("[") {
            self.at += 1;
            let e = self.expr()?;
            self.sym("]")?;
            Some(e)
        } else {
            None
        };
        self.sym(":=")?;
        let e = self.expr()?;
        self.sym(";")?;
        Ok(Stmt::Assign(name, idx, e))
    }

    fn expr(&mut self) -> R<Expr> {
        if !self.is_id("if") {
            return self.or();
        }
        self.at += 1;
        let mut arms = Vec::new();
        let c = self.expr()?;
        self.kw("then")?;
        arms.push((c, self.expr()?));
        while self.is_id("elseif") {
            self.at += 1;
            let c = self.expr()?;
            self.kw("then")?;
            arms.push((c, self.expr()?));
        }
        self.kw("else")?;
        let e = self.expr()?;
        Ok(Expr::If(arms, Box::new(e)))
    }

    fn or(&mut self) -> R<Expr> {
        let mut a = self.and()?;
        while self.is_id("or") {
            self.at += 1;
            a = Expr::Bin("or", Box::new(a), Box::new(self.and()?));
        }
        Ok(a)
    }

    fn and(&mut self) -> R<Expr> {
        let mut a = self.not()?;
        while self.is_id("and") {
            self.at += 1;
            a = Expr::Bin("and", Box::new(a), Box::new(self.not()?));
        }
        Ok(a)
    }

    fn not(&mut self) -> R<Expr> {
        if self.is_id("not") {
            self.at += 1;
            return Ok(Expr::Not(Box::new(self.relation()?)));
        }
        self.relation()
    }

    fn relation(&mut self) -> R<Expr> {
        let a = self.arith()?;
        for op in ["==", "<>", "<=", ">=", "<", ">"] {
            if self.is_sym(op) {
                self.at += 1;
                let b = self.arith()?;
                return Ok(Expr::Bin(op, Box::new(a), Box::new(b)));
            }
        }
        Ok(a)
    }

    fn arith(&mut self) -> R<Expr> {
        let neg = self.is_sym("-");
        if neg {
            self.at += 1;
        }
        let mut a = self.term()?;
        if neg {
            a = Expr::Neg(Box::new(a));
        }
        loop {
            let op = if self.is_sym("+") {
                "+"
            } else if self.is_sym("-") {
                "-"
            } else {
                return Ok(a);
            };
            self.at += 1;
            a = Expr::Bin(op, Box::new(a), Box::new(self.term()?));
        }
    }

    fn term(&mut self) -> R<Expr> {
        let mut a = self.primary()?;
        while self.is_sym("*") {
            self.at += 1;
            a = Expr::Bin("*", Box::new(a), Box::new(self.primary()?));
        }
        Ok(a)
    }

    fn primary(&mut self) -> R<Expr> {
        match self.peek().cloned() {
            Some(Tok::Int(v)) => {
                self.at += 1;
                Ok(Expr::Int(v))
            }
            Some(Tok::Str(s)) => {
                self.at += 1;
                Ok(Expr::Str(s))
            }
            Some(Tok::Sym("(")) => {
                self.at += 1;
                let e = self.expr()?;
                self.sym(")")?;
                Ok(e)
            }
            Some(Tok::Id(x)) if x == "true" || x == "false" => {
                self.at += 1;
                Ok(Expr::Bool(x == "true"))
            }
            Some(Tok::Id(x)) if x == "Integer" || x == "String" => {
                self.at += 1;
                self.call(x)
            }
            Some(Tok::Id(_)) => {
                let n = self.id()?;
                if self.is_sym(".") {
                    self.at += 1;
                    let l = self.id()?;
                    Ok(Expr::Lit(n, l))
                } else if self.is_sym("[") {
                    self.at += 1;
                    let e = self.expr()?;
                    self.sym("]")?;
                    Ok(Expr::Index(n, Box::new(e)))
                } else if self.is_sym("(") {
                    self.call(n)
                } else {
                    Ok(Expr::Name(n))
                }
            }
            _ => self.err("an expression"),
        }
    }

    fn call(&mut self, f: String) -> R<Expr> {
        self.sym("(")?;
        let mut args = vec![self.expr()?];
        while self.is_sym(",") {
            self.at += 1;
            args.push(self.expr()?);
        }
        self.sym(")")?;
        Ok(Expr::Call(f, args))
    }
}

/// Modelica keywords: never a name.
const KEYWORDS: &str = "\
    algorithm and annotation block break class connect connector constant constrainedby \
    der discrete each else elseif elsewhen encapsulated end enumeration equation \
    expandable extends external false final flow for function if import impure in \
    initial inner input loop model not operator or outer output package parameter \
    partial protected public pure record redeclare replaceable return stream then true \
    type when while within";

const BUILTINS: &[&str] = &[
    "min", "max", "abs", "div", "rem", "mod", "Integer", "String",
];

/// Parse a generated model.
pub fn parse(text: &str) -> Result<Model, String> {
    let toks = lex(text)?;
    P { toks, at: 0 }.model()
}

/// Every name used is declared (as a variable, function, enumeration literal or built-in),
/// every declared type exists, and no name is declared twice.
pub fn check_names(m: &Model) -> Result<(), String> {
    let mut seen = std::collections::BTreeSet::new();
    for n in m
        .decls
        .iter()
        .map(|d| &d.name)
        .chain(m.types.keys())
        .chain(m.functions.keys())
        .chain(m.params.iter())
    {
        if !seen.insert(n.clone()) {
            return Err(format!("`{n}` declared twice"));
        }
    }
    for d in &m.decls {
        if !matches!(d.ty.as_str(), "Integer" | "Boolean") && !m.types.contains_key(&d.ty) {
            return Err(format!("`{}` has unknown type `{}`", d.name, d.ty));
        }
    }
    let globals: Vec<&String> = m.decls.iter().map(|d| &d.name).collect();
    let check = |stmts: &[Stmt], locals: &[&String]| -> Result<(), String> {
        let known = |n: &String| globals.contains(&n) || locals.contains(&n);
        let (mut used, mut targets) = (Vec::new(), Vec::new());
        walk_stmts(stmts, &mut |e| used.push(e.clone()), &mut |t| {
            targets.push(t.clone())
        });
        for t in &targets {
            if !known(t) {
                return Err(format!("assignment to undeclared `{t}`"));
            }
        }
        for e in &used {
            let bad = match e {
                Expr::Name(n) | Expr::Index(n, _) => (!known(n)).then(|| n.clone()),
                Expr::Lit(t, l) => m
                    .types
                    .get(t)
                    .is_none_or(|ls| !ls.contains(l))
                    .then(|| format!("{t}.{l}")),
                Expr::Call(f, _) => (!m.functions.contains_key(f)
                    && !BUILTINS.contains(&f.as_str()))
                .then(|| f.clone()),
                _ => None,
            };
            if let Some(b) = bad {
                return Err(format!("undeclared `{b}`"));
            }
        }
        Ok(())
    };
    check(&m.tick, &[])?;
    for (n, f) in &m.functions {
        let locals: Vec<&String> = f
            .inputs
            .iter()
            .chain(std::iter::once(&f.output))
            .chain(f.locals.iter())
            .map(|(_, n)| n)
            .collect();
        check(&f.body, &locals).map_err(|e| format!("function {n}: {e}"))?;
    }
    Ok(())
}

fn walk_stmts(stmts: &[Stmt], f: &mut dyn FnMut(&Expr), t: &mut dyn FnMut(&String)) {
    for s in stmts {
        match s {
            Stmt::Assign(n, i, e) => {
                t(n);
                if let Some(i) = i {
                    walk_expr(i, f);
                }
                walk_expr(e, f);
            }
            Stmt::If(arms, o) => {
                for (c, b) in arms {
                    walk_expr(c, f);
                    walk_stmts(b, f, t);
                }
                walk_stmts(o, f, t);
            }
            Stmt::Assert(c, m) => {
                walk_expr(c, f);
                walk_expr(m, f);
            }
            Stmt::While(c, b) => {
                walk_expr(c, f);
                walk_stmts(b, f, t);
            }
            Stmt::For(_, a, b, body) => {
                walk_expr(a, f);
                walk_expr(b, f);
                walk_stmts(body, f, t);
            }
        }
    }
}

fn walk_expr(e: &Expr, f: &mut dyn FnMut(&Expr)) {
    f(e);
    match e {
        Expr::Index(_, i) | Expr::Neg(i) | Expr::Not(i) => walk_expr(i, f),
        Expr::Call(_, args) => args.iter().for_each(|a| walk_expr(a, f)),
        Expr::Bin(_, a, b) => {
            walk_expr(a, f);
            walk_expr(b, f);
        }
        Expr::If(arms, e) => {
            for (c, v) in arms {
                walk_expr(c, f);
                walk_expr(v, f);
            }
            walk_expr(e, f);
        }
        _ => {}
    }
}

/// A value.
#[derive(Clone, Debug, PartialEq)]
pub enum Val {
    Int(i64),
    Bool(bool),
    Enum(String, usize),
    Str(String),
}

/// Why a tick stopped.
#[derive(Clone, Debug)]
pub enum Fail {
    /// An `assert` failed, with its message.
    Assert(String),
    /// The model did something a Modelica tool would reject.
    Error(String),
}

fn error<T>(msg: String) -> Result<T, Fail> {
    Err(Fail::Error(msg))
}

/// The model's variables and a way to run one tick.
pub struct Machine<'m> {
    m: &'m Model,
    vars: BTreeMap<String, Vec<Val>>,
}

impl<'m> Machine<'m> {
    /// Every variable at its `start` value or binding.
    pub fn new(m: &'m Model) -> Result<Machine<'m>, Fail> {
        let mut mm = Machine {
            m,
            vars: BTreeMap::new(),
        };
        for d in &m.decls {
            let init = d
                .mods
                .iter()
                .find(|(k, _)| k == "start")
                .map(|(_, e)| e)
                .or(d.binding.as_ref());
            let Some(init) = init else {
                return error(format!("`{}` has no start value", d.name));
            };
            let v = mm.eval(init, &mut None)?;
            mm.check_type(&d.ty, &v, &d.name)?;
            let fixed = d.mods.iter().any(|(k, _)| k == "fixed");
            if d.prefix.as_deref() != Some("input") && d.binding.is_none() && !fixed {
                return error(format!("`{}` has no fixed start value", d.name));
            }
            mm.vars.insert(d.name.clone(), vec![v; d.size.unwrap_or(1)]);
        }
        Ok(mm)
    }

    fn check_type(&self, ty: &str, v: &Val, what: &str) -> Result<(), Fail> {
        let ok = match (ty, v) {
            ("Integer", Val::Int(_)) | ("Boolean", Val::Bool(_)) => true,
            (t, Val::Enum(e, _)) => t == e,
            _ => false,
        };
        if ok {
            Ok(())
        } else {
            error(format!("{what}: a {ty} cannot hold {v:?}"))
        }
    }

    /// Set an input from its IR value.
    pub fn set_input(&mut self, name: &str, v: i64) -> Result<(), Fail> {
        let Some(d) = self.m.decl(name) else {
            return error(format!("no input `{name}`"));
        };
        if d.prefix.as_deref() != Some("input") {
            return error(format!("`{name}` is not an input"));
        }
        let val = match d.ty.as_str() {
            "Integer" => Val::Int(v),
            "Boolean" => Val::Bool(v != 0),
            t => Val::Enum(t.to_string(), v as usize),
        };
        self.vars.insert(name.to_string(), vec![val]);
        Ok(())
    }

    /// A scalar variable or array element (`a[3]`) as an IR value.
    pub fn value(&self, name: &str) -> Result<i64, Fail> {
        let (n, i) = match name.split_once('[') {
            Some((n, i)) => (n, i.trim_end_matches(']').parse::<usize>().unwrap_or(0)),
            None => (name, 1),
        };
        match self.vars.get(n).and_then(|v| v.get(i.wrapping_sub(1))) {
            Some(Val::Int(x)) => Ok(*x),
            Some(Val::Bool(b)) => Ok(i64::from(*b)),
            Some(Val::Enum(_, k)) => Ok(*k as i64),
            other => error(format!("`{name}` is {other:?}")),
        }
    }

    /// Run the `when` clause once (one tick).
    pub fn tick(&mut self) -> Result<(), Fail> {
        let body = &self.m.tick;
        self.exec(body, &mut None)
    }

    fn exec(&mut self, stmts: &[Stmt], fr: &mut Frame) -> Result<(), Fail> {
        for s in stmts {
            match s {
                Stmt::Assign(n, idx, e) => {
                    let v = self.eval(e, fr)?;
                    let i = match idx {
                        Some(i) => match self.eval(i, fr)? {
                            Val::Int(i) => Some(i),
                            x => return error(format!("index {x:?}")),
                        },
                        None => None,
                    };
                    self.assign(n, i, v, fr)?;
                }
                Stmt::If(arms, otherwise) => {
                    let mut done = false;
                    for (c, body) in arms {
                        if self.cond(c, fr)? {
                            self.exec(body, fr)?;
                            done = true;
                            break;
                        }
                    }
                    if !done {
                        self.exec(otherwise, fr)?;
                    }
                }
                Stmt::Assert(c, msg) => {
                    if !self.cond(c, fr)? {
                        return match self.eval(msg, fr)? {
                            Val::Str(s) => Err(Fail::Assert(s)),
                            x => error(format!("assert message {x:?}")),
                        };
                    }
                }
                Stmt::While(c, body) => {
                    let mut n = 0;
                    while self.cond(c, fr)? {
                        self.exec(body, fr)?;
                        n += 1;
                        if n > 10_000 {
                            return error("endless while loop".into());
                        }
                    }
                }
                Stmt::For(v, a, b, body) => {
                    let (Val::Int(a), Val::Int(b)) = (self.eval(a, fr)?, self.eval(b, fr)?) else {
                        return error("for range".into());
                    };
                    for k in a..=b {
                        if let Some(f) = fr.as_mut() {
                            f.insert(v.clone(), (String::from("Integer"), Some(Val::Int(k))));
                        }
                        self.exec(body, fr)?;
                    }
                }
            }
        }
        Ok(())
    }

    fn assign(&mut self, n: &str, idx: Option<i64>, v: Val, fr: &mut Frame) -> Result<(), Fail> {
        if let Some(f) = fr.as_mut() {
            if let Some((ty, slot)) = f.get_mut(n) {
                self.check_type(ty, &v, n)?;
                *slot = Some(v);
                return Ok(());
            }
        }
        let Some(d) = self.m.decl(n) else {
            return error(format!("assignment to undeclared `{n}`"));
        };
        if d.prefix.as_deref() == Some("input") || d.binding.is_some() {
            return error(format!("assignment to `{n}`, which is not a variable"));
        }
        self.check_type(&d.ty, &v, n)?;
        if let Val::Int(x) = v {
            for (k, e) in &d.mods {
                let bound = match self.eval(e, &mut None)? {
                    Val::Int(b) => b,
                    _ => continue,
                };
                if (k == "min" && x < bound) || (k == "max" && x > bound) {
                    return error(format!("`{n}` = {x} violates {k} = {bound}"));
                }
            }
        }
        let i = match (idx, d.size) {
            (None, None) => 0,
            (Some(i), Some(s)) if i >= 1 && (i as usize) <= s => i as usize - 1,
            _ => return error(format!("bad index {idx:?} of `{n}`")),
        };
        if let Some(cell) = self.vars.get_mut(n).and_then(|a| a.get_mut(i)) {
            *cell = v;
        }
        Ok(())
    }

    fn cond(&mut self, e: &Expr, fr: &mut Frame) -> Result<bool, Fail> {
        match self.eval(e, fr)? {
            Val::Bool(b) => Ok(b),
            x => error(format!("condition {x:?} is not Boolean")),
        }
    }

    fn int(&mut self, e: &Expr, fr: &mut Frame) -> Result<i64, Fail> {
        match self.eval(e, fr)? {
            Val::Int(x) => Ok(x),
            x => error(format!("{x:?} is not an Integer")),
        }
    }

    fn eval(&mut self, e: &Expr, fr: &mut Frame) -> Result<Val, Fail> {
        Ok(match e {
            Expr::Int(v) => Val::Int(*v),
            Expr::Bool(b) => Val::Bool(*b),
            Expr::Str(s) => Val::Str(s.clone()),
            Expr::Lit(t, l) => match self
                .m
                .types
                .get(t)
                .and_then(|ls| ls.iter().position(|x| x == l))
            {
                Some(k) => Val::Enum(t.clone(), k),
                None => return error(format!("no literal {t}.{l}")),
            },
            Expr::Name(n) => {
                if let Some(f) = fr.as_ref() {
                    if let Some((_, v)) = f.get(n) {
                        return v
                            .clone()
                            .ok_or_else(|| Fail::Error(format!("`{n}` read before assignment")));
                    }
                }
                match self.vars.get(n) {
                    Some(a) if a.len() == 1 && self.m.decl(n).is_some_and(|d| d.size.is_none()) => {
                        a[0].clone()
                    }
                    _ => return error(format!("no scalar `{n}`")),
                }
            }
            Expr::Index(n, i) => {
                let i = self.int(i, fr)?;
                match self.vars.get(n).and_then(|a| a.get((i - 1) as usize)) {
                    Some(v) if i >= 1 => v.clone(),
                    _ => return error(format!("bad index {n}[{i}]")),
                }
            }
            Expr::Neg(a) => Val::Int(
                self.int(a, fr)?
                    .checked_neg()
                    .ok_or(Fail::Error("overflow".into()))?,
            ),
            Expr::Not(a) => Val::Bool(!self.cond(a, fr)?),
            Expr::If(arms, otherwise) => {
                let mut ty = None;
                let mut out = None;
                for (c, v) in arms {
                    if out.is_none() && self.cond(c, fr)? {
                        out = Some(self.eval(v, fr)?);
                    }
                    ty = Some(self.type_of(v, fr)?);
                }
                let t2 = self.type_of(otherwise, fr)?;
                if ty.as_ref().is_some_and(|t| *t != t2) {
                    return error(format!("if-expression branches of types {ty:?} and {t2}"));
                }
                match out {
                    Some(v) => v,
                    None => self.eval(otherwise, fr)?,
                }
            }
            Expr::Bin(op, a, b) => {
                // Both sides are evaluated: a Modelica tool need not short-circuit.
                let (x, y) = (self.eval(a, fr)?, self.eval(b, fr)?);
                binary(op, x, y)?
            }
            Expr::Call(f, args) => {
                let mut vals = Vec::new();
                for a in args {
                    vals.push(self.eval(a, fr)?);
                }
                self.call(f, vals)?
            }
        })
    }

    /// The type of an expression without evaluating it (for if-expression branches).
    fn type_of(&mut self, e: &Expr, fr: &mut Frame) -> Result<String, Fail> {
        Ok(match e {
            Expr::Int(_) | Expr::Neg(_) => "Integer".into(),
            Expr::Bool(_) | Expr::Not(_) => "Boolean".into(),
            Expr::Str(_) => "String".into(),
            Expr::Lit(t, _) => t.clone(),
            Expr::Name(n) | Expr::Index(n, _) => match fr.as_ref().and_then(|f| f.get(n)) {
                Some((t, _)) => t.clone(),
                None => self.m.decl(n).map_or(String::new(), |d| d.ty.clone()),
            },
            Expr::Bin(op, a, _) => match *op {
                "+" => self.type_of(a, fr)?,
                "-" | "*" => "Integer".into(),
                _ => "Boolean".into(),
            },
            Expr::If(_, o) => self.type_of(o, fr)?,
            Expr::Call(f, _) => match self.m.functions.get(f) {
                Some(func) => func.output.0.clone(),
                None if f == "String" => "String".into(),
                None => "Integer".into(),
            },
        })
    }

    fn call(&mut self, f: &str, args: Vec<Val>) -> Result<Val, Fail> {
        let ints = |args: &[Val]| -> Result<Vec<i64>, Fail> {
            args.iter()
                .map(|a| match a {
                    Val::Int(x) => Ok(*x),
                    x => error(format!("{f}: argument {x:?}")),
                })
                .collect()
        };
        let two = |args: &[Val]| -> Result<(i64, i64), Fail> {
            match ints(args)?.as_slice() {
                [a, b] => Ok((*a, *b)),
                _ => error(format!("{f}: two arguments")),
            }
        };
        Ok(match f {
            "min" => {
                let (a, b) = two(&args)?;
                Val::Int(a.min(b))
            }
            "max" => {
                let (a, b) = two(&args)?;
                Val::Int(a.max(b))
            }
            "abs" => match ints(&args)?.as_slice() {
                [a] => Val::Int(a.checked_abs().ok_or(Fail::Error("overflow".into()))?),
                _ => return error("abs".into()),
            },
            "div" | "rem" | "mod" => {
                let (a, b) = two(&args)?;
                if b == 0 {
                    return error(format!("{f}({a}, 0)"));
                }
                Val::Int(match f {
                    "div" => a / b,
                    "rem" => a % b,
                    _ => a.rem_euclid(b),
                })
            }
            "Integer" => match args.as_slice() {
                [Val::Enum(_, k)] => Val::Int(*k as i64 + 1),
                _ => return error(format!("Integer({args:?})")),
            },
            "String" => match args.as_slice() {
                [Val::Int(x)] => Val::Str(x.to_string()),
                _ => return error(format!("String({args:?})")),
            },
            _ => {
                let Some(func) = self.m.functions.get(f) else {
                    return error(format!("no function `{f}`"));
                };
                if func.inputs.len() != args.len() {
                    return error(format!("{f}: {} arguments", args.len()));
                }
                let mut frame = BTreeMap::new();
                for ((ty, n), v) in func.inputs.iter().zip(args) {
                    self.check_type(ty, &v, n)?;
                    frame.insert(n.clone(), (ty.clone(), Some(v)));
                }
                for (ty, n) in func.locals.iter().chain(std::iter::once(&func.output)) {
                    frame.insert(n.clone(), (ty.clone(), None));
                }
                let mut fr = Some(frame);
                let body = func.body.clone();
                self.exec(&body, &mut fr)?;
                let out = fr
                    .and_then(|mut f| f.remove(&func.output.1))
                    .and_then(|(_, v)| v);
                out.ok_or_else(|| Fail::Error(format!("{f}: output not assigned")))?
            }
        })
    }
}

/// Locals of a function call: name -> (type, value once assigned).
type Frame = Option<BTreeMap<String, (String, Option<Val>)>>;

fn binary(op: &str, x: Val, y: Val) -> Result<Val, Fail> {
    let overflow = || Fail::Error("overflow".into());
    Ok(match (op, x, y) {
        ("+", Val::Int(a), Val::Int(b)) => Val::Int(a.checked_add(b).ok_or_else(overflow)?),
        ("+", Val::Str(a), Val::Str(b)) => Val::Str(a + &b),
        ("-", Val::Int(a), Val::Int(b)) => Val::Int(a.checked_sub(b).ok_or_else(overflow)?),
        ("*", Val::Int(a), Val::Int(b)) => Val::Int(a.checked_mul(b).ok_or_else(overflow)?),
        ("and", Val::Bool(a), Val::Bool(b)) => Val::Bool(a && b),
        ("or", Val::Bool(a), Val::Bool(b)) => Val::Bool(a || b),
        (op, x, y) => {
            let ord = match (&x, &y) {
                (Val::Int(a), Val::Int(b)) => a.cmp(b),
                (Val::Bool(a), Val::Bool(b)) if op == "==" || op == "<>" => a.cmp(b),
                (Val::Enum(s, a), Val::Enum(t, b)) if s == t => a.cmp(b),
                _ => return error(format!("`{op}` on {x:?} and {y:?}")),
            };
            use std::cmp::Ordering::*;
            Val::Bool(match op {
                "==" => ord == Equal,
                "<>" => ord != Equal,
                "<" => ord == Less,
                "<=" => ord != Greater,
                ">" => ord == Greater,
                ">=" => ord != Less,
                _ => return error(format!("operator `{op}`")),
            })
        }
    })
}
