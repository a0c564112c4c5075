#!/bin/sh
# platform.sh: the programs built for another system or C library keep
# this build's promises. Run by make test-windows (MinGW-w64's programs,
# under Wine) and make test-musl (musl's):
#
#  1. their unit tests pass, and every example scene renders to its golden
#     bytes (tests/golden.sh, run on their programs);
#  2. they render the same bytes as this system's build (REFERENCE) on
#     scenes of every format, feature and model, --noise among them;
#  3. an image written to standard output is the file's bytes, a scene
#     read from standard input is the file's scene;
#  4. an existing output is replaced whole, a failed or interrupted render
#     leaves it as it was (an interrupt exits 130), and nothing is left
#     beside it either way; the output may not be the scene file itself,
#     even under another name;
#  5. errors name file, line and column, and exit 1 (a missing scene, a
#     bad record, a folder that is not there), 2 for a bad option;
#  6. file names in UTF-8 open (a scene, its texture, the output); on
#     Windows, a scene's texture path with backslashes, and one with a
#     drive letter, open too;
#  7. -v says the threads and the peak memory the system counted.
#
# Usage: sh tests/platform.sh windows|musl DIR UNIT REFERENCE
#   DIR holds their raytrace and raytrace-diff (NAME.exe on Windows), UNIT
#   is their unit test program, REFERENCE this system's raytrace. On
#   Windows, WINE names Wine's program (default: wine64 or, as Debian's
#   wine64 package has it, /usr/lib/wine/wine64), in a prefix of its own
#   under the build (WINEPREFIX).

PORT=$1
DIR=$2
UNIT=$3
REF=$4
SUITE=$PORT
. "$(dirname "$0")/check.sh"

# --- how to run their programs: $T/bin/NAME ---
mkdir -p "$T/bin"
case $PORT in
windows)
    EXE=.exe
    WINE=${WINE:-$(command -v wine64 || echo /usr/lib/wine/wine64)}
    if [ ! -x "$WINE" ] && ! command -v "$WINE" >/dev/null 2>&1; then
        echo "$SUITE: no Wine (Debian: wine64): cannot run Windows programs" >&2
        exit 1
    fi
    # Wine's own prefix, kept between runs (its first start takes seconds),
    # and its server kept up while the suite runs.
    WINEPREFIX=${WINEPREFIX:-$(pwd)/build/wine}
    WINEDEBUG=-all
    export WINEPREFIX WINEDEBUG
    mkdir -p "$WINEPREFIX"
    run() { "$WINE" "$@"; }
    server=$(dirname "$(command -v "$WINE" || echo "$WINE")")/wineserver
    [ -x "$server" ] || server=wineserver
    "$server" -p 30 >/dev/null 2>&1
    ;;
musl)
    EXE=
    run() { "$@"; }
    ;;
*)
    echo "usage: sh tests/platform.sh windows|musl DIR UNIT REFERENCE" >&2
    exit 2
    ;;
esac
for p in raytrace raytrace-diff; do
    [ -f "$DIR/$p$EXE" ] || { echo "$SUITE: no $DIR/$p$EXE" >&2; exit 1; }
    abs=$(cd "$DIR" && pwd)/$p$EXE
    if [ "$PORT" = windows ]; then
        printf '#!/bin/sh\nexec "%s" "%s" "$@"\n' "$WINE" "$abs" >"$T/bin/$p"
    else
        printf '#!/bin/sh\nexec "%s" "$@"\n' "$abs" >"$T/bin/$p"
    fi
    chmod +x "$T/bin/$p"
done
RT=$T/bin/raytrace
DIFF=$T/bin/raytrace-diff

# --- 1. their unit tests, and the golden renders ---
run "$UNIT" >"$T/unit" 2>&1
last=$(tail -n 1 "$T/unit" | tr -d '\r')
case $last in
*" passed, 0 failed") pass ;;
*) fail "unit tests: $last" "$(grep FAIL "$T/unit" | head -n 20)" ;;
esac
if RAYTRACE_TEST_LEVEL=${RAYTRACE_TEST_LEVEL:-full} sh tests/golden.sh "$RT" "$DIFF" >"$T/golden" 2>&1; then
    pass
else
    fail "golden renders" "$(tail -n 20 "$T/golden")"
fi

