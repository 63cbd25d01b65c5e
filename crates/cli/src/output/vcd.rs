//! VCD waveforms (IEEE 1364 value change dump) that GTKWave opens: every variable, every
//! event, and a 1-bit signal per state that is high while the state is active.

use statecheck_ir::view::TraceView as Views;
use statecheck_ir::{eval, Program};
use statecheck_sim::TickRecord;
use std::fmt::Write;

fn ident(mut n: usize) -> String {
    let mut s = String::new();
    loop {
        s.push((33 + (n % 94)) as u8 as char);
        n /= 94;
        if n == 0 {
            return s;
        }
    }
}

fn vcd_name(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect()
}

/// Render a trace as VCD: with a declared tick, in a time scale that matches it
/// ([`statecheck_ir::time::vcd_timescale`]); without one, one tick is one unit of `1ms`.
pub fn render(p: &Program, views: &Views, trace: &[TickRecord]) -> String {
    let (mut s, mut out) = Stream::new(p, views);
    for rec in trace {
        out.push_str(&s.tick(rec.tick, &rec.slots));
    }
    out.push_str(&s.finish());
    out
}

enum Sig {
    Var { slot: u32, is_bool: bool },
    Event(u32),
    State(u32),
}

/// A VCD file written tick by tick: the last value of each signal is all it keeps.
pub struct Stream<'a> {
    p: &'a Program,
    sigs: Vec<(String, Sig)>,
    last: Vec<Option<i64>>,
    last_tick: Option<u64>,
    /// Time units of the `$timescale` per tick.
    units: i64,
}

impl<'a> Stream<'a> {
    /// The stream and the file's header (the signal definitions).
    pub fn new(p: &'a Program, views: &Views) -> (Self, String) {
        let mut sigs: Vec<(String, Sig)> = Vec::new();
        let mut out = String::new();
        let (units, scale) = match p.tick_ms {
            Some(ms) => {
                let (unit_ms, text) = statecheck_ir::time::vcd_timescale(ms);
                (ms / unit_ms, text)
            }
            None => (1, "1ms"),
        };
        let _ = writeln!(
            out,
            "$date statecheck trace $end\n$version statecheck {} $end\n$timescale {scale} $end",
            env!("CARGO_PKG_VERSION")
        );
        // An instance of a composite component (`storage.feeder.cyl`) sits in one scope per
        // component instance on its path, shared by its siblings.
        let mut parents: Vec<&str> = Vec::new();
        for (i, inst) in views.instances.iter().enumerate() {
            let inst = &inst.name;
            let path: Vec<&str> = inst.split('.').collect();
            let (up, leaf) = path.split_at(path.len() - 1);
            let common = parents.iter().zip(up).take_while(|(a, b)| a == b).count();
            while parents.len() > common {
                parents.pop();
                let _ = writeln!(out, "$upscope $end");
            }
            for p in &up[common..] {
                let _ = writeln!(out, "$scope module {} $end", vcd_name(p));
                parents.push(p);
            }
            let _ = writeln!(out, "$scope module {} $end", vcd_name(leaf[0]));
            let prefix = format!("{inst}.");
            for v in views.vars.iter().filter(|v| v.name.starts_with(&prefix)) {
                let id = ident(sigs.len());
                let local = vcd_name(&v.name[prefix.len()..]);
                if v.is_bool {
                    let _ = writeln!(out, "$var wire 1 {id} {local} $end");
                } else {
                    let _ = writeln!(out, "$var integer 64 {id} {local} $end");
                }
                sigs.push((
                    id,
                    Sig::Var {
                        slot: v.slot,
                        is_bool: v.is_bool,
                    },
                ));
            }
            for (name, slot) in views.events.iter().filter(|(n, _)| n.starts_with(&prefix)) {
                let id = ident(sigs.len());
                let _ = writeln!(
                    out,
                    "$var wire 1 {id} {} $end",
                    vcd_name(&name[prefix.len()..])
                );
                sigs.push((id, Sig::Event(*slot)));
            }
            // States as a scope tree mirroring the hierarchy: `states.Go.GoLeft` is the wire
            // `GoLeft` in scope `Go` in scope `states` (the wire `Go` sits beside scope `Go`).
            let _ = writeln!(out, "$scope module states $end");
            let mut open: Vec<String> = Vec::new();
            for s in &views.instances[i].states {
                let (path, e) = (&s.path, &s.active);
                let parts: Vec<&str> = path.split('.').collect();
                let (parent, leaf) = parts.split_at(parts.len() - 1);
                let common = open
                    .iter()
                    .zip(parent)
                    .take_while(|(a, b)| a.as_str() == **b)
                    .count();
                while open.len() > common {
                    open.pop();
                    let _ = writeln!(out, "$upscope $end");
                }
                for p in &parent[common..] {
                    let _ = writeln!(out, "$scope module {} $end", vcd_name(p));
                    open.push((*p).to_string());
                }
                let id = ident(sigs.len());
                let _ = writeln!(out, "$var wire 1 {id} {} $end", vcd_name(leaf[0]));
                sigs.push((id, Sig::State(*e)));
            }
            for _ in open {
                let _ = writeln!(out, "$upscope $end");
            }
            let _ = writeln!(out, "$upscope $end\n$upscope $end");
        }
        for _ in parents {
            let _ = writeln!(out, "$upscope $end");
        }
        let _ = writeln!(out, "$enddefinitions $end");
        let last = vec![None; sigs.len()];
        (
            Stream {
                p,
                sigs,
                last,
                last_tick: None,
                units,
            },
            out,
        )
    }

    /// The value changes of one tick.
    pub fn tick(&mut self, tick: u64, slots: &[i64]) -> String {
        let mut changes = String::new();
        for (k, (id, sig)) in self.sigs.iter().enumerate() {
            let (v, bit) = match sig {
                Sig::Var { slot, is_bool } => (slots[*slot as usize], *is_bool),
                Sig::Event(slot) => (slots[*slot as usize], true),
                Sig::State(e) => (eval(&self.p.nodes, slots, *e).unwrap_or(0), true),
            };
            if self.last[k] == Some(v) {
                continue;
            }
            self.last[k] = Some(v);
            if bit {
                let _ = writeln!(changes, "{}{id}", if v != 0 { 1 } else { 0 });
            } else {
                let _ = writeln!(changes, "b{:b} {id}", v);
            }
        }
        self.last_tick = Some(tick);
        if changes.is_empty() && tick != 0 {
            return changes;
        }
        format!("#{}\n{changes}", tick as i64 * self.units)
    }

    /// The end of the last tick (call once after it).
    pub fn finish(&mut self) -> String {
        self.last_tick
            .map(|t| format!("#{}\n", (t as i64 + 1) * self.units))
            .unwrap_or_default()
    }
}
