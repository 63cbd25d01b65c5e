//! Guards from the explicit engine's result, built only when asked and in time linear in the
//! supervisor: one pass over the kept states files each into the *allowed* or *forbidden*
//! minterm list of every controllable event the plant enables there, and each list becomes a
//! BDD directly ([`crate::build::from_minterms`]); [`Encoding::simplify`] then minimises.

use crate::encode::Encoding;
use crate::explicit::{participants, Explicit};
use crate::limits::Budget;
use crate::problem::{EventId, Problem, NONE};
use crate::{Error, Guard};

/// States between two polls of the budget.
const POLL: usize = 4096;

/// One guard per controllable event, in event order; `Err` when `budget` runs out (polled
/// every [`POLL`] states and inside the simplification).
pub fn explicit_guards(
    p: &Problem,
    x: &Explicit,
    enc: &Encoding,
    budget: &Budget,
) -> Result<Vec<Guard>, Error> {
    let states = x.product_states as f64;
    let n_ev = p.events.len();
    let parts = participants(p);
    let words = enc.minterm_words();
    let mut on: Vec<Vec<u64>> = vec![Vec::new(); n_ev];
    let mut off: Vec<Vec<u64>> = vec![Vec::new(); n_ev];
    let mut locs = vec![0u32; p.automata.len()];
    let mut term = Vec::with_capacity(words);
    let mut allowed = vec![false; n_ev];
    for s in 0..x.kept.len() {
        if !x.kept[s] {
            continue;
        }
        if s % POLL == 0 {
            budget.check("guards", states, 0)?;
        }
        x.locs(s, &mut locs);
        term.clear();
        enc.minterm(&locs, &mut term);
        allowed.fill(false);
        for &(e, t) in x.edges(s) {
            if x.kept[t as usize] {
                allowed[e as usize] = true;
            }
        }
        for e in 0..n_ev {
            if !p.events[e].controllable {
                continue;
            }
            let plant = parts[e]
                .iter()
                .filter(|(_, plant)| *plant)
                .all(|&(a, _)| p.automata[a].next[locs[a] as usize * n_ev + e] != NONE);
            if !plant {
                continue;
            }
            if allowed[e] {
                on[e].extend_from_slice(&term);
            } else {
                off[e].extend_from_slice(&term);
            }
        }
    }
    (0..n_ev)
        .filter(|&e| p.events[e].controllable)
        .map(|e| {
            budget.check("guards", states, 0)?;
            let on = crate::build::from_minterms(&enc.vars, words, &mut on[e]);
            let off = crate::build::from_minterms(&enc.vars, words, &mut off[e]);
            Ok(Guard {
                event: e as EventId,
                allow: enc.simplify_until(&on, &off, budget, states)?,
            })
        })
        .collect()
}
