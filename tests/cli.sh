#!/bin/sh
# cli.sh: tests of the raytrace command as users run it: exit codes, error
# positions, outputs never damaged, standard input and output, formats,
# options, the hierarchy against the loops.
#
# Usage: sh tests/cli.sh RAYTRACE RAYTRACE-DIFF   (run from the repository root)
# Environment: RT_FLOAT, the single-precision build, to check it too;
# RAYTRACE_TEST_LEVEL=quick (make test) checks the hierarchy on fewer
# objects. The golden renders are tests/golden.sh's.

RT=$1
DIFF=$2
SUITE=cli
. "$(dirname "$0")/check.sh"


scene=scenes/course.txt
grep -v '^#' tests/golden.sha256 >"$T/golden"
printf '0 0 0\n-1 1 1\n1 1 1\n-1 -1 1\n8\n0 0 0\n0 5 0 255 255 255\nsphere: 0 0 5 1 200 100 50 0.25\n' >"$T/small.txt"

# --- README's samples of what the programs print are what they print ---
if sh docs/samples.sh --check README.md >"$T/out" 2>"$T/err"; then pass; else
    fail "README.md's samples are stale: run make samples" "$(cat "$T/err")"; fi

# --- help, version, usage errors ---
expect_exit help 0 "$RT" --help
expect_grep help 'Usage: raytrace [OPTIONS] SCENE OUTPUT' "$T/out"
expect_grep help 'Exit status' "$T/out"
expect_exit version 0 "$RT" --version
expect_grep version 'raytrace ' "$T/out"
for args in "" "$scene" "--bogus $scene x.ppm" "--max-depth $scene x.ppm" \
    "--max-depth -1 $scene x.ppm" "--max-depth 1001 $scene x.ppm" "--threads 0 $scene x.ppm" \
    "-j x $scene x.ppm" "$scene a.ppm b.ppm" "--spp 0 $scene x.ppm" "--spp 65537 $scene x.ppm" \
    "-s 2.5 $scene x.ppm" "--ao -1 $scene x.ppm" "--ao 4097 $scene x.ppm" \
    "--gi 2.5 $scene x.ppm" "--gi-bounces 0 $scene x.ppm" "--gi-bounces 65 $scene x.ppm" \
    "--ao-distance -1 $scene x.ppm" "--ao-distance x $scene x.ppm"; do
    # shellcheck disable=SC2086
    expect_exit "usage '$args'" 2 "$RT" $args
    expect_line "usage '$args' says how to get help" 2 "Try 'raytrace --help'." "$T/err"
    n=$(wc -l <"$T/err")
    [ "$n" -eq 2 ] && pass || fail "usage '$args': $n lines on stderr, expected 2"
done
# Ambient occlusion and global illumination: what -v says of them, and a
# scene's own settings (the MPL ray tracer's c AO and c GI lines) that options override.
expect_exit "ao and gi" 0 "$RT" -v --ao 4 --ao-distance 2.5 --gi 3 --gi-bounces 2 \
    scenes/indirect.txt "$T/ind.ppm"
expect_grep "ao and gi" 'raytrace: ambient occlusion: 4 rays a point, distance 2.5' "$T/err"
expect_grep "ao and gi" 'raytrace: global illumination: 3 rays a point, 2 bounces' "$T/err"
{ echo "c AO 8 0.5"; echo "c GI 2 3"; grep -v '^#' scenes/indirect.txt; } >"$T/ind-set.txt"
expect_exit "scene ao and gi" 0 "$RT" -v "$T/ind-set.txt" "$T/ind.ppm"
expect_grep "scene ao and gi" 'raytrace: ambient occlusion: 8 rays a point, distance 0.5' "$T/err"
expect_grep "scene ao and gi" 'raytrace: global illumination: 2 rays a point, 3 bounces' "$T/err"
expect_exit "options over scene" 0 "$RT" -v --ao 0 --gi 0 "$T/ind-set.txt" "$T/ind.ppm"
grep -q 'occlusion' "$T/err" && fail "--ao 0 --gi 0 still casts indirect rays" "$(cat "$T/err")" ||
    pass
"$RT" -q scenes/indirect.txt "$T/plain.ppm"
cmp -s "$T/ind.ppm" "$T/plain.ppm" && pass || fail "--ao 0 --gi 0 over the scene's: not the plain render"
expect_exit "empty OUTPUT" 2 "$RT" "$scene" ""
expect_line "empty OUTPUT" 1 "raytrace: OUTPUT is an empty file name" "$T/err"
expect_exit "empty SCENE" 2 "$RT" "" "$T/x.ppm"
expect_exit "option forms" 0 "$RT" --max-depth=3 -j1 -d 2 --threads 2 -q "$T/small.txt" "$T/forms.ppm"
expect_exit "-- ends options" 0 "$RT" -- "$T/small.txt" "$T/forms.ppm"
expect_exit "--spp forms" 0 "$RT" --spp=4 -s 2 --spp 3 "$T/small.txt" "$T/forms.ppm"

# --- --spp overrides a samples: record; textures are found beside the scene ---
expect_exit "--spp 1 over samples: 4" 0 "$RT" --spp 1 scenes/glass.txt "$T/glass1.ppm"
sed 's/^samples: 4/samples: 1/' scenes/glass.txt >"$T/glass-1.txt"
mkdir "$T/textures" && cp scenes/textures/checker.ppm "$T/textures/"
expect_exit "samples: 1 (texture beside the scene)" 0 "$RT" "$T/glass-1.txt" "$T/glass-1.ppm"
cmp -s "$T/glass1.ppm" "$T/glass-1.ppm" && pass || fail "--spp 1 differs from samples: 1"
here=$(pwd)
(cd / && "$here/$RT" "$here/scenes/textures.txt" "$T/tex.ppm" 2>"$T/err") && pass ||
    fail "texture paths from another directory" "$(cat "$T/err")"
rm "$T/textures/checker.ppm"
expect_exit "missing texture" 1 "$RT" "$T/glass-1.txt" "$T/missing.ppm"
expect_line "missing texture message" 1 \
    "raytrace: $T/glass-1.txt:20:10: error: cannot use the texture 'textures/checker.ppm': cannot open: No such file or directory" "$T/err"
[ ! -e "$T/missing.ppm" ] && pass || fail "missing texture left an output"

# --- quiet on success when stderr is not a terminal ---
expect_exit render 0 "$RT" "$scene" "$T/course.ppm"
[ ! -s "$T/err" ] && [ ! -s "$T/out" ] && pass || fail "render is not quiet" "$(cat "$T/err")"
expect_clean "render leaves no temporary file" "$T"

# --- on a terminal: a one-line summary, unless -q (util-linux's script fakes one) ---
if script -qc true /dev/null >/dev/null 2>&1; then
    script -qc "$RT $T/small.txt $T/tty.ppm" /dev/null >"$T/tty" 2>&1
    expect_grep "summary on a terminal" "raytrace: wrote $T/tty.ppm: 8 x 8 pixels, 1 object," "$T/tty"
    script -qc "$RT -q $T/small.txt $T/tty.ppm" /dev/null >"$T/tty" 2>&1
    [ ! -s "$T/tty" ] && pass || fail "-q prints on a terminal" "$(cat "$T/tty")"
    # A render long enough for the progress bar (half a second on one
    # thread), which is then erased.
    script -qc "$RT -j 1 --spp 16 --size 240x180 scenes/glass.txt $T/bar.ppm" /dev/null >"$T/tty" 2>&1
    expect_grep "progress bar" "% [#" "$T/tty"
    expect_grep "progress ETA" " s left" "$T/tty"
    expect_grep "progress bar erased" "$(printf '\r\033[K')raytrace: wrote" "$T/tty"
    script -qc "$RT -q -j 1 --spp 16 --size 240x180 scenes/glass.txt $T/bar.ppm" /dev/null >"$T/tty" 2>&1
    [ ! -s "$T/tty" ] && pass || fail "-q draws a progress bar" "$(cat "$T/tty")"