# --- 2. the same bytes as this system's build ---
# SCENE|OPTIONS: the course format (its scene, glass, textures, meshes),
# the keyword format, the MPL ray tracer's by its model and ours, and adaptive
# sampling of indirect light.
for line in "scenes/course.txt|" "scenes/glass.txt|" "scenes/textures.txt|" \
    "scenes/keyword.txt|" "scenes/mpl.txt|--size 200x200" \
    "scenes/mpl.txt|--model physical --size 160x120" \
    "scenes/indirect.txt|--noise 4 --size 120x90" "scenes/materials.txt|--size 160x120" \
    "scenes/mesh.txt|--size 160x120" "scenes/indirect.txt|--gi 8 --ao 4 --size 96x72"; do
    scene=${line%%|*} opts=${line#*|}
    # shellcheck disable=SC2086
    "$REF" -q $opts "$scene" "$T/ref.ppm" 2>"$T/err" || fail "reference render of $scene $opts" "$(cat "$T/err")"
    # shellcheck disable=SC2086
    "$RT" -q $opts "$scene" "$T/port.ppm" 2>"$T/err"
    cmp -s "$T/ref.ppm" "$T/port.ppm" && pass || fail "$scene $opts: other bytes than this system's build" \
        "$(cat "$T/err"; "$DIFF" "$T/ref.ppm" "$T/port.ppm" 2>&1 | head -n 3)"
done
# The numbers --save writes (printf) read back (strtod) as this build's.
"$REF" --save "$T/ref-save.txt" scenes/keyword.txt 2>"$T/err" &&
    "$RT" --save "$T/port-save.txt" scenes/keyword.txt 2>"$T/err" &&
    cmp -s "$T/ref-save.txt" "$T/port-save.txt" && pass ||
    fail "--save writes other text than this system's build" "$(cat "$T/err"; diff "$T/ref-save.txt" "$T/port-save.txt" | head -n 5)"

# --- 3. standard output and input carry the bytes unchanged ---
"$RT" -q scenes/course.txt "$T/file.ppm" &&
    "$RT" -q scenes/course.txt - >"$T/stdout.ppm" 2>"$T/err" &&
    cmp -s "$T/file.ppm" "$T/stdout.ppm" && pass || fail "a PPM on standard output differs from the file" "$(cat "$T/err")"
"$RT" -q --format png scenes/course.txt - >"$T/stdout.png" 2>"$T/err" && "$RT" -q scenes/course.txt "$T/file.png" &&
    cmp -s "$T/file.png" "$T/stdout.png" && pass || fail "a PNG on standard output differs from the file" "$(cat "$T/err")"
"$RT" -q - "$T/stdin.ppm" <scenes/course.txt 2>"$T/err" && cmp -s "$T/file.ppm" "$T/stdin.ppm" && pass ||
    fail "a scene from standard input renders otherwise" "$(cat "$T/err")"

# --- 4. outputs replaced whole or not at all ---
mkdir -p "$T/dir"
printf 'old output\n' >"$T/dir/image.ppm"
expect_exit "replace an existing output" 0 "$RT" -q scenes/course.txt "$T/dir/image.ppm"
cmp -s "$T/dir/image.ppm" "$T/file.ppm" && pass || fail "the existing output was not replaced by the render"
expect_clean "nothing left beside a replaced output" "$T/dir"
printf 'old output\n' >"$T/dir/kept.ppm"
printf '0 0 0\n' >"$T/bad.txt"
expect_exit "a bad scene" 1 "$RT" -q "$T/bad.txt" "$T/dir/kept.ppm"
[ "$(cat "$T/dir/kept.ppm")" = "old output" ] && pass || fail "a failed render changed the existing output"
expect_clean "nothing left beside the output a failed render kept" "$T/dir"
cp scenes/course.txt "$T/dir/scene.txt"
expect_exit "the output is the scene" 1 "$RT" -q "$T/dir/scene.txt" "$T/dir/scene.txt"
expect_grep "the output is the scene: message" "the output is the scene file itself" "$T/err"
cmp -s "$T/dir/scene.txt" scenes/course.txt && pass || fail "the scene file was overwritten"
if [ "$PORT" = windows ]; then
    # The same file by another spelling of its name.
    expect_exit "the output is the scene, named otherwise" 1 "$RT" -q "$T/dir/scene.txt" "$T/dir/../out/SCENE.TXT"
    cmp -s "$T/dir/scene.txt" scenes/course.txt && pass || fail "the scene file was overwritten under another name"
fi

# An interrupt (Ctrl-C: Wine makes SIGINT the console's Ctrl-C event) ends
# a render with 130 and its message, the existing output kept.
# It waits for -v's first line (the scene is read), not a fixed time.
printf 'old output\n' >"$T/dir/kept.ppm"
: >"$T/err"
$DEFAULT_INT "$RT" -v --size 1600x1600 -s 64 scenes/glass.txt "$T/dir/kept.ppm" 2>"$T/err" &
awaits $! "$T/err" "read the scene" || fail "an interrupt: the render ended before its first line"
pkill -INT -f "glass.txt $T/dir/kept.ppm" || kill -INT $!
wait $!
code=$?
tr -d '\r' <"$T/err" >"$T/int"
[ "$code" = 130 ] && grep -q '^raytrace: interrupted$' "$T/int" && pass ||
    fail "an interrupt: exit $code, expected 130 and its message" "$(describe "$T/int")"
[ "$(cat "$T/dir/kept.ppm")" = "old output" ] && pass || fail "an interrupt changed the existing output"
expect_clean "nothing left beside the output after an interrupt" "$T/dir"

# --- 5. errors: where, and the exit status ---
expect_exit "a missing scene" 1 "$RT" -q "$T/none.txt" "$T/x.ppm"
expect_grep "a missing scene: message" "none.txt: error: cannot open" "$T/err"
printf '0 0 -5\n-1 1 0\n1 1 0\n-1 -1 0\n4 4\n0 0 0\n0 5 0 1 1 1\nsphere: 0 0 5 1 x 0 0 0\n' >"$T/pos.txt"
expect_exit "a bad record" 1 "$RT" -q "$T/pos.txt" "$T/x.ppm"
expect_grep "a bad record: file:line:col" "pos.txt:5:3: error: expected 1 number" "$T/err"
expect_exit "a folder that is not there" 1 "$RT" -q scenes/course.txt "$T/nowhere/x.ppm"
expect_grep "a folder that is not there: message" "cannot create a file in directory" "$T/err"
expect_exit "a bad option" 2 "$RT" --no-such-option scenes/course.txt "$T/x.ppm"
[ ! -e "$T/x.ppm" ] && pass || fail "a failed command left an output"

# --- 6. names in UTF-8, and Windows's own paths ---
u="$T/été"
mkdir -p "$u/imagés"
cp scenes/textures.txt "$u/scène.txt"
# The textures of scenes/textures.txt, moved to a folder named in UTF-8.
for t in $(sed -n 's/^texture:[ \t]*\([^ \t]*\).*/\1/p' scenes/textures.txt | sort -u); do
    mkdir -p "$u/imagés/$(dirname "$t")"
    cp "scenes/$t" "$u/imagés/$t"
done
sed 's|^texture:\([ \t]*\)|texture:\1imagés/|' scenes/textures.txt >"$u/scène.txt"
"$REF" -q scenes/textures.txt "$T/tex.ppm"
expect_exit "UTF-8 names" 0 "$RT" -q "$u/scène.txt" "$u/rendu é.ppm"
cmp -s "$T/tex.ppm" "$u/rendu é.ppm" && pass || fail "UTF-8 names: other bytes" "$(cat "$T/err")"
if [ "$PORT" = windows ]; then
    sed 's|^texture:\([ \t]*\)|texture:\1imagés\\|' scenes/textures.txt >"$u/back.txt"
    expect_exit "a texture path with backslashes" 0 "$RT" -q "$u/back.txt" "$u/back.ppm"
    cmp -s "$T/tex.ppm" "$u/back.ppm" && pass || fail "backslashes: other bytes" "$(cat "$T/err")"
    # Wine's drive Z: is the root of this system's files.
    drive="Z:$(printf '%s' "$u" | tr / '\\')\\imagés\\"
    sed "s|^texture:\([ \t]*\)|texture:\1$(printf '%s' "$drive" | sed 's/\\/\\\\/g')|" scenes/textures.txt >"$u/drive.txt"
    expect_exit "a texture path with a drive letter" 0 "$RT" -q "$u/drive.txt" "$u/drive.ppm"
    cmp -s "$T/tex.ppm" "$u/drive.ppm" && pass || fail "a drive letter: other bytes" "$(cat "$T/err")"
fi

# --- 7. -v: threads and peak memory from the system ---
# (Windows's standard error ends its lines with CR LF, as its programs do.)
expect_exit "-v" 0 "$RT" -v scenes/course.txt "$T/v.ppm"
tr -d '\r' <"$T/err" >"$T/v"
grep -q '^raytrace: peak memory: [1-9][0-9.]* MB$' "$T/v" && pass || fail "-v: no peak memory" "$(cat "$T/v")"
grep -q ' [0-9]* threads\{0,1\}$' "$T/v" && pass || fail "-v: no threads" "$(cat "$T/v")"

[ "$PORT" = windows ] && "$server" -k >/dev/null 2>&1
finish
