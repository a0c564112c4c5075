#!/bin/sh
# anchor.sh: the races against the exact Embree renderers (spheres, and
# triangle meshes), the scaling of time and memory with the sphere count,
# and the shapes' fields (`make bench`, after bench.sh; `make race`
# alone). Not a test: it measures.
#
# The anchor (embree_rt: Embree 3 packets, every hit re-solved in double,
# so its pictures are ours) lives outside the project, in BENCH_ANCHOR
# (default ../shared/anchors/embree); it is built in build/anchor with
# its own Makefile when libembree-dev is installed, and its scenes are
# made by its gen_spheres.py. Both renderers run on every processor, run
# for run alternately, BENCH_RUNS times (default 3); the table gives the
# median and the best wall time of the whole command, and the peak
# resident memory (GNU time), of each. Without the anchor, the race is
# left out and said so; the scaling and shapes tables need only raytrace.
#
# Usage: sh tests/bench/anchor.sh RAYTRACE RAYTRACE-DIFF SCENEGEN [OUT.md]
# Environment: BENCH_RUNS, BENCH_ANCHOR, BENCH_SCALE_MAX (largest sphere
# count of the scaling table, default 10000000).
# The section it writes replaces the one between its markers in OUT.

RT=$1
DIFF=$2
GEN=$3
OUT=${4:-docs/benchmarks.md}
RUNS=${BENCH_RUNS:-3}
ANCHOR=${BENCH_ANCHOR:-../shared/anchors/embree}
SCALE_MAX=${BENCH_SCALE_MAX:-10000000}
DIR=build/anchor
ALL=$(nproc 2>/dev/null || echo 1)
mkdir -p "$DIR" || exit 2

. tests/lib.sh


# timed FILE CMD...: runs CMD, its output to /dev/null, and appends to FILE
# its wall time (ms) and peak resident size (KB, 0 without GNU time).
timed() {
    f=$1
    shift
    start=$(now)
    if [ -n "$GNUTIME" ]; then
        "$GNUTIME" -f %M -o "$DIR/rss" "$@" >/dev/null 2>"$DIR/err" ||
            { cat "$DIR/err" >&2; exit 1; }
    else
        "$@" >/dev/null 2>"$DIR/err" || { cat "$DIR/err" >&2; exit 1; }
        echo 0 >"$DIR/rss"
    fi
    end=$(now)
    echo "$(((end - start) / 1000000)) $(tail -n 1 "$DIR/rss")" >>"$f"
}

# race_stats TIME-SHARE MEMORY-SHARE: from the runs in $DIR/t-a (the
# anchor's) and $DIR/t-r (raytrace's) and their last pictures, sets a and
# r (median ms), ab and rb (best), mem (the memory columns), px (pixels
# that differ) and met (whether raytrace took at most TIME-SHARE of the
# anchor's time and MEMORY-SHARE of its memory).
race_stats() {
    a=$(cut -d' ' -f1 "$DIR/t-a" | median)
    r=$(cut -d' ' -f1 "$DIR/t-r" | median)
    ab=$(cut -d' ' -f1 "$DIR/t-a" | sort -n | head -1)
    rb=$(cut -d' ' -f1 "$DIR/t-r" | sort -n | head -1)
    am=$(cut -d' ' -f2 "$DIR/t-a" | sort -n | tail -1)
    rm_=$(cut -d' ' -f2 "$DIR/t-r" | sort -n | tail -1)
    "$DIFF" "$DIR/a.ppm" "$DIR/r.ppm" >"$DIR/diff.log" 2>&1
    px=$(sed -n 's/^over tolerance 0: \([0-9]*\) of \([0-9]*\) pixels.*/\1 of \2/p' "$DIR/diff.log")
    met=time
    [ "$(echo "$r <= $1 * $a" | bc)" = 1 ] || met=
    if [ "$am" -gt 0 ]; then
        mem=$(printf '%.0f MB | %.0f MB | %.2f' "$(echo "$am / 1024" | bc -l)" \
            "$(echo "$rm_ / 1024" | bc -l)" "$(echo "$rm_ / $am" | bc -l)")
        [ "$(echo "$rm_ <= $2 * $am" | bc)" = 1 ] && met="$met${met:+, }memory"
    else
        mem="n/a | n/a | n/a"
    fi
    case $met in
    "time, memory") met="met" ;;
    "") met="not met" ;;
    *) met="$met only" ;;
    esac
}

