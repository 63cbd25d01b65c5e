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

/// The events of a run: `modes[k]` and `pos[k]` are the variable's mode and grid value after
/// tick `k` of the discretized run (the motion between ticks `k - 1` and `k` is that of
/// `modes[k]`). The continuous motion is followed exactly from the initial value, with the
/// same modes and end stops; each time it reaches a critical point (`Plan::critical`) other
/// than where the motion started, the event is listed.
pub fn events(p: &Plan, tick: Ratio, modes: &[i64], pos: &[i64]) -> Vec<Event> {
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
        // The motion of mode `m` from tick `start` to tick `end`.
        let mode = usize::try_from(m - 1).ok().and_then(|i| p.modes.get(i));
        if let Some(mode) = mode {
            let dir = mode.direction();
            let span = Ratio::int((end - start) as i64).checked_mul(tick);
            let covered = span.and_then(|s| distance(&mode.profile, s));
            if let (Some(span), Some(covered)) = (span, covered) {
                let room = if dir > 0 {
                    Ratio::int(p.hi).checked_sub(x)
                } else {
                    x.checked_sub(Ratio::int(p.lo))
                };
                let covered = room.map_or(covered, |r| covered.min(r));
                let ahead: Vec<i64> = p
                    .critical
                    .iter()
                    .copied()
                    .filter(|c| {
                        let c = Ratio::int(*c);
                        if dir > 0 {
                            c > x
                        } else {
                            c < x
                        }
                    })
                    .collect();
                for c in ahead {
                    let dist = Ratio::int(c).checked_sub(x).map(Ratio::abs);
                    let Some(t) = dist.and_then(|d| crossing(&mode.profile, d)) else {
                        continue;
                    };
                    if t > span {
                        continue;
                    }
                    let Some(abs) = Ratio::int(start as i64)
                        .checked_mul(tick)
                        .and_then(|s| s.checked_add(t))
                    else {
                        continue;
                    };
                    let model_tick = (start..=end)
                        .find(|j| pos.get(*j) == Some(&c) && *j > start)
                        .map(|j| j as u64);
                    out.push(Event {
                        point: c,
                        state: mode.path.join("."),
                        seconds: abs,
                        ticks: abs.checked_div(tick).unwrap_or(Ratio::ZERO),
                        model_tick,
                    });
                }
                let moved = if dir > 0 {
                    x.checked_add(covered)
                } else {
                    x.checked_sub(covered)
                };
                x = moved.unwrap_or(x);
            }
        }
        k = end + 1;
    }
    out.sort_by_key(|e| e.seconds);
    out
}
