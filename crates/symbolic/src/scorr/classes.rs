//! Candidate equivalence classes of AIG variables, refined by counterexample values.
//!
//! Each class lists its members by increasing variable number with a phase relative to the
//! first member, its representative: member `v` with phase `p` is claimed to equal the
//! representative's value xor `p`. Variable 0 (the constant false) may be a representative, so
//! "this node is constant" is a class like any other. Singletons are dropped.

/// A member of a class: its variable and its phase relative to the representative.
pub(crate) type Member = (u32, bool);

/// Candidate classes.
#[derive(Clone, Debug, Default)]
pub(crate) struct Classes {
    classes: Vec<Vec<Member>>,
}

impl Classes {
    /// Classes of the candidates with equal keys; `key(v)` gives a hash of `v`'s normalized
    /// signature and the phase that normalizes it. `cands` must be sorted by variable.
    pub(crate) fn from_keys(cands: &[u32], key: impl Fn(u32) -> (u64, bool)) -> Classes {
        let mut by_key: std::collections::HashMap<u64, usize> = std::collections::HashMap::new();
        let mut classes: Vec<Vec<Member>> = Vec::new();
        for &v in cands {
            let (k, phase) = key(v);
            match by_key.get(&k) {
                Some(&c) => {
                    let rep_phase = classes[c][0].1;
                    classes[c].push((v, phase ^ rep_phase));
                }
                None => {
                    by_key.insert(k, classes.len());
                    // The representative's phase is kept here until every member is in.
                    classes.push(vec![(v, phase)]);
                }
            }
        }
        for c in &mut classes {
            c[0].1 = false;
        }
        classes.retain(|c| c.len() > 1);
        Classes { classes }
    }

    /// The classes.
    pub(crate) fn iter(&self) -> impl Iterator<Item = &[Member]> {
        self.classes.iter().map(Vec::as_slice)
    }

    /// Every claimed equality `(member, representative, phase)`.
    pub(crate) fn pairs(&self) -> Vec<(u32, u32, bool)> {
        self.classes
            .iter()
            .flat_map(|c| c[1..].iter().map(move |&(v, p)| (v, c[0].0, p)))
            .collect()
    }

    /// Number of members that are not representatives (the nodes a merge removes).
    pub(crate) fn merged(&self) -> usize {
        self.classes.iter().map(|c| c.len() - 1).sum()
    }

    /// The representative and phase of every variable below `n` (`None`: not merged).
    pub(crate) fn repr_map(&self, n: usize) -> Vec<Option<(u32, bool)>> {
        let mut m = vec![None; n];
        for c in &self.classes {
            for &(v, p) in &c[1..] {
                m[v as usize] = Some((c[0].0, p));
            }
        }
        m
    }

    /// Split every class by the values `value(v)` of one sample (xor the member's phase);
    /// true when some class was split. (The engine refines by 64 samples at once,
    /// [`Classes::refine_lanes`]; this is its specification.)
    #[cfg(test)]
    pub(crate) fn refine(&mut self, value: impl Fn(u32) -> bool) -> bool {
        let mut out: Vec<Vec<Member>> = Vec::with_capacity(self.classes.len());
        let mut changed = false;
        for c in std::mem::take(&mut self.classes) {
            let rv = value(c[0].0);
            let (same, other): (Vec<Member>, Vec<Member>) =
                c.into_iter().partition(|&(v, p)| value(v) ^ p == rv);
            if !other.is_empty() {
                changed = true;
                let p0 = other[0].1;
                let other: Vec<Member> = other.into_iter().map(|(v, p)| (v, p ^ p0)).collect();
                if other.len() > 1 {
                    out.push(other);
                }
            }
            if same.len() > 1 {
                out.push(same);
            }
        }
        self.classes = out;
        changed
    }

    /// [`Classes::refine`] by up to 64 samples at once: bit `b` of `value(v)` is `v`'s value
    /// in sample `b`, and only the samples of the bits set in `lanes` count. The classes end
    /// as after one `refine` per sample (members are equal in every sample, up to their phase,
    /// exactly when their masked words are), in one pass instead of one per sample.
    pub(crate) fn refine_lanes(&mut self, value: impl Fn(u32) -> u64, lanes: u64) -> bool {
        let mut out: Vec<Vec<Member>> = Vec::with_capacity(self.classes.len());
        let mut changed = false;
        for c in std::mem::take(&mut self.classes) {
            let key = |&(v, p): &Member| (value(v) ^ if p { !0 } else { 0 }) & lanes;
            let k0 = key(&c[0]);
            if c.iter().all(|m| key(m) == k0) {
                out.push(c);
                continue;
            }
            changed = true;
            let mut keyed: Vec<(u64, Member)> = c.iter().map(|m| (key(m), *m)).collect();
            // Stable: each group keeps its members in increasing variable order, so its first
            // member (its new representative) is its smallest.
            keyed.sort_by_key(|&(k, _)| k);
            for group in keyed.chunk_by(|a, b| a.0 == b.0) {
                if group.len() > 1 {
                    let p0 = group[0].1 .1;
                    out.push(group.iter().map(|&(_, (v, p))| (v, p ^ p0)).collect());
                }
            }
        }
        self.classes = out;
        changed
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classes_group_equal_keys_with_phases_and_split_on_a_sample() {
        // Keys: 1 and 3 equal, 2 their complement, 4 alone.
        let keys = |v: u32| match v {
            1 | 3 => (7, false),
            2 => (7, true),
            _ => (9, false),
        };
        let mut c = Classes::from_keys(&[1, 2, 3, 4], keys);
        assert_eq!(c.pairs(), vec![(2, 1, true), (3, 1, false)]);
        assert_eq!(c.merged(), 2);
        // A sample with 1 = 1, 2 = 0 (consistent: 2 = !1), 3 = 0 (inconsistent with 3 = 1).
        let changed = c.refine(|v| v == 1);
        assert!(changed);
        assert_eq!(c.pairs(), vec![(2, 1, true)]);
        assert!(!c.refine(|v| v == 1));
    }

    /// `refine_lanes` against one `refine` per lane, on random classes and samples: the same
    /// claimed equalities (as a set) after each.
    #[test]
    fn refining_by_lanes_equals_refining_lane_by_lane() {
        let mut seed = 0x1234_5678_9abc_def0_u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        for _ in 0..200 {
            let n = 1 + (next() % 40) as u32;
            let cands: Vec<u32> = (1..=n).collect();
            let keys: Vec<(u64, bool)> = (0..=n).map(|_| (next() % 4, next() % 2 == 1)).collect();
            let mut a = Classes::from_keys(&cands, |v| keys[v as usize]);
            let mut b = a.clone();
            // Values biased towards few distinct words, so that some classes survive.
            let words: Vec<u64> = (0..=n)
                .map(|_| match next() % 3 {
                    0 => 0,
                    1 => !0,
                    _ => next() & next() & next(),
                })
                .collect();
            let lanes = next() | 1;
            let changed_a = a.refine_lanes(|v| words[v as usize], lanes);
            let mut changed_b = false;
            for lane in (0..64).filter(|l| lanes >> l & 1 == 1) {
                changed_b |= b.refine(|v| words[v as usize] >> lane & 1 == 1);
            }
            assert_eq!(changed_a, changed_b);
            let mut pa = a.pairs();
            let mut pb = b.pairs();
            pa.sort_unstable();
            pb.sort_unstable();
            assert_eq!(pa, pb);
        }
    }
}