elif [ "${RAYTRACE_TEST_TOOLS:-}" = required ]; then
    fail "script(1) is missing: the terminal tests cannot run"
fi

# --- output formats hold the same pixels ---
expect_exit "png by extension" 0 "$RT" "$scene" "$T/course.png"
head -c 8 "$T/course.png" | od -An -tx1 | grep -q '89 50 4e 47 0d 0a 1a 0a' && pass || fail "no PNG signature"
expect_exit "png = ppm" 0 "$DIFF" "$T/course.ppm" "$T/course.png"
expect_exit "png stored" 0 "$RT" --png-deflate stored "$scene" "$T/stored.png"
expect_exit "stored png = ppm" 0 "$DIFF" "$T/course.ppm" "$T/stored.png"
[ "$(wc -c <"$T/stored.png")" -gt "$(wc -c <"$T/course.png")" ] && pass || fail "fixed Huffman PNG is not smaller than stored"
# Independent decoders, when installed (.ci/run installs them and sets
# RAYTRACE_TEST_TOOLS=required, so that CI cannot skip them).
if command -v pngcheck >/dev/null; then
    pngcheck -q "$T/course.png" "$T/stored.png" >"$T/out" 2>&1 && pass || fail "pngcheck" "$(cat "$T/out")"
elif [ "${RAYTRACE_TEST_TOOLS:-}" = required ]; then
    fail "pngcheck is missing"
fi
if command -v pngtopnm >/dev/null; then
    pngtopnm "$T/course.png" >"$T/netpbm.ppm" 2>"$T/err" && cmp -s "$T/netpbm.ppm" "$T/course.ppm" && pass ||
        fail "netpbm's pngtopnm decodes other pixels" "$(cat "$T/err")"
    # And raytrace-diff reads PNGs of other tools (dynamic Huffman codes).
    pnmtopng "$T/course.ppm" >"$T/netpbm.png" 2>"$T/err" &&
        "$DIFF" -q "$T/course.ppm" "$T/netpbm.png" 2>>"$T/err" && pass ||
        fail "raytrace-diff cannot read netpbm's PNG" "$(cat "$T/err")"
elif [ "${RAYTRACE_TEST_TOOLS:-}" = required ]; then
    fail "pngtopnm is missing"
fi
for f in glass focus; do
    expect_exit "$f png" 0 "$RT" --spp 2 "scenes/$f.txt" "$T/$f.png"
    expect_exit "$f ppm" 0 "$RT" --spp 2 "scenes/$f.txt" "$T/$f.ppm"
    expect_exit "$f png = ppm" 0 "$DIFF" "$T/$f.ppm" "$T/$f.png"
done
# BMP: 24 bits, rows bottom to top, padded to 4 bytes (a 7-pixel width
# needs 3 bytes of it), the PPM's pixels; netpbm's bmptopnm, when
# installed, reads them too.
expect_exit "bmp by extension" 0 "$RT" "$scene" "$T/course.bmp"
expect_exit "bmp = ppm" 0 "$DIFF" "$T/course.ppm" "$T/course.bmp"
expect_exit "odd bmp" 0 "$RT" --size 7x5 "$scene" "$T/odd.BMP"
expect_exit "odd ppm" 0 "$RT" --size 7x5 "$scene" "$T/odd.ppm"
[ "$(head -c 2 "$T/odd.BMP")" = BM ] && [ "$(wc -c <"$T/odd.BMP")" -eq $((54 + 24 * 5)) ] && pass ||
    fail "a 7 x 5 BMP is not 54 + 5 rows of 24 bytes" "$(describe "$T/odd.BMP")"
if command -v bmptopnm >/dev/null; then
    for f in course odd; do
        b=$T/$f.bmp
        [ -f "$b" ] || b=$T/$f.BMP
        bmptopnm "$b" >"$T/netpbm.ppm" 2>"$T/err" && cmp -s "$T/netpbm.ppm" "$T/$f.ppm" && pass ||
            fail "netpbm's bmptopnm reads other pixels in $b" "$(cat "$T/err")"
    done
elif [ "${RAYTRACE_TEST_TOOLS:-}" = required ]; then
    fail "bmptopnm is missing"
fi
# An image format raytrace cannot write: exit 2, the formats it writes, no
# file; --format overrides the name.
for ext in tif TIFF gif webp exr tga; do
    expect_exit "out.$ext refused" 2 "$RT" "$scene" "$T/out.$ext"
    expect_grep "out.$ext lists the formats" "it writes PPM (.ppm), PNG (.png), PFM (.pfm), JPEG (.jpg, .jpeg) and BMP (.bmp)" "$T/err"
    [ ! -e "$T/out.$ext" ] && pass || fail "out.$ext refused but written"
done
expect_exit "--format png out.tif" 0 "$RT" --format png "$scene" "$T/named.tif"
head -c 8 "$T/named.tif" | od -An -tx1 | grep -q '89 50 4e 47' && pass || fail "--format png did not write a PNG"
expect_exit "--spp-map out.gif refused" 2 "$RT" --noise 4 --spp-map "$T/map.gif" "$scene" "$T/x.ppm"
expect_exit "no extension: PPM" 0 "$RT" "$scene" "$T/plain"
cmp -s "$T/plain" "$T/course.ppm" && pass || fail "a name without an extension is not PPM"
expect_exit "pfm by extension" 0 "$RT" "$scene" "$T/course.pfm"
head -c 20 "$T/course.pfm" | head -3 | tr '\n' ' ' | grep -q '^PF 400 400 -1.0 ' && pass || fail "PFM header"
expect_exit "pfm rounds to ppm" 0 "$DIFF" --tolerance 0.5 "$T/course.ppm" "$T/course.pfm"
expect_exit "pfm is not quantised" 1 "$DIFF" "$T/course.ppm" "$T/course.pfm"
expect_exit "ascii ppm" 0 "$RT" --ascii "$scene" "$T/ascii.ppm"
head -c 3 "$T/ascii.ppm" | grep -q P3 && pass || fail "--ascii is not P3"
expect_exit "ascii = binary" 0 "$DIFF" "$T/course.ppm" "$T/ascii.ppm"
expect_exit "--format png to stdout" 0 sh -c "\"$RT\" --format png \"$scene\" - >\"$T/fmt.out\""
expect_exit "--format png = ppm" 0 "$DIFF" "$T/course.ppm" "$T/fmt.out"
expect_exit "--ascii with png" 2 "$RT" --ascii "$scene" "$T/x.png"
expect_exit "--format tiff" 2 "$RT" --format tiff "$scene" "$T/x.ppm"
expect_line "--format tiff message" 1 "raytrace: option '--format' takes ppm, png, pfm, jpeg, jpg or bmp, found 'tiff'" "$T/err"
expect_exit "--format bmp to stdout" 0 sh -c "\"$RT\" --format bmp \"$scene\" - >\"$T/fmt.bmp\""
cmp -s "$T/fmt.bmp" "$T/course.bmp" && pass || fail "--format bmp to standard output is not the .bmp file"

