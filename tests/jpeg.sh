#!/bin/sh
# jpeg.sh: our JPEG reader against libjpeg-turbo's djpeg (`make test`).
#
#  1. A corpus made here by cjpeg (Debian's libjpeg-turbo-progs) from our
#     own renders and from noise, at odd and even sizes and many settings
#     (quality, every chroma subsampling, progressive, greyscale, restart
#     markers, optimised tables, smoothing): our pixels must be djpeg's
#     (`djpeg -rgb`, default settings) to within 1 level on 99.9% of pixels
#     or more (so far they are the same to the byte); and every size from
#     1 x 1 to 17 x 17 under six subsamplings, to the byte.
#     Damaged files (bytes changed, cut out or added, no end marker, cut
#     short), sequential and progressive, with restart markers: our pixels
#     are djpeg's C decoder's, and we warn when it does.
#  2. Exif orientations 2 to 8: our picture is djpeg's turned by netpbm's
#     pamflip as the tag says.
#  3. What we do not read is refused with an error that names it:
#     arithmetic coding (cjpeg -arithmetic), lossless and hierarchical
#     frames, 12-bit samples, four components.
#  4. A texture whose decoding would pass --memory-limit is refused before
#     it is decoded, leaving the output as it was.
#  5. Our JPEG writer: djpeg reads everything raytrace writes (four scenes
#     at six quality and subsampling settings, odd sizes), our reader gives
#     djpeg's pixels for them, quality 90 keeps 38 dB of PSNR on the course
#     scene (and quality 100 in 4:4:4 keeps 50 dB on every scene), PSNR
#     grows with quality, and the bytes do not depend on the thread count.
#
# Without cjpeg and djpeg (or pamflip) the parts that need them are skipped,
# saying so, unless RAYTRACE_TEST_TOOLS=required (CI), where that fails.
#
# The quick suite (make test, RAYTRACE_TEST_LEVEL=quick) takes a sample of
# each part: two sources at five settings, the sizes up to 3 x 3, one
# orientation, two scenes written at two settings, two odd sizes; make
# check takes them all.
#
# Usage: sh tests/jpeg.sh RAYTRACE RAYTRACE-DIFF   (from the repository root)

RT=$1
DIFF=$2
SUITE=jpeg
. "$(dirname "$0")/check.sh"

# have TOOL: says whether TOOL is here; when it is not, says what is
# skipped (or fails when the tools are required).
have() {
    command -v "$1" >/dev/null 2>&1 && return 0
    if [ "${RAYTRACE_TEST_TOOLS:-}" = required ]; then
        fail "$1 is missing (install libjpeg-turbo-progs and netpbm)"
    else
        echo "jpeg: skipped what needs $1 (not installed)"
    fi
    return 1
}

# noise W H FILE: a W x H PPM of random bytes.
noise() {
    printf 'P6\n%d %d\n255\n' "$1" "$2" >"$3"
    head -c $(($1 * $2 * 3)) /dev/urandom >>"$3"
}

