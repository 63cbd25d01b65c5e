//! One person's run of the program: the inputs held, the state, the input history (for step
//! back, saving and replaying) and coverage. Pure: no I/O, no async.
//!
//! Every tick goes through [`statecheck_sim::tick_once`] — the same function `statecheck sim`
//! runs — on a [`Machine`] of the shared program, so a saved scenario replays to the same
//! trace. Step back re-simulates from the nearest snapshot of the state vector.

use statecheck_ir::{Machine, Program};
use statecheck_sim::lasso::run_lasso;
use statecheck_sim::{random::RandomInputs, scenario, tick_once, unreached, Options, Stop};
use std::sync::Arc;

/// Most ticks a session keeps (its input history; stepping further is refused until a step
/// back or a reset). With the snapshots this bounds a session's memory: about
/// `HISTORY_CAP × 8 B × (inputs + n_state / SNAPSHOT_EVERY)`.
pub const HISTORY_CAP: usize = 20_000;
/// A snapshot of the state, coverage and reached properties is kept every this many ticks.
pub const SNAPSHOT_EVERY: usize = 64;
/// Most ticks one message may ask for.
pub const MAX_BATCH: u64 = 1_000;

/// Why a request was refused (the session is unchanged).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Error {
    /// What went wrong.
    pub kind: ErrorKind,
    /// A sentence for the page.
    pub message: String,
}

/// Kinds of [`Error`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum ErrorKind {
    /// The run has stopped (violation or run-time error); step back or reset.
    Stopped,
    /// The history cap is reached.
    HistoryFull,
    /// The inputs violate an `assume` (or no random inputs satisfy it).
    Assume,
    /// A tick number out of range.
    BadTick,
    /// A scenario that does not parse or is too long.
    BadScenario,
}

fn err(kind: ErrorKind, message: impl Into<String>) -> Error {
    Error {
        kind,
        message: message.into(),
    }
}

/// What one tick produced.
#[derive(Clone, Debug)]
pub struct TickOut {
    /// The tick number.
    pub tick: u64,
    /// All slots after the tick (`None` when a run-time error stopped it).
    pub slots: Option<Vec<i64>>,
    /// Coverage items counted in this tick (states entered, transitions fired).
    pub fired: Vec<u32>,
    /// How the run stopped at this tick, if it did.
    pub stop: Option<Stop>,
}

/// A lasso scenario loaded in the session (a `.scn` with a `loop:` line, as `verify` writes
/// for a violated temporal property): its ticks `0..end`, the loop `start..end` repeating
/// forever. While `following`, stepping past the end continues around the loop.
#[derive(Clone, Debug)]
pub struct Lasso {
    /// The loop's first tick.
    pub start: usize,
    /// The scenario's length in ticks (the loop is `start..end`).
    pub end: usize,
    /// The temporal property the lasso violates, as `statecheck sim` reports it
    /// (`statecheck_sim::lasso::run_lasso`), if any.
    pub violated: Option<Stop>,
    /// Why the scenario is not a lasso of the model, if it is not.
    pub broken: Option<String>,
    /// False when the lasso is not fair (its temporal properties were not evaluated).
    pub fair: bool,
    /// True until the inputs are changed or the run branches before the loop's end: a step
    /// then applies the loop's next input vector.
    pub following: bool,
}

struct Snapshot {
    state: Vec<i64>,
    coverage: Vec<u64>,
    reached: Vec<(String, Option<u64>)>,
}

/// A session's run.
pub struct Session {
    program: Arc<crate::load::Loaded>,
    held: Vec<i64>,
    state: Vec<i64>,
    coverage: Vec<u64>,
    reached: Vec<(String, Option<u64>)>,
    history: Vec<Vec<i64>>,
    future: Vec<Vec<i64>>,
    snapshots: Vec<Snapshot>,
    stop: Option<Stop>,
    /// The seed of the random stream and how many random batches it has given (each batch
    /// draws from its own generator, seeded from both, so a session is reproducible).
    random: Option<(u64, u64)>,
    last_assume: usize,
    note: Option<String>,
    lasso: Option<Lasso>,
}

