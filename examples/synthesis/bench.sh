#!/usr/bin/env bash
# Synthesis benchmarks: time and supervisor size per model, for both engines, in one run.
# Usage: examples/synthesis/bench.sh [path/to/statecheck]   (default: a release build)
# The explicit engine is skipped on line_12 (1.09e9 product states; the symbolic engine's case).
set -u
cd "$(dirname "$0")/../.."
BIN=${1:-}
if [ -z "$BIN" ]; then
    cargo build --release -q -p statecheck-cli || exit 2
    BIN=${CARGO_TARGET_DIR:-target}/release/statecheck
fi
run() { # file system engine
    local sys=()
    [ -n "$2" ] && sys=(--system "$2")
    printf '%-34s %-9s ' "$1${2:+ ($2)}" "$3"
    "$BIN" synth -q --engine "$3" "${sys[@]}" "examples/synthesis/$1" | tail -1
}
for spec in "small_factory.sc SmallFactory" "small_factory.sc SmallFactoryRepair" "cat_mouse.sc" \
            "transfer_line.sc" "philosophers_5.sc" "line_4.sc" "line_12.sc"; do
    set -- $spec
    for engine in explicit symbolic; do
        if [ "$1" = line_12.sc ] && [ "$engine" = explicit ]; then
            printf '%-34s %-9s skipped (product too large for enumeration)\n' "$1" "$engine"
            continue
        fi
        run "$1" "${2:-}" "$engine"
    done
done
