//! The scenario format: the inputs of a run, one line per tick.
//!
//! ```text
//! # comments start with '#'
//! fam.runMode = NORMAL_RUN, fam.targetPos = 100   # set inputs; they hold until changed
//! -  * 20                                         # 20 ticks with no changes
//! fam.stallNow = true, request                    # a bare name makes an input event present
//! ```
//! A line is a tick: a comma-separated list of `input = value` and event names, or `-` for no
//! change. `* N` at the end of a line repeats it N times (events are present in every repeat).
//! Names may omit the instance (`runMode`) when that is unambiguous. The same format is what
//! `--save-scenario` and the model checkers' counterexamples write.

use statecheck_ir::Program;

/// The inputs of a run: for each tick, the inputs that change (and the events present).
///
/// Stored run-length encoded, one entry per line of the file: `- * 100000000` is one entry,
/// not 10^8, so memory grows with the file, not with the ticks it stands for.
#[derive(Clone, Debug, Default)]
pub struct Scenario {
    /// `(changes, repeat)`: `changes` (`(index into Program::inputs, value)` pairs) in each of
    /// `repeat ≥ 1` consecutive ticks.
    lines: Vec<(Vec<(usize, i64)>, usize)>,
    /// The first tick of each entry of `lines` (ascending), for lookup by tick.
    starts: Vec<usize>,
    /// The number of ticks.
    total: usize,
    /// A lasso's first loop tick (a `loop:` line before it): after the last tick the state
    /// after tick `loop_start - 1` recurs and the loop repeats forever (`crate::lasso`).
    pub loop_start: Option<usize>,
}

/// Two scenarios are equal when they give the same changes in every tick and the same loop,
/// however their lines are split.
impl PartialEq for Scenario {
    fn eq(&self, other: &Self) -> bool {
        self.total == other.total
            && self.loop_start == other.loop_start
            && self.runs() == other.runs()
    }
}

impl Eq for Scenario {}

impl Scenario {
    /// The lines with equal neighbours merged.
    fn runs(&self) -> Vec<(&[(usize, i64)], usize)> {
        let mut out: Vec<(&[(usize, i64)], usize)> = Vec::with_capacity(self.lines.len());
        for (c, n) in &self.lines {
            match out.last_mut() {
                Some((last, m)) if *last == c.as_slice() => *m += n,
                _ => out.push((c, *n)),
            }
        }
        out
    }

    /// An empty scenario.
    pub fn new() -> Self {
        Scenario::default()
    }

    /// The number of ticks.
    pub fn len(&self) -> usize {
        self.total
    }

    /// True when the scenario has no tick.
    pub fn is_empty(&self) -> bool {
        self.total == 0
    }

    /// The changes of tick `t` (0-based), or `None` past the end.
    pub fn tick(&self, t: usize) -> Option<&[(usize, i64)]> {
        if t >= self.total {
            return None;
        }
        let i = self.starts.partition_point(|&s| s <= t) - 1;
        Some(&self.lines[i].0)
    }

    /// Every tick's changes in order (a repeated line is yielded once per tick).
    pub fn ticks(&self) -> impl Iterator<Item = &[(usize, i64)]> + '_ {
        self.lines
            .iter()
            .flat_map(|(c, n)| std::iter::repeat_n(c.as_slice(), *n))
    }

    /// Append `repeat` ticks with the same changes (nothing when `repeat` is 0). Consecutive
    /// equal lines are merged.
    pub fn push_repeated(&mut self, changes: Vec<(usize, i64)>, repeat: usize) {
        if repeat == 0 {
            return;
        }
        self.total += repeat;
        if let Some((last, n)) = self.lines.last_mut() {
            if *last == changes {
                *n += repeat;
                return;
            }
        }
        self.starts.push(self.total - repeat);
        self.lines.push((changes, repeat));
    }

    /// Append one tick.
    pub fn push(&mut self, changes: Vec<(usize, i64)>) {
        self.push_repeated(changes, 1);
    }

    /// Replace the changes of tick `t` (a repeated line is split around it); nothing past the
    /// end.
    pub fn set_tick(&mut self, t: usize, changes: Vec<(usize, i64)>) {
        if t >= self.total {
            return;
        }
        let old = std::mem::take(&mut self.lines);
        let loop_start = self.loop_start;
        *self = Scenario::new();
        self.loop_start = loop_start;
        let mut at = 0;
        for (c, n) in old {
            if t >= at && t < at + n {
                let before = t - at;
                self.push_unmerged(c.clone(), before);
                self.push_unmerged(changes.clone(), 1);
                self.push_unmerged(c, n - before - 1);
            } else {
                self.push_unmerged(c, n);
            }
            at += n;
        }
    }

    /// Append without merging into the previous line (keeps an edited tick its own line).
    fn push_unmerged(&mut self, changes: Vec<(usize, i64)>, repeat: usize) {
        if repeat == 0 {
            return;
        }
        self.starts.push(self.total);
        self.total += repeat;
        self.lines.push((changes, repeat));
    }
}