impl Session {
    /// A session at the initial state with every input at its declared initial value.
    pub fn new(loaded: Arc<crate::load::Loaded>) -> Session {
        let p = &loaded.program;
        let held = p
            .inputs
            .iter()
            .map(|i| p.slots[i.slot as usize].init)
            .collect();
        let m = Machine::new(p);
        let state = m.state().to_vec();
        let coverage = vec![0; p.covers.len()];
        let reached = unreached(p);
        Session {
            held,
            state,
            coverage,
            reached,
            history: Vec::new(),
            future: Vec::new(),
            snapshots: Vec::new(),
            stop: None,
            random: None,
            last_assume: 0,
            note: None,
            lasso: None,
            program: loaded,
        }
    }

    /// The program.
    pub fn program(&self) -> &Program {
        &self.program.program
    }

    /// The loaded model.
    pub fn loaded(&self) -> &Arc<crate::load::Loaded> {
        &self.program
    }

    /// A remark about the last request that still succeeded (for instance a random batch
    /// cut short); taken once.
    pub fn take_note(&mut self) -> Option<String> {
        self.note.take()
    }

    /// Ticks run so far.
    pub fn ticks(&self) -> u64 {
        self.history.len() as u64
    }

    /// Ticks that `forward` can replay (undone by `back`).
    pub fn future_len(&self) -> usize {
        self.future.len()
    }

    /// The held input values (one per input).
    pub fn held(&self) -> &[i64] {
        &self.held
    }

    /// Set a held input. A changed value leaves a lasso's loop (the run branches).
    pub fn set_held(&mut self, input: usize, value: i64) {
        if let Some(h) = self.held.get_mut(input) {
            if *h != value {
                if let Some(l) = &mut self.lasso {
                    l.following = false;
                }
            }
            *h = value;
        }
    }

    /// The lasso scenario loaded, if the last scenario was one.
    pub fn lasso(&self) -> Option<&Lasso> {
        self.lasso.as_ref()
    }

    /// Cumulative coverage counts (indexed like `Program::covers`).
    pub fn coverage(&self) -> &[u64] {
        &self.coverage
    }

    /// How the run stopped, if it did.
    pub fn stop(&self) -> Option<&Stop> {
        self.stop.as_ref()
    }

    /// The applied input vectors.
    pub fn history(&self) -> &[Vec<i64>] {
        &self.history
    }

    /// The inputs so far as a scenario text (the `statecheck sim --scenario` format).
    /// A followed lasso at its end, or after whole laps of its loop, is written with its
    /// `loop:` line (the loop then spans the laps: the same infinite run).
    pub fn scenario_text(&self) -> String {
        let p = self.program();
        let len = self.history.len();
        let sc = match &self.lasso {
            Some(l)
                if l.following
                    && l.broken.is_none()
                    && l.end > l.start
                    && len >= l.end
                    && (len - l.end).is_multiple_of(l.end - l.start) =>
            {
                scenario::from_lasso(p, &self.history, l.start)
            }
            _ => scenario::from_input_vectors(p, &self.history),
        };
        scenario::format(&sc, p)
    }

    /// The input vector of the next tick around a followed lasso's loop, if the run is at or
    /// past the loop's end and follows it (a branch before the end leaves the loop).
    fn loop_vector(&mut self) -> Option<Vec<i64>> {
        let l = self.lasso.as_mut()?;
        let len = self.history.len();
        if !l.following || l.broken.is_some() || l.end <= l.start {
            return None;
        }
        if len < l.end {
            l.following = false;
            return None;
        }
        let period = l.end - l.start;
        self.history
            .get(l.start + (len - l.start) % period)
            .cloned()
    }

    /// Run `n` ticks with the held inputs, `pulse` (input index, value) applying to the first
    /// tick only. Discards the ticks a `back` undid. Stops early when the run stops.
    pub fn step(&mut self, n: u64, pulse: &[(usize, i64)]) -> Result<Vec<TickOut>, Error> {
        self.check_can_step()?;
        if !pulse.is_empty() {
            if let Some(l) = &mut self.lasso {
                l.following = false;
            }
        }
        let mut out = Vec::new();
        for k in 0..n.min(MAX_BATCH) {
            if let Some(v) = self.loop_vector() {
                let going = self.push_tick(v.clone(), &mut out)?;
                self.held_from(v);
                if !going {
                    break;
                }
                continue;
            }
            let mut inputs = self.held.clone();
            if k == 0 {
                for &(i, v) in pulse {
                    if let Some(x) = inputs.get_mut(i) {
                        *x = v;
                    }
                }
            }
            if !self.push_tick(inputs, &mut out)? {
                break;
            }
        }
        self.future.clear();
        Ok(out)
    }

