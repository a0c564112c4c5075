#!/bin/sh
# bench.sh: the benchmark behind `make bench`. Not a test: it measures.
#
# Generates its scenes (tests/bench/scenegen.c) into build/bench, renders
# each BENCH_RUNS times (default 3) on 1 thread and on all of them, run for
# run alternately, and writes docs/benchmarks.md: median wall time (reading
# the scene and building the hierarchy included), rays by kind, Mrays/s
# (render only), peak memory, the speed-up from 1 thread to all. When
# POV-Ray is installed, it renders the two sphere fields with it too, side
# by side in the same run, and compares the pixels. When BENCH_EMBREE names
# an executable (raytrace with Embree 3's traversal in place of ours:
# tests/bench/embree_bvh.c), it races the sphere fields with it too.
#
# Usage: sh tests/bench/bench.sh RAYTRACE RAYTRACE-DIFF SCENEGEN [OUT.md]
# Environment: BENCH_RUNS (runs per measure), BENCH_ONLY (a space-separated
# subset of: course spheres-1000 spheres-100000 spheres-1000000 terrain).

RT=$1
DIFF=$2
GEN=$3
OUT=${4:-docs/benchmarks.md}
RUNS=${BENCH_RUNS:-3}
ONLY=${BENCH_ONLY:-"course spheres-1000 spheres-100000 spheres-1000000 terrain"}
DIR=build/bench
ALL=$(nproc 2>/dev/null || echo 1)
mkdir -p "$DIR" || exit 2

. tests/lib.sh


# scene NAME: generates build/bench/NAME.txt once.
scene() {
    f="$DIR/$1.txt"
    [ -s "$f" ] && return
    case $1 in
    course) "$GEN" course 3840 >"$f" ;;
    spheres-*) "$GEN" spheres "${1#spheres-}" >"$f" ;;
    terrain) "$GEN" terrain 1000000 "$(pwd)/$DIR/terrain.obj" >"$f" ;;
    esac || { rm -f "$f"; echo "bench: cannot generate $1" >&2; exit 2; }
}

# run NAME THREADS: renders once; appends the wall time (ms) and Mrays/s to
# $DIR/t-THREADS and leaves the -v log in $DIR/log-THREADS.
run() {
    start=$(now)
    "$RT" -v -j "$2" "$DIR/$1.txt" "$DIR/$1.ppm" 2>"$DIR/log-$2" || { cat "$DIR/log-$2" >&2; exit 1; }
    end=$(now)
    speed=$(sed -n 's/^raytrace: rendered in .*: \(.*\) Mrays\/s$/\1/p' "$DIR/log-$2")
    echo "$(((end - start) / 1000000)) $speed" >>"$DIR/t-$2"
}

# row NAME THREADS: appends the table row of THREADS' runs to $DIR/rows.
row() {
    log=$DIR/log-$2
    wall=$(cut -d' ' -f1 "$DIR/t-$2" | median)
    speed=$(cut -d' ' -f2 "$DIR/t-$2" | median)
    rays=$(sed -n 's/^raytrace: rays: //p' "$log")
    mem=$(sed -n 's/^raytrace: peak memory: \(.*\) MB$/\1/p' "$log")
    size=$(sed -n 's/^raytrace: \([0-9]* x [0-9]*\) pixels.*/\1/p' "$log")
    printf '| %s | %s | %s | %s | %s s | %.2f | %s MB |\n' "$1" "$size" "$2" "$rays" \
        "$(seconds "$wall")" "$speed" "$mem" >>"$DIR/rows"
    echo "bench: $1, $2 thread(s): median $wall ms ($(cut -d' ' -f1 "$DIR/t-$2" | tr '\n' ' '))" >&2
}

# together NAME: renders ALL times at once, one thread each (separate
# processes, which share nothing but the machine); appends the wall time
# (ms) until the last ends to $DIR/t-together.
together() {
    start=$(now)
    k=0
    pids=
    while [ $k -lt "$ALL" ]; do
        "$RT" -q -j 1 "$DIR/$1.txt" "$DIR/$1-$k.ppm" &
        pids="$pids $!"
        k=$((k + 1))
    done
    for p in $pids; do
        wait "$p" || exit 1
    done
    end=$(now)
    echo $(((end - start) / 1000000)) >>"$DIR/t-together"
}

# ticks: the machine's CPU time so far, in all and stolen by other guests
# of its host (/proc/stat; "0 0" where there is none).
ticks() {
    awk '$1 == "cpu" { t = 0; for (i = 2; i <= NF; i++) t += $i; print t, $9 + 0; exit }' \
        /proc/stat 2>/dev/null || echo "0 0"
}

