//! Symmetry of instance arrays: which arrays' elements are interchangeable in a lowered
//! program, so that a checker may store one state per orbit (docs/verification.md, "Symmetry
//! reduction").
//!
//! The elements of `instance a[N]: C;` are interchangeable when permuting them maps every run
//! to a run and leaves every checked property's answer unchanged. [`detect`] accepts an array
//! only on conditions that make this plain:
//! - every connection into an element comes from outside the array and is made for every
//!   element alike (`connect x.o -> a[*].i`), and no connection reads an element's output
//!   (nothing else can then observe the order in which the elements run, rule R2);
//! - no observer is in the system (an observer may read any element);
//! - no `assume` reads an element's input or state;
//! - every property either reads no element, or is a chart property of the elements
//!   (`a[k].p`, one per element: a *family*, whose members the checker answers together);
//! - the elements' slots correspond one to one (same roles, ranges and initial values).
//!
//! Temporal properties are not reduced (the explicit engine's temporal search runs on the
//! full state space, the SAT engines check every temporal row as it is), so they do not
//! restrict the symmetry. Everything else breaks symmetry
//! with a diagnostic naming what breaks it: W0316 for a connection, W0317 for a property, an
//! assume or an observer, W0318 when the elements' slots do not correspond.
//!
//! The permutations themselves are here too, for every engine that uses the symmetry: a
//! permutation of one array's elements acting on a state ([`Group::permute_state`]) and on an
//! input vector ([`Group::permute_inputs`]; [`Group::exchange_inputs`] maps a run deciding one
//! member of a family to a run deciding another), and [`Symmetry::validate`], the test of
//! the detection on the step itself that an engine runs before it relies on it.

use crate::interp::Machine;
use crate::program::{Node, Program, SlotId, SlotRole};
use statecheck_base::{Diagnostic, Span};
use statecheck_model::System;
use std::collections::{BTreeMap, BTreeSet};

/// Interchangeable element blocks of the arrays of one program.
#[derive(Clone, Debug, Default)]
pub struct Symmetry {
    /// One entry per symmetric array.
    pub groups: Vec<Group>,
}

/// One array whose elements are interchangeable.
#[derive(Clone, Debug)]
pub struct Group {
    /// The array's name (`fams`).
    pub array: String,
    /// Per element (in index order): its persistent state slots, in one order shared by all
    /// elements (`blocks[i][j]` and `blocks[k][j]` play the same role).
    pub blocks: Vec<Vec<SlotId>>,
    /// Per element: positions in [`Program::inputs`] of its free inputs, in a shared order.
    pub inputs: Vec<Vec<usize>>,
    /// Chart properties of the elements: per family, the index in [`Program::properties`] of
    /// each element's member, in element order.
    pub families: Vec<Vec<usize>>,
}

impl Group {
    /// Write into `out` element `q`'s free inputs of the input vector `inputs` (in
    /// [`Program::inputs`] order) at element `sigma[q]`'s positions, for every element; the
    /// other positions of `out` are left as they are (`out` starts as a copy of `inputs`).
    pub fn permute_inputs(&self, inputs: &[i64], sigma: &[usize], out: &mut [i64]) {
        for (q, &to) in sigma.iter().enumerate() {
            for (&at, &dst) in self.inputs[q].iter().zip(&self.inputs[to]) {
                out[dst] = inputs[at];
            }
        }
    }

    /// Write into `out` element `q`'s state block of `state` at element `sigma[q]`'s slots,
    /// for every element; the other slots of `out` are left as they are.
    pub fn permute_state(&self, state: &[i64], sigma: &[usize], out: &mut [i64]) {
        for (q, &to) in sigma.iter().enumerate() {
            for (&at, &dst) in self.blocks[q].iter().zip(&self.blocks[to]) {
                out[dst as usize] = state[at as usize];
            }
        }
    }