/// A problem in a scenario file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ScenarioError {
    /// The stable diagnostic code (E08xx, `statecheck explain`).
    pub code: &'static str,
    /// 1-based line.
    pub line: usize,
    /// 1-based column.
    pub col: usize,
    /// Length of the offending text (for underlining).
    pub len: usize,
    /// What is wrong.
    pub message: String,
    /// How to fix it.
    pub hint: Option<String>,
}

/// Most ticks a scenario may expand to (a guard against `* 999999999999`).
pub const MAX_TICKS: usize = 100_000_000;

/// Parse a scenario for a program. Collects every error rather than stopping at the first.
pub fn parse(text: &str, program: &Program) -> Result<Scenario, Vec<ScenarioError>> {
    let mut ticks = Scenario::new();
    let mut errors = Vec::new();
    let mut loop_start: Option<usize> = None;
    for (ln, raw) in text.lines().enumerate() {
        let line_no = ln + 1;
        let content = raw.split('#').next().unwrap_or("");
        if content.trim().is_empty() {
            continue;
        }
        if content.trim() == "loop:" {
            if loop_start.is_some() {
                errors.push(ScenarioError {
                    code: "E0810",
                    line: line_no,
                    col: 1,
                    len: raw.len().max(1),
                    message: "a second `loop:` line".into(),
                    hint: Some("a scenario has at most one loop, at its end".into()),
                });
            }
            loop_start = Some(ticks.len());
            continue;
        }
        let err =
            |code: &'static str, col: usize, len: usize, message: String, hint: Option<String>| {
                ScenarioError {
                    code,
                    line: line_no,
                    col: col + 1,
                    len: len.max(1),
                    message,
                    hint,
                }
            };
        // `* N` repeat suffix.
        let (body, repeat) = match content.rfind('*') {
            Some(star) => {
                let n_text = content[star + 1..].trim();
                match n_text.parse::<usize>() {
                    Ok(n) if n >= 1 => (&content[..star], n),
                    _ => {
                        errors.push(err(
                            "E0801",
                            star,
                            content.len() - star,
                            format!("bad repeat count `{n_text}`"),
                            Some("write `* N` with N ≥ 1 at the end of the line".into()),
                        ));
                        continue;
                    }
                }
            }
            None => (content, 1),
        };
        let mut changes: Vec<(usize, i64)> = Vec::new();
        let trimmed = body.trim();
        if trimmed != "-" {
            let mut offset = 0;
            for item in body.split(',') {
                let start = offset + (item.len() - item.trim_start().len());
                offset += item.len() + 1;
                let item_t = item.trim();
                if item_t.is_empty() {
                    errors.push(err(
                        "E0802",
                        start,
                        1,
                        "empty item".into(),
                        Some("items are separated by single commas".into()),
                    ));
                    continue;
                }
                let (name, value) = match item_t.split_once('=') {
                    Some((n, v)) => (n.trim(), Some(v.trim())),
                    None => (item_t, None),
                };
                let idx = match resolve(program, name) {
                    Ok(i) => i,
                    Err((code, msg, hint)) => {
                        errors.push(err(code, start, name.len(), msg, hint));
                        continue;
                    }
                };
                let input = &program.inputs[idx];
                let slot = &program.slots[input.slot as usize];
                let v = match (value, input.is_event) {
                    (None, true) => 1,
                    (Some(v), true) => {
                        // An event is present or absent: it takes no value, not even `true`.
                        errors.push(err(
                            "E0805",
                            start,
                            item_t.len(),
                            format!("event `{}` takes no value, found `{v}`", input.name),
                            Some(format!(
                                "write just `{name}` to make it present in this tick, or leave it out"
                            )),
                        ));
                        continue;
                    }
                    (None, false) => {
                        errors.push(err(
                            "E0806",
                            start,
                            name.len(),
                            format!("`{}` is not an event; give it a value", input.name),
                            Some(format!("write `{name} = <value>`")),
                        ));
                        continue;
                    }
                    // A bool takes `true` or `false`, not a number (the IR's parser, which
                    // also reads traces, accepts `1` and `0`).
                    (Some(v), false)
                        if matches!(slot.display, statecheck_ir::ValueKind::Bool)
                            && !matches!(v, "true" | "false") =>
                    {
                        errors.push(err(
                            "E0808",
                            start,
                            item_t.len(),
                            format!("`{}` is a `bool`, found `{v}`", input.name),
                            Some(match suggest(v, vec!["true", "false"]) {
                                Some(s) => format!("did you mean `{s}`?"),
                                None => "`true` or `false`".into(),
                            }),
                        ));
                        continue;
                    }
                    (Some(v), false) => match slot.display.parse(v) {
                        Some(x) if x >= slot.lo && x <= slot.hi => x,
                        Some(x) => {
                            errors.push(err(
                                "E0807",
                                start,
                                item_t.len(),
                                format!(
                                    "{x} is out of range {}..{} for `{}`",
                                    slot.lo, slot.hi, input.name
                                ),
                                None,
                            ));
                            continue;
                        }
                        None => {
                            let hint = match &slot.display {
                                statecheck_ir::ValueKind::Enum(names) => {
                                    format!("one of: {}", names.join(", "))
                                }
                                statecheck_ir::ValueKind::Bool => "`true` or `false`".into(),
                                statecheck_ir::ValueKind::Int => "an integer".into(),
                            };
                            let hint = match suggest(v, slot_names(&slot.display)) {
                                Some(s) => format!("did you mean `{s}`?"),
                                None => hint,
                            };
                            errors.push(err(
                                "E0808",
                                start,
                                item_t.len(),
                                format!("`{v}` is not a value of `{}`", input.name),
                                Some(hint),
                            ));
                            continue;
                        }
                    },
                };
                changes.push((idx, v));
            }
        }
        if ticks.len().saturating_add(repeat) > MAX_TICKS {
            errors.push(err(
                "E0809",
                0,
                content.len(),
                format!("the scenario would exceed {MAX_TICKS} ticks"),
                None,
            ));
            break;
        }
        ticks.push_repeated(changes, repeat);
    }
    if errors.is_empty() {
        if loop_start.is_some_and(|k| k == 0 || k >= ticks.len()) {
            return Err(vec![ScenarioError {
                code: "E0810",
                line: 1,
                col: 1,
                len: 1,
                message:
                    "the `loop:` line must follow the first tick and precede at least one tick"
                        .into(),
                hint: Some("tick 0 only initialises, so a loop starts at tick 1 or later".into()),
            }]);
        }
        ticks.loop_start = loop_start;
        Ok(ticks)
    } else {
        Err(errors)
    }
}

