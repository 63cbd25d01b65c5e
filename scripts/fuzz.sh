#!/bin/sh
# The long runs of the fuzzers (docs/reliability.md; the short runs are part of `cargo test`).
#
#   scripts/fuzz.sh targets [SECONDS|--executions N] [more flags]
#       the four mutation fuzzers (check, scenario, aiger, fmt), each for SECONDS (default 60)
#       on two worker processes; prints executions, panics, aborts, timeouts (> 10 s),
#       violations per target; failing inputs go to fuzz-out/crashes and fuzz-out/timeouts.
#   scripts/fuzz.sh diff [MODELS] [more flags]
#       the differential fuzzer over MODELS random models (default 1000): verdict pairs,
#       replays, C/Rust trace comparisons, SPIN acceptance, disagreements, compile failures.
#
# Any further flags go to `statecheck-fuzz` (--seed S, --jobs J, --timeout S, --out DIR,
# --target NAME, --batch N, --rust-every K, --seconds T). Exit code 0: nothing failed.
set -eu
ROOT=$(cd "$(dirname "$0")/.." && pwd)
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$ROOT/target}
cargo build --release -q -p statecheck-fuzz --manifest-path "$ROOT/Cargo.toml"
FUZZ=$CARGO_TARGET_DIR/release/statecheck-fuzz
MODE=${1:-targets}
[ $# -gt 0 ] && shift
case "$MODE" in
  targets)
    if [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; then SECS=$1; shift; else SECS=60; fi
    case " $* " in
      *" --executions "*) exec "$FUZZ" run --root "$ROOT" "$@" ;;
      *) exec "$FUZZ" run --root "$ROOT" --seconds "$SECS" "$@" ;;
    esac
    ;;
  diff)
    if [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; then N=$1; shift; else N=1000; fi
    exec "$FUZZ" diff --root "$ROOT" --models "$N" "$@"
    ;;
  *)
    echo "usage: scripts/fuzz.sh targets [SECONDS] | diff [MODELS]  [statecheck-fuzz flags]" >&2
    exit 2
    ;;
esac
