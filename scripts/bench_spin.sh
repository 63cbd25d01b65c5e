#!/bin/sh
# The explicit engine against SPIN on the same models, side by side in one run (figures, never
# a timed test): for each model, `statecheck verify --engine explicit` and SPIN's pan on the
# Promela that `statecheck export promela` writes for the same system, each with the same time
# limit. Both explore every reachable state (pan with -A: assertion violations do not stop it;
# our engine checks every property on the way and stops early only when all are decided),
# so when both finish, their state counts must be equal; the script says so, or says which
# run stopped at the limit (its figures are then partial).
# SPIN's rate is pan's own states/second (compilation of pan.c excluded); ours is the engine's
# `states_per_s` (the native successor generator's build included).
# Usage: scripts/bench_spin.sh [SECONDS] [THREADS]   (defaults 600, all cores; SPIN is
#        single-threaded: pass 1 for a per-core comparison). Needs gcc, spin, python3.
#        STATECHECK=path/to/statecheck uses that binary instead of building one.
#        COLLAPSE=1 compresses both visited sets: ours with `--collapse`, pan compiled with
#        -DCOLLAPSE (SPIN's own collapse compression); bytes/state then compares the two.
#        BITSTATE=MIB runs both in bitstate mode with an array of MIB mebibytes (a power of
#        two), 3 bits per state: ours with `--bitstate MIBM`, pan compiled with -DBITSTATE and
#        run with -w (log2 of the bits) -k3. Both counts are then lower bounds (omissions), so
#        they may differ slightly even when both finish.
# Models: the FAM alone (FamAloneSmall) and the closed loop master + 1 FAM (FamSystem; its
#         Promela reads properties and assumes with "an evaluation error is false", as the IR
#         does); override with MODELS="file.sc:System file2.sc:System2". The last line of each
#         model gives the ratio of the rates (and of the states stored when a run stopped at
#         the limit: same time budget, so that is the ratio of work done).
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
LIMIT=${1:-600}
THREADS=${2:-$(nproc)}
if [ "${COLLAPSE:-0}" = 1 ]; then OURS_COLLAPSE=--collapse; PAN_COLLAPSE=-DCOLLAPSE; else OURS_COLLAPSE=; PAN_COLLAPSE=; fi
if [ -n "${BITSTATE:-}" ]; then
  W=$(python3 -c "import math,sys; b=int(sys.argv[1])*8*1048576; w=int(math.log2(b)); assert 2**w==b, 'BITSTATE must be a power of two'; print(w)" "$BITSTATE")
  OURS_COLLAPSE="--bitstate ${BITSTATE}M"; PAN_COLLAPSE="$PAN_COLLAPSE -DBITSTATE"; PAN_RUN="-w$W -k3"
else
  PAN_RUN=
fi
MODELS=${MODELS:-"$ROOT/examples/fam/fam_alone.sc:FamAloneSmall $ROOT/examples/fam/fam_system.sc:FamSystem"}
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$ROOT/target}
if [ -n "${STATECHECK:-}" ]; then
  SC=$STATECHECK   # a statecheck binary already built (release)
else
  cargo build --release -q -p statecheck-cli --manifest-path "$ROOT/Cargo.toml"
  SC=$CARGO_TARGET_DIR/release/statecheck
fi
TMP=$(mktemp -d "${TMPDIR:-/tmp}/statecheck-spin.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
printf '%-28s %-9s %12s %14s %10s %8s  %s\n' model checker states states/s bytes/st time_s finished
for entry in $MODELS; do
  model=${entry%%:*}; system=${entry##*:}; name=$(basename "$model" .sc):$system
  rc=0
  "$SC" verify "$model" --system "$system" --engine explicit --threads "$THREADS" \
    --timeout "$LIMIT" $OURS_COLLAPSE --json > "$TMP/v.json" 2>/dev/null || rc=$?
  s=$(date +%s.%N)
  if "$SC" export promela "$model" --system "$system" -o "$TMP/m.pml" 2> "$TMP/pan.out"; then
    (cd "$TMP" && spin -a m.pml > /dev/null \
      && gcc -O2 -DSAFETY -DNOFAIR -DMEMLIM=16000 $PAN_COLLAPSE -o pan pan.c 2> /dev/null)
    s=$(date +%s.%N)
    (cd "$TMP" && timeout -s INT "$LIMIT" ./pan -A -m10000000 $PAN_RUN > pan.out 2>&1) || true
  fi
  wall=$(echo "$(date +%s.%N) - $s" | bc)
  python3 - "$TMP/v.json" "$TMP/pan.out" "$name" "$wall" "$rc" <<'PY'
import json, re, sys
v, pan_text, name, wall, rc = sys.argv[1], open(sys.argv[2]).read(), sys.argv[3], float(sys.argv[4]), sys.argv[5]
try:
    d = json.load(open(v))["stats"]
except Exception:
    print(f"{name:28} explicit: no JSON (exit {rc})")
    sys.exit(0)
ours = d["states"]
# A bitstate run that ran out of states is finished, though not complete (omissions).
finished = d["complete"] or (d.get("bitstate") is not None and d.get("limit") is None)
row = "{:28} {:9} {:>12,} {:>14,.0f} {:>10.1f} {:>8.1f}  {}"
print(row.format(name, "explicit", ours, d["states_per_s"], d.get("bytes_per_state", float("nan")),
                 d["time_s"], "yes" if finished else "no (" + str(d.get("limit")) + ")"))
m = re.search(r"(\d+) states, stored", pan_text)
if not m:
    print(f"{name:28} SPIN: no statistics\n{pan_text[-400:]}")
    sys.exit(0)
theirs = int(m.group(1))
rate = re.search(r"rate\s+([\d.e+]+) states/second", pan_text)
t = re.search(r"pan: elapsed time ([\d.e+]+) seconds", pan_text)
secs = float(t.group(1)) if t else wall
rate = float(rate.group(1)) if rate else theirs / max(secs, 1e-9)
vec = re.search(r"State-vector (\d+) byte", pan_text)
mem = re.search(r"([\d.]+)\s+actual memory usage for states", pan_text)
bps = float(mem.group(1)) * 1048576 / max(theirs, 1) if mem else float("nan")
done = "Interrupted" not in pan_text and "max search depth too small" not in pan_text
print(row.format(name, "SPIN", theirs, rate, bps, secs,
                 ("yes" if done else "no (interrupted)") + (f", state vector {vec.group(1)} bytes" if vec else "")))
ratio = d["states_per_s"] / rate if rate > 0 else float("nan")
if finished and done and d.get("bitstate") is not None:
    print(f"{'':28} bitstate counts (lower bounds) {ours:,} and {theirs:,}; states/s ratio explicit/SPIN = {ratio:.2f}")
elif finished and done:
    print(f"{'':28} state counts {'equal' if ours == theirs else 'DIFFER'}; states/s ratio explicit/SPIN = {ratio:.2f}")
else:
    # Neither count is final: the rates are over different prefixes of the state space
    # (breadth-first for us, depth-first for SPIN), so the ratio is indicative only.
    print(f"{'':28} stopped at the limit (partial counts); states/s ratio explicit/SPIN = {ratio:.2f}, "
          f"stored ratio = {ours / max(theirs, 1):.2f}")
PY
done