# --- raytrace-diff: statistics, tolerance, diff image, exit status ---
"$RT" --max-depth 1 "$scene" "$T/d1.ppm"
expect_exit "depth 1 differs" 1 "$DIFF" --tolerance 1 --diff "$T/diff.ppm" tests/ref/course.ppm "$T/d1.ppm"
expect_grep "max error and where" "max error: 17 at pixel (122, 252), red: reference (174, 2, 3), image (157, 0, 0)" "$T/out"
expect_grep "over tolerance" "over tolerance 1: 2638 of 160000 pixels" "$T/out"
expect_grep "PSNR" "PSNR: 48.29 dB" "$T/out"
expect_exit "diff image is an image" 0 "$DIFF" --tolerance 255 "$T/d1.ppm" "$T/diff.ppm"
expect_exit "max pixels" 0 "$DIFF" -q --tolerance 1 --max-pixels 2638 tests/ref/course.ppm "$T/d1.ppm"
[ ! -s "$T/out" ] && pass || fail "-q prints"
expect_exit "one pixel too many" 1 "$DIFF" -q -t 1 -m 2637 tests/ref/course.ppm "$T/d1.ppm"
"$RT" "$T/small.txt" "$T/small.ppm"
expect_exit "sizes differ" 2 "$DIFF" "$T/course.ppm" "$T/small.ppm"
expect_line "both sizes" 1 "raytrace-diff: error: the sizes differ: $T/course.ppm is 400 x 400, $T/small.ppm is 8 x 8" "$T/err"
expect_exit "unreadable" 2 "$DIFF" "$T/course.ppm" "$T/nothing.ppm"
expect_exit "not an image" 2 "$DIFF" "$T/course.ppm" "$scene"
expect_exit "diff usage" 2 "$DIFF" "$T/course.ppm"
# raytrace-diff's options read by the shared parser (cli/args.c): every
# spelling, and a clear refusal of what an option does not take.
expect_exit "diff --tolerance=N -mN" 0 "$DIFF" --tolerance=0 -m0 "$T/course.ppm" "$T/course.ppm"
expect_exit "diff -t inf" 2 "$DIFF" -t inf "$T/course.ppm" "$T/course.ppm"
expect_grep "diff -t inf message" "option '--tolerance' takes a number >= 0, found 'inf'" "$T/err"
expect_exit "diff -m 1.5" 2 "$DIFF" -m 1.5 "$T/course.ppm" "$T/course.ppm"
expect_grep "diff -m message" "option '--max-pixels' takes a whole number >= 0, found '1.5'" "$T/err"
expect_exit "diff too many" 2 "$DIFF" "$T/course.ppm" "$T/course.ppm" "$T/course.ppm"
expect_grep "diff too many message" "too many arguments: '$T/course.ppm' after REFERENCE and IMAGE" "$T/err"
expect_exit "diff bad tolerance" 2 "$DIFF" -t -1 "$T/course.ppm" "$T/course.ppm"
head -c 1000 "$T/course.png" >"$T/cut.png"
expect_exit "truncated png" 2 "$DIFF" "$T/course.ppm" "$T/cut.png"
expect_grep "truncated png message" "cut.png: error: chunk 'IDAT' at byte 33 is longer than the file" "$T/err"

# --- raytrace-diff --box: how close two pictures look ---
# A checkerboard of 0 and 254 against a flat 127: every pixel 127 apart,
# every 2 x 2 box equal.
awk 'BEGIN { print "P3\n4 4\n255"; for (y = 0; y < 4; y++) for (x = 0; x < 4; x++) { v = (x + y) % 2 ? 254 : 0; print v, v, v } }' >"$T/checker.ppm"
awk 'BEGIN { print "P3\n4 4\n255"; for (k = 0; k < 16; k++) print 127, 127, 127 }' >"$T/flat.ppm"
expect_exit "pixels apart" 1 "$DIFF" -t 1 "$T/flat.ppm" "$T/checker.ppm"
expect_exit "boxes alike" 0 "$DIFF" --box 2x2 "$T/flat.ppm" "$T/checker.ppm"
expect_grep "--box says so" "compared:  2 x 2 boxes, each the mean of the pixels it covers" "$T/out"
expect_grep "--box mean" "mean error: 0," "$T/out"
expect_exit "--box larger than the image" 2 "$DIFF" --box 5x5 "$T/flat.ppm" "$T/checker.ppm"
expect_exit "--box bad" 2 "$DIFF" --box 2 "$T/flat.ppm" "$T/checker.ppm"
# The worst 1%: every pixel 127 apart; then of 100 pixels, one pixel 30
# apart (within the 1% let pass), and two.
"$DIFF" "$T/flat.ppm" "$T/checker.ppm" >"$T/out"
expect_grep "worst 1%, all apart" "worst 1% of pixels: error over 127 " "$T/out"
for off in 1 2; do
    awk -v off=$off 'BEGIN { print "P3\n10 10\n255"; for (k = 0; k < 100; k++) print 100, 100 + (k < off ? 30 : 0), 100 }' >"$T/off$off.ppm"
done
awk 'BEGIN { print "P3\n10 10\n255"; for (k = 0; k < 100; k++) print 100, 100, 100 }' >"$T/grey.ppm"
"$DIFF" "$T/grey.ppm" "$T/off1.ppm" >"$T/out"
expect_grep "worst 1%, one pixel of 100" "worst 1% of pixels: error over 0 " "$T/out"
"$DIFF" "$T/grey.ppm" "$T/off2.ppm" >"$T/out"
expect_grep "worst 1%, two pixels of 100" "worst 1% of pixels: error over 17.375 " "$T/out"
expect_grep "--box bad message" "--box takes WxH, the boxes across and down (as 100x100), found '2'" "$T/err"

# --- --size, --no-shadows, --model, and options that change nothing ---
for args in "--model pbr $scene x.ppm" "--size 0x5 $scene x.ppm" "--size 5 $scene x.ppm" \
    "--size 5x $scene x.ppm" "--size x5 $scene x.ppm" "--size 40000x10 $scene x.ppm"; do
    # shellcheck disable=SC2086
    expect_exit "usage '$args'" 2 "$RT" $args
done
expect_grep "--size message" "option '--size' takes WxH, the image's width and height in pixels, each from 1 to 32768 (as 500x500), found '40000x10'" "$T/err"
expect_exit "--size" 0 "$RT" --size 40x30 "$scene" "$T/size.ppm"
[ "$(head -c 11 "$T/size.ppm")" = "$(printf 'P6\n40 30\n25')" ] && pass || fail "--size 40x30 gives $(head -c 11 "$T/size.ppm")"
"$RT" --size 400x400 "$scene" "$T/size400.ppm" && cmp -s "$T/size400.ppm" "$T/course.ppm" && pass ||
    fail "--size at the scene's own size changes bytes"
