//! Time in the user's units: with `tick 100 ms;` declared, tick `n` happens at `n × 100 ms`.
//! Every consumer that shows a time (trace tables, JSON, CSV, VCD, counterexample reports, the
//! studio) formats it here, from [`Program::tick_ms`](crate::Program::tick_ms), so that a time
//! is computed once and reads the same everywhere: an exact decimal number of seconds, never a
//! float product.

impl crate::Program {
    /// The time of tick `tick` as [`time_text`] writes it, when the model declares a tick.
    pub fn time_text(&self, tick: u64) -> Option<String> {
        self.tick_ms.map(|ms| time_text(tick, ms))
    }

    /// `tick 95` as messages name a tick, followed by its time when the model declares a
    /// tick: `tick 95 (118.75 s)`.
    pub fn tick_label(&self, tick: u64) -> String {
        match self.time_text(tick) {
            Some(t) => format!("tick {tick} ({t} s)"),
            None => format!("tick {tick}"),
        }
    }

    /// The time of tick `tick` in seconds as [`seconds`] gives it, when the model declares a
    /// tick.
    pub fn seconds(&self, tick: u64) -> Option<f64> {
        self.tick_ms.map(|ms| seconds(tick, ms))
    }
}

/// Tick `tick` as seconds, exactly, with the decimals the tick length needs (none for whole
/// seconds, one for tenths, two for hundredths, else three): `time_text(95, 1250)` is
/// `"118.75"`, `time_text(0, 100)` is `"0.0"`. Every time of one trace has the same number of
/// decimals, so that a column of them lines up.
pub fn time_text(tick: u64, tick_ms: i64) -> String {
    let total = i128::from(tick) * i128::from(tick_ms);
    let whole = total / 1000;
    let frac = (total % 1000).abs();
    match decimals(tick_ms) {
        0 => whole.to_string(),
        1 => format!("{whole}.{}", frac / 100),
        2 => format!("{whole}.{:02}", frac / 10),
        _ => format!("{whole}.{frac:03}"),
    }
}

/// The number of decimals a time in seconds needs for a tick of `tick_ms` milliseconds.
fn decimals(tick_ms: i64) -> usize {
    if tick_ms % 1000 == 0 {
        0
    } else if tick_ms % 100 == 0 {
        1
    } else if tick_ms % 10 == 0 {
        2
    } else {
        3
    }
}

/// Tick `tick` as seconds, a number for JSON: the value of [`time_text`] read back, which
/// prints as that decimal (the shortest text that reads back as the same `f64`) whenever the
/// time has at most 15 significant digits, that is below 10^12 s for a whole-millisecond tick.
pub fn seconds(tick: u64, tick_ms: i64) -> f64 {
    time_text(tick, tick_ms).parse().unwrap_or(f64::NAN)
}

/// A VCD time scale that matches a tick of `tick_ms` milliseconds: the largest of 1, 10 and
/// 100 ms and 1, 10 and 100 s that divides the tick, as `(scale in ms, "$timescale" text)`.
/// Timestamps are then `tick × tick_ms / scale`: `tick 100 ms` gives `100ms` and one unit per
/// tick, `tick 1250 ms` gives `10ms` and 125 units per tick.
pub fn vcd_timescale(tick_ms: i64) -> (i64, &'static str) {
    const SCALES: [(i64, &str); 6] = [
        (100_000, "100s"),
        (10_000, "10s"),
        (1_000, "1s"),
        (100, "100ms"),
        (10, "10ms"),
        (1, "1ms"),
    ];
    SCALES
        .into_iter()
        .find(|(ms, _)| tick_ms > 0 && tick_ms % ms == 0)
        .unwrap_or((1, "1ms"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_time_is_printed_exactly_with_the_decimals_the_tick_needs() {
        // 95 × 1.25 s = 118.75 s (the WDS collision of issue 18).
        assert_eq!(time_text(95, 1250), "118.75");
        assert_eq!(time_text(31, 100), "3.1");
        assert_eq!(time_text(250, 250), "62.50");
        assert_eq!(time_text(3, 1000), "3");
        assert_eq!(time_text(7, 5), "0.035");
        assert_eq!(time_text(0, 100), "0.0");
        // 3 × 0.1 s is 0.3 s, not the float product 0.30000000000000004.
        assert_eq!(seconds(3, 100).to_string(), "0.3");
        assert_eq!(seconds(95, 1250).to_string(), "118.75");
    }

    #[test]
    fn the_vcd_timescale_is_the_largest_unit_dividing_the_tick() {
        assert_eq!(vcd_timescale(100), (100, "100ms"));
        assert_eq!(vcd_timescale(1250), (10, "10ms"));
        assert_eq!(vcd_timescale(2000), (1000, "1s"));
        assert_eq!(vcd_timescale(60_000), (10_000, "10s"));
        assert_eq!(vcd_timescale(7), (1, "1ms"));
    }
}
