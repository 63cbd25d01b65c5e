#!/bin/sh
# Benchmark: the FAM closed loop's liveness properties (examples/fam/liveness, issue 16) with
# our SAT engines against ABC on the same property, side by side in one run (figures, never a
# timed test). Ours: `statecheck verify MODEL --system S --property P --engine ic3` (IC3 on
# liveness-to-safety and k-liveness with bounded persistence, side by side). ABC: the property
# as `statecheck export aiger --abc-liveness` writes it (ABC's own liveness convention: this
# ABC does not read AIGER's justice sections), then `l2s; logic; undc; strash; zero; pdr`.
# Whole-process wall clock, one run each, each with the same time limit; the ratio ours / ABC
# is printed when both decided (below 1.0: ours is faster).
#
#   sh crates/symbolic/benches/vs_abc_live.sh                    # from the repository root
#   TIMEOUT=1200 PROPS="stall_procedure_completes_unless_permanent" sh crates/symbolic/benches/vs_abc_live.sh
#   MODEL=examples/fam/liveness/fam_live2.sc SYSTEM=FamLive2 sh crates/symbolic/benches/vs_abc_live.sh
# Properties with compassion constraints cannot be written for ABC (AIGER has no compassion):
# such a row says so. SERIAL=1 runs ABC after ours instead of beside it (2 cores assumed).
# ABC_CMD=kcs runs ABC's k-liveness instead (`export aiger --abc-kcs`, then `kcs`): it only
# proves, so its column reads proved or unknown.
set -eu
ROOT=$(cd "$(dirname "$0")/../../.." && pwd)
TIMEOUT=${TIMEOUT:-300}
ABC=${ABC:-berkeley-abc}
MODEL=${MODEL:-examples/fam/liveness/fam_live.sc}
SYSTEM=${SYSTEM:-FamLive}
ABC_CMD=${ABC_CMD:-l2s}
case "$ABC_CMD" in
  l2s) FORM=--abc-liveness; SCRIPT="l2s; logic; undc; strash; zero; pdr" ;;
  kcs) FORM=--abc-kcs; SCRIPT="kcs" ;;
  *) echo "error: ABC_CMD is l2s or kcs"; exit 2 ;;
esac
PROPS=${PROPS:-"stall_procedure_completes recalibrates_after_failure reaches_target stall_procedure_completes_unless_permanent recalibrates_with_end_stops reaches_target_with_end_stops"}
command -v "$ABC" >/dev/null || { echo "error: $ABC not found (apt-get install berkeley-abc)"; exit 2; }
[ -n "${NO_BUILD:-}" ] || cargo build --release -q -p statecheck-cli --manifest-path "$ROOT/Cargo.toml"
BIN=${STATECHECK:-${CARGO_TARGET_DIR:-$ROOT/target}/release/statecheck}
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

now() { date +%s.%N; }

printf "%-46s %-10s %-10s %9s %9s %7s\n" property ours abc ours_s abc_s ratio
for prop in $PROPS; do
  aig=$WORK/$prop.aig
  if ! "$BIN" export aiger "$ROOT/$MODEL" --system "$SYSTEM" --property "$prop" "$FORM" \
       -o "$aig" 2> "$WORK/export.err"; then
    printf "%-46s %s\n" "$prop" "not written for ABC: $(tail -1 "$WORK/export.err")"
    continue
  fi
  t0=$(now)
  ( timeout "$((TIMEOUT + 60))" "$BIN" verify "$ROOT/$MODEL" --system "$SYSTEM" --property "$prop" \
      --engine ic3 --timeout "$TIMEOUT" --json > "$WORK/ours.json" 2>/dev/null || true
    echo "$(now) - $t0" | bc -l > "$WORK/ours.t" ) &
  ours_pid=$!
  [ -z "${SERIAL:-}" ] || wait "$ours_pid"
  t1=$(now)
  timeout "$TIMEOUT" stdbuf -oL "$ABC" -c "read $aig; $SCRIPT" > "$WORK/abc.out" 2>&1 || true
  abc_t=$(echo "$(now) - $t1" | bc -l)
  wait "$ours_pid" || true
  ours_t=$(cat "$WORK/ours.t")
  ours=$(sed -n 's/.*"verdict":"\([a-z]*\)".*/\1/p' "$WORK/ours.json" | head -1)
  case "$(cat "$WORK/abc.out")" in
    *"Property proved"*) abc=proved ;;
    *"was asserted in frame"*) abc=violated ;;
    *) abc=unknown ;;
  esac
  case "$ours:$abc" in
    unknown:*|*:unknown|:*) ratio="-" ;;
    *) ratio=$(printf "%.2f" "$(echo "$ours_t / $abc_t" | bc -l)") ;;
  esac
  printf "%-46s %-10s %-10s %9.1f %9.1f %7s\n" "$prop" "${ours:-none}" "$abc" "$ours_t" "$abc_t" "$ratio"
done
