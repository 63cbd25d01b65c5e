#!/bin/sh
# Benchmarks of the code generators (figures, not a timed test):
#  1. steps/s of the generated C (gcc -O2) vs the simulator's step engine (the IR Machine that
#     `statecheck sim` runs), same model, same random input vectors (bench target
#     crates/codegen/benches/step_c.rs), reported as a ratio;
#  2. states/s of our explicit checker (`statecheck verify`) vs SPIN on the exported Promela of
#     the same model (every property the checker proves asserted, so both explore the whole
#     state space), reported as a ratio. SPIN's rate is pan's own "states/second" (compilation of
#     pan.c excluded), ours is `stats.states_per_s` of `verify --json`.
# Usage: scripts/bench_codegen.sh [MODEL SYSTEM]   (default: the FAM plant, FamAlone)
# Compares on 1 checker thread (SPIN is single-threaded). Needs gcc, spin, python3.
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
MODEL=${1:-$ROOT/examples/fam/fam.sc}
SYSTEM=${2:-FamAlone}
# FamAlone has too many input vectors per tick for exhaustive exploration without --force, so
# the checker comparison defaults to the linear drive (207,421 states); override with
# SPIN_MODEL / SPIN_SYSTEM.
SPIN_MODEL=${SPIN_MODEL:-$ROOT/examples/linear_drive/linear_drive.sc}
SPIN_SYSTEM=${SPIN_SYSTEM:-LinearDrive}
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$ROOT/target}
cargo build --release -q -p statecheck-cli --manifest-path "$ROOT/Cargo.toml"
SC=$CARGO_TARGET_DIR/release/statecheck
TMP=$(mktemp -d "${TMPDIR:-/tmp}/statecheck-bench.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

# 1. Generated C vs the simulator's step engine (same random input vectors, one process).
cargo bench -q -p statecheck-codegen --bench step_c --manifest-path "$ROOT/Cargo.toml" -- "$MODEL" "$SYSTEM"

# 2. Explicit checker vs SPIN on the exported Promela.
"$SC" verify "$SPIN_MODEL" --system "$SPIN_SYSTEM" --json --threads 1 > "$TMP/v.json" 2>/dev/null || true
PROPS=$(python3 -c "
import json; d=json.load(open('$TMP/v.json'))
print(' '.join('--property '+r['property'] for r in d['results'] if r['verdict'] in ('proved','unreachable')))")
"$SC" export promela "$SPIN_MODEL" --system "$SPIN_SYSTEM" $PROPS -o "$TMP/m.pml"
(cd "$TMP" && spin -a m.pml > /dev/null && gcc -O2 -DSAFETY -DNOFAIR -DMEMLIM=8000 -o pan pan.c && ./pan -m10000000 > pan.out)
python3 - "$TMP/v.json" "$TMP/pan.out" <<'PY'
import json, re, sys
d = json.load(open(sys.argv[1]))["stats"]
pan = open(sys.argv[2]).read()
states = int(re.search(r"(\d+) states, stored", pan).group(1))
rate = float(re.search(r"rate\s+([\d.e+]+) states/second", pan).group(1)) if "rate" in pan else float("nan")
print(f"explicit checker: {d['states']} states, {d['states_per_s']:,.0f} states/s (1 thread)")
print(f"SPIN:             {states} states, {rate:,.0f} states/s")
print(f"ratio explicit / SPIN = {d['states_per_s']/rate:.2f}")
PY
