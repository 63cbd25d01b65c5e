//! The stored state graph the temporal engines work on: a Kripke structure whose nodes are
//! the **positions** of runs (the state after a tick, with the letter of atoms the tick made
//! true; `statecheck_ir::temporal`). Atoms may read the tick's inputs, so one state can give
//! several positions; successors depend on the state alone.
//!
//! Built breadth-first with the IR interpreter and the same input enumeration and `assume`
//! handling as the safety search (`statecheck_ir::assume`). States are stored bit-packed in one flat
//! vector with a hash index; every edge keeps the first input vector (in enumeration order)
//! that realises it, so a path is a scenario. Memory: the packed state, its index entry
//! (about 40 bytes), 16 bytes per node and 8 bytes per distinct edge.

use crate::pack::Packer;
use statecheck_ir::assume::InputSpace;
use statecheck_ir::{ExprId, Machine, Prepared, Program};
use std::collections::HashMap;
use std::time::{Duration, Instant};

/// Limits of a graph construction.
#[derive(Clone, Copy, Debug, Default)]
pub struct GraphLimits {
    /// Most states.
    pub max_states: Option<u64>,
    /// Most bytes of graph.
    pub max_memory: Option<u64>,
    /// Deadline.
    pub deadline: Option<Instant>,
    /// Most input vectors per tick (`--force` lifts it to `u32::MAX`, the hard cap).
    pub max_branching: Option<u128>,
}

/// Why a construction stopped early.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Stopped {
    /// `--max-states`.
    States,
    /// `--max-memory`.
    Memory,
    /// `--timeout`.
    Time,
    /// Too many input vectors per tick to enumerate.
    Branching,
}

/// The graph of positions.
#[derive(Debug, Default)]
pub struct Kripke {
    /// Words per packed state.
    words: usize,
    /// Packed states, `words` each; state 0 is the initial (pre-tick-0) state.
    states: Vec<u64>,
    /// Each node's state.
    pub node_state: Vec<u32>,
    /// Each node's letter: bit `i` set when atom `i` holds.
    pub node_letter: Vec<u64>,
    /// Each state's first edge in `edges` (one more entry than states).
    edge_start: Vec<u32>,
    /// Edges `(target node, input position)`, grouped by source state.
    edges: Vec<(u32, u32)>,
    /// Each state's BFS parent and the input position that first reached it (state 0: none).
    parent: Vec<(u32, u32)>,
    /// States where the `assume`s allow no input vector (deadlocks), in discovery order.
    pub deadlocks: Vec<u32>,
    /// Transitions that stopped with a run-time error (no successor).
    pub errors: u64,
    /// Transitions taken.
    pub transitions: u64,
    /// Time to build.
    pub time: Duration,
}

impl Kripke {
    /// Number of states (including the pre-tick-0 state 0).
    pub fn n_states(&self) -> usize {
        self.edge_start.len().saturating_sub(1)
    }

    /// Number of nodes (positions).
    pub fn n_nodes(&self) -> usize {
        self.node_state.len()
    }

    /// Edges out of state `s`: `(node, input position)`.
    #[inline]
    pub fn state_edges(&self, s: u32) -> &[(u32, u32)] {
        let a = self.edge_start[s as usize] as usize;
        let b = self.edge_start[s as usize + 1] as usize;
        &self.edges[a..b]
    }

    /// Edges out of node `n`.
    #[inline]
    pub fn succ(&self, n: u32) -> &[(u32, u32)] {
        self.state_edges(self.node_state[n as usize])
    }

    /// Edges from the initial state: the positions after tick 0.
    pub fn initial(&self) -> &[(u32, u32)] {
        self.state_edges(0)
    }

    /// The packed words of state `s`.
    pub fn packed(&self, s: u32) -> &[u64] {
        let w = self.words;
        &self.states[s as usize * w..s as usize * w + w]
    }

    /// Input positions of a shortest scenario from the initial state to state `s`.
    pub fn path_to(&self, s: u32) -> Vec<u32> {
        let mut out = Vec::new();
        let mut cur = s;
        while cur != 0 {
            let Some(&(p, inp)) = self.parent.get(cur as usize) else {
                break;
            };
            out.push(inp);
            cur = p;
        }
        out.reverse();
        out
    }

    /// Bytes held.
    pub fn bytes(&self) -> u64 {
        (self.states.len() * 8
            + self.node_state.len() * 12
            + self.edge_start.len() * 4
            + self.edges.len() * 8
            + self.parent.len() * 8) as u64
    }
}

/// Build the graph of `program`, with the letters of `atoms` (at most 64).
pub fn build(program: &Program, atoms: &[ExprId], limits: GraphLimits) -> Result<Kripke, Stopped> {
    match build_partial(program, atoms, limits) {
        (g, None) => Ok(g),
        (_, Some(why)) => Err(why),
    }
}