GNUTIME=
for t in /usr/bin/time /bin/time; do
    [ -x "$t" ] && "$t" -f %M true >/dev/null 2>&1 && GNUTIME=$t && break
done

section=$DIR/section.md
{
    echo "<!-- anchor.sh: begin -->"
    echo "## Against an exact Embree renderer"
    echo
    echo "Written by \`make bench\` (tests/bench/anchor.sh) on $(date +%Y-%m-%d), $ALL threads."
    echo
} >"$section"

# The race.
have_anchor=
if [ -f "$ANCHOR/embree_rt.c" ] && [ -f "$ANCHOR/gen_spheres.py" ] &&
    command -v python3 >/dev/null 2>&1; then
    cp "$ANCHOR/embree_rt.c" "$ANCHOR/gen_spheres.py" "$ANCHOR/Makefile" "$DIR/" 2>/dev/null
    chmod u+w "$DIR"/* 2>/dev/null
    if make -s -C "$DIR" embree_rt >"$DIR/build.log" 2>&1; then
        have_anchor=yes
    else
        echo "anchor: cannot build embree_rt (libembree-dev?): $(tail -n 1 "$DIR/build.log")" >&2
    fi
else
    echo "anchor: no anchor in $ANCHOR (or no python3): no race" >&2
fi
if [ -n "$have_anchor" ]; then
    for f in course_3840 spheres_1k spheres_100k spheres_1m; do
        [ -s "$DIR/$f.txt" ] || { python3 "$DIR/gen_spheres.py" all --dir "$DIR" 2>/dev/null; break; }
    done
    {
        echo "The anchor: $ANCHOR (embree_rt: Embree 3 packets of 8, every hit"
        echo "re-solved in double), built with its own Makefile (-O3 -march=native);"
        echo "its scenes from its gen_spheres.py. Both on $ALL threads, run for run"
        echo "alternately, $RUNS runs each; wall time of the whole command (reading,"
        echo "building, rendering, writing), median (best); peak memory: the"
        echo "process's maximum resident size. Ratios: raytrace over the anchor"
        echo "(below 1: raytrace is faster or smaller). Pixels: where the two"
        echo "pictures differ (ties the two break apart)."
        echo
        echo "The target (issue 50): at most 0.50 of the anchor's time on each"
        echo "scene, and at most 0.70 of its memory at 10^6 spheres (no more than"
        echo "its memory on the others)."
        echo
        echo "| scene | anchor | raytrace | time ratio (median, best) | anchor memory | raytrace memory | memory ratio | target | pixels that differ |"
        echo "|-------|--------|----------|---------------------------|---------------|-----------------|--------------|--------|--------------------|"
    } >>"$section"
    : >"$DIR/who"
    for s in course_3840 spheres_1k spheres_100k spheres_1m; do
        : >"$DIR/t-a"
        : >"$DIR/t-r"
        i=0
        while [ $i -lt "$RUNS" ]; do
            timed "$DIR/t-a" "$DIR/embree_rt" "$DIR/$s.txt" "$DIR/a.ppm" --threads "$ALL"
            timed "$DIR/t-r" "$RT" -q -j "$ALL" "$DIR/$s.txt" "$DIR/r.ppm"
            i=$((i + 1))
        done
        share=1
        [ "$s" = spheres_1m ] && share=0.7
        race_stats 0.5 "$share"
        printf '| %s | %s s | %s s | %.2f (%.2f) | %s | %s | %s |\n' "$s" "$(seconds "$a")" \
            "$(seconds "$r")" "$(echo "$r / $a" | bc -l)" "$(echo "$rb / $ab" | bc -l)" \
            "$mem" "$met" "${px:-0 of all}" >>"$section"
        echo "anchor: $s: anchor $a ms, raytrace $r ms" >&2
        # Who is right where they differ most: the row of that pixel again,
        # every ray against every sphere (--no-accel), on scenes where
        # that takes seconds.
        at=$(sed -n 's/^max error: [1-9][0-9]* at pixel (\([0-9]*\), \([0-9]*\)).*/\1 \2/p' "$DIR/diff.log")
        if [ -n "$at" ] && [ "$s" != spheres_1m ]; then
            set -- $at
            w=$(head -c 64 "$DIR/r.ppm" | sed -n 2p | cut -d' ' -f1)
            h=$(head -c 64 "$DIR/r.ppm" | sed -n 2p | cut -d' ' -f2)
            "$RT" -q --no-accel --tile "$(($2 + 1))/$h" --tile-layout bands "$DIR/$s.txt" "$DIR/row.ppm"
            loop=$(tail -c $((w * 3)) "$DIR/row.ppm" | dd bs=1 skip=$(($1 * 3)) count=3 2>/dev/null | od -An -tu1)
            ours=$(tail -c $(((h - $2) * w * 3)) "$DIR/r.ppm" | dd bs=1 skip=$(($1 * 3)) count=3 2>/dev/null | od -An -tu1)
            theirs=$(tail -c $(((h - $2) * w * 3)) "$DIR/a.ppm" | dd bs=1 skip=$(($1 * 3)) count=3 2>/dev/null | od -An -tu1)
            echo "$s: at pixel ($1, $2), the largest difference: anchor$theirs, raytrace$ours, every ray against every sphere$loop." |
                tr -s ' ' >>"$DIR/who"
        fi
    done
    echo >>"$section"
    if [ -s "$DIR/who" ]; then
        echo "Where the two differ most, the row is rendered again testing every ray" >>"$section"
        echo "against every sphere (\`--no-accel\`), which is the course's definition:" >>"$section"
        echo >>"$section"
        sed 's/^/- /' "$DIR/who" >>"$section"
        echo >>"$section"
    fi
    # What bounds the 1,000-sphere field: the same race at each depth
    # (both programs' --max-depth), so that what each kind of ray costs the
    # two is seen apart.
    {
        echo "### The 1,000-sphere field by depth"
        echo
        echo "spheres_1k again with both programs' \`--max-depth\` at 0 (primary rays"
        echo "and their shadow rays alone), 1 (the first mirror rays too) and 10 (the"
        echo "race's), run for run alternately, $RUNS runs each, medians of the whole"
        echo "command; the rays each depth casts (the anchor's count). Depth 0 is"
        echo "what the field costs before any mirror ray."
        echo
        echo "| depth | rays | anchor | raytrace | time ratio |"
        echo "|-------|------|--------|----------|------------|"
    } >>"$section"
    for d in 0 1 10; do
        : >"$DIR/t-a"
        : >"$DIR/t-r"
        i=0
        while [ $i -lt "$RUNS" ]; do
            timed "$DIR/t-a" "$DIR/embree_rt" "$DIR/spheres_1k.txt" "$DIR/a.ppm" --threads "$ALL" \
                --max-depth "$d"
            cp "$DIR/err" "$DIR/err-a"
            timed "$DIR/t-r" "$RT" -q -j "$ALL" --max-depth "$d" "$DIR/spheres_1k.txt" "$DIR/r.ppm"
            i=$((i + 1))
        done
        rays=$(sed -n 's/.*| rays \([0-9]*\) (primary \([0-9]*\), shadow \([0-9]*\), reflection \([0-9]*\)).*/\1 (\2 primary, \3 shadow, \4 reflection)/p' "$DIR/err-a")
        a=$(cut -d' ' -f1 "$DIR/t-a" | median)
        r=$(cut -d' ' -f1 "$DIR/t-r" | median)
        printf '| %s | %s | %s s | %s s | %.2f |\n' "$d" "${rays:-?}" "$(seconds "$a")" \
            "$(seconds "$r")" "$(echo "$r / $a" | bc -l)" >>"$section"
        echo "anchor: spheres_1k at depth $d: anchor $a ms, raytrace $r ms" >&2
    done
    echo >>"$section"
