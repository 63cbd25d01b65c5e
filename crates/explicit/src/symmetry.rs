//! Symmetry reduction: one stored state per orbit of the permutations of interchangeable
//! array elements ([`statecheck_ir::symmetry`] says which), and counterexamples mapped back to
//! concrete runs.
//!
//! A state's canonical form sorts each symmetric array's element blocks (the elements' state
//! slots) lexicographically; the search stores and expands canonical forms only. A path of
//! canonical states is made concrete by replaying it: with `σ` mapping canonical positions to
//! the concrete elements (the identity at the start, where all elements are equal), the
//! concrete input of a tick is the canonical one with element `q`'s inputs given to element
//! `σ(q)`, and after the tick `σ` is composed with the sort that made the successor
//! canonical. A chart property of the elements (a family, one member per element) is
//! answered for all members together: the run that decides one member, with two elements
//! exchanged, decides another.
//!
//! Before a search, the engine tests the detection on the program itself
//! ([`Symmetry::validate`], shared with the SAT engines' reduction); should the detection ever
//! accept an array that the step does not treat alike, the reduction is switched off. The
//! permutations of states and input vectors are the IR's ([`statecheck_ir::symmetry::Group`]).

use crate::expand::decides;
use crate::pack::{Key, Packer};
use crate::props::Spec;
use statecheck_ir::symmetry::Symmetry;
use statecheck_ir::{Machine, Program};
use std::cell::RefCell;

/// One symmetric array, flattened for speed.
#[derive(Clone, Debug)]
struct Block {
    /// Elements.
    n: usize,
    /// State slots per element.
    width: usize,
    /// `slots[i * width + j]`: slot `j` of element `i`.
    slots: Vec<u32>,
}

/// The canonical form of states under a [`Symmetry`].
#[derive(Clone, Debug)]
pub(crate) struct Canon {
    blocks: Vec<Block>,
    /// The arrays as detected: their permutations of states and inputs.
    sym: Symmetry,
    /// Per family: the array (index into the blocks) and its members' indices in the specs
    /// (element order).
    pub families: Vec<(usize, Vec<usize>)>,
}

thread_local! {
    /// Per thread: a copy of the state, the blocks' values, the sort order.
    static SCRATCH: RefCell<(Vec<i64>, Vec<i64>, Vec<usize>)> =
        const { RefCell::new((Vec::new(), Vec::new(), Vec::new())) };
}

impl Canon {
    /// The canonical form for `sym` on `p`; `Ok(None)` when no array is symmetric. Families
    /// are given as spec indices. `Err` (why the reduction is off) when only some members of
    /// a family are checked (`--property a[2].below`): one member alone is not invariant under
    /// the permutations, so a canonical state could hide its violation.
    pub fn new(p: &Program, sym: &Symmetry, specs: &[Spec]) -> Result<Option<Canon>, String> {
        let blocks: Vec<Block> = sym
            .groups
            .iter()
            .map(|g| Block {
                n: g.blocks.len(),
                width: g.blocks[0].len(),
                slots: g.blocks.iter().flatten().copied().collect(),
            })
            .collect();
        if blocks.iter().all(|b| b.n < 2) {
            return Ok(None);
        }
        let spec_of = |q: usize| specs.iter().position(|s| s.name == p.properties[q].name);
        let mut families = Vec::new();
        for (g, gr) in sym.groups.iter().enumerate() {
            for f in &gr.families {
                let members: Vec<Option<usize>> = f.iter().map(|&q| spec_of(q)).collect();
                if members.iter().all(Option::is_some) {
                    families.push((g, members.into_iter().flatten().collect()));
                } else if let Some(q) = f.iter().find(|&&q| spec_of(q).is_some()) {
                    return Err(format!(
                        "symmetry reduction off: `{}` is checked without the other members of its family (check all of them, or none)",
                        p.properties[*q].name
                    ));
                }
            }
        }
        Ok(Some(Canon {
            blocks,
            sym: sym.clone(),
            families,
        }))
    }

