#!/bin/sh
# gicache.sh: the irradiance cache's error against time (`make trade-cache`,
# part of `make trade`).
#
# On scenes/room.txt (the course format's closed room) and
# scenes/indirect.txt, both at 200 x 200 with one bounce, it renders a
# converged reference (uniform, GICACHE_REF samples a pixel, 64 rays each),
# then uniform sampling (-s N --gi 16), --noise and --gi-cache at several
# accuracies E (-s 16, 256 rays a record), timing each (median of
# GICACHE_RUNS, default 3) and measuring the RMSE of the 8-bit picture
# against the reference. Writes
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

# rmse REF NAME: the RMSE of $DIR/NAME.ppm against the clamped reference.
rmse() {
    "$DIFF" --clamp "$DIR/$1.pfm" "$DIR/$2.ppm" 2>&1 |
        sed -n 's/^mean error: .*, RMS error: \([0-9.e+-]*\),.*/\1/p'
}

: >"$DIR/rows"
: >"$DIR/plot"
for s in room indirect; do
    echo "gicache: $s" >&2
    "$RT" -q --size 200x200 -s "$REF" --gi 64 --format pfm "scenes/$s.txt" "$DIR/$s-ref.pfm" || exit 1
    while read -r label opts; do
        # shellcheck disable=SC2086
        t=$(timed "$s-x" --size 200x200 $opts "scenes/$s.txt") || exit 1
        e=$(rmse "$s-ref" "$s-x")
        printf '| %s | `%s` | %.3f s | %s |\n' "$s" "$opts" "$t" "$e" >>"$DIR/rows"
        echo "$s-$label $t $e" >>"$DIR/plot"
    done <<LIST
uniform -s 8 --gi 16
uniform -s 16 --gi 16
uniform -s 32 --gi 16
noise --noise 2 --gi 8
cache -s 16 --gi 256 --gi-cache --gi-cache-error 0.4
cache -s 16 --gi 256 --gi-cache --gi-cache-error 0.2
cache -s 16 --gi 256 --gi-cache --gi-cache-error 0.1
cache2 -s 16 --gi 256 --gi-cache --gi-bounces 3
uniform2 -s 16 --gi 16 --gi-bounces 3
LIST
done
awk -v title="Irradiance cache against uniform sampling and --noise (200 x 200)" \
    -v xlabel="render time, s" -v ylabel="RMSE against the converged render, levels" -v logx=1 -v logy=1 \
    -f tests/bench/plot.awk "$DIR/plot" >"$(dirname "$OUT")/gicache.svg"
{
    echo "# The irradiance cache: error against time"
    echo
    echo "Written by \`make trade-cache\` (tests/bench/gicache.sh) on $(uname -m), $(nproc) threads,"
    echo "$(date -u +%Y-%m-%d). Each scene at 200 × 200, one bounce unless said, against a"
    echo "uniform render of $REF samples a pixel and 64 rays; time: the median of $RUNS runs"
    echo "of the whole command, measured side by side in one run. RMSE: the 8-bit"
    echo "picture against the reference's colours clamped to 0..255, in levels."
    echo
    echo "![error against time](gicache.svg)"
    echo
    echo "| scene | options | time | RMSE |"
    echo "|-------|---------|------|------|"
    cat "$DIR/rows"
} >"$OUT"
echo "gicache: wrote $OUT" >&2