    /// Run `n` ticks of random inputs (the simulator's generator) from `seed`; a seed other
    /// than the last one starts a new stream. The held inputs follow the last random values.
    pub fn step_random(&mut self, n: u64, seed: u64) -> Result<Vec<TickOut>, Error> {
        self.check_can_step()?;
        if let Some(l) = &mut self.lasso {
            l.following = false;
        }
        let batch = match self.random {
            Some((s, b)) if s == seed => b + 1,
            _ => 0,
        };
        self.random = Some((seed, batch));
        let mut out = Vec::new();
        let loaded = Arc::clone(&self.program);
        let p = &loaded.program;
        // The simulator's generator (it honours the `assume`s as `sim --random` does); it
        // borrows the program, so each batch makes its own, from the seed and the batch number.
        let mut gen = RandomInputs::new(
            p,
            seed.wrapping_add(batch.wrapping_mul(0x9E37_79B9_7F4A_7C15)),
            u64::MAX,
        );
        for _ in 0..n.min(MAX_BATCH) {
            let mut inputs = self.held.clone();
            let mut m = Machine::new(p);
            m.load_state(&self.state);
            let tick = self.ticks();
            use statecheck_sim::InputSource;
            if let Err(a) = gen.next(tick, &m, &mut inputs) {
                let message = format!(
                    "no random inputs satisfying `assume` #{} of the system were found for tick {tick} ({} draws); {} random ticks ran",
                    a.assume() + 1,
                    statecheck_sim::random::MAX_TRIES,
                    out.len()
                );
                if out.is_empty() {
                    return Err(err(ErrorKind::Assume, message));
                }
                self.note = Some(message);
                break;
            }
            for (i, inp) in p.inputs.iter().enumerate() {
                if !inp.is_event {
                    self.held[i] = inputs[i];
                }
            }
            if !self.push_tick(inputs, &mut out)? {
                break;
            }
        }
        self.future.clear();
        Ok(out)
    }

    /// Replay up to `n` ticks that a `back` undid.
    pub fn forward(&mut self, n: u64) -> Result<Vec<TickOut>, Error> {
        self.check_can_step()?;
        let mut out = Vec::new();
        let k = (n.min(MAX_BATCH) as usize).min(self.future.len());
        let replay: Vec<Vec<i64>> = self.future.drain(..k).collect();
        for (j, inputs) in replay.iter().enumerate() {
            if !self.push_tick(inputs.clone(), &mut out)? {
                // Keep what was not replayed (cannot happen: these ticks ran before).
                let rest: Vec<Vec<i64>> = replay[j + 1..].to_vec();
                self.future.splice(0..0, rest);
                break;
            }
        }
        if let Some(last) = self.history.last() {
            self.held_from(last.clone());
        }
        Ok(out)
    }

    /// Go back to the state after `tick - 1` (`tick` = 0: the initial state), keeping the
    /// undone ticks for `forward`. Returns the record of the last kept tick, re-simulated.
    pub fn back(&mut self, tick: u64) -> Result<Option<TickOut>, Error> {
        let len = self.history.len();
        if tick as usize > len {
            return Err(err(
                ErrorKind::BadTick,
                format!("tick {tick} is beyond the run ({len} ticks)"),
            ));
        }
        let to = tick as usize;
        let undone: Vec<Vec<i64>> = self.history.drain(to..).collect();
        self.future.splice(0..0, undone);
        let kept = std::mem::take(&mut self.history);
        // Restore the snapshot taken before tick `j * SNAPSHOT_EVERY`, then re-run the ticks
        // after it; `push_tick` takes that snapshot again.
        let j = to / SNAPSHOT_EVERY;
        let start = if j < self.snapshots.len() {
            self.snapshots.truncate(j + 1);
            if let Some(s) = self.snapshots.pop() {
                self.state = s.state;
                self.coverage = s.coverage;
                self.reached = s.reached;
            }
            j * SNAPSHOT_EVERY
        } else {
            let fresh = Session::new(Arc::clone(&self.program));
            self.state = fresh.state;
            self.coverage = fresh.coverage;
            self.reached = fresh.reached;
            self.snapshots.clear();
            0
        };
        self.stop = None;
        self.history = kept[..start].to_vec();
        let mut out = Vec::new();
        for inputs in &kept[start..] {
            out.clear();
            self.push_tick(inputs.clone(), &mut out)?;
        }
        if let Some(last) = self.history.last() {
            self.held_from(last.clone());
        }
        Ok(out.pop())
    }

