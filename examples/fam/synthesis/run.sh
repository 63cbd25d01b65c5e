#!/usr/bin/env bash
# The FAM run-mode supervisor, end to end (docs/synthesis.md, "FAM run-mode supervisor"):
#  1. synthesize it from runmode.sc with both engines (their outputs must be identical);
#  2. check it with the independent checker, and the emitted system's own properties;
#  3. check the hand-written master (master_policy.sc) against the same plant: as written, with
#     FORGET_REFERENCE_ON_FAILURE, with RETRY_IN_FAILURE_RUN, and with both; and prove what it
#     never does (its `system MasterLoop`);
#  4. the comparison: every event the master lets happen, the supervisor lets happen too (the
#     master in series with the supervisor, containment.part), and the supervisor reaches what
#     the master never does (`system SupervisorReach`).
# Usage: examples/fam/synthesis/run.sh [path/to/statecheck] [OUTDIR]
# The master's checks report violations (exit status 1) by design; the script goes on and
# prints a summary of each. It exits 1 only if a step that must pass fails. A counterexample
# tick shows only what changed, so an event proposed twice in a row shows once.
set -u
cd "$(dirname "$0")/../../.."
BIN=${1:-}
if [ -z "$BIN" ]; then
    cargo build --release -q -p statecheck-cli || exit 2
    BIN=${CARGO_TARGET_DIR:-target}/release/statecheck
fi
OUT=${2:-$(mktemp -d)}
mkdir -p "$OUT"
D=examples/fam/synthesis
fail=0
must() { "$@" || { echo "FAILED: $*"; fail=1; }; }

echo "== 1. synthesis"
for engine in explicit symbolic; do
    must "$BIN" synth "$D/runmode.sc" --engine "$engine" -o "$OUT/supervisor_$engine.sc"
done
must cmp "$OUT/supervisor_explicit.sc" "$OUT/supervisor_symbolic.sc"

echo "== 2. the supervisor, checked"
must "$BIN" verify "$OUT/supervisor_explicit.sc" --plant "$D/runmode.sc"
must "$BIN" verify -q "$OUT/supervisor_explicit.sc"

# One line per kind of violation, with its count and the first (shortest) trace.
summary() {
    awk '/^violation: / {
             k = $0; sub(/ after .*/, "", k)
             if (!(k in n)) { first[k] = $0; order[++m] = k }
             n[k]++; next }
         { print }
         END { for (i = 1; i <= m; i++) printf "%d x %s\n   first: %s\n", n[order[i]], order[i], first[order[i]] }'
}
# A counterexample row lists every variable that changed: keep the events.
events() {
    awk '/^tick / { next }
         /^ +[0-9]+ +[A-Za-z]/ {
             row = sprintf("  tick %2d:", $1)
             for (i = 2; i <= NF; i++)
                 if ($i ~ /^((master|sup)\.)?(ev|fire)=/) row = row " " $i
             print row; next }
         { print }'
}

echo "== 3. the master, checked against the same plant"
variant() { # name, constants to set to true
    local f="$OUT/$1.sc"; shift
    cp "$D/master_policy.sc" "$f"
    for c in "$@"; do sed -i "s/^const $c: bool = false;/const $c: bool = true;/" "$f"; done
}
variant master_policy
variant master_policy_forget FORGET_REFERENCE_ON_FAILURE
variant master_policy_retry RETRY_IN_FAILURE_RUN
variant master_policy_both FORGET_REFERENCE_ON_FAILURE RETRY_IN_FAILURE_RUN
MASTERS="master_policy master_policy_forget master_policy_retry master_policy_both"
for m in $MASTERS; do
    echo "-- $m"
    "$BIN" verify "$OUT/$m.sc" --plant "$D/runmode.sc" | summary
done
echo "-- what the master never does (system MasterLoop, master as written)"
must "$BIN" verify "$OUT/master_policy.sc"

echo "== 4. the master within the supervisor"
for m in $MASTERS; do
    # No import in the language: the supervisor's file (its `enum Event` is the master's), the
    # master's file and the systems of containment.part.
    {
        grep -v '^enum Event ' "$OUT/supervisor_explicit.sc"
        cat "$OUT/$m.sc" "$D/containment.part"
    } > "$OUT/containment_$m.sc"
    echo "-- $m"
    "$BIN" verify "$OUT/containment_$m.sc" --system Containment | events
done
echo "-- what the supervisor reaches and the master never does"
must "$BIN" verify "$OUT/containment_master_policy.sc" --system SupervisorReach | events
echo "files in $OUT"
exit $fail
