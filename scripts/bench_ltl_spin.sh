#!/bin/sh
# Explicit LTL throughput next to SPIN's, on the same models, in one run (issue 16's bar):
#   sh scripts/bench_ltl_spin.sh [N] [M]...   (default: 3 counters, M in 15 31)
# For each M: a model of N modulo counters `int[0..M]` (one input event each, at most one per
# tick) and a flag set once by its own event, with `ltl stays_done: G(f.done => G f.done)`
# (holds, so both tools explore the whole product). Ours: the explicit engine's position graph
# and product (`cargo bench -p statecheck-explicit --bench ltl`). SPIN: `statecheck export
# promela`, the same formula as an `ltl` claim (`!started U (started && φ)`: our positions
# start after tick 0), `spin -a`, `gcc -O2 -DNOREDUCE`, `pan -a`. Prints both tools' state
# counts, times and states/s. SPIN's states include the intermediate states of each atomic
# tick (the inputs chosen, the step not yet taken), so its counts are larger for the same
# model. Needs spin and gcc.
set -eu
cd "$(dirname "$0")/.."
N=${1:-3}
shift 2>/dev/null || true
MS=${*:-15 31}
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-target}
cargo build --release -q -p statecheck-cli
bin=$CARGO_TARGET_DIR/release/statecheck
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
for M in $MS; do
  f=$dir/ltl_$M.sc
  {
    echo "chart Counter { input event inc; output c: int[0..$M] = 0; initial Run;"
    echo "  state Run { on inc [c < $M] / { c += 1; }; on inc / { c = 0; }; } }"
    echo "chart Flag { input event go; output done: bool = false; initial Off;"
    echo "  state Off { on go / { done = true; } -> On; } state On { } }"
    echo "system Bench {"
    evs="f.go"
    i=0
    while [ $i -lt "$N" ]; do
      echo "  instance k$i: Counter;"
      evs="$evs k$i.inc"
      i=$((i + 1))
    done
    echo "  instance f: Flag;"
    # at most one event per tick
    pairs=""
    for a in $evs; do
      for b in $evs; do
        if [ "$a" \< "$b" ]; then pairs="$pairs${pairs:+ && }!($a && $b)"; fi
      done
    done
    echo "  assume $pairs;"
    echo "  ltl stays_done: G(f.done => G f.done);"
    echo "}"
  } > "$f"
  states=1
  i=0
  while [ $i -lt "$N" ]; do states=$((states * (M + 1))); i=$((i + 1)); done
  echo "== $N counters int[0..$M] + flag: $((states * 2)) reachable states (hand count: (M+1)^N x 2)"
  cargo bench -q -p statecheck-explicit --bench ltl -- "$f" 2>/dev/null | sed 's/^/  /'
  "$bin" export promela "$f" --system Bench -o "$dir/m.pml"
  echo 'ltl claim0 { (!started) U (started && ([] (f_done -> [] f_done))) }' >> "$dir/m.pml"
  (cd "$dir" && spin -a m.pml > /dev/null && gcc -O2 -DNOREDUCE -o pan pan.c 2>/dev/null)
  out=$(cd "$dir" && ./pan -a -m10000000 -N claim0 2>&1)
  errs=$(echo "$out" | sed -n 's/.*errors: \([0-9]*\).*/\1/p' | head -1)
  st=$(echo "$out" | sed -n 's/^ *\([0-9.e+]*\) states, stored.*/\1/p' | head -1)
  tm=$(echo "$out" | sed -n 's/.*elapsed time \([0-9.e+]*\) seconds.*/\1/p' | head -1)
  rate=$(echo "$out" | sed -n 's/.*rate *\([0-9.e+]*\) states\/second.*/\1/p' | head -1)
  echo "  spin stays_done: errors $errs; $st states stored; elapsed ${tm:-?} s; ${rate:-?} states/s"
done
