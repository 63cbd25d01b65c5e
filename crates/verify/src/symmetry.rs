//! Symmetry on the SAT side (`verify --symmetry`): of each family of element properties
//! (`a[0].p`, `a[1].p`, …, [`statecheck_ir::symmetry::Group::families`]) the SAT engines
//! check one member, the *representative* (the selected member of the lowest element, `a[0].p`
//! when all are selected), and every other selected member gets its verdict.
//!
//! Why that is sound (docs/verification.md, "Symmetry reduction"): with π the exchange of
//! elements 0 and k, the step commutes with π and the initial state is fixed by it, so π maps
//! runs to runs, and member k is member 0 read through π (P_k = P_0 ∘ π). Member 0 proved
//! (no reachable state violates it) makes member k proved; a run violating member 0 (or
//! reaching its target) at tick t, with elements 0 and k exchanged at every tick
//! ([`Group::exchange_inputs`]), violates member k at tick t; bounded at depth d is bounded
//! at depth d. Before relying on the detection, [`Families::new`] tests it on the step
//! ([`Symmetry::validate`]), as the explicit engine does.
//!
//! Temporal rows are never in a family (families are `invariant`, `reachable` and bounded
//! `respond` properties), so they are checked as they are.

use crate::Meta;
use statecheck_ir::symmetry::{Group, Symmetry};
use statecheck_ir::verdict::PropResult;
use statecheck_ir::Program;
use std::sync::Arc;

/// How the detection is tested before a SAT run relies on it: random runs, ticks per run
/// (the explicit engine's figures).
const VALIDATE: (usize, usize) = (8, 64);

/// A row answered from its family's representative.
#[derive(Clone, Debug)]
struct Derived {
    /// The representative's row.
    rep: usize,
    /// The array (index into [`Symmetry::groups`]).
    group: usize,
    /// The representative's element.
    from: usize,
    /// This row's element.
    to: usize,
}

/// The rows of one run that the SAT engines answer by symmetry.
#[derive(Clone, Debug, Default)]
pub(crate) struct Families {
    sym: Option<Arc<Symmetry>>,
    /// Per row: `Some` when the row is answered from its representative.
    derived: Vec<Option<Derived>>,
    /// Per row: the rows answered from it.
    followers: Vec<Vec<usize>>,
    /// Per row: its name (for the derived results).
    names: Vec<String>,
    /// Why the reduction was asked for but not used.
    pub note: Option<String>,
}

impl Families {
    /// The families among `rows` (the run's row names, in report order) of the symmetric
    /// arrays `sym` of `p`: empty without `sym`, without a family with two selected members,
    /// or when the step does not pass [`Symmetry::validate`] (then [`Families::note`] says
    /// why).
    pub fn new(p: &Program, sym: Option<&Arc<Symmetry>>, rows: &[&str]) -> Families {
        let n = rows.len();
        let mut out = Families {
            derived: vec![None; n],
            followers: vec![Vec::new(); n],
            names: rows.iter().map(|r| r.to_string()).collect(),
            ..Families::default()
        };
        let Some(sym) = sym else {
            return out;
        };
        let row_of: std::collections::BTreeMap<&str, usize> =
            rows.iter().enumerate().map(|(i, &r)| (r, i)).collect();
        let mut any = false;
        for (g, group) in sym.groups.iter().enumerate() {
            for fam in &group.families {
                // (element, row) of each selected member, in element order.
                let members: Vec<(usize, usize)> = fam
                    .iter()
                    .enumerate()
                    .filter_map(|(e, &q)| {
                        let name = p.properties.get(q)?.name.as_str();
                        Some((e, *row_of.get(name)?))
                    })
                    .collect();
                let Some((&(from, rep), rest)) = members.split_first() else {
                    continue;
                };
                for &(to, row) in rest {
                    out.derived[row] = Some(Derived {
                        rep,
                        group: g,
                        from,
                        to,
                    });
                    out.followers[rep].push(row);
                    any = true;
                }
            }
        }
        if !any {
            return out;
        }
        if let Err(why) = sym.validate(p, VALIDATE.0, VALIDATE.1, random_inputs(p)) {
            return Families {
                note: Some(format!("symmetry reduction off: {why}")),
                derived: vec![None; n],
                followers: vec![Vec::new(); n],
                ..out
            };
        }
        out.sym = Some(Arc::clone(sym));
        out
    }

    /// [`Families::new`] for the rows named `rows`, with the flag of every derived row raised
    /// (one flag per row), so that no engine schedules it.
    pub fn raising(
        p: &Program,
        sym: Option<&Arc<Symmetry>>,
        rows: &[&str],
        flags: &[Arc<std::sync::atomic::AtomicBool>],
    ) -> Families {
        let families = Families::new(p, sym, rows);
        for (i, f) in flags.iter().enumerate() {
            if families.is_derived(i) {
                f.store(true, std::sync::atomic::Ordering::Relaxed);
            }
        }
        families
    }

