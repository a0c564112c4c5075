#!/bin/sh
# noise.sh: --noise as users run it: the same bytes on any number of
# threads and any tiles, what -v and --spp-map tell, the options' errors
# and notes, a scene's c Noise line, and the estimate against the truth
# (the measured error of a render against a converged one stays within
# the level asked for; make trade measures the trade in full).
#
# Usage: sh tests/noise.sh RAYTRACE RAYTRACE-DIFF RAYTRACE-MERGE (from the
# repository root). RAYTRACE_TEST_LEVEL=quick (make test) checks fewer
# scenes and skips the converged reference.

RT=$1
DIFF=$2
MERGE=$3
SUITE=noise
. "$(dirname "$0")/check.sh"

# --- the bytes are each pixel's own: threads and tiles change none ---
# A lens (focus), and occlusion with gathering (indirect); make check adds
# textures and glass (materials) and the MPL model (its gamma).
scenes="focus indirect"
full && scenes="$scenes materials mpl"
for s in $scenes; do
    opts="--size 64x48 --noise 3 --max-spp 256"
    [ "$s" = indirect ] && opts="$opts --ao 2 --gi 2"
    for j in 1 2 7; do
        # shellcheck disable=SC2086
        expect_exit "$s -j$j" 0 "$RT" -j$j $opts "scenes/$s.txt" "$T/$s-$j.ppm"
    done
    cmp -s "$T/$s-1.ppm" "$T/$s-2.ppm" && cmp -s "$T/$s-1.ppm" "$T/$s-7.ppm" && pass ||
        fail "$s: --noise renders differ between 1, 2 and 7 threads"
    for k in 1 2 3; do
        # shellcheck disable=SC2086
        "$RT" -q -j2 $opts --tile $k/3 "scenes/$s.txt" "$T/$s-t$k.ppm" || fail "$s: tile $k/3"
    done
    "$MERGE" "$T/$s-tiles.ppm" "$T/$s-t1.ppm" "$T/$s-t2.ppm" "$T/$s-t3.ppm" 2>"$T/err" &&
        cmp -s "$T/$s-1.ppm" "$T/$s-tiles.ppm" && pass ||
        fail "$s: --noise tiles do not merge into the whole render" "$(cat "$T/err")"
done

# --- -v and --spp-map tell where the samples went ---
expect_exit "-v" 0 "$RT" -v --size 64x48 --noise 2 --spp-map "$T/map.png" scenes/focus.txt \
    "$T/focus.png"
expect_grep "-v" "raytrace: 64 x 48 pixels, --noise 2 (32 to 4096 samples a pixel)" "$T/err"
expect_grep "-v" "raytrace: --noise 2: samples a pixel 32 to 4096: mean " "$T/err"
expect_grep "-v" "raytrace: estimated error (one standard error, 68% confidence): mean " "$T/err"
expect_grep "-v" "raytrace: map of samples: $T/map.png" "$T/err"
"$DIFF" "$T/focus.png" "$T/map.png" >"$T/out" 2>&1
[ $? -le 1 ] && grep -q 'image: .*64 x 48, PNG' "$T/out" && pass ||
    fail "--spp-map is not a 64 x 48 PNG" "$(cat "$T/out")"
# In focus.txt the sharp plane in focus is flat and the blurred ones are
# not: the map is black somewhere (the least) and bright somewhere.
"$DIFF" -q "$T/map.png" "$T/map.png" && pass || fail "--spp-map unreadable"

# --- the options: errors, notes, what wins ---
for args in "--noise -1" "--noise 256" "--noise x" "--min-spp 0" "--max-spp 1048577" \
    "--min-spp 64 --max-spp 16" "--noise 1 --spp-map="; do
    # shellcheck disable=SC2086
    expect_exit "usage '$args'" 2 "$RT" $args scenes/course.txt "$T/x.ppm"
