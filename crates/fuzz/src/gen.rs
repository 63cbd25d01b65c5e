//! A generator of random well-typed `.sc` models (seeded, deterministic): nested exclusive and
//! parallel states, history, timers, local and input events, choices, priorities, internal and
//! self transitions, arithmetic that can fail at run time (division by zero, bad shifts, range
//! errors), `assume`s (input-only and state-dependent), `invariant`/`reachable`/`respond`
//! properties and, in some models, `ltl`/`ctl`/`fair` declarations, a chart parameter (used in
//! expressions, fixed differently per instance) and time units (`tick 100 ms;`, `after(200
//! ms)`, `within 300 ms`). Optionally two instances connected in a system, an interleaved
//! system, a composite component (ports, parameters, nesting, instance arrays) and a hybrid
//! plant (`continuous`, `grid`, `sensor`, `der`, `profile`), see [`extra`], and arrays of
//! variables (`input r[2]`, `output g[2]`) read and written by constant index and in `for j
//! in 0..2` loops, connected element by element (`[*]`) between two instances, and an
//! interface with two implementing charts filling a slot in two configurations ([`slots`]).
//! Not generated: imports (file-level). Also the generator of the codegen crate's differential test.

mod extra;
mod slots;

use rand::rngs::StdRng;
use rand::{RngExt, SeedableRng};

/// Builds one model.
pub struct Gen {
    rng: StdRng,
    next_state: usize,
    /// Paths of every state (targets and `in()` operands).
    paths: Vec<String>,
    /// Paths that are inside a parallel state (transitions into them are avoided in regions).
    leaves: Vec<String>,
    /// The chart has the parameter `k: int[0..3]` (used as an expression leaf).
    param: bool,
    /// Properties are being written (system scope: `k` is not visible there).
    in_props: bool,
    /// The model declares `tick 100 ms;` and writes delays and bounds in milliseconds.
    time_units: bool,
    /// The chart has the arrays `input r[2]` and `output g[2]` (constant indices, `for`
    /// loops, and `[*]` connections between two instances).
    arrays: bool,
    /// A `for j in 0..2` loop's body is being written (`j`, `r[j]`, `g[j]` are leaves).
    in_loop: bool,
}

impl Gen {
    /// A generator for `seed`.
    pub fn new(seed: u64) -> Gen {
        Gen {
            rng: StdRng::seed_from_u64(seed),
            next_state: 0,
            paths: Vec::new(),
            leaves: Vec::new(),
            param: false,
            in_props: false,
            time_units: false,
            arrays: false,
            in_loop: false,
        }
    }

    fn pick(&mut self, n: usize) -> usize {
        self.rng.random_range(0..n)
    }

    fn chance(&mut self, percent: u32) -> bool {
        self.rng.random_range(0..100u32) < percent
    }

    fn int_leaf(&mut self) -> String {
        if self.param && !self.in_props && self.chance(12) {
            return "k".into();
        }
        if self.arrays && self.chance(15) {
            if self.in_loop && self.chance(60) {
                return ["j", "r[j]", "g[j]"][self.pick(3)].into();
            }
            return format!("{}[{}]", ["r", "g"][self.pick(2)], self.pick(2));
        }
        match self.pick(6) {
            0 => "x".into(),
            1 => "y".into(),
            2 => "a".into(),
            3 => "c".into(),
            _ => format!("{}", self.rng.random_range(-3i64..6)),
        }
    }

    /// An integer expression of depth at most `d`.
    pub fn int_expr(&mut self, d: u32) -> String {
        if d == 0 || self.chance(30) {
            return self.int_leaf();
        }
        let (l, r) = (self.int_expr(d - 1), self.int_expr(d - 1));
        match self.pick(13) {
            0 | 1 => format!("({l} + {r})"),
            2 | 3 => format!("({l} - {r})"),
            4 => format!("({l} * {r})"),
            5 => format!("({l} / {})", self.var_int()),
            6 => format!("({l} % {})", self.var_int()),
            7 => format!("min({l}, {r})"),
            8 => format!("max({l}, {r})"),
            9 => format!("abs({l})"),
            10 => {
                let c = self.bool_expr(d - 1);
                format!("(if {c} then {l} else {r})")
            }
            11 => format!("({l} << {})", self.var_int()),
            _ => format!("({l} >> {})", self.var_int()),
        }
    }

    fn var_int(&mut self) -> String {
        ["x", "y", "a", "c", "(a + 1)"][self.pick(5)].into()
    }

