//! From a chart's hybrid elements to a [`Plan`] per continuous variable: the grid (equal
//! cells, forced critical points, or the coarse ends), the motion modes (one per state with
//! `der`), and the clock readings, in ticks, at which each mode reaches each grid point.

use super::rational::Ratio;
use super::Cx;
use statecheck_base::Span;
use statecheck_syntax::ast::{self, HybridElem};

/// The most grid points a variable may have.
pub const MAX_POINTS: usize = 2_000;

/// One continuous variable of a chart, discretized.
#[derive(Clone, Debug)]
pub struct Plan {
    /// The variable.
    pub var: String,
    /// The range.
    pub lo: i64,
    /// The range's upper end.
    pub hi: i64,
    /// The initial value (a grid point).
    pub init: i64,
    /// The grid, ascending, both ends included.
    pub points: Vec<i64>,
    /// Grid points added only because the model compares the variable with them.
    pub forced: Vec<i64>,
    /// The home/moving/end abstraction (`grid x coarse;`).
    pub coarse: bool,
    /// The motion modes; mode `m` is `modes[m - 1]` (0: standing still).
    pub modes: Vec<Mode>,
    /// The points the model names: range ends, initial value, sensor bounds and compared
    /// constants inside the range (all on the grid unless `coarse`).
    pub critical: Vec<i64>,
    /// The sensors: output name and range.
    pub sensors: Vec<(String, i64, i64)>,
    /// The `continuous` declaration.
    pub span: Span,
}

/// A state with `der(x) = …`.
#[derive(Clone, Debug)]
pub struct Mode {
    /// The state's path from the chart (`Outer.Inner`).
    pub path: Vec<String>,
    /// Speed segments from the state's entry (units per second; the last lasts forever).
    pub profile: Vec<(Ratio, Option<Ratio>)>,
    /// Clock readings: `table[s]` lists `(j, ticks)` for a motion that starts at point `s`
    /// and reaches point `j` after `ticks` ticks, nearest point first. A constant speed lists
    /// only the next point (the reading restarts there); a profile lists every point it
    /// reaches.
    pub table: Vec<Vec<(usize, i64)>>,
    /// The `der` element.
    pub span: Span,
}

impl Mode {
    /// The direction of motion: 1 up, -1 down, 0 standing still.
    pub fn direction(&self) -> i128 {
        self.profile
            .iter()
            .map(|(v, _)| v.signum())
            .find(|s| *s != 0)
            .unwrap_or(0)
    }

    /// A constant speed (not a profile).
    pub fn constant(&self) -> Option<Ratio> {
        match self.profile.as_slice() {
            [(v, None)] => Some(*v),
            _ => None,
        }
    }
}

/// The time (seconds, from the state's entry) at which the motion has covered `dist` (> 0),
/// or `None` if it never does.
pub fn crossing(profile: &[(Ratio, Option<Ratio>)], dist: Ratio) -> Option<Ratio> {
    let mut t = Ratio::ZERO;
    let mut left = dist;
    for (v, d) in profile {
        let v = v.abs();
        match d {
            Some(d) => {
                let covered = v.checked_mul(*d)?;
                if v.signum() != 0 && covered >= left {
                    return t.checked_add(left.checked_div(v)?);
                }
                left = left.checked_sub(covered)?;
                t = t.checked_add(*d)?;
            }
            None => {
                if v.signum() == 0 {
                    return None;
                }
                return t.checked_add(left.checked_div(v)?);
            }
        }
    }
    None
}