    /// Back to the initial state; the inputs keep their held values, the history is dropped.
    pub fn reset(&mut self) {
        let held = std::mem::take(&mut self.held);
        *self = Session::new(Arc::clone(&self.program));
        self.held = held;
    }

    /// Reset and run a scenario text; the run stops where `statecheck sim` would stop.
    pub fn load_scenario(&mut self, text: &str) -> Result<Vec<TickOut>, Error> {
        let p = self.program();
        let sc = scenario::parse(text, p).map_err(|errs| {
            let msgs: Vec<String> = errs
                .iter()
                .take(5)
                .map(|e| format!("line {}:{}: {}", e.line, e.col, e.message))
                .collect();
            err(ErrorKind::BadScenario, msgs.join("; "))
        })?;
        if sc.len() > HISTORY_CAP {
            return Err(err(
                ErrorKind::BadScenario,
                format!(
                    "the scenario has {} ticks; a session keeps at most {HISTORY_CAP}",
                    sc.len()
                ),
            ));
        }
        // The input vectors exactly as `ScenarioInputs` builds them.
        let mut vectors = Vec::with_capacity(sc.len());
        let mut inputs: Vec<i64> = p
            .inputs
            .iter()
            .map(|i| p.slots[i.slot as usize].init)
            .collect();
        for changes in sc.ticks() {
            for (k, inp) in p.inputs.iter().enumerate() {
                if inp.is_event {
                    inputs[k] = 0;
                }
            }
            for &(k, v) in changes {
                inputs[k] = v;
            }
            vectors.push(inputs.clone());
        }
        let fresh = Session::new(Arc::clone(&self.program));
        *self = fresh;
        let mut out = Vec::new();
        for v in vectors {
            match self.push_tick(v, &mut out) {
                Ok(true) => {}
                Ok(false) => break,
                Err(e) if e.kind == ErrorKind::Assume => {
                    // `sim` stops the run here too; show it as the run's end.
                    self.stop = Some(Stop::AssumeViolated {
                        tick: self.ticks(),
                        assume: self.last_assume,
                    });
                    out.push(TickOut {
                        tick: self.ticks(),
                        slots: None,
                        fired: Vec::new(),
                        stop: self.stop.clone(),
                    });
                    break;
                }
                Err(e) => return Err(e),
            }
        }
        if let Some(last) = self.history.last() {
            self.held_from(last.clone());
        }
        if let Some(k) = sc.loop_start {
            // The verdict on the infinite run is `sim`'s: the same replay function.
            let l = run_lasso(self.program(), &sc, Options::default());
            let violated = match l.run.stop {
                s @ Stop::Violation { .. } => Some(s),
                _ => None,
            };
            self.lasso = Some(Lasso {
                start: k,
                end: sc.len(),
                violated,
                broken: l.broken,
                fair: l.fair,
                following: self.stop.is_none() && self.history.len() == sc.len(),
            });
        }
        Ok(out)
    }