/// Find an input by `instance.var` or by an unambiguous bare `var`.
fn resolve(program: &Program, name: &str) -> Result<usize, (&'static str, String, Option<String>)> {
    if let Some(i) = program.inputs.iter().position(|inp| inp.name == name) {
        return Ok(i);
    }
    let matches: Vec<usize> = program
        .inputs
        .iter()
        .enumerate()
        .filter(|(_, inp)| inp.name.rsplit('.').next() == Some(name))
        .map(|(i, _)| i)
        .collect();
    match matches.as_slice() {
        [i] => Ok(*i),
        [] => {
            let known: Vec<&str> = program.inputs.iter().map(|i| i.name.as_str()).collect();
            let is_var = program
                .slots
                .iter()
                .any(|s| s.name == name || s.name.rsplit('.').next() == Some(name));
            let names: Vec<&str> = program
                .inputs
                .iter()
                .flat_map(|i| [i.name.as_str(), i.name.rsplit('.').next().unwrap_or("")])
                .collect();
            let hint = if let Some(s) = suggest(name, names).filter(|_| !is_var) {
                Some(format!("did you mean `{s}`?"))
            } else if is_var {
                Some(format!("`{name}` is not a free input (it is computed or connected); the free inputs are: {}", known.join(", ")))
            } else if known.is_empty() {
                Some("this system has no free inputs".into())
            } else {
                Some(format!("the free inputs are: {}", known.join(", ")))
            };
            Err(("E0803", format!("unknown input `{name}`"), hint))
        }
        many => Err((
            "E0804",
            format!("`{name}` is ambiguous"),
            Some(format!(
                "qualify it: {}",
                many.iter()
                    .map(|i| program.inputs[*i].name.as_str())
                    .collect::<Vec<_>>()
                    .join(" or ")
            )),
        )),
    }
}

