#!/bin/sh
# Figures of the distributed explicit search (docs/distributed.md; printed, never asserted):
# states/s and bytes exchanged per state for one process (1 worker), one process of two
# workers, and two processes of one worker on loopback, on the same model and property set.
# Usage: scripts/bench_dist.sh [MODEL [EXTRA VERIFY ARGS...]]
#   default MODEL: examples/fam/fam_alone.sc (66,889 states)
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$ROOT/target}
cargo build --release -q -p statecheck-cli --manifest-path "$ROOT/Cargo.toml"
SC=$CARGO_TARGET_DIR/release/statecheck
MODEL=${1:-$ROOT/examples/fam/fam_alone.sc}
[ $# -gt 0 ] && shift
TMP=$(mktemp -d "${TMPDIR:-/tmp}/statecheck-bench-dist.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
port() { python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'; }
summary() {
  python3 - "$1" "$2" <<'PY'
import json, sys
v = json.load(open(sys.argv[2]))
s = v["stats"]
d = s.get("distributed") or {}
t = s["time_s"]
bps = d.get("bytes_per_state", 0.0)
print(f"{sys.argv[1]:<28} {s['states']:>10} states {s['transitions']:>11} transitions "
      f"{t:7.2f} s {s['states'] / max(t, 1e-9):>10.0f} states/s "
      f"{bps:7.1f} B/state exchanged  peak {s['peak_memory_bytes'] / 2**20:.1f} MiB/process "
      f"per worker {d.get('worker_states', [s['states']])}")
PY
}
echo "model: $MODEL $*"
"$SC" verify "$MODEL" --workers 1 --json "$@" > "$TMP/w1.json" || true
summary "1 process x 1 worker" "$TMP/w1.json"
"$SC" verify "$MODEL" --workers 2 --json "$@" > "$TMP/w2.json" || true
summary "1 process x 2 workers" "$TMP/w2.json"
printf '127.0.0.1:%s\n127.0.0.1:%s\n' "$(port)" "$(port)" > "$TMP/hosts"
"$SC" verify "$MODEL" --workers 1 --hosts "$TMP/hosts" --process 1 --json "$@" > "$TMP/p1.json" &
P1=$!
"$SC" verify "$MODEL" --workers 1 --hosts "$TMP/hosts" --process 0 --json "$@" > "$TMP/p0.json" || true
wait "$P1" || true
summary "2 processes x 1 worker" "$TMP/p0.json"
"$SC" verify "$MODEL" --engine explicit --threads 1 --backend interpreter --json "$@" > "$TMP/e.json" || true
summary "explicit engine, 1 thread" "$TMP/e.json"
