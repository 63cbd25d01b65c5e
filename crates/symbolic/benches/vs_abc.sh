#!/bin/sh
# Benchmark: time per property of `statecheck verify F.aig --engine ic3` against ABC's `pdr` on
# the same exported AIGER file, and the ratio ours / ABC (below 1.0: ours is faster).
#
# Properties: the FAM invariants of the thesis table, open loop with every input free
# (examples/fam/fam.sc, FamAlone: no assume, targetPos over 0..4095) and the closed-loop
# master + 1 FAM safety properties (examples/fam/fam_system.sc, FamSystem).
# Prints one row per property and the median ratio. Wall-clock times of whole processes
# (parsing and, for ABC, its preprocessing included), best of $REPEAT runs (default 3).
#
#   sh crates/symbolic/benches/vs_abc.sh            # from the repository root
#   TIMEOUT=600 REPEAT=1 sh crates/symbolic/benches/vs_abc.sh
set -eu
ROOT=$(cd "$(dirname "$0")/../../.." && pwd)
TIMEOUT=${TIMEOUT:-300}
REPEAT=${REPEAT:-3}
ABC=${ABC:-berkeley-abc}
command -v "$ABC" >/dev/null || { echo "error: $ABC not found (apt-get install berkeley-abc)"; exit 2; }
[ -n "${NO_BUILD:-}" ] || cargo build --release -q -p statecheck-cli --manifest-path "$ROOT/Cargo.toml"
BIN=${CARGO_TARGET_DIR:-$ROOT/target}/release/statecheck
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT

now() { date +%s.%N; }

# best-of-REPEAT wall time of a command; prints the seconds; its output goes to $WORK/last
timeit() {
  best=""
  for _ in $(seq "$REPEAT"); do
    t0=$(now)
    timeout "$TIMEOUT" "$@" > "$WORK/last" 2>&1 || true
    t1=$(now)
    t=$(echo "$t1 - $t0" | bc -l)
    if [ -z "$best" ] || [ "$(echo "$t < $best" | bc -l)" = 1 ]; then best=$t; fi
  done
  echo "$best"
}

printf "%-16s %-46s %-12s %-12s %9s %9s %7s\n" system property ours abc ours_s abc_s ratio
RATIOS=$WORK/ratios
: > "$RATIOS"
run() { # file system property
  f=$ROOT/examples/fam/$1; sys=$2; prop=$3
  aig=$WORK/$sys.$prop.aig
  "$BIN" export aiger "$f" --system "$sys" --property "$prop" -o "$aig" 2>/dev/null
  ours_t=$(timeit "$BIN" verify "$aig" --engine ic3 --timeout "$TIMEOUT" --json)
  ours=$(sed -n 's/.*"verdict":"\([a-z]*\)".*/\1/p' "$WORK/last" | head -1)
  abc_t=$(timeit "$ABC" -c "read $aig; logic; undc; strash; zero; fold; pdr")
  case "$(cat "$WORK/last")" in
    *"Property proved"*) abc=proved ;;
    *"was asserted in frame"*|*"Counter-example"*|*"is asserted"*) abc=violated ;;
    *) abc=unknown ;;
  esac
  ratio=$(echo "$ours_t / $abc_t" | bc -l)
  printf "%-16s %-46s %-12s %-12s %9.3f %9.3f %7.2f\n" "$sys" "$prop" "$ours" "$abc" "$ours_t" "$abc_t" "$ratio"
  echo "$ratio" >> "$RATIOS"
}

for p in fam_stall_blocks_run fam_failure_blocks_run fam_cof_with_notcalib fam_actualpos_in_range \
         fam_stall_running_possible fam_failure_running_possible no_range_overflow; do
  run fam.sc FamAlone "$p"
done
for p in fam_stall_blocks_run fam_failure_blocks_run fam_cof_with_notcalib fam_actualpos_in_range \
         master_no_normal_run_on_failure master_failure_before_stall master_outputs_in_range \
         master_target_outside_ends_only_calibrating master_failure_sequence no_range_overflow; do
  run fam_system.sc FamSystem "$p"
done
n=$(wc -l < "$RATIOS")
median=$(sort -g "$RATIOS" | awk -v n="$n" '{a[NR]=$1} END {if (n%2) print a[(n+1)/2]; else print (a[n/2]+a[n/2+1])/2}')
echo "median ratio ours/abc over $n properties: $median"
