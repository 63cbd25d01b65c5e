//! Graphviz drawings of charts, optionally annotated with coverage counts: triggers, guards
//! and actions as written (`dot_text`), one line each; an observer's `error` state, meant
//! never to be entered, is drawn with a double border and never as a coverage gap.

use super::dot_text::{esc, label as lines, Written};
use statecheck_ir::{CoverKind, Program};
use statecheck_model::{Chart, Dest, Model, NodeKind, StateId, Trigger};
use std::fmt::Write;

fn node_id(inst: usize, s: StateId) -> String {
    format!("i{inst}_s{s}")
}

/// Draw every instance of a program's system; `written` gives the transitions' text;
/// `counts` annotates entries and firings.
pub fn render(model: &Model, p: &Program, written: &Written, counts: Option<&[u64]>) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "digraph \"{}\" {{\n  compound=true;\n  rankdir=LR;\n  node [shape=box, style=rounded, fontname=\"Helvetica\"];\n  edge [fontname=\"Helvetica\", fontsize=10];", esc(&p.name));
    // The count of an item, and whether it is meant never to be covered.
    let count_of = |inst: usize, kind: &CoverKind| -> Option<(u64, bool)> {
        let counts = counts?;
        p.covers
            .iter()
            .position(|c| c.instance as usize == inst && &c.kind == kind)
            .map(|k| (counts[k], p.covers[k].expected_unreached))
    };
    for (i, inst) in p.instances.iter().enumerate() {
        let chart = &model.charts[inst.chart as usize];
        let _ = writeln!(
            out,
            "  subgraph cluster_i{i} {{\n    label=\"{}: {}\";",
            esc(&inst.name),
            esc(&chart.name)
        );
        draw_children(&mut out, chart, i, 0, &count_of, 2);
        let _ = writeln!(out, "  }}");
        for (t, tr) in chart.transitions.iter().enumerate() {
            let n = count_of(i, &CoverKind::Transition(t as u32));
            let parts = written.parts(tr.span);
            let mut first = parts.trigger.map(|t| written.text(t)).unwrap_or_default();
            // A timer written in ticks also shows its time when the model declares a tick.
            if let Trigger::After(n) = tr.trigger {
                let in_units = [" s)", "ms)", "min)"].iter().any(|u| first.ends_with(u));
                if let Some(t) = u64::try_from(n).ok().and_then(|n| p.time_text(n)) {
                    if !in_units {
                        first = format!("{first} = {t} s");
                    }
                }
            }
            if let Some(g) = parts.guard {
                first = format!("{first} [{}]", written.text(g));
            }
            if let Some(p) = tr.priority {
                first = format!("{p}: {}", first.trim());
            }
            let mut label = vec![first.trim().to_string()];
            if let Some(a) = parts.action {
                label.push(format!("/ {}", written.action(a)));
            }
            if let Some((n, _)) = n {
                label.push(format!("×{n}"));
            }
            let color = gap_color(n);
            let src = anchor(chart, i, tr.source);
            let ltail = lcluster(chart, i, tr.source, "ltail");
            match &tr.dest {
                Dest::Internal => {
                    let _ = writeln!(
                        out,
                        "  {src} -> {src} [label=\"{}\", style=dashed{ltail}{color}];",
                        lines(&[label, vec!["(internal)".to_string()]].concat())
                    );
                }
                Dest::State(d) => {
                    let lhead = lcluster(chart, i, *d, "lhead");
                    let _ = writeln!(
                        out,
                        "  {src} -> {} [label=\"{}\"{ltail}{lhead}{color}];",
                        anchor(chart, i, *d),
                        lines(&label)
                    );
                }
                Dest::Choice(branches) => {
                    let cid = format!("i{i}_t{t}_choice");
                    let _ = writeln!(
                        out,
                        "  {cid} [shape=diamond, label=\"\", width=0.25, height=0.25];"
                    );
                    let _ = writeln!(
                        out,
                        "  {src} -> {cid} [label=\"{}\"{ltail}{color}];",
                        lines(&label)
                    );
                    let mut k = 0;
                    let at = Branches {
                        chart,
                        i,
                        t,
                        written,
                        count_of: &count_of,
                    };
                    draw_branches(&mut out, &at, &cid, branches, &mut k);
                }
            }
        }
    }
    out.push_str("}\n");
    out
}

/// An item's count and whether it is meant never to be covered.
type CountOf<'a> = dyn Fn(usize, &CoverKind) -> Option<(u64, bool)> + 'a;

/// What drawing a transition's choice branches needs.
struct Branches<'a> {
    chart: &'a Chart,
    i: usize,
    t: usize,
    written: &'a Written<'a>,
    count_of: &'a CountOf<'a>,
}