    /// The exchange of elements `a` and `b`, as a permutation of the elements.
    pub fn exchange(&self, a: usize, b: usize) -> Vec<usize> {
        (0..self.blocks.len())
            .map(|i| match i {
                _ if i == a => b,
                _ if i == b => a,
                _ => i,
            })
            .collect()
    }

    /// The input vector `inputs` with elements `a` and `b`'s free inputs exchanged. Applied
    /// to every tick of a run that decides family member `a` at some tick, it gives a run
    /// that decides member `b` at the same tick (docs/verification.md, "Symmetry
    /// reduction"): the step commutes with the exchange and the initial state is fixed by it.
    pub fn exchange_inputs(&self, inputs: &[i64], a: usize, b: usize) -> Vec<i64> {
        let mut out = inputs.to_vec();
        self.permute_inputs(inputs, &self.exchange(a, b), &mut out);
        out
    }
}

impl Symmetry {
    /// `inputs` with, per array `g`, element `q`'s free inputs given to element `sigma[g][q]`.
    pub fn permute_inputs(&self, inputs: &[i64], sigma: &[Vec<usize>]) -> Vec<i64> {
        let mut out = inputs.to_vec();
        for (g, s) in self.groups.iter().zip(sigma) {
            g.permute_inputs(inputs, s, &mut out);
        }
        out
    }

    /// `state` with, per array `g`, element `q`'s block moved to element `sigma[g][q]`.
    pub fn permute_state(&self, state: &[i64], sigma: &[Vec<usize>]) -> Vec<i64> {
        let mut out = state.to_vec();
        for (g, s) in self.groups.iter().zip(sigma) {
            g.permute_state(state, s, &mut out);
        }
        out
    }

    /// Test the detection on the step of `p` itself: along `runs` random runs of `len` ticks
    /// from the initial state (tick inputs `vector(r)` for random numbers `r`), stepping each
    /// state permuted with its inputs permuted must give the permuted successor (the same
    /// run-time error, or none) — for the exchange of the first two elements of every array
    /// and for the rotation, which together make every permutation. `Err` describes the
    /// first state where the outcome differed. Also `Err` when the initial state is not
    /// fixed by these permutations.
    pub fn validate(
        &self,
        p: &Program,
        runs: usize,
        len: usize,
        mut vector: impl FnMut(u64) -> Vec<i64>,
    ) -> Result<(), String> {
        let gens: Vec<Vec<Vec<usize>>> = (0..2)
            .map(|kind| {
                self.groups
                    .iter()
                    .map(|g| {
                        let n = g.blocks.len();
                        (0..n)
                            .map(|i| match kind {
                                0 if i < 2 => 1 - i,
                                0 => i,
                                _ => (i + 1) % n,
                            })
                            .collect()
                    })
                    .collect()
            })
            .collect();
        let mut seed = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut m = Machine::new(p);
        let init = m.state().to_vec();
        if gens.iter().any(|g| self.permute_state(&init, g) != init) {
            return Err("the elements' initial states differ".to_string());
        }
        for _ in 0..runs {
            let mut state = init.clone();
            for _ in 0..len {
                let v = vector(next());
                m.load(&state, &v);
                let r = m.step().map(|_| m.state().to_vec());
                for g in &gens {
                    let (ps, pv) = (self.permute_state(&state, g), self.permute_inputs(&v, g));
                    m.load(&ps, &pv);
                    let rp = m.step().map(|_| m.state().to_vec());
                    let same = match (&r, &rp) {
                        (Ok(a), Ok(b)) => self.permute_state(a, g) == *b,
                        (Err(a), Err(b)) => a.kind.builtin() == b.kind.builtin(),
                        _ => false,
                    };
                    if !same {
                        return Err(format!(
                            "the step does not treat the elements alike (state {state:?}, inputs {v:?})"
                        ));
                    }
                }
                match r {
                    Ok(s) => state = s,
                    Err(_) => break,
                }
            }
        }
        Ok(())
    }
}

