//! "Did you mean" suggestions by edit distance.

/// Names longer than this get no suggestion: nobody mistypes a 200-character identifier, and
/// the comparison costs length × allowed edits per candidate.
pub const MAX_SUGGEST_LEN: usize = 128;

/// The candidate closest to `name` within an edit distance of a third of its length (at least 1;
/// names of one or two characters match only when they differ in case).
/// Swapping two adjacent characters (`levle` for `level`) counts as one edit; empty candidates
/// (the chart's root has an empty path) are never suggested. The cost is bounded: names or
/// candidates longer than [`MAX_SUGGEST_LEN`] characters are not compared, and each comparison
/// only fills the band of the table within the allowed distance.
pub fn closest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<String> {
    let n = name.chars().count();
    if n > MAX_SUGGEST_LEN {
        return None;
    }
    let limit = if n <= 2 { 0 } else { (name.len() / 3).max(1) };
    let a: Vec<char> = name.to_lowercase().chars().collect();
    let ascii = name.is_ascii();
    candidates
        .filter(|c| *c != name && !c.is_empty() && c.len() <= 4 * MAX_SUGGEST_LEN)
        // Lower-casing keeps an ASCII name's length, so a candidate whose length differs by
        // more than the allowed distance is dropped before any allocation (a flattened system
        // has thousands of instance names, and one misspelt connection in a component is
        // checked once per copy).
        .filter(|c| !(ascii && c.is_ascii()) || c.len().abs_diff(n) <= limit)
        .filter_map(|c| {
            let b: Vec<char> = c.to_lowercase().chars().collect();
            distance_within(&a, &b, limit).map(|d| (d, c))
        })
        .min()
        .map(|(_, c)| c.to_string())
}

/// Case-insensitive optimal-string-alignment distance: insertions, deletions, substitutions
/// and transpositions of adjacent characters.
#[cfg(test)]
fn distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.to_lowercase().chars().collect();
    let b: Vec<char> = b.to_lowercase().chars().collect();
    distance_within(&a, &b, a.len().max(b.len())).unwrap_or(usize::MAX)
}

/// The optimal-string-alignment distance of `a` and `b` if it is at most `limit`. Only cells
/// within `limit` of the diagonal can lead to such a distance, so only those are computed
/// (the others count as `limit + 1`).
fn distance_within(a: &[char], b: &[char], limit: usize) -> Option<usize> {
    if a.len().abs_diff(b.len()) > limit {
        return None;
    }
    let far = limit + 1;
    let mut prev2: Vec<usize> = vec![far; b.len() + 1];
    let mut prev: Vec<usize> = (0..=b.len()).map(|j| j.min(far)).collect();
    let mut cur: Vec<usize> = vec![far; b.len() + 1];
    for i in 1..=a.len() {
        let lo = i.saturating_sub(limit).max(1);
        let hi = (i + limit).min(b.len());
        cur.iter_mut().for_each(|c| *c = far);
        cur[0] = i.min(far);
        for j in lo..=hi {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            let mut v = (prev[j] + 1).min(cur[j - 1] + 1).min(prev[j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                v = v.min(prev2[j - 2] + 1);
            }
            cur[j] = v.min(far);
        }
        std::mem::swap(&mut prev2, &mut prev);
        std::mem::swap(&mut prev, &mut cur);
    }
    let d = prev[b.len()];
    (d <= limit).then_some(d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transpositions_are_one_edit() {
        assert_eq!(distance("levle", "level"), 1);
        assert_eq!(distance("strat", "start"), 1);
        assert_eq!(distance("abc", "abc"), 0);
        assert_eq!(distance("", "ab"), 2);
        assert_eq!(
            closest("levle", ["level", "speed"].into_iter()),
            Some("level".into())
        );
        assert_eq!(closest("x", ["g", "y"].into_iter()), None);
        assert_eq!(closest("b", ["", "B"].into_iter()), Some("B".into()));
        assert_eq!(closest("abc", ["", "abd"].into_iter()), Some("abd".into()));
    }

    #[test]
    fn banded_distance_agrees_with_the_full_table() {
        // Every pair over a small alphabet up to length 5, against a plain full-table OSA.
        fn full(a: &[char], b: &[char]) -> usize {
            let mut d = vec![vec![0usize; b.len() + 1]; a.len() + 1];
            for (i, row) in d.iter_mut().enumerate() {
                row[0] = i;
            }
            for (j, cell) in d[0].iter_mut().enumerate() {
                *cell = j;
            }
            for i in 1..=a.len() {
                for j in 1..=b.len() {
                    let cost = usize::from(a[i - 1] != b[j - 1]);
                    d[i][j] = (d[i - 1][j] + 1)
                        .min(d[i][j - 1] + 1)
                        .min(d[i - 1][j - 1] + cost);
                    if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                        d[i][j] = d[i][j].min(d[i - 2][j - 2] + 1);
                    }
                }
            }
            d[a.len()][b.len()]
        }
        let words: Vec<Vec<char>> = (0..=5usize)
            .flat_map(|len| {
                (0..3usize.pow(len as u32)).map(move |mut k| {
                    (0..len)
                        .map(|_| {
                            let c = ['a', 'b', 'c'][k % 3];
                            k /= 3;
                            c
                        })
                        .collect()
                })
            })
            .collect();
        for a in words.iter().step_by(7) {
            for b in &words {
                let d = full(a, b);
                for limit in 0..4 {
                    let want = (d <= limit).then_some(d);
                    assert_eq!(distance_within(a, b, limit), want, "{a:?} {b:?} {limit}");
                }
            }
        }
    }
}