# --- 1. the corpus against djpeg ---
if have cjpeg && have djpeg; then
    "$RT" -q scenes/textures.txt "$T/render.ppm"
    full && "$RT" -q scenes/materials.txt "$T/materials.ppm"
    noise 1 1 "$T/n1.ppm"
    noise 7 5 "$T/n7.ppm"
    noise 17 9 "$T/n17.ppm"
    noise 33 65 "$T/n33.ppm"
    noise 257 131 "$T/n257.ppm"
    images=0
    sources="render materials n1 n7 n17 n33 n257"
    settings='-quality 90;-quality 10;-quality 50 -sample 1x1;-quality 100;-sample 2x1;-sample 1x2;-sample 2x2;-sample 4x1;-sample 1x4;-sample 4x2;-sample 2x2,1x1,2x1;-progressive;-progressive -sample 1x1;-grayscale;-grayscale -progressive;-restart 1;-restart 3b -sample 2x1;-optimize;-smooth 40;-dct float -quality 95;-baseline -quality 5'
    if ! full; then
        sources="render n33"
        settings='-quality 90;-sample 2x1;-progressive;-grayscale;-restart 1'
    fi
    for src in $sources; do
        for opts in $(printf '%s' "$settings" | tr ' ;' '@ '); do
            opts=$(printf '%s' "$opts" | tr '@' ' ')
            # shellcheck disable=SC2086
            if ! cjpeg $opts -outfile "$T/c.jpg" "$T/$src.ppm" 2>"$T/err"; then
                fail "cjpeg $opts $src" "$(cat "$T/err")"
                continue
            fi
            djpeg -rgb -outfile "$T/d.ppm" "$T/c.jpg"
            # At most one pixel in a thousand more than 1 level away.
            pixels=$(head -n 2 "$T/d.ppm" | tail -n 1 | awk '{ print $1 * $2 }')
            allowed=$((pixels / 1000))
            if "$DIFF" --tolerance 1 --max-pixels "$allowed" "$T/d.ppm" "$T/c.jpg" \
                >"$T/out" 2>&1; then
                pass
            else
                fail "$src with cjpeg $opts: our pixels are not djpeg's" "$(cat "$T/out")"
            fi
            images=$((images + 1))
        done
    done
    echo "jpeg: $images files made by cjpeg compared with djpeg"
    # Every size from 1 x 1 to 17 x 17 under each chroma subsampling, of
    # noise: where a subsampled component is 1 or 2 samples wide, libjpeg
    # repeats its samples instead of filtering them (the quick suite: up to
    # 3 x 3).
    last=17
    full || last=3
    sizes=0 bad=""
    w=1
    while [ $w -le $last ]; do
        h=1
        while [ $h -le $last ]; do
            noise $w $h "$T/s.ppm"
            for sample in 2x1 1x2 2x2 4x1 1x4 4x2; do
                cjpeg -quality 90 -sample $sample -outfile "$T/s.jpg" "$T/s.ppm" &&
                    djpeg -rgb -outfile "$T/s-d.ppm" "$T/s.jpg" &&
                    "$DIFF" -q "$T/s-d.ppm" "$T/s.jpg" || bad="$bad ${w}x$h/$sample"
                sizes=$((sizes + 1))
            done
            h=$((h + 1))
        done
        w=$((w + 1))
    done
    [ -z "$bad" ] && pass || fail "sizes whose pixels are not djpeg's:$bad"
    echo "jpeg: $sizes small files (1 x 1 to $last x $last, six subsamplings) identical to djpeg's"
fi