/// What [`detect`] found: the symmetric arrays, and why the others are not.
#[derive(Clone, Debug, Default)]
pub struct Detection {
    /// The symmetric arrays.
    pub symmetry: Symmetry,
    /// One warning per connection, property, assume or observer that breaks an array's
    /// symmetry (W0316–W0318).
    pub diagnostics: Vec<Diagnostic>,
}

/// A slot's role with its instance left out: what makes two elements' slots correspond.
fn role_key(role: &SlotRole) -> Option<(u32, (u8, u32))> {
    Some(match *role {
        SlotRole::Var { instance, var } => (instance, (0, var)),
        SlotRole::Input { instance, var } => (instance, (1, var)),
        SlotRole::Region { instance, node } => (instance, (2, node)),
        SlotRole::Visited { instance, node } => (instance, (3, node)),
        SlotRole::Timer { instance, state } => (instance, (4, state)),
        SlotRole::Pending { instance, var } => (instance, (5, var)),
        SlotRole::Present { instance, var } => (instance, (6, var)),
        SlotRole::Abort { instance, state } => (instance, (7, state)),
        SlotRole::Started => return None,
        // A monitor belongs to its property: placed with the property's family, if any.
        SlotRole::Monitor { .. } => return None,
    })
}

/// Slots read by expression `e`.
fn reads(p: &Program, e: u32, acc: &mut BTreeSet<SlotId>) {
    let mut stack = vec![e];
    while let Some(e) = stack.pop() {
        match p.nodes[e as usize] {
            Node::Const(_) | Node::Local(_) => {}
            Node::Slot(s) => {
                acc.insert(s);
            }
            Node::Unary(_, a) | Node::Abs(a, _) | Node::Check(a, ..) => stack.push(a),
            Node::Binary(_, a, b, _) | Node::Min(a, b) | Node::Max(a, b) | Node::Let(_, a, b) => {
                stack.extend([a, b])
            }
            Node::Ite(c, a, b) => stack.extend([c, a, b]),
        }
    }
}

/// Find the arrays of `sys` (lowered to `p`) whose elements are interchangeable.
pub fn detect(sys: &System, p: &Program) -> Detection {
    let mut out = Detection::default();
    if sys.instances.len() != p.instances.len()
        || sys
            .instances
            .iter()
            .zip(&p.instances)
            .any(|(a, b)| a.name != b.name)
    {
        return out;
    }
    // Arrays: base name -> element instances in index order.
    let mut arrays: BTreeMap<&str, Vec<(u32, u32)>> = BTreeMap::new();
    for (k, inst) in sys.instances.iter().enumerate() {
        if let (Some(i), Some(base)) = (inst.index, inst.name.split('[').next()) {
            arrays.entry(base).or_default().push((i, k as u32));
        }
    }
    for (name, mut elems) in arrays {
        elems.sort_unstable();
        let elems: Vec<u32> = elems.into_iter().map(|(_, k)| k).collect();
        if elems.len() < 2 {
            continue;
        }
        let (group, diags) = array(sys, p, name, &elems);
        out.diagnostics.extend(diags);
        out.symmetry.groups.extend(group);
    }
    out
}

fn warn(code: &'static str, array: &str, what: String, span: Span, hint: &str) -> Diagnostic {
    Diagnostic::warning(
        code,
        format!("{what} breaks the symmetry of `{array}`: symmetry reduction is off for it"),
        span,
    )
    .with_hint(hint.to_string())
}

/// A connection into elements: its source (instance, variable) and the element input.
type Fanout = ((u32, u32), u32);

