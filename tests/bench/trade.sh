#!/bin/sh
# trade.sh: the speed/accuracy trade of every knob, measured (`make trade`).
#
# For samples per pixel (1 to 256, against 1024), ambient occlusion and
# global illumination rays (1 to 1024, against 4096), the maximum depth (0 to
# 20, against 50) and the cut-off (against no cut-off), it renders example
# scenes, times them (median of TRADE_RUNS, default 3) and measures the
# error: on the 8-bit output, the share of channels that differ and the
# largest difference; on the linear PFM, the root mean square difference
# (in 8-bit levels). Then the precision: the single-precision build against
# the double one, side by side, on scenes near the origin, far from it, and
# at huge and tiny scales. Writes docs/trade.md and its plots
# docs/trade-*.svg.
#
# Usage: sh tests/bench/trade.sh RAYTRACE RAYTRACE-DIFF RAYTRACE-FLOAT SCENEGEN [OUT.md]
# Environment: TRADE_RUNS (runs per measure, default 3), TRADE_ONLY (a
# subset of: spp indirect depth cut precision; the others keep their last
# rows).

RT=$1
DIFF=$2
RT_FLOAT=$3
GEN=$4
OUT=${5:-docs/trade.md}
RUNS=${TRADE_RUNS:-3}
ONLY=${TRADE_ONLY:-"spp indirect depth cut precision"}
DIR=build/trade
PLOT=tests/bench/plot.awk
DOCS=$(dirname "$OUT")
mkdir -p "$DIR" || exit 2

. tests/lib.sh

# timed NAME OPTIONS...: renders to $DIR/NAME.ppm RUNS times and prints the
# median wall time in seconds; also renders $DIR/NAME.pfm once unless
# pfm=0.
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
    [ "${pfm:-1}" = 0 ] || "$RT" -q "$@" "$DIR/$name.pfm" || exit 1
    echo "$(median <"$DIR/times") / 1000" | bc -l
}

# error REF NAME: "channels% max rmse" of $DIR/NAME against $DIR/REF.
error() {
    "$DIFF" "$DIR/$1.ppm" "$DIR/$2.ppm" >"$DIR/d8" 2>&1
    "$DIFF" "$DIR/$1.pfm" "$DIR/$2.pfm" >"$DIR/df" 2>&1
    pct=$(sed -n 's/^channels over tolerance 0: [0-9]* of [0-9]* (\(.*\)%)$/\1/p' "$DIR/d8")
    max=$(sed -n 's/^max error: \([0-9.e+-]*\).*/\1/p' "$DIR/d8")
    rms=$(sed -n 's/^mean error: .*, RMS error: \([0-9.e+-]*\),.*/\1/p' "$DIR/df")
    echo "$pct $max $rms"
}

# wanted SECTION: whether TRADE_ONLY includes it.
wanted() { case " $ONLY " in *" $1 "*) return 0 ;; esac; return 1; }

# --- samples per pixel: glass.txt at 240 pixels wide ---
resize scenes/glass.txt 240 >scenes/.trade-glass.txt
trap 'rm -f scenes/.trade-glass.txt' EXIT
scene=scenes/.trade-glass.txt
if wanted spp; then
echo "trade: samples per pixel" >&2
timed spp-ref --spp 1024 "$scene" >/dev/null || exit 1
: >"$DIR/spp.rows"
: >"$DIR/spp.plot"
for n in 1 2 4 8 16 32 64 128 256; do
    t=$(timed "spp-$n" --spp "$n" "$scene") || exit 1
    set -- $(error spp-ref "spp-$n")
    printf '| %d | %.3f s | %s%% | %s | %s |\n' "$n" "$t" "$1" "$2" "$3" >>"$DIR/spp.rows"
    echo "RMSE $t $3 $n" >>"$DIR/spp.plot"
done
awk -v title="Samples per pixel: error against time (glass.txt, 240 x 160)" \
    -v xlabel="render time, s" -v ylabel="RMSE against 1024 samples, levels" -v logx=1 -v logy=1 \
    -f "$PLOT" "$DIR/spp.plot" >"$DOCS/trade-spp.svg"
fi

# --- ambient occlusion and global illumination: scenes/indirect.txt at
# 200 x 200, N = 1 to 1024 rays a point against 4096 ---
sed 's/^c Camera \(.*\) 400 400$/c Camera \1 200 200/' scenes/indirect.txt >"$DIR/indirect.txt"
if wanted indirect; then
echo "trade: ambient occlusion and global illumination" >&2
: >"$DIR/indirect.rows"
: >"$DIR/indirect.plot"
for k in ao gi; do
    "$RT" -q "--$k" 4096 "$DIR/indirect.txt" "$DIR/$k-ref.pfm" || exit 1
    "$RT" -q "--$k" 4096 "$DIR/indirect.txt" "$DIR/$k-ref.ppm" || exit 1
    for n in 1 2 4 8 16 32 64 128 256 512 1024; do
        t=$(timed "$k-$n" "--$k" "$n" "$DIR/indirect.txt") || exit 1
        set -- $(error "$k-ref" "$k-$n")
        printf '| %s | %d | %.3f s | %s%% | %s | %s |\n' "$(echo "$k" | tr a-z A-Z)" "$n" "$t" \
            "$1" "$2" "$3" >>"$DIR/indirect.rows"
        echo "$(echo "$k" | tr a-z A-Z) $t $3 $n" >>"$DIR/indirect.plot"
    done