    /// Is row `i` answered from its representative (so no engine needs to check it)?
    pub fn is_derived(&self, i: usize) -> bool {
        self.derived.get(i).is_some_and(Option::is_some)
    }

    /// The rows answered from row `i`.
    pub fn followers(&self, i: usize) -> &[usize] {
        self.followers.get(i).map_or(&[], Vec::as_slice)
    }

    /// Row `k`'s result from its representative's result `rep` and metadata `meta`: the same
    /// verdict and depth, the counterexample with the two elements exchanged at every tick,
    /// and the metadata naming the representative (`symmetry_of`). `None` when `k` is not
    /// derived.
    pub fn derive(&self, k: usize, rep: &PropResult, meta: &Meta) -> Option<(PropResult, Meta)> {
        let d = self.derived.get(k)?.as_ref()?;
        let group: &Group = self.sym.as_ref()?.groups.get(d.group)?;
        let counterexample = rep.counterexample.as_ref().map(|run| {
            run.iter()
                .map(|v| group.exchange_inputs(v, d.from, d.to))
                .collect()
        });
        let result = PropResult {
            name: self.names[k].clone(),
            counterexample,
            ..rep.clone()
        };
        let meta = Meta {
            symmetry_of: Some(self.names[d.rep].clone()),
            // The representative's check is the only one made.
            time_s: meta.time_s.map(|_| 0.0),
            ..meta.clone()
        };
        Some((result, meta))
    }
}

