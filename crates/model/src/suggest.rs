//! "Did you mean" suggestions by edit distance.

/// The candidate closest to `name` within an edit distance of a third of its length (at least 1;
/// names of one or two characters match only when they differ in case).
/// Swapping two adjacent characters (`levle` for `level`) counts as one edit; empty candidates
/// (the chart's root has an empty path) are never suggested.
pub fn closest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<String> {
    let limit = if name.chars().count() <= 2 {
        0
    } else {
        (name.len() / 3).max(1)
    };
    candidates
        .filter(|c| *c != name && !c.is_empty())
        .map(|c| (distance(name, c), c))
        .filter(|(d, _)| *d <= limit)
        .min()
        .map(|(_, c)| c.to_string())
}

/// Case-insensitive optimal-string-alignment distance: insertions, deletions, substitutions
/// and transpositions of adjacent characters.
fn distance(a: &str, b: &str) -> usize {
    let a: Vec<char> = a.to_lowercase().chars().collect();
    let b: Vec<char> = b.to_lowercase().chars().collect();
    let mut prev2: Vec<usize> = Vec::new();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for i in 1..=a.len() {
        let mut cur = vec![i; b.len() + 1];
        for j in 1..=b.len() {
            let cost = usize::from(a[i - 1] != b[j - 1]);
            cur[j] = (prev[j] + 1).min(cur[j - 1] + 1).min(prev[j - 1] + cost);
            if i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] {
                cur[j] = cur[j].min(prev2[j - 2] + 1);
            }
        }
        prev2 = std::mem::replace(&mut prev, cur);
    }
    prev[b.len()]
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
}