expect_exit "--no-shadows" 0 "$RT" -v --no-shadows "$scene" "$T/noshadow.ppm"
expect_grep "--no-shadows casts none" " 0 shadow," "$T/err"
cmp -s "$T/noshadow.ppm" "$T/course.ppm" && fail "--no-shadows changes nothing on the course scene" || pass
expect_exit "--model on a course scene" 0 "$RT" --model physical "$scene" "$T/model.ppm"
expect_grep "--model note" "raytrace: note: --model changes nothing here: it chooses how MPL scenes are lit; the course and keyword formats have one model" "$T/err"
cmp -s "$T/model.ppm" "$T/course.ppm" && pass || fail "--model changed a course render"
expect_exit "--ao without ambient" 0 "$RT" --ao 4 "$scene" "$T/ao.ppm"
expect_grep "--ao note" "raytrace: note: --ao changes nothing here" "$T/err"
[ "$(grep -c note "$T/err")" = 1 ] && pass || fail "the note is not said once" "$(cat "$T/err")"
expect_exit "-q silences notes" 0 "$RT" -q --ao 4 "$scene" "$T/ao.ppm"
[ ! -s "$T/err" ] && pass || fail "-q printed a note" "$(cat "$T/err")"
# The MPL model: 500 x 500 and 4 samples without a camera or c Samples;
# a matte plane lit head on, without occlusion or gathering, is 255 / pi
# encoded with gamma 2.2 (152); by the physical model, linear (255).
printf 'c Background 0 0 0\nm w MATTE 1 1 1 0 0 0 N\np Plane 0 0 2 0 0 -1 w\nl DirectionLight 0 0 1 1 1 1 1\n' >"$T/flat-mpl.txt"
expect_exit "the MPL ray tracer's defaults" 0 "$RT" -v --ao 0 --gi 0 "$T/flat-mpl.txt" "$T/flat-mpl.ppm"
expect_grep "the MPL ray tracer's size and samples" "raytrace: 500 x 500 pixels, 4 samples per pixel" "$T/err"
"$RT" --ao 0 --gi 0 --size 1x1 --ascii "$T/flat-mpl.txt" - | sed -n 4p >"$T/px" && expect_line "gamma-encoded" 1 "152 152 152" "$T/px"
"$RT" --model physical --size 1x1 --ascii "$T/flat-mpl.txt" - | sed -n 4p >"$T/px" && expect_line "physical: linear" 1 "255 255 255" "$T/px"
"$RT" --gi 0 --size 1x1 --ascii "$T/flat-mpl.txt" - | sed -n 4p >"$T/px" && expect_line "occlusion open to the sky changes nothing" 1 "152 152 152" "$T/px"
expect_exit "--gi-bounces by the MPL model" 0 "$RT" --gi-bounces 2 --size 2x2 "$T/flat-mpl.txt" "$T/b.ppm"
expect_grep "--gi-bounces note" "raytrace: note: --gi-bounces changes nothing here: the MPL model gathers the colours its rays meet" "$T/err"
# The tracer's own rule for the note on --ao: a physical MPL scene whose
# materials take no ambient light (metal: ka = 0) has nothing to darken,
# one with a matte material has (c Ambient lights it).
printf 'c Ambient 0.2 0.2 0.2\nm m METALLIC 1 1 1 0 0 0 N\np Sphere 0 0 3 1 m\nl PointLight 0 0 0 1 1 1 1\n' >"$T/metal-mpl.txt"
expect_exit "--ao on metal" 0 "$RT" --model physical --ao 4 --size 8x8 "$T/metal-mpl.txt" "$T/m.ppm"
expect_grep "--ao note on metal" "raytrace: note: --ao changes nothing here" "$T/err"
sed 's/METALLIC/MATTE/' "$T/metal-mpl.txt" >"$T/matte-mpl.txt"
expect_exit "--ao on matte" 0 "$RT" --model physical --ao 4 --size 8x8 "$T/matte-mpl.txt" "$T/m.ppm"
grep -q 'note' "$T/err" && fail "--ao on a matte MPL scene is said to change nothing" "$(cat "$T/err")" || pass
# The MPL ray tracer's files: textures beside the scene's folder (its repository's
# Scene/ and Textures/), BMP textures, and the layout of raytrace 0.1.
mkdir -p "$T/repo/Scene" "$T/repo/Textures"
cp tests/fuzz/corpus/picture/rgb24.bmp "$T/repo/Textures/t.jpg"
printf 'm t MATTE 1 1 1 0 0 0 t.jpg\np Square 0 0 2 0 0 -1 1 t\nl DirectionLight 0 0 1 1 1 1 1\n' >"$T/repo/Scene/s.txt"
expect_exit "a BMP texture in ../Textures" 0 "$RT" --check "$T/repo/Scene/s.txt"
# A texture there but unreadable (a link to itself) is reported as it is,
# not taken for missing and looked for elsewhere.
mkdir -p "$T/repo/Scene/Textures"
cp tests/fuzz/corpus/picture/rgb24.bmp "$T/repo/Scene/Textures/loop.jpg"
ln -s loop.jpg "$T/repo/Scene/loop.jpg"
sed 's/t\.jpg/loop.jpg/' "$T/repo/Scene/s.txt" >"$T/repo/Scene/loop.txt"
expect_exit "an unreadable texture" 1 "$RT" --check "$T/repo/Scene/loop.txt"
expect_grep "an unreadable texture, as it is" "cannot use the texture 'loop.jpg': cannot open: Too many levels of symbolic links" "$T/err"
printf 'm a PLASTIC 1 1 1 0 0.4 40 N 1.5\n' >"$T/old.txt"
expect_exit "raytrace 0.1's layout" 1 "$RT" --check "$T/old.txt"
expect_grep "raytrace 0.1's layout message" "old.txt:1:30: error: the material has an 11th field, '1.5'" "$T/err"

# --- --pass: its words, its notes, the picture unchanged without it ---
expect_exit "--pass bogus" 2 "$RT" --pass bogus scenes/course.txt "$T/x.ppm"
expect_grep "--pass bogus names the passes" "takes full, direct, indirect, ao, albedo, normal or depth" "$T/err"
"$RT" -q --pass full scenes/course.txt "$T/pf.ppm" && "$RT" -q scenes/course.txt "$T/p0.ppm" &&
    cmp -s "$T/pf.ppm" "$T/p0.ppm" && pass || fail "--pass full is not the picture"
expect_exit "--pass indirect without gathering" 0 "$RT" --pass indirect --size 40x40 scenes/room.txt "$T/pi.ppm"
expect_grep "--pass indirect without gathering" \
    "raytrace: note: --pass indirect is black here: no light is gathered (--gi N)" "$T/err"
[ "$(tail -c +16 "$T/pi.ppm" | tr -d '\0' | wc -c)" -eq 0 ] && pass || fail "--pass indirect without gathering is not black"
expect_exit "--pass ao without occlusion rays" 0 "$RT" --pass ao --size 40x40 scenes/room.txt "$T/pa.ppm"
expect_grep "--pass ao without occlusion rays" \
    "raytrace: note: --pass ao is white here: no occlusion rays are cast (--ao N)" "$T/err"
# A data pass takes no gamma: the MPL model's floor, facing up, is (n + 1) / 2
# = (128, 255, 128) in its normal pass, not gamma-encoded.
"$RT" -q --pass normal --size 60x60 scenes/mpl.txt "$T/pn.ppm" &&
    [ "$(tail -c 3 "$T/pn.ppm" | od -An -tu1 | tr -s ' ')" = " 128 255 128" ] && pass ||
    fail "the MPL model's normal pass: the floor's last pixel is not (128, 255, 128)" \
        "$(tail -c 3 "$T/pn.ppm" | od -An -tu1)"

# --- --texture-filter: what it changes, its note, the mip-maps' memory ---
expect_exit "--texture-filter cubic" 2 "$RT" --texture-filter cubic scenes/horizon.txt "$T/x.ppm"
expect_exit "--texture-filter on no texture" 0 "$RT" --texture-filter trilinear "$T/small.txt" "$T/tf.ppm"
expect_grep "--texture-filter on no texture" \
    "raytrace: note: --texture-filter changes nothing here: no object has a texture or stripes" "$T/err"
"$RT" -q "$T/small.txt" "$T/tf0.ppm" && cmp -s "$T/tf.ppm" "$T/tf0.ppm" && pass ||
    fail "--texture-filter changed a scene without textures"