# stolen BEFORE: the share (%) of CPU time stolen since ticks printed BEFORE.
stolen() {
    echo "$1 $(ticks)" | awk '{ d = $3 - $1; s = d > 0 ? 100 * ($4 - $2) / d : 0; printf "%.0f%%", s }'
}

# measure NAME: renders RUNS times on 1 thread, on all of them, and as ALL
# one-thread processes at once, run for run alternately, so that all see
# the machine alike; appends the table rows of the first two, and to
# $DIR/speedup the medians over the runs of the speed-ups: the whole
# command's, the render's alone, and the machine's own (ALL renders at
# once against one alone: what threads could at best reach).
measure() {
    : >"$DIR/t-1"
    : >"$DIR/t-$ALL"
    : >"$DIR/t-together"
    before=$(ticks)
    i=0
    while [ $i -lt "$RUNS" ]; do
        run "$1" 1
        if [ "$ALL" -gt 1 ]; then
            run "$1" "$ALL"
            together "$1"
        fi
        i=$((i + 1))
    done
    row "$1" 1
    [ "$ALL" -gt 1 ] || return 0
    row "$1" "$ALL"
    whole=$(paste -d' ' "$DIR/t-1" "$DIR/t-$ALL" | awk '$3 > 0 { print $1 / $3 }' | median)
    render=$(paste -d' ' "$DIR/t-1" "$DIR/t-$ALL" | awk '$2 > 0 { print $4 / $2 }' | median)
    machine=$(paste -d' ' "$DIR/t-1" "$DIR/t-together" |
        awk -v all="$ALL" '$3 > 0 { print all * $1 / $3 }' | median)
    printf '| %s | %.2f× | %.2f× | %.2f× | %s |\n' "$1" "$whole" "$render" "$machine" \
        "$(stolen "$before")" >>"$DIR/speedup"
}

: >"$DIR/rows"
: >"$DIR/speedup"
for s in $ONLY; do
    scene "$s"
    measure "$s"
done

# render_time SCENE: renders RUNS times on all threads; sets render to the
# median render time (seconds, from -v) and leaves the last -v log.
render_time() {
    : >"$DIR/times"
    i=0
    while [ $i -lt "$RUNS" ]; do
        "$RT" -v -j "$ALL" "$1" "$DIR/scale.ppm" 2>"$DIR/log" || exit 1
        sed -n 's/^raytrace: rendered in \([0-9.]*\) s.*/\1/p' "$DIR/log" >>"$DIR/times"
        i=$((i + 1))
    done
    render=$(median <"$DIR/times")
}

