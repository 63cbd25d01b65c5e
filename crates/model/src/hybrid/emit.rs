//! A [`Plan`] as `.sc` text: the declarations that replace `continuous x`, and the chart-level
//! `during` statements that move `x` along its grid and keep the sensors up to date.
//!
//! This text is the one definition of the discretized chart: the checker parses it into the
//! chart's syntax tree (`mod.rs`), and `statecheck show --discretized` prints it in place
//! (`splice.rs`), so what a user reads is what is verified.

use super::plan::Plan;
use std::fmt::Write;

/// The generated names of a variable's timer, mode and start point.
pub struct Names {
    /// Ticks since the last grid point (constant speed) or since the motion began (profile).
    pub ticks: String,
    /// The active motion mode (0: standing still).
    pub mode: String,
    /// Where the current profile motion began.
    pub from: String,
}

impl Names {
    /// The names for variable `var`.
    pub fn of(var: &str) -> Names {
        Names {
            ticks: format!("{var}_ticks"),
            mode: format!("{var}_mode"),
            from: format!("{var}_from"),
        }
    }
}

/// Does any mode of `p` follow a profile (so `x_from` is needed)?
fn has_profile(p: &Plan) -> bool {
    p.modes.iter().any(|m| m.constant().is_none())
}

/// The largest clock reading of `p` in ticks (at least 1).
fn max_ticks(p: &Plan) -> i64 {
    p.modes
        .iter()
        .flat_map(|m| m.table.iter().flatten().map(|(_, k)| *k))
        .max()
        .unwrap_or(1)
        .max(1)
}

/// The declarations replacing `continuous x: …;`, one per line.
pub fn decls(p: &Plan) -> String {
    let n = Names::of(&p.var);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "output {}: int[{} .. {}] = {};",
        p.var, p.lo, p.hi, p.init
    );
    if !p.modes.is_empty() {
        let _ = writeln!(s, "local {}: int[0 .. {}] = 0;", n.mode, p.modes.len());
        let _ = writeln!(s, "local {}: int[0 .. {}] = 0;", n.ticks, max_ticks(p));
        if has_profile(p) {
            let _ = writeln!(
                s,
                "local {}: int[{} .. {}] = {};",
                n.from, p.lo, p.hi, p.init
            );
        }
    }
    s
}

/// The comment describing the grid (for `show --discretized`).
pub fn grid_comment(p: &Plan) -> String {
    let pts: Vec<String> = p.points.iter().map(i64::to_string).collect();
    let mut s = format!("// `{}` on the grid {{{}}}", p.var, pts.join(", "));
    if p.coarse {
        s.push_str(" (coarse: home/moving/end)");
    } else if !p.forced.is_empty() {
        let f: Vec<String> = p.forced.iter().map(i64::to_string).collect();
        let _ = write!(s, "; critical points added: {}", f.join(", "));
    }
    s
}

/// A sensor's predicate over the grid variable.
pub fn sensor_expr(p: &Plan, lo: i64, hi: i64) -> String {
    let mut parts = Vec::new();
    if lo > p.lo {
        parts.push(format!("{} >= {lo}", p.var));
    }
    if hi < p.hi {
        parts.push(format!("{} <= {hi}", p.var));
    }
    if lo > hi || lo > p.hi || hi < p.lo {
        return "false".into();
    }
    if parts.is_empty() {
        "true".into()
    } else {
        parts.join(" && ")
    }
}

/// Is a sensor on at the grid point `x`?
pub fn sensor_at(x: i64, lo: i64, hi: i64) -> bool {
    lo <= x && x <= hi
}

/// The statements of the chart-level `during` for `p`.
pub fn during(p: &Plan) -> String {
    let n = Names::of(&p.var);
    let mut s = String::new();
    if !p.modes.is_empty() {
        // Which mode is active: the innermost state first (a nested `der` overrides).
        let mut order: Vec<usize> = (0..p.modes.len()).collect();
        order.sort_by_key(|i| std::cmp::Reverse(p.modes[*i].path.len()));
        for (k, i) in order.iter().enumerate() {
            let m = i + 1;
            let path = p.modes[*i].path.join(".");
            let reset_from = if has_profile(p) {
                format!(" {} = {};", n.from, p.var)
            } else {
                String::new()
            };
            let _ = write!(
                s,
                "{}if in({path}) {{ if {} != {m} {{ {} = {m}; {} = 0;{reset_from} }} }}",
                if k == 0 { "" } else { " else " },
                n.mode,
                n.mode,
                n.ticks
            );
        }
        let _ = writeln!(s, " else {{ {} = 0; {} = 0; }}", n.mode, n.ticks);
        let mut first = true;
        for (i, m) in p.modes.iter().enumerate() {
            let body = motion(p, i, &n);
            if body.is_empty() {
                continue;
            }
            let _ = writeln!(
                s,
                "{}if {} == {} {{\n{body}}}",
                if first { "" } else { "else " },
                n.mode,
                i + 1
            );
            let _ = m;
            first = false;
        }
    }
    // A sensor is sampled exactly at every tick for constant speeds: after a motion left a
    // grid point (timer > 0) the position lies strictly inside the next cell, whose sensor
    // value is that of the open cell.
    let moving = |dir: i128| -> Vec<String> {
        p.modes
            .iter()
            .enumerate()
            .filter(|(_, m)| m.constant().is_some() && m.direction() == dir)
            .map(|(i, _)| format!("{} == {}", n.mode, i + 1))
            .collect()
    };
    let (up, down) = (moving(1), moving(-1));
    for (out, lo, hi) in &p.sensors {
        let at_point = sensor_expr(p, *lo, *hi);
        let mut arms = Vec::new();
        if !up.is_empty() {
            arms.push((up.join(" || "), cell_expr(p, *lo, *hi, true)));
        }
        if !down.is_empty() {
            arms.push((down.join(" || "), cell_expr(p, *lo, *hi, false)));
        }
        arms.retain(|(_, e)| *e != at_point);
        for (k, (cond, e)) in arms.iter().enumerate() {
            let _ = write!(
                s,
                "{}if ({cond}) && {} > 0 {{ {out} = {e}; }}",
                if k == 0 { "" } else { " else " },
                n.ticks
            );
        }
        if arms.is_empty() {
            let _ = writeln!(s, "{out} = {at_point};");
        } else {
            let _ = writeln!(s, " else {{ {out} = {at_point}; }}");
        }
    }
    s
}