# A course scene keeps its bytes unless asked; asked, only its minified
# texels change (the far floor), its magnified ones not at all.
"$RT" -q scenes/textures.txt "$T/tex0.ppm" && "$RT" -q --texture-filter bilinear scenes/textures.txt "$T/texb.ppm"
"$RT" -q --texture-filter trilinear scenes/textures.txt "$T/text.ppm" || fail "--texture-filter trilinear"
"$DIFF" -t 1 "$T/texb.ppm" "$T/text.ppm" >"$T/out" 2>&1
pct=$(sed -n 's/^over tolerance 1: [0-9]* of [0-9]* pixels (\([0-9.]*\)%).*/\1/p' "$T/out")
echo "$pct" | awk '{ exit !($1 > 0 && $1 < 6) }' && pass ||
    fail "textures.txt trilinear against bilinear: $pct% of pixels over 1 level (expected some, the far floor, under 6%)" "$(cat "$T/out")"
# The MPL format filters by default; its line's word and the option win.
grep -v '^#' scenes/horizon.txt | sed 's/carrelage.jpg$/carrelage.jpg bilinear/; s/^\(m candy .*\) N$/\1 N bilinear/' >"$T/hz-b.txt"
mkdir -p "$T/textures" && cp scenes/textures/carrelage.jpg "$T/textures/"
"$RT" -q "$T/hz-b.txt" "$T/hz-b.ppm" && "$RT" -q --texture-filter bilinear scenes/horizon.txt "$T/hz-o.ppm" &&
    cmp -s "$T/hz-b.ppm" "$T/hz-o.ppm" && pass || fail "an MPL line's bilinear is not --texture-filter bilinear"
"$RT" -q "$T/hz-b.txt" "$T/hz-b2.ppm" && "$RT" -q scenes/horizon.txt "$T/hz-t.ppm" &&
    ! cmp -s "$T/hz-b2.ppm" "$T/hz-t.ppm" && pass || fail "horizon.txt renders the same filtered and not"
"$RT" -q --save "$T/hz-saved.txt" "$T/hz-b.txt" && grep -q 'carrelage.jpg bilinear$' "$T/hz-saved.txt" &&
    pass || fail "--save lost the material's filter" "$(cat "$T/hz-saved.txt")"
expect_exit "mip-maps over the memory limit" 1 "$RT" --memory-limit 1200K scenes/horizon.txt "$T/mm.ppm"
expect_grep "mip-maps over the memory limit" "the mip-maps of the scene's textures need 256.1 KiB" "$T/err"
[ ! -e "$T/mm.ppm" ] && pass || fail "a refused render left an output"
expect_exit "no mip-maps, no memory for them" 0 "$RT" --memory-limit 1200K --texture-filter bilinear \
    scenes/horizon.txt "$T/mm.ppm"

# --- --check and -v ---
expect_exit "--check" 0 "$RT" --check scenes/glass.txt
expect_line "--check report" 1 "scenes/glass.txt: OK: 480 x 320 pixels, 7 objects, 2 lights" "$T/out"
printf '0 0 0\n-1 1 1\n1 1 1\n-1 -1 1\n8\n0 0 0\n0 5 0 255 255 255\nsphere: 0 0 5 1 2 3\n' >"$T/short.txt"
expect_exit "--check bad scene" 1 "$RT" --check "$T/short.txt"
expect_grep "--check bad scene position" "short.txt:8:20: error:" "$T/err"
expect_exit "--check takes one file" 2 "$RT" --check "$scene" "$T/x.ppm"
expect_exit "-v" 0 "$RT" -v "$scene" "$T/v.ppm"
expect_grep "-v rays" "raytrace: rays: 160000 primary, 29186 shadow, 47899 reflection, 0 refraction, 237085 in all" "$T/err"
expect_grep "-v cut-off" "raytrace: cut-off 0.1 levels: 23 rays left out, 0 pixels refined" "$T/err"
expect_exit "-v --cutoff 0" 0 "$RT" -v --cutoff 0 "$scene" "$T/v0.ppm"
expect_grep "-v rays, every one" "raytrace: rays: 160000 primary, 29209 shadow, 47899 reflection, 0 refraction, 237108 in all" "$T/err"
cmp -s "$T/v.ppm" "$T/v0.ppm" && pass || fail "-v --cutoff 0 renders other bytes"
expect_grep "-v speed" "Mrays/s" "$T/err"

# --- the bounding volume hierarchy changes no byte ---
# 4,000 objects in full, 400 in the quick suite.
objects=2000
full || objects=200
awk -v n=$objects 'BEGIN {
    print "0 0 -30"; print "-8 6 0"; print "8 6 0"; print "-8 -6 0"; print "96";
    print "10 10 30"; print "20 30 -20 255 255 255"; print "light: -20 10 -10 100 100 160";
    print "plane: 0 -12 0 0 1 0 200 200 200 0.2";
    for (i = 0; i < n; i++) {
        x = (i * 7919) % 61 - 30; y = (i * 104729) % 41 - 20; z = 20 + (i * 31) % 100;
        if (i % 3) printf "sphere: %d %d %d 0.9 %d 120 80 0.3\n", x, y, z, i % 256;
        else printf "sphere: %d %d %d 0.9 200 200 255 0.1 0.6 1.5\n", x, y, z;
        printf "triangle: %d %d %d %d %d %d %d %d %d 80 200 80 0.2\n", x, y, z + 1, x + 1, y, z + 1, x, y + 1, z + 1;
    }
}' >"$T/many.txt"
expect_exit "many objects, hierarchy" 0 "$RT" -v "$T/many.txt" "$T/many-bvh.ppm"
# On an x86-64 processor with AVX2 and FMA the queries run their AVX2 build.
if [ "$(uname -m)" = x86_64 ] && grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo; then
    expect_grep "AVX2 box tests where the processor has them" "box tests in AVX2 and FMA" "$T/err"
fi
expect_exit "many objects, every object" 0 "$RT" --no-accel "$T/many.txt" "$T/many-all.ppm"
cmp -s "$T/many-bvh.ppm" "$T/many-all.ppm" && pass || fail "--no-accel changes the picture of $((2 * objects)) objects"
full && for s in mesh keyword; do
    hash=$(grep " scenes/$s.txt\$" "$T/golden" | cut -d' ' -f1)
    [ "$("$RT" --no-accel "scenes/$s.txt" - | sha256sum | cut -d' ' -f1)" = "$hash" ] && pass ||
        fail "--no-accel changes scenes/$s.txt"
done
# The single-precision build (make REAL=float, not exact against double:
# docs/trade.md; make check builds it) keeps its own promise: the hierarchy finds what a loop
# over every object finds, to the byte.
if [ -n "$RT_FLOAT" ]; then
    "$RT_FLOAT" -V | grep -q "single precision" && pass || fail "the float build says what it is"
    for s in "$T/many.txt" scenes/mirrors.txt scenes/keyword.txt; do
        "$RT_FLOAT" -q "$s" "$T/f-bvh.ppm" && "$RT_FLOAT" -q --no-accel "$s" "$T/f-all.ppm" &&
            cmp -s "$T/f-bvh.ppm" "$T/f-all.ppm" && pass || fail "float build: --no-accel changes $s"
    done
fi