else
    echo "No anchor was found or built in this run (BENCH_ANCHOR, libembree-dev): no race." >>"$section"
    echo >>"$section"
fi

# The mesh race: embree_mesh (Embree 3 triangles, one ray at a time,
# every candidate re-solved in double) on its gen_meshes.py scenes, each
# program's read, build and render times beside the whole command's.
have_mesh=
if [ -n "$have_anchor" ] && [ -f "$ANCHOR/embree_mesh.c" ] && [ -f "$ANCHOR/gen_meshes.py" ]; then
    cp "$ANCHOR/embree_mesh.c" "$ANCHOR/gen_meshes.py" "$DIR/" 2>/dev/null
    chmod u+w "$DIR"/* 2>/dev/null
    if make -s -C "$DIR" embree_mesh >"$DIR/build.log" 2>&1; then
        have_mesh=yes
        [ -s "$DIR/meshes/mesh_4m.txt" ] || python3 "$DIR/gen_meshes.py" "$DIR/meshes" >/dev/null
    else
        echo "anchor: cannot build embree_mesh: $(tail -n 1 "$DIR/build.log")" >&2
    fi
fi
if [ -n "$have_mesh" ]; then
    {
        echo "### Meshes"
        echo
        echo "The anchor: embree_mesh (Embree 3 triangles, one ray at a time, every"
        echo "candidate re-solved in double); its scenes from its gen_meshes.py:"
        echo "bumpy spheres of 10^4, 10^6 (with and without vertex normals) and"
        echo "4 × 10^6 triangles over a mirror floor, 1920 × 1080. As above: $ALL"
        echo "threads, $RUNS runs each alternately, medians; each program's read,"
        echo "build and render times are its own report of the last run (raytrace's"
        echo "-v). The target (issue 72): at most 0.60 of the anchor's time and 0.80"
        echo "of its memory on each."
        echo
        echo "| scene | anchor read / build / render | raytrace read / build / render | anchor | raytrace | time ratio (median, best) | anchor memory | raytrace memory | memory ratio | target | pixels that differ |"
        echo "|-------|------------------------------|--------------------------------|--------|----------|---------------------------|---------------|-----------------|--------------|--------|--------------------|"
    } >>"$section"
    for s in mesh_10k mesh_1m mesh_1m_vn mesh_4m; do
        : >"$DIR/t-a"
        : >"$DIR/t-r"
        i=0
        while [ $i -lt "$RUNS" ]; do
            timed "$DIR/t-a" "$DIR/embree_mesh" "$DIR/meshes/$s.txt" "$DIR/a.ppm" --threads "$ALL"
            cp "$DIR/err" "$DIR/err-a"
            timed "$DIR/t-r" "$RT" -v -j "$ALL" "$DIR/meshes/$s.txt" "$DIR/r.ppm"
            i=$((i + 1))
        done
        phases_a=$(sed -n 's/.*read \([0-9.]*\) s, build \([0-9.]*\) s, render \([0-9.]*\) s.*/\1 \/ \2 \/ \3 s/p' "$DIR/err-a")
        phases_r="$(sed -n 's/^raytrace: read the scene in \([0-9.]*\) s.*/\1/p' "$DIR/err") / $(sed -n 's/^raytrace: bounding volume hierarchy: .* built in \([0-9.]*\) s.*/\1/p' "$DIR/err") / $(sed -n 's/^raytrace: rendered in \([0-9.]*\) s.*/\1/p' "$DIR/err") s"
        race_stats 0.6 0.8
        printf '| %s | %s | %s | %s s | %s s | %.2f (%.2f) | %s | %s | %s |\n' "$s" \
            "${phases_a:-?}" "$phases_r" "$(seconds "$a")" "$(seconds "$r")" \
            "$(echo "$r / $a" | bc -l)" "$(echo "$rb / $ab" | bc -l)" "$mem" "$met" \
            "${px:-0 of all}" >>"$section"
        echo "anchor: $s: anchor $a ms, raytrace $r ms" >&2
    done
    echo >>"$section"
