//! The generator's interfaces, slots and configurations: an interface `Cnt` (an input event,
//! an input and an output variable), two charts that implement it with different ranges
//! (`Ea`: exactly the interface's; `Eb(m)`: a wider input, a narrower output, one more free
//! input and a parameter), a slot `s: Cnt` in the system connected to the main instance one
//! way or the other, and two configurations that fill it (`Ea`, `Eb(m = …)`) in a random
//! order: the model's system is its first configuration, so both charts are compared over a
//! run. Properties read the slot by its interface's ports (`s.n`, `s.v`). In two models in
//! five the slot is inside a component `Holder` with the interface's ports (a slot inside a
//! component, bound by path: `s.t = Ea`; read as `s.t.n`). Like the other
//! extras, configurations are resolved before the IR: the oracles apply unchanged.

use super::extra::Extra;
use super::Gen;

/// Guards of the slot charts (over the ports `v`, `n`; `Eb` also reads `m` and `hold`).
const GUARDS: [&str; 5] = ["n < 2", "v > 1", "v <= 0", "n + v > 2", "true"];

/// Actions of the slot charts: some may leave `n`'s range (a run-time error the engines must
/// agree on; `Eb`'s `n` is `int[1..2]`).
const ACTIONS: [&str; 5] = [
    "n = n + 1;",
    "n = 1;",
    "n = max(n - 1, 1);",
    "n = min(n + v, 2);",
    "n = 2;",
];

impl Gen {
    fn slot_transition(&mut self, target: &str, extra_guard: &str) -> String {
        let trig = if self.chance(50) { "go " } else { "" };
        let guard = if trig.is_empty() || self.chance(50) {
            let g = GUARDS[self.pick(GUARDS.len())];
            if extra_guard.is_empty() || self.chance(50) {
                format!("[{g}] ")
            } else {
                format!("[{g} && {extra_guard}] ")
            }
        } else {
            String::new()
        };
        let rest = self.action_and_target(&ACTIONS, target);
        format!("on {trig}{guard}{rest};")
    }

    /// The interface, its two charts, the slot, its connections, configurations and
    /// properties.
    pub(super) fn slotted(&mut self) -> Extra {
        // In two models in five the slot sits inside a component `Holder` whose ports are the
        // interface's: configurations bind it by path (`s.t = Ea`), properties read it as
        // `s.t.n`.
        let inside = self.chance(40);
        let slot = if inside { "s.t" } else { "s" };
        let (a1, a2) = (self.slot_transition("B", ""), self.slot_transition("A", ""));
        let (b1, b2) = (
            self.slot_transition("B", "!hold"),
            self.slot_transition("A", "v != m"),
        );
        let items = format!(
            "\ninterface Cnt {{\n  input event go;\n  input v: int[-4..4];\n  output n: int[0..3];\n}}\n\
             chart Ea implements Cnt {{\n  input event go;\n  input v: int[-4..4] = 0;\n  output n: int[0..3] = 0;\n  initial A;\n  state A {{ {a1} }}\n  state B {{ {a2} }}\n}}\n\
             chart Eb(m: int[0..3] = 1) implements Cnt {{\n  input event go;\n  input v: int[-6..6] = 0;\n  input hold: bool = false;\n  output n: int[1..2] = 1;\n  initial A;\n  state A {{ {b1} }}\n  state B {{ entry {{ n = 2; }} {b2} }}\n}}\n"
        );
        let holder = if inside {
            "component Holder {\n  input event go;\n  input v: int[-4..4];\n  output n: int[0..3];\n  \
             instance t: Cnt;\n  connect go -> t.go;\n  connect v -> t.v;\n  connect t.n -> n;\n}\n"
        } else {
            ""
        };
        let items = format!("{items}{holder}");
        let configs = [
            format!("  configuration ca {{ {slot} = Ea; }}\n"),
            format!(
                "  configuration cb {{ {slot} = Eb(m = {}); }}\n",
                self.pick(4)
            ),
        ];
        let first = self.pick(2);
        let mut props = format!("{}{}", configs[first], configs[1 - first]);
        for j in 0..1 + self.pick(2) {
            let n = self.pick(4);
            let e = match self.pick(4) {
                0 => format!("{slot}.n <= {n}"),
                1 => format!("{slot}.n != {n}"),
                2 => format!("{slot}.n != {n} || p.x > 0"),
                _ => format!("{slot}.v > 2 || {slot}.n < {}", 1 + n),
            };
            if self.chance(35) {
                props.push_str(&format!("  reachable sreach{j}: !({e});\n"));
            } else {
                props.push_str(&format!("  invariant sinv{j}: {e};\n"));
            }
        }
        // The main instance drives the slot (which runs after it), or the slot drives `p.a`.
        let decl = format!("  instance s: {};\n", if inside { "Holder" } else { "Cnt" });
        let (before, after, conns) = match self.pick(3) {
            0 => (
                String::new(),
                decl,
                "  connect p.oe -> s.go;\n  connect p.y -> s.v;\n".to_string(),
            ),
            1 => (decl, String::new(), "  connect s.n -> p.a;\n".to_string()),
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
}