/// The literal names of an enum display (none for other kinds).
fn slot_names(d: &statecheck_ir::ValueKind) -> Vec<&str> {
    match d {
        statecheck_ir::ValueKind::Enum(names) => names.iter().map(String::as_str).collect(),
        _ => Vec::new(),
    }
}

/// The candidate closest to `word` when it is close enough to be a likely misspelling
/// (edit distance at most 1 for words of up to three characters, 2 for longer ones).
fn suggest<'c>(word: &str, candidates: Vec<&'c str>) -> Option<&'c str> {
    let limit = if word.chars().count() >= 4 { 2 } else { 1 };
    candidates
        .into_iter()
        .filter(|c| !c.is_empty() && *c != word)
        .map(|c| (edit_distance(word, c), c))
        .filter(|(d, _)| *d <= limit)
        .min_by_key(|(d, c)| (*d, *c))
        .map(|(_, c)| c)
}

/// Levenshtein distance over characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur.push(sub.min(prev[j + 1] + 1).min(cur[j] + 1));
        }
        prev = cur;
    }
    prev[b.len()]
}
/// The header line of a scenario file.
const HEADER: &str =
    "# statecheck scenario: one line per tick; `name = value` holds, bare names are events\n";

/// Write a scenario in the canonical format: qualified names, held inputs written only when
/// they change, identical consecutive lines folded into `* N`.
pub fn format(s: &Scenario, program: &Program) -> String {
    let mut w = ScenarioWriter::new(program);
    let mut out = w.header().to_string();
    let mut at = 0;
    for (changes, n) in &s.lines {
        let mut n = *n;
        // A fold never crosses the loop's start: split the line there.
        if let Some(k) = s.loop_start.filter(|&k| k > at && k < at + n) {
            out.push_str(&w.push_repeated(changes, k - at));
            n -= k - at;
            at = k;
        }
        if s.loop_start == Some(at) {
            out.push_str(&w.mark_loop());
        }
        out.push_str(&w.push_repeated(changes, n));
        at += n;
    }
    out.push_str(&w.finish());
    out
}

/// A scenario written tick by tick, in the canonical format of [`format`], holding only the
/// pending line (for folding repeats) and the held inputs: constant memory for any length.
pub struct ScenarioWriter<'p> {
    program: &'p Program,
    held: Vec<i64>,
    /// The last line, not yet written, how many ticks it stands for, and whether repeats
    /// of it fold.
    pending: Option<(String, u64, bool)>,
}

impl<'p> ScenarioWriter<'p> {
    /// A writer for scenarios of `program`.
    pub fn new(program: &'p Program) -> Self {
        ScenarioWriter {
            program,
            held: program
                .inputs
                .iter()
                .map(|i| program.slots[i.slot as usize].init)
                .collect(),
            pending: None,
        }
    }

