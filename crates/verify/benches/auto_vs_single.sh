#!/usr/bin/env bash
# Wall-clock time of `statecheck verify` on every example and test model with each engine
# alone and with `auto`, and auto's ratio to the fastest single engine that decided every
# property. Prints a table; never fails on figures (this is a benchmark, not a test).
#
#   cargo build --release -p statecheck-cli
#   crates/verify/benches/auto_vs_single.sh [TIMEOUT_S]
#   MODELS="examples/linear_drive/*.sc tests/verify/*.sc" crates/verify/benches/auto_vs_single.sh 10
#
# Each run gets TIMEOUT_S seconds (default 60); a run that leaves a property unknown is shown
# with `*` and is not a candidate for "fastest".
set -u
cd "$(dirname "$0")/../../.."
BIN=${STATECHECK:-${CARGO_TARGET_DIR:-target}/release/statecheck}
T=${1:-60}
[ -x "$BIN" ] || { echo "build first: cargo build --release -p statecheck-cli ($BIN)"; exit 2; }
systems() { grep -o '^system [A-Za-z_][A-Za-z0-9_]*' "$1" | cut -d' ' -f2; }
now() { date +%s.%N; }
printf '%-40s %9s %9s %9s %9s %9s %7s\n' model explicit bmc kind ic3 auto ratio
for f in ${MODELS:-examples/linear_drive/*.sc examples/fam/*.sc tests/verify/*.sc}; do
  case "$f" in *hard.sc) continue ;; esac
  for s in $(systems "$f"); do
    line=$(printf '%-40s' "$(basename "$f"):$s")
    best=""
    for e in explicit bmc kind ic3 auto; do
      t0=$(now)
      out=$("$BIN" verify "$f" --system "$s" --engine "$e" --timeout "$T" --json 2>/dev/null)
      t1=$(now)
      dt=$(echo "$t1 - $t0" | bc -l)
      mark=" "
      if echo "$out" | grep -q '"verdict":"unknown"\|"verdict":"bounded"' || [ -z "$out" ]; then mark="*"; fi
      line="$line $(printf '%8.2f%s' "$dt" "$mark")"
      if [ "$e" != auto ] && [ "$mark" = " " ]; then
        if [ -z "$best" ] || [ "$(echo "$dt < $best" | bc -l)" = 1 ]; then best=$dt; fi
      fi
      [ "$e" = auto ] && auto=$dt
    done
    if [ -n "$best" ]; then
      line="$line $(printf '%7.2f' "$(echo "$auto / $best" | bc -l)")"
    else
      line="$line       -"
    fi
    echo "$line"
  done
done
echo "(* = some property unknown or bounded within ${T} s; ratio = auto / fastest complete single engine)"
