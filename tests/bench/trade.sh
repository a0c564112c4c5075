#!/bin/sh
# trade.sh: the speed/accuracy trade of every knob, measured (`make trade`).
#
# For samples per pixel (1 to 256, against 1024), ambient occlusion and
# global illumination rays (1 to 1024, against 4096), adaptive sampling
# (--noise L against uniform N, four scenes, each against a converged
# render), texture filtering (mip-maps and ray differentials against
# unfiltered lookups, on the floor beyond ten units), the maximum depth (0 to 20, against 50) and the cut-off
# (against no cut-off), it renders example
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
# subset of: spp indirect noise texture depth cut precision; the others
# keep their last rows).

RT=$1
DIFF=$2
RT_FLOAT=$3
GEN=$4
OUT=${5:-docs/trade.md}
RUNS=${TRADE_RUNS:-3}
ONLY=${TRADE_ONLY:-"spp indirect noise texture depth cut precision"}
DIR=build/trade
PLOT=tests/bench/plot.awk
DOCS=$(dirname "$OUT")
mkdir -p "$DIR" || exit 2

. tests/lib.sh

# timed NAME OPTIONS...: renders to $DIR/NAME.ppm RUNS times and prints the
# median wall time in seconds; also renders $DIR/NAME.pfm once unless
# pfm=0.
timed() {
    seconds=$(time_renders "$@") || exit 1
    name=$1
    shift
    [ "${pfm:-1}" = 0 ] || "$RT" -q "$@" "$DIR/$name.pfm" || exit 1
    echo "$seconds"
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

# --- adaptive sampling: --noise L against uniform N samples a pixel, four
# scenes, each against a converged render (uniform, many samples). The
# error is what the user sees: the 8-bit render against the reference's
# colours clamped to 0..255 (its rounding, 0.29 levels RMS, included). ---
# noise_scene NAME: sets $opts (size and options), $ref (the reference's
# samples), $uniform (the N tried) for scene NAME.
noise_scene() {
    case $1 in
    indirect) opts="--size 200x200 --gi 16" ref=1024 uniform="2 4 8 16 32 64 128" ;;
    focus) opts="--size 240x160" ref=16384 uniform="4 8 16 32 64 128 256 512" ;;
    materials) opts="--size 240x150" ref=8192 uniform="1 2 4 8 16 32 64 128 256" ;;
    course) opts="--size 200x200" ref=16384 uniform="1 2 4 8 16 32 64 128 256" ;;
    esac
}
# rmse REF IMAGE [MASK]: the RMS difference, the 8-bit IMAGE against the
# clamped REF (over MASK's pixels that are not black, when given).
rmse() {
    if [ -n "$3" ]; then "$DIFF" --clamp --only "$3" "$DIR/$1" "$DIR/$2"; else "$DIFF" --clamp "$DIR/$1" "$DIR/$2"; fi |
        sed -n 's/^mean error: .*, RMS error: \([0-9.e+-]*\),.*/\1/p'
}
if wanted noise; then
echo "trade: adaptive sampling" >&2
pfm=0
: >"$DIR/noise.rows"
: >"$DIR/honest.rows"
: >"$DIR/refnoise.rows"
for s in indirect focus materials course; do
    noise_scene $s
    # shellcheck disable=SC2086
    "$RT" -q $opts -s "$ref" --format pfm "scenes/$s.txt" "$DIR/nz-$s-ref.pfm" || exit 1
    # The reference's own error: against a quarter of its samples, whose
    # error is at least twice its own (RMSE falls at least as N^-0.5), the
    # difference d is at least sqrt(5) times it: d / sqrt(5) bounds it.
    # shellcheck disable=SC2086
    "$RT" -q $opts -s $((ref / 4)) --format pfm "scenes/$s.txt" "$DIR/nz-$s-refq.pfm" || exit 1
    d=$("$DIFF" "$DIR/nz-$s-ref.pfm" "$DIR/nz-$s-refq.pfm" |
        sed -n 's/^mean error: .*, RMS error: \([0-9.e+-]*\),.*/\1/p')
    printf '| %s | %d | %.3f | %.3f |\n' "$s" "$ref" "$d" "$(echo "$d / sqrt(5)" | bc -l)" \
        >>"$DIR/refnoise.rows"
    : >"$DIR/noise-$s.plot"
    for n in $uniform; do
        # shellcheck disable=SC2086
        t=$(timed "nz-$s-u$n" $opts -s "$n" "scenes/$s.txt") || exit 1
        e=$(rmse "nz-$s-ref.pfm" "nz-$s-u$n.ppm")
        printf '| %s | -s %d | %.3f s | %s | %d |\n' "$s" "$n" "$t" "$e" "$n" >>"$DIR/noise.rows"
        echo "uniform $t $e $n" >>"$DIR/noise-$s.plot"
    done
    for l in 8 4 2 1 0.5; do
        # shellcheck disable=SC2086
        t=$(timed "nz-$s-n$l" $opts --noise "$l" "scenes/$s.txt") || exit 1
        e=$(rmse "nz-$s-ref.pfm" "nz-$s-n$l.ppm")
        # shellcheck disable=SC2086
        "$RT" -v $opts --noise "$l" --spp-map "$DIR/nz-$s-map$l.ppm" "scenes/$s.txt" \
            "$DIR/nz-$s-n$l.ppm" 2>"$DIR/v" || exit 1
        spp=$(sed -n 's/.*samples a pixel .*: mean \([0-9.]*\), most.*/\1/p' "$DIR/v")
        printf '| %s | --noise %s | %.3f s | %s | %s |\n' "$s" "$l" "$t" "$e" "$spp" >>"$DIR/noise.rows"
        echo "adaptive $t $e L=$l" >>"$DIR/noise-$s.plot"
        # Honesty: the estimate against the measured error, on the linear
        # colours the estimate then speaks of (a PFM render), over the
        # pixels that took more than the first round (the map's not black).
        case $l in 8) continue ;; esac
        # shellcheck disable=SC2086
        "$RT" -q $opts --noise "$l" --spp-map "$DIR/nz-$s-pmap.ppm" --format pfm "scenes/$s.txt" \
            "$DIR/nz-$s-p$l.pfm" || exit 1
        sampled=$("$DIFF" --only "$DIR/nz-$s-pmap.ppm" "$DIR/nz-$s-ref.pfm" "$DIR/nz-$s-p$l.pfm" |
            sed -n 's/^compared: *the \([0-9]*\) pixels.*/\1/p')
        all=$("$DIFF" "$DIR/nz-$s-ref.pfm" "$DIR/nz-$s-p$l.pfm" |
            sed -n 's/^mean error: .*, RMS error: \([0-9.e+-]*\),.*/\1/p')
        over=$("$DIFF" --only "$DIR/nz-$s-pmap.ppm" "$DIR/nz-$s-ref.pfm" "$DIR/nz-$s-p$l.pfm" |
            sed -n 's/^mean error: .*, RMS error: \([0-9.e+-]*\),.*/\1/p')
        printf '| %s | %s | %s | %s | %s | %.2f |\n' "$s" "$l" "${sampled:-0}" "$all" "${over:--}" \
            "$(echo "${over:-0} / $l" | bc -l)" >>"$DIR/honest.rows"
    done
    # The same RMSE by uniform sampling: its time there, log-log between
    # the two uniform renders around it; the speed-up over adaptive.
    awk -v scene=$s '$1 == "uniform" { n++; ut[n] = $2; ue[n] = $3 }
        $1 == "adaptive" { m++; at[m] = $2; ae[m] = $3; al[m] = $4 }
        END { for (j = 1; j <= m; j++) {
            t = ""
            for (i = 1; i < n; i++) if (ue[i] >= ae[j] && ue[i + 1] <= ae[j] && ue[i] > ue[i + 1]) {
                f = (log(ue[i]) - log(ae[j])) / (log(ue[i]) - log(ue[i + 1]))
                t = exp(log(ut[i]) + f * (log(ut[i + 1]) - log(ut[i]))) }
            sub(/^L=/, "", al[j])
            if (t == "") printf "| %s | %s | %.3f s | %s | outside uniform'"'"'s range | - |\n", scene, al[j], at[j], ae[j]
            else printf "| %s | %s | %.3f s | %s | %.3f s | %.2f |\n", scene, al[j], at[j], ae[j], t, t / at[j] } }' \
        "$DIR/noise-$s.plot" >>"$DIR/speedup.rows.$s"
    awk -v title="--noise L against uniform N: $s.txt ($(echo "$opts" | sed 's/--size //'))" \
        -v xlabel="render time, s" -v ylabel="RMSE against the converged render, levels" \
        -v logx=1 -v logy=1 -f "$PLOT" "$DIR/noise-$s.plot" >"$DOCS/trade-noise-$s.svg"
