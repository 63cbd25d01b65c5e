#!/bin/sh
# Figures of issue 20's limits (printed, never asserted by a timed test):
#  1. `verify --timeout 1` on a system with 10^4 invariants, per engine: wall time (bar: the
#     timeout + 1 s, start-up included);
#  2. `--max-memory 256M`: peak RSS of `verify --engine explicit` on the FAM closed loop and of
#     `synth --engine explicit` on examples/synthesis/line_12.sc (bar: < 282 MiB);
#  3. a C compiler of the native backend left running after `verify` returns (bar: 0).
# Usage: scripts/bench_limits.sh            Needs /usr/bin/time (GNU time).
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$ROOT/target}
PROFILE=${PROFILE:-release}
if [ "$PROFILE" = release ]; then
  cargo build --release -q -p statecheck-cli --manifest-path "$ROOT/Cargo.toml"
  SC=$CARGO_TARGET_DIR/release/statecheck
else
  cargo build -q -p statecheck-cli --manifest-path "$ROOT/Cargo.toml"
  SC=$CARGO_TARGET_DIR/debug/statecheck
fi
TMP=$(mktemp -d "${TMPDIR:-/tmp}/statecheck-bench-limits.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
python3 - "$TMP/many.sc" <<'PY'
import sys
props = "".join(f"  invariant p{k}: c.n != {k % 97 + 100};\n" for k in range(10000))
open(sys.argv[1], "w").write(
    "chart C {\n  input event e;\n  output n: int[0..255] = 0;\n  initial S;\n"
    "  state S { on e / { n = (n + 1) % 256; }; }\n}\n"
    f"system Many {{\n  instance c: C;\n{props}}}\n")
PY
now() { date +%s.%N; }
echo "1. verify --timeout 1, 10^4 invariants"
printf '   %-9s %-5s %s\n' engine exit wall_s
for eng in explicit bmc kind ic3 auto; do
  s=$(now); rc=0; "$SC" verify "$TMP/many.sc" --engine $eng --timeout 1 >/dev/null 2>&1 || rc=$?
  printf '   %-9s %-5s %.2f\n' $eng $rc "$(echo "$(now) - $s" | bc)"
done
echo "2. --max-memory 256M, peak RSS"
peak() { # label, command...
  label=$1; shift; rc=0
  /usr/bin/time -f '%M' -o "$TMP/rss" "$@" >/dev/null 2>&1 || rc=$?
  printf '   %-44s exit %-3s peak %6.1f MiB\n' "$label" $rc "$(echo "$(tail -1 "$TMP/rss") / 1024" | bc -l)"
}
peak "verify --engine explicit fam_system.sc" "$SC" verify "$ROOT/examples/fam/fam_system.sc" --engine explicit --max-memory 256M --timeout 300
peak "synth --engine explicit line_12.sc" "$SC" synth "$ROOT/examples/synthesis/line_12.sc" --engine explicit --max-memory 256M --timeout 300 -o "$TMP/sup.sc"
echo "3. C compilers left running after verify (native backend, 1 s timeout)"
mkdir -m 700 "$TMP/cache"
STATECHECK_CACHE_DIR="$TMP/cache" "$SC" verify "$ROOT/examples/fam/fam_system.sc" --engine explicit --backend native --timeout 1 >/dev/null 2>&1 || true
sleep 0.2
left=$(pgrep -f "$TMP/cache" | wc -l || true)
echo "   compiler processes left: $left"