/// Random input vectors for [`Symmetry::validate`]: every free input drawn in its range.
fn random_inputs(p: &Program) -> impl FnMut(u64) -> Vec<i64> + '_ {
    move |seed| {
        let mut x = seed | 1;
        p.inputs
            .iter()
            .map(|inp| {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                let s = &p.slots[inp.slot as usize];
                let width = (s.hi - s.lo).unsigned_abs().saturating_add(1);
                s.lo + (x % width) as i64
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    impl Families {
        /// Does any row get its answer by symmetry?
        fn any(&self) -> bool {
            self.derived.iter().any(Option::is_some)
        }
    }

    fn program(src: &str, system: &str) -> (Program, Symmetry) {
        let file = statecheck_syntax::parse(src).0;
        let (model, diags) = statecheck_model::check(&file);
        assert!(!diags.iter().any(|d| d.is_error()), "{diags:?}");
        let sys = model
            .systems
            .iter()
            .find(|s| s.name == system)
            .expect("system");
        let p = statecheck_ir::lower(&model, sys).expect("lowers");
        let found = statecheck_ir::symmetry::detect(sys, &p);
        assert!(found.diagnostics.is_empty(), "{:?}", found.diagnostics);
        (p, found.symmetry)
    }

    const COUNTERS: &str = "chart Counter {
        input event inc;
        output c: int[0..2] = 0;
        initial S;
        state S { on inc / { c = (c + 1) % 3; }; }
        invariant below: c != 2;
      }
      system Counters { instance a[3]: Counter; }";

    /// Rows `a[0].below`, `a[1].below`, `a[2].below` (then the built-ins): the first is the
    /// representative, the other two follow it; a selection without `a[0].below` makes
    /// `a[1].below` the representative.
    #[test]
    fn the_lowest_selected_member_represents_its_family() {
        let (p, sym) = program(COUNTERS, "Counters");
        let sym = Arc::new(sym);
        let rows = [
            "a[0].below",
            "a[1].below",
            "a[2].below",
            "no_range_overflow",
        ];
        let f = Families::new(&p, Some(&sym), &rows);
        assert!(f.note.is_none());
        assert_eq!(
            (0..4).map(|i| f.is_derived(i)).collect::<Vec<_>>(),
            [false, true, true, false]
        );
        assert_eq!(f.followers(0), [1, 2]);
        let f = Families::new(&p, Some(&sym), &["a[1].below", "a[2].below"]);
        assert_eq!(f.followers(0), [1]);
        // One member selected, or no symmetry asked for: nothing is derived.
        assert!(!Families::new(&p, Some(&sym), &["a[2].below"]).any());
        assert!(!Families::new(&p, None, &rows).any());
    }

    /// A counterexample of `a[0].below` (element 0's `inc` at ticks 1 and 2: the inputs are
    /// one event per element, in element order) becomes one of `a[2].below` with element 2's
    /// `inc` at those ticks, same verdict and depth, named after its own row.
    #[test]
    fn a_derived_counterexample_exchanges_the_two_elements_inputs() {
        let (p, sym) = program(COUNTERS, "Counters");
        let sym = Arc::new(sym);
        let rows = ["a[0].below", "a[1].below", "a[2].below"];
        let f = Families::new(&p, Some(&sym), &rows);
        let rep = PropResult {
            verdict: statecheck_ir::verdict::Verdict::Violated,
            depth: 3,
            counterexample: Some(vec![vec![0, 0, 0], vec![1, 0, 0], vec![1, 1, 0]]),
            ..PropResult::unknown("a[0].below", statecheck_ir::verdict::PropKind::Invariant)
        };
        let meta = Meta {
            engine: "ic3",
            time_s: Some(1.5),
            ..Meta::default()
        };
        let (r, m) = f.derive(2, &rep, &meta).expect("derived");
        assert_eq!(r.name, "a[2].below");
        assert_eq!((r.verdict, r.depth), (rep.verdict, 3));
        assert_eq!(
            r.counterexample,
            Some(vec![vec![0, 0, 0], vec![0, 0, 1], vec![0, 1, 1]])
        );
        assert_eq!(m.symmetry_of.as_deref(), Some("a[0].below"));
        assert_eq!((m.engine, m.time_s), ("ic3", Some(0.0)));
        assert!(f.derive(0, &rep, &meta).is_none(), "the representative");
    }

    /// The guard: a chart whose elements look alike to the detection but are not — here
    /// made by a `Group` that claims the counters' blocks in a wrong order (element 0's
    /// counter paired with element 1's input) — fails validation, and nothing is derived.
    #[test]
    fn a_symmetry_the_step_does_not_respect_is_not_used() {
        let (p, mut sym) = program(COUNTERS, "Counters");
        sym.groups[0].inputs.swap(0, 1);
        let sym = Arc::new(sym);
        let f = Families::new(&p, Some(&sym), &["a[0].below", "a[1].below", "a[2].below"]);
        assert!(!f.any());
        assert!(
            f.note
                .as_deref()
                .is_some_and(|n| n.contains("symmetry reduction off")),
            "{:?}",
            f.note
        );
    }
    /// `--engine bmc|kind|ic3|cegar --symmetry` on the three counters: only `a[0].below` of
    /// the family is given to the engine (no `Working` event for rows 1 and 2); all three are
    /// violated at depth 3 (tick 0 starts the counters, two `inc`s make one 2: ticks 1 and 2),
    /// rows 1 and 2 name `a[0].below`, and each row's counterexample, replayed, ends with its
    /// own element's counter at 2. Without symmetry every row is worked on.
    #[test]
    fn a_sat_engine_checks_one_member_per_family() {
        use crate::{Engine, Event, ExplicitOptions, Options};
        use statecheck_ir::verdict::Verdict;
        let (p, sym) = program(COUNTERS, "Counters");
        let sym = Arc::new(sym);
        for engine in [Engine::Bmc, Engine::Kind, Engine::Ic3, Engine::Cegar] {
            for with in [true, false] {
                let check = ExplicitOptions {
                    depth: Some(6),
                    symmetry: with.then(|| Arc::clone(&sym)),
                    ..ExplicitOptions::default()
                };
                let working = std::sync::Mutex::new(vec![0usize; 6]);
                let events = |e: Event| {
                    if let Event::Working { index, .. } = e {
                        if let Ok(mut w) = working.lock() {
                            w[index] += 1;
                        }
                    }
                };
                let run = crate::verify(&p, &Options::new(engine, check), &events).expect("runs");
                let working = working.into_inner().expect("lock");
                let asked: Vec<bool> = working.iter().map(|&w| w > 0).collect();
                let of: Vec<Option<&str>> =
                    run.meta.iter().map(|m| m.symmetry_of.as_deref()).collect();
                if with {
                    assert_eq!(asked[..3], [true, false, false], "{engine:?}");
                    assert_eq!(of[..3], [None, Some("a[0].below"), Some("a[0].below")]);
                } else {
                    assert_eq!(asked[..3], [true, true, true], "{engine:?}");
                    assert!(of.iter().all(Option::is_none));
                }
                for k in 0..3 {
                    let r = &run.report.results[k];
                    assert_eq!(r.name, format!("a[{k}].below"));
                    assert_eq!((r.verdict, r.depth), (Verdict::Violated, 3), "{engine:?}");
                    let mut m = statecheck_ir::Machine::new(&p);
                    for v in r.counterexample.as_ref().expect("a counterexample") {
                        let s = m.state().to_vec();
                        m.load(&s, v);
                        m.step().expect("no run-time error");
                    }
                    let c = p
                        .slots
                        .iter()
                        .position(|s| s.name == format!("a[{k}].c"))
                        .expect("slot");
                    assert_eq!(m.state()[c], 2, "{engine:?} a[{k}]");
                }
            }
        }
    }
}