/// Red for an item never covered, unless it is meant never to be.
fn gap_color(n: Option<(u64, bool)>) -> &'static str {
    if n == Some((0, false)) {
        ", color=red, fontcolor=red"
    } else {
        ""
    }
}

fn draw_branches(
    out: &mut String,
    at: &Branches,
    from: &str,
    branches: &[statecheck_model::Branch],
    k: &mut u32,
) {
    let (chart, i) = (at.chart, at.i);
    for b in branches {
        let n = (at.count_of)(i, &CoverKind::Branch(at.t as u32, *k));
        *k += 1;
        let parts = at.written.parts(b.span);
        let mut label = vec![match parts.guard {
            Some(g) => format!("[{}]", at.written.text(g)),
            None if b.guard.is_some() => "[..]".to_string(),
            None => "else".to_string(),
        }];
        if let Some(a) = parts.action {
            label.push(format!("/ {}", at.written.action(a)));
        }
        if let Some((n, _)) = n {
            label.push(format!("×{n}"));
        }
        let color = gap_color(n);
        match &b.dest {
            Dest::State(d) => {
                let lhead = lcluster(chart, i, *d, "lhead");
                let _ = writeln!(
                    out,
                    "  {from} -> {} [label=\"{}\"{lhead}{color}];",
                    anchor(chart, i, *d),
                    lines(&label)
                );
            }
            Dest::Choice(inner) => {
                let cid = format!("{from}_{k}");
                let _ = writeln!(
                    out,
                    "  {cid} [shape=diamond, label=\"\", width=0.25, height=0.25];"
                );
                let _ = writeln!(
                    out,
                    "  {from} -> {cid} [label=\"{}\"{color}];",
                    lines(&label)
                );
                draw_branches(out, at, &cid, inner, k);
            }
            Dest::Internal => {}
        }
    }
}

fn is_composite(chart: &Chart, s: StateId) -> bool {
    !matches!(chart.states[s as usize].kind, NodeKind::Simple)
}

/// The node an edge attaches to: the state itself, or a composite's invisible anchor.
fn anchor(chart: &Chart, i: usize, s: StateId) -> String {
    if is_composite(chart, s) {
        format!("{}_anchor", node_id(i, s))
    } else {
        node_id(i, s)
    }
}

fn lcluster(chart: &Chart, i: usize, s: StateId, attr: &str) -> String {
    if is_composite(chart, s) && s != 0 {
        format!(", {attr}=cluster_{}", node_id(i, s))
    } else {
        String::new()
    }
}

fn draw_children(
    out: &mut String,
    chart: &Chart,
    i: usize,
    s: StateId,
    count_of: &CountOf,
    depth: usize,
) {
    let pad = "  ".repeat(depth);
    let kids: Vec<StateId> = match &chart.states[s as usize].kind {
        NodeKind::Simple => Vec::new(),
        NodeKind::Or { children, .. } => children.clone(),
        NodeKind::And { regions } => regions.clone(),
    };
    let initial = match &chart.states[s as usize].kind {
        NodeKind::Or {
            children, initial, ..
        } => Some(children[*initial]),
        _ => None,
    };
    if let Some(init) = initial {
        let _ = writeln!(out, "{pad}{}_init [shape=point];", node_id(i, s));
        let lhead = lcluster(chart, i, init, "lhead");
        let _ = writeln!(
            out,
            "{pad}{}_init -> {} [arrowhead=normal{lhead}];",
            node_id(i, s),
            anchor(chart, i, init)
        );
    }
    for k in kids {
        let node = &chart.states[k as usize];
        let n = count_of(i, &CoverKind::State(k));
        let mut name = node.name.clone();
        if let NodeKind::Or {
            history: Some(h), ..
        } = &node.kind
        {
            name.push_str(match h {
                statecheck_syntax::ast::HistoryKind::Shallow => " (H)",
                statecheck_syntax::ast::HistoryKind::Deep => " (H*)",
            });
        }
        let mut label = vec![name];
        if let Some((n, _)) = n {
            label.push(format!("×{n}"));
        }
        let mut color = gap_color(n);
        if chart.is_observer_error(k) {
            color = ", peripheries=2";
        }
        if is_composite(chart, k) {
            let style = if node.is_region { "dashed" } else { "rounded" };
            let _ = writeln!(
                out,
                "{pad}subgraph cluster_{} {{\n{pad}  label=\"{}\"; style={style}{};",
                node_id(i, k),
                lines(&label),
                color.replace(", ", "; ")
            );
            let _ = writeln!(
                out,
                "{pad}  {}_anchor [shape=point, style=invis];",
                node_id(i, k)
            );
            draw_children(out, chart, i, k, count_of, depth + 1);
            let _ = writeln!(out, "{pad}}}");
        } else {
            let _ = writeln!(
                out,
                "{pad}{} [label=\"{}\"{color}];",
                node_id(i, k),
                lines(&label)
            );
        }
    }
}
