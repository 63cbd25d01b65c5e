#!/usr/bin/env bash
# Synthesis benchmarks (docs/synthesis.md, "Benchmarks"): both engines on the fixed examples,
# then on the philosophers and line families grown until an engine needs LIMIT seconds
# (default 60); CPU seconds, peak memory and sizes per run, and the reference implementation
# (reference.py, an independent textbook implementation) beside the explicit engine on the
# philosophers. Supervisors written with -o are re-read and checked with `verify --plant` up
# to VERIFY_MAX supervisor states (default 100000). Then the (n, k) families TL, DP, CM, AT,
# BW, TA (docs/synthesis.md, "Benchmark families"), both engines, n grown.
# Usage: examples/synthesis/bench.sh [path/to/statecheck]   (default: a release build)
set -u
cd "$(dirname "$0")/../.."
BIN=${1:-}
LIMIT=${LIMIT:-60}
VERIFY_MAX=${VERIFY_MAX:-100000}
if [ -z "$BIN" ]; then
    cargo build --release -q -p statecheck-cli || exit 2
    BIN=${CARGO_TARGET_DIR:-target}/release/statecheck
fi
# The instance generator (crates/synth/examples/gen_families.rs).
cargo build --release -q -p statecheck-synth --example gen_families || exit 2
GEN=${CARGO_TARGET_DIR:-target}/release/examples/gen_families
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
TIME=/usr/bin/time
[ -x "$TIME" ] || TIME=

# run LABEL ENGINE FILE [SYSTEM]: prints one line; returns 1 when the run hit the limit.
run() {
    local label=$1 engine=$2 file=$3 sys=()
    [ -n "${4:-}" ] && sys=(--system "$4")
    local out=$TMP/sup.sc
    rm -f "$out"
    if [ -n "$TIME" ]; then
        $TIME -f "%U %S %M" -o "$TMP/t" "$BIN" synth -q --engine "$engine" --timeout "$LIMIT" \
            "${sys[@]}" "$file" -o "$out" >"$TMP/o" 2>&1
    else
        "$BIN" synth -q --engine "$engine" --timeout "$LIMIT" "${sys[@]}" "$file" -o "$out" >"$TMP/o" 2>&1
        echo "0 0 0" >"$TMP/t"
    fi
    local line cpu mem u s m
    line=$(tail -1 "$TMP/o")
    # time(1) adds "Command exited with non-zero status N" first when the exit code is not 0.
    read -r u s m < <(tail -1 "$TMP/t")
    cpu=$(awk "BEGIN { printf \"%.2f\", $u + $s }")
    mem=$((m / 1024))
    printf '%-28s %-9s cpu %7ss %6s MB  %s' "$label" "$engine" "$cpu" "$mem" "$line"
    local states
    states=$(echo "$line" | sed -n 's/.*supervisor \([0-9]*\) states.*/\1/p')
    if [ -n "$states" ] && [ -f "$out" ] && [ "$states" -le "$VERIFY_MAX" ]; then
        if "$BIN" verify "$out" --plant "$file" "${sys[@]/--system/--plant-system}" -q >"$TMP/v" 2>&1; then
            printf '  [re-read, verify --plant ok]'
        else
            printf '  [VERIFY FAILED: %s]' "$(tail -1 "$TMP/v")"
        fi
    fi
    echo
    case $line in unknown:*) return 1 ;; esac
    return 0
}

# SECTIONS: which parts to run (default all): fixed, grown (philosophers and line), families.
SECTIONS=${SECTIONS:-fixed grown families}
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)"

if [[ " $SECTIONS " == *" fixed "* ]]; then
echo "== fixed examples"
for spec in "small_factory.sc SmallFactory" "small_factory.sc SmallFactoryRepair" "cat_mouse.sc" \
            "transfer_line.sc" "philosophers_5.sc" "line_4.sc" "line_12.sc"; do
    set -- $spec
    for engine in explicit symbolic; do
        [ "$1" = line_12.sc ] && [ "$engine" = explicit ] && continue
        run "$1${2:+ ($2)}" "$engine" "examples/synthesis/$1" "${2:-}"
    done
done

fi

if [[ " $SECTIONS " == *" grown "* ]]; then
for family in philosophers line; do
    echo "== $family family (grown until an engine needs ${LIMIT} s)"
    alive_explicit=1 alive_symbolic=1 alive_reference=1
    n=4
    while [ $alive_explicit = 1 ] || [ $alive_symbolic = 1 ]; do
        f=$TMP/${family}_$n.sc
        "$GEN" "$family" "$n" "$f"
        for engine in explicit symbolic; do
            var=alive_$engine
            [ "${!var}" = 1 ] || continue
            run "${family}_$n" "$engine" "$f" || eval "$var=0"
        done
        if [ "$family" = philosophers ] && [ $alive_reference = 1 ]; then
            # The explicit engine as the reference runs: no guards, no output file.
            if [ -n "$TIME" ]; then
                $TIME -f "%U %S %M" -o "$TMP/t" "$BIN" synth -q --engine explicit --timeout "$LIMIT" "$f" >"$TMP/o" 2>&1
                read -r u s m < <(tail -1 "$TMP/t")
                printf '%-28s %-9s cpu %7ss %6s MB  %s\n' "${family}_$n" "expl. -q" \
                    "$(awk "BEGIN { printf \"%.2f\", $u + $s }")" $((m / 1024)) "$(tail -1 "$TMP/o")"
            fi
            t0=$(date +%s)
            ref=$(timeout "$LIMIT" python3 examples/synthesis/reference.py "$family" "$n")
            [ -n "$ref" ] && printf '%-28s %-9s %s\n' "${family}_$n" reference "$ref"
            [ -z "$ref" ] || [ $(( $(date +%s) - t0 )) -ge "$LIMIT" ] && alive_reference=0
        fi
        n=$((n + 1))
    done
done
fi

# The (n, k) families of crates/synth/src/families/scaled.rs: k fixed per family (K_TL=…
# overrides), n grown from 2 until both engines need LIMIT seconds or n reaches MAXN.
if [[ " $SECTIONS " == *" families "* ]]; then
MAXN=${MAXN:-12}
for fk in "tl ${K_TL:-3}" "dp ${K_DP:-2}" "cm ${K_CM:-2}" "at ${K_AT:-3}" "bw ${K_BW:-3}" "ta ${K_TA:-3}"; do
    set -- $fk
    family=$1 k=$2
    echo "== $family family, k = $k (n grown until both engines need ${LIMIT} s)"
    alive_explicit=1 alive_symbolic=1
    n=2
    while { [ $alive_explicit = 1 ] || [ $alive_symbolic = 1 ]; } && [ "$n" -le "$MAXN" ]; do
        f=$TMP/${family}_${n}_$k.sc
        "$GEN" "$family" "$n" "$k" "$f" || break
        for engine in explicit symbolic; do
            var=alive_$engine
            [ "${!var}" = 1 ] || continue
            run "${family}($n,$k)" "$engine" "$f" || eval "$var=0"
        done
        n=$((n + 1))
    done
done
fi
