#!/bin/sh
# mpl.sh: the MPL ray tracer's four scenes rendered by raytrace with its
# program's model and defaults, against the renders its program made,
# both box-filtered to 100 x 100 (raytrace-diff --box): the mean absolute
# difference (levels) and the share of boxes off by more than 32 levels in
# some channel. Targets: at most 12 levels and 5% on each scene.
#
# Usage: sh tests/bench/mpl.sh RAYTRACER [OUTDIR]   (make mpl
#        MPL=RAYTRACER): RAYTRACER is a checkout of the repository its
#        report names (github.com/Paillette/Raytracer): its scenes in
#        RayTracer/Scene/, its textures in RayTracer/Textures/, its renders
#        where the table below says. Our renders go to OUTDIR (default: a
#        temporary folder, removed). MPL_OPTS adds options to every
#        render (say --model physical, or --ao 0). Nothing here is run by
#        make test.
set -eu
cd "$(dirname "$0")/../.."
REPO=${1:?usage: mpl.sh RAYTRACER [OUTDIR]}
RT=./raytrace
DIFF=./raytrace-diff
[ -x "$RT" ] && [ -x "$DIFF" ] || { echo "mpl.sh: run make first" >&2; exit 2; }
[ -f "$REPO/RayTracer/Scene/scene1.txt" ] ||
    { echo "mpl.sh: no RayTracer/Scene/scene1.txt in $REPO" >&2; exit 2; }
if [ $# -ge 2 ]; then
    OUT=$2
    mkdir -p "$OUT"
else
    OUT=$(mktemp -d "${TMPDIR:-/tmp}/raytrace-mpl.XXXXXX")
    trap 'rm -rf "$OUT"' EXIT
fi

# scene N, its render (BMP files named .jpg, and one JPEG), its size.
set -- 1 RayTracer/scene1.jpg 500x500 \
    2 RayTracer/Screenshots/Scene2HD.jpg 500x500 \
    3 RayTracer/Screenshots/renduScene3.jpg 500x500 \
    4 RayTracer/Screenshots/scene4.jpg 1000x1000

echo "| scene | its render | size | time | mean abs. difference | boxes off by > 32 | target |"
echo "|-------|------------|------|------|----------------------|-------------------|--------|"
missed=0
while [ $# -ge 3 ]; do
    n=$1 name=${2##*/} ref=$REPO/$2 size=$3
    shift 3
    start=$(date +%s.%N)
    # shellcheck disable=SC2086
    "$RT" -q --size "$size" ${MPL_OPTS:-} "$REPO/RayTracer/Scene/scene$n.txt" "$OUT/scene$n.png"
    end=$(date +%s.%N)
    "$DIFF" --box 100x100 -t 32 "$ref" "$OUT/scene$n.png" >"$OUT/diff$n.txt" || true
    mad=$(sed -n 's/^mean error: \([0-9.e+-]*\),.*/\1/p' "$OUT/diff$n.txt")
    far=$(sed -n 's/^over tolerance 32: .*(\([0-9.]*\)%).*/\1/p' "$OUT/diff$n.txt")
    [ -n "$mad" ] && [ -n "$far" ] || { cat "$OUT/diff$n.txt" >&2; exit 1; }
    ok=$(echo "$mad <= 12 && $far <= 5" | bc -l)
    [ "$ok" = 1 ] && verdict=met || { verdict=MISSED; missed=1; }
    printf '| scene%s.txt | %s | %s | %.1f s | %.1f | %.1f%% | %s |\n' "$n" "$name" "$size" \
        "$(echo "$end - $start" | bc -l)" "$mad" "$far" "$verdict"
done
exit $missed