fi

# Scaling with the sphere count: the benchmark's field at 480 x 270, and
# the anchor's times and memory on the same files when it was built.
{
    echo "### Time and memory against the sphere count"
    echo
    echo "The benchmark's field (tests/bench/scenegen.c) at 480 × 270, $ALL threads,"
    echo "one run each: reading, building the hierarchy, building the light"
    echo "buffers (— when the field has none) and rendering (from -v), peak memory"
    echo "and the memory it takes a sphere ((peak − the 10-sphere run's) / n)."
    if [ -n "$have_anchor" ]; then
        echo "Beside them, the anchor's on the same file (its own parse, build and"
        echo "render times, and its peak memory; its times exclude starting"
        echo "Embree's device)."
        echo
        echo "| spheres | read | build | light buffers | render | render / log2 n | peak memory | bytes a sphere | anchor's read | anchor's build | anchor's render | anchor's peak |"
        echo "|---------|------|-------|---------------|--------|-----------------|-------------|----------------|---------------|----------------|-----------------|---------------|"
    else
        echo
        echo "| spheres | read | build | light buffers | render | render / log2 n | peak memory | bytes a sphere |"
        echo "|---------|------|-------|---------------|--------|-----------------|-------------|----------------|"
    fi
} >>"$section"
: >"$DIR/fit"
: >"$DIR/plot-time"
: >"$DIR/plot-memory"
base=
n=10
while [ "$n" -le "$SCALE_MAX" ]; do
    "$GEN" spheres "$n" | resize /dev/stdin 480 >"$DIR/field.txt"
    "$RT" -v -j "$ALL" "$DIR/field.txt" "$DIR/field.ppm" 2>"$DIR/log" >/dev/null ||
        { cat "$DIR/log" >&2; exit 1; }
    read_s=$(sed -n 's/^raytrace: read the scene in \([0-9.]*\) s.*/\1/p' "$DIR/log")
    build_s=$(sed -n 's/^raytrace: bounding volume hierarchy: .* built in \([0-9.]*\) s.*/\1/p' "$DIR/log")
    buffers_s=$(sed -n 's/^raytrace: light buffers built in \([0-9.]*\) s$/\1 s/p' "$DIR/log")
    render_s=$(sed -n 's/^raytrace: rendered in \([0-9.]*\) s.*/\1/p' "$DIR/log")
    peak=$(sed -n 's/^raytrace: peak memory: \([0-9.]*\) MB$/\1/p' "$DIR/log")
    [ -n "$base" ] || base=$peak
    # Below 10,000 spheres the scene is lost in the process's own memory.
    per=—
    [ "$n" -lt 10000 ] || per=$(printf '%.0f' "$(echo "($peak - $base) * 1000000 / $n" | bc -l)")
    lg=$(echo "l($n) / l(2)" | bc -l)
    row=$(printf '| %s | %s s | %s s | %s | %s s | %.4f s | %s MB | %s |' "$n" "$read_s" \
        "${build_s:-0}" "${buffers_s:-—}" "$render_s" "$(echo "$render_s / $lg" | bc -l)" \
        "$peak" "$per")
    echo "raytrace-build $n ${build_s:-0}" >>"$DIR/plot-time"
    echo "raytrace-render $n $render_s" >>"$DIR/plot-time"
    echo "raytrace-peak $n $peak" >>"$DIR/plot-memory"
    if [ -n "$have_anchor" ]; then
        : >"$DIR/t-s"
        timed "$DIR/t-s" "$DIR/embree_rt" "$DIR/field.txt" "$DIR/a.ppm" --threads "$ALL" \
            --stats "$DIR/stats"
        line=$(tail -n 1 "$DIR/stats")
        a_read=$(echo "$line" | sed -n 's/.*| parse \([0-9.]*\) s |.*/\1/p')
        a_build=$(echo "$line" | sed -n 's/.*| build \([0-9.]*\) s |.*/\1/p')
        a_render=$(echo "$line" | sed -n 's/.*| render \([0-9.]*\) s |.*/\1/p')
        a_peak=$(awk '{ printf "%.1f", $2 / 1024 }' "$DIR/t-s")
        row="$row $a_read s | $a_build s | $a_render s | $a_peak MB |"
        echo "anchor-build $n $a_build" >>"$DIR/plot-time"
        echo "anchor-render $n $a_render" >>"$DIR/plot-time"
        echo "anchor-peak $n $a_peak" >>"$DIR/plot-memory"
    fi
    echo "$row" >>"$section"
    echo "$lg $render_s" >>"$DIR/fit"
    echo "anchor: scaling: $n spheres" >&2
    n=$((n * 10))