# Scaling: time against sphere count (one image size) and against image
# size (one field), all threads, median of RUNS.
: >"$DIR/scale"
if [ "${BENCH_SCALING:-1}" = 1 ]; then
    for n in 10 100 1000 10000 100000 1000000; do
        f="$DIR/scale-$n.txt"
        [ -s "$f" ] || "$GEN" spheres "$n" | sed '6s/^1920$/480/' >"$f"
        render_time "$f"
        read_s=$(sed -n 's/^raytrace: read the scene in \([0-9.]*\) s/\1/p' "$DIR/log")
        # The hierarchy and the light buffers together.
        build=$(awk '/built in/ { for (i = NF; i > 1; i--) if ($i == "built") b += $(i + 2) }
            END { printf "%.3f", b }' "$DIR/log")
        printf '| spheres | %s | 480 x 270 | %s s | %s s | %s s |\n' "$n" "${read_s:-0}" \
            "${build:-0}" "$render" >>"$DIR/scale"
        echo "bench: scaling, $n spheres" >&2
    done
    scene spheres-1000
    for w in 480 960 1920 3840; do
        f="$DIR/scale-w$w.txt"
        resize "$DIR/spheres-1000.txt" "$w" >"$f"
        render_time "$f"
        size=$(sed -n 's/^raytrace: \([0-9]* x [0-9]*\) pixels.*/\1/p' "$DIR/log")
        printf '| image size | 1000 | %s | | | %s s |\n' "$size" "$render" >>"$DIR/scale"
        echo "bench: scaling, width $w" >&2
    done
fi

# Features a scene does not use: the course scene rendered by the
# course-only renderer (the commit before planes, triangles, glass, several
# lights, samples, textures, the keyword format and the hierarchy existed)
# and by this one, run for run alternately, with the same bytes.
BASE=${BENCH_BASELINE:-194c48f}
BASE_CFLAGS=${BENCH_BASELINE_CFLAGS:--O3 -g} # today's default, for a fair race
: >"$DIR/unused"
if [ "${BENCH_UNUSED:-1}" = 1 ] && git rev-parse -q --verify "$BASE^{commit}" >/dev/null 2>&1; then
    scene course
    if [ ! -x "$DIR/baseline/raytrace" ] || [ "$(cat "$DIR/baseline/.cflags" 2>/dev/null)" != "$BASE_CFLAGS" ]; then
        rm -rf "$DIR/baseline"
        mkdir -p "$DIR/baseline"
        git archive "$BASE" | tar -x -C "$DIR/baseline" &&
            make -s -C "$DIR/baseline" CFLAGS="$BASE_CFLAGS" raytrace &&
            echo "$BASE_CFLAGS" >"$DIR/baseline/.cflags" ||
            { echo "bench: cannot build $BASE" >&2; exit 1; }
    fi
    for j in 1 "$ALL"; do
        : >"$DIR/t-base"
        : >"$DIR/t-now"
        i=0
        while [ $i -lt "$RUNS" ]; do
            for b in base now; do
                [ $b = base ] && bin=$DIR/baseline/raytrace || bin=$RT
                start=$(now)
                "$bin" -q -j "$j" "$DIR/course.txt" "$DIR/course-$b.ppm" || exit 1
                end=$(now)
                echo $(((end - start) / 1000000)) >>"$DIR/t-$b"
            done
            i=$((i + 1))
        done
        cmp -s "$DIR/course-base.ppm" "$DIR/course-now.ppm" && same=yes || same=NO
        tb=$(median <"$DIR/t-base")
        tn=$(median <"$DIR/t-now")
        printf '| course 3840 x 3840 | %s | %s s | %s s | %+.1f%% | %s |\n' "$j" \
            "$(seconds "$tb")" "$(seconds "$tn")" \
            "$(echo "($tn - $tb) * 100 / $tb" | bc -l)" "$same" >>"$DIR/unused"
        echo "bench: unused features, $j thread(s): course-only $tb ms, now $tn ms" >&2
    done
fi

# The MPL ray tracer's scenes: its example by its program's model at its defaults
# (500 x 500, then 1000 x 1000 as its report's render: 4 samples a pixel,
# 10 occlusion and 10 gathering rays a point; four JPEG textures), every
# material kind (scenes/materials.txt, the physical model), and a
# texture-heavy field made here: 200 cubes and 200 spheres under JPEG
# textures, 1920 x 1080, the physical model at one sample a pixel. Reading
# (JPEG decoding included) and rendering apart, medians of RUNS on all
# threads.
: >"$DIR/mpl"
if [ "${BENCH_MPL:-1}" = 1 ]; then
    tex=$(pwd)/scenes/textures
    awk -v tex="$tex" 'BEGIN {
        print "c Camera 0 9 -22 0 0 4 45 1920 1080"
        print "c Model physical"
        print "c Samples 1"
        split("Wallpaper carrelage painting marble", t, " ")
        for (k = 1; k <= 4; k++)
            printf "m t%d MATTE 1 1 1 0 0.3 30 %s/%s.jpg\n", k, tex, t[k]
        print "p Plane 0 -1 0 0 1 0 t2"
        for (i = 0; i < 20; i++)
            for (j = 0; j < 20; j++) {
                x = i - 9.5; z = j - 5.5; m = 1 + (i + j) % 4
                if ((i + j) % 2) printf "p Sphere %g -0.6 %g 0.4 t%d\n", x, z, m
                else printf "p Cube %g -0.6 %g 0.4 t%d\n", x, z, m
            }
        print "l DirectionLight -0.5 -1 0.7 1 1 1 1"
        print "l PointLight 0 4 2 1 0.9 0.8 20 30"
    }' >"$DIR/textured.txt"
    for run in scenes/mpl.txt scenes/mpl.txt:1000x1000 scenes/materials.txt \
        "$DIR/textured.txt"; do
        f=${run%%:*}
        size=
        [ "$f" = "$run" ] || size="--size ${run#*:}"
        : >"$DIR/times"
        : >"$DIR/reads"
        i=0
        while [ $i -lt "$RUNS" ]; do
            # shellcheck disable=SC2086
            "$RT" -v -j "$ALL" $size "$f" "$DIR/mpl.ppm" 2>"$DIR/log" || exit 1
            sed -n 's/^raytrace: rendered in \([0-9.]*\) s.*/\1/p' "$DIR/log" >>"$DIR/times"
            sed -n 's/^raytrace: read the scene in \([0-9.]*\) s/\1/p' "$DIR/log" >>"$DIR/reads"
            i=$((i + 1))
        done
        size=$(sed -n 's/^raytrace: \([0-9]* x [0-9]*\) pixels.*/\1/p' "$DIR/log")
        printf '| %s | %s | %s s | %s s |\n' "${f##*/}" "$size" "$(median <"$DIR/reads")" \
            "$(median <"$DIR/times")" >>"$DIR/mpl"
        echo "bench: the MPL ray tracer, ${f##*/}" >&2
    done
