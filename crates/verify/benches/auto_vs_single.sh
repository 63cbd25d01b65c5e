#!/usr/bin/env bash
# Wall-clock time of `statecheck verify` on every example and test model with each engine
# alone and with `auto`, and auto's ratio to the fastest single engine that decided every
# property. Prints a table; never fails on figures (this is a benchmark, not a test).
#
#   cargo build --release -p statecheck-cli
#   crates/verify/benches/auto_vs_single.sh [TIMEOUT_S]
#   MODELS="examples/linear_drive/*.sc tests/verify/*.sc" crates/verify/benches/auto_vs_single.sh 10
#   FAM_ONLY=1 crates/verify/benches/auto_vs_single.sh      # only the last line below
#
# The last line times `statecheck verify examples/fam/fam_system.sc` with no flags (auto, the
# default): the wall clock and CPU time to its last verdict, the load average, and when each
# property was decided (`--json-lines`' decided_at_s), slowest last.
# Each run gets TIMEOUT_S seconds (default 60); a run that leaves a property unknown is shown
# with `*` and is not a candidate for "fastest".
set -u
cd "$(dirname "$0")/../../.."
BIN=${STATECHECK:-${CARGO_TARGET_DIR:-target}/release/statecheck}
T=${1:-60}
[ -x "$BIN" ] || { echo "build first: cargo build --release -p statecheck-cli ($BIN)"; exit 2; }
systems() { grep -o '^system [A-Za-z_][A-Za-z0-9_]*' "$1" | cut -d' ' -f2; }
now() { date +%s.%N; }
fam_no_flags() {
  local out=/tmp/auto_vs_single.$$.jsonl tf=/tmp/auto_vs_single.$$.time
  echo "fam_system.sc, no flags (load average before: $(cut -d' ' -f1-3 /proc/loadavg)):"
  /usr/bin/time -f '%e %U %S' -o "$tf" "$BIN" verify examples/fam/fam_system.sc --json-lines >"$out" 2>/dev/null
  # The last line: GNU time first writes "Command exited with non-zero status N" when the
  # run's exit code is not 0 (a violated property gives 1).
  read -r wall user sys < <(tail -n 1 "$tf")
  python3 - "$out" "$wall" "$user" "$sys" <<'PY'
import json, sys
rows = [r for r in (json.loads(l) for l in open(sys.argv[1]) if l.strip()) if "property" in r]
rows.sort(key=lambda r: r.get("decided_at_s") or 1e9)
wall, user, sysc = (float(x) for x in sys.argv[2:5])
print(f"  {len(rows)} verdicts; last at {max((r.get('decided_at_s') or 0) for r in rows):.1f} s; "
      f"process {wall:.1f} s wall, {user + sysc:.1f} s CPU")
for r in rows:
    print(f"  {r.get('decided_at_s') or 0:7.1f} s  {r['property']:<45} {r['verdict']:<10} {r.get('engine', '')}")
PY
  rm -f "$out" "$tf"
}
if [ -n "${FAM_ONLY:-}" ]; then fam_no_flags; exit 0; fi
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
fam_no_flags
