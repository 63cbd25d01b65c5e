//! Strongly connected components of a subgraph (Tarjan's algorithm with an explicit stack),
//! and fair-cycle search with justice and compassion (Streett) constraints by repeated SCC
//! decomposition: a component that meets some compassion trigger but none of its responses
//! loses the trigger's states and is decomposed again (Emerson–Lei; as in NuSMV's fair-EG
//! and in the SCC-based emptiness checks of Couvreur and of Latvala–Heljanko). Each round
//! removes a state, so the search ends; a component left that is non-trivial and meets every
//! acceptance and justice set holds a fair cycle.

/// A set of vertices, as a predicate.
pub type Pred<'a> = &'a dyn Fn(u32) -> bool;

/// An owned vertex predicate.
pub type BoxPred<'a> = Box<dyn Fn(u32) -> bool + 'a>;

/// Reusable arrays indexed by vertex.
pub struct Scratch {
    index: Vec<u32>,
    low: Vec<u32>,
    on_stack: Vec<bool>,
}

const UNSEEN: u32 = u32::MAX;

impl Scratch {
    /// Arrays for `n` vertices.
    pub fn new(n: usize) -> Scratch {
        Scratch {
            index: vec![UNSEEN; n],
            low: vec![0; n],
            on_stack: vec![false; n],
        }
    }
}

/// The SCCs of the subgraph induced by `verts` (`inside(v)` must be true exactly for them),
/// in reverse topological order.
pub fn sccs<'g>(
    verts: &[u32],
    inside: &dyn Fn(u32) -> bool,
    succ: &dyn Fn(u32) -> &'g [u32],
    sc: &mut Scratch,
) -> Vec<Vec<u32>> {
    let mut out = Vec::new();
    let mut counter = 0u32;
    let mut stack: Vec<u32> = Vec::new();
    // Call stack: (vertex, next successor position).
    let mut calls: Vec<(u32, usize)> = Vec::new();
    for &root in verts {
        if sc.index[root as usize] != UNSEEN {
            continue;
        }
        calls.push((root, 0));
        sc.index[root as usize] = counter;
        sc.low[root as usize] = counter;
        counter += 1;
        stack.push(root);
        sc.on_stack[root as usize] = true;
        while let Some(&mut (v, ref mut pos)) = calls.last_mut() {
            let ss = succ(v);
            if *pos < ss.len() {
                let w = ss[*pos];
                *pos += 1;
                if !inside(w) {
                    continue;
                }
                if sc.index[w as usize] == UNSEEN {
                    sc.index[w as usize] = counter;
                    sc.low[w as usize] = counter;
                    counter += 1;
                    stack.push(w);
                    sc.on_stack[w as usize] = true;
                    calls.push((w, 0));
                } else if sc.on_stack[w as usize] {
                    let l = sc.low[v as usize].min(sc.index[w as usize]);
                    sc.low[v as usize] = l;
                }
                continue;
            }
            calls.pop();
            if let Some(&(u, _)) = calls.last() {
                let l = sc.low[u as usize].min(sc.low[v as usize]);
                sc.low[u as usize] = l;
            }
            if sc.low[v as usize] == sc.index[v as usize] {
                let mut comp = Vec::new();
                while let Some(w) = stack.pop() {
                    sc.on_stack[w as usize] = false;
                    comp.push(w);
                    if w == v {
                        break;
                    }
                }
                out.push(comp);
            }
        }
    }
    for &v in verts {
        sc.index[v as usize] = UNSEEN;
    }
    out
}

/// What a fair cycle must meet.
pub struct Fairness<'a> {
    /// Sets to visit infinitely often (Büchi acceptance sets and justice).
    pub visit: &'a [&'a dyn Fn(u32) -> bool],
    /// Compassion pairs: if the first is visited infinitely often, so is the second.
    pub compassion: &'a [(Pred<'a>, Pred<'a>)],
}

/// A set of vertices within which a fair cycle exists (strongly connected, non-trivial, meeting
/// every `visit` set, and for each compassion pair either no trigger or some response), or
/// `None`. `verts` are all vertices of the graph.
pub fn fair_component<'g>(
    verts: &[u32],
    n: usize,
    succ: &dyn Fn(u32) -> &'g [u32],
    fair: &Fairness,
) -> Option<Vec<u32>> {
    let mut sc = Scratch::new(n);
    // Membership of the component being decomposed: vertices with `mark[v] == epoch`.
    let mut mark = vec![0u32; n];
    let mut epoch = 1u32;
    for &v in verts {
        mark[v as usize] = epoch;
    }
    let first = {
        let m = &mark;
        sccs(verts, &|w| m[w as usize] == 1, succ, &mut sc)
    };
    let mut work = first;
    while let Some(comp) = work.pop() {
        let nontrivial = comp.len() > 1 || comp.first().is_some_and(|&v| succ(v).contains(&v));
        if !nontrivial {
            continue;
        }
        let mut remove = vec![false; fair.compassion.len()];
        let mut any_bad = false;
        for (k, (p, q)) in fair.compassion.iter().enumerate() {
            if comp.iter().any(|&v| p(v)) && !comp.iter().any(|&v| q(v)) {
                remove[k] = true;
                any_bad = true;
            }
        }
        if !any_bad {
            if fair.visit.iter().all(|s| comp.iter().any(|&v| s(v))) {
                return Some(comp);
            }
            continue;
        }
        let rest: Vec<u32> = comp
            .iter()
            .copied()
            .filter(|&v| {
                !fair
                    .compassion
                    .iter()
                    .zip(&remove)
                    .any(|((p, _), r)| *r && p(v))
            })
            .collect();
        epoch += 1;
        for &v in &rest {
            mark[v as usize] = epoch;
        }
        let m = &mark;
        let e = epoch;
        work.extend(sccs(&rest, &|w| m[w as usize] == e, succ, &mut sc));
    }
    None
}

/// A shortest path (at least one step when `step` is true) inside `inside` from `from` to a
/// vertex satisfying `goal`; the vertices after `from`.
pub fn path_within<'g>(
    from: u32,
    goal: &dyn Fn(u32) -> bool,
    inside: &dyn Fn(u32) -> bool,
    succ: &dyn Fn(u32) -> &'g [u32],
    step: bool,
) -> Option<Vec<u32>> {
    if !step && goal(from) {
        return Some(Vec::new());
    }
    let mut parent: std::collections::HashMap<u32, u32> = std::collections::HashMap::new();
    let mut queue = std::collections::VecDeque::from([from]);
    let mut seen = std::collections::HashSet::from([from]);
    while let Some(v) = queue.pop_front() {
        for &w in succ(v) {
            if !inside(w) {
                continue;
            }
            if goal(w) {
                let mut path = vec![w];
                let mut cur = v;
                while cur != from {
                    path.push(cur);
                    match parent.get(&cur) {
                        Some(&p) => cur = p,
                        None => break,
                    }
                }
                path.reverse();
                return Some(path);
            }
            if seen.insert(w) {
                parent.insert(w, v);
                queue.push_back(w);
            }
        }
    }
    None
}