# --- the keyword format of the OCaml course project: detection, errors, --save ---
expect_exit "keyword --check" 0 "$RT" --check scenes/keyword.txt
expect_line "keyword --check report" 1 "scenes/keyword.txt: OK: 480 x 320 pixels, 1605 objects, 2 lights" "$T/out"
printf 'camera 0 0 0 0 0 5 1 40 30\nmaterial m 255 0 0 1 1 1 1\nsphere 0 0 5 1 n\n' >"$T/kw-bad.txt"
expect_exit "keyword error" 1 "$RT" "$T/kw-bad.txt" "$T/kw-bad.ppm"
expect_grep "keyword error position" "kw-bad.txt:3:16: error: unknown material 'n': a material line must define it before the sphere" "$T/err"
[ ! -e "$T/kw-bad.ppm" ] && pass || fail "a bad keyword scene left an output"
expect_exit "--scene-format course on a keyword scene" 1 "$RT" --check --scene-format course scenes/ocaml-test.txt
expect_grep "--scene-format course message" "ocaml-test.txt:5:1: error: expected a number for the camera position's x, found 'camera'" "$T/err"
expect_exit "--scene-format keyword on a course scene" 1 "$RT" --check --scene-format keyword "$scene"
expect_grep "--scene-format keyword message" "course.txt:6:1: error: expected an element such as 'sphere', found the number '100'" "$T/err"
expect_exit "--scene-format bad" 2 "$RT" --check --scene-format pov "$scene"
expect_grep "--scene-format bad message" "option '--scene-format' takes course, keyword, mpl or auto, found 'pov'" "$T/err"
expect_exit "keyword scene on standard input" 0 sh -c "\"$RT\" - \"$T/stdin-kw.ppm\" <scenes/ocaml-test.txt"
"$RT" scenes/ocaml-test.txt "$T/ocaml.ppm" && cmp -s "$T/ocaml.ppm" "$T/stdin-kw.ppm" && pass ||
    fail "a keyword scene reads the same from standard input"
# --save: the saved scene renders the same bytes, and saves to the same text
# (the tori and disks of rings.txt at the size of its quick golden line).
mkdir "$T/elsewhere"
for s in ocaml-test keyword materials rings; do
    size=
    [ "$s" = rings ] && size="--size 240x160"
    expect_exit "--save $s" 0 "$RT" --save "$T/elsewhere/$s.txt" "scenes/$s.txt"
    expect_exit "--save $s again" 0 "$RT" --save "$T/elsewhere/$s-2.txt" "$T/elsewhere/$s.txt"
    cmp -s "$T/elsewhere/$s.txt" "$T/elsewhere/$s-2.txt" && pass || fail "--save $s is not stable" "$(diff "$T/elsewhere/$s.txt" "$T/elsewhere/$s-2.txt")"
    hash=$(grep " scenes/$s.txt${size:+ $size}\$" "$T/golden" | cut -d' ' -f1)
    # shellcheck disable=SC2086 # $size is two words or none
    [ "$("$RT" $size "$T/elsewhere/$s.txt" - | sha256sum | cut -d' ' -f1)" = "$hash" ] && pass ||
        fail "the saved $s renders differently" "$(cat "$T/elsewhere/$s.txt")"
done
# From another folder, a mesh's path is relative to the saved file, so that
# the saved scene and its files may move together.
mkdir -p "$T/project/saved"
cp -R scenes "$T/project/scenes"
expect_exit "--save into another folder" 0 "$RT" --save "$T/project/saved/keyword.txt" "$T/project/scenes/keyword.txt"
expect_grep "--save writes the mesh's path from the saved file's folder" "mesh ../scenes/models/torus-smooth.obj gold" "$T/project/saved/keyword.txt"
mv "$T/project" "$T/moved"
hash=$(grep " scenes/keyword.txt\$" "$T/golden" | cut -d' ' -f1)
[ "$("$RT" "$T/moved/saved/keyword.txt" - 2>"$T/err" | sha256sum | cut -d' ' -f1)" = "$hash" ] && pass ||
    fail "a saved scene moved with its files renders differently" "$(cat "$T/err")"
rm -rf "$T/moved"
expect_exit "--save beside the scene" 0 "$RT" --save scenes/.saved-by-cli.txt scenes/keyword.txt
expect_grep "--save keeps a relative mesh path beside the scene" "mesh models/torus-smooth.obj gold" scenes/.saved-by-cli.txt
rm -f scenes/.saved-by-cli.txt
expect_exit "--save to standard output" 0 "$RT" --save - scenes/ocaml-test.txt
expect_line "--save output" 2 "camera 0 0 0 0 0 5 2.0943951 700 500" "$T/out"
echo old >"$T/kept.txt"
expect_exit "--save a course scene" 1 "$RT" --save "$T/kept.txt" "$scene"
expect_grep "--save a course scene message" "course.txt: error: --save writes the keyword and MPL formats, which cannot express a course-format scene" "$T/err"
expect_grep "--save a course scene keeps the output" "old" "$T/kept.txt"
expect_clean "--save a course scene leaves no temporary file" "$T"
expect_exit "--save a bad scene" 1 "$RT" --save "$T/kept.txt" "$T/kw-bad.txt"
expect_grep "--save a bad scene keeps the output" "old" "$T/kept.txt"
expect_exit "--save into a missing directory" 1 "$RT" --save "$T/nowhere/x.txt" scenes/ocaml-test.txt
expect_exit "--save onto the scene itself" 1 "$RT" --save "$T/elsewhere/ocaml-test.txt" "$T/elsewhere/ocaml-test.txt"
expect_exit "--save without SCENE" 2 "$RT" --save "$T/x.txt"
expect_exit "--save with an OUTPUT too" 2 "$RT" --save "$T/x.txt" scenes/ocaml-test.txt "$T/x.ppm"
expect_exit "--save with --check" 2 "$RT" --check --save "$T/x.txt" scenes/ocaml-test.txt

# --- OBJ files written by other tools: Debian's assimp-testmodels ---
models=/usr/share/assimp/models
if [ -d "$models/OBJ" ]; then
    # obj_check FILE STATUS [MESSAGE]: a scene with FILE as its mesh checks
    # with STATUS, and its error (if any) contains MESSAGE.
    obj_check() {
        printf '0 0 -5\n-1 1 -4\n1 1 -4\n-1 -1 -4\n32\n0 0 0\n5 5 -10 255 255 255\nmesh: %s 200 150 100 0\n' \
            "$1" >"$T/obj.txt"
        expect_exit "assimp $(basename "$1")" "$2" "$RT" --check "$T/obj.txt"
        [ -z "$3" ] || expect_grep "assimp $(basename "$1") message" "$3" "$T/err"
    }
    obj_check "$models/OBJ/WusonOBJ.obj" 0
    expect_line "WusonOBJ triangles" 1 "$T/obj.txt: OK: 32 x 32 pixels, 3732 objects, 1 light" "$T/out"
    for f in box box_longline box_mat_with_spaces box_without_lineending concave_polygon \
        cube_mtllib_after_g cube_usemtl cube_with_vertexcolors cube_with_vertexcolors_uni \
        empty_mat multiple_spaces regr01 regr_3429812 space_in_material_name spider testmixed; do
        obj_check "$models/OBJ/$f.obj" 0
    done
    obj_check "$models/OBJ/box_UTF16BE.obj" 1 "box_UTF16BE.obj:1:3: NUL byte"
    obj_check "$models/OBJ/number_formats.obj" 1 "number_formats.obj:11:14: expected a number for a vertex (x y z), found '3.1+e2'"
    obj_check "$models/OBJ/point_cloud.obj" 1 "has no faces with an area"
    obj_check "$models/OBJ/testline.obj" 1 "has no faces with an area"
    obj_check "$models/invalid/empty.obj" 1 "has no faces with an area"
    obj_check "$models/invalid/malformed.obj" 1 "malformed.obj:23:5: vertex 12 does not exist (8 vertices so far)"
    obj_check "$models/invalid/malformed2.obj" 1 "malformed2.obj:23:2: a face needs at least 3 corners, found 0"
    printf '0 1 -3\n-1 2 -2\n1 2 -2\n-1 0 -2\n48\n20 20 30\n5 5 -10 255 255 255\nmesh: %s 200 150 100 0.2\n' \
        "$models/OBJ/spider.obj" >"$T/spider.txt"
    expect_exit "render an assimp model" 0 "$RT" "$T/spider.txt" "$T/spider.ppm"
