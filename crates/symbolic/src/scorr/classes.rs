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
    /// true when some class was split.
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
}