    /// A session on `loaded` with this session's inputs so far re-applied (its saved scenario
    /// replayed, so the run is the one `statecheck sim` gives for them on `loaded`), and the
    /// records of the ticks re-run. On the same model the held inputs are kept too. When the
    /// inputs do not apply (the model's inputs changed, or its `assume`s refuse them), the
    /// new session starts at the initial state and the message says why.
    pub fn reapply(
        &self,
        loaded: Arc<crate::load::Loaded>,
    ) -> (Session, Vec<TickOut>, Option<String>) {
        let mut fresh = Session::new(Arc::clone(&loaded));
        if self.history.is_empty() {
            if Arc::ptr_eq(&self.program, &loaded) {
                fresh.held = self.held.clone();
            }
            return (fresh, Vec::new(), None);
        }
        let text = self.scenario_text();
        let n = self.history.len();
        match fresh.load_scenario(&text) {
            Ok(ticks) => {
                if Arc::ptr_eq(&self.program, &loaded) {
                    fresh.held = self.held.clone();
                    if let (Some(a), Some(b)) = (&mut fresh.lasso, &self.lasso) {
                        a.following = b.following;
                    }
                }
                let note = (ticks.len() < n).then(|| {
                    format!(
                        "{} of the {n} ticks so far re-applied: the run stops earlier now",
                        ticks.len()
                    )
                });
                (fresh, ticks, note)
            }
            Err(e) => (
                Session::new(loaded),
                Vec::new(),
                Some(format!(
                    "the {n} ticks so far do not apply to the model now ({}); the run starts again",
                    e.message
                )),
            ),
        }
    }

    fn held_from(&mut self, mut last: Vec<i64>) {
        let p = &self.program.program;
        for (k, inp) in p.inputs.iter().enumerate() {
            if inp.is_event {
                last[k] = 0;
            }
        }
        self.held = last;
    }

    fn check_can_step(&self) -> Result<(), Error> {
        if let Some(s) = &self.stop {
            let tick = match s {
                Stop::Violation { tick, .. }
                | Stop::RuntimeError { tick, .. }
                | Stop::AssumeViolated { tick, .. } => *tick,
                Stop::Completed => self.ticks(),
            };
            return Err(err(
                ErrorKind::Stopped,
                format!("the run stopped at tick {tick}; step back or reset to go on"),
            ));
        }
        if self.history.len() >= HISTORY_CAP {
            return Err(err(
                ErrorKind::HistoryFull,
                format!("a session keeps at most {HISTORY_CAP} ticks; save the scenario, step back or reset"),
            ));
        }
        Ok(())
    }

    /// Run one tick with `inputs`; push its record. `Ok(false)` when the run stopped.
    fn push_tick(&mut self, inputs: Vec<i64>, out: &mut Vec<TickOut>) -> Result<bool, Error> {
        if self.stop.is_some() || self.history.len() >= HISTORY_CAP {
            return Ok(false);
        }
        let tick = self.history.len() as u64;
        if (tick as usize).is_multiple_of(SNAPSHOT_EVERY)
            && self.snapshots.len() == tick as usize / SNAPSHOT_EVERY
        {
            self.snapshots.push(Snapshot {
                state: self.state.clone(),
                coverage: self.coverage.clone(),
                reached: self.reached.clone(),
            });
        }
        let loaded = Arc::clone(&self.program);
        let p = &loaded.program;
        let mut m = Machine::new(p);
        m.load_state(&self.state);
        m.enable_coverage();
        let result = tick_once(p, &mut m, tick, &inputs, &mut self.reached, &mut || {});
        if let Err(Stop::AssumeViolated { assume, .. }) = result {
            self.last_assume = assume;
            return Err(err(
                ErrorKind::Assume,
                format!(
                    "the inputs of tick {tick} violate `assume` #{} of the system",
                    assume + 1
                ),
            ));
        }
        let mut fired = Vec::new();
        if let Some(c) = m.coverage() {
            for (k, (&d, total)) in c.iter().zip(self.coverage.iter_mut()).enumerate() {
                if d > 0 {
                    *total += d;
                    fired.push(k as u32);
                }
            }
        }
        self.history.push(inputs);
        let (slots, stop) = match result {
            Ok(()) => (Some(m.slots().to_vec()), None),
            Err(s @ Stop::Violation { .. }) => (Some(m.slots().to_vec()), Some(s)),
            Err(s) => (None, Some(s)),
        };
        if slots.is_some() {
            self.state = m.state().to_vec();
        }
        self.stop = stop.clone();
        let going = stop.is_none();
        out.push(TickOut {
            tick,
            slots,
            fired,
            stop,
        });
        Ok(going)
    }
}