impl Cx<'_, '_> {
    /// The plans of one chart (empty when it has no continuous variable).
    pub fn plan_chart(&mut self, chart: &ast::Chart) -> Vec<Plan> {
        let mut plans = Vec::new();
        let mut grids: Vec<(String, Option<i64>, Span)> = Vec::new();
        let mut sensors = Vec::new();
        for h in &chart.body.hybrid {
            match h {
                HybridElem::Continuous {
                    name,
                    lo,
                    hi,
                    init,
                    span,
                } => {
                    if plans.iter().any(|p: &Plan| p.var == name.name) {
                        self.error(
                            *span,
                            "E0182",
                            format!("`{}` is declared twice", name.name),
                            "declare each continuous variable once",
                        );
                        continue;
                    }
                    let (Some(l), Some(h)) = (self.konst(lo), self.konst(hi)) else {
                        continue;
                    };
                    if l >= h {
                        self.error(
                            *span,
                            "E0180",
                            format!(
                                "the range of `{}` is empty or a single point ({l} .. {h})",
                                name.name
                            ),
                            "write the range as `[lo .. hi]` with lo < hi",
                        );
                        continue;
                    }
                    let i = match init {
                        Some(e) => match self.konst(e) {
                            Some(v) => v,
                            None => continue,
                        },
                        None => l,
                    };
                    if i < l || i > h {
                        self.error(
                            *span,
                            "E0180",
                            format!(
                                "the initial value {i} of `{}` is outside its range {l} .. {h}",
                                name.name
                            ),
                            "give an initial value inside the range",
                        );
                        continue;
                    }
                    plans.push(Plan {
                        var: name.name.clone(),
                        lo: l,
                        hi: h,
                        init: i,
                        points: Vec::new(),
                        forced: Vec::new(),
                        critical: Vec::new(),
                        coarse: false,
                        modes: Vec::new(),
                        sensors: Vec::new(),
                        span: *span,
                    });
                }
                HybridElem::Grid { var, cells, span } => {
                    if grids.iter().any(|g| g.0 == var.name) {
                        self.error(
                            *span,
                            "E0182",
                            format!("`{}` has two `grid` declarations", var.name),
                            "keep one",
                        );
                        continue;
                    }
                    let n = match cells {
                        Some(e) => match self.konst(e) {
                            Some(n) if n >= 1 => Some(n),
                            Some(n) => {
                                self.error(
                                    *span,
                                    "E0180",
                                    format!("a grid needs at least one cell, not {n}"),
                                    "write `grid x N;` with N >= 1, or `grid x coarse;`",
                                );
                                continue;
                            }
                            None => continue,
                        },
                        None => None,
                    };
                    grids.push((var.name.clone(), n, *span));
                }
                HybridElem::Sensor {
                    output,
                    var,
                    lo,
                    hi,
                    span,
                } => {
                    if let (Some(l), Some(h)) = (self.konst(lo), self.konst(hi)) {
                        sensors.push((output.clone(), var.clone(), l, h, *span));
                    }
                }
                HybridElem::Der { span, .. } => {
                    self.error(
                        *span,
                        "E0182",
                        "`der` belongs in a state, not at chart level",
                        "move it into the state in which the variable moves",
                    );
                }
            }
        }
        for (g, _, span) in &grids {
            if !plans.iter().any(|p| &p.var == g) {
                self.error(
                    *span,
                    "E0182",
                    format!("`{g}` is not a continuous variable of this chart"),
                    "declare it with `continuous NAME: [lo .. hi];`",
                );
            }
        }
        for (out, var, l, h, span) in sensors {
            let Some(p) = plans.iter_mut().find(|p| p.var == var.name) else {
                self.error(
                    span,
                    "E0182",
                    format!("`{}` is not a continuous variable of this chart", var.name),
                    "declare it with `continuous NAME: [lo .. hi];`",
                );
                continue;
            };
            let decl = chart.vars.iter().find(|v| v.name.name == out.name);
            let is_bool = decl.is_some_and(|v| {
                !v.is_event
                    && v.kind != ast::VarKind::Input
                    && matches!(v.ty, Some(ast::TypeExpr::Bool(_)))
            });
            if !is_bool {
                self.error(
                    span,
                    "E0182",
                    format!(
                        "sensor `{}` must be a `bool` output or local of the chart",
                        out.name
                    ),
                    format!("declare `output {}: bool;`", out.name),
                );
                continue;
            }
            if p.sensors.iter().any(|s| s.0 == out.name) {
                self.error(
                    span,
                    "E0182",
                    format!("`{}` is the output of two sensors", out.name),
                    "one sensor per output",
                );
                continue;
            }
            p.sensors.push((out.name.clone(), l, h));
        }
        let critical = super::critical::collect(chart, self.file, &plans);
        for p in &mut plans {
            let grid = grids.iter().find(|g| g.0 == p.var);
            self.grid(p, grid.map(|g| (g.1, g.2)), &critical);
        }
        self.modes(chart, &mut plans);
        plans
    }

    /// The grid points of `p`.
    fn grid(
        &mut self,
        p: &mut Plan,
        grid: Option<(Option<i64>, Span)>,
        critical: &[(String, i64)],
    ) {
        let mut named = vec![p.lo, p.hi, p.init];
        named.extend(
            critical
                .iter()
                .filter(|(v, c)| *v == p.var && *c > p.lo && *c < p.hi)
                .map(|(_, c)| *c),
        );
        named.extend(
            p.sensors
                .iter()
                .flat_map(|(_, l, h)| [*l, *h])
                .filter(|x| *x >= p.lo && *x <= p.hi),
        );
        named.sort_unstable();
        named.dedup();
        p.critical = named;
        let mut pts = vec![p.lo, p.hi, p.init];
        let mut equal = Vec::new();
        match grid {
            Some((None, _)) => p.coarse = true,
            Some((Some(n), span)) => {
                let width = p.hi as i128 - p.lo as i128;
                if width % n as i128 != 0 {
                    self.error(span, "E0180", format!("{n} equal cells of `{}` ({} .. {}) are not whole numbers wide", p.var, p.lo, p.hi), "choose a number of cells that divides the range's width, or scale the variable's unit");
                    return;
                }
                if n as usize > MAX_POINTS {
                    self.error(
                        span,
                        "E0180",
                        format!("a grid of {n} cells is more than the {MAX_POINTS} points allowed"),
                        "use fewer cells",
                    );
                    return;
                }
                let cell = (width / n as i128) as i64;
                equal = (0..=n).map(|i| p.lo + i * cell).collect();
                pts.extend(&equal);
            }
            None => {}
        }
        if !p.coarse {
            for (v, c) in critical {
                if *v == p.var && *c > p.lo && *c < p.hi {
                    pts.push(*c);
                }
            }
            for (_, l, h) in &p.sensors {
                pts.extend([*l, *h].into_iter().filter(|x| *x > p.lo && *x < p.hi));
            }
        }
        pts.sort_unstable();
        pts.dedup();
        if pts.len() > MAX_POINTS {
            self.error(
                p.span,
                "E0180",
                format!(
                    "`{}` needs {} grid points, more than the {MAX_POINTS} allowed",
                    p.var,
                    pts.len()
                ),
                "compare the variable with fewer distinct numbers",
            );
            return;
        }
        if !equal.is_empty() {
            p.forced = pts.iter().copied().filter(|x| !equal.contains(x)).collect();
        }
        p.points = pts;
    }
}
