//! Discretization of continuous variables (docs/hybrid.md): grids, forced critical points,
//! clock readings and the analysis of runs, against values derived by hand in each test.

use statecheck_model::hybrid::{self, analyse, ChartPlans, Ratio};

fn plans(src: &str) -> Vec<ChartPlans> {
    let (file, diags) = statecheck_syntax::parse(src);
    assert!(diags.is_empty(), "{diags:?}");
    hybrid::plans(&file).unwrap_or_else(|d| panic!("{d:?}"))
}

fn errors(src: &str) -> Vec<(String, String, Option<String>)> {
    let (file, diags) = statecheck_syntax::parse(src);
    assert!(diags.is_empty(), "{diags:?}");
    let (_, diags) = statecheck_model::check(&file);
    diags
        .into_iter()
        .filter(|d| d.is_error())
        .map(|d| (d.code.to_string(), d.message, d.hint))
        .collect()
}

fn r(n: i128, d: i128) -> Ratio {
    Ratio::new(n, d).unwrap_or(Ratio::ZERO)
}

/// A reading: (point, seconds, ticks).
type Row = (i64, Ratio, Ratio);

/// The readings of each moving state.
fn table(p: &hybrid::Plan, tick: Ratio) -> Vec<(String, Vec<Row>)> {
    analyse::readings(p, tick)
        .into_iter()
        .map(|m| {
            (
                m.state,
                m.readings
                    .into_iter()
                    .map(|x| (x.point, x.seconds, x.ticks))
                    .collect(),
            )
        })
        .collect()
}

const PAPER: &str = "tick 1 s;
plant chart Linear {
  continuous x: [0 .. 100] = 0;
  grid x 4;
  initial Forward;
  state Forward { der(x) = 5; }
}";

#[test]
fn paper_section_vi_readings() {
    // D = 100, N = 4, Speed = 5: T(x) = x / 5 at x = 25, 50, 75, 100.
    let c = plans(PAPER);
    let p = &c[0].plans[0];
    assert_eq!(p.points, vec![0, 25, 50, 75, 100]);
    let want: Vec<(i64, Ratio, Ratio)> = [(25, 5), (50, 10), (75, 15), (100, 20)]
        .into_iter()
        .map(|(x, t)| (x, Ratio::int(t), Ratio::int(t)))
        .collect();
    assert_eq!(table(p, Ratio::int(1)), vec![("Forward".to_string(), want)]);
}

#[test]
fn profile_readings() {
    // Speed 1 for 2 s, then 4. Distance d(t) = t for t <= 2, 2 + 4 (t - 2) after, so from 0:
    // 2 at 2 s, 4 at 2.5 s, 6 at 3 s, 8 at 3.5 s, 10 at 4 s; with 0.5 s ticks: 4, 5, 6, 7, 8.
    // From 4 (a motion started there): 6 at 2 s (4 ticks), 8 at 2.5 s (5), 10 at 3 s (6).
    let src = "tick 500 ms;
plant chart P {
  continuous x: [0 .. 10] = 0;
  grid x 5;
  initial Go;
  state Go { der(x) = profile(1 for 2 s, 4); }
}";
    let c = plans(src);
    let p = &c[0].plans[0];
    let half = r(1, 2);
    let got = table(p, half);
    let want: Vec<(i64, Ratio, Ratio)> = [
        (2, r(2, 1)),
        (4, r(5, 2)),
        (6, r(3, 1)),
        (8, r(7, 2)),
        (10, r(4, 1)),
    ]
    .into_iter()
    .map(|(x, t)| (x, t, t.checked_div(half).unwrap_or(Ratio::ZERO)))
    .collect();
    assert_eq!(got, vec![("Go".to_string(), want)]);
    let from4 = &p.modes[0].table[2];
    assert_eq!(from4, &vec![(3, 4), (4, 5), (5, 6)]);
}

#[test]
fn critical_points_are_forced_onto_the_grid() {
    // 20 cells of 5; the sensor's bound 97 and the guard's 42 are not multiples of 5.
    let src = "tick 1 s;
const NEAR = 42;
plant chart P {
  output far: bool;
  continuous x: [0 .. 100] = 0;
  grid x 20;
  sensor far = x in [97 .. 100];
  initial Go;
  state Go { der(x) = 1; on [x >= NEAR] -> Stop; }
  state Stop;
}";
    let c = plans(src);
    let p = &c[0].plans[0];
    assert_eq!(p.forced, vec![42, 97]);
    assert_eq!(p.points.len(), 21 + 2);
    assert!(p.points.windows(2).all(|w| w[0] < w[1]));
    // At 1 unit/s and 1 s ticks: 95 -> 97 takes 2 ticks, 97 -> 100 takes 3.
    let m = &p.modes[0];
    let at = |x: i64| p.points.iter().position(|y| *y == x).unwrap_or(usize::MAX);
    assert_eq!(m.table[at(95)], vec![(at(97), 2)]);
    assert_eq!(m.table[at(97)], vec![(at(100), 3)]);
}