    /// Sort the element blocks of `state` in place; `perm` (when given) receives, per array,
    /// the element each canonical position came from.
    fn sort(
        &self,
        state: &mut [i64],
        scratch: &mut Vec<i64>,
        ord: &mut Vec<usize>,
        mut perm: Option<&mut Vec<Vec<usize>>>,
    ) {
        for (g, b) in self.blocks.iter().enumerate() {
            let w = b.width;
            ord.clear();
            ord.extend(0..b.n);
            let key = |i: usize, j: usize| state[b.slots[i * w + j] as usize];
            ord.sort_by(|&x, &y| {
                (0..w)
                    .map(|j| key(x, j).cmp(&key(y, j)))
                    .find(|o| o.is_ne())
                    .unwrap_or(std::cmp::Ordering::Equal)
            });
            if let Some(p) = perm.as_deref_mut() {
                p[g].clone_from(ord);
            }
            if ord.iter().enumerate().all(|(q, &i)| q == i) {
                continue;
            }
            scratch.clear();
            scratch.extend(b.slots.iter().map(|&s| state[s as usize]));
            for (q, &i) in ord.iter().enumerate() {
                for j in 0..w {
                    state[b.slots[q * w + j] as usize] = scratch[i * w + j];
                }
            }
        }
    }

    /// The packed canonical form of `state`.
    #[inline]
    pub fn pack<K: Key>(&self, packer: &Packer, state: &[i64], words: &mut [u64]) -> K {
        SCRATCH.with(|c| {
            let mut c = c.borrow_mut();
            let (s, buf, ord) = &mut *c;
            s.clear();
            s.extend_from_slice(state);
            self.sort(s, buf, ord, None);
            packer.pack(s, words)
        })
    }

    /// Canonicalize in place, returning per array the element of each canonical position.
    fn canonical(&self, state: &mut [i64]) -> Vec<Vec<usize>> {
        let mut perm: Vec<Vec<usize>> = self.blocks.iter().map(|b| (0..b.n).collect()).collect();
        let (mut buf, mut ord) = (Vec::new(), Vec::new());
        self.sort(state, &mut buf, &mut ord, Some(&mut perm));
        perm
    }

    /// The concrete run of a path of canonical states given by its canonical input vectors
    /// from the initial state (see the module documentation).
    pub fn concretize(&self, p: &Program, path: &[Vec<i64>]) -> Vec<Vec<i64>> {
        let mut m = Machine::new(p);
        let mut state = m.state().to_vec();
        let mut sigma = self.canonical(&mut state);
        let mut out = Vec::with_capacity(path.len());
        for v in path {
            out.push(self.sym.permute_inputs(v, &sigma));
            m.load(&state, v);
            if m.step().is_err() {
                break;
            }
            state.copy_from_slice(m.state());
            let p2 = self.canonical(&mut state);
            // σ' = σ ∘ p': canonical position q came from p'[q], which σ sends to σ[p'[q]].
            sigma = sigma
                .iter()
                .zip(&p2)
                .map(|(s, pp)| pp.iter().map(|&x| s[x]).collect())
                .collect();
        }
        out
    }

    /// Does replaying `run` from the initial state end with `spec` decided?
    pub fn decides_at_end(p: &Program, run: &[Vec<i64>], spec: &Spec) -> bool {
        let mut m = Machine::new(p);
        for v in run {
            let s = m.state().to_vec();
            m.load(&s, v);
            if m.step().is_err() {
                return false;
            }
        }
        decides(&mut m, spec.check)
    }

    /// A run deciding member `k` of family `fam` from one deciding another: `run` with element
    /// `k` exchanged with each element in turn, the first that replays to a decision.
    pub fn member_run(
        &self,
        p: &Program,
        run: &[Vec<i64>],
        (g, fam): (usize, &[usize]),
        k: usize,
        specs: &[Spec],
    ) -> Option<Vec<Vec<i64>>> {
        let group = &self.sym.groups[g];
        (0..fam.len()).find_map(|e| {
            let r: Vec<Vec<i64>> = run.iter().map(|v| group.exchange_inputs(v, e, k)).collect();
            Self::decides_at_end(p, &r, &specs[fam[k]]).then_some(r)
        })
    }

    /// Test the symmetry on the step itself ([`Symmetry::validate`]) along `runs` random runs
    /// of `len` ticks over the input vectors `vector(i)`, `i < count`.
    pub fn validate(
        &self,
        p: &Program,
        count: u128,
        vector: impl Fn(u128) -> Vec<i64>,
        runs: usize,
        len: usize,
    ) -> Result<(), String> {
        if count == 0 {
            return Ok(());
        }
        self.sym
            .validate(p, runs, len, |r| vector(u128::from(r) % count))
    }
}
