#!/usr/bin/env bash
# Synthesis benchmarks (docs/synthesis.md, "Benchmarks"): both engines on the fixed examples,
# then on the philosophers and line families grown until an engine needs LIMIT seconds
# (default 60; the line family up to LINE_MAX = 16 machines, 1.4e12 product states); CPU
# seconds, peak memory and sizes per run, and the reference implementations (reference.py,
# an independent textbook implementation in Python, and the simple Rust reference
# crates/synth/examples/simple_reference.rs) beside the explicit engine on the philosophers,
# with the ratios of CPU seconds. Supervisors written with -o are re-read and checked with `verify --plant` up
# to VERIFY_MAX supervisor states (default 100000). Then the (n, k) families TL, DP, CM, AT,
# BW, TA (docs/synthesis.md, "Benchmark families"), both engines, n grown. Then the issue's
# bars with --engine auto (SECTIONS=bars).
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
cargo build --release -q -p statecheck-synth --example gen_families --example simple_reference || exit 2
GEN=${CARGO_TARGET_DIR:-target}/release/examples/gen_families
# The simple reference implementation in Rust (crates/synth/examples/simple_reference.rs).
SIMPLE=${CARGO_TARGET_DIR:-target}/release/examples/simple_reference
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
TIME=/usr/bin/time
[ -x "$TIME" ] || TIME=

# cpu_of FILE: user + system seconds of a time(1) -f "%U %S %M" file (last line).
cpu_of() {
    local u s m
    read -r u s m < <(tail -1 "$1")
    awk "BEGIN { printf \"%.2f\", $u + $s }"
}

# ratio A B: B / A with one decimal; "-" when A is 0 (below the clock's resolution) or B is
# missing (the peer did not finish).
ratio() {
    if [ -z "$2" ]; then printf -- '- (peer did not finish)'; return; fi
    awk "BEGIN { if ($1 > 0) printf \"%.1f\", $2 / $1; else printf \"-\" }"
}

# quiet LABEL ENGINE FILE [THREADS]: `synth -q` (no guards, no file), with `--threads
# THREADS` when given; prints one line (CPU and wall seconds) and leaves the CPU seconds in
# $QCPU, the wall seconds in $QWALL; returns 1 when the run hit the limit.
quiet() {
    local th=() tag="$2 -q"
    [ -n "${4:-}" ] && th=(--threads "$4") && tag="$2 -q t$4"
    $TIME -f "%U %S %M %e" -o "$TMP/t" "$BIN" synth -q --engine "$2" --timeout "$LIMIT" "${th[@]}" "$3" >"$TMP/o" 2>&1
    local m
    m=$(tail -1 "$TMP/t" | cut -d' ' -f3)
    QWALL=$(tail -1 "$TMP/t" | cut -d' ' -f4)
    QCPU=$(cpu_of "$TMP/t")
    QLINE=$(tail -1 "$TMP/o")
    printf '%-28s %-12s cpu %7ss wall %6ss %6s MB  %s\n' "$1" "$tag" "$QCPU" "$QWALL" $((m / 1024)) "$QLINE"
    case $QLINE in unknown:*) return 1 ;; esac
    return 0
}

# simple LABEL FILE: the simple Rust reference (crates/synth/examples/simple_reference.rs),
# CPU seconds of its synthesis in $SCPU ("" when it did not finish within LIMIT).
simple() {
    local r
    r=$(timeout "$LIMIT" "$SIMPLE" "$2" 2>&1)
    SCPU=$(echo "$r" | sed -n 's/^simple-ref \([0-9.]*\)s.*/\1/p')
    printf '%-28s %-9s %s\n' "$1" simple-ref "${r:-did not finish in ${LIMIT} s}"
}

# compare LABEL FILE N: the explicit engine as the references run (no guards, no output
# file, one thread: the references have one), the simple Rust reference (while alive_simple
# is 1) and reference.py on philosophers_N (while alive_reference is 1); ratios of CPU
# seconds in this run. Then the explicit engine on two threads (its pipeline) with the ratio
# of wall times. Leaves the references' CPU seconds in $SCPU and $RCPU ("" when not run or
# not finished in LIMIT s).
compare() {
    quiet "$1" explicit "$2" 2
    local wall2=$QWALL
    quiet "$1" explicit "$2" 1
    printf '%-28s %-12s two threads take %s of one thread'"'"'s wall time\n' "$1" ratio \
        "$(awk "BEGIN { if ($QWALL > 0) printf \"%.2f\", $wall2 / $QWALL; else printf \"-\" }")"
    SCPU= RCPU=
    [ "${alive_simple:-1}" = 1 ] && simple "$1" "$2"
    if [ "${alive_reference:-1}" = 1 ]; then
        local t0 ref
        t0=$(date +%s)
        ref=$(timeout "$LIMIT" python3 examples/synthesis/reference.py philosophers "$3")
        [ -n "$ref" ] && printf '%-28s %-9s %s\n' "$1" reference.py "$ref"
        [ $(( $(date +%s) - t0 )) -lt "$LIMIT" ] &&
            RCPU=$(echo "$ref" | sed -n 's/^reference \([0-9.]*\)s.*/\1/p')
    fi
    printf '%-28s %-12s explicit -q t1 is %sx the simple Rust reference, %sx reference.py\n' \
        "$1" ratio "$(ratio "$QCPU" "$SCPU")" "$(ratio "$QCPU" "$RCPU")"
}

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