elif [ "${RAYTRACE_TEST_TOOLS:-}" = required ]; then
    fail "assimp-testmodels is missing: the OBJ files of other tools are not tested"
fi

# --- max depth changes the picture, 0 included ---
expect_exit "depth 0" 0 "$RT" --max-depth 0 "$scene" "$T/d0.ppm"
cmp -s "$T/d0.ppm" "$T/course.ppm" && fail "--max-depth 0 renders the same as 10" || pass

# --- bad scenes: positioned error, caret, exit 1, output untouched ---
printf 'keep me\n' >"$T/keep.ppm"
printf '0 0 0\n-1 1 1\n1 1 1\n-1 -1 1\n8\n0 0 0\n0 5 0 255 255 255\nsphere: 0 0 5 1 200 100 50 1.5\n' >"$T/bad.txt"
expect_exit "bad scene" 1 "$RT" "$T/bad.txt" "$T/keep.ppm"
expect_line "bad scene message" 1 "raytrace: $T/bad.txt:8:28: error: the sphere's reflection must be in [0, 1], found '1.5'" "$T/err"
expect_line "bad scene excerpt" 2 "    8 | sphere: 0 0 5 1 200 100 50 1.5" "$T/err"
expect_line "bad scene caret" 3 "      |                            ^" "$T/err"
expect_grep "bad scene keeps output" 'keep me' "$T/keep.ppm"
expect_clean "bad scene leaves no temporary file" "$T"
printf '0 0 0\n\t-1\t1 x\n' >"$T/tab.txt"
expect_exit "tab caret" 1 "$RT" "$T/tab.txt" "$T/keep.ppm"
expect_line "tab caret aligned" 3 "$(printf '      | \t  \t  ^')" "$T/err"
expect_exit "missing scene" 1 "$RT" "$T/none.txt" "$T/keep.ppm"
expect_line "missing scene message" 1 "raytrace: $T/none.txt: error: cannot open: No such file or directory" "$T/err"
expect_exit "scene is a directory" 1 "$RT" "$T" "$T/keep.ppm"
expect_grep "scene is a directory" 'it is a directory, not a file' "$T/err"
expect_grep "failed runs keep output" 'keep me' "$T/keep.ppm"

# --- the MPL ray tracer's lenient lines: read with a warning each, --strict refuses ---
printf 'm a MATTE 1 1 1 0 0 0 N\nc Camera 0 0 -5 0 0 0 60 16 12\np Sphere 0 0 0 1.5abc a shiny\n' >"$T/lenient.txt"
expect_exit "the MPL ray tracer's lenient lines" 0 "$RT" "$T/lenient.txt" "$T/lenient.ppm"
expect_grep "a number up to its letter: warning" "raytrace: $T/lenient.txt:3:19: warning: read '1.5abc' as 1.5, up to its first letter (as the MPL ray tracer did; --strict refuses it)" "$T/err"
expect_grep "words after the material: warning" "$T/lenient.txt:3:25: warning: ignored 1 word after the material's name" "$T/err"
expect_exit "the MPL ray tracer's lenient lines, quietly" 0 "$RT" -q "$T/lenient.txt" "$T/lenient.ppm"
[ ! -s "$T/err" ] && pass || fail "-q printed warnings" "$(cat "$T/err")"
printf 'old\n' >"$T/strict.ppm"
expect_exit "--strict" 1 "$RT" --strict "$T/lenient.txt" "$T/strict.ppm"
expect_grep "--strict: message" "$T/lenient.txt:3:16: error: expected a number for the sphere's radius, found '1.5abc'" "$T/err"
expect_grep "--strict keeps the output" "old" "$T/strict.ppm"

# --- bad outputs: clear error, nothing damaged or left behind ---
expect_exit "missing directory" 1 "$RT" "$T/small.txt" "$T/no/such/dir/out.ppm"
expect_grep "missing directory" "No such file or directory" "$T/err"
expect_exit "output is a directory" 1 "$RT" "$T/small.txt" "$T"
expect_exit "output is the scene" 1 "$RT" "$T/small.txt" "$T/small.txt"
expect_grep "output is the scene" "refusing to overwrite" "$T/err"
head -1 "$T/small.txt" | grep -q '^0 0 0$' && pass || fail "scene was overwritten"
# Nor any file the scene reads, by its name or through a link.
mkdir -p "$T/own/models"
cp scenes/textures/checker.ppm "$T/own/tex.ppm"
cp scenes/models/torus-flat.obj "$T/own/models/t.obj"
printf '0 0 -5\n-1 1 0\n1 1 0\n-1 -1 0\n8\n0 0 0\n0 5 -5 255 255 255\nplane: 0 -1 0 0 1 0 200 200 200 0\ntexture: tex.ppm\nmesh: models/t.obj 200 100 50 0\n' >"$T/own/s.txt"
ln -s tex.ppm "$T/own/link.ppm"
for out in tex.ppm link.ppm ../own/tex.ppm; do
    expect_exit "output is the scene's texture ($out)" 1 "$RT" -q "$T/own/s.txt" "$T/own/$out"
    expect_grep "output is the scene's texture ($out): message" "the output is the scene's texture" "$T/err"
done
cmp -s "$T/own/tex.ppm" scenes/textures/checker.ppm && pass || fail "the scene's texture was overwritten"
expect_exit "output is the scene's mesh" 1 "$RT" -q "$T/own/s.txt" "$T/own/models/t.obj"
expect_grep "output is the scene's mesh: message" "the output is the scene's mesh" "$T/err"
cmp -s "$T/own/models/t.obj" scenes/models/torus-flat.obj && pass || fail "the scene's mesh was overwritten"
expect_exit "--spp-map is the scene's texture" 1 "$RT" -q --noise 8 --spp-map "$T/own/tex.ppm" "$T/own/s.txt" "$T/own/out.ppm"
cmp -s "$T/own/tex.ppm" scenes/textures/checker.ppm && pass || fail "--spp-map overwrote the scene's texture"
expect_exit "--save over the keyword scene's mesh" 1 "$RT" --save scenes/models/torus-smooth.obj scenes/keyword.txt
git diff --quiet -- scenes/models/torus-smooth.obj 2>/dev/null && pass || fail "--save overwrote the scene's mesh"
if [ -w /dev/full ]; then
    expect_exit "full disk" 1 "$RT" "$T/small.txt" /dev/full
    expect_grep "full disk" "No space left on device" "$T/err"
    [ -c /dev/full ] && pass || fail "/dev/full was replaced"
fi
mkdir "$T/ro" && chmod 555 "$T/ro"
if ! (: >"$T/ro/probe") 2>/dev/null; then # not when running as root
    expect_exit "read-only directory" 1 "$RT" "$T/small.txt" "$T/ro/out.ppm"
    expect_grep "read-only directory" "Permission denied" "$T/err"
fi
rm -f "$T/ro/probe"
chmod 755 "$T/ro"
expect_exit "/dev/null output" 0 "$RT" "$T/small.txt" /dev/null
[ -c /dev/null ] && pass || fail "/dev/null was replaced"

# --- a symbolic link is written through, not replaced ---
ln -s keep.ppm "$T/link.ppm"
expect_exit "through a link" 0 "$RT" "$T/small.txt" "$T/link.ppm"
[ -L "$T/link.ppm" ] && head -c 2 "$T/keep.ppm" | grep -q P6 && pass || fail "link replaced"