#[test]
fn coarse_grid_has_only_the_ends() {
    let src = "tick 1 s;
plant chart P {
  output mid: bool;
  continuous x: [0 .. 100] = 0;
  grid x coarse;
  sensor mid = x in [40 .. 60];
  initial Go;
  state Go { der(x) = 5; }
}";
    let c = plans(src);
    let p = &c[0].plans[0];
    assert!(p.coarse);
    assert_eq!(p.points, vec![0, 100]);
    // The one cell takes 100 / 5 = 20 s.
    assert_eq!(p.modes[0].table[0], vec![(1, 20)]);
}

#[test]
fn reading_not_a_whole_tick() {
    // 5 % at 0.8 %/s is 6.25 s: not whole 1 s ticks. Tick lengths that divide 6.25 s are
    // 6.25 s / m; in whole milliseconds m divides 6250 = 2 * 5^5: the nearest at or below
    // 1 s is m = 10 (625 ms), at or above is m = 5 (1250 ms).
    let src = "tick 1 s;
plant chart P {
  continuous x: [0 .. 100] = 0;
  grid x 20;
  initial Go;
  state Go { der(x) = 0.8; }
}";
    let e = errors(src);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!(e[0].0, "E0181");
    assert!(
        e[0].1.contains("from 0 to 5") && e[0].1.contains("6.25 s"),
        "{}",
        e[0].1
    );
    let hint = e[0].2.clone().unwrap_or_default();
    assert!(hint.contains("625 ms or 1250 ms"), "{hint}");
}

#[test]
fn events_follow_the_exact_motion() {
    // Speed 2 over [0 .. 10], cells of 5, tick 1.25 s: 2 ticks per cell at full speed.
    // Modes per tick: moving up (mode 1) from tick 1 to tick 3, then mode 0. The exact
    // motion covers 2.5 per tick: 5 at tick 2 (2.5 s), then 7.5 at tick 3 where it stops;
    // 10 is never reached. The discretized run (pos after each tick) reaches 5 at tick 2.
    // The sensor makes 5 a critical point.
    let src = "tick 1250 ms;
plant chart P {
  output low: bool;
  continuous x: [0 .. 10] = 0;
  sensor low = x in [0 .. 5];
  grid x 2;
  initial Go;
  state Go { der(x) = 2; }
}";
    let c = plans(src);
    let p = &c[0].plans[0];
    let modes = [0, 1, 1, 1, 0, 0];
    let pos = [0, 0, 5, 5, 5, 5];
    let ev = analyse::events(p, r(5, 4), &modes, &pos);
    assert_eq!(ev.len(), 1, "{ev:?}");
    assert_eq!(ev[0].point, 5);
    assert_eq!(ev[0].seconds, r(5, 2));
    assert_eq!(ev[0].ticks, Ratio::int(2));
    assert_eq!(ev[0].model_tick, Some(2));
}

#[test]
fn misplaced_elements() {
    let src = "tick 1 s;
plant chart P {
  output o: int[0 .. 1];
  continuous x: [0 .. 10];
  sensor o = x in [0 .. 5];
  der(x) = 1;
  grid y 2;
  initial A;
  state A { der(z) = 1; }
}";
    let e = errors(src);
    let codes: Vec<&str> = e.iter().map(|x| x.0.as_str()).collect();
    // The int sensor output, `der` at chart level, the grid of an unknown variable, the
    // `der` of an unknown variable.
    assert_eq!(codes, vec!["E0182"; 4], "{e:?}");
}

