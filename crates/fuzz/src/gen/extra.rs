//! The generator's constructs beside the main chart: a composite component (ports, a
//! parameter given to an inner chart, an array of chart instances, optionally nested in a
//! second component or instantiated as an array) and a hybrid plant (a `continuous`
//! variable with a grid, sensors and `der(x) = c` or `profile(…)` motions). Each comes with
//! the system's instance lines, its connections to the main instance `p` and properties by
//! path. Every one is flattened or discretized before the IR, so the differential oracles
//! apply unchanged. All stay small (a few dozen states each) to keep the explicit engine's
//! reference within its bound.

use super::Gen;
use rand::RngExt;

/// What an extra adds to the model: top-level items, the system's instance lines (in
/// execution order: `before` runs ahead of the main instances, `after` behind them), its
/// connections and its properties.
#[derive(Default)]
pub(super) struct Extra {
    pub items: String,
    pub before: String,
    pub after: String,
    pub conns: String,
    pub props: String,
}

/// A guard of the counter chart `D` (over its input `v`, its output `n`, its parameter `m`).
const D_GUARDS: [&str; 7] = [
    "n < 3",
    "v > m",
    "v <= m",
    "n == m",
    "v != 0",
    "n + v > 2",
    "true",
];

/// An action of `D`: some may leave `n`'s range (a run-time error the engines must agree on).
const D_ACTIONS: [&str; 6] = [
    "n = n + 1;",
    "n = 0;",
    "n = m;",
    "raise full;",
    "n = max(n - 1, 0);",
    "n = min(n + v, 3);",
];

impl Gen {
    fn d_transition(&mut self, target: &str) -> String {
        let trig = if self.chance(50) { "go " } else { "" };
        let guard = if trig.is_empty() || self.chance(50) {
            format!("[{}] ", D_GUARDS[self.pick(D_GUARDS.len())])
        } else {
            String::new()
        };
        let rest = self.action_and_target(&D_ACTIONS, target);
        format!("on {trig}{guard}{rest};")
    }

    /// A transition's end: an action drawn from `actions` (60 %) and `-> target` (70 %).
    pub(super) fn action_and_target(&mut self, actions: &[&str], target: &str) -> String {
        let action = if self.chance(60) {
            format!("/ {{ {} }} ", actions[self.pick(actions.len())])
        } else {
            String::new()
        };
        let tgt = if self.chance(30) {
            String::new()
        } else {
            format!("-> {target}")
        };
        format!("{action}{tgt}")
    }

    /// The counter chart `D(m)` and the component `K(m)` around it, perhaps nested in `W`,
    /// with the system's instance of it and properties by path.
    pub(super) fn composite(&mut self) -> Extra {
        let (t1, t2, t3) = (
            self.d_transition("Hi"),
            self.d_transition("Lo"),
            self.d_transition("Lo"),
        );
        let mut items = format!(
            "chart D(m: int[0..3] = 1) {{\n  input event go;\n  input v: int[-4..4] = 0;\n  output n: int[0..3] = 0;\n  output event full;\n  initial Lo;\n  state Lo {{ {t1} }}\n  state Hi {{ {t2} {t3} }}\n}}\n"
        );
        // Inside K: the counter `d` with K's parameter, and either a second counter fed by
        // `d` or an array of two counters.
        let inner = match self.pick(3) {
            0 => "  instance e: D(2);\n  connect go -> e.go;\n  connect d.n -> e.v;\n".to_string(),
            1 => "  instance ds[2]: D(1);\n  connect go -> ds[0].go;\n  connect d.full -> ds[1].go;\n  connect v -> ds[1].v;\n".to_string(),
            _ => String::new(),
        };
        let kprop = match self.pick(3) {
            0 => "  invariant capped: d.n <= m;\n",
            1 => "  reachable full_once: in(d.Hi) && d.n == m;\n",
            _ => "",
        };
        items.push_str(&format!(
            "\ncomponent K(m: int[0..3] = 1) {{\n  input event go;\n  input v: int[-4..4];\n  output cnt: int[0..3];\n  output event full;\n  instance d: D(m);\n{inner}  connect go -> d.go;\n  connect v -> d.v;\n  connect d.n -> cnt;\n  connect d.full -> full;\n{kprop}}}\n"
        ));
        let arg = self.pick(4);
        // The instance in the system: one K, an array of two, or K nested in W.
        let (decl, path, port) = match self.pick(3) {
            0 => (format!("  instance u: K({arg});\n"), "u".to_string(), "u"),
            1 => (
                format!("  instance us[2]: K(m = {arg});\n"),
                format!("us[{}]", self.pick(2)),
                "us[0]",
            ),
            _ => {
                items.push_str(&format!(
                    "\ncomponent W {{\n  input event go;\n  output cnt: int[0..3];\n  output event full;\n  instance inner: K({arg});\n  connect go -> inner.go;\n  connect inner.cnt -> cnt;\n  connect inner.full -> full;\n}}\n"
                ));
                ("  instance w: W;\n".to_string(), "w.inner".to_string(), "w")
            }
        };
        let mut props = String::new();
        for j in 0..1 + self.pick(2) {
            let n = self.pick(4);
            let e = match self.pick(4) {
                0 => format!("{path}.d.n <= {n}"),
                1 => format!("!(in({path}.d.Hi) && {path}.d.n == {n})"),
                2 => format!("{path}.d.n != {n} || in({path}.d.Lo)"),
                _ => format!("in({path}.d.Lo) || p.x != {}", self.pick(3)),
            };
            if self.chance(35) {
                props.push_str(&format!("  reachable creach{j}: !({e});\n"));
            } else {
                props.push_str(&format!("  invariant cinv{j}: {e};\n"));
            }
        }
        // Connected to `p` one way: p drives the component (which then runs after p), or
        // the component drives p's free inputs `c` and `e1` (and runs before p).
        let (before, after, conns) = match self.pick(3) {
            0 => (
                String::new(),
                decl,
                format!("  connect p.oe -> {port}.go;\n"),
            ),
            1 => {
                let ev = if self.chance(50) {
                    format!("  connect {port}.full -> p.e1;\n")
                } else {
                    String::new()
                };
                (
                    decl,
                    String::new(),
                    format!("  connect {port}.cnt -> p.c;\n{ev}"),
                )
            }
            _ => (String::new(), decl, String::new()),
        };
        Extra {
            items,
            before,
            after,
            conns,
            props,
        }
    }

