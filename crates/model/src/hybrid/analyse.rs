//! The continuous model analysed exactly (`statecheck analyse`, docs/hybrid.md): the clock
//! readings of each mode, and for a run of the discretized model, the exact times at which
//! the continuous motion reaches each critical point, beside the tick at which the
//! discretized model got there (the role CheckMate plays in the IEC 61499 paper).

use super::plan::{crossing, Plan};
use super::rational::Ratio;

/// One clock reading: a motion that starts at `from` reaches `point` after `seconds`.
#[derive(Clone, Debug, PartialEq)]
pub struct Reading {
    /// The grid point reached.
    pub point: i64,
    /// Seconds from the state's entry.
    pub seconds: Ratio,
    /// The same in ticks (whole: the discretization checked it).
    pub ticks: Ratio,
}

/// The readings of one mode from the range end it moves away from (or from the initial
/// value when it is a grid point in the direction of motion).
#[derive(Clone, Debug, PartialEq)]
pub struct ModeReadings {
    /// The state (`Outer.Inner`).
    pub state: String,
    /// Where the motion starts.
    pub from: i64,
    /// Every grid point it reaches, nearest first.
    pub readings: Vec<Reading>,
}

/// The clock readings of every moving mode of `p`, for a `tick` in seconds.
pub fn readings(p: &Plan, tick: Ratio) -> Vec<ModeReadings> {
    let mut out = Vec::new();
    for m in &p.modes {
        let dir = m.direction();
        if dir == 0 {
            continue;
        }
        let from = if dir > 0 { p.lo } else { p.hi };
        let mut rs = Vec::new();
        let ahead: Vec<i64> = if dir > 0 {
            p.points.iter().copied().filter(|x| *x > from).collect()
        } else {
            p.points
                .iter()
                .rev()
                .copied()
                .filter(|x| *x < from)
                .collect()
        };
        for x in ahead {
            let Some(t) = crossing(&m.profile, Ratio::int((x - from).abs())) else {
                break;
            };
            let Some(ticks) = t.checked_div(tick) else {
                break;
            };
            rs.push(Reading {
                point: x,
                seconds: t,
                ticks,
            });
        }
        out.push(ModeReadings {
            state: m.path.join("."),
            from,
            readings: rs,
        });
    }
    out
}

/// The distance covered `t` seconds after a motion's start.
pub fn distance(profile: &[(Ratio, Option<Ratio>)], t: Ratio) -> Option<Ratio> {
    let mut left = t;
    let mut d = Ratio::ZERO;
    for (v, dur) in profile {
        let v = v.abs();
        match dur {
            Some(dur) if *dur < left => {
                d = d.checked_add(v.checked_mul(*dur)?)?;
                left = left.checked_sub(*dur)?;
            }
            _ => return d.checked_add(v.checked_mul(left)?),
        }
    }
    Some(d)
}

/// The continuous motion reached a critical point.
#[derive(Clone, Debug, PartialEq)]
pub struct Event {
    /// The point.
    pub point: i64,
    /// The state whose motion reached it.
    pub state: String,
    /// The exact time, in seconds from tick 0.
    pub seconds: Ratio,
    /// The same in ticks (a whole number when the grid contains the event).
    pub ticks: Ratio,
    /// The tick at which the discretized model's variable reached the point in the same
    /// motion, if it did.
    pub model_tick: Option<u64>,
}

/// One stretch of continuous motion in a run: a mode ran from tick `start` to tick `end`.
#[derive(Clone, Debug, PartialEq)]
pub struct Motion {
    /// The mode (index into `Plan::modes`).
    pub mode: usize,
    /// The tick at which the motion starts (its time is `start` ticks).
    pub start: usize,
    /// The tick at which the mode stops running.
    pub end: usize,
    /// The exact position at `start`.
    pub from: Ratio,
    /// The exact position at `end` (end stops applied).
    pub to: Ratio,
}

/// The continuous motions of a run: `modes[k]` is the variable's mode after tick `k` of the
/// discretized run (the motion between ticks `k - 1` and `k` is that of `modes[k]`). The
/// continuous motion is followed exactly from the initial value, with the same modes and end
/// stops (no snapping to the grid).
pub fn motions(p: &Plan, tick: Ratio, modes: &[i64]) -> Vec<Motion> {
    let mut out = Vec::new();
    let mut x = Ratio::int(p.init);
    let mut k = 1;
    while k < modes.len() {
        let m = modes[k];
        let start = k - 1;
        let mut end = k;
        while end + 1 < modes.len() && modes[end + 1] == m {
            end += 1;
        }
        k = end + 1;
        let Some((mi, mode)) = usize::try_from(m - 1)
            .ok()
            .and_then(|i| p.modes.get(i).map(|md| (i, md)))
        else {
            continue;
        };
        let dir = mode.direction();
        let span = Ratio::int((end - start) as i64).checked_mul(tick);
        let Some(covered) = span.and_then(|s| distance(&mode.profile, s)) else {
            continue;
        };
        let room = if dir > 0 {
            Ratio::int(p.hi).checked_sub(x)
        } else {
            x.checked_sub(Ratio::int(p.lo))
        };
        let covered = room.map_or(covered, |r| covered.min(r));
        let to = if dir > 0 {
            x.checked_add(covered)
        } else {
            x.checked_sub(covered)
        }
        .unwrap_or(x);
        out.push(Motion {
            mode: mi,
            start,
            end,
            from: x,
            to,
        });
        x = to;
    }
    out
}

