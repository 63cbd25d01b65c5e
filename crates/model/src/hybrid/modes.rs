//! The motion modes of a chart (each state with `der(x) = …`) and their clock readings: the
//! ticks after which the motion reaches each grid point, exact in rational arithmetic, with
//! `E0181` when a reading is not a whole number of ticks.

use super::plan::{crossing, Mode, Plan};
use super::rational::Ratio;
use super::Cx;
use statecheck_base::{Diagnostic, Span};
use statecheck_syntax::ast::{self, HybridElem, SpeedExpr, SpeedNumber};

/// The most states a variable may move in (the generated mode selection is one `if … else
/// if …` chain, which must stay well within the parser's nesting limit).
const MAX_MODES: usize = 100;

/// The most grid points a variable with a speed profile may have (its table is quadratic).
const MAX_PROFILE_POINTS: usize = 200;

impl Cx<'_, '_> {
    /// Collect the modes of every plan from the chart's states and compute their tables.
    pub(super) fn modes(&mut self, chart: &ast::Chart, plans: &mut [Plan]) {
        let mut found = Vec::new();
        walk(&chart.body, &mut Vec::new(), &mut found, self, true);
        for (path, var, rate, span) in found {
            if let Some((name, at)) = variable_in(&rate, chart, plans) {
                self.error(
                    at,
                    "E0183",
                    format!("the speed of `{var}` depends on `{name}`, a variable"),
                    "only piecewise-constant speeds have exact clock readings: use constants, \
                     chart parameters or a `profile(…)` (docs/hybrid.md, \"Why every reading \
                     is exact\")",
                );
                continue;
            }
            let Some(p) = plans.iter_mut().find(|p| p.var == var) else {
                self.error(
                    span,
                    "E0182",
                    format!("`{var}` is not a continuous variable of this chart"),
                    "declare it at chart level with `continuous NAME: [lo .. hi];`",
                );
                continue;
            };
            if p.modes.iter().any(|m| m.path == path) {
                self.error(
                    span,
                    "E0182",
                    format!("a state gives `der({var})` twice"),
                    "keep one",
                );
                continue;
            }
            let Some(profile) = self.profile(&rate) else {
                continue;
            };
            let signs: Vec<i128> = profile
                .iter()
                .map(|(v, _)| v.signum())
                .filter(|s| *s != 0)
                .collect();
            if signs.windows(2).any(|w| w[0] != w[1]) {
                self.error(
                    span,
                    "E0182",
                    "a speed profile changes direction",
                    "split the motion into states, one per direction",
                );
                continue;
            }
            p.modes.push(Mode {
                path,
                profile,
                table: Vec::new(),
                span,
            });
        }
        for p in plans.iter_mut() {
            if p.modes.len() > MAX_MODES {
                self.error(
                    p.span,
                    "E0182",
                    format!(
                        "`{}` moves in {} states, more than the {MAX_MODES} allowed",
                        p.var,
                        p.modes.len()
                    ),
                    "merge states that move alike",
                );
                p.modes.clear();
                continue;
            }
            self.tables(p);
        }
    }

    /// A `der` right-hand side as speed segments (units per second).
    fn profile(&mut self, rate: &SpeedExpr) -> Option<Vec<(Ratio, Option<Ratio>)>> {
        match rate {
            SpeedExpr::Constant(s) => Some(vec![(self.speed(s)?, None)]),
            SpeedExpr::Profile(segs, last) => {
                let mut out = Vec::new();
                for (s, d) in segs {
                    let v = self.speed(s)?;
                    let amount = self.konst(&d.amount)?;
                    let per = match d.unit {
                        ast::TimeUnit::Ms => Ratio::new(1, 1000)?,
                        ast::TimeUnit::S => Ratio::int(1),
                        ast::TimeUnit::Min => Ratio::int(60),
                    };
                    let secs = Ratio::int(amount).checked_mul(per)?;
                    if secs.signum() <= 0 {
                        self.error(
                            d.span,
                            "E0182",
                            "a profile segment must last a positive time",
                            "write e.g. `1 for 2 s`",
                        );
                        return None;
                    }
                    out.push((v, Some(secs)));
                }
                out.push((self.speed(last)?, None));
                Some(out)
            }
        }
    }

