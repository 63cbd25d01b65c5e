#!/usr/bin/env python3
"""A simple reference implementation of monolithic Ramadge-Wonham synthesis, independent of
statecheck's engines: the families of crates/synth/src/families.rs built directly as automata
(no .sc parsing), the reachable product as a dict of tuples, then the textbook fixpoint
(remove blocking states, remove states with an uncontrollable edge into a removed state,
repeat), restricted to the states reachable from the initial one.

Usage: reference.py philosophers|line N, or reference.py tl|dp|cm|at|bw|ta N K
(crates/synth/src/families/scaled.rs)   ->  prints product, supervisor states, transitions
and the seconds taken (CPU time of this process).
"""
import sys, time


def philosophers(n):
    auts = []  # (name, plant?, locs, initial, marked set, {(loc, ev): loc}, alphabet)
    for i in range(n):
        t = {(0, f"take{i}l"): 1, (1, f"take{i}r"): 2, (2, f"put{i}"): 0}
        auts.append((f"p{i}", True, 3, 0, {0}, t, {f"take{i}l", f"take{i}r", f"put{i}"}))
    for j in range(n):
        p = (j + n - 1) % n
        t = {(0, f"take{j}l"): 1, (0, f"take{p}r"): 2, (1, f"put{j}"): 0, (2, f"put{p}"): 0}
        auts.append((f"f{j}", True, 3, 0, {0}, t, {f"take{j}l", f"take{p}r", f"put{j}", f"put{p}"}))
    unc = {f"put{i}" for i in range(n)}
    return auts, unc


def line(n):
    auts = []
    for i in range(1, n + 1):
        t = {(0, f"start{i}"): 1, (1, f"finish{i}"): 0, (1, f"break{i}"): 2, (2, f"repair{i}"): 0}
        auts.append((f"m{i}", True, 3, 0, {0}, t, {f"start{i}", f"finish{i}", f"break{i}", f"repair{i}"}))
    for i in range(1, n):
        t = {(0, f"finish{i}"): 1, (1, f"start{i + 1}"): 0}
        auts.append((f"b{i}", False, 2, 0, {0}, t, {f"finish{i}", f"start{i + 1}"}))
    unc = {f"finish{i}" for i in range(1, n + 1)} | {f"break{i}" for i in range(1, n + 1)}
    return auts, unc


# The two-parameter families of crates/synth/src/families/scaled.rs (docs/synthesis.md,
# "Benchmark families"), written here from their descriptions. Each returns
# (automata, uncontrollable events, never) where never is a list of predicates on the
# location tuple (automata in instance order).

def aut(name, plant, nlocs, marked, trans):
    return (name, plant, nlocs, 0, set(marked), dict(((f, e), t) for f, e, t in trans),
            {e for _, e, _ in trans})


def tl(n, k):
    auts, unc = [], set()
    for i in range(1, n + 1):
        auts.append(aut(f"m{i}", True, 3, [0], [(0, f"start{i}", 1), (1, f"finish{i}", 0),
                                                (1, f"break{i}", 2), (2, f"repair{i}", 0)]))
        unc |= {f"finish{i}", f"break{i}"}
        if i < n:
            tr = [(j, f"finish{i}", j + 1) for j in range(k)] + \
                 [(j + 1, f"start{i + 1}", j) for j in range(k)]
            auts.append(aut(f"b{i}", False, k + 1, [0], tr))
    return auts, unc, []


def dp(n, k):
    auts, unc = [], set()
    for i in range(n):
        # 0 Thinking, 1 HasLeft, 2 Eating, 3.. resting
        tr = [(0, f"take{i}l", 1), (1, f"take{i}r", 2), (2, f"put{i}", 3 if k > 1 else 0)]
        tr += [(r + 2, f"rest{i}_{r}", r + 3 if r + 1 < k else 0) for r in range(1, k)]
        unc |= {f"put{i}"} | {f"rest{i}_{r}" for r in range(1, k)}
        auts.append(aut(f"p{i}", True, k + 2, [0], tr))
    for j in range(n):
        q = (j + n - 1) % n
        auts.append(aut(f"f{j}", True, 3, [0], [(0, f"take{j}l", 1), (0, f"take{q}r", 2),
                                                (1, f"put{j}", 0), (2, f"put{q}", 0)]))
    return auts, unc, []


def cm(n, k):
    m, home = 2 * k + 2, k + 1
    auts, unc = [], set()
    for who, start in (("c", 0), ("m", home)):
        for i in range(n):
            # location index = (room - start) mod m, so the initial room is 0
            loc = lambda r, s=start: (r - s) % m
            tr = []
            for r in range(m):
                tr.append((loc(r), f"{who}{i}_{r}cw", loc((r + 1) % m)))
                tr.append((loc(r), f"{who}{i}_{r}ccw", loc((r - 1) % m)))
                if who == "c" and r == 0:
                    unc |= {f"c{i}_0cw", f"c{i}_0ccw"}
            auts.append(aut(f"{who}{i}", True, m, [0], tr))
    # cat c (automaton c) at room r has location r; mouse j (automaton n + j) at room r has
    # location (r - home) mod m
    never = [lambda s, c=c, j=j: s[c] == (s[n + j] + home) % m
             for c in range(n) for j in range(n)]
    return auts, unc, never