    /// A boolean expression of depth at most `d`.
    pub fn bool_expr(&mut self, d: u32) -> String {
        if d == 0 || self.chance(25) {
            return match self.pick(6) {
                0 => "b".into(),
                1 => "f".into(),
                2 => "e0".into(),
                3 if !self.paths.is_empty() => {
                    let k = self.pick(self.paths.len());
                    format!("in({})", self.paths[k])
                }
                _ => {
                    let (l, r) = (self.int_leaf(), self.int_leaf());
                    format!(
                        "{l} {} {r}",
                        ["<", "<=", "==", "!=", ">", ">="][self.pick(6)]
                    )
                }
            };
        }
        match self.pick(5) {
            0 => format!("({} && {})", self.bool_expr(d - 1), self.bool_expr(d - 1)),
            1 => format!("({} || {})", self.bool_expr(d - 1), self.bool_expr(d - 1)),
            2 => format!("!({})", self.bool_expr(d - 1)),
            _ => {
                let (l, r) = (self.int_expr(d - 1), self.int_expr(d - 1));
                format!(
                    "{l} {} {r}",
                    ["<", "<=", "==", "!=", ">", ">="][self.pick(6)]
                )
            }
        }
    }

    fn stmts(&mut self, n: usize) -> String {
        let mut out = String::new();
        for _ in 0..n {
            if self.arrays && !self.in_loop && self.chance(25) {
                let s = self.array_stmt();
                out.push_str(&s);
                out.push(' ');
                continue;
            }
            let s = match self.pick(8) {
                0 | 1 => format!("x = {};", self.int_expr(2)),
                2 => {
                    let e = fit(self.int_expr(2), 0, 3);
                    format!("y = {e};")
                }
                3 => format!("f = {};", self.bool_expr(2)),
                4 => "raise le;".into(),
                5 => "raise oe;".into(),
                6 => format!("x += {};", self.int_leaf()),
                _ => {
                    let c = self.bool_expr(2);
                    let t = format!("x = {};", self.int_expr(1));
                    let e = format!("y = {};", fit(self.int_expr(1), 0, 3));
                    format!("if {c} {{ {t} }} else {{ {e} }}")
                }
            };
            out.push_str(&s);
            out.push(' ');
        }
        out
    }

    /// A statement on the arrays: a `for` loop over both elements or an element by a
    /// constant index (values may leave `int[0..3]`: a run-time error).
    fn array_stmt(&mut self) -> String {
        if self.chance(60) {
            self.in_loop = true;
            let e = fit(self.int_expr(1), 0, 3);
            let extra = if self.chance(40) {
                format!(" x += {};", self.int_leaf())
            } else {
                String::new()
            };
            self.in_loop = false;
            format!("for j in 0..2 {{ g[j] = {e};{extra} }}")
        } else {
            let i = self.pick(2);
            let e = fit(self.int_expr(1), 0, 3);
            if self.chance(30) {
                format!("g[{i}] += {e};")
            } else {
                format!("g[{i}] = {e};")
            }
        }
    }

    fn trigger(&mut self) -> String {
        match self.pick(7) {
            0 => "e0 ".into(),
            1 => "e1 ".into(),
            2 => "le ".into(),
            3 => {
                let n = self.rng.random_range(1..4);
                if self.time_units {
                    format!("after({} ms) ", n * 100)
                } else {
                    format!("after({n}) ")
                }
            }
            4 => "oe ".into(),
            _ => String::new(),
        }
    }

    fn target(&mut self, siblings: &[String]) -> String {
        if !self.leaves.is_empty() && self.chance(30) {
            let k = self.pick(self.leaves.len());
            return self.leaves[k].clone();
        }
        siblings[self.pick(siblings.len())].clone()
    }

    fn transition(&mut self, siblings: &[String]) -> String {
        let trig = self.trigger();
        let guard = if trig.is_empty() || self.chance(40) {
            format!("[{}] ", self.bool_expr(2))
        } else {
            String::new()
        };
        let action = if self.chance(50) {
            let n = 1 + self.pick(2);
            format!("/ {{ {}}} ", self.stmts(n))
        } else {
            String::new()
        };
        let prio = if self.chance(15) { " priority 1" } else { "" };
        let tgt = match self.pick(6) {
            0 => String::new(), // internal
            1 => {
                let (t1, t2) = (self.target(siblings), self.target(siblings));
                let g = self.bool_expr(1);
                let else_ = if self.chance(50) {
                    format!(" else -> {t2};")
                } else {
                    String::new()
                };
                format!(
                    "-> choice {{ [{g}] / {{ {}}} -> {t1};{else_} }}",
                    self.stmts(1)
                )
            }
            _ => format!("-> {}", self.target(siblings)),
        };
        format!("on {trig}{guard}{action}{tgt}{prio};")
    }