done
awk -v title="Ambient occlusion and global illumination: error against time (indirect.txt, 200 x 200)" \
    -v xlabel="render time, s" -v ylabel="RMSE against 4096 rays, levels" -v logx=1 -v logy=1 \
    -f "$PLOT" "$DIR/indirect.plot" >"$DOCS/trade-indirect.svg"
fi

# --- maximum depth: facing mirrors and a ring of mirror balls ---
if wanted depth; then
echo "trade: maximum depth" >&2
: >"$DIR/depth.rows"
: >"$DIR/depth.plot"
for s in corridor mirrors; do
    timed "$s-d50" --cutoff 0 -d 50 "scenes/$s.txt" >/dev/null || exit 1
    for d in 0 1 2 3 4 5 6 8 10 12 15 20; do
        t=$(timed "$s-d$d" --cutoff 0 -d "$d" "scenes/$s.txt") || exit 1
        set -- $(error "$s-d50" "$s-d$d")
        printf '| %s | %d | %.3f s | %s%% | %s | %s |\n' "$s" "$d" "$t" "$1" "$2" "$3" >>"$DIR/depth.rows"
        echo "$s $t $3 $d" >>"$DIR/depth.plot"
    done
done
awk -v title="Maximum depth: error against time" -v xlabel="render time, s" \
    -v ylabel="RMSE against depth 50, levels" -v logy=1 \
    -f "$PLOT" "$DIR/depth.plot" >"$DOCS/trade-depth.svg"
fi

# --- the cut-off: time only, the bytes never change ---
if wanted cut; then
echo "trade: cut-off" >&2
pfm=0
: >"$DIR/cut.rows"
: >"$DIR/cut.plot"
"$GEN" spheres 100000 | resize /dev/stdin 480 >"$DIR/field-cut.txt" || exit 1
for s in glass keyword field; do
    f=scenes/$s.txt depths="10 30"
    [ $s = field ] && f=$DIR/field-cut.txt depths=10
    for d in $depths; do
        for c in 0 0.000001 0.0001 0.001 0.01 0.02 0.05 0.1 1; do
            t=$(timed "$s-c" --cutoff "$c" -d "$d" "$f") || exit 1
            [ "$c" = 0 ] && cp "$DIR/$s-c.ppm" "$DIR/$s-c0.ppm"
            cmp -s "$DIR/$s-c0.ppm" "$DIR/$s-c.ppm" && same=yes || same=NO
            "$RT" -v --cutoff "$c" -d "$d" "$f" "$DIR/$s-v.ppm" 2>"$DIR/v"
            left=$(sed -n 's/.*: \([0-9]*\) rays left out.*/\1/p' "$DIR/v")
            again=$(sed -n 's/.*, \([0-9]*\) pixels refined/\1/p' "$DIR/v")
            printf '| %s | %d | %s | %.3f s | %s | %s | %s |\n' "$s" "$d" "$c" "$t" "${left:-0}" \
                "${again:-0}" "$same" >>"$DIR/cut.rows"
            [ "$c" = 0 ] || echo "$s-depth-$d $c $t" >>"$DIR/cut.plot"
        done
    done
done
awk -v title="Cut-off: render time (the bytes never change)" -v xlabel="cut-off, levels" \
    -v ylabel="render time, s" -v logx=1 -v logy=1 -f "$PLOT" "$DIR/cut.plot" >"$DOCS/trade-cutoff.svg"
pfm=1
fi

