#!/bin/sh
# tiles.sh: what cutting a render into tiles costs (docs/distributed.md).
#
#  1. Load balance: make bench's 1,000-sphere field (1920 x 1080) as 8
#     tiles, each rendered alone, one after another (median of RUNS), in
#     the rows and the bands layout: the slowest tile against the mean.
#  2. Scale: the 1,000,000-sphere field whole, then as N = 1, 2, 4, 8 tiles
#     one after another: the sum of the tiles' times against the whole's,
#     and each tile's reading and building (from -v).
#  3. The merge: raytrace-merge's time and peak memory on the 8 tiles of
#     the 1,000-sphere field, at 1920 x 1080 and at 7680 x 4320.
# Prints the tables (markdown) on standard output.
#
# Usage: sh tests/bench/tiles.sh RAYTRACE RAYTRACE-MERGE SCENEGEN
# Environment: BENCH_RUNS (runs per measure, default 3).

RT=$1
MERGE=$2
GEN=$3
RUNS=${BENCH_RUNS:-3}
DIR=build/bench-tiles
mkdir -p "$DIR" || exit 2
. tests/lib.sh

# ms CMD...: runs CMD RUNS times; prints the median wall time in ms.
ms() {
    : >"$DIR/times"
    i=0
    while [ $i -lt "$RUNS" ]; do
        start=$(now)
        "$@" || exit 1
        end=$(now)
        echo $(((end - start) / 1000000)) >>"$DIR/times"
        i=$((i + 1))
    done
    median <"$DIR/times"
}

[ -s "$DIR/s1k.txt" ] || "$GEN" spheres 1000 >"$DIR/s1k.txt"
[ -s "$DIR/s1m.txt" ] || "$GEN" spheres 1000000 >"$DIR/s1m.txt"

echo "| layout | tile times (ms) | mean | slowest | slowest / mean |"
echo "|--------|-----------------|------|---------|----------------|"
for layout in rows bands; do
    list=
    : >"$DIR/tile-ms"
    k=1
    while [ $k -le 8 ]; do
        t=$(ms "$RT" -q --tile $k/8 --tile-layout $layout "$DIR/s1k.txt" "$DIR/t-$k.ppm")
        echo "$t" >>"$DIR/tile-ms"
        list="$list${list:+, }$t"
        k=$((k + 1))
    done
    awk -v layout=$layout -v list="$list" '{ s += $1; if ($1 > m) m = $1 }
        END { printf "| %s | %s | %.0f | %d | %.2f |\n", layout, list, s / NR, m, m / (s / NR) }' \
        "$DIR/tile-ms"
done
echo

echo "| tiles | sum of the tiles' times | against the whole | reading and building, each tile |"
echo "|-------|-------------------------|-------------------|---------------------------------|"
whole=$(ms "$RT" -q "$DIR/s1m.txt" "$DIR/whole.ppm")
echo "| whole | $whole ms | 1.00 | |"
for n in 1 2 4 8; do
    sum=0
    k=1
    while [ $k -le $n ]; do
        t=$(ms "$RT" -q --tile $k/$n "$DIR/s1m.txt" "$DIR/m-$k.ppm")
        sum=$((sum + t))
        k=$((k + 1))
    done
    "$RT" -v --tile 1/$n "$DIR/s1m.txt" "$DIR/m-1.ppm" 2>"$DIR/log"
    setup=$(awk '/read the scene in/ { r = $6 } /built in/ { for (i = NF; i > 1; i--) if ($i == "built") b += $(i + 2) }
        END { printf "%.0f ms", (r + b) * 1000 }' "$DIR/log")
    echo "| $n | $sum ms | $(echo "scale=2; $sum / $whole" | bc) | $setup |"
done
echo

echo "| picture | tiles | merge time | merge peak memory |"
echo "|---------|-------|------------|-------------------|"
for size in 1920 7680; do
    sed "6s/^1920\$/$size/" "$DIR/s1k.txt" >"$DIR/s1k-$size.txt"
    k=1
    while [ $k -le 8 ]; do
        "$RT" -q --tile $k/8 "$DIR/s1k-$size.txt" "$DIR/w-$k.ppm" || exit 1
        k=$((k + 1))
    done
    t=$(ms "$MERGE" -q "$DIR/merged.png" "$DIR"/w-*.ppm)
    peak=$( (command time -f %M "$MERGE" -q "$DIR/merged.ppm" "$DIR"/w-*.ppm) 2>&1 | tail -n 1)
    h=$(sed -n 2p "$DIR/w-1.ppm" >/dev/null; "$RT" --check "$DIR/s1k-$size.txt" 2>&1 | sed -n 's/.*: OK: \([0-9]* x [0-9]*\) pixels.*/\1/p')
    echo "| $h | 8 | $t ms (to PNG) | $((peak / 1024)) MB |"
done
