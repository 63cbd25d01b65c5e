#!/usr/bin/env python3
"""A simple reference implementation of monolithic Ramadge-Wonham synthesis, independent of
statecheck's engines: the families of crates/synth/src/families.rs built directly as automata
(no .sc parsing), the reachable product as a dict of tuples, then the textbook fixpoint
(remove blocking states, remove states with an uncontrollable edge into a removed state,
repeat), restricted to the states reachable from the initial one.

Usage: reference.py philosophers|line N   ->  prints product, supervisor states, transitions
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


def synthesize(auts, unc):
    events = sorted(set().union(*(a[6] for a in auts)))
    init = tuple(a[3] for a in auts)
    index = {init: 0}
    states = [init]
    edges = []  # (src, event, dst)
    bad = []
    i = 0
    while i < len(states):
        s = states[i]
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
    product, sup, trans = synthesize(*{"philosophers": philosophers, "line": line}[family](n))
    print(f"reference {time.process_time() - t0:.3f}s product {product} supervisor {sup} states {trans} transitions")