done
rm -f "$DIR/field.txt" "$DIR/stats"
# Drawn too (tests/bench/plot.awk), for the report.
awk -v title="Build and render time against the sphere count (480 x 270, $ALL threads)" \
    -v xlabel="spheres" -v ylabel="time (s)" -v logx=1 -v logy=1 \
    -f tests/bench/plot.awk "$DIR/plot-time" >docs/bench-scaling.svg
awk -v title="Peak memory against the sphere count" -v xlabel="spheres" \
    -v ylabel="peak memory (MB)" -v logx=1 -v logy=1 \
    -f tests/bench/plot.awk "$DIR/plot-memory" >docs/bench-memory.svg
# The render time fitted as a + b log2 n (least squares, n >= 1000).
awk 'NR >= 3 { x += $1; y += $2; xx += $1 * $1; xy += $1 * $2; yy += $2 * $2; k++ }
    END { b = (k * xy - x * y) / (k * xx - x * x); a = (y - b * x) / k
          r = (k * xy - x * y) / sqrt((k * xx - x * x) * (k * yy - y * y))
          printf "\nRender time fitted from 1,000 spheres on: %.4f s + %.4f s × log2 n (correlation %.3f).\n\n", a, b, r }' \
    "$DIR/fit" >>"$section"
{
    echo "![build and render time against the sphere count](bench-scaling.svg)"
    echo
    echo "![peak memory against the sphere count](bench-memory.svg)"
    echo
} >>"$section"

