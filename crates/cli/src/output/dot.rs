//! Graphviz drawings of charts, optionally annotated with coverage counts.

use statecheck_ir::{CoverKind, Program};
use statecheck_model::{Chart, Dest, Model, NodeKind, StateId, Trigger};
use std::fmt::Write;

fn esc(s: &str) -> String {
    s.replace('\\', "\\\\").replace('"', "\\\"")
}

fn node_id(inst: usize, s: StateId) -> String {
    format!("i{inst}_s{s}")
}

/// Draw every instance of a program's system; `counts` annotates entries and firings.
pub fn render(model: &Model, p: &Program, counts: Option<&[u64]>) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "digraph \"{}\" {{\n  compound=true;\n  rankdir=LR;\n  node [shape=box, style=rounded, fontname=\"Helvetica\"];\n  edge [fontname=\"Helvetica\", fontsize=10];", esc(&p.name));
    let count_of = |inst: usize, kind: &CoverKind| -> Option<u64> {
        let counts = counts?;
        p.covers
            .iter()
            .position(|c| c.instance as usize == inst && &c.kind == kind)
            .map(|k| counts[k])
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
            let mut label = String::new();
            match &tr.trigger {
                Trigger::None => {}
                Trigger::Event(v) => label.push_str(&chart.vars[*v as usize].name),
                Trigger::After(k) => label.push_str(&format!("after({k})")),
            }
            if tr.guard.is_some() {
                label.push_str(" [..]");
            }
            if let Some(p) = tr.priority {
                label = format!("{p}: {label}");
            }
            if let Some(n) = n {
                label.push_str(&format!(" ×{n}"));
            }
            let color = if n == Some(0) {
                ", color=red, fontcolor=red"
            } else {
                ""
            };
            let src = anchor(chart, i, tr.source);
            let ltail = lcluster(chart, i, tr.source, "ltail");
            match &tr.dest {
                Dest::Internal => {
                    let _ = writeln!(
                        out,
                        "  {src} -> {src} [label=\"{} (internal)\", style=dashed{ltail}{color}];",
                        esc(label.trim())
                    );
                }
                Dest::State(d) => {
                    let lhead = lcluster(chart, i, *d, "lhead");
                    let _ = writeln!(
                        out,
                        "  {src} -> {} [label=\"{}\"{ltail}{lhead}{color}];",
                        anchor(chart, i, *d),
                        esc(label.trim())
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
                        esc(label.trim())
                    );
                    let mut k = 0;
                    draw_branches(&mut out, chart, i, t, &cid, branches, &count_of, &mut k);
                }
            }
        }
    }
    out.push_str("}\n");
    out
}

#[allow(clippy::too_many_arguments)] // reason: recursive helper threading the drawing context
fn draw_branches(
    out: &mut String,
    chart: &Chart,
    i: usize,
    t: usize,
    from: &str,
    branches: &[statecheck_model::Branch],
    count_of: &dyn Fn(usize, &CoverKind) -> Option<u64>,
    k: &mut u32,
) {
    for b in branches {
        let n = count_of(i, &CoverKind::Branch(t as u32, *k));
        *k += 1;
        let mut label = if b.guard.is_some() {
            "[..]".to_string()
        } else {
            "else".to_string()
        };
        if let Some(n) = n {
            label.push_str(&format!(" ×{n}"));
        }
        let color = if n == Some(0) {
            ", color=red, fontcolor=red"
        } else {
            ""
        };
        match &b.dest {
            Dest::State(d) => {
                let lhead = lcluster(chart, i, *d, "lhead");
                let _ = writeln!(
                    out,
                    "  {from} -> {} [label=\"{}\"{lhead}{color}];",
                    anchor(chart, i, *d),
                    esc(&label)
                );
            }
            Dest::Choice(inner) => {
                let cid = format!("{from}_{k}");
                let _ = writeln!(
                    out,
                    "  {cid} [shape=diamond, label=\"\", width=0.25, height=0.25];"
                );
                let _ = writeln!(out, "  {from} -> {cid} [label=\"{}\"{color}];", esc(&label));
                draw_branches(out, chart, i, t, &cid, inner, count_of, k);
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
    count_of: &dyn Fn(usize, &CoverKind) -> Option<u64>,
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
        let mut label = node.name.clone();
        if let NodeKind::Or {
            history: Some(h), ..
        } = &node.kind
        {
            label.push_str(match h {
                statecheck_syntax::ast::HistoryKind::Shallow => " (H)",
                statecheck_syntax::ast::HistoryKind::Deep => " (H*)",
            });
        }
        if let Some(n) = n {
            label.push_str(&format!("\\n×{n}"));
        }
        let color = if n == Some(0) {
            ", color=red, fontcolor=red"
        } else {
            ""
        };
        if is_composite(chart, k) {
            let style = if node.is_region { "dashed" } else { "rounded" };
            let _ = writeln!(
                out,
                "{pad}subgraph cluster_{} {{\n{pad}  label=\"{}\"; style={style}{};",
                node_id(i, k),
                esc(&label),
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
                esc(&label)
            );
        }
    }
}