fi

# race NAME BIN OUT: renders NAME on all threads with BIN into OUT; appends
# the wall time (ms) and the render's alone (ms, from -v) to $DIR/t-OUT.
race() {
    start=$(now)
    "$2" -v -j "$ALL" "$DIR/$1.txt" "$DIR/$3.ppm" 2>"$DIR/log-race" ||
        { cat "$DIR/log-race" >&2; exit 1; }
    end=$(now)
    echo "$(((end - start) / 1000000)) $(sed -n \
        's/^raytrace: rendered in \([0-9.]*\) s.*/\1/p' "$DIR/log-race" |
        awk '{ printf "%d", $1 * 1000 + 0.5 }')" >>"$DIR/t-$3"
}

# The sphere fields raced on all threads, run for run alternately: POV-Ray
# (the fields of 1,000 and 100,000 spheres) when it is installed, raytrace,
# and raytrace with Embree's traversal when there is one.
EMBREE=${BENCH_EMBREE:-}
[ -n "$EMBREE" ] && [ -x "$EMBREE" ] || EMBREE=
command -v povray >/dev/null 2>&1 && POV=yes || POV=
: >"$DIR/pov"
: >"$DIR/embree"
for s in $ONLY; do
    case $s in spheres-1000 | spheres-100000) pov=$POV ;; spheres-*) pov= ;; *) continue ;; esac
    [ -n "$pov$EMBREE" ] || continue
    scene "$s"
    n=${s#spheres-}
    [ -z "$pov" ] || [ -s "$DIR/$s.pov" ] || "$GEN" spheres "$n" pov >"$DIR/$s.pov"
    : >"$DIR/t-pov"
    : >"$DIR/t-rt"
    : >"$DIR/t-eb"
    i=0
    while [ $i -lt "$RUNS" ]; do
        if [ -n "$pov" ]; then
            start=$(now)
            povray +I"$DIR/$s.pov" +O"$DIR/$s-pov.ppm" +W1920 +H1080 -A +FP File_Gamma=1.0 \
                +WT"$ALL" -D -V >/dev/null 2>"$DIR/pov.log" || { cat "$DIR/pov.log" >&2; exit 1; }
            end=$(now)
            echo $(((end - start) / 1000000)) >>"$DIR/t-pov"
        fi
        race "$s" "$RT" rt
        [ -z "$EMBREE" ] || race "$s" "$EMBREE" eb
        i=$((i + 1))
    done
    rt=$(cut -d' ' -f1 "$DIR/t-rt" | median)
    rt_alone=$(cut -d' ' -f2 "$DIR/t-rt" | median)
    if [ -n "$EMBREE" ]; then
        eb=$(cut -d' ' -f1 "$DIR/t-eb" | median)
        eb_alone=$(cut -d' ' -f2 "$DIR/t-eb" | median)
        cmp -s "$DIR/rt.ppm" "$DIR/eb.ppm" && same=yes || same=NO
        printf '| %s | %s s | %s s | %.2f | %s s | %s s | %.2f | %s |\n' "$s" \
            "$(seconds "$rt")" "$(seconds "$eb")" "$(echo "$rt / $eb" | bc -l)" \
            "$(seconds "$rt_alone")" "$(seconds "$eb_alone")" \
            "$(echo "$rt_alone / $eb_alone" | bc -l)" "$same" >>"$DIR/embree"
        echo "bench: $s: raytrace $rt ms, with Embree's traversal $eb ms" >&2
    fi
    if [ -n "$pov" ]; then
        pov_ms=$(median <"$DIR/t-pov")
        "$DIFF" --tolerance 1 "$DIR/$s-pov.ppm" "$DIR/rt.ppm" >"$DIR/diff.log" 2>&1
        over=$(sed -n 's/^over tolerance 1: \([0-9]*\) of \([0-9]*\) pixels.*/\1 of \2/p' "$DIR/diff.log")
        maxerr=$(sed -n 's/^max error: \([0-9]*\).*/\1/p' "$DIR/diff.log")
        ebcol=
        [ -z "$EMBREE" ] || ebcol=$(printf ' %s s (%.1f×) |' "$(seconds "$eb")" "$(echo "$pov_ms / $eb" | bc -l)")
        printf '| %s | %s s | %s s | %.1f× |%s %s | %s |\n' "$s" "$(seconds "$pov_ms")" \
            "$(seconds "$rt")" "$(echo "$pov_ms / $rt" | bc -l)" "$ebcol" "$over" "$maxerr" >>"$DIR/pov"
        echo "bench: $s: POV-Ray $pov_ms ms, raytrace $rt ms" >&2
    fi
done

# embree_version: the version of the Embree library raytrace-embree loads.
embree_version() {
    lib=$(ldd "$EMBREE" 2>/dev/null | sed -n 's/.*libembree3[^ ]* => \([^ ]*\) .*/\1/p' | head -1)
    readlink -f "$lib" 2>/dev/null | sed -n 's/.*libembree3\.so\.\([0-9.]*\)$/\1/p'
}

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -1)
# Which build of the hierarchy's queries this processor runs (bvh_query.h).
scene spheres-1000
kernel=$("$RT" -v -d 0 "$DIR/spheres-1000.txt" "$DIR/kernel.ppm" 2>&1 |
    grep -q 'box tests in AVX2 and FMA' && echo "AVX2 and FMA" || echo "the base build")