/// A sensor's value inside the open cell after the grid point `x` (moving up: `(x, next)`)
/// or before it (moving down: `(prev, x)`); the bounds are grid points, so the cell is
/// wholly inside or outside.
fn cell_expr(p: &Plan, lo: i64, hi: i64, up: bool) -> String {
    if lo > hi || lo >= p.hi || hi <= p.lo {
        return "false".into();
    }
    let x = &p.var;
    let mut parts = Vec::new();
    if up {
        if lo > p.lo {
            parts.push(format!("{x} >= {lo}"));
        }
        if hi < p.hi {
            parts.push(format!("{x} < {hi}"));
        }
    } else {
        if lo > p.lo {
            parts.push(format!("{x} > {lo}"));
        }
        if hi < p.hi {
            parts.push(format!("{x} <= {hi}"));
        }
    }
    if parts.is_empty() {
        "true".into()
    } else {
        parts.join(" && ")
    }
}

/// The motion of mode `i` (empty when it never moves).
fn motion(p: &Plan, i: usize, n: &Names) -> String {
    let m = &p.modes[i];
    let dir = m.direction();
    if dir == 0 || m.table.iter().all(Vec::is_empty) {
        return String::new();
    }
    let mut s = String::new();
    let x = &p.var;
    if m.constant().is_some() {
        let (end, cmp) = if dir > 0 { (p.hi, "<") } else { (p.lo, ">") };
        let _ = writeln!(s, "if {x} {cmp} {end} {{ {} += 1;", n.ticks);
        let steps: Vec<(usize, usize, i64)> = m
            .table
            .iter()
            .enumerate()
            .flat_map(|(from, t)| t.iter().map(move |(to, k)| (from, *to, *k)))
            .collect();
        let uniform = steps.windows(2).all(|w| {
            w[0].2 == w[1].2
                && (p.points[w[0].1] - p.points[w[0].0]) == (p.points[w[1].1] - p.points[w[1].0])
        });
        if uniform && !steps.is_empty() {
            let (from, to, k) = steps[0];
            let step = p.points[to] - p.points[from];
            let (op, mag) = if step > 0 {
                ("+=", step)
            } else {
                ("-=", -step)
            };
            let _ = writeln!(
                s,
                "if {} >= {k} {{ {x} {op} {mag}; {} = 0; }}",
                n.ticks, n.ticks
            );
        } else {
            for (c, (from, to, k)) in steps.iter().enumerate() {
                let _ = writeln!(
                    s,
                    "{}if {x} == {} && {} >= {k} {{ {x} = {}; {} = 0; }}",
                    if c == 0 { "" } else { "else " },
                    p.points[*from],
                    n.ticks,
                    p.points[*to],
                    n.ticks
                );
            }
        }
        s.push_str("}\n");
    } else {
        let h = m.table.iter().flatten().map(|(_, k)| *k).max().unwrap_or(1);
        let _ = writeln!(s, "if {} < {h} {{ {} += 1; }}", n.ticks, n.ticks);
        let mut first = true;
        for (from, t) in m.table.iter().enumerate() {
            if t.is_empty() {
                continue;
            }
            let _ = write!(
                s,
                "{}if {} == {} {{ ",
                if first { "" } else { "else " },
                n.from,
                p.points[from]
            );
            for (c, (to, k)) in t.iter().enumerate() {
                let _ = write!(
                    s,
                    "{}if {} == {k} {{ {x} = {}; }}",
                    if c == 0 { "" } else { " else " },
                    n.ticks,
                    p.points[*to]
                );
            }
            s.push_str(" }\n");
            first = false;
        }
    }
    s
}
