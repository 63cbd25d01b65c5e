//! State bodies, transitions, choices and action blocks.

use super::{is_chart_elem_kw, is_item_kw, is_sync_kw, PResult, Parser};
use crate::ast::{
    BinOp, Block, Branch, Expr, History, HistoryKind, Initial, Junction, Path, PathSegment, Region,
    State, StateBody, Stmt, Target, Transition, Trigger,
};
use crate::lexer::{Kw, Tok};
use statecheck_base::{Diagnostic, Span};

/// Keywords that start a `body_elem`.
pub(super) fn is_body_kw(t: Tok) -> bool {
    matches!(
        t,
        Tok::Kw(
            Kw::Entry
                | Kw::During
                | Kw::Exit
                | Kw::Initial
                | Kw::History
                | Kw::State
                | Kw::Region
                | Kw::Junction
                | Kw::On
                | Kw::Marked
        )
    )
}

/// Keywords at which an unterminated action block is assumed to have ended.
fn is_block_outer(t: Tok) -> bool {
    is_sync_kw(t) && !matches!(t, Tok::Kw(Kw::Raise | Kw::Let | Kw::Return))
}

impl Parser<'_> {
    /// At the head of a `{ … }` list loop: true when the list is over, either because its
    /// `}` was consumed or because it was reported unclosed (at end of file, or at a token
    /// for which `outer` says it belongs to an enclosing construct).
    pub(super) fn at_list_end(&mut self, open: Span, what: &str, outer: fn(Tok) -> bool) -> bool {
        let t = self.peek();
        if t == Tok::RBrace {
            self.bump();
            return true;
        }
        if t == Tok::Eof || outer(t) {
            self.unclosed(open, what);
            return true;
        }
        false
    }

    /// A hint for an unexpected token where a state element was expected.
    pub(super) fn body_hint(&self) -> Option<String> {
        let t = self.tok();
        let next = self.nth(1).kind;
        match t.kind {
            Tok::Ident => {
                let name = self.text(t.span);
                Some(match next {
                    Tok::Semi => format!(
                        "did you mean `state {name};` or `initial {name};`?"
                    ),
                    Tok::LBrace => format!("to declare a state, write `state {name} {{ … }}`"),
                    Tok::Ident => format!(
                        "to choose the default child state, write `initial {};`",
                        self.text(self.nth(1).span)
                    ),
                    Tok::Arrow | Tok::LBracket | Tok::Slash => {
                        format!("transitions start with `on`, e.g. `on {name} -> Target;`")
                    }
                    Tok::Colon => format!(
                        "declare variables with `input`, `output` or `local`, e.g. `local {name}: int[0..3] = 0;`"
                    ),
                    _ => return None,
                })
            }
            Tok::Kw(Kw::Shallow | Kw::Deep) => {
                Some(format!("write `history {};`", self.text(t.span)))
            }
            Tok::LBracket | Tok::Arrow => {
                Some("transitions start with `on`, e.g. `on [x > 0] -> Target;`".into())
            }
            _ => None,
        }
    }

    /// Parse the elements of a state or region body after its `{`.
    pub(super) fn body_list(&mut self, open: Span, what: &str) -> StateBody {
        let mut body = StateBody::default();
        loop {
            if self.at_list_end(open, what, is_item_kw) {
                break;
            }
            let start = self.pos;
            let t = self.peek();
            if self.at_hybrid_elem() {
                match self.hybrid_elem() {
                    Ok(h) => body.hybrid.push(h),
                    Err(_) => self.recover(),
                }
            } else if is_body_kw(t) {
                if self.body_elem(&mut body).is_err() {
                    self.recover();
                }
            } else {
                self.misplaced_in_body(&mut body);
            }
            if self.pos == start {
                self.bump();
            }
        }
        body
    }

    /// Handle a token that cannot start a state element: `parallel` (parsed anyway),
    /// declarations and properties (E0017, skipped) or anything else (E0010, skipped).
    #[inline(never)]
    fn misplaced_in_body(&mut self, body: &mut StateBody) {
        let t = self.peek();
        if t == Tok::Kw(Kw::Parallel) {
            let d = Diagnostic::error(
                "E0017",
                "`parallel { … }` is only allowed at chart level",
                self.tok().span,
            )
            .with_label("inside a state")
            .with_hint("inside a state, write the regions directly: `region r { … }`");
            self.report(d);
            if self.parallel(body).is_err() {
                self.recover();
            }
        } else if is_chart_elem_kw(t) {
            let kw = self.text(self.tok().span).to_string();
            let (msg, hint) = if matches!(
                t,
                Tok::Kw(Kw::Input | Kw::Output | Kw::Local | Kw::Controllable | Kw::Uncontrollable)
            ) {
                (
                    "variables are declared at chart level, not inside a state",
                    "move this declaration to the top of the chart",
                )
            } else {
                (
                    "properties are stated at chart or system level, not inside a state",
                    "move this property to the chart or the system",
                )
            };
            let d = Diagnostic::error("E0017", msg, self.tok().span)
                .with_label(format!("`{kw}` not allowed here"))
                .with_hint(hint);
            self.report(d);
            self.bump();
            self.recover();
        } else {
            let hint = self.body_hint();
            self.unexpected(
                "a state element (`state`, `on`, `entry`, `initial`, …)",
                hint,
            );
        }
    }

    /// Parse one `body_elem` (the current token satisfies [`is_body_kw`]) into `body`.
    ///
    /// Each arm lives in its own function so that this frame, which is on the recursion path
    /// of nested states, stays small.
    pub(super) fn body_elem(&mut self, body: &mut StateBody) -> PResult<()> {
        match self.peek() {
            Tok::Kw(Kw::Entry | Kw::During | Kw::Exit) => self.action_elem(body),
            Tok::Kw(Kw::Initial) => self.initial_elem(body),
            Tok::Kw(Kw::History) => self.history_elem(body),
            Tok::Kw(Kw::State) => self.state_elem(body),
            Tok::Kw(Kw::Marked) => self.marked_state_elem(body),
            Tok::Kw(Kw::Region) => self.region_elem(body),
            Tok::Kw(Kw::Junction) => self.junction_elem(body),
            Tok::Kw(Kw::On) => self.transition_elem(body),
            _ => Err(self.expected("a state element")),
        }
    }

    fn state_elem(&mut self, body: &mut StateBody) -> PResult<()> {
        let s = self.state()?;
        body.states.push(s);
        Ok(())
    }

    /// `'marked' state`: an accepting state for synthesis.
    #[inline(never)]
    fn marked_state_elem(&mut self, body: &mut StateBody) -> PResult<()> {
        self.bump();
        if !self.at_kw(Kw::State) {
            return Err(self.expected("`state` after `marked`"));
        }
        let mut s = self.state()?;
        s.marked = true;
        body.states.push(s);
        Ok(())
    }

    fn region_elem(&mut self, body: &mut StateBody) -> PResult<()> {
        let r = self.region()?;
        body.regions.push(r);
        Ok(())
    }

    #[inline(never)]
    fn junction_elem(&mut self, body: &mut StateBody) -> PResult<()> {
        let j = self.junction()?;
        body.junctions.push(j);
        Ok(())
    }

    #[inline(never)]
    fn transition_elem(&mut self, body: &mut StateBody) -> PResult<()> {
        let t = self.transition()?;
        body.transitions.push(t);
        Ok(())
    }

    /// `entry`, `during` or `exit` followed by a block.
    #[inline(never)]
    fn action_elem(&mut self, body: &mut StateBody) -> PResult<()> {
        let t = self.bump();
        let (list, ctx) = match t.kind {
            Tok::Kw(Kw::Entry) => (&mut body.entry, "after `entry`"),
            Tok::Kw(Kw::During) => (&mut body.during, "after `during`"),
            _ => (&mut body.exit, "after `exit`"),
        };
        list.push(self.block(ctx)?);
        Ok(())
    }

    /// `'initial' IDENT [ '/' block ] ';'`
    #[inline(never)]
    fn initial_elem(&mut self, body: &mut StateBody) -> PResult<()> {
        let start = self.bump().span;
        let target = self.expect_ident("the name of the initial child state")?;
        let action = if self.eat(Tok::Slash).is_some() {
            Some(self.block("after `/`")?)
        } else {
            None
        };
        self.expect_semi("after `initial`");
        body.initial.push(Initial {
            target,
            action,
            span: self.span_from(start),
        });
        Ok(())
    }

    /// `'history' ( 'shallow' | 'deep' ) ';'`
    #[inline(never)]
    fn history_elem(&mut self, body: &mut StateBody) -> PResult<()> {
        let start = self.bump().span;
        let kind = if self.eat_kw(Kw::Shallow).is_some() {
            HistoryKind::Shallow
        } else if self.eat_kw(Kw::Deep).is_some() {
            HistoryKind::Deep
        } else {
            let d = self
                .expected_diag("`shallow` or `deep` after `history`")
                .with_hint("write `history shallow;` or `history deep;`");
            self.report(d);
            return Err(super::Failed);
        };
        self.expect_semi("after `history`");
        body.history.push(History {
            kind,
            span: self.span_from(start),
        });
        Ok(())
    }

    /// `'parallel' '{' { region } '}'`, adding the regions to `body`.
    pub(super) fn parallel(&mut self, body: &mut StateBody) -> PResult<()> {
        self.bump();
        let open = self.expect(Tok::LBrace, "after `parallel`")?;
        loop {
            if self.at_list_end(open, "`parallel`", is_item_kw) {
                break;
            }
            let start = self.pos;
            if self.at_kw(Kw::Region) {
                match self.region() {
                    Ok(r) => body.regions.push(r),
                    Err(_) => self.recover(),
                }
            } else {
                self.unexpected(
                    "`region` inside `parallel`",
                    Some("a `parallel` block holds only regions: `region r { … }`".into()),
                );
            }
            if self.pos == start {
                self.bump();
            }
        }
        Ok(())
    }

    /// `'state' IDENT ( '{' { body_elem } '}' | ';' )`
    fn state(&mut self) -> PResult<State> {
        let start = self.bump().span;
        let name = self.expect_ident("a state name after `state`")?;
        let body = if self.eat(Tok::Semi).is_some() {
            StateBody::default()
        } else if self.at(Tok::LBrace) {
            let what = format!("state `{}`", name.name);
            self.nested_body(&what)
        } else {
            self.state_without_body(&name.name)?;
            StateBody::default()
        };
        Ok(State {
            name,
            marked: false,
            body,
            span: self.span_from(start),
        })
    }

    /// After `state NAME`, neither `{` nor `;`: report, and keep the state if `;` seems
    /// merely missing.
    #[inline(never)]
    fn state_without_body(&mut self, name: &str) -> PResult<()> {
        if matches!(self.peek(), Tok::RBrace | Tok::Eof) || is_sync_kw(self.peek()) {
            let found = self.describe(self.tok());
            let d = Diagnostic::error(
                "E0011",
                format!("expected `;` or a body after state `{name}`, found {found}"),
                self.missing_span(),
            )
            .with_label("expected `;`")
            .with_hint(format!("a state without a body is written `state {name};`"));
            self.report(d);
            return Ok(());
        }
        let d = self.expected_diag("`{` or `;` after the state name");
        self.report(d);
        Err(super::Failed)
    }

    /// `'{' { body_elem } '}'` at the current `{`, guarding the nesting depth.
    fn nested_body(&mut self, what: &str) -> StateBody {
        if !self.enter() {
            self.skip_group();
            return StateBody::default();
        }
        let open = self.bump().span;
        let body = self.body_list(open, what);
        self.leave();
        body
    }

    /// `'region' IDENT '{' { body_elem } '}'`
    fn region(&mut self) -> PResult<Region> {
        let start = self.bump().span;
        let name = self.expect_ident("a region name after `region`")?;
        if !self.at(Tok::LBrace) {
            return Err(self.expected("`{` after the region name"));
        }
        let what = format!("region `{}`", name.name);
        let body = self.nested_body(&what);
        Ok(Region {
            name,
            body,
            span: self.span_from(start),
        })
    }

    /// `'junction' IDENT '{' { branch } '}'`
    fn junction(&mut self) -> PResult<Junction> {
        let start = self.bump().span;
        let name = self.expect_ident("a junction name after `junction`")?;
        if !self.at(Tok::LBrace) {
            return Err(self.expected("`{` after the junction name"));
        }
        let what = format!("junction `{}`", name.name);
        let branches = self.branch_list(&what);
        Ok(Junction {
            name,
            branches,
            span: self.span_from(start),
        })
    }

    /// `'{' { branch } '}'` at the current `{`.
    fn branch_list(&mut self, what: &str) -> Vec<Branch> {
        let mut branches = Vec::new();
        if !self.enter() {
            self.skip_group();
            return branches;
        }
        let open = self.bump().span;
        loop {
            if self.at_list_end(open, what, is_sync_kw) {
                break;
            }
            let start = self.pos;
            if self.at(Tok::LBracket) || self.at_kw(Kw::Else) {
                match self.branch() {
                    Ok(b) => branches.push(b),
                    Err(_) => self.recover(),
                }
            } else {
                self.unexpected(
                    "a branch (`[guard] -> target;` or `else -> target;`)",
                    Some("each branch starts with a guard in brackets or with `else`".into()),
                );
            }
            if self.pos == start {
                self.bump();
            }
        }
        self.leave();
        branches
    }

    /// `( '[' expr ']' | 'else' ) [ '/' block ] '->' target ';'`
    fn branch(&mut self) -> PResult<Branch> {
        let start = self.tok().span;
        let guard = if let Some(open) = self.eat(Tok::LBracket) {
            let g = self.expr();
            if !self.close(Tok::RBracket, open, "the guard's `[`") {
                return Err(super::Failed);
            }
            Some(g)
        } else {
            self.bump();
            None
        };
        let action = if self.eat(Tok::Slash).is_some() {
            Some(self.block("after `/`")?)
        } else {
            None
        };
        self.expect(Tok::Arrow, "before the branch target")?;
        let target = self.target()?;
        self.expect_semi("after the branch");
        Ok(Branch {
            guard,
            action,
            target,
            span: self.span_from(start),
        })
    }

    /// `target = path | 'choice' '{' { branch } '}'`
    fn target(&mut self) -> PResult<Target> {
        if let Some(start) = self.eat_kw(Kw::Choice) {
            if !self.at(Tok::LBrace) {
                return Err(self.expected("`{` after `choice`"));
            }
            let branches = self.branch_list("the choice");
            return Ok(Target::Choice {
                branches,
                span: self.span_from(start),
            });
        }
        if !self.at(Tok::Ident) {
            return Err(self.expected("a target state after `->`"));
        }
        Ok(Target::Path(self.path()?))
    }

    /// `'on' [ trigger ] [ '[' expr ']' ] [ '/' block ] [ '->' target ] [ 'priority' INT ] ';'`
    fn transition(&mut self) -> PResult<Transition> {
        let start = self.bump().span;
        let trigger = if self.at(Tok::Ident) {
            let t = self.bump();
            Some(Trigger::Event(self.ident_of(t)))
        } else if let Some(after) = self.eat_kw(Kw::After) {
            let open = self.expect(Tok::LParen, "after `after`")?;
            let delay = self.delay();
            if !self.close(Tok::RParen, open, "`after(`") {
                return Err(super::Failed);
            }
            Some(Trigger::After {
                delay,
                span: self.span_from(after),
            })
        } else {
            None
        };
        let guard = if let Some(open) = self.eat(Tok::LBracket) {
            let g = self.expr();
            if !self.close(Tok::RBracket, open, "the guard's `[`") {
                return Err(super::Failed);
            }
            Some(g)
        } else {
            None
        };
        let action = if self.eat(Tok::Slash).is_some() {
            Some(self.block("after `/`")?)
        } else {
            None
        };
        let target = if self.eat(Tok::Arrow).is_some() {
            Some(self.target()?)
        } else if self.at(Tok::Ident) {
            let name = self.text(self.tok().span).to_string();
            let d = Diagnostic::error(
                "E0010",
                format!("expected `->` before the target state, found identifier `{name}`"),
                self.missing_span(),
            )
            .with_label("expected `->`")
            .with_hint(format!("write `-> {name}`"));
            self.report(d);
            Some(self.target()?)
        } else {
            None
        };
        let priority = if self.eat_kw(Kw::Priority).is_some() {
            let t = self.tok();
            let Tok::Int(v) = t.kind else {
                return Err(self.expected("a number after `priority`"));
            };
            self.bump();
            Some((v, t.span))
        } else {
            None
        };
        if trigger.is_none() && guard.is_none() && target.is_none() {
            let d = Diagnostic::error(
                "E0014",
                "empty transition: no trigger, guard or target",
                self.span_from(start),
            )
            .with_label("this transition can never be taken")
            .with_hint("add an event (`on Go -> B;`), a guard (`on [x > 0] -> B;`) or a target");
            self.report(d);
        }
        self.expect_semi("after the transition");
        Ok(Transition {
            trigger,
            guard,
            action,
            target,
            priority,
            span: self.span_from(start),
        })
    }

    /// `block = '{' { stmt } '}'`; `ctx` says where it is expected (for messages).
    pub(super) fn block(&mut self, ctx: &str) -> PResult<Block> {
        if !self.at(Tok::LBrace) {
            let d = self.expected_diag(&format!("`{{` {ctx}"));
            self.report(d);
            return Err(super::Failed);
        }
        let start = self.tok().span;
        if !self.enter() {
            self.skip_group();
            return Ok(Block {
                stmts: Vec::new(),
                span: self.span_from(start),
            });
        }
        self.bump();
        let mut stmts = Vec::new();
        loop {
            if self.at_list_end(start, "the block", is_block_outer) {
                break;
            }
            let pos = self.pos;
            match self.peek() {
                Tok::Ident | Tok::Kw(Kw::Raise | Kw::If) => match self.stmt() {
                    Ok(s) => stmts.push(s),
                    Err(_) => self.recover(),
                },
                _ => self.not_a_statement(),
            }
            if self.pos == pos {
                self.bump();
            }
        }
        self.leave();
        Ok(Block {
            stmts,
            span: self.span_from(start),
        })
    }

    #[inline(never)]
    fn not_a_statement(&mut self) {
        let hint = match self.peek() {
            Tok::Kw(Kw::Let) => Some("`let` is only allowed in function bodies"),
            Tok::Kw(Kw::Else) => Some("`else` must follow the `}` of an `if`"),
            Tok::Int(_) | Tok::LParen | Tok::Minus | Tok::Bang => {
                Some("an expression on its own is not a statement")
            }
            _ => None,
        };
        self.unexpected(
            "a statement (assignment, `raise` or `if`)",
            hint.map(String::from),
        );
    }

    /// `stmt = IDENT ['[' expr ']'] ('=' | '+=' | '-=') expr ';' | 'raise' IDENT ';' | if_stmt
    /// | for_stmt`
    fn stmt(&mut self) -> PResult<Stmt> {
        let t = self.tok();
        match t.kind {
            Tok::Kw(Kw::Raise) => {
                self.bump();
                let event = self.expect_ident("an event name after `raise`")?;
                self.expect_semi("after `raise`");
                Ok(Stmt::Raise {
                    event,
                    span: self.span_from(t.span),
                })
            }
            Tok::Kw(Kw::If) => {
                if !self.enter() {
                    self.skip_rest();
                    return Err(super::Failed);
                }
                let r = self.if_stmt();
                self.leave();
                r
            }
            Tok::Ident
                if self.text(t.span) == "for"
                    && self.nth(1).kind == Tok::Ident
                    && self.nth(2).kind == Tok::Kw(Kw::In) =>
            {
                if !self.enter() {
                    self.skip_rest();
                    return Err(super::Failed);
                }
                let r = self.for_stmt();
                self.leave();
                r
            }
            _ => self.assign(),
        }
    }

    /// `'for' IDENT 'in' expr '..' expr block` (`for` is contextual; depth already entered).
    fn for_stmt(&mut self) -> PResult<Stmt> {
        let start = self.bump().span;
        let var = self.expect_ident("the loop variable after `for`")?;
        self.bump(); // `in`, checked by the caller
        let lo = self.expr();
        if self.eat(Tok::DotDot).is_none() {
            let d = self
                .expected_diag("`..` between the loop's bounds")
                .with_hint(format!("write `for {} in 0..N {{ … }}`", var.name));
            self.report(d);
            return Err(super::Failed);
        }
        let hi = self.expr();
        let body = self.block("after the loop's bounds")?;
        Ok(Stmt::For {
            var,
            lo: Box::new(lo),
            hi: Box::new(hi),
            body,
            span: self.span_from(start),
        })
    }

    fn assign(&mut self) -> PResult<Stmt> {
        let id = self.bump();
        let target = self.ident_of(id);
        let index = if self.eat(Tok::LBracket).is_some() {
            let i = self.expr();
            if self.eat(Tok::RBracket).is_none() {
                self.report(self.expected_diag("`]` after the index"));
                return Err(super::Failed);
            }
            Some(Box::new(i))
        } else {
            None
        };
        let op = match self.peek() {
            Tok::Assign => None,
            Tok::PlusAssign => Some(BinOp::Add),
            Tok::MinusAssign => Some(BinOp::Sub),
            other => {
                let mut d = self.expected_diag("`=`, `+=` or `-=` after the assigned variable");
                let hint = match other {
                    Tok::EqEq => Some("did you mean `=`? `==` compares, `=` assigns"),
                    Tok::LParen => Some("a function call is not a statement"),
                    Tok::Dot => Some("only plain variable names of the chart can be assigned"),
                    _ => None,
                };
                if let Some(h) = hint {
                    d = d.with_hint(h);
                }
                self.report(d);
                return Err(super::Failed);
            }
        };
        self.bump();
        let rhs = self.expr();
        let value = match op {
            None => rhs,
            Some(op) => {
                let span = target.span.to(rhs.span());
                let lhs = Expr::Path(Path {
                    segments: vec![PathSegment {
                        name: target.clone(),
                        index: index.clone().map(crate::ast::Index::At),
                    }],
                    span: target.span,
                });
                Expr::Binary(op, Box::new(lhs), Box::new(rhs), span)
            }
        };
        self.expect_semi("after assignment");
        Ok(Stmt::Assign {
            target,
            index,
            value,
            span: self.span_from(id.span),
        })
    }

    #[inline(never)]
    fn then_in_if_stmt(&mut self) {
        let d = self
            .expected_diag("`{` after the condition")
            .with_hint("an `if` statement has no `then`: write `if cond { … }`");
        self.report(d);
        self.bump();
    }

    /// `'if' expr block [ 'else' ( block | if_stmt ) ]` (depth already entered).
    fn if_stmt(&mut self) -> PResult<Stmt> {
        let start = self.bump().span;
        let cond = self.expr();
        if self.at_kw(Kw::Then) {
            self.then_in_if_stmt();
        }
        let then = self.block("after the `if` condition")?;
        let otherwise = if self.eat_kw(Kw::Else).is_some() {
            if self.at_kw(Kw::If) {
                let s = self.stmt()?;
                let span = match &s {
                    Stmt::If { span, .. } => *span,
                    _ => self.span_from(start),
                };
                Some(Block {
                    stmts: vec![s],
                    span,
                })
            } else {
                Some(self.block("after `else`")?)
            }
        } else {
            None
        };
        Ok(Stmt::If {
            cond,
            then,
            otherwise,
            span: self.span_from(start),
        })
    }
}
