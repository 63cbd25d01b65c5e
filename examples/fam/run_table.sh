#!/bin/sh
# run_table.sh — regenerate the verification table of docs/case-studies/fam.md from real runs.
# Usage: sh examples/fam/run_table.sh [STATECHECK] [TIMEOUT_S]  (prints Markdown on stdout)
# Runs `statecheck verify --json` on the files of expected.json and prints
#   property | thesis verdict | statecheck verdict | engine | states | time
# (states and time are those of the file's whole exploration: all properties of a run are
# checked in one exploration).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
bin=${1:-statecheck}
timeout=${2:-600}
tmp=$(mktemp -d)
for f in fam_alone.sc fam_system.sc bug_modulus.sc bug_short_timeout.sc; do
  sys=$(python3 -c "import json;print(json.load(open('$here/expected.json'))['runs']['$f']['system'])")
  extra=$(python3 -c "import json;r=json.load(open('$here/expected.json'))['runs']['$f'];print(' '.join('--property '+p for p in r.get('properties',[]))+(' --depth %d'%r['depth'] if 'depth' in r else ''))")
  # shellcheck disable=SC2086
  "$bin" verify "$here/$f" --system "$sys" --json --timeout "$timeout" $extra > "$tmp/$f.json" || true
done
python3 - "$here/expected.json" "$tmp" <<'PY'
import json, sys, os
exp = json.load(open(sys.argv[1])); tmp = sys.argv[2]
print("| file | property | thesis verdict | statecheck verdict | engine | states | time (s) |")
print("|---|---|---|---|---|---|---|")
for f, run in exp["runs"].items():
    p = os.path.join(tmp, f + ".json")
    try:
        d = json.load(open(p))
    except Exception:
        print(f"| {f} | (no result) | | | | | |"); continue
    st = d["stats"]
    limit = st.get("limit")
    for r in d["results"]:
        name = r["property"]
        if name.startswith("no_") and name not in run["verdicts"]:
            continue
        thesis = exp["thesis"].get(name, "—")
        v = r["verdict"]
        if v == "unknown" and limit:
            v += f" ({limit['kind']} limit)"
        print(f"| {f} | `{name}` | {thesis} | {v} (depth {r.get('depth')}) | {r.get('engine','explicit')} "
              f"| {st['states']} | {st['time_s']:.1f} |")
PY
rm -rf "$tmp"