def at(n, k):
    auts, unc = [], set()
    for i in range(n):
        # 0 Cruise, 1 Wait, 1 + h level h, k + 2 Runway
        tr = [(0, f"arrive{i}", 1), (1, f"enter{i}", k + 1), (2, f"land{i}", k + 2),
              (k + 2, f"exit{i}", 0)]
        tr += [(h + 1, f"down{i}_{h}", h) for h in range(2, k + 1)]
        unc |= {f"arrive{i}", f"land{i}", f"exit{i}"}
        auts.append(aut(f"p{i}", True, k + 3, [0], tr))
    never = [lambda s, i=i, j=j: s[i] == s[j] and s[i] >= 2 for i in range(n) for j in range(i + 1, n)]
    return auts, unc, never


def bw(n, k):
    # workflow: 0 Open, 1 Approved, 2 Denied; company: 0 Idle, 1 Eval, 2 Acc, 3 Rej
    auts = [aut("w", True, 3, [1, 2], [(0, "approve", 1), (0, "deny", 2)])]
    unc = set()
    for i in range(n):
        auts.append(aut(f"c{i}", True, 4, [2, 3], [(0, f"assign{i}", 1), (1, f"accept{i}", 2),
                                                    (1, f"reject{i}", 3), (3, f"retry{i}", 1),
                                                    (2, "approve", 2)]))
        unc |= {f"accept{i}", f"reject{i}"}
    tr = [(j, f"retry{i}", j + 1) for j in range(k) for i in range(n)] + [(k, "deny", k)]
    auts.append(aut("r", False, k + 1, range(k + 1), tr))
    return auts, unc, []


def ta(n, k):
    tr = [(0, "request", 1), (1, "done", 0), (1, "abort", 0)] + [(1, f"query{i}", 1) for i in range(n)]
    auts, unc = [aut("a", True, 2, [0], tr)], {"request"}
    for i in range(n):
        # 0 Idle, 1 Query, 2 NA, 3 Booked, 3 + j offer j
        tr = [(0, f"query{i}", 1), (1, f"na{i}", 2), (3, "done", 0)]
        tr += [(1, f"offer{i}_{j}", 3 + j) for j in range(1, k + 1)]
        tr += [(3 + j, f"book{i}_{j}", 3) for j in range(1, k + 1)]
        tr += [(l, "abort", 0) for l in [0, 2, 3] + list(range(4, 4 + k))]
        unc |= {f"na{i}"} | {f"offer{i}_{j}" for j in range(1, k + 1)}
        auts.append(aut(f"s{i}", True, 4 + k, [0], tr))
    never = [lambda s, i=i, j=j: s[1 + i] == 3 and s[1 + j] == 2
             for i in range(n) for j in range(n) if i != j]
    return auts, unc, never


SCALED = {"tl": tl, "dp": dp, "cm": cm, "at": at, "bw": bw, "ta": ta}


def synthesize(auts, unc, never=()):
    events = sorted(set().union(*(a[6] for a in auts)))
    init = tuple(a[3] for a in auts)
    index = {init: 0}
    states = [init]
    edges = []  # (src, event, dst)
    bad = []
    i = 0
    while i < len(states):
        s = states[i]
        if any(f(s) for f in never):
            bad.append(True)
            i += 1
            continue
        is_bad = False
        for e in events:
            nxt = list(s)
            plant_ok, req_ok = True, True
            for k, (_, plant, _, _, _, t, alph) in enumerate(auts):
                if e in alph:
                    d = t.get((s[k], e))
                    if d is None:
                        if plant:
                            plant_ok = False
                        else:
                            req_ok = False
                    else:
                        nxt[k] = d
            if not plant_ok:
                continue
            if not req_ok:
                if e in unc:
                    is_bad = True
                continue
            nxt = tuple(nxt)
            j = index.get(nxt)
            if j is None:
                j = index[nxt] = len(states)
                states.append(nxt)
            edges.append((i, e, j))
        bad.append(is_bad)
        i += 1
    n = len(states)
    preds = [[] for _ in range(n)]
    for s, e, t in edges:
        preds[t].append((s, e))
    alive = [not b for b in bad]
    marked = [all(s[k] in auts[k][4] for k in range(len(auts))) for s in states]
    while True:
        before = sum(alive)
        co = [False] * n
        stack = [s for s in range(n) if alive[s] and marked[s]]
        for s in stack:
            co[s] = True
        while stack:
            t = stack.pop()
            for s, _ in preds[t]:
                if alive[s] and not co[s]:
                    co[s] = True
                    stack.append(s)
        alive = [a and c for a, c in zip(alive, co)]
        work = [s for s in range(n) if not alive[s]]
        while work:
            t = work.pop()
            for s, e in preds[t]:
                if alive[s] and e in unc:
                    alive[s] = False
                    work.append(s)
        if sum(alive) == before:
            break
    kept = [False] * n
    if alive[0]:
        succ = [[] for _ in range(n)]
        for s, _, t in edges:
            succ[s].append(t)
        kept[0] = True
        stack = [0]
        while stack:
            s = stack.pop()
            for t in succ[s]:
                if alive[t] and not kept[t]:
                    kept[t] = True
                    stack.append(t)
    trans = sum(1 for s, _, t in edges if kept[s] and kept[t])
    return n, sum(kept), trans


if __name__ == "__main__":
    family, n = sys.argv[1], int(sys.argv[2])
    t0 = time.process_time()
    if family in SCALED:
        product, sup, trans = synthesize(*SCALED[family](n, int(sys.argv[3])))
    else:
        product, sup, trans = synthesize(*{"philosophers": philosophers, "line": line}[family](n))
    print(f"reference {time.process_time() - t0:.3f}s product {product} supervisor {sup} states {trans} transitions")