    fn speed(&mut self, s: &ast::Speed) -> Option<Ratio> {
        let num = self.number(&s.num)?;
        let v = match &s.den {
            Some(d) => {
                let d = self.number(d)?;
                if d.signum() == 0 {
                    self.error(
                        s.span,
                        "E0023",
                        "a speed divided by zero",
                        "write a non-zero denominator",
                    );
                    return None;
                }
                num.checked_div(d)?
            }
            None => num,
        };
        if s.negative {
            v.checked_neg()
        } else {
            Some(v)
        }
    }

    fn number(&mut self, n: &SpeedNumber) -> Option<Ratio> {
        match n {
            SpeedNumber::Decimal(text, span) => {
                let r = Ratio::decimal(text);
                if r.is_none() {
                    self.error(
                        *span,
                        "E0023",
                        format!("`{text}` is not a speed this checker can represent"),
                        "use fewer digits",
                    );
                }
                r
            }
            SpeedNumber::Expr(e) => self.konst(e).map(Ratio::int),
        }
    }

    /// Clock readings of every mode of `p`, in ticks; `E0181` where one is not whole.
    fn tables(&mut self, p: &mut Plan) {
        let Some(tick) = self.tick else {
            if !p.modes.is_empty() {
                self.error(
                    p.span,
                    "E0120",
                    "a continuous variable needs the file's `tick` length (speeds are per second)",
                    "declare e.g. `tick 100 ms;`",
                );
            }
            return;
        };
        let n = p.points.len();
        let mut times: Vec<Ratio> = Vec::new();
        let mut bad: Vec<(usize, Span, String)> = Vec::new();
        for (mi, m) in p.modes.iter_mut().enumerate() {
            let dir = m.direction();
            let constant = m.constant().is_some();
            if !constant && n > MAX_PROFILE_POINTS {
                bad.push((mi, m.span, format!("a speed profile needs at most {MAX_PROFILE_POINTS} grid points, `{}` has {n}", p.var)));
                continue;
            }
            m.table = vec![Vec::new(); n];
            let mut first_bad: Option<String> = None;
            for s in 0..n {
                // Constant speed: only the next point matters (the motion restarts there).
                let targets: Vec<usize> = match (dir, constant) {
                    (0, _) => Vec::new(),
                    (1, true) => (s + 1..n).take(1).collect(),
                    (_, true) => (0..s).rev().take(1).collect(),
                    (1, false) => (s + 1..n).collect(),
                    (_, false) => (0..s).rev().collect(),
                };
                for j in targets {
                    let dist = Ratio::int((p.points[j] - p.points[s]).abs());
                    let Some(t) = crossing(&m.profile, dist) else {
                        continue;
                    };
                    times.push(t);
                    let ticks = t.checked_div(tick).and_then(Ratio::as_int);
                    match ticks.and_then(|k| i64::try_from(k).ok()) {
                        Some(k) => m.table[s].push((j, k)),
                        None => {
                            if first_bad.is_none() {
                                first_bad = Some(format!(
                                    "moving `{}` from {} to {} {} takes {} s, which is not a whole number of {} s ticks",
                                    p.var,
                                    p.points[s],
                                    p.points[j],
                                    describe(&m.profile),
                                    t,
                                    tick
                                ));
                            }
                        }
                    }
                }
            }
            if let Some(msg) = first_bad {
                bad.push((mi, m.span, msg));
            }
        }
        if bad.is_empty() {
            return;
        }
        let hint = tick_hint(&times, tick);
        for (_, span, msg) in bad {
            self.file_diags.push(
                Diagnostic::error("E0181", msg, span)
                    .with_label("clock reading not a whole tick")
                    .with_hint(hint.clone()),
            );
        }
    }
}

/// The first name in `rate` that is a variable of the chart (a continuous one included): a
/// speed that depends on the state has no closed-form clock readings.
fn variable_in<'a>(
    rate: &'a SpeedExpr,
    chart: &ast::Chart,
    plans: &[Plan],
) -> Option<(&'a str, Span)> {
    let speeds: Vec<&ast::Speed> = match rate {
        SpeedExpr::Constant(s) => vec![s],
        SpeedExpr::Profile(segs, last) => segs.iter().map(|(s, _)| s).chain([last]).collect(),
    };
    speeds
        .into_iter()
        .flat_map(|s| std::iter::once(&s.num).chain(s.den.as_ref()))
        .find_map(|n| match n {
            SpeedNumber::Expr(ast::Expr::Path(p)) if p.segments.len() == 1 => {
                let name = p.segments[0].name.name.as_str();
                let is_var = chart.vars.iter().any(|v| v.name.name == name)
                    || plans.iter().any(|pl| pl.var == name);
                is_var.then_some((name, p.span))
            }
            _ => None,
        })
}