    /// A plant chart `P` with a continuous variable `z` (tick 100 ms: every rate crosses a
    /// cell of the grid in a whole number of ticks), its instance `h` and properties.
    pub(super) fn plant(&mut self) -> Extra {
        let init = [0, 2][self.pick(2)];
        let grid = if self.chance(60) { "  grid z 4;\n" } else { "" };
        let lo = self.pick(2);
        let hi = 2 + self.pick(3);
        // Units per second: with integer grid points 1 unit is 1, 2 or 4 ticks of 100 ms.
        let rate = |g: &mut Gen, sign: &str| -> String {
            match g.pick(4) {
                0 => format!("{sign}10"),
                1 => format!("{sign}5"),
                2 => format!("{sign}2.5"),
                _ => format!("profile({sign}10 for 200 ms, {sign}5)"),
            }
        };
        let up = rate(self, "");
        let down = rate(self, "-");
        let top = 1 + self.pick(4);
        let bottom = self.pick(2);
        let items = format!(
            "\nplant chart P {{\n  input go: bool = false;\n  input back: bool = false;\n  output low: bool;\n  output high: bool;\n  continuous z: [0 .. 4] = {init};\n{grid}  sensor low = z in [0 .. {lo}];\n  sensor high = z in [{hi} .. 4];\n  initial Rest;\n  state Rest {{ on [go] -> Up; on [back && !go] -> Down; }}\n  state Up {{ der(z) = {up}; on [z >= {top}] -> Rest; on [back] -> Down; }}\n  state Down {{ der(z) = {down}; on [z <= {bottom}] -> Rest; }}\n}}\n"
        );
        let mut props = String::new();
        for j in 0..1 + self.pick(2) {
            let n = self.rng.random_range(0..5);
            let e = match self.pick(5) {
                0 => format!("h.z <= {n}"),
                1 => "!(h.low && h.high)".to_string(),
                2 => format!("!in(h.Up) || h.z < {n}"),
                3 => format!("h.high || h.z < {n}"),
                _ => format!("!(in(h.Down) && h.z == {n})"),
            };
            match self.pick(3) {
                0 => props.push_str(&format!("  reachable hreach{j}: !({e});\n")),
                1 => props.push_str(&format!(
                    "  respond hresp{j}: in(h.Up) => !in(h.Up) within {} ms;\n",
                    100 * (1 + self.pick(8))
                )),
                _ => props.push_str(&format!("  invariant hinv{j}: {e};\n")),
            }
        }
        // The plant runs first; its sensor may drive `p.b`.
        let conn = if self.chance(50) {
            "  connect h.high -> p.b;\n"
        } else {
            ""
        };
        Extra {
            items,
            before: "  instance h: P;\n".to_string(),
            after: String::new(),
            conns: conn.to_string(),
            props,
        }
    }
}