#[test]
fn a_motion_switched_between_grid_points_is_reported() {
    // Up at 2 (2.5 per 1.25 s tick) for one tick: the exact position is 2.5, mid-cell; the
    // discretized one stays 0. Then down at 4: exactly, 0 is reached 2.5 / 4 = 0.625 s
    // later, at 1.875 s = 1.5 ticks, between ticks; the model "reaches" 0 at once (it never
    // left it), in tick 2.
    let src = "tick 1250 ms;
plant chart P {
  continuous x: [0 .. 10] = 0;
  grid x 2;
  initial Up;
  state Up { der(x) = 2; }
  state Down { der(x) = -4; }
}";
    let c = plans(src);
    let p = &c[0].plans[0];
    let modes = [0, 1, 2, 2];
    let pos = [0, 0, 0, 0];
    let ev = analyse::events(p, r(5, 4), &modes, &pos);
    assert_eq!(ev.len(), 1, "{ev:?}");
    assert_eq!((ev[0].point, ev[0].state.as_str()), (0, "Down"));
    assert_eq!(ev[0].seconds, r(15, 8));
    assert_eq!(ev[0].ticks, r(3, 2));
    assert_eq!(ev[0].model_tick, Some(2));
}

/// A zone event: (sensor, entered, seconds, expected tick, model tick, on grid).
type ZoneRow = (usize, bool, Ratio, Option<u64>, Option<u64>, bool);

#[test]
fn zone_entries_and_departures_of_a_two_speed_profile() {
    // Start-up at 1 unit/s for 4 s, then 5 units/s; tick 200 ms, a zone [10 .. 20] and a
    // zone [0 .. 2]. The state is active from tick 0, so the motion starts at 0 s:
    // d(t) = t for t <= 4, 4 + 5 (t - 4) after.
    // - [0 .. 2] left when x passes 2: t = 2 s = tick 10 (the sensor reads false from 11).
    // - [10 .. 20] entered at x = 10: 4 + 6/5 = 5.2 s = tick 26.
    // - [10 .. 20] left at x = 20: 4 + 16/5 = 7.2 s = tick 36 (false from tick 37).
    // The motion runs 40 ticks (modes[1..=40] = 1), far enough for all three.
    let src = "tick 200 ms;
plant chart P {
  output low: bool;
  output mid: bool;
  continuous x: [0 .. 100] = 0;
  sensor low = x in [0 .. 2];
  sensor mid = x in [10 .. 20];
  initial Go;
  state Go { der(x) = profile(1 for 4 s, 5); }
}";
    let c = plans(src);
    let p = &c[0].plans[0];
    let tick = r(1, 5);
    let modes: Vec<i64> = (0..=40).map(|k| i64::from(k > 0)).collect();
    // The discretized sensors after each tick as the derivation says they should read; a
    // model one tick late on `mid`'s entry (true from 27) is reported off the grid.
    let low: Vec<i64> = (0..=40).map(|k| i64::from(k <= 10)).collect();
    let mid: Vec<i64> = (0..=40)
        .map(|k| i64::from((26..=36).contains(&k)))
        .collect();
    let late: Vec<i64> = (0..=40)
        .map(|k| i64::from((27..=36).contains(&k)))
        .collect();
    let rows = |ev: Vec<analyse::ZoneEvent>| -> Vec<ZoneRow> {
        ev.iter()
            .map(|e| {
                (
                    e.sensor,
                    e.entered,
                    e.seconds,
                    e.expected_tick,
                    e.model_tick,
                    e.on_grid(),
                )
            })
            .collect()
    };
    assert_eq!(
        rows(analyse::zone_events(p, tick, &modes, &[low.clone(), mid])),
        vec![
            (0, false, Ratio::int(2), Some(11), Some(11), true),
            (1, true, r(26, 5), Some(26), Some(26), true),
            (1, false, r(36, 5), Some(37), Some(37), true),
        ]
    );
    let got = rows(analyse::zone_events(p, tick, &modes, &[low, late]));
    assert_eq!(got[1], (1, true, r(26, 5), Some(26), Some(27), false));
}

#[test]
fn constants_in_temporal_formulas_are_critical_points() {
    // 4 cells of 25; `G p.x <= 30` (ltl) and `AG (p.x != 60)` (ctl) compare x with 30 and 60,
    // which the cells miss: both are forced onto the grid.
    let src = "tick 1 s;
plant chart P {
  continuous x: [0 .. 100] = 0;
  grid x 4;
  initial Go;
  state Go { der(x) = 5; }
}
system S {
  instance p: P;
  ltl low: G p.x <= 30;
  ctl not60: AG (p.x != 60);
}";
    let c = plans(src);
    let p = &c[0].plans[0];
    assert_eq!(p.forced, vec![30, 60]);
    assert_eq!(p.points, vec![0, 25, 30, 50, 60, 75, 100]);
}
