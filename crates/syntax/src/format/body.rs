//! State bodies, transitions, choices, action blocks and statements.

use super::{Printer, WIDTH};
use crate::ast::{
    BinOp, Block, Branch, Expr, HistoryKind, Initial, Junction, Property, Region, State, StateBody,
    Stmt, Target, Transition, Trigger, VarDecl,
};
use crate::lexer::Tok;
use statecheck_base::Span;

/// The most elements a state printed on one line may have (`state A { on e -> B; }`).
const MAX_ONE_LINE: usize = 3;

/// One element of a chart or state body, for printing in textual order.
pub(super) enum Member<'t> {
    Var(&'t VarDecl),
    Property(&'t Property),
    Action(&'static str, &'t Block),
    Initial(&'t Initial),
    History(HistoryKind, Span),
    State(&'t State),
    /// Chart-level regions, printed together in one `parallel { … }`.
    Parallel(&'t [Region]),
    Region(&'t Region),
    Junction(&'t Junction),
    Transition(&'t Transition),
    /// A hybrid element (`docs/hybrid.md`), printed as written with its spaces normalised.
    Hybrid(Span),
}

impl Printer<'_> {
    /// Where an element starts in the source (its first keyword).
    fn member_start(&self, m: &Member<'_>) -> u32 {
        match m {
            Member::Var(v) => v.span.start,
            Member::Property(p) => p.span.start,
            // The keyword (`entry`, …) is the token before the block.
            Member::Action(_, b) => self
                .tok_before(b.span.start)
                .map_or(b.span.start, |t| t.span.start),
            Member::Initial(i) => i.span.start,
            Member::History(_, s) => s.start,
            Member::State(s) => {
                if s.marked {
                    self.tok_before(s.span.start)
                        .map_or(s.span.start, |t| t.span.start)
                } else {
                    s.span.start
                }
            }
            Member::Parallel(rs) => {
                let first = rs.first().map_or(0, |r| r.span.start);
                // `parallel {` precede the first region.
                match self.tok_before(first) {
                    Some(t) if t.kind == Tok::LBrace => self
                        .tok_before(t.span.start)
                        .map_or(first, |k| k.span.start),
                    _ => first,
                }
            }
            Member::Region(r) => r.span.start,
            Member::Junction(j) => j.span.start,
            Member::Transition(t) => t.span.start,
            Member::Hybrid(s) => s.start,
        }
    }

    /// The elements of a body (and, for a chart, its declarations and properties) in textual
    /// order.
    pub(super) fn members<'t>(
        &self,
        body: &'t StateBody,
        vars: &'t [VarDecl],
        props: &'t [Property],
        chart_level: bool,
    ) -> Vec<Member<'t>> {
        let mut ms: Vec<Member<'t>> = Vec::new();
        ms.extend(vars.iter().map(Member::Var));
        ms.extend(props.iter().map(Member::Property));
        ms.extend(body.entry.iter().map(|b| Member::Action("entry", b)));
        ms.extend(body.during.iter().map(|b| Member::Action("during", b)));
        ms.extend(body.exit.iter().map(|b| Member::Action("exit", b)));
        ms.extend(body.initial.iter().map(Member::Initial));
        ms.extend(body.history.iter().map(|h| Member::History(h.kind, h.span)));
        ms.extend(body.states.iter().map(Member::State));
        let wrapped = body.regions.first().is_some_and(|r| {
            self.tok_before(r.span.start)
                .filter(|t| t.kind == Tok::LBrace)
                .and_then(|t| self.tok_before(t.span.start))
                .is_some_and(|t| t.kind == Tok::Kw(crate::lexer::Kw::Parallel))
        });
        if chart_level && wrapped {
            ms.push(Member::Parallel(&body.regions));
        } else {
            ms.extend(body.regions.iter().map(Member::Region));
        }
        ms.extend(body.junctions.iter().map(Member::Junction));
        ms.extend(body.transitions.iter().map(Member::Transition));
        ms.extend(body.hybrid.iter().map(|h| Member::Hybrid(h.span())));
        // A stable sort: equal starts cannot happen in a parsed file, but stay deterministic.
        let mut keyed: Vec<(u32, Member<'t>)> =
            ms.into_iter().map(|m| (self.member_start(&m), m)).collect();
        keyed.sort_by_key(|(k, _)| *k);
        keyed.into_iter().map(|(_, m)| m).collect()
    }

    /// Print the elements of a body, one per line (or block).
    pub(super) fn print_members(&mut self, ms: &[Member<'_>]) {
        for m in ms {
            let start = self.member_start(m);
            match m {
                Member::Var(v) => {
                    let t = self.var_decl(v);
                    self.line(
                        Span {
                            start,
                            end: v.span.end,
                        },
                        &t,
                    );
                }
                Member::Property(p) => self.property_line(p),
                Member::Action(kw, b) => {
                    let span = Span {
                        start,
                        end: b.span.end,
                    };
                    self.block_elem(span, &format!("{kw} "), b, "", span.end);
                }
                Member::Initial(i) => {
                    let head = format!("initial {}", i.target.name);
                    match &i.action {
                        None => self.line(i.span, &format!("{head};")),
                        Some(b) => {
                            self.block_elem(i.span, &format!("{head} / "), b, ";", i.span.end)
                        }
                    }
                }
                Member::History(k, span) => {
                    let kind = match k {
                        HistoryKind::Shallow => "shallow",
                        HistoryKind::Deep => "deep",
                    };
                    self.line(*span, &format!("history {kind};"));
                }
                Member::State(s) => self.state(s, start),
                Member::Parallel(rs) => {
                    self.start_line(start);
                    self.out.push_str("parallel {");
                    let brace = self.lbrace_after(start);
                    self.open(brace);
                    for r in rs.iter() {
                        self.region(r);
                    }
                    let end = rs.last().map_or(brace, |r| r.span.end);
                    // The `}` of `parallel` follows the last region.
                    let close = self.tok_after(end).filter(|t| t.kind == Tok::RBrace);
                    let close_end = close.map_or(end, |t| t.span.end);
                    self.close(close_end, "", close_end);
                }
                Member::Region(r) => self.region(r),
                Member::Junction(j) => {
                    self.start_line(j.span.start);
                    self.out.push_str(&format!("junction {}", j.name.name));
                    self.branches(j.name.span.end, &j.branches, j.span.end, "", j.span.end);
                }
                Member::Transition(t) => self.transition(t),
                Member::Hybrid(span) => {
                    let t = self.hybrid_text(*span);
                    self.line(*span, &t);
                }
            }
        }
    }

    /// A hybrid element's source text on one line: runs of white space become one space, and
    /// none is left inside brackets and parentheses or before `,` and `;`.
    fn hybrid_text(&self, span: Span) -> String {
        let mut out = String::new();
        let mut prev: Option<crate::lexer::Token> = None;
        for tok in self
            .toks
            .iter()
            .filter(|t| t.span.start >= span.start && t.span.end <= span.end)
        {
            if let Some(p) = prev {
                let close = matches!(
                    tok.kind,
                    Tok::Semi | Tok::Comma | Tok::RParen | Tok::RBracket | Tok::Colon
                );
                let open = matches!(p.kind, Tok::LParen | Tok::LBracket);
                let sep = matches!(p.kind, Tok::Comma | Tok::Colon);
                let adjacent = p.span.end == tok.span.start;
                if !close && !open && (sep || !adjacent) {
                    out.push(' ');
                }
            }
            out.push_str(self.text(tok.span));
            prev = Some(*tok);
        }
        out
    }

    fn state(&mut self, s: &State, start: u32) {
        let marked = if s.marked { "marked " } else { "" };
        let ms = self.members(&s.body, &[], &[], false);
        let head = format!("{marked}state {}", s.name.name);
        if ms.is_empty() && !self.has_comment_in(s.span) {
            self.line(
                Span {
                    start,
                    end: s.span.end,
                },
                &format!("{head};"),
            );
            return;
        }
        if ms.len() <= MAX_ONE_LINE && !self.has_comment_in(s.span) {
            let parts: Option<Vec<String>> = ms.iter().map(|m| self.one_line(m)).collect();
            if let Some(parts) = parts {
                let text = format!("{head} {{ {} }}", parts.join(" "));
                if self.indent_width() + text.len() <= WIDTH {
                    self.line(
                        Span {
                            start,
                            end: s.span.end,
                        },
                        &text,
                    );
                    return;
                }
            }
        }
        self.start_line(start);
        self.out.push_str(&head);
        self.out.push_str(" {");
        let brace = self.lbrace_after(s.name.span.end);
        self.open(brace);
        self.print_members(&ms);
        self.close(s.span.end, "", s.span.end);
    }

    fn region(&mut self, r: &Region) {
        let ms = self.members(&r.body, &[], &[], false);
        self.start_line(r.span.start);
        self.out.push_str(&format!("region {} {{", r.name.name));
        let brace = self.lbrace_after(r.name.span.end);
        self.open(brace);
        self.print_members(&ms);
        self.close(r.span.end, "", r.span.end);
    }

    /// After a head already printed on the current line (its source before `head`): ` {`, the
    /// branches, `}` and `suffix`; `end` is where the `}` ends in the source, `line_end`
    /// where the line does.
    fn branches(&mut self, head: u32, bs: &[Branch], end: u32, suffix: &str, line_end: u32) {
        let brace = self.lbrace_after(head);
        if bs.is_empty() && !self.has_comment_in(Span { start: brace, end }) {
            self.out.push_str(" {}");
            self.out.push_str(suffix);
            self.end_line(line_end);
            return;
        }
        self.out.push_str(" {");
        self.open(brace);
        for b in bs {
            self.branch(b);
        }
        self.close(end, suffix, line_end);
    }

    fn branch(&mut self, b: &Branch) {
        let head = match &b.guard {
            Some(g) => format!("[{}]", self.expr(g)),
            None => "else".to_string(),
        };
        self.guarded(b.span, head, b.action.as_ref(), Some(&b.target), None);
    }

    fn transition(&mut self, t: &Transition) {
        let (head, prio) = self.transition_head(t);
        self.guarded(t.span, head, t.action.as_ref(), t.target.as_ref(), prio);
    }

    /// `on trigger [guard]` and ` priority N` of a transition.
    fn transition_head(&self, t: &Transition) -> (String, Option<String>) {
        let mut head = "on".to_string();
        match &t.trigger {
            None => {}
            Some(Trigger::Event(e)) => {
                head.push(' ');
                head.push_str(&e.name);
            }
            Some(Trigger::After { delay, .. }) => {
                head.push_str(&format!(" after({})", self.delay(delay)));
            }
        }
        if let Some(g) = &t.guard {
            head.push_str(&format!(" [{}]", self.expr(g)));
        }
        let prio = t
            .priority
            .map(|(_, span)| format!(" priority {}", self.text(span)));
        (head, prio)
    }

    /// An element as one line of text, if it has a one-line form: a transition without a
    /// choice and with an inline action, `initial`, `history`, an inline `entry`/`during`/
    /// `exit`. None for the others and for elements with a comment inside.
    fn one_line(&self, m: &Member<'_>) -> Option<String> {
        let simple = |p: &Self, head: String, action: Option<&Block>, tail: String| {
            Some(match action {
                None => format!("{head}{tail}"),
                Some(b) => format!("{head} / {}{tail}", p.inline_block(b)?),
            })
        };
        match m {
            Member::Transition(t) => {
                if self.has_comment_in(t.span) {
                    return None;
                }
                let (head, prio) = self.transition_head(t);
                let target = match &t.target {
                    None => String::new(),
                    Some(Target::Path(p)) => format!(" -> {}", self.path(p)),
                    Some(Target::Choice { .. }) => return None,
                };
                let tail = format!("{target}{};", prio.unwrap_or_default());
                simple(self, head, t.action.as_ref(), tail)
            }
            Member::Initial(i) => {
                if self.has_comment_in(i.span) {
                    return None;
                }
                simple(
                    self,
                    format!("initial {}", i.target.name),
                    i.action.as_ref(),
                    ";".into(),
                )
            }
            Member::History(k, _) => Some(match k {
                HistoryKind::Shallow => "history shallow;".to_string(),
                HistoryKind::Deep => "history deep;".to_string(),
            }),
            Member::Action(kw, b) => Some(format!("{kw} {}", self.inline_block(b)?)),
            _ => None,
        }
    }

    /// A transition or branch: `head [/ block] [-> target] [priority];`.
    fn guarded(
        &mut self,
        span: Span,
        head: String,
        action: Option<&Block>,
        target: Option<&Target>,
        prio: Option<String>,
    ) {
        let prio = prio.unwrap_or_default();
        // The part after the action: a path target, or the head of a choice.
        let (tail, choice) = match target {
            None => (String::new(), None),
            Some(Target::Path(p)) => (format!(" -> {}", self.path(p)), None),
            Some(Target::Choice { branches, span }) => {
                (" -> choice".to_string(), Some((branches, *span)))
            }
        };
        let Some(b) = action else {
            match choice {
                None => self.line(span, &format!("{head}{tail}{prio};")),
                Some((bs, cspan)) => {
                    self.start_line(span.start);
                    self.out.push_str(&head);
                    self.out.push_str(&tail);
                    self.branches(cspan.start, bs, cspan.end, &format!("{prio};"), span.end);
                }
            }
            return;
        };
        let inline = self.inline_block(b);
        let prefix = format!("{head} / ");
        match (inline, choice) {
            (Some(text), None) => {
                let line = format!("{prefix}{text}{tail}{prio};");
                if self.indent_width() + line.len() <= WIDTH {
                    self.line(span, &line);
                    return;
                }
                self.block_elem_multi(span.start, &prefix, b, &format!("{tail}{prio};"), span.end);
            }
            (_, None) => {
                self.block_elem_multi(span.start, &prefix, b, &format!("{tail}{prio};"), span.end);
            }
            (_, Some((bs, cspan))) => {
                // The block is printed over several lines, then the choice.
                self.start_line(span.start);
                self.out.push_str(&prefix);
                self.out.push('{');
                self.open(b.span.start + 1);
                self.stmts(&b.stmts);
                self.close_no_newline(b.span.end);
                self.out.push_str(&tail);
                self.branches(cspan.start, bs, cspan.end, &format!("{prio};"), span.end);
            }
        }
    }

    /// Like [`Printer::close`] but the line goes on (a choice follows the block).
    fn close_no_newline(&mut self, close_end: u32) {
        self.comments_before(close_end.saturating_sub(1));
        self.indent = self.indent.saturating_sub(1);
        self.push_indent();
        self.out.push('}');
        self.at_block_start = false;
    }

    /// A block as one line (`{ x = 1; raise e; }`, `{}`), if it may be: no `if` and no comment
    /// inside (the caller checks the width).
    fn inline_block(&self, b: &Block) -> Option<String> {
        if self.has_comment_in(b.span) {
            return None;
        }
        if b.stmts.is_empty() {
            return Some("{}".to_string());
        }
        let mut parts = Vec::with_capacity(b.stmts.len());
        for s in &b.stmts {
            if matches!(s, Stmt::If { .. } | Stmt::For { .. }) {
                return None;
            }
            parts.push(self.simple_stmt(s));
        }
        Some(format!("{{ {} }}", parts.join(" ")))
    }

    /// `prefix block suffix` for an element spanning `span` (on one line if it fits).
    fn block_elem(&mut self, span: Span, prefix: &str, b: &Block, suffix: &str, end: u32) {
        if let Some(text) = self.inline_block(b) {
            let line = format!("{prefix}{text}{suffix}");
            if self.indent_width() + line.len() <= WIDTH {
                self.line(span, &line);
                return;
            }
        }
        self.block_elem_multi(span.start, prefix, b, suffix, end);
    }

    fn block_elem_multi(&mut self, start: u32, prefix: &str, b: &Block, suffix: &str, end: u32) {
        self.start_line(start);
        self.out.push_str(prefix);
        self.out.push('{');
        self.open(b.span.start + 1);
        self.stmts(&b.stmts);
        self.close(b.span.end, suffix, end);
    }

    /// The statements of a block, one per line.
    fn stmts(&mut self, stmts: &[Stmt]) {
        for s in stmts {
            match s {
                Stmt::Assign { span, .. } => {
                    let (head, value) = self.assign_parts(s);
                    match value {
                        Some(v) => self.line_expr(*span, &head, v, ";"),
                        None => {
                            let t = self.simple_stmt(s);
                            self.line(*span, &t);
                        }
                    }
                }
                Stmt::Raise { span, .. } => {
                    let t = self.simple_stmt(s);
                    self.line(*span, &t);
                }
                Stmt::If { .. } => self.if_stmt(s, true),
                Stmt::For {
                    var,
                    lo,
                    hi,
                    body,
                    span,
                } => {
                    self.start_line(span.start);
                    let (lo, hi) = (self.expr(lo), self.expr(hi));
                    self.out
                        .push_str(&format!("for {} in {lo}..{hi} {{", var.name));
                    self.open(body.span.start + 1);
                    self.stmts(&body.stmts);
                    self.close(body.span.end, "", span.end);
                }
            }
        }
    }

    /// `if c { … } [else if … | else { … }]`; `new_line` is false after `} else `.
    fn if_stmt(&mut self, s: &Stmt, new_line: bool) {
        let Stmt::If {
            cond,
            then,
            otherwise,
            span,
        } = s
        else {
            return;
        };
        if new_line {
            self.start_line(span.start);
        }
        let c = self.expr(cond);
        self.out.push_str(&format!("if {c} {{"));
        self.open(then.span.start + 1);
        self.stmts(&then.stmts);
        match otherwise {
            None => self.close(then.span.end, "", span.end),
            Some(o) => {
                self.close_no_newline(then.span.end);
                self.out.push_str(" else ");
                // `else if` parses into a block holding the `if`, with the `if`'s span.
                if let [inner @ Stmt::If { span: is, .. }] = o.stmts.as_slice() {
                    if *is == o.span {
                        self.if_stmt(inner, false);
                        return;
                    }
                }
                self.out.push('{');
                self.open(o.span.start + 1);
                self.stmts(&o.stmts);
                self.close(o.span.end, "", span.end);
            }
        }
    }

    /// An assignment's `x =` (or `x +=`, `x -=` as written) and its right-hand side.
    fn assign_parts<'e>(&self, s: &'e Stmt) -> (String, Option<&'e Expr>) {
        let Stmt::Assign {
            target,
            index,
            value,
            ..
        } = s
        else {
            return (String::new(), None);
        };
        let name = match index {
            Some(i) => format!("{}[{}]", target.name, self.expr(i)),
            None => target.name.clone(),
        };
        // `x += e` is parsed into `x = x + e` whose left operand has the target's span.
        if let Expr::Binary(op @ (BinOp::Add | BinOp::Sub), l, r, _) = value {
            if let Expr::Path(p) = &**l {
                if p.span == target.span && p.segments.len() == 1 {
                    let o = if *op == BinOp::Add { "+=" } else { "-=" };
                    return (format!("{name} {o}"), Some(&**r));
                }
            }
        }
        (format!("{name} ="), Some(value))
    }

    /// An assignment or `raise` as one line, with compound assignments kept as written.
    pub(super) fn simple_stmt(&self, s: &Stmt) -> String {
        match s {
            Stmt::Assign { .. } => {
                let (head, value) = self.assign_parts(s);
                let v = value.map(|v| self.expr(v)).unwrap_or_default();
                format!("{head} {v};")
            }
            Stmt::Raise { event, .. } => format!("raise {};", event.name),
            Stmt::If { .. } | Stmt::For { .. } => String::new(),
        }
    }
}