done
expect_exit "--spp under --noise" 0 "$RT" --noise 4 -s 8 --size 16x16 scenes/focus.txt "$T/n.ppm"
expect_grep "--spp under --noise" "raytrace: note: --spp changes nothing here: --noise takes" "$T/err"
"$RT" -q --noise 4 --size 16x16 scenes/focus.txt "$T/n2.ppm"
cmp -s "$T/n.ppm" "$T/n2.ppm" && pass || fail "-s changed a --noise render"
expect_exit "--min-spp alone" 0 "$RT" --min-spp 8 --size 16x16 scenes/focus.txt "$T/m.ppm"
expect_grep "--min-spp alone" "raytrace: note: --min-spp and --max-spp change nothing without --noise" "$T/err"
expect_exit "--spp-map alone" 0 "$RT" --spp-map "$T/alone.png" --size 16x16 scenes/focus.txt "$T/m.ppm"
expect_grep "--spp-map alone" "raytrace: note: --spp-map writes nothing without --noise" "$T/err"
[ ! -e "$T/alone.png" ] && pass || fail "--spp-map without --noise wrote a map"
cp "$T/n.ppm" "$T/keep.ppm"
expect_exit "--spp-map onto the output" 1 "$RT" --noise 4 --spp-map "$T/keep.ppm" --size 16x16 \
    scenes/focus.txt "$T/keep.ppm"
expect_grep "--spp-map onto the output" "--spp-map must name a file of its own" "$T/err"
cmp -s "$T/n.ppm" "$T/keep.ppm" && pass || fail "a refused --spp-map damaged the output"
expect_exit "--spp-map in a missing folder" 1 "$RT" --noise 4 --spp-map "$T/no/map.png" \
    --size 16x16 scenes/focus.txt "$T/new.ppm"
[ ! -e "$T/new.ppm" ] && pass || fail "a --spp-map that cannot be written left an output"
expect_clean "no temporary file" "$T"
# A bound alone moves the other's default out of its way.
expect_exit "--max-spp 8" 0 "$RT" -v --noise 0.01 --max-spp 8 --size 8x8 scenes/focus.txt "$T/m.ppm"
expect_grep "--max-spp 8" "--noise 0.01 (8 to 8 samples a pixel)" "$T/err"

# --- a scene's c Noise, and --noise 0 over it ---
{ echo "c Noise 3 32 128"; grep -v '^#' scenes/indirect.txt | grep -v '^c Samples'; } >"$T/noisy.txt"
expect_exit "c Noise" 0 "$RT" -v --size 32x32 "$T/noisy.txt" "$T/noisy.ppm"
expect_grep "c Noise" "--noise 3 (32 to 128 samples a pixel)" "$T/err"
expect_exit "--noise 0 over c Noise" 0 "$RT" -v --noise 0 --size 32x32 "$T/noisy.txt" "$T/off.ppm"
expect_grep "--noise 0 over c Noise" "32 x 32 pixels, 4 samples per pixel" "$T/err"
"$RT" -q --size 32x32 --noise 3 --min-spp 32 --max-spp 128 scenes/indirect.txt "$T/cmd.ppm"
cmp -s "$T/noisy.ppm" "$T/cmd.ppm" && pass || fail "c Noise 3 32 128 is not --noise 3 --min-spp 32 --max-spp 128"

# --- README's map is the gallery render's (make check; golden.sh checks
# the render) ---
if full; then
    "$RT" -q --noise 4 --max-spp 1024 --spp-map "$T/gmap.png" scenes/materials.txt "$T/g.png" &&
        "$DIFF" -q docs/gallery/materials-noise4maxspp1024-spp.png "$T/gmap.png" && pass ||
        fail "docs/gallery/materials-noise4maxspp1024-spp.png is not the map of its render (run make gallery)"
fi

# --- the estimate against the truth (make check) ---
# indirect.txt with occlusion and gathering, 48 x 48: a converged render
# (uniform, 256 samples of 16 rays), then --noise 2: over the pixels that
# needed more than the first round, the measured RMSE (the 8-bit render's
# rounding, 0.29 levels, included) lies between half the level and the
# level and a half.
if full; then
    opts="--size 48x48 --ao 16 --gi 16"
    # shellcheck disable=SC2086
    "$RT" -q $opts -s 256 --format pfm scenes/indirect.txt "$T/ref.pfm" || fail "reference render"
    # shellcheck disable=SC2086
    "$RT" -q $opts --noise 2 --spp-map "$T/spp.ppm" scenes/indirect.txt "$T/adaptive.ppm" ||
        fail "--noise 2 render"
    "$DIFF" --clamp --only "$T/spp.ppm" "$T/ref.pfm" "$T/adaptive.ppm" >"$T/out" 2>&1
    rms=$(sed -n 's/^mean error: .*, RMS error: \([0-9.e+-]*\),.*/\1/p' "$T/out")
    echo "$rms" | awk '{ exit !($1 >= 1 && $1 <= 3) }' && pass ||
        fail "--noise 2: RMSE $rms over the sampled pixels, outside [1, 3]" "$(cat "$T/out")"
fi

finish
