//! Writing AIGER 1.9 (ASCII `aag` and binary `aig`).

use crate::aig::{Aig, Lit, Node};

/// The graph renumbered in AIGER order: inputs, latches, then AND gates (topological).
struct Numbered {
    map: Vec<u32>,
    ands: Vec<(u32, u32, u32)>,
    max_var: u32,
}

fn number(g: &Aig) -> Numbered {
    let mut map = vec![0u32; g.nodes.len()];
    let mut next = 1u32;
    for &v in &g.inputs {
        map[v as usize] = next;
        next += 1;
    }
    for l in &g.latches {
        map[l.var as usize] = next;
        next += 1;
    }
    let lit = |map: &[u32], l: Lit| (map[l.var() as usize] << 1) | u32::from(l.is_neg());
    let mut ands = Vec::new();
    for (v, n) in g.nodes.iter().enumerate() {
        if let Node::And(a, b) = *n {
            map[v] = next;
            let (x, y) = (lit(&map, a), lit(&map, b));
            let (x, y) = if x >= y { (x, y) } else { (y, x) };
            ands.push((next << 1, x, y));
            next += 1;
        }
    }
    Numbered {
        map,
        ands,
        max_var: next - 1,
    }
}

fn header(g: &Aig, n: &Numbered, kind: &str) -> String {
    let live = if g.justice.is_empty() && g.fairness.is_empty() {
        String::new()
    } else {
        format!(" {} {}", g.justice.len(), g.fairness.len())
    };
    format!(
        "{kind} {} {} {} 0 {} {} {}{live}\n",
        n.max_var,
        g.inputs.len(),
        g.latches.len(),
        n.ands.len(),
        g.bad.len(),
        g.constraints.len()
    )
}

/// The bad, constraint, justice and fairness sections (one literal per line; each justice
/// property's size first).
fn properties(g: &Aig, n: &Numbered, s: &mut String) {
    let lit = |x: Lit| (n.map[x.var() as usize] << 1) | u32::from(x.is_neg());
    for &b in &g.bad {
        s.push_str(&format!("{}\n", lit(b)));
    }
    for &c in &g.constraints {
        s.push_str(&format!("{}\n", lit(c)));
    }
    for j in &g.justice {
        s.push_str(&format!("{}\n", j.len()));
    }
    for &l in g.justice.iter().flatten() {
        s.push_str(&format!("{}\n", lit(l)));
    }
    for &f in &g.fairness {
        s.push_str(&format!("{}\n", lit(f)));
    }
}

fn latch_line(n: &Numbered, g: &Aig, i: usize, with_lhs: bool) -> String {
    let l = &g.latches[i];
    let lit = |x: Lit| (n.map[x.var() as usize] << 1) | u32::from(x.is_neg());
    let cur = n.map[l.var as usize] << 1;
    let next = lit(l.next);
    let reset = match l.init {
        Some(false) => String::new(),
        Some(true) => " 1".to_string(),
        None => format!(" {cur}"),
    };
    if with_lhs {
        format!("{cur} {next}{reset}\n")
    } else {
        format!("{next}{reset}\n")
    }
}

fn tail(g: &Aig, n: &Numbered, out: &mut Vec<u8>, comment: &str) {
    let lit = |x: Lit| (n.map[x.var() as usize] << 1) | u32::from(x.is_neg());
    let mut s = String::new();
    let _ = lit;
    for (i, name) in g.input_names.iter().enumerate() {
        if let Some(nm) = name {
            s.push_str(&format!("i{i} {nm}\n"));
        }
    }
    for (i, name) in g.latch_names.iter().enumerate() {
        if let Some(nm) = name {
            s.push_str(&format!("l{i} {nm}\n"));
        }
    }
    for (i, name) in g.bad_names.iter().enumerate() {
        if let Some(nm) = name {
            s.push_str(&format!("b{i} {nm}\n"));
        }
    }
    for (i, name) in g.justice_names.iter().enumerate() {
        if let Some(nm) = name {
            s.push_str(&format!("j{i} {nm}\n"));
        }
    }
    if !comment.is_empty() {
        s.push_str("c\n");
        s.push_str(comment);
        if !comment.ends_with('\n') {
            s.push('\n');
        }
    }
    out.extend_from_slice(s.as_bytes());
}

/// The ASCII AIGER (`aag`) text of a graph, with its symbol table and a comment.
pub fn ascii(g: &Aig, comment: &str) -> Vec<u8> {
    let n = number(g);
    let mut s = header(g, &n, "aag");
    for &v in &g.inputs {
        s.push_str(&format!("{}\n", n.map[v as usize] << 1));
    }
    for i in 0..g.latches.len() {
        s.push_str(&latch_line(&n, g, i, true));
    }
    properties(g, &n, &mut s);
    for &(o, a, b) in &n.ands {
        s.push_str(&format!("{o} {a} {b}\n"));
    }
    let mut out = s.into_bytes();
    tail(g, &n, &mut out, comment);
    out
}

fn push_delta(out: &mut Vec<u8>, mut x: u32) {
    while x & !0x7f != 0 {
        out.push((x & 0x7f) as u8 | 0x80);
        x >>= 7;
    }
    out.push(x as u8);
}

/// The binary AIGER (`aig`) bytes of a graph, with its symbol table and a comment.
pub fn binary(g: &Aig, comment: &str) -> Vec<u8> {
    let n = number(g);
    let mut s = header(g, &n, "aig");
    for i in 0..g.latches.len() {
        s.push_str(&latch_line(&n, g, i, false));
    }
    properties(g, &n, &mut s);
    let mut out = s.into_bytes();
    for &(o, a, b) in &n.ands {
        push_delta(&mut out, o - a);
        push_delta(&mut out, a - b);
    }
    tail(g, &n, &mut out, comment);
    out
}