# --- the irradiance cache: the same bytes on any threads (tiles:
# tests/tiles.sh), its
# -v lines, its map, its notes, its memory limit ---
sed 's/^200 .*/48    # horizontal resolution/' scenes/room.txt >"$T/room.txt"
"$RT" -q -j1 --gi 32 --gi-cache --gi-bounces 2 "$T/room.txt" "$T/gc1.ppm" &&
    "$RT" -q -j2 --gi 32 --gi-cache --gi-bounces 2 "$T/room.txt" "$T/gc2.ppm" &&
    cmp -s "$T/gc1.ppm" "$T/gc2.ppm" && pass || fail "--gi-cache: -j1 and -j2 differ"
"$RT" -q --gi 32 "$T/room.txt" "$T/gc0.ppm" && ! cmp -s "$T/gc0.ppm" "$T/gc1.ppm" && pass ||
    fail "--gi-cache changes no byte"
"$RT" -v --gi 32 --gi-cache --gi-cache-map "$T/gcmap.png" "$T/room.txt" "$T/gcv.ppm" 2>"$T/err"
expect_grep "--gi-cache -v records" "irradiance cache: error 0.3, " "$T/err"
expect_grep "--gi-cache -v lookups" "lookups served" "$T/err"
# Its rays counted with the render's, its time with the render's too.
expect_grep "--gi-cache -v speed over both" "Mrays/s over both" "$T/err"
[ -s "$T/gcmap.png" ] && pass || fail "--gi-cache-map wrote no map"
expect_exit "--gi-cache-map with --tile" 1 "$RT" -q --gi 32 --gi-cache --gi-cache-map "$T/m.png" --tile 1/2 "$T/room.txt" "$T/t.ppm"
"$RT" --gi 0 --gi-cache "$T/room.txt" "$T/n.ppm" 2>"$T/err"
expect_grep "--gi-cache with --gi 0" "note: --gi-cache changes nothing here: no global illumination rays" "$T/err"
"$RT" -q --gi 2048 --gi-cache "$T/room.txt" "$T/gd1.ppm" &&
    "$RT" -v --gi-cache "$T/room.txt" "$T/gd0.ppm" 2>"$T/err" && cmp -s "$T/gd0.ppm" "$T/gd1.ppm" &&
    grep -q "global illumination: 2048 rays a point" "$T/err" && pass ||
    fail "--gi-cache alone gathers 2048 rays a record"
"$RT" --gi 8 --gi-cache --model mpl scenes/indirect.txt --size 8x8 "$T/n.ppm" 2>"$T/err"
expect_grep "--gi-cache under the MPL model" "note: --gi-cache changes nothing here: the MPL model" "$T/err"
"$RT" --gi-cache-error 0.1 "$T/room.txt" "$T/n.ppm" 2>"$T/err"
expect_grep "--gi-cache-error alone" "note: --gi-cache-error and --gi-cache-map change nothing" "$T/err"
expect_exit "--gi-cache-error 0" 2 "$RT" --gi 8 --gi-cache --gi-cache-error 0 "$T/room.txt" "$T/n.ppm"
printf 'old\n' >"$T/keep.ppm"
"$RT" -q --gi 64 --gi-cache --gi-cache-error 0.01 --memory-limit 40K "$T/room.txt" "$T/keep.ppm" 2>"$T/err"
expect_grep "--gi-cache over the memory limit" "irradiance cache would pass the memory limit" "$T/err"
expect_grep "--gi-cache over the limit keeps the output" "old" "$T/keep.ppm"
{ sed -n '1,20p' scenes/indirect.txt | sed 's/ 400 400$/ 24 24/'; echo "c GI 16"; echo "c GICache 0.3"; } >"$T/gc.mpl"
"$RT" -q "$T/gc.mpl" "$T/gcs.ppm" && "$RT" -q --gi 16 --gi-cache --gi-cache-error 0.3 --scene-format mpl "$T/gc.mpl" "$T/gco.ppm" &&
    cmp -s "$T/gcs.ppm" "$T/gco.ppm" && pass || fail "c GICache 0.3 differs from --gi-cache --gi-cache-error 0.3"

# --- an interrupted render leaves the old output and no temporary file ---
awk 'BEGIN {
    print "0 0 0"; print "-1 1 1"; print "1 1 1"; print "-1 -1 1"; print "3000";
    print "0 0 0"; print "0 50 0 255 255 255";
    for (i = 0; i < 3000; i++) printf "sphere: %d %d 40 0.3 200 100 50 0.5\n", i % 60 - 30, i / 60 - 25
}' >"$T/slow.txt"
printf 'old\n' >"$T/slow.ppm"

# An interrupt is caught from raytrace's start, whatever it is doing;
# one its parent ignores stays ignored (README, "Exit status"). Each test
# waits for -v's first line (the scene is read, the render begins) as its
# sign, never a fixed time.
#
# interrupt SIGNAL STATUS: starts the slow render (16 samples a pixel, so
# that it lasts long after its first line, however loaded the machine),
# sends SIGNAL once the scene is read, and checks the exit status and that
# nothing changed. SIGINT's default is restored first: a background job of
# sh starts with SIGINT ignored.
interrupt() {
    : >"$T/err"
    printf 'old\n' >"$T/slow.ppm"
    $DEFAULT_INT "$RT" -v -s 16 "$T/slow.txt" "$T/slow.ppm" 2>"$T/err" &
    pid=$!
    awaits $pid "$T/err" "read the scene" || fail "SIG$1: the render ended before its first line" "$(describe "$T/err")"
    kill -"$1" $pid
    wait $pid
    code=$?
    [ "$code" = "$2" ] && pass || fail "SIG$1: exit $code, expected $2" "$(describe "$T/err")"
    expect_grep "SIG$1 message" "raytrace: interrupted" "$T/err"
    expect_grep "SIG$1 keeps output" "old" "$T/slow.ppm"
    expect_clean "SIG$1 leaves no temporary file" "$T"
}
interrupt INT 130
interrupt TERM 143

# An interrupt in the scene's reading, before any line: the same. The
# scene comes through a pipe that stays open, so the reading waits.
: >"$T/err"
mkfifo "$T/fifo"
$DEFAULT_INT "$RT" "$T/fifo" "$T/slow.ppm" 2>"$T/err" &
pid=$!
exec 9>"$T/fifo" # opens once raytrace has opened its end: it is reading
kill -INT $pid
exec 9>&-
wait $pid
code=$?
[ "$code" = 130 ] && pass || fail "SIGINT while reading: exit $code, expected 130" "$(describe "$T/err")"
expect_grep "SIGINT while reading keeps output" "old" "$T/slow.ppm"

# A SIGINT ignored by the parent (trap '' INT, as a background job has it)
# stays ignored: the render goes on and writes its picture.
"$RT" -q "$T/small.txt" "$T/small-ref.ppm"
: >"$T/err"
(trap '' INT && exec "$RT" -v --size 1200x1200 -s 4 "$T/small.txt" "$T/ignored.ppm" 2>"$T/err") &
pid=$!
awaits $pid "$T/err" "read the scene" || fail "ignored SIGINT: the render ended before its first line"
kill -INT $pid 2>/dev/null
wait $pid
code=$?
[ "$code" = 0 ] && pass || fail "ignored SIGINT: exit $code, expected 0 (the render goes on)" "$(describe "$T/err")"
"$RT" -q --size 1200x1200 -s 4 "$T/small.txt" "$T/small-big.ppm"
cmp -s "$T/ignored.ppm" "$T/small-big.ppm" && pass || fail "ignored SIGINT: the picture is not the render's"

finish
