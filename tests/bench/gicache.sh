#!/bin/sh
# gicache.sh: the irradiance cache's error against time (`make trade-cache`,
# part of `make trade`).
#
# On scenes/room.txt (the course format's closed room, with one bounce and
# with three), scenes/indirect.txt and scenes/cache-hard.txt (a thin wall,
# a narrow gap, small bright balls), each at 200 x 200, it renders a
# converged reference (uniform, GICACHE_REF samples a pixel, 64 rays each),
# then uniform sampling (-s N --gi 16), --noise and --gi-cache at several
# accuracies E (-s 16, 2048 rays a record), timing each (median of
# GICACHE_RUNS, default 3, the whole command) and measuring the 8-bit
# picture against the reference: its RMSE and the error its worst 1% of
# pixels pass (raytrace-diff's). For each scene, the cache's default (E
# 0.3) against uniform sampling at the same RMSE: uniform's time there
# read off its curve (log-log between the two points around it). Writes
# docs/gicache.md and its plot docs/gicache.svg.
#
# Usage: sh tests/bench/gicache.sh RAYTRACE RAYTRACE-DIFF [OUT.md]

RT=$1
DIFF=$2
OUT=${3:-docs/gicache.md}
RUNS=${GICACHE_RUNS:-3}
REF=${GICACHE_REF:-128}
DIR=build/gicache
mkdir -p "$DIR" || exit 2
. tests/lib.sh

# timed NAME OPTIONS...: renders $DIR/NAME.ppm RUNS times; prints the
# median wall time in seconds.
timed() {
    name=$1
    shift
    : >"$DIR/times"
    i=0
    while [ $i -lt "$RUNS" ]; do
        start=$(now)
        "$RT" -q "$@" "$DIR/$name.ppm" || exit 1
        end=$(now)
        echo $(((end - start) / 1000000)) >>"$DIR/times"
        i=$((i + 1))
    done
    echo "$(median <"$DIR/times") / 1000" | bc -l
}

# errors REF NAME: "RMSE WORST" of $DIR/NAME.ppm against the clamped
# reference: the RMS error and the error the worst 1% of pixels pass.
errors() {
    "$DIFF" --clamp "$DIR/$1.pfm" "$DIR/$2.ppm" 2>&1 | awk '
        /^mean error:/ { sub(/.*RMS error: /, ""); sub(/,.*/, ""); rmse = $0 }
        /^worst 1% of pixels:/ { sub(/.*error over (at least )?/, ""); worst = $1 }
        END { print rmse, worst }'
}

: >"$DIR/rows"
: >"$DIR/plot"
: >"$DIR/ratios"
for run in "room 1" "room 3" "indirect 1" "cache-hard 1"; do
    set -- $run
    s=$1
    b=$2
    key="$s-b$b"
    echo "gicache: $s, $b bounce(s)" >&2
    "$RT" -q --size 200x200 -s "$REF" --gi 64 --gi-bounces "$b" --format pfm "scenes/$s.txt" \
        "$DIR/$key-ref.pfm" || exit 1
    : >"$DIR/curve"
    while read -r label opts; do
        # shellcheck disable=SC2086
        t=$(timed "$key-x" --size 200x200 --gi-bounces "$b" $opts "scenes/$s.txt") || exit 1
        set -- $(errors "$key-ref" "$key-x")
        printf '| %s | %s | `%s` | %.2f s | %s | %s |\n' "$s" "$b" "$opts" "$t" "$1" "$2" >>"$DIR/rows"
        echo "$key-$label $t $1" >>"$DIR/plot"
        echo "$label $t $1" >>"$DIR/curve"
    done <<LIST
uniform -s 8 --gi 16
uniform -s 16 --gi 16
uniform -s 32 --gi 16
uniform -s 64 --gi 16
noise --noise 2 --gi 8
cache -s 16 --gi 2048 --gi-cache --gi-cache-error 0.5
default -s 16 --gi 2048 --gi-cache --gi-cache-error 0.3
cache -s 16 --gi 2048 --gi-cache --gi-cache-error 0.2
LIST
    # Uniform's time at the default cache's RMSE, on uniform's curve.
    awk -v scene="$s" -v bounces="$b" '
        $1 == "uniform" { n++; t[n] = $2; e[n] = $3 }
        $1 == "default" { ct = $2; ce = $3 }
        END {
            for (i = 1; i < n; i++)
                if (e[i] >= ce && e[i + 1] <= ce) {
                    f = (log(ce) - log(e[i])) / (log(e[i + 1]) - log(e[i]))
                    ut = exp(log(t[i]) + f * (log(t[i + 1]) - log(t[i])))
                }
            if (ut > 0)
                printf "| %s | %s | %.3f | %.2f s | %.2f s | %.2f |\n", scene, bounces, ce, ct, ut, ct / ut
            else
                printf "| %s | %s | %.3f | %.2f s | beyond -s 8 to -s 64 | |\n", scene, bounces, ce, ct
        }' "$DIR/curve" >>"$DIR/ratios"
done
awk -v title="Irradiance cache against uniform sampling and --noise (200 x 200)" \
    -v xlabel="render time, s" -v ylabel="RMSE against the converged render, levels" -v logx=1 -v logy=1 \
    -f tests/bench/plot.awk "$DIR/plot" >"$(dirname "$OUT")/gicache.svg"
{
    echo "# The irradiance cache: error against time"
    echo
    echo "Written by \`make trade-cache\` (tests/bench/gicache.sh) on $(uname -m), $(nproc) threads,"
    echo "$(date -u +%Y-%m-%d). Each scene at 200 × 200 against a uniform render of $REF"
    echo "samples a pixel and 64 rays (with the same bounces); time: the median of"
    echo "$RUNS runs of the whole command, every row measured in this one run. RMSE:"
    echo "the 8-bit picture against the reference's colours clamped to 0..255, in"
    echo "levels; worst 1%: the error that 1% of the pixels pass (each pixel's the"
    echo "RMS of its channels), as raytrace-diff prints it."
    echo
    echo "The cache's default (\`-s 16 --gi-cache\`: 2048 rays a record, E 0.3)"
    echo "against uniform sampling at the same RMSE (uniform's time read off its"
    echo "curve, log-log between the two -s around it):"
    echo
    echo "| scene | bounces | cache's RMSE | cache's time | uniform's time at that RMSE | ratio |"
    echo "|-------|---------|--------------|--------------|-----------------------------|-------|"
    cat "$DIR/ratios"
    echo
    echo "At -s 16 the anti-aliasing alone (the camera's 16 samples against the"
    echo "reference's $REF) is most of the error on these scenes: the cache's own"
    echo "error is what it adds to it."
    echo
    echo "![error against time](gicache.svg)"
    echo
    echo "| scene | bounces | options | time | RMSE | worst 1% |"
    echo "|-------|---------|---------|------|------|----------|"
    cat "$DIR/rows"
} >"$OUT"
echo "gicache: wrote $OUT" >&2