/// The absolute time (seconds from tick 0) at which motion `mv` of `p` has covered `dist`,
/// if it does within the motion.
fn time_at(p: &Plan, tick: Ratio, mv: &Motion, dist: Ratio) -> Option<Ratio> {
    let mode = p.modes.get(mv.mode)?;
    let covered = mv.to.checked_sub(mv.from)?.abs();
    if dist > covered || dist.signum() <= 0 {
        return None;
    }
    let t = crossing(&mode.profile, dist)?;
    Ratio::int(mv.start as i64)
        .checked_mul(tick)?
        .checked_add(t)
}

/// A sensor range (a zone) entered or left by the continuous motion.
#[derive(Clone, Debug, PartialEq)]
pub struct ZoneEvent {
    /// The sensor (index into `Plan::sensors`).
    pub sensor: usize,
    /// Entered (true) or left (false). A zone is left at the last instant inside it: the
    /// position is on the bound at `seconds` and outside right after.
    pub entered: bool,
    /// The state whose motion crossed the bound.
    pub state: String,
    /// The exact time, in seconds from tick 0.
    pub seconds: Ratio,
    /// The same in ticks.
    pub ticks: Ratio,
    /// The tick the discretized model should show the change at: the time itself for an
    /// entry, the first tick after it for a departure (`None` when that is not a whole tick).
    pub expected_tick: Option<u64>,
    /// The first tick (after the motion started) at which the discretized model's sensor
    /// changed that way, if it did.
    pub model_tick: Option<u64>,
}

impl ZoneEvent {
    /// The event is on the grid: its time is a whole tick and the discretized model's sensor
    /// changed exactly when it should.
    pub fn on_grid(&self) -> bool {
        self.expected_tick.is_some() && self.expected_tick == self.model_tick
    }
}

/// The zone events of a run: `modes` as for [`motions`], `sensors[s][k]` the discretized
/// model's value of sensor `s` (`Plan::sensors`) after tick `k`. Sorted by time.
pub fn zone_events(p: &Plan, tick: Ratio, modes: &[i64], sensors: &[Vec<i64>]) -> Vec<ZoneEvent> {
    let mut out = Vec::new();
    for mv in motions(p, tick, modes) {
        let Some(mode) = p.modes.get(mv.mode) else {
            continue;
        };
        let up = mode.direction() > 0;
        for (si, (_, lo, hi)) in p.sensors.iter().enumerate() {
            let (lo, hi) = (Ratio::int(*lo), Ratio::int(*hi));
            // Entered at the near bound, left at the far bound.
            let (near, far) = if up { (lo, hi) } else { (hi, lo) };
            let before = |a: Ratio, b: Ratio| if up { a < b } else { a > b };
            let mut found = Vec::new();
            if before(mv.from, near) {
                found.push((true, near));
            }
            if !before(far, mv.from) {
                found.push((false, far));
            }
            for (entered, bound) in found {
                let Some(dist) = bound.checked_sub(mv.from).map(Ratio::abs) else {
                    continue;
                };
                // A departure needs the motion to pass the bound, not only reach it.
                let passes = mv.to.checked_sub(mv.from).map(Ratio::abs) > Some(dist);
                if !entered && !passes {
                    continue;
                }
                let Some(seconds) = time_at(p, tick, &mv, dist) else {
                    continue;
                };
                let ticks = seconds.checked_div(tick).unwrap_or(Ratio::ZERO);
                let whole = ticks.as_int().and_then(|t| u64::try_from(t).ok());
                let expected_tick = if entered { whole } else { whole.map(|t| t + 1) };
                let want = i64::from(entered);
                let col = sensors.get(si);
                let model_tick = col.and_then(|c| {
                    (mv.start + 1..c.len())
                        .find(|j| c[*j] == want && c[*j - 1] != want)
                        .map(|j| j as u64)
                });
                out.push(ZoneEvent {
                    sensor: si,
                    entered,
                    state: mode.path.join("."),
                    seconds,
                    ticks,
                    expected_tick,
                    model_tick,
                });
            }
        }
    }
    out.sort_by(|a, b| a.seconds.cmp(&b.seconds).then(a.sensor.cmp(&b.sensor)));
    out
}

/// The events of a run: `modes[k]` and `pos[k]` are the variable's mode and grid value after
/// tick `k` of the discretized run (the motion between ticks `k - 1` and `k` is that of
/// `modes[k]`). The continuous motion is followed exactly from the initial value, with the
/// same modes and end stops; each time it reaches a critical point (`Plan::critical`) other
/// than where the motion started, the event is listed.
pub fn events(p: &Plan, tick: Ratio, modes: &[i64], pos: &[i64]) -> Vec<Event> {
    let mut out = Vec::new();
    for mv in motions(p, tick, modes) {
        let Some(mode) = p.modes.get(mv.mode) else {
            continue;
        };
        let up = mode.direction() > 0;
        for c in p.critical.iter().copied() {
            let cr = Ratio::int(c);
            let ahead = if up { cr > mv.from } else { cr < mv.from };
            if !ahead {
                continue;
            }
            let Some(dist) = cr.checked_sub(mv.from).map(Ratio::abs) else {
                continue;
            };
            let Some(abs) = time_at(p, tick, &mv, dist) else {
                continue;
            };
            let model_tick = (mv.start + 1..=mv.end)
                .find(|j| pos.get(*j) == Some(&c))
                .map(|j| j as u64);
            out.push(Event {
                point: c,
                state: mode.path.join("."),
                seconds: abs,
                ticks: abs.checked_div(tick).unwrap_or(Ratio::ZERO),
                model_tick,
            });
        }
    }
    out.sort_by_key(|e| e.seconds);
    out
}