    /// The file's header line.
    pub fn header(&self) -> &'static str {
        HEADER
    }

    /// The next tick, as a full input vector (in `Program::inputs` order); returns the text
    /// that is complete (possibly empty).
    pub fn push_vector(&mut self, vector: &[i64]) -> String {
        let changes = changes(self.program, &mut self.held, vector);
        self.push_changes(&changes)
    }

    /// `n` ticks with the same changes, written as one `* N` line (reading it back gives the
    /// same scenario).
    pub fn push_repeated(&mut self, tick: &[(usize, i64)], n: usize) -> String {
        if n == 0 {
            return String::new();
        }
        let done = self.push_changes(tick);
        if let Some((_, count, _)) = &mut self.pending {
            *count += (n - 1) as u64;
        }
        done
    }

    /// The next tick, as its changes (input index, value).
    pub fn push_changes(&mut self, tick: &[(usize, i64)]) -> String {
        let p = self.program;
        let items: Vec<String> = tick
            .iter()
            .map(|(i, v)| {
                let inp = &p.inputs[*i];
                if inp.is_event {
                    inp.name.clone()
                } else {
                    format!(
                        "{} = {}",
                        inp.name,
                        p.slots[inp.slot as usize].display.format(*v)
                    )
                }
            })
            .collect();
        let line = if items.is_empty() {
            "-".to_string()
        } else {
            items.join(", ")
        };
        // Only lines that are pure repeats fold: event lines, or `-`.
        let foldable = tick.iter().all(|(k, _)| p.inputs[*k].is_event);
        if let Some((last, n, true)) = &mut self.pending {
            if *last == line {
                *n += 1;
                return String::new();
            }
        }
        let done = self.finish();
        self.pending = Some((line, 1, foldable));
        done
    }

    /// Mark the start of a lasso's loop before the next tick: the pending line is written
    /// (a fold never crosses the loop's start), then `loop:`.
    pub fn mark_loop(&mut self) -> String {
        let mut done = self.finish();
        done.push_str("loop:\n");
        done
    }

    /// The text of the pending line (call once after the last tick).
    pub fn finish(&mut self) -> String {
        match self.pending.take() {
            Some((line, n, _)) if n > 1 => format!("{line} * {n}\n"),
            Some((line, _, _)) => format!("{line}\n"),
            None => String::new(),
        }
    }
}

/// The changes of one full input vector against the held values (updated): the present
/// events and the held inputs whose value changed.
fn changes(program: &Program, held: &mut [i64], vector: &[i64]) -> Vec<(usize, i64)> {
    let mut changes = Vec::new();
    for (k, inp) in program.inputs.iter().enumerate() {
        let v = vector[k];
        if inp.is_event {
            if v != 0 {
                changes.push((k, 1));
            }
        } else if v != held[k] {
            held[k] = v;
            changes.push((k, v));
        }
    }
    changes
}

/// Build a scenario from full input vectors (one per tick, in `Program::inputs` order),
/// keeping only the changes of held inputs and the present events.
pub fn from_input_vectors(program: &Program, vectors: &[Vec<i64>]) -> Scenario {
    let mut held: Vec<i64> = program
        .inputs
        .iter()
        .map(|i| program.slots[i.slot as usize].init)
        .collect();
    let mut s = Scenario::new();
    for vec in vectors {
        s.push(changes(program, &mut held, vec));
    }
    s
}

/// A lasso scenario: like [`from_input_vectors`], with a `loop:` before tick `loop_start`
/// whose first tick writes every held input, so that repeating the loop repeats its inputs.
pub fn from_lasso(program: &Program, vectors: &[Vec<i64>], loop_start: usize) -> Scenario {
    let mut s = from_input_vectors(program, vectors);
    if let Some(vec) = vectors.get(loop_start) {
        let tick = program
            .inputs
            .iter()
            .enumerate()
            .filter(|(k, inp)| !inp.is_event || vec[*k] != 0)
            .map(|(k, _)| (k, vec[k]))
            .collect();
        s.set_tick(loop_start, tick);
    }
    s.loop_start = Some(loop_start);
    s
}