rm -f "$DIR/kernel.ppm"
{
    echo "# Benchmarks"
    echo
    echo "Written by \`make bench\` (tests/bench/bench.sh) on $(date -u +%Y-%m-%d)."
    echo "Machine: ${cpu:-unknown CPU}, $ALL hardware thread(s), $(uname -sm);"
    echo "compiler: $(${CC:-cc} --version 2>/dev/null | head -1); box tests: $kernel."
    echo "Machines here are shared and"
    echo "noisy: compare figures measured in the same run, not across runs."
    echo
    echo "Scenes (generated by tests/bench/scenegen.c, the same on every machine):"
    echo "the course scene at 3840 pixels wide; fields of 1,000, 100,000 and"
    echo "1,000,000 random spheres (radius 2·(1000/n)^⅓, reflection 0.3) on a floor"
    echo "sphere of radius 10^5, 1920 × 1080; a terrain of 1,002,528 triangles"
    echo "(reflection 0.2), 1920 × 1080. Default depth 10, one sample per pixel."
    echo
    echo "Wall time is the median of $RUNS runs of the whole command (reading the"
    echo "scene and building the hierarchy included); Mrays/s, the median of the"
    echo "same runs, counts every ray (primary, shadow, reflection, refraction)"
    echo "over the render alone; peak memory is the process's maximum resident"
    echo "size, image included."
    echo
    echo "| scene | pixels | threads | rays | wall time | Mrays/s | peak memory |"
    echo "|-------|--------|---------|------|-----------|---------|-------------|"
    cat "$DIR/rows"
    if [ "$ALL" -gt 1 ]; then
        echo
        echo "Speed-up from 1 to $ALL threads: the 1-thread and $ALL-thread runs above"
        echo "alternate with $ALL 1-thread runs of the same scene at once (separate"
        echo "processes), and each figure is the median over the $RUNS rounds of"
        echo "the 1-thread run's time over the other's: the whole command's (reading"
        echo "and building included), the render's alone (Mrays/s), and the"
        echo "machine's own ($ALL × the time of one run alone over that of $ALL at"
        echo "once: the throughput $ALL processes that share nothing get, which"
        echo "threads sharing one scene cannot pass). Stolen: the share of the"
        echo "machine's CPU time its host gave other guests during those runs"
        echo "(/proc/stat), which none of these figures can see past."
        echo
        echo "| scene | whole command | render alone | $ALL processes at once | stolen |"
        echo "|-------|---------------|--------------|----------------------|--------|"
        cat "$DIR/speedup"
    fi
    if [ -s "$DIR/scale" ]; then
        echo
        echo "## Scaling"
        echo
        echo "Render time alone (median of $RUNS, $ALL threads) as the sphere count"
        echo "grows (the same field generator, 480 × 270) and as the image grows (the"
        echo "1,000-sphere field); reading the scene and building the hierarchy"
        echo "are shown apart. Depth: see docs/trade.md."
        echo
        echo "| varies | spheres | pixels | read | build | render |"
        echo "|--------|---------|--------|------|-------|--------|"
        cat "$DIR/scale"
    fi
    if [ -s "$DIR/mpl" ]; then
        echo
        echo "## The MPL ray tracer's scenes"
        echo
        echo "Its example scene (scenes/mpl.txt: squares, a cube, four infinite"
        echo "cylinders, a cone, a metallic ball, four JPEG textures) by its program's"
        echo "model at its defaults (4 samples a pixel, 10 occlusion and 10 gathering"
        echo "rays a point), at 500 x 500 and at the 1000 x 1000 of its report's render"
        echo "(target: 15 s on 2 threads); every material kind (scenes/materials.txt:"
        echo "4 samples per pixel, glass, a ranged point light, the physical model),"
        echo "and a texture-heavy field generated here (textured.txt: 200 cubes and"
        echo "200 spheres under the four JPEG textures on a textured plane, one sample"
        echo "a pixel). Reading includes decoding the JPEGs; medians of $RUNS runs on"
        echo "$ALL threads."
        echo
        echo "| scene | pixels | read | render |"
        echo "|-------|--------|------|--------|"
        cat "$DIR/mpl"
    fi
    if [ -s "$DIR/unused" ]; then
        echo
        echo "## What unused features cost"
        echo
        echo "The course scene (spheres, one light, reflection, one sample per pixel)"
        echo "rendered by the course-only renderer (commit $BASE, before planes,"
        echo "triangles, glass, several lights, samples, lenses, textures, the keyword"
        echo "format, Blinn-Phong, the hierarchy and the cut-off existed) and by this"
        echo "one, both built with CFLAGS=\"$BASE_CFLAGS\", run for run alternately;"
        echo "medians of $RUNS runs of the whole command."
        echo
        echo "| scene | threads | course-only | now | difference | same bytes |"
        echo "|-------|---------|-------------|-----|------------|------------|"
        cat "$DIR/unused"
    fi
    if [ -s "$DIR/pov" ]; then
        echo
        echo "## Against POV-Ray 3.7"
        echo
        echo "The same fields rendered by POV-Ray ($(povray --version 2>&1 | sed -n 's/^POV-Ray \([0-9][0-9.]*[0-9]\).*/\1/p' | head -1)) with"
        echo "\`finish { ambient 0 diffuse 0.7 reflection 0.3 }\`, \`max_trace_level 11\`,"
        echo "\`adc_bailout 0\`, \`assumed_gamma 1\`, \`File_Gamma=1.0 -A +FP\`, $ALL threads"
        echo "each, run for run alternately; medians of $RUNS runs (wall time, whole"
        echo "command). Pixels over 1 level: pixels where some channel differs by more"
        echo "than one level (stricter than counting channels)."
        echo
        if [ -n "$EMBREE" ]; then
            echo "Raytrace with Embree's traversal (below) raced in the same runs; its"
            echo "speed-up over POV-Ray in brackets."
            echo
            echo "| scene | POV-Ray | raytrace | speed-up | with Embree's traversal | pixels over 1 level | max difference |"
            echo "|-------|---------|----------|----------|-------------------------|---------------------|----------------|"
        else
            echo "| scene | POV-Ray | raytrace | speed-up | pixels over 1 level | max difference |"
            echo "|-------|---------|----------|----------|---------------------|----------------|"
        fi
        cat "$DIR/pov"
    fi
    if [ -s "$DIR/embree" ]; then
        echo
        echo "## Against Embree's traversal"
        echo
        echo "Raytrace built with Intel's Embree ($(embree_version)) in place of our"
        echo "hierarchy (tests/bench/embree_bvh.c: Embree builds its tree over the"
        echo "spheres' boxes and traverses it; every sphere it reaches gets our own"
        echo "double-precision test and tie rule), so that only the structure and"
        echo "its traversal differ: the same reading, tiles, threads, shading and"
        echo "cut-off. $ALL threads each, run for run alternately; medians of $RUNS runs."
        echo "Same bytes: whether the two renders are identical."
        echo
        echo "| scene | raytrace | with Embree's | ours over Embree's | render alone: raytrace | with Embree's | ours over Embree's | same bytes |"
        echo "|-------|----------|---------------|--------------------|------------------------|---------------|--------------------|------------|"
        cat "$DIR/embree"
    fi
} >"$OUT"
echo "bench: wrote $OUT" >&2
