#!/bin/sh
# memcheck.sh: a few renders and comparisons under Valgrind's memcheck
# (`make memcheck`, and CI): no invalid read or write, no use of an
# uninitialised value, no leak, on the success paths and the failure ones.
#
# Usage: sh tests/memcheck.sh RAYTRACE RAYTRACE-DIFF [RAYTRACE-MERGE]
#        (from the repository root)

RT=$1
DIFF=$2
MERGE=${3:-./raytrace-merge}
T=$(mktemp -d "${TMPDIR:-/tmp}/raytrace-memcheck.XXXXXX") || exit 2
passed=0
failed=0

# run NAME CODE COMMAND...: COMMAND under memcheck must exit CODE with no
# Valgrind error (Valgrind's own exit code would be 99).
run() {
    name=$1 code=$2
    shift 2
    valgrind -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect \
        --show-leak-kinds=definite,indirect --track-origins=yes "$@" >"$T/out" 2>"$T/err"
    got=$?
    if [ "$got" = "$code" ]; then
        passed=$((passed + 1))
    else
        failed=$((failed + 1))
        echo "FAIL $name: exit $got, expected $code" >&2
        sed 's/^/    /' "$T/err" | head -40 >&2
    fi
}

. tests/lib.sh

# small SCENE WIDTH: the example scene at WIDTH pixels wide (memcheck runs
# some 50 times slower), kept in scenes/ for its textures and meshes.
small() { resize "$1" "$2" >"scenes/.memcheck-$(basename "$1")"; }
trap 'rm -rf "$T" scenes/.memcheck-*' EXIT

command -v valgrind >/dev/null || { echo "memcheck: valgrind is not installed" >&2; exit 1; }
for s in course keyword textures glass; do small "scenes/$s.txt" 48; done
sed 's/^c Camera \(.*\) 640 400$/c Camera \1 48 30/' scenes/materials.txt >scenes/.memcheck-materials.txt
sed 's/^c Camera \(.*\) 400 400$/c Camera \1 24 24/' scenes/indirect.txt >scenes/.memcheck-indirect.txt
run "course scene" 0 "$RT" -q -j 2 scenes/course.txt "$T/course.ppm"
run "keyword scene, mesh and hierarchy" 0 "$RT" -q -j 2 scenes/.memcheck-keyword.txt "$T/keyword.png"
run "textures, samples, PFM" 0 "$RT" -q -j 1 --spp 2 scenes/.memcheck-textures.txt "$T/textures.pfm"
run "glass, depth 30, cut-off" 0 "$RT" -q -j 1 -d 30 --cutoff 0.5 scenes/.memcheck-glass.txt "$T/glass.ppm"
# A field of 1.2 MiB of sphere: records, read on every thread, and the
# same with a fault near its end, which sends the reading back to one.
awk 'BEGIN { print "0 0 -10\n-1 1 -9\n1 1 -9\n-1 -1 -9\n8\n0 0 0\n5 9 -20 255 255 255"
             for (i = 0; i < 34000; i++)
                 printf "sphere: %d.5 %d -%d 0.25 10 20 30 0.2\n", i % 97 - 48, i % 89 - 44, i % 83 }' \
    >"$T/field.txt"
run "a large field read on every thread" 0 "$RT" -q -j 2 "$T/field.txt" "$T/field.ppm"
sed '33000s/0.25/x/' "$T/field.txt" >"$T/field-bad.txt"
run "a fault in a large field" 1 "$RT" -q -j 2 "$T/field-bad.txt" "$T/field.ppm"
run "save a keyword scene" 0 "$RT" --save "$T/saved.txt" scenes/keyword.txt
run "MPL scene, JPEG textures, every material, JPEG out" 0 "$RT" -q -j 2 \
    scenes/.memcheck-materials.txt "$T/materials.jpg"
run "mip-maps and ray differentials, EWA, through glass and mirrors" 0 "$RT" -q -j 2 \
    --texture-filter ewa -s 2 scenes/.memcheck-materials.txt "$T/materials-ewa.ppm"
run "--noise, -v and the map of samples" 0 "$RT" -q -j 2 -v --noise 4 --max-spp 64 \
    --spp-map "$T/map.png" scenes/.memcheck-materials.txt "$T/materials-noise.png"
run "ambient occlusion and global illumination" 0 "$RT" -q -j 2 --ao 4 --gi 3 --gi-bounces 2 \
    scenes/.memcheck-indirect.txt "$T/indirect.ppm"
run "the irradiance cache: its pre-pass on two threads, two bounces, its map" 0 "$RT" -q -j 2 \
    --gi 16 --gi-bounces 2 --gi-cache --gi-cache-map "$T/cache-map.png" \
    scenes/.memcheck-indirect.txt "$T/indirect-cache.ppm"
run "the MPL model: its example, textures, occlusion, gathering" 0 "$RT" -q -j 2 \
    --size 16x16 scenes/mpl.txt "$T/mpl.png"
run "raytrace-diff, a BMP and --box" 0 "$DIFF" -q --box 2x1 tests/fuzz/corpus/picture/rgb24.bmp \
    tests/fuzz/corpus/picture/palette8.bmp
run "a tile" 0 "$RT" -q -j 2 --tile 1/2 scenes/.memcheck-glass.txt "$T/tile-1.ppm"
"$RT" -q --tile 2/2 scenes/.memcheck-glass.txt "$T/tile-2.png"
run "raytrace-merge" 0 "$MERGE" -q "$T/merged.png" "$T/tile-2.png" "$T/tile-1.ppm"
run "raytrace-merge, a tile missing" 1 "$MERGE" -q "$T/merged.png" "$T/tile-2.png"
run "a scene fault" 1 "$RT" -q tests/hostile/mesh-bad-index.txt "$T/bad.ppm"
run "a memory limit" 1 "$RT" -q --memory-limit 1K scenes/mirrors.txt "$T/bad.ppm"
run "an unwritable output" 1 "$RT" -q scenes/course.txt "$T/no/dir/out.ppm"
run "raytrace-diff, PNG against PPM" 0 "$DIFF" -q "$T/course.ppm" "$T/course.ppm"
"$RT" -q -d 1 scenes/.memcheck-glass.txt "$T/glass-2.ppm"
run "raytrace-diff, images that differ" 1 "$DIFF" -q --diff "$T/d.png" "$T/glass.ppm" "$T/glass-2.ppm"
run "raytrace-diff, sizes that differ" 2 "$DIFF" -q "$T/keyword.png" "$T/course.ppm"
echo "memcheck: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
