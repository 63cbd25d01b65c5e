//! Top-level items, charts, systems, declarations and properties.

use super::body::is_body_kw;
use super::{is_chart_elem_kw, is_item_kw, is_system_kw, Failed, PResult, Parser};
use crate::ast::{
    Assume, Chart, ConstDecl, Control, EnumDecl, Expr, File, FnDecl, Ident, Instance, Item,
    OrderDecl, Param, Property, PropertyKind, Rename, RequirementKind, StateBody, StateRequirement,
    System, TickDecl, VarDecl, VarKind,
};
use crate::lexer::{Kw, Tok};
use statecheck_base::{Diagnostic, Span};

const ITEM_EXPECTED: &str =
    "an item (`import`, `const`, `enum`, `fn`, `chart`, `system` or `tick`)";

impl Parser<'_> {
    /// `file = { item }`
    pub(super) fn file(&mut self) -> File {
        let mut items = Vec::new();
        loop {
            let t = self.tok();
            let start = self.pos;
            match t.kind {
                Tok::Eof => break,
                Tok::Ident if self.text(t.span) == "import" => match self.import_decl() {
                    Ok(item) => items.push(crate::ast::Item::Import(item)),
                    Err(Failed) => self.recover(),
                },
                Tok::Ident
                    if self.text(t.span) == "interface"
                        && self.nth(1).kind == Tok::Ident
                        && self.nth(2).kind == Tok::LBrace =>
                {
                    match self.interface() {
                        Ok(item) => items.push(crate::ast::Item::Interface(item)),
                        Err(Failed) => self.recover(),
                    }
                }
                Tok::Ident if self.at_component() => match self.component() {
                    Ok(item) => items.push(crate::ast::Item::Component(item)),
                    Err(Failed) => self.recover(),
                },
                Tok::RBrace => {
                    let d = Diagnostic::error("E0010", "unmatched `}`", t.span)
                        .with_label("no open `{` to close");
                    self.report(d);
                    self.bump();
                }
                k if is_item_kw(k) => match self.item() {
                    Ok(item) => items.push(item),
                    Err(Failed) => self.recover(),
                },
                k => {
                    let hint = if k == Tok::Kw(Kw::Observer) {
                        Some("observers are declared inside a `system { … }`".to_string())
                    } else if is_chart_elem_kw(k) {
                        Some("this belongs inside a `chart { … }`".to_string())
                    } else if is_system_kw(k) {
                        Some("this belongs inside a `system { … }`".to_string())
                    } else {
                        None
                    };
                    self.unexpected(ITEM_EXPECTED, hint);
                }
            }
            if self.pos == start && !self.at(Tok::Eof) {
                self.bump();
            }
        }
        File { items }
    }

    fn item(&mut self) -> PResult<Item> {
        match self.peek() {
            Tok::Kw(Kw::Const) => self.const_decl().map(Item::Const),
            Tok::Kw(Kw::Enum) => self.enum_decl().map(Item::Enum),
            Tok::Kw(Kw::Fn) => self.fn_decl().map(Item::Fn),
            Tok::Kw(Kw::Tick) => {
                let start = self.bump().span;
                let duration = self.duration();
                self.expect_semi("after the `tick` declaration");
                Ok(Item::Tick(TickDecl {
                    duration,
                    span: self.span_from(start),
                }))
            }
            Tok::Kw(Kw::System) => self.system().map(Item::System),
            _ => self.chart().map(Item::Chart),
        }
    }

    /// `'const' IDENT [ ':' type ] '=' expr ';'`
    fn const_decl(&mut self) -> PResult<ConstDecl> {
        let start = self.bump().span;
        let name = self.expect_ident("a constant name after `const`")?;
        let ty = if self.eat(Tok::Colon).is_some() {
            Some(self.ty()?)
        } else {
            None
        };
        self.expect(Tok::Assign, "before the constant's value")?;
        let value = self.expr();
        self.expect_semi("after the constant declaration");
        Ok(ConstDecl {
            name,
            ty,
            value,
            span: self.span_from(start),
        })
    }

    /// `'enum' IDENT '{' IDENT { ',' IDENT } [ ',' ] '}'`
    fn enum_decl(&mut self) -> PResult<EnumDecl> {
        let start = self.bump().span;
        let name = self.expect_ident("an enum name after `enum`")?;
        let open = self.expect(Tok::LBrace, "after the enum name")?;
        let mut variants = Vec::new();
        loop {
            let t = self.peek();
            if t == Tok::RBrace {
                if variants.is_empty() {
                    let d = Diagnostic::error(
                        "E0010",
                        format!("enum `{}` has no variants", name.name),
                        self.tok().span,
                    )
                    .with_label("expected at least one variant name")
                    .with_hint(format!("e.g. `enum {} {{ A, B }}`", name.name));
                    self.report(d);
                }
                self.bump();
                break;
            }
            if t == Tok::Eof || super::is_sync_kw(t) {
                self.unclosed(open, &format!("enum `{}`", name.name));
                break;
            }
            if t != Tok::Ident {
                let d = self.expected_diag("an enum variant name");
                self.report(d);
                self.skip_group();
                self.eat(Tok::Comma);
                continue;
            }
            let v = self.bump();
            variants.push(self.ident_of(v));
            if self.eat(Tok::Comma).is_some() || self.at(Tok::RBrace) {
                continue;
            }
            let d = self.expected_diag("`,` or `}` after an enum variant");
            self.report(d);
            if !self.at(Tok::Ident) {
                self.skip_group();
            }
        }
        Ok(EnumDecl {
            name,
            variants,
            span: self.span_from(start),
        })
    }

    /// `'fn' IDENT '(' [ param { ',' param } ] ')' '->' type ( '=' expr ';' | '{' … '}' )`
    fn fn_decl(&mut self) -> PResult<FnDecl> {
        let start = self.bump().span;
        let name = self.expect_ident("a function name after `fn`")?;
        let open = self.expect(Tok::LParen, "after the function name")?;
        let mut params = Vec::new();
        if self.eat(Tok::RParen).is_none() {
            loop {
                let pname = self.expect_ident("a parameter name")?;
                if self.eat(Tok::Colon).is_none() {
                    let d = self
                        .expected_diag("`:` after the parameter name")
                        .with_hint(format!(
                            "parameters need a type, e.g. `{}: int`",
                            pname.name
                        ));
                    self.report(d);
                    return Err(Failed);
                }
                let ty = self.ty()?;
                params.push(Param { name: pname, ty });
                if self.eat(Tok::Comma).is_some() {
                    continue;
                }
                if !self.close(Tok::RParen, open, "the parameter list") {
                    return Err(Failed);
                }
                break;
            }
        }
        if self.eat(Tok::Arrow).is_none() {
            let mut d = self.expected_diag("`->` and the return type after the parameters");
            if self.at(Tok::Colon) {
                d = d.with_hint("the return type follows `->`: `fn f(x: int) -> int …`");
            } else {
                d = d.with_hint("functions must declare their return type: `-> int`");
            }
            self.report(d);
            return Err(Failed);
        }
        let ret = self.ty()?;
        let mut lets = Vec::new();
        let body = if self.eat(Tok::Assign).is_some() {
            let e = self.expr();
            self.expect_semi("after the function body");
            e
        } else if self.at(Tok::LBrace) {
            self.fn_body(&name, &mut lets)
        } else {
            return Err(self.expected("`=` or `{` after the return type"));
        };
        Ok(FnDecl {
            name,
            params,
            ret,
            lets,
            body,
            span: self.span_from(start),
        })
    }

    /// `'{' { 'let' IDENT '=' expr ';' } 'return' expr ';' '}'` at the current `{`.
    fn fn_body(&mut self, name: &Ident, lets: &mut Vec<(Ident, Expr)>) -> Expr {
        let open = self.bump().span;
        let what = format!("the body of function `{}`", name.name);
        let mut ret: Option<Expr> = None;
        let outer = |t: Tok| super::is_sync_kw(t) && !matches!(t, Tok::Kw(Kw::Let | Kw::Return));
        loop {
            if self.at_list_end(open, &what, outer) {
                break;
            }
            let start = self.pos;
            if ret.is_some() {
                let d = self
                    .expected_diag("`}` after `return`")
                    .with_hint("`return` must be the last statement of a function body");
                self.report(d);
            }
            match self.peek() {
                Tok::Kw(Kw::Let) => {
                    self.bump();
                    if let Ok(x) = self.expect_ident("a name after `let`") {
                        if self.expect(Tok::Assign, "after the `let` name").is_ok() {
                            let e = self.expr();
                            self.expect_semi("after `let`");
                            lets.push((x, e));
                            continue;
                        }
                    }
                    self.recover();
                }
                Tok::Kw(Kw::Return) => {
                    self.bump();
                    let e = self.expr();
                    self.expect_semi("after `return`");
                    ret = Some(e);
                }
                t => {
                    let hint = match (t, self.nth(1).kind) {
                        (Tok::Ident, Tok::Assign) => {
                            Some("local bindings are written `let x = …;`".to_string())
                        }
                        (Tok::Kw(Kw::If), _) => Some(
                            "use an `if c then a else b` expression in `let` or `return`"
                                .to_string(),
                        ),
                        _ => Some("a function body is `let` bindings and one `return`".into()),
                    };
                    self.unexpected("`let` or `return`", hint);
                }
            }
            if self.pos == start {
                self.bump();
            }
        }
        match ret {
            Some(e) => e,
            None => {
                let end = self.missing_span();
                let d = Diagnostic::error(
                    "E0020",
                    format!("missing `return` in function `{}`", name.name),
                    Span::new(open.start as usize, end.end as usize),
                )
                .with_label("this body returns nothing")
                .with_hint("end the body with `return expr;`");
                self.diags.push(d);
                Expr::Error(end)
            }
        }
    }

    /// `[ 'plant' | 'requirement' ] 'chart' IDENT [ '(' params ')' ] '{' { chart_elem } '}'`
    fn chart(&mut self) -> PResult<Chart> {
        let start = self.tok().span;
        let role = if self.at_kw(Kw::Plant) || self.at_kw(Kw::Requirement) {
            let t = self.bump();
            let role = self.ident_of(t);
            if !self.at_kw(Kw::Chart) {
                let d = self.expected_diag(&format!("`chart` after `{}`", role.name));
                self.report(d);
                return Err(Failed);
            }
            Some(role)
        } else {
            None
        };
        self.bump();
        let name = self.expect_ident("a chart name after `chart`")?;
        let params = if self.at(Tok::LParen) {
            self.chart_params()?
        } else {
            Vec::new()
        };
        let mut implements = Vec::new();
        if self.at(Tok::Ident) && self.text(self.tok().span) == "implements" {
            self.bump();
            implements.push(self.expect_ident("an interface name after `implements`")?);
            while self.eat(Tok::Comma).is_some() {
                implements.push(self.expect_ident("an interface name after `,`")?);
            }
        }
        let open = self.expect(Tok::LBrace, "after the chart name")?;
        let mut chart = Chart {
            name,
            role,
            params,
            implements,
            vars: Vec::new(),
            body: StateBody::default(),
            properties: Vec::new(),
            span: start,
        };
        let what = format!("chart `{}`", chart.name.name);
        self.chart_elems(&mut chart, open, &what, is_item_kw);
        chart.span = self.span_from(start);
        Ok(chart)
    }

    /// The elements of a chart (or observer) body after its `{`.
    fn chart_elems(&mut self, chart: &mut Chart, open: Span, what: &str, outer: fn(Tok) -> bool) {
        loop {
            if self.at_list_end(open, what, outer) {
                break;
            }
            let start = self.pos;
            let t = self.peek();
            let r = match t {
                Tok::Ident if self.at_hybrid_elem() => {
                    self.hybrid_elem().map(|h| chart.body.hybrid.push(h))
                }
                Tok::Ident if self.at_temporal_decl() => {
                    self.temporal_property().map(|p| chart.properties.push(p))
                }
                Tok::Kw(Kw::Input | Kw::Output | Kw::Local) => {
                    self.var_decl().map(|v| chart.vars.push(v))
                }
                Tok::Kw(Kw::Controllable | Kw::Uncontrollable) => {
                    self.event_decl().map(|v| chart.vars.push(v))
                }
                Tok::Kw(Kw::Invariant | Kw::Reachable | Kw::Respond) => {
                    self.property().map(|p| chart.properties.push(p))
                }
                Tok::Kw(Kw::Parallel) => self.parallel(&mut chart.body),
                t if is_body_kw(t) => self.body_elem(&mut chart.body),
                t if is_system_kw(t) => {
                    let kw = self.text(self.tok().span).to_string();
                    let d = Diagnostic::error(
                        "E0017",
                        format!("`{kw}` is only allowed in a system"),
                        self.tok().span,
                    )
                    .with_label("inside a chart")
                    .with_hint("move it into a `system { … }`");
                    self.report(d);
                    self.bump();
                    Err(Failed)
                }
                _ => {
                    let hint = self.body_hint();
                    self.unexpected(
                        "a chart element (a declaration, `state`, `on`, `initial`, …)",
                        hint,
                    );
                    Ok(())
                }
            };
            if r.is_err() {
                self.recover();
            }
            if self.pos == start {
                self.bump();
            }
        }
    }

    /// `( 'input' | 'output' | 'local' ) ( 'event' IDENT | IDENT ':' type [ '=' expr ] ) ';'`
    pub(super) fn var_decl(&mut self) -> PResult<VarDecl> {
        let t = self.bump();
        let kind = match t.kind {
            Tok::Kw(Kw::Input) => VarKind::Input,
            Tok::Kw(Kw::Output) => VarKind::Output,
            _ => VarKind::Local,
        };
        let kw = self.text(t.span).to_string();
        let decl = if self.eat_kw(Kw::Event).is_some() {
            let name = self.expect_ident("an event name after `event`")?;
            VarDecl {
                kind,
                is_event: true,
                name,
                len: None,
                ty: None,
                init: None,
                control: None,
                span: t.span,
            }
        } else {
            let name = self.expect_ident(&format!("a variable name or `event` after `{kw}`"))?;
            let len = if self.eat(Tok::LBracket).is_some() {
                let n = self.expr();
                if self.eat(Tok::RBracket).is_none() {
                    let d = self
                        .expected_diag("`]` after the array length")
                        .with_hint(format!("write `{kw} {}[N]: int[0..9];`", name.name));
                    self.report(d);
                    return Err(Failed);
                }
                Some(n)
            } else {
                None
            };
            if self.eat(Tok::Colon).is_none() {
                let d = self
                    .expected_diag("`:` and a type after the variable name")
                    .with_hint(format!(
                        "write `{kw} {0}: int[0..9];`, or `{kw} event {0};` for an event",
                        name.name
                    ));
                self.report(d);
                return Err(Failed);
            }
            let ty = self.ty()?;
            let init = if self.eat(Tok::Assign).is_some() {
                Some(self.expr())
            } else {
                None
            };
            VarDecl {
                kind,
                is_event: false,
                name,
                len,
                ty: Some(ty),
                init,
                control: None,
                span: t.span,
            }
        };
        self.expect_semi("after the variable declaration");
        Ok(VarDecl {
            span: self.span_from(t.span),
            ..decl
        })
    }

    /// `( 'controllable' | 'uncontrollable' ) 'event' IDENT ';'`: an input event with a
    /// controllability, for synthesis.
    fn event_decl(&mut self) -> PResult<VarDecl> {
        let t = self.bump();
        let control = if t.kind == Tok::Kw(Kw::Controllable) {
            Control::Controllable
        } else {
            Control::Uncontrollable
        };
        let kw = self.text(t.span).to_string();
        if self.eat_kw(Kw::Event).is_none() {
            return Err(self.expected(&format!("`event` after `{kw}`")));
        }
        let name = self.expect_ident("an event name after `event`")?;
        self.expect_semi("after the event declaration");
        Ok(VarDecl {
            kind: VarKind::Input,
            is_event: true,
            name,
            len: None,
            ty: None,
            init: None,
            control: Some(control),
            span: self.span_from(t.span),
        })
    }

    /// `'requirement' ( 'never' expr | IDENT 'needs' expr ) ';'` inside a system.
    fn state_requirement(&mut self) -> PResult<StateRequirement> {
        let start = self.bump().span;
        if !self.at(Tok::Ident) {
            return Err(self.expected("`never` or an event name after `requirement`"));
        }
        let first = self.bump();
        let first = self.ident_of(first);
        let kind = if first.name == "never" {
            RequirementKind::Never(self.expr())
        } else {
            let ok = self.at(Tok::Ident) && self.text(self.tok().span) == "needs";
            if !ok {
                let d = self
                    .expected_diag("`needs` after the event name")
                    .with_hint(
                        "write `requirement never (cond);` or `requirement e needs (cond);`",
                    );
                self.report(d);
                return Err(Failed);
            }
            self.bump();
            RequirementKind::Needs {
                event: first,
                cond: self.expr(),
            }
        };
        self.expect_semi("after the requirement");
        Ok(StateRequirement {
            kind,
            span: self.span_from(start),
        })
    }

    /// `property = 'invariant' … | 'reachable' … | 'respond' …`
    fn property(&mut self) -> PResult<Property> {
        let t = self.bump();
        let kw = self.text(t.span).to_string();
        let example = match t.kind {
            Tok::Kw(Kw::Invariant) => "invariant NAME: expr [assuming expr];",
            Tok::Kw(Kw::Reachable) => "reachable NAME: expr;",
            _ => "respond NAME: trigger => response [within N];",
        };
        let name = self.expect_ident(&format!("a property name after `{kw}`"))?;
        if self.eat(Tok::Colon).is_none() {
            let d = self
                .expected_diag("`:` after the property name")
                .with_hint(format!("properties are named: `{example}`"));
            self.report(d);
            return Err(Failed);
        }
        let kind = match t.kind {
            Tok::Kw(Kw::Invariant) => {
                let expr = self.expr();
                let assuming = if self.eat_kw(Kw::Assuming).is_some() {
                    Some(self.expr())
                } else {
                    None
                };
                PropertyKind::Invariant { expr, assuming }
            }
            Tok::Kw(Kw::Reachable) => PropertyKind::Reachable { expr: self.expr() },
            _ => {
                let trigger = self.expr();
                if self.eat(Tok::FatArrow).is_none() {
                    let d = self
                        .expected_diag("`=>` after the trigger of `respond`")
                        .with_hint(format!("write `{example}`"));
                    self.report(d);
                    return Err(Failed);
                }
                let response = self.expr();
                if self.at(Tok::Semi) {
                    // No bound: the response must come eventually (liveness).
                    self.expect_semi("after the property");
                    return Ok(Property {
                        name,
                        kind: PropertyKind::RespondEventually { trigger, response },
                        span: self.span_from(t.span),
                    });
                }
                if self.eat_kw(Kw::Within).is_none() {
                    let d = self
                        .expected_diag("`within` and a tick bound, or `;`, after the response")
                        .with_hint(format!("write `{example}`"));
                    self.report(d);
                    return Err(Failed);
                }
                let within = self.delay();
                PropertyKind::Respond {
                    trigger,
                    response,
                    within,
                }
            }
        };
        self.expect_semi("after the property");
        Ok(Property {
            name,
            kind,
            span: self.span_from(t.span),
        })
    }

    /// `'system' IDENT [ 'interleaved' ] '{' { sys_elem } '}'`
    fn system(&mut self) -> PResult<System> {
        let start = self.bump().span;
        let name = self.expect_ident("a system name after `system`")?;
        let interleaved = self.at(Tok::Ident) && self.text(self.tok().span) == "interleaved";
        if interleaved {
            self.bump();
        }
        let open = self.expect(Tok::LBrace, "after the system name")?;
        let what = format!("system `{}`", name.name);
        let mut sys = System {
            name,
            instances: Vec::new(),
            connections: Vec::new(),
            order: Vec::new(),
            assumes: Vec::new(),
            rates: Vec::new(),
            properties: Vec::new(),
            observers: Vec::new(),
            requirements: Vec::new(),
            configurations: Vec::new(),
            interleaved,
            span: start,
        };
        self.system_elems(&mut sys, open, &what, None);
        sys.span = self.span_from(start);
        Ok(sys)
    }

    /// The elements of a system (or, with `ports`, a component) body after its `{`; a
    /// component's `input`/`output` declarations go to `ports`.
    pub(super) fn system_elems(
        &mut self,
        sys: &mut System,
        open: Span,
        what: &str,
        mut ports: Option<&mut Vec<VarDecl>>,
    ) {
        loop {
            if self.at_kw(Kw::Requirement) && self.nth(1).kind != Tok::Kw(Kw::Chart) {
                let pos = self.pos;
                match self.state_requirement() {
                    Ok(r) => sys.requirements.push(r),
                    Err(Failed) => self.recover(),
                }
                if self.pos == pos {
                    self.bump();
                }
                continue;
            }
            if self.at_list_end(open, what, is_item_kw) {
                break;
            }
            let pos = self.pos;
            let t = self.peek();
            let r = match t {
                Tok::Kw(Kw::Input | Kw::Output) if ports.is_some() => self.var_decl().map(|v| {
                    if let Some(p) = ports.as_deref_mut() {
                        p.push(v);
                    }
                }),
                Tok::Ident if self.at_temporal_decl() => {
                    self.temporal_property().map(|p| sys.properties.push(p))
                }
                Tok::Ident if self.at_rate_decl() => self.rate().map(|r| sys.rates.push(r)),
                Tok::Ident
                    if self.text(self.tok().span) == "configuration"
                        && self.nth(1).kind == Tok::Ident
                        && self.nth(2).kind == Tok::LBrace =>
                {
                    self.configuration().map(|c| sys.configurations.push(c))
                }
                Tok::Kw(Kw::Instance) => self.instance().map(|i| sys.instances.push(i)),
                Tok::Kw(Kw::Connect) => self.connection().map(|c| sys.connections.push(c)),
                Tok::Kw(Kw::Order) => self.order().map(|o| sys.order.push(o)),
                Tok::Kw(Kw::Assume) => {
                    let s = self.bump().span;
                    let expr = self.expr();
                    self.expect_semi("after `assume`");
                    sys.assumes.push(Assume {
                        expr,
                        span: self.span_from(s),
                    });
                    Ok(())
                }
                Tok::Kw(Kw::Invariant | Kw::Reachable | Kw::Respond) => {
                    self.property().map(|p| sys.properties.push(p))
                }
                Tok::Kw(Kw::Observer) => self.observer().map(|c| sys.observers.push(c)),
                t if is_chart_elem_kw(t) => {
                    let kw = self.text(self.tok().span).to_string();
                    let d = Diagnostic::error(
                        "E0017",
                        format!("`{kw}` is not allowed directly in a system"),
                        self.tok().span,
                    )
                    .with_label("inside a system")
                    .with_hint(
                        "states, transitions and variables belong in a `chart` or an `observer`",
                    );
                    self.report(d);
                    self.skip_group();
                    Err(Failed)
                }
                _ => {
                    self.unexpected(
                        "a system element (`instance`, `connect`, `order`, `assume`, `rate`, a property or `observer`)",
                        None,
                    );
                    Ok(())
                }
            };
            if r.is_err() {
                self.recover();
            }
            if self.pos == pos {
                self.bump();
            }
        }
    }

    /// `'instance' IDENT [ '[' expr ']' ] ':' IDENT [ '(' args ')' ] ( ';' | renames [ ';' ] )`
    fn instance(&mut self) -> PResult<Instance> {
        let start = self.bump().span;
        let name = self.expect_ident("an instance name after `instance`")?;
        let count = if let Some(open) = self.eat(Tok::LBracket) {
            let e = self.expr();
            if !self.close(Tok::RBracket, open, "the instance count's `[`") {
                return Err(Failed);
            }
            Some(e)
        } else {
            None
        };
        self.expect(Tok::Colon, "before the chart name")?;
        let chart = self.expect_ident("a chart name")?;
        let args = if self.at(Tok::LParen) {
            self.instance_args()?
        } else {
            Vec::new()
        };
        let renames = if self.at(Tok::LBrace) {
            let renames = self.renames()?;
            self.eat(Tok::Semi);
            renames
        } else {
            self.expect_semi("after the instance declaration");
            Vec::new()
        };
        Ok(Instance {
            name,
            count,
            chart,
            args,
            renames,
            span: self.span_from(start),
        })
    }

    /// `'{' { IDENT '->' IDENT ';' } '}'`: an instance's event renames.
    fn renames(&mut self) -> PResult<Vec<Rename>> {
        let open = self.bump().span;
        let mut renames = Vec::new();
        loop {
            if self.at_list_end(open, "the instance's renames", is_item_kw) {
                return Ok(renames);
            }
            let start = self.tok().span;
            let event = self.expect_ident("the event to rename (`take -> take1;`)")?;
            self.expect(Tok::Arrow, "between the event and its new name")?;
            let to = self.expect_ident("the event's new name after `->`")?;
            self.expect_semi("after the rename");
            renames.push(Rename {
                event,
                to,
                span: self.span_from(start),
            });
        }
    }

    /// `'connect' path '->' path ';'`
    fn connection(&mut self) -> PResult<crate::ast::Connection> {
        let start = self.bump().span;
        if !self.at(Tok::Ident) {
            return Err(self.expected("the source port after `connect`"));
        }
        let from = self.path()?;
        if self.eat(Tok::Arrow).is_none() {
            let d = self
                .expected_diag("`->` between the connected ports")
                .with_hint("write `connect a.out -> b.in;`");
            self.report(d);
            return Err(Failed);
        }
        if !self.at(Tok::Ident) {
            return Err(self.expected("the destination port after `->`"));
        }
        let to = self.path()?;
        self.expect_semi("after the connection");
        Ok(crate::ast::Connection {
            from,
            to,
            span: self.span_from(start),
        })
    }

    /// `'order' IDENT { ',' IDENT } ';'`
    fn order(&mut self) -> PResult<OrderDecl> {
        let start = self.bump().span;
        let mut instances = vec![self.expect_ident("an instance name after `order`")?];
        while self.eat(Tok::Comma).is_some() {
            instances.push(self.expect_ident("an instance name after `,`")?);
        }
        self.expect_semi("after the `order` list");
        Ok(OrderDecl {
            instances,
            span: self.span_from(start),
        })
    }

    /// `'observer' IDENT '{' { chart_elem } '}'`
    fn observer(&mut self) -> PResult<Chart> {
        let kw = self.bump();
        let role = self.ident_of(kw);
        let name = self.expect_ident("an observer name after `observer`")?;
        let open = self.expect(Tok::LBrace, "after the observer name")?;
        let what = format!("observer `{}`", name.name);
        let mut chart = Chart {
            name,
            role: Some(role),
            params: Vec::new(),
            implements: Vec::new(),
            vars: Vec::new(),
            body: StateBody::default(),
            properties: Vec::new(),
            span: kw.span,
        };
        let outer = |t: Tok| is_item_kw(t) || is_system_kw(t);
        self.chart_elems(&mut chart, open, &what, outer);
        chart.span = self.span_from(kw.span);
        Ok(chart)
    }
}