# The shapes' fields: the same positions as spheres, cubes and cylinders.
{
    echo "### Fields of each bounded and unbounded shape"
    echo
    echo "The field in the keyword format (\`scenegen field KIND N\`: the same"
    echo "positions, eight Blinn-Phong materials, a floor plane, a distant light),"
    echo "1920 × 1080, $ALL threads, median of $RUNS runs of the whole command."
    echo "Cubes and squares go into the hierarchy like spheres; infinite cylinders"
    echo "and cones cannot (they have no box), so every ray tests each of them:"
    echo "their fields are measured at sizes a renderer can finish."
    echo
    echo "| shape | count | wall time | over spheres of the same count |"
    echo "|-------|-------|-----------|--------------------------------|"
} >>"$section"
for spec in "sphere 100000" "cube 100000" "square 100000" "sphere 10" "cylinder 10" \
    "cone 10" "sphere 100" "cylinder 100" "cone 100"; do
    set -- $spec
    "$GEN" field "$1" "$2" >"$DIR/$1-$2.txt"
    : >"$DIR/t-f"
    i=0
    while [ $i -lt "$RUNS" ]; do
        timed "$DIR/t-f" "$RT" -q -j "$ALL" "$DIR/$1-$2.txt" "$DIR/f.ppm"
        i=$((i + 1))
    done
    ms=$(cut -d' ' -f1 "$DIR/t-f" | median)
    [ "$1" = sphere ] && eval "sphere_$2=$ms"
    eval "ref=\$sphere_$2"
    printf '| %s | %s | %s s | %.2f× |\n' "$1" "$2" "$(seconds "$ms")" \
        "$(echo "$ms / $ref" | bc -l)" >>"$section"
    echo "anchor: field of $2 ${1}s: $ms ms" >&2
done
echo "<!-- anchor.sh: end -->" >>"$section"

# Into OUT, in place of the last section it wrote, or at its end.
if grep -q '^<!-- anchor.sh: begin -->$' "$OUT" 2>/dev/null; then
    awk -v f="$section" '/^<!-- anchor.sh: begin -->$/ { while ((getline l < f) > 0) print l; skip = 1; next }
        /^<!-- anchor.sh: end -->$/ { skip = 0; next } !skip' "$OUT" >"$DIR/out.md" &&
        cat "$DIR/out.md" >"$OUT"
else
    { echo; cat "$section"; } >>"$OUT"
fi
echo "anchor: wrote $OUT" >&2