done
cat "$DIR/speedup.rows.indirect" "$DIR/speedup.rows.focus" "$DIR/speedup.rows.materials" \
    "$DIR/speedup.rows.course" >"$DIR/speedup.rows"
rm -f "$DIR"/speedup.rows.*
pfm=1
fi

# --- texture filtering: materials.txt and horizon.txt, their floors far
# and near, at 1 and 4 samples a pixel, against 1024 unfiltered ---
# mask_scene SCENE FLOOR MODE [X Y Z R]: SCENE (MPL) with FLOOR white and
# every other material black, no lights: lit by ambient light alone (MODE
# floor: the floor's pixels white), or by a light at X Y Z reaching R
# units (MODE near: the floor within R of it lit, beyond it black).
mask_scene() {
    awk -v floor="$2" -v mode="$3" -v x="$4" -v y="$5" -v z="$6" -v r="$7" '
        /^[ \t]*#/ || !/[^ \t]/ { next }
        $1 == "l" { next }
        $1 == "c" && ($2 == "Ambient" || $2 == "Sky" || $2 == "Background" || $2 == "Samples" ||
                      $2 == "Noise") { next }
        $1 == "m" { print "m", $2, "MATTE", ($2 == floor ? "1 1 1" : "0 0 0"), "0 0 0 N"; next }
        { print }
        END {
            print "c Background 0 0 0"
            print "c Samples 1"
            if (mode == "floor") print "c Ambient 1 1 1"
            else print "l PointLight", x, y, z, "1 1 1 1000000", r
        }' "$1"
}
# floor_mask SCENE FLOOR X Y Z R OUT SIZE: OUT, a P3 image white where
# SCENE's FLOOR is seen farther than R from the camera at X Y Z (R
# negative: nearer than -R), black elsewhere.
floor_mask() {
    mask_scene "$1" "$2" floor >"$DIR/mask-floor.txt"
    mask_scene "$1" "$2" near "$3" "$4" "$5" "${6#-}" >"$DIR/mask-near.txt"
    "$RT" -q --ascii --size "$8" "$DIR/mask-floor.txt" "$DIR/mask-floor.ppm" || exit 1
    "$RT" -q --ascii --size "$8" "$DIR/mask-near.txt" "$DIR/mask-near.ppm" || exit 1
    awk -v far="$([ "${6#-}" = "$6" ] && echo 1 || echo 0)" '
        FNR == 1 { file++ }
        { for (i = 1; i <= NF; i++) { if ($i ~ /^#/) break; n[file]++; v[file, n[file]] = $i } }
        END {
            w = v[1, 2]; h = v[1, 3]
            print "P3"; print w, h; print 255
            for (p = 0; p < w * h; p++) {
                f = v[1, 5 + 3 * p]; l = v[2, 5 + 3 * p]
                on = f > 128 && (far ? l == 0 : l > 0)
                print on ? "255 255 255" : "0 0 0"
            }
        }' "$DIR/mask-floor.ppm" "$DIR/mask-near.ppm" >"$7"
}
# only REF IMAGE MASK: "RMSE max" of IMAGE against REF over MASK's pixels.
only() {
    "$DIFF" --only "$DIR/$3" "$DIR/$1" "$DIR/$2" >"$DIR/do" 2>&1
    echo "$(sed -n 's/^mean error: .*, RMS error: \([0-9.e+-]*\),.*/\1/p' "$DIR/do")" \
        "$(sed -n 's/^max error: \([0-9.e+-]*\).*/\1/p' "$DIR/do")"
}
if wanted texture; then
echo "trade: texture filtering" >&2
pfm=0
: >"$DIR/texture.rows"
: >"$DIR/texture-time.rows"
for s in materials horizon; do
    case $s in
    materials) size=320x200 tsize=1280x800 floor=floor cam="0 2.2 -6.5" ;;
    horizon) size=320x180 tsize=1280x720 floor=tiles cam="0 1.1 -6" ;;
    esac
    # shellcheck disable=SC2086
    floor_mask "scenes/$s.txt" $floor $cam 10 "$DIR/tx-$s-far.ppm" "$size"
    "$RT" -q --size "$size" -s 1024 --texture-filter bilinear "scenes/$s.txt" "$DIR/tx-$s-ref.ppm" ||
        exit 1
    for n in 1 4; do
        for f in b:bilinear t:trilinear e:ewa; do
            "$RT" -q --size "$size" -s "$n" --texture-filter "${f#*:}" "scenes/$s.txt" \
                "$DIR/tx-$s-${f%%:*}$n.ppm" || exit 1
        done
        # Times at a size where the render, not the start, is measured.
        tb=$(timed "tm-$s" --size "$tsize" -s "$n" --texture-filter bilinear "scenes/$s.txt") || exit 1
        tt=$(timed "tm-$s" --size "$tsize" -s "$n" --texture-filter trilinear "scenes/$s.txt") || exit 1
        te=$(timed "tm-$s" --size "$tsize" -s "$n" --texture-filter ewa "scenes/$s.txt") || exit 1
        set -- $(only "tx-$s-ref.ppm" "tx-$s-b$n.ppm" "tx-$s-far.ppm")
        fb=$1
        set -- $(only "tx-$s-ref.ppm" "tx-$s-t$n.ppm" "tx-$s-far.ppm")
        ft=$1
        set -- $(only "tx-$s-ref.ppm" "tx-$s-e$n.ppm" "tx-$s-far.ppm")
        fe=$1
        printf '| %s | %d | %s | %s (%.2f) | %s (%.2f) |\n' "$s" "$n" "$fb" "$ft" \
            "$(echo "$ft / $fb" | bc -l)" "$fe" "$(echo "$fe / $fb" | bc -l)" >>"$DIR/texture.rows"
        printf '| %s | %d | %.3f s | %.3f s (%.2f) | %.3f s (%.2f) |\n' "$s" "$n" "$tb" "$tt" \
            "$(echo "$tt / $tb" | bc -l)" "$te" "$(echo "$te / $tb" | bc -l)" >>"$DIR/texture-time.rows"
    done
done
# Magnified textures change nothing: textures.txt (its checker floor, a
# planet and a gradient, a texel wider than a pixel but far away), filtered
# against bilinear: the share of pixels more than a level apart.
: >"$DIR/magnified.rows"
for n in 1 4; do
    "$RT" -q -s "$n" --texture-filter bilinear scenes/textures.txt "$DIR/mg-b.ppm" || exit 1
    for f in trilinear ewa; do
        "$RT" -q -s "$n" --texture-filter "$f" scenes/textures.txt "$DIR/mg-$f.ppm" || exit 1
        "$DIFF" -t 1 "$DIR/mg-b.ppm" "$DIR/mg-$f.ppm" >"$DIR/dm" 2>&1
        printf '| %d | %s | %s |\n' "$n" "$f" \
            "$(sed -n 's/^over tolerance 1: \([0-9]* of [0-9]* pixels ([0-9.]*%)\).*/\1/p' "$DIR/dm")" \
            >>"$DIR/magnified.rows"
    done
done
pfm=1
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
    echo "## Adaptive sampling: --noise against uniform samples"
    echo
    echo "Four scenes, each against a converged render of its own (uniform"
    echo "sampling, many samples a pixel): scenes/indirect.txt at 200 × 200 with"
    echo "\`--gi 16\` (global illumination, one bounce, 16 gathering rays a"
    echo "sample; reference 1024 samples), scenes/focus.txt at 240 × 160 (its lens;"
    echo "16384), scenes/materials.txt at 240 × 150 (textures, glass, metal;"
    echo "8192) and scenes/course.txt at 200 × 200 (anti-aliased edges; 16384)."
    echo "Uniform: \`-s N\` (the multi-jittered pattern); adaptive: \`--noise L\`"
    echo "with its defaults (64 / L, 16 to 256, to 4096 samples a pixel, scrambled Sobol points,"
    echo "docs/design.md). The error is what the user sees: the 8-bit render"
    echo "against the reference's colours clamped to 0..255, its own rounding"
    echo "(0.29 levels RMS) included; times are medians of $RUNS runs."
    echo
    echo "![indirect](trade-noise-indirect.svg)"
    echo "![focus](trade-noise-focus.svg)"
    echo "![materials](trade-noise-materials.svg)"
    echo "![course](trade-noise-course.svg)"
    echo
    echo "The references' own error bounds what can be measured below it: each"
    echo "against a render of a quarter of its samples (RMSE, linear), whose"
    echo "error is at least twice its own, so that the difference over"
    echo "sqrt(5) bounds the reference's error from above:"
    echo
    echo "| scene | reference samples | against a quarter of them | reference's error, at most |"
    echo "|-------|-------------------|---------------------------|----------------------------|"
    cat "$DIR/refnoise.rows"
    echo
    echo "| scene | sampling | time | RMSE | samples a pixel (mean) |"
    echo "|-------|----------|------|------|------------------------|"
    cat "$DIR/noise.rows"
    echo
    echo "At the RMSE each \`--noise L\` reached, the time uniform sampling takes"
    echo "to reach it (log-log between the two uniform renders around it) and"
    echo "the speed-up:"
    echo
    echo "| scene | L | adaptive time | RMSE | uniform time at that RMSE | speed-up |"
    echo "|-------|---|---------------|------|---------------------------|----------|"
    cat "$DIR/speedup.rows"
    echo
    echo "Honesty: the estimate is one standard error of each pixel's value; the"
    echo "measured RMSE against the reference (linear colours, PFM renders, so"
    echo "that rounding does not mix in) over the pixels that took more than"
    echo "the first round (those whose estimate said they needed it), and over"
    echo "the whole picture, whose pixels exact at the first round bring it down:"
    echo
    echo "| scene | L | pixels past the first round | RMSE, whole picture | RMSE, those pixels | that / L |"
    echo "|-------|---|-----------------------------|---------------------|--------------------|----------|"
    cat "$DIR/honest.rows"
    echo
    echo "Reading these (noise.md): a bound on every pixel's error costs, in"
    echo "plain Monte Carlo, what uniform sampling pays for the same RMSE, so"
    echo "\`--noise\` wins on RMSE where pixels converge at different rates — flat"
    echo "walls and sky exact at the first round, filtered textures, edges —"
    echo "and cannot where a lens blurs every pixel alike (focus.txt), where it"
    echo "pays the doubling rounds' overshoot. Below 0.5 L the estimate errs on"
    echo "the safe side (smooth integrands on a net, the first round's floor of"
    echo "64 / L samples); the references' own error bounds the lowest rows."
    echo
    echo "## Texture filtering: mip-maps and ray differentials"
    echo
    echo "scenes/materials.txt at 320 × 200 and scenes/horizon.txt at 320 × 180,"
    echo "at 1 and 4 samples a pixel, against 1024 samples a pixel read without"
    echo "a filter over the footprint (bilinear, the texel's neighbours only)."
    echo "The error is the RMSE over the floor farther than ten units from the"
    echo "camera (its pixels found by rendering the scene with the floor white,"
    echo "everything else black, and a light at the camera reaching ten units),"
    echo "for bilinear lookups, trilinear mip-maps (the MPL format's default) and"
    echo "EWA, with their ratio to bilinear's."
    echo
    echo "| scene | samples | far floor, bilinear | trilinear (ratio) | EWA (ratio) |"
    echo "|-------|---------|---------------------|-------------------|-------------|"
    cat "$DIR/texture.rows"
    echo
    echo "Part of what remains is the reference's own moiré: 1024 samples a pixel"
    echo "average the checkered floor over each pixel's square, and a box filter"
    echo "lets a checker's fine frequencies through as beats, so the reference"
    echo "shows moiré toward the horizon that a mip-map's mean (grey) does not"
    echo "reproduce; the rest is the isotropic filter's blur at grazing angles,"
    echo "which EWA halves."
    echo
    echo "Both scenes' floors (256 texels a unit) are minified even near the"
    echo "camera at these sizes, so filtering rightly changes them there too."
    echo "Where a texture is magnified (a texel wider than the pixel) a filtered"
    echo "lookup is bilinear's to the bit: scenes/textures.txt (a 2 × 2 checker"
    echo "tiled every 2 units, a planet, a gradient; 480 × 320) filtered against"
    echo "bilinear, the pixels more than one level apart (its far floor and the"
    echo "planet's rim, where they are minified):"
    echo
    echo "| samples | filter | pixels over 1 level |"
    echo "|---------|--------|---------------------|"
    cat "$DIR/magnified.rows"
    echo
    echo "Render times (whole command, medians of $RUNS runs, materials.txt at"
    echo "1280 × 800 and horizon.txt at 1280 × 720, so that the render and not"
    echo "the start is timed), and their ratio to bilinear's:"
    echo
    echo "| scene | samples | bilinear | trilinear | EWA |"
    echo "|-------|---------|----------|-----------|-----|"
    cat "$DIR/texture-time.rows"
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