# --- 1b. damaged files: read as djpeg reads them, with a warning ---
# corrupt IN OUT KIND: OUT is IN damaged at fixed places of its data:
# bytes changed, bytes cut out, two bytes deleted (no marker to resync
# on: the blocks after are decoded from shifted bits, so that values out
# of every valid range reach the inverse DCT), fill bytes before a marker,
# a frame 256 rows taller than its data, junk between segments, no end
# marker, or cut short.
# marker_at FILE XX N: the offset of the Nth marker 0xFF 0xXX in FILE.
marker_at() {
    od -An -v -tx1 -w1 "$1" | awk -v m="$2" -v n="$3" '
        $1 == "ff" { f = NR; next } $1 == m && f == NR - 1 && ++k == n { print NR - 2; exit }'
}
corrupt() {
    size=$(wc -c <"$1")
    sos=$(od -An -v -tx1 -w1 "$1" | awk '/ff/ { f = NR } /da/ && f == NR - 1 { print NR; exit }')
    cp "$1" "$2"
    case $3 in
    changed)
        for at in $((sos + (size - sos) * 2 / 5)) $((sos + (size - sos) * 3 / 5)) \
            $((sos + (size - sos) * 4 / 5)); do
            printf '\132' | dd of="$2" bs=1 seek="$at" conv=notrunc 2>/dev/null
        done ;;
    cut) { head -c $((sos + (size - sos) / 2)) "$1"; tail -c +$((sos + (size - sos) / 2 + 40)) "$1"; } >"$2" ;;
    deleted) { head -c $((sos + (size - sos) / 3)) "$1"; tail -c +$((sos + (size - sos) / 3 + 3)) "$1"; } >"$2" ;;
    fill) { head -c $((sos - 2)) "$1"; printf '\377\377\377'; tail -c +$((sos - 1)) "$1"; } >"$2" ;;
    taller) # the frame's height 256 rows more: the data ends before the picture
        sof=$(od -An -v -tx1 -w1 "$1" | awk '/ff/ { f = NR } /c[02]/ && f == NR - 1 { print NR; exit }')
        high=$(od -An -v -tu1 -j $((sof + 3)) -N 1 "$1" | tr -d ' ')
        printf "\\$(printf '%03o' $((high + 1)))" | dd of="$2" bs=1 seek=$((sof + 3)) conv=notrunc 2>/dev/null ;;
    junk) { head -c 20 "$1"; printf 'junk'; tail -c +21 "$1"; } >"$2" ;;
    noeoi) head -c $((size - 2)) "$1" >"$2" ;;
    short) head -c $((sos + (size - sos) * 2 / 3)) "$1" >"$2" ;;
    esac
}
if have cjpeg && have djpeg; then
    damaged=0
    # djpeg as it runs, with its SIMD inverse DCT (SSE2, AVX2 and NEON give
    # the same pixels), which computes in 16 bits and saturates: blocks of
    # damaged data out of every valid range come out as ours; its C code
    # (JSIMD_FORCENONE, where there is no SIMD) wraps them around instead.
    for opts in "-restart 1" "-restart 2 -sample 2x2" "-restart 1 -progressive" "-optimize"; do
        full || [ "$opts" = "-restart 1" ] || [ "$opts" = "-restart 1 -progressive" ] || continue
        # shellcheck disable=SC2086
        cjpeg -quality 85 $opts -outfile "$T/good.jpg" "$T/render.ppm"
        for kind in changed cut deleted fill taller junk noeoi short; do
            # (A progressive file cut short: djpeg smooths the blocks whose
            # coefficients never came, and so do we.)
            corrupt "$T/good.jpg" "$T/bad.jpg" $kind
            djpeg -rgb -outfile "$T/bad-d.ppm" "$T/bad.jpg" 2>"$T/djpeg-err"
            "$DIFF" "$T/bad-d.ppm" "$T/bad.jpg" >"$T/out" 2>"$T/err" &&
                { [ -s "$T/djpeg-err" ] || [ ! -s "$T/err" ]; } &&
                { [ ! -s "$T/djpeg-err" ] || grep -q 'warning: corrupt JPEG data' "$T/err"; } && pass ||
                fail "damaged ($kind) cjpeg $opts file: not djpeg's pixels, or not its warning" \
                    "$(cat "$T/djpeg-err" "$T/err" "$T/out")"
            damaged=$((damaged + 1))
        done
    done
    echo "jpeg: $damaged damaged files read as djpeg reads them"
    # Progressive files cut short at five places each, where djpeg smooths
    # the coefficients that never came: with two block rows an MCU row
    # (2x2, 1x2), whose second and next-to-last MCU rows libjpeg-turbo 2.1
    # smooths from nearer rows than 3.0.1 does, and two blocks wide (16
    # pixels), whose window's right end it takes from the first column.
    "$RT" -q --size 16x240 scenes/materials.txt "$T/narrow.ppm"
    cuts=0
    for opts in "-sample 2x2 $T/render.ppm" "-sample 1x2 $T/render.ppm" \
        "-sample 1x1 $T/narrow.ppm" "-sample 2x2 $T/narrow.ppm"; do
        # shellcheck disable=SC2086
        cjpeg -quality 85 -progressive $opts >"$T/prog.jpg"
        size=$(wc -c <"$T/prog.jpg")
        for part in 2 3 4 5 6; do
            head -c $((size * part / 7)) "$T/prog.jpg" >"$T/prog-cut.jpg"
            djpeg -rgb -outfile "$T/prog-d.ppm" "$T/prog-cut.jpg" 2>/dev/null
            [ -s "$T/prog-d.ppm" ] || continue # cut before its first scan's data
            "$DIFF" "$T/prog-d.ppm" "$T/prog-cut.jpg" >"$T/out" 2>&1 && pass ||
                fail "progressive cjpeg $opts file cut to $part/7: not djpeg's pixels" \
                    "$(cat "$T/out")"
            cuts=$((cuts + 1))
        done
    done
    echo "jpeg: $cuts progressive files cut short read as djpeg reads them"
    # Tables as libjpeg-turbo takes them: a sequential file without its
    # Huffman tables (Motion JPEG leaves out the standard's, which cjpeg
    # writes) is read with the standard's; a progressive AC scan naming DC
    # table 15, which it does not use, is read; a DC table with a symbol
    # above 15 is refused.
    cjpeg -quality 85 -outfile "$T/good.jpg" "$T/render.ppm"
    dht=$(marker_at "$T/good.jpg" c4 1)
    dht_len=$(od -An -tu1 -j $((dht + 2)) -N 2 "$T/good.jpg" | awk '{ print $1 * 256 + $2 }')
    { head -c "$dht" "$T/good.jpg"; tail -c +$((dht + 3 + dht_len)) "$T/good.jpg"; } >"$T/notables.jpg"
    djpeg -rgb -outfile "$T/notables-d.ppm" "$T/notables.jpg" 2>/dev/null
    "$DIFF" "$T/notables-d.ppm" "$T/notables.jpg" >"$T/out" 2>&1 && pass ||
        fail "a file without Huffman tables: not djpeg's pixels" "$(cat "$T/out")"
    cjpeg -quality 85 -progressive -outfile "$T/prog.jpg" "$T/render.ppm"
    sos=$(marker_at "$T/prog.jpg" da 2)
    cp "$T/prog.jpg" "$T/dc15.jpg"
    printf '\360' | dd of="$T/dc15.jpg" bs=1 seek=$((sos + 6)) conv=notrunc 2>/dev/null
    djpeg -rgb -outfile "$T/dc15-d.ppm" "$T/dc15.jpg" 2>/dev/null
    "$DIFF" "$T/dc15-d.ppm" "$T/dc15.jpg" >"$T/out" 2>&1 && pass ||
        fail "an AC scan naming DC table 15: not djpeg's pixels" "$(cat "$T/out")"
    cp "$T/good.jpg" "$T/dc-symbol.jpg"
    printf '\040' | dd of="$T/dc-symbol.jpg" bs=1 seek=$((dht + 21)) conv=notrunc 2>/dev/null
    if djpeg -rgb -outfile "$T/dc-symbol-d.ppm" "$T/dc-symbol.jpg" 2>/dev/null; then
        fail "djpeg reads a DC table with a symbol above 15: the test is wrong"
    else
        expect_exit "a DC table with a symbol above 15" 2 "$DIFF" "$T/dc-symbol.jpg" "$T/dc-symbol.jpg"
        grep -q "a DC symbol above 15" "$T/err" && pass ||
            fail "a DC table with a symbol above 15: not refused as such" "$(cat "$T/err")"
    fi
    # Junk between the data and the end marker: the bytes passed over are
    # counted as djpeg counts them, after the bytes the decoder read ahead
    # (djpeg's read-ahead depends on how its 4096-byte reads fall: the
    # counts may differ by the 8 bytes its bit buffer holds).
    cjpeg -quality 85 -outfile "$T/good.jpg" "$T/render.ppm"
    size=$(wc -c <"$T/good.jpg")
    for n in 17 300; do
        { head -c $((size - 2)) "$T/good.jpg"; head -c "$n" /dev/zero | tr '\0' A
            tail -c 2 "$T/good.jpg"; } >"$T/junk.jpg"
        djpeg -rgb -outfile "$T/junk-d.ppm" "$T/junk.jpg" 2>"$T/djpeg-err"
        count=$(sed -n 's/.*: \([0-9]*\) extraneous bytes.*/\1/p' "$T/djpeg-err")
        "$DIFF" "$T/junk-d.ppm" "$T/junk.jpg" >"$T/out" 2>"$T/err"
        status=$?
        ours=$(sed -n 's/.*: \([0-9]*\) extraneous bytes before marker 0xD9.*/\1/p' "$T/err")
        [ "$status" = 0 ] && [ -n "$count" ] && [ -n "$ours" ] && [ "$ours" -le "$n" ] &&
            [ $((ours - count)) -le 8 ] && [ $((count - ours)) -le 8 ] &&
            pass || fail "$n junk bytes before the end: not djpeg's pixels or count" \
            "$(cat "$T/djpeg-err" "$T/err" "$T/out")"
    done
