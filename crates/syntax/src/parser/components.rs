//! Components: chart parameters and instance arguments, `interface` declarations, and a
//! system's `configuration`s with their slot bindings (docs/components.md).

use super::{is_item_kw, Failed, PResult, Parser};
use crate::ast::{Arg, Binding, ChartParam, Component, Configuration, InterfaceDecl, System};
use crate::lexer::{Kw, Tok};

impl Parser<'_> {
    /// `'(' [ IDENT ':' type [ '=' expr ] { ',' … } ] ')'` after a chart's name.
    pub(super) fn chart_params(&mut self) -> PResult<Vec<ChartParam>> {
        let open = self.bump().span;
        let mut params = Vec::new();
        if self.eat(Tok::RParen).is_some() {
            return Ok(params);
        }
        loop {
            let name = self.expect_ident("a parameter name")?;
            if self.eat(Tok::Colon).is_none() {
                let d = self
                    .expected_diag("`:` after the parameter name")
                    .with_hint(format!(
                        "chart parameters need a type, e.g. `{}: int`",
                        name.name
                    ));
                self.report(d);
                return Err(Failed);
            }
            let ty = self.ty()?;
            let default = if self.eat(Tok::Assign).is_some() {
                Some(self.expr())
            } else {
                None
            };
            let span = self.span_from(name.span);
            params.push(ChartParam {
                name,
                ty,
                default,
                span,
            });
            if self.eat(Tok::Comma).is_some() {
                continue;
            }
            if !self.close(Tok::RParen, open, "the parameter list") {
                return Err(Failed);
            }
            return Ok(params);
        }
    }

    /// `'(' [ arg { ',' arg } ] ')'` after an instance's chart, `arg = [ IDENT '=' ] expr`.
    pub(super) fn instance_args(&mut self) -> PResult<Vec<Arg>> {
        let open = self.bump().span;
        let mut args = Vec::new();
        if self.eat(Tok::RParen).is_some() {
            return Ok(args);
        }
        loop {
            let start = self.tok().span;
            let name = if self.at(Tok::Ident) && self.nth(1).kind == Tok::Assign {
                let t = self.bump();
                self.bump();
                Some(self.ident_of(t))
            } else {
                None
            };
            let value = self.expr();
            args.push(Arg {
                name,
                value,
                span: self.span_from(start),
            });
            if self.eat(Tok::Comma).is_some() {
                continue;
            }
            if !self.close(Tok::RParen, open, "the argument list") {
                return Err(Failed);
            }
            return Ok(args);
        }
    }

    /// `'interface' IDENT '{' { ( 'input' | 'output' ) var_decl } '}'`
    pub(super) fn interface(&mut self) -> PResult<InterfaceDecl> {
        let start = self.bump().span;
        let name = self.expect_ident("an interface name after `interface`")?;
        let open = self.expect(Tok::LBrace, "after the interface name")?;
        let what = format!("interface `{}`", name.name);
        let mut members = Vec::new();
        loop {
            if self.at_list_end(open, &what, is_item_kw) {
                break;
            }
            let pos = self.pos;
            let r = if self.at_kw(Kw::Input) || self.at_kw(Kw::Output) {
                self.var_decl().map(|v| members.push(v))
            } else {
                self.unexpected(
                    "a port of the interface (`input x: T;`, `output event e;`, …)",
                    None,
                );
                Ok(())
            };
            if r.is_err() {
                self.recover();
            }
            if self.pos == pos {
                self.bump();
            }
        }
        Ok(InterfaceDecl {
            name,
            members,
            span: self.span_from(start),
        })
    }

    /// `'configuration' IDENT '{' { IDENT '=' IDENT [ '(' args ')' ] ';' } '}'`
    pub(super) fn configuration(&mut self) -> PResult<Configuration> {
        let start = self.bump().span;
        let name = self.expect_ident("a configuration name after `configuration`")?;
        let open = self.expect(Tok::LBrace, "after the configuration name")?;
        let what = format!("configuration `{}`", name.name);
        let mut bindings = Vec::new();
        loop {
            if self.at_list_end(open, &what, is_item_kw) {
                break;
            }
            let pos = self.pos;
            let r = self.binding().map(|b| bindings.push(b));
            if r.is_err() {
                self.recover();
            }
            if self.pos == pos {
                self.bump();
            }
        }
        Ok(Configuration {
            name,
            bindings,
            span: self.span_from(start),
        })
    }

    /// `IDENT { '.' IDENT } '=' IDENT [ '(' args ')' ] ';'`: a dotted path names an instance
    /// inside a component instance (kept as one name, `storage.feeder.home`).
    pub(super) fn binding(&mut self) -> PResult<Binding> {
        let mut instance = self.expect_ident("an instance name")?;
        while self.eat(Tok::Dot).is_some() {
            let next = self.expect_ident("an instance name after `.`")?;
            instance.name = format!("{}.{}", instance.name, next.name);
            instance.span = instance.span.to(next.span);
        }
        self.expect(Tok::Assign, "after the instance name")?;
        let chart = self.expect_ident("a chart name after `=`")?;
        let args = if self.at(Tok::LParen) {
            self.instance_args()?
        } else {
            Vec::new()
        };
        self.expect_semi("after the binding");
        Ok(Binding {
            span: self.span_from(instance.span),
            instance,
            chart,
            args,
        })
    }

    /// At `component NAME {` or `component NAME implements`: `component` is a contextual
    /// keyword, so it stays usable as a name elsewhere.
    pub(super) fn at_component(&self) -> bool {
        self.text(self.tok().span) == "component"
            && self.nth(1).kind == Tok::Ident
            && (self.nth(2).kind == Tok::LBrace
                || self.nth(2).kind == Tok::LParen
                || (self.nth(2).kind == Tok::Ident && self.text(self.nth(2).span) == "implements"))
    }

    /// `'component' IDENT [ '(' params ')' ] [ 'implements' IDENT { ',' IDENT } ]
    /// '{' { port | sys_elem } '}'`
    pub(super) fn component(&mut self) -> PResult<Component> {
        let start = self.bump().span;
        let name = self.expect_ident("a component name after `component`")?;
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
        let open = self.expect(Tok::LBrace, "after the component name")?;
        let what = format!("component `{}`", name.name);
        let mut body = System {
            name: name.clone(),
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
            span: start,
        };
        let mut ports = Vec::new();
        self.system_elems(&mut body, open, &what, Some(&mut ports));
        let span = self.span_from(start);
        body.span = span;
        Ok(Component {
            name,
            params,
            implements,
            ports,
            body,
            span,
        })
    }
}