/// The symmetry of one array, or the diagnostics saying why it has none.
fn array(sys: &System, p: &Program, name: &str, elems: &[u32]) -> (Option<Group>, Vec<Diagnostic>) {
    let n = elems.len();
    let pos = |inst: u32| elems.iter().position(|&e| e == inst);
    let mut diags = Vec::new();
    // Connections: none out of an element; every one into an element made for all alike.
    let mut fanout: BTreeMap<Fanout, (BTreeSet<usize>, Span)> = BTreeMap::new();
    let mut seen_spans = BTreeSet::new();
    for c in &sys.connections {
        if pos(c.from.0).is_some() {
            if seen_spans.insert((c.span.start, c.span.end)) {
                diags.push(warn(
                    "W0316",
                    name,
                    "a connection that reads an element's output".into(),
                    c.span,
                    "symmetry needs the elements to be connected only from outside the array, by `connect x.out -> arr[*].in;`",
                ));
            }
            continue;
        }
        if let Some(i) = pos(c.to.0) {
            let e = fanout
                .entry(((c.from.0, c.from.1), c.to.1))
                .or_insert((BTreeSet::new(), c.span));
            e.0.insert(i);
        }
    }
    for (elements, span) in fanout.values() {
        if elements.len() != n && seen_spans.insert((span.start, span.end)) {
            diags.push(warn(
                "W0316",
                name,
                "a connection to some elements only".into(),
                *span,
                "connect the same output to every element (`arr[*].in`) for the elements to be interchangeable",
            ));
        }
    }
    for (k, inst) in p.instances.iter().enumerate() {
        if inst.observer {
            diags.push(warn(
                "W0317",
                name,
                format!("observer `{}`", inst.name),
                sys.instances[k].span,
                "an observer may read any element; symmetry reduction runs without observers",
            ));
        }
    }
    // Element blocks of state slots and of free inputs.
    let mut blocks: Vec<Vec<((u8, u32), SlotId)>> = vec![Vec::new(); n];
    for s in 0..p.n_state {
        if let Some((inst, key)) = role_key(&p.slots[s].role) {
            if let Some(i) = pos(inst) {
                blocks[i].push((key, s as SlotId));
            }
        }
    }
    let mut inputs: Vec<Vec<((u8, u32), usize)>> = vec![Vec::new(); n];
    let mut element_slot: BTreeMap<SlotId, usize> = BTreeMap::new();
    for (k, inp) in p.inputs.iter().enumerate() {
        if let Some(i) = pos(inp.instance) {
            inputs[i].push(((1, inp.var), k));
            element_slot.insert(inp.slot, i);
        }
    }
    for (i, b) in blocks.iter().enumerate() {
        for &(_, s) in b {
            element_slot.insert(s, i);
        }
    }
    // Properties: reading no element, or one member of a family of chart properties.
    let prefix = |i: usize| format!("{}.", sys.instances[elems[i] as usize].name);
    let mut families: BTreeMap<String, Vec<Option<usize>>> = BTreeMap::new();
    for (q, prop) in p.properties.iter().enumerate() {
        let mut r = BTreeSet::new();
        for e in prop.goal.exprs() {
            reads(p, e, &mut r);
        }
        let touched: BTreeSet<usize> = r
            .iter()
            .filter_map(|s| element_slot.get(s))
            .copied()
            .collect();
        // A monitor (`respond ... within`) is updated by the step from its trigger and
        // response, which the goal does not show: only an element's own is accepted.
        let monitor = r
            .iter()
            .any(|&s| matches!(p.slots[s as usize].role, SlotRole::Monitor { .. }));
        let member = (0..n).find(|&i| prop.name.starts_with(&prefix(i)));
        match member {
            Some(i) if touched.iter().all(|&t| t == i) => {
                let suffix = prop.name[prefix(i).len()..].to_string();
                families.entry(suffix).or_insert_with(|| vec![None; n])[i] = Some(q);
            }
            _ if touched.is_empty() && !monitor => {}
            _ => diags.push(warn(
                "W0317",
                name,
                format!("property `{}`", prop.name),
                prop.span,
                "a property that names one element (or some) is not invariant under permuting them; state it in the chart (it then holds for every element) or over none",
            )),
        }
    }
    let mut fams = Vec::new();
    for (suffix, members) in families {
        match members.iter().copied().collect::<Option<Vec<usize>>>() {
            Some(m) => fams.push(m),
            None => diags.push(warn(
                "W0317",
                name,
                format!("property `{suffix}` of some elements only"),
                sys.span,
                "a chart property is checked for every element alike",
            )),
        }
    }
    // Monitors of family members belong to their element's block.
    for s in 0..p.n_state {
        if let SlotRole::Monitor { property } = p.slots[s].role {
            for (f, m) in fams.iter().enumerate() {
                if let Some(i) = m.iter().position(|&q| q == property as usize) {
                    blocks[i].push(((8, f as u32), s as SlotId));
                }
            }
        }
    }
    for (k, &a) in p.assumes.iter().enumerate() {
        let mut r = BTreeSet::new();
        reads(p, a, &mut r);
        if r.iter().any(|s| element_slot.contains_key(s)) {
            let span = sys.assumes.get(k).map_or(sys.span, |e| e.span);
            diags.push(warn(
                "W0317",
                name,
                "an `assume` that reads elements".into(),
                span,
                "symmetry reduction needs assumes over the other instances' inputs only",
            ));
        }
    }
    // Corresponding slots: same roles in the same order, same ranges and initial values.
    let shape = |b: &[((u8, u32), SlotId)]| -> Vec<((u8, u32), i64, i64, i64)> {
        b.iter()
            .map(|&(k, s)| {
                let sl = &p.slots[s as usize];
                (k, sl.lo, sl.hi, sl.init)
            })
            .collect()
    };
    let ishape = |b: &[((u8, u32), usize)]| -> Vec<(u8, u32)> { b.iter().map(|x| x.0).collect() };
    let chart = sys.instances[elems[0] as usize].chart;
    if elems
        .iter()
        .any(|&e| sys.instances[e as usize].chart != chart)
        || blocks.iter().any(|b| shape(b) != shape(&blocks[0]))
        || inputs.iter().any(|b| ishape(b) != ishape(&inputs[0]))
    {
        diags.push(warn(
            "W0318",
            name,
            "elements of different charts, or whose state slots do not correspond".into(),
            sys.instances[elems[0] as usize].span,
            "the elements differ in their slots (ranges or initial values): they are not interchangeable",
        ));
    }
    if !diags.is_empty() {
        return (None, diags);
    }
    let group = Group {
        array: name.to_string(),
        blocks: blocks
            .into_iter()
            .map(|b| b.into_iter().map(|x| x.1).collect())
            .collect(),
        inputs: inputs
            .into_iter()
            .map(|b| b.into_iter().map(|x| x.1).collect())
            .collect(),
        families: fams,
    };
    (Some(group), diags)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Three elements of one slot and one input each; the input vector has one more input
    /// (position 3, outside the array) and the state one more slot (3), which no permutation
    /// moves.
    fn group() -> Group {
        Group {
            array: "a".into(),
            blocks: vec![vec![0], vec![1], vec![2]],
            inputs: vec![vec![0], vec![1], vec![2]],
            families: Vec::new(),
        }
    }

    #[test]
    fn exchanging_two_elements_swaps_their_inputs_only() {
        let g = group();
        assert_eq!(g.exchange(0, 2), [2, 1, 0]);
        assert_eq!(g.exchange_inputs(&[10, 20, 30, 40], 0, 2), [30, 20, 10, 40]);
        assert_eq!(g.exchange_inputs(&[10, 20, 30, 40], 1, 1), [10, 20, 30, 40]);
    }

    /// The rotation `sigma = [1, 2, 0]` sends element 0's block to element 1, 1's to 2 and
    /// 2's to 0: `[a, b, c]` becomes `[c, a, b]`.
    #[test]
    fn a_permutation_moves_element_q_to_sigma_q() {
        let sym = Symmetry {
            groups: vec![group()],
        };
        let sigma = [vec![1, 2, 0]];
        assert_eq!(sym.permute_state(&[1, 2, 3, 9], &sigma), [3, 1, 2, 9]);
        assert_eq!(sym.permute_inputs(&[1, 2, 3, 9], &sigma), [3, 1, 2, 9]);
    }
}