    /// States of one exclusive level under `prefix`: returns their text.
    fn level(&mut self, prefix: &str, depth: u32, in_parallel: bool) -> String {
        let n = 2 + self.pick(2);
        let names: Vec<String> = (0..n)
            .map(|_| {
                self.next_state += 1;
                format!("S{}", self.next_state)
            })
            .collect();
        let full: Vec<String> = names.iter().map(|s| format!("{prefix}{s}")).collect();
        self.paths.extend(full.iter().cloned());
        let mut out = format!("initial {}; ", names[0]);
        if depth > 0 && self.chance(30) {
            out.push_str(if self.chance(50) {
                "history shallow; "
            } else {
                "history deep; "
            });
        }
        for (k, name) in names.iter().enumerate() {
            let mut body = String::new();
            for (kw, pct) in [("entry", 50), ("during", 50), ("exit", 30)] {
                if self.chance(pct) {
                    let n = 1 + self.pick(2);
                    body.push_str(&format!("{kw} {{ {}}} ", self.stmts(n)));
                }
            }
            for _ in 0..self.pick(3) {
                let t = self.transition(&full);
                body.push_str(&t);
                body.push(' ');
            }
            let inner = format!("{}.", full[k]);
            if depth < 2 && self.chance(35) {
                if !in_parallel && self.chance(30) {
                    let mut regions = String::new();
                    for r in 0..2 {
                        let rp = format!("{inner}r{r}.");
                        let lv = self.level(&rp, depth + 1, true);
                        regions.push_str(&format!("region r{r} {{ {lv} }} "));
                    }
                    body.push_str(&regions);
                } else {
                    body.push_str(&self.level(&inner, depth + 1, in_parallel));
                }
            } else if !in_parallel {
                self.leaves.push(full[k].clone());
            }
            out.push_str(&format!("state {name} {{ {body}}} "));
        }
        out
    }

    /// Properties and assumes over the instance prefix `p` (`C.` for a chart's implicit
    /// system, `p.` in the system of two instances); `temporal` adds `ltl`/`ctl`/`fair`.
    fn properties(&mut self, p: &str, temporal: bool) -> String {
        let mut out = String::new();
        let qual = |e: String| -> String {
            // Prefix the chart's names with the instance.
            let mut o = String::new();
            let mut word = String::new();
            let flush = |w: &mut String, o: &mut String| {
                if ["x", "y", "a", "b", "c", "f", "e0", "r", "g"].contains(&w.as_str()) {
                    o.push_str(p);
                }
                o.push_str(w);
                w.clear();
            };
            let mut in_path = false;
            for ch in e.chars() {
                if ch.is_alphanumeric() || ch == '_' {
                    word.push(ch);
                } else {
                    if ch == '(' && word == "in" {
                        o.push_str(&word);
                        word.clear();
                        o.push('(');
                        o.push_str(p);
                        in_path = true;
                        continue;
                    }
                    if in_path {
                        o.push_str(&word);
                        word.clear();
                        if ch == ')' {
                            in_path = false;
                        }
                        o.push(ch);
                        continue;
                    }
                    flush(&mut word, &mut o);
                    o.push(ch);
                }
            }
            if in_path {
                o.push_str(&word);
            } else {
                flush(&mut word, &mut o);
            }
            o
        };
        if self.chance(40) {
            let e = match self.pick(3) {
                0 => format!("a != {}", self.rng.random_range(-4i64..5)),
                1 => "!(b && c > 1)".to_string(),
                _ => format!("x < {} || a <= 0", self.rng.random_range(-5i64..10)),
            };
            out.push_str(&format!("  assume {};\n", qual(e)));
        }
        for k in 0..1 + self.pick(3) {
            let e = self.bool_expr(2).replace("e0", "b");
            let e = qual(e);
            match self.pick(4) {
                0 | 1 => out.push_str(&format!("  invariant inv{k}: {e};\n")),
                2 => out.push_str(&format!("  reachable reach{k}: {e};\n")),
                _ => {
                    let r = qual(self.bool_expr(1).replace("e0", "b"));
                    let n = self.pick(3);
                    let within = if self.time_units {
                        format!("{} ms", n * 100)
                    } else {
                        n.to_string()
                    };
                    out.push_str(&format!("  respond resp{k}: {e} => {r} within {within};\n"));
                }
            }
        }
        if temporal && !self.paths.is_empty() {
            let k = self.pick(self.paths.len());
            let s = format!("in({p}{})", self.paths[k]);
            let v = qual("x > 0".to_string());
            match self.pick(3) {
                0 => out.push_str(&format!(
                    "  ltl l0: G F {s};\n  ltl l1: G({v} => F !({v}));\n"
                )),
                1 => out.push_str(&format!("  ctl c0: AG EF {s};\n")),
                _ => out.push_str(&format!("  fair j0: {s};\n  ltl l2: F G !({v});\n")),
            }
        }
        out
    }