# transform FILE SCALE SHIFT: a course scene (camera, corners, light and
# spheres only) with every point p moved to SCALE p + SHIFT and every
# radius to SCALE r.
transform() {
    awk -v s="$2" -v d="$3" '
        function point(i) { $i = sprintf("%.17g", $i * s + d); $(i + 1) = sprintf("%.17g", $(i + 1) * s + d)
                            $(i + 2) = sprintf("%.17g", $(i + 2) * s + d) }
        { sub(/#.*/, "") }
        !/[^ \t]/ { next }
        { n++ }
        n <= 4 || n == 7 { point(1) }
        $1 == "sphere:" { point(2); $5 = sprintf("%.17g", $5 * s) }
        { print }' "$1"
}

# pair NAME SCENE OPTIONS...: renders SCENE with the double and the float
# build, run for run alternately RUNS times; prints "double-s float-s" (the
# medians) and leaves NAME-double.ppm/.pfm and NAME-float.ppm/.pfm.
pair() {
    name=$1
    shift
    : >"$DIR/times-double"
    : >"$DIR/times-float"
    i=0
    while [ $i -lt "$RUNS" ]; do
        for b in double float; do
            [ $b = double ] && bin=$RT || bin=$RT_FLOAT
            start=$(now)
            "$bin" -q "$@" "$DIR/$name-$b.ppm" || exit 1
            end=$(now)
            echo $(((end - start) / 1000000)) >>"$DIR/times-$b"
        done
        i=$((i + 1))
    done
    "$RT" -q "$@" "$DIR/$name-double.pfm" || exit 1
    "$RT_FLOAT" -q "$@" "$DIR/$name-float.pfm" || exit 1
    echo "$(median <"$DIR/times-double") $(median <"$DIR/times-float")"
}

# --- precision: the float build against the double one ---
if wanted precision; then
echo "trade: precision" >&2
: >"$DIR/real.rows"
"$GEN" spheres 1000 | resize /dev/stdin 960 >"$DIR/field.txt" || exit 1
transform scenes/course.txt 1 0 | resize /dev/stdin 1200 >"$DIR/course-1.txt"
transform scenes/course.txt 0.0001 0 | resize /dev/stdin 1200 >"$DIR/course-tiny.txt"
transform scenes/course.txt 1000000 0 | resize /dev/stdin 1200 >"$DIR/course-huge.txt"
transform scenes/course.txt 1 10000000 | resize /dev/stdin 1200 >"$DIR/course-far.txt"
transform scenes/course.txt 0.000001 1 | resize /dev/stdin 1200 >"$DIR/course-far-tiny.txt"
for s in course-1 course-tiny course-huge course-far course-far-tiny field mirrors keyword obj; do
    case $s in
    mirrors | keyword | obj) f=scenes/$s.txt ;;
    *) f=$DIR/$s.txt ;;
    esac
    set -- $(pair "real-$s" "$f") || exit 1
    td=$1 tf=$2
    set -- $(error "real-$s-double" "real-$s-float")
    printf '| %s | %.3f s | %.3f s | %.2f | %s%% | %s | %s |\n' "$s" "$(echo "$td / 1000" | bc -l)" \
        "$(echo "$tf / 1000" | bc -l)" "$(echo "$td / $tf" | bc -l)" "$1" "$2" "$3" >>"$DIR/real.rows"
done
fi
# The plot: each scene a point, float's time over double's against its RMSE.
if [ -s "$DIR/real.rows" ]; then
    awk -F' *[|] *' '{ sub(/ s$/, "", $3); sub(/ s$/, "", $4); print $2, $4 / $3, $8, $2 }' \
        "$DIR/real.rows" >"$DIR/real.plot"
    awk -v title="Float against double: time and error, per scene" \
        -v xlabel="float's time / double's" -v ylabel="RMSE against double, levels" -v logy=1 \
        -f "$PLOT" "$DIR/real.plot" >"$DOCS/trade-precision.svg"
fi