# SECTIONS: which parts to run (default all but reference): fixed, grown (philosophers and
# line), reference (only the philosophers against the references), families, bars (the issue's bars: auto on one instance of >= 10^6 states per family, line_16, symbolic
# under 10^5 states).
SECTIONS=${SECTIONS:-fixed grown families bars}
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
    alive_explicit=1 alive_symbolic=1 alive_reference=1 alive_simple=1
    n=4
    while [ $alive_explicit = 1 ] || [ $alive_symbolic = 1 ]; do
        f=$TMP/${family}_$n.sc
        "$GEN" "$family" "$n" "$f"
        for engine in explicit symbolic; do
            var=alive_$engine
            [ "${!var}" = 1 ] || continue
            run "${family}_$n" "$engine" "$f" || eval "$var=0"
        done
        if [ "$family" = philosophers ] && [ -n "$TIME" ] &&
            { [ $alive_simple = 1 ] || [ $alive_reference = 1 ]; }; then
            compare "${family}_$n" "$f" "$n"
            [ -n "$SCPU" ] || alive_simple=0
            [ -n "$RCPU" ] || alive_reference=0
        fi
        [ "$family" = line ] && [ "$n" -ge "${LINE_MAX:-16}" ] && break
        n=$((n + 1))
    done
done
fi

# Only the references' comparison on the philosophers (SECTIONS=reference; not in the
# default list, the grown section makes it too): n from REF_FROM (default 12) while the simple
# Rust reference finishes within LIMIT.
if [[ " $SECTIONS " == *" reference "* ]] && [ -n "$TIME" ]; then
    echo "== the explicit engine against the references on the philosophers (n grown while the simple Rust reference finishes in ${LIMIT} s)"
    alive_simple=1 alive_reference=1
    n=${REF_FROM:-12}
    while [ $alive_simple = 1 ]; do
        f=$TMP/philosophers_$n.sc
        "$GEN" philosophers "$n" "$f"
        compare "philosophers_$n" "$f" "$n"
        [ -n "$SCPU" ] || alive_simple=0
        [ -n "$RCPU" ] || alive_reference=0
        n=$((n + 1))
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

# The issue's bars (docs/synthesis.md, "Benchmarks"), with `synth -q --engine auto`: one
# instance of at least 10^6 reachable states per family (BAR_INSTANCES overrides), each beside
# the simple Rust reference when its product is at most SIMPLE_MAX reachable states; the
# line family at 10^12 product states; and the largest symbolic CPU time over the family
# instances under 10^5 reachable states (n grown from 2 per family, k as above).
if [[ " $SECTIONS " == *" bars "* ]] && [ -n "$TIME" ]; then
SIMPLE_MAX=${SIMPLE_MAX:-3000000}
echo "== bar: every family an instance of >= 10^6 reachable states in under 30 s (auto)"
for inst in ${BAR_INSTANCES:-tl,7,3 dp,11,2 cm,4,3 at,7,6 bw,10,3 ta,8,3}; do
    IFS=, read -r family n k <<<"$inst"
    f=$TMP/${family}_${n}_$k.sc
    "$GEN" "$family" "$n" "$k" "$f" || continue
    quiet "${family}($n,$k)" auto "$f"
    product=$(echo "$QLINE" | sed -n 's/.*product \([0-9.e+]*\) .*/\1/p')
    if [ -n "$product" ] && awk "BEGIN { exit !($product <= $SIMPLE_MAX) }"; then
        simple "${family}($n,$k)" "$f"
        printf '%-28s %-9s auto -q is %sx the simple Rust reference\n' "${family}($n,$k)" ratio \
            "$(ratio "$QCPU" "$SCPU")"
    fi
done
echo "== bar: the line family at 10^12 product states in under 60 s"
"$GEN" line 16 "$TMP/line_16.sc"
for engine in auto symbolic; do quiet line_16 "$engine" "$TMP/line_16.sc"; done
echo "== bar: no instance under 10^5 reachable states takes the symbolic engine more than 2 s"
worst=0 worst_at=-
for fk in "tl ${K_TL:-3}" "dp ${K_DP:-2}" "cm ${K_CM:-2}" "at ${K_AT:-3}" "bw ${K_BW:-3}" "ta ${K_TA:-3}" \
          "line 0" "philosophers 0"; do
    set -- $fk
    family=$1 k=$2 n=2
    while [ "$n" -le 40 ]; do
        f=$TMP/small.sc
        if [ "$k" = 0 ]; then "$GEN" "$family" "$n" "$f"; else "$GEN" "$family" "$n" "$k" "$f"; fi || break
        # The explicit engine's count of reachable states decides (fast below 10^5).
        "$BIN" synth -q --engine explicit --max-states 100000 "$f" >"$TMP/o" 2>&1
        product=$(sed -n 's/.*product \([0-9.e+]*\) .*/\1/p' "$TMP/o")
        [ -n "$product" ] && awk "BEGIN { exit !($product < 100000) }" || break
        $TIME -f "%U %S %M" -o "$TMP/t" "$BIN" synth -q --engine symbolic --timeout "$LIMIT" "$f" >"$TMP/o" 2>&1
        c=$(cpu_of "$TMP/t")
        label="$family($n,$k)"
        [ "$k" = 0 ] && label="${family}_$n"
        if awk "BEGIN { exit !($c > $worst) }"; then worst=$c worst_at="$label, product $product"; fi
        n=$((n + 1))
    done
done
echo "largest symbolic -q CPU time under 10^5 reachable states: ${worst} s ($worst_at)"
fi