    /// A whole model: one chart, or a system of two connected instances.
    pub fn model(&mut self) -> String {
        self.model_with(false)
    }

    /// A whole model with properties and assumes (and, if `temporal`, temporal properties);
    /// with properties, some models also get a composite component, a hybrid plant or an
    /// interleaved system ([`extra`]).
    pub fn model_with(&mut self, props: bool) -> String {
        let (mut plant, mut composite, mut interleaved, mut slotted) = (false, false, false, false);
        if props {
            self.param = self.chance(25);
            self.time_units = self.chance(25);
            composite = self.chance(20);
            slotted = self.chance(20);
            plant = self.chance(15);
            interleaved = self.chance(15);
            self.arrays = self.chance(25);
            // A continuous variable's rates are per second: its model declares the tick.
            self.time_units |= plant;
        }
        let body = self.level("", 0, false);
        let two = self.chance(30);
        let temporal = props && self.chance(20);
        self.in_props = true;
        let (decl, args) = if self.param {
            let (a, b) = (self.pick(4), self.pick(4));
            (
                "(k: int[0..3] = 1)".to_string(),
                [format!("({a})"), format!("(k = {b})")],
            )
        } else {
            (String::new(), [String::new(), String::new()])
        };
        let [pa, qa] = args;
        let tick = if self.time_units {
            "tick 100 ms;\n"
        } else {
            ""
        };
        let arrays = if self.arrays {
            "input r[2]: int[0..3] = 0;\n  output g[2]: int[0..3] = 0;\n  "
        } else {
            ""
        };
        let mut text = format!(
            "{tick}chart C{decl} {{\n  input event e0;\n  input event e1;\n  input a: int[-4..4] = 0;\n  input b: bool = false;\n  input c: int[-2..3] = 1;\n  {arrays}output x: int[-20..20] = 0;\n  output y: int[0..3] = 0;\n  local f: bool = false;\n  local event le;\n  output event oe;\n  {body}\n}}\n"
        );
        if !two && !props {
            return text;
        }
        let sys_props = if props {
            self.properties("p.", temporal)
        } else {
            String::new()
        };
        let mut extras = Vec::new();
        if composite {
            extras.push(self.composite());
        }
        if slotted {
            extras.push(self.slotted());
        }
        if plant {
            extras.push(self.plant());
        }
        let mut sys = String::new();
        for e in &extras {
            text.push_str(&e.items);
            sys.push_str(&e.before);
        }
        sys.push_str(&format!("  instance p: C{pa};\n"));
        if two {
            sys.push_str(&format!(
                "  instance q: C{qa};\n  connect p.y -> q.c;\n  connect p.oe -> q.e1;\n"
            ));
            // `q`'s free data inputs follow `p`'s (an input-only assume, solved before the
            // search): 864 input vectors per tick instead of 15,552, so that the explicit
            // reference can decide most systems of two (over 50,000 it skips the model).
            sys.push_str("  assume q.a == p.a && q.b != p.b;\n");
            if self.arrays {
                sys.push_str(if self.chance(60) {
                    "  connect p.g[*] -> q.r[*];\n"
                } else {
                    "  connect p.g[1] -> q.r[0];\n"
                });
            }
        }
        for e in &extras {
            sys.push_str(&e.after);
        }
        for e in &extras {
            sys.push_str(&e.conns);
        }
        sys.push_str(&sys_props);
        for e in &extras {
            sys.push_str(&e.props);
        }
        let name = if two { "Two" } else { "One" };
        let mode = if interleaved { " interleaved" } else { "" };
        format!("{text}\nsystem {name}{mode} {{\n{sys}}}\n")
    }
}

/// `e` itself, or, if it is an integer literal outside `lo..=hi`, a literal inside: the
/// checker rejects a constant assignment out of its target's range (E0104), which would
/// waste the whole model; values that leave the range at run time stay (a run-time error
/// the engines must agree on).
fn fit(e: String, lo: i64, hi: i64) -> String {
    match e.parse::<i64>() {
        Ok(v) if v < lo || v > hi => (lo + v.rem_euclid(hi - lo + 1)).to_string(),
        _ => e,
    }
}

impl Gen {
    /// A random value of a slot (its whole range).
    pub fn value(&mut self, s: &statecheck_ir::Slot) -> i64 {
        self.rng.random_range(s.lo..=s.hi)
    }
}