# Where the noise drops below what 8-bit output shows (1 level of RMSE),
# and the slope of log RMSE against log N (plain Monte Carlo: -0.5).
[ -s "$DIR/indirect.plot" ] &&
    awk '{ k = $1; n[k]++; t[k, n[k]] = $2; e[k, n[k]] = $3; c[k, n[k]] = $4 }
    END { for (k in n) {
        one = ""
        for (i = 1; i <= n[k]; i++) if (one == "" && e[k, i] <= 1) one = sprintf("%d (%.3f s)", c[k, i], t[k, i])
        slope = (log(e[k, n[k]]) - log(e[k, 1])) / (log(c[k, n[k]]) - log(c[k, 1]))
        printf "| %s | %s | %.2f |\n", k, one == "" ? "not within 1024" : one, slope } }' \
        "$DIR/indirect.plot" | sort >"$DIR/knee.rows"

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -1)
{
    echo "# The speed/accuracy trade, measured"
    echo
    echo "Written by \`make trade\` (tests/bench/trade.sh) on $(date -u +%Y-%m-%d), on"
    echo "${cpu:-an unknown CPU} with $(nproc) thread(s); times are medians of $RUNS runs of the"
    echo "whole command, all threads. Error on the 8-bit output: the share of"
    echo "channels that differ from the reference and the largest difference; on"
    echo "the linear PFM output (colours before clamping and rounding): the root"
    echo "mean square difference, in 8-bit levels."
    echo
    echo "## Samples per pixel"
    echo
    echo "scenes/glass.txt at 240 × 160 (glass, a mirror, a checker texture:"
    echo "edges, refraction and texture aliasing), against 1024 samples per pixel."
    echo
    echo "![samples per pixel](trade-spp.svg)"
    echo
    echo "| samples | time | channels that differ | largest difference | RMSE (linear) |"
    echo "|---------|------|----------------------|--------------------|---------------|"
    cat "$DIR/spp.rows"
    echo
    echo "## Ambient occlusion and global illumination"
    echo
    echo "scenes/indirect.txt at 200 × 200 (a room of matte walls, a cube, clay,"
    echo "plastic and chrome balls, a ranged point light, ambient light 0.3),"
    echo "rendered with \`--ao N\` and with \`--gi N\` (one bounce), each against"
    echo "4096 rays of its own kind. The rays of a point are cosine-weighted and"
    echo "stratified: the N rays of each of a pixel's samples are N points of one"
    echo "multi-jittered pattern of N × samples, carried to the hemisphere by"
    echo "Malley's method (the disk's concentric map lifted), so that they cover"
    echo "it evenly and their cosine needs no weight. A gathering ray's hit takes"
    echo "its direct light through shadow rays (next-event estimation), never by"
    echo "waiting to hit the light. Plain Monte Carlo's RMSE falls as N^-0.5;"
    echo "the slope column is the measured exponent from N = 1 to 1024."
    echo
    echo "![ambient occlusion and global illumination](trade-indirect.svg)"
    echo
    echo "| knob | N | time | channels that differ | largest difference | RMSE (linear) |"
    echo "|------|---|------|----------------------|--------------------|---------------|"
    cat "$DIR/indirect.rows"
    echo
    echo "There is no knee in the usual sense: each doubling of N cuts the RMSE by"
    echo "about 40% all the way, a power law whose exponent (the slope, from N = 1"
    echo "to 1024) stratification brings from plain Monte Carlo's -0.5 to about"
    echo "-0.74. The useful stopping point is where the noise drops below what"
    echo "8-bit output shows, 1 level of RMSE:"
    echo
    echo "| knob | RMSE ≤ 1 level at N (time) | slope of log RMSE / log N |"
    echo "|------|----------------------------|---------------------------|"
    cat "$DIR/knee.rows"
    echo
    echo "## Maximum depth"
    echo
    echo "scenes/corridor.txt (two facing mirrors) and scenes/mirrors.txt (a ring"
    echo "of mirror balls), against depth 50, with \`--cutoff 0\` so that the"
    echo "time is the depth's alone."
    echo
    echo "![maximum depth](trade-depth.svg)"
    echo
    echo "| scene | depth | time | channels that differ | largest difference | RMSE (linear) |"
    echo "|-------|-------|------|----------------------|--------------------|---------------|"
    cat "$DIR/depth.rows"
    echo
    echo "## The cut-off"
    echo
    echo "\`--cutoff L\` leaves out rays that could add less than L levels; in the"
    echo "pixels it cannot prove unchanged it traces them after all, with"
    echo "cut-offs 16 times smaller, and at last traces the pixel in full"
    echo "(docs/design.md), so the error is always 0: the last column checks"
    echo "that the bytes equal the render without the cut-off. What it trades is"
    echo "time: rays left out for good against pixels refined (whose left-out"
    echo "rays were traced). \`field\` is the benchmark's 100,000-sphere field"
    echo "at 480 × 270 (reflection 0.3: a ray at depth k weighs 0.3^k). Times are"
    echo "the whole command's (medians of $RUNS runs), reading and building"
    echo "included."
    echo
    echo "![cut-off](trade-cutoff.svg)"
    echo
    echo "| scene | depth | cut-off | time | rays left out | pixels refined | same bytes |"
    echo "|-------|-------|---------|------|---------------|---------------------|------------|"
    cat "$DIR/cut.rows"
    echo
    echo "## Precision: float against double"
    echo
    echo "\`make REAL=float\` computes the geometry (points, directions, ray"
    echo "parameters, intersections, error bounds, the hierarchy's boxes) in"
    echo "single precision; colours stay double (include/math/real.h). Each scene is"
    echo "rendered by both builds, run for run alternately; the error is the float"
    echo "render's against the double one. The course scene is also shown"
    echo "scaled by 10^-4 and 10^6, moved 10^7 away on each axis, and both shrunk"
    echo "to 10^-6 and moved 1 away, all at 1200 × 1200; \`field\` is the"
    echo "benchmark's 1,000-sphere field at 960 × 540."
    echo
    echo "![precision](trade-precision.svg)"
    echo
    echo "| scene | double | float | speed-up | channels that differ | largest difference | RMSE (linear) |"
    echo "|-------|--------|-------|----------|----------------------|--------------------|---------------|"
    cat "$DIR/real.rows"
} >"$OUT"
echo "trade: wrote $OUT" >&2