/// [`build`], keeping what was built when a limit stops it: the states expanded so far have
/// all their edges, the others (found but not expanded) none. Every path and cycle of such a
/// graph is one of the system, so a lasso found in it is a real counterexample (early
/// accepting-cycle detection); an absence proves nothing. The reason is `Some` when stopped.
pub fn build_partial(
    program: &Program,
    atoms: &[ExprId],
    limits: GraphLimits,
) -> (Kripke, Option<Stopped>) {
    let start = Instant::now();
    let mut space = InputSpace::new(program);
    space.solve_static(program);
    let per_tick = space.per_tick();
    if per_tick > u128::from(u32::MAX) || limits.max_branching.is_some_and(|m| per_tick > m) {
        return (Kripke::default(), Some(Stopped::Branching));
    }
    // The limits are read before expanding one state in `every`: each expansion steps up to
    // `per_tick` input vectors, so with wide inputs a fixed 1024 states between readings ran
    // minutes past `--timeout` (4·10^8 ticks with 420,000 vectors per state).
    let every = (65_536 / per_tick.max(1)).clamp(1, 1024) as u32;
    let packer = Packer::new(program);
    let words = packer.words.max(1);
    let mut m = Machine::new(program);
    let prepared =
        |ids: &[ExprId]| -> Vec<Prepared> { ids.iter().map(|&e| program.prepare(e)).collect() };
    let atom_code = prepared(atoms);
    let state_assumes = prepared(&space.state_assumes);
    let mut per_tick = prepared(&space.mixed_assumes);
    if space.listed().is_none() {
        per_tick.extend(prepared(&space.input_assumes));
    }
    let mut g = Kripke {
        words,
        edge_start: vec![0],
        parent: vec![(0, 0)],
        ..Kripke::default()
    };
    let mut index: HashMap<Box<[u64]>, u32> = HashMap::new();
    let mut node_index: HashMap<(u32, u64), u32> = HashMap::new();
    let mut scratch = vec![0u64; words];
    let init: Vec<i64> = m.state().to_vec();
    packer.pack_words(&init, &mut scratch);
    index.insert(scratch.clone().into_boxed_slice(), 0);
    g.states.extend_from_slice(&scratch);
    let mut state = vec![0i64; program.n_state];
    let mut inp = vec![0i64; space.slots.len()];
    let n_inp = space.slots.len();
    let mut seen_here: Vec<u32> = Vec::new();
    let mut s = 0u32;
    while (s as usize) < g.states.len() / words {
        if s.is_multiple_of(every) {
            let stop = if limits.max_states.is_some_and(|k| index.len() as u64 > k) {
                Some(Stopped::States)
            } else if limits
                .max_memory
                .is_some_and(|k| g.bytes() + index.len() as u64 * (40 + 8 * words as u64) > k)
            {
                Some(Stopped::Memory)
            } else if limits.deadline.is_some_and(|d| Instant::now() >= d) {
                Some(Stopped::Time)
            } else {
                None
            };
            if let Some(why) = stop {
                // The unexpanded states keep no edges.
                while g.edge_start.len() <= g.states.len() / words {
                    g.edge_start.push(g.edges.len() as u32);
                }
                g.time = start.elapsed();
                return (g, Some(why));
            }
        }
        packer.unpack_words(g.packed(s), &mut state);
        seen_here.clear();
        let mut any = false;
        m.load_state(&state);
        let allowed_here = state_assumes.iter().all(|a| m.holds(*a));
        let count = if allowed_here {
            space.per_tick() as u64
        } else {
            0
        };
        if space.listed().is_none() {
            space.first(&mut inp);
        }
        for idx in 0..count {
            match space.listed() {
                Some((flat, _)) => {
                    let i = idx as usize;
                    m.load(&state, &flat[i * n_inp..i * n_inp + n_inp]);
                }
                None => {
                    m.load(&state, &inp);
                    space.advance(&mut inp);
                }
            }
            if !per_tick.iter().all(|a| m.holds(*a)) {
                continue;
            }
            any = true;
            g.transitions += 1;
            if m.step().is_err() {
                g.errors += 1;
                continue;
            }
            let mut letter = 0u64;
            for (k, a) in atom_code.iter().enumerate() {
                if m.holds(*a) {
                    letter |= 1 << k;
                }
            }
            packer.pack_words(m.state(), &mut scratch);
            let next = g.states.len() / words;
            let t = *index
                .entry(scratch.clone().into_boxed_slice())
                .or_insert(next as u32);
            if t as usize == next {
                g.states.extend_from_slice(&scratch);
                g.parent.push((s, idx as u32));
            }
            let nn = g.node_state.len() as u32;
            let node = *node_index.entry((t, letter)).or_insert(nn);
            if node == nn {
                g.node_state.push(t);
                g.node_letter.push(letter);
            }
            if !seen_here.contains(&node) {
                seen_here.push(node);
                g.edges.push((node, idx as u32));
            }
        }
        if !any && s != 0 {
            g.deadlocks.push(s);
        }
        g.edge_start.push(g.edges.len() as u32);
        s += 1;
    }
    g.time = start.elapsed();
    (g, None)
}

/// The input vector at position `idx` of the enumeration.
pub fn input_vector(program: &Program, idx: u32) -> Vec<i64> {
    let mut space = InputSpace::new(program);
    space.solve_static(program);
    space.vector(u128::from(idx))
}