/// `at 2 units/s` or `with profile …` for messages.
fn describe(profile: &[(Ratio, Option<Ratio>)]) -> String {
    match profile {
        [(v, None)] => format!("at {v} units/s"),
        _ => {
            let parts: Vec<String> = profile
                .iter()
                .map(|(v, d)| match d {
                    Some(d) => format!("{v} for {d} s"),
                    None => v.to_string(),
                })
                .collect();
            format!("with profile({})", parts.join(", "))
        }
    }
}

/// Candidate tick lengths [`tick_hint`] tries on each side of the given one.
const HINT_BUDGET: i128 = 100_000;

/// The tick lengths nearest to `tick` that divide every clock reading, as a hint.
fn tick_hint(times: &[Ratio], tick: Ratio) -> String {
    let Some(g) = times
        .iter()
        .copied()
        .try_fold(None::<Ratio>, |acc, t| match acc {
            None => Some(Some(t)),
            Some(a) => rgcd(a, t).map(Some),
        })
        .flatten()
    else {
        return "choose a tick length that divides every crossing time".into();
    };
    // Tick lengths that work are g/m; prefer whole milliseconds.
    let ms = |r: Ratio| r.checked_mul(Ratio::int(1000));
    let whole = |m: i128| -> Option<Ratio> {
        let t = g.checked_div(Ratio::new(m, 1)?)?;
        ms(t)?.as_int().map(|_| t)
    };
    let q = g
        .checked_div(tick)
        .map(|r| r.num() / r.den())
        .unwrap_or(1)
        .max(1);
    // At most HINT_BUDGET candidates on each side: a slow motion makes `q` astronomical
    // (a rate of 20/2^31 per second with 1.25 s ticks gives q = 4.3e8) and a hint must not
    // cost more than the check.
    let below = (q.saturating_add(1)..q.saturating_add(HINT_BUDGET)).find_map(whole);
    let above = (q.saturating_sub(HINT_BUDGET).max(1)..=q)
        .rev()
        .find_map(whole);
    let fmt = |t: Ratio| match ms(t) {
        Some(m) => format!("{m} ms"),
        None => format!("{t} s"),
    };
    let mut opts = Vec::new();
    if let Some(a) = above.filter(|a| *a >= tick) {
        opts.push(fmt(a));
    }
    if let Some(b) = below.filter(|b| *b < tick) {
        opts.insert(0, fmt(b));
    }
    if opts.is_empty() {
        format!("every crossing time is a multiple of {g} s; choose a tick length that divides it")
    } else {
        format!(
            "the nearest tick lengths that make every crossing a whole number of ticks: {} (every crossing time is a multiple of {g} s); or change the grid or the speed",
            opts.join(" or ")
        )
    }
}

/// The greatest common divisor of two positive rationals.
fn rgcd(a: Ratio, b: Ratio) -> Option<Ratio> {
    let n = gcd(a.num().checked_mul(b.den())?, b.num().checked_mul(a.den())?);
    Ratio::new(n, a.den().checked_mul(b.den())?)
}

fn gcd(mut a: i128, mut b: i128) -> i128 {
    a = a.abs();
    b = b.abs();
    while b != 0 {
        let t = a % b;
        a = b;
        b = t;
    }
    a
}

/// Every `der` under `body`: (state path, variable, rate, span).
fn walk(
    body: &ast::StateBody,
    path: &mut Vec<String>,
    out: &mut Vec<(Vec<String>, String, SpeedExpr, Span)>,
    cx: &mut Cx<'_, '_>,
    chart_level: bool,
) {
    for h in &body.hybrid {
        if chart_level {
            continue; // Reported by `plan_chart`.
        }
        match h {
            HybridElem::Der { var, rate, span } => {
                if path.is_empty() {
                    cx.error(
                        *span,
                        "E0182",
                        "`der` belongs in a state",
                        "move it into a state",
                    );
                } else {
                    out.push((path.clone(), var.name.clone(), rate.clone(), *span));
                }
            }
            other => cx.error(
                other.span(),
                "E0182",
                "`continuous`, `grid` and `sensor` are declared at chart level",
                "move this to the top of the chart",
            ),
        }
    }
    for s in &body.states {
        path.push(s.name.name.clone());
        walk(&s.body, path, out, cx, false);
        path.pop();
    }
    for r in &body.regions {
        path.push(r.name.name.clone());
        // `in()` accepts a region's path too: "the region is active".
        walk(&r.body, path, out, cx, false);
        path.pop();
    }
}