fi

# --- 2. Exif orientation ---
# exif O: an APP1 segment whose IFD0 holds Orientation O (big-endian TIFF).
exif() {
    printf '\377\341\000\042Exif\000\000MM\000\052\000\000\000\010\000\001'
    printf '\001\022\000\003\000\000\000\001\000'
    printf "\\$(printf '%03o' "$1")"
    printf '\000\000\000\000\000\000'
}
if have cjpeg && have djpeg && have pamflip; then
    noise 23 11 "$T/o.ppm"
    cjpeg -quality 95 -outfile "$T/o.jpg" "$T/o.ppm"
    djpeg -rgb -outfile "$T/o-d.ppm" "$T/o.jpg"
    # Orientation 7 (transverse) is pamflip's transpose then half a turn.
    orientations="2:-leftright 3:-rotate180 4:-topbottom 5:-transpose 6:-cw 7:-transpose,-rotate180 8:-ccw"
    full || orientations="6:-cw"
    for o in $orientations; do
        { printf '\377\330'; exif "${o%%:*}"; tail -c +3 "$T/o.jpg"; } >"$T/t.jpg"
        flips=${o#*:}
        cp "$T/o-d.ppm" "$T/want.ppm"
        for f in $(echo "$flips" | tr ',' ' '); do
            pamflip "$f" "$T/want.ppm" >"$T/flipped.ppm" && mv "$T/flipped.ppm" "$T/want.ppm"
        done
        "$DIFF" --tolerance 0 "$T/want.ppm" "$T/t.jpg" >"$T/out" 2>&1 && pass ||
            fail "Exif orientation ${o%%:*} is not pamflip $flips" "$(cat "$T/out")"
    done
fi

# --- 3. what is refused, by name ---
# refused NAME MESSAGE: raytrace-diff must say MESSAGE of $T/NAME.jpg.
refused() {
    "$DIFF" "$T/$1.jpg" "$T/$1.jpg" >"$T/out" 2>&1
    if [ $? -eq 2 ] && grep -q "$2" "$T/out"; then pass; else fail "$1: expected '$2'" "$(cat "$T/out")"; fi
}
if have cjpeg; then
    cjpeg -arithmetic -outfile "$T/arith.jpg" "$T/render.ppm" 2>/dev/null ||
        cjpeg -arithmetic -outfile "$T/arith.jpg" scenes/textures/checker.ppm
    refused arith "unsupported JPEG: arithmetic coding"
fi
# frame HEADER-BYTES: SOI, a frame header, EOI (octal escapes).
frame() { printf '\377\330'; printf "$1"; printf '\377\331'; }
frame '\377\303\000\013\010\000\010\000\010\001\001\021\000' >"$T/lossless.jpg"
refused lossless "unsupported JPEG: lossless coding"
frame '\377\305\000\013\010\000\010\000\010\001\001\021\000' >"$T/hier.jpg"
refused hier "unsupported JPEG: hierarchical coding"
frame '\377\301\000\013\014\000\010\000\010\001\001\021\000' >"$T/twelve.jpg"
refused twelve "unsupported JPEG: 12-bit samples"
frame '\377\300\000\024\010\000\010\000\010\004\001\021\000\002\021\000\003\021\000\004\021\000' \
    >"$T/cmyk.jpg"
refused cmyk "unsupported JPEG: four components"
frame '\377\311\000\013\010\000\010\000\010\001\001\021\000' >"$T/sof9.jpg"
refused sof9 "unsupported JPEG: arithmetic coding"

# --- 4. a texture too large for --memory-limit: refused, output untouched ---
if have cjpeg; then
    printf 'P6\n4000 3000\n255\n' >"$T/big.ppm"
    head -c 36000000 /dev/zero >>"$T/big.ppm"
    cjpeg -quality 50 "$T/big.ppm" >"$T/big.jpg"
    printf 'm t MATTE 1 1 1 0 0 0 big.jpg\np Sphere 0 0 5 1 t\n' >"$T/big.txt"
    printf 'keep me\n' >"$T/big-out.ppm"
    "$RT" -q --memory-limit 16M "$T/big.txt" "$T/big-out.ppm" 2>"$T/err"
    got=$?
    want="raytrace: $T/big.txt:1:23: error: cannot use the texture 'big.jpg': a 4000 x 3000 JPEG needs 85.99 MiB to decode, more than the 16 MiB the memory limit leaves (raise it with --memory-limit)"
    if [ $got != 1 ] || [ "$(head -n 1 "$T/err")" != "$want" ]; then
        fail "a texture over --memory-limit: exit $got" "$(head -n 1 "$T/err")"
    elif [ "$(cat "$T/big-out.ppm")" != "keep me" ]; then
        fail "a texture over --memory-limit: the existing output was changed"
    else
        pass
    fi
    # Read whole (seconds): in full only.
    if full; then
        "$RT" -q --memory-limit 256M "$T/big.txt" "$T/big-out.ppm" && pass ||
            fail "a texture within --memory-limit 256M"
    fi
fi

# --- 5. our JPEG writer: djpeg reads every file, our reader gives its pixels,
# quality 90 keeps 38 dB, the bytes do not depend on threads ---
# psnr A B: the PSNR of B against A, in dB, as raytrace-diff says it.
psnr() { "$DIFF" "$1" "$2" 2>&1 | sed -n 's/.*PSNR: \([0-9.]*\) dB.*/\1/p'; }
if have djpeg; then
    written=0
    # The MPL ray tracer's example by the physical model: its textures' sharp edges,
    # without its own model's noise.
    scenes="course lights mpl materials"
    settings=';--jpeg-subsampling 444;--jpeg-quality 1;--jpeg-quality 50;--jpeg-quality 100;--jpeg-quality 100 --jpeg-subsampling 444'
    if ! full; then
        scenes="course lights"
        settings=';--jpeg-quality 100 --jpeg-subsampling 444'
    fi
    for src in $scenes; do
        model=
        [ "$src" = mpl ] && model="--model physical"
        # shellcheck disable=SC2086
        "$RT" -q $model "scenes/$src.txt" "$T/w-$src.ppm"
        for opts in $(printf '%s' "$settings" | tr ' ;' '@ ' | sed 's/^ /_ /'); do
            opts=$(printf '%s' "$opts" | tr '@' ' ' | sed 's/^_$//')
            # shellcheck disable=SC2086
            "$RT" -q $model $opts "scenes/$src.txt" "$T/w.jpg" || fail "$src $opts: no JPEG written"
            written=$((written + 1))
            if ! djpeg -rgb "$T/w.jpg" >"$T/w-djpeg.ppm" 2>"$T/err" || [ -s "$T/err" ]; then
                fail "djpeg cannot read our $src $opts" "$(cat "$T/err")"
                continue
            fi
            "$DIFF" -q "$T/w-djpeg.ppm" "$T/w.jpg" && pass ||
                fail "our reader differs from djpeg on our own $src $opts"
            p=$(psnr "$T/w-$src.ppm" "$T/w-djpeg.ppm")
            # The course scene at the defaults (quality 90, 4:2:0) keeps 38 dB;
            # any scene at quality 100 in 4:4:4 keeps 50. (Scenes of sharp,
            # saturated colour edges lose more in 4:2:0, as with cjpeg:
            # docs/scene-format.md's output section.)
            case "$src:$opts" in
            course:) min=38 ;;
            *:--jpeg-quality\ 100\ --jpeg-subsampling\ 444) min=50 ;;
            *) min=0 ;;
            esac
            [ "$(echo "$p >= $min" | bc)" = 1 ] && pass || fail "$src $opts: PSNR $p dB, under $min"
        done
    done
    echo "jpeg: $written JPEGs written by raytrace read back by djpeg"
    # Odd sizes, from one pixel to two MCUs and a bit.
    sizes="1@1 7@5 17@9 33@65"
    full || sizes="1@1 17@9"
    for size in $sizes; do
        size=$(printf '%s' "$size" | tr '@' ' ')
        set -- $size
        sed "s/ 700 500\$/ $1 $2/" scenes/ocaml-test.txt >"$T/odd.txt"
        for sub in 420 444; do
            "$RT" -q --jpeg-subsampling $sub "$T/odd.txt" "$T/odd.jpg" &&
                djpeg -rgb "$T/odd.jpg" >"$T/odd-d.ppm" 2>"$T/err" && [ ! -s "$T/err" ] &&
                [ "$(head -c 20 "$T/odd-d.ppm" | sed -n 2p)" = "$1 $2" ] && pass ||
                fail "a $1 x $2 JPEG ($sub) that djpeg cannot read" "$(cat "$T/err")"
        done
    done
    # Quality buys accuracy: PSNR grows with it.
    last=0
    for q in 10 50 90 100; do
        "$RT" -q --jpeg-quality $q scenes/course.txt "$T/q.jpg"
        p=$(psnr "$T/w-course.ppm" "$T/q.jpg")
        [ "$(echo "$p > $last" | bc)" = 1 ] && pass || fail "quality $q: PSNR $p, not above $last"
        last=$p
    done
    # The same bytes on any number of threads (the quick suite: a smaller
    # picture).
    size=
    full || size="--size 200x150"
    # shellcheck disable=SC2086
    "$RT" -q -j 1 $size scenes/materials.txt "$T/j1.jpg"
    # shellcheck disable=SC2086
    "$RT" -q -j 2 $size scenes/materials.txt "$T/j2.jpg"
    cmp -s "$T/j1.jpg" "$T/j2.jpg" && pass || fail "JPEG bytes differ between 1 and 2 threads"
fi

finish
