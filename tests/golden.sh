#!/bin/sh
# golden.sh: every example scene renders to its golden bytes
# (tests/golden.sha256) and to the README's gallery pictures, the course
# scene to the reference render of an independent implementation, and the
# same bytes for any thread count, to standard output and from standard
# input. In full (make check) each golden render is made again without the
# cut-off, and the lines after the file's "make check only" marker are
# rendered too; the quick suite (make test) renders each of the others
# once (every scene has one, the costliest at a smaller size).
#
# Usage: sh tests/golden.sh RAYTRACE RAYTRACE-DIFF   (from the repository root)

RT=$1
DIFF=$2
SUITE=golden
. "$(dirname "$0")/check.sh"

scene=scenes/course.txt
expect_exit render 0 "$RT" "$scene" "$T/course.ppm"

# --- the course scene against the reference (independent implementation):
# within one level, on all but 0.5% of the pixels (today: identical) ---
expect_exit "course matches reference" 0 "$DIFF" --tolerance 1 --max-pixels 800 tests/ref/course.ppm "$T/course.ppm"
expect_grep "course identical to reference" "max error: 0 (identical pixels)" "$T/out"
head -c 15 "$T/course.ppm" | od -c | head -1 | grep -q 'P   6  \\n   4   0   0       4   0   0  \\n   2   5   5  \\n' \
    && pass || fail "PPM header is not 'P6\\n400 400\\n255\\n'"

# --- threads and standard output give the same bytes ---
expect_exit "threads 1" 0 "$RT" --threads 1 "$scene" "$T/t1.ppm"
expect_exit "threads 2" 0 "$RT" --threads 2 "$scene" "$T/t2.ppm"
cmp -s "$T/t1.ppm" "$T/t2.ppm" && cmp -s "$T/t1.ppm" "$T/course.ppm" && pass || fail "threads change the bytes"
"$RT" "$scene" - >"$T/stdout.ppm" 2>"$T/err" && cmp -s "$T/stdout.ppm" "$T/course.ppm" && pass || fail "'-' output differs"
"$RT" - "$T/stdin.ppm" <"$scene" 2>"$T/err" && cmp -s "$T/stdin.ppm" "$T/course.ppm" && pass || fail "'-' scene differs"

# --- every example scene renders to its golden bytes ---
# The lines to render: before the marker only, in the quick suite.
if full; then
    grep -v '^#' tests/golden.sha256 >"$T/golden"
else
    sed '/^# --- make check only ---$/q' tests/golden.sha256 | grep -v '^#' >"$T/golden"
fi
while read -r hash file opts; do
    # shellcheck disable=SC2086
    "$RT" $opts "$file" "$T/golden.ppm" 2>"$T/err"
    got=$(sha256sum <"$T/golden.ppm" | cut -d' ' -f1)
    [ "$got" = "$hash" ] && pass || fail "golden render of $file $opts changed: $got" "$(cat "$T/err")"
    # The cut-off (on by default) changes no byte: the same render without it.
    if full; then
        # shellcheck disable=SC2086
        got=$("$RT" --cutoff 0 $opts "$file" - 2>"$T/err" | sha256sum | cut -d' ' -f1)
        [ "$got" = "$hash" ] && pass || fail "$file $opts renders other bytes with --cutoff 0: $got" "$(cat "$T/err")"
    fi
    # The README's gallery shows these very pixels (a render with options
    # as NAME-OPTS.png, OPTS without spaces and dashes, when there is one).
    suffix=$(printf '%s' "$opts" | tr -d ' -')
    picture=docs/gallery/$(basename "$file" .txt)${suffix:+-$suffix}.png
    if [ -z "$opts" ] || [ -f "$picture" ]; then
        "$DIFF" "$picture" "$T/golden.ppm" >"$T/out" 2>"$T/err" && pass ||
            fail "$file renders other pixels than $picture (if the change is meant, run 'make gallery')" \
                "$(cat "$T/out" "$T/err")"
    fi
done <"$T/golden"
for file in scenes/*.txt; do
    grep -q " $file\( \|\$\)" "$T/golden" && pass ||
        fail "$file has no golden hash before the marker in tests/golden.sha256"
done

# --- the cut-off keeps every byte at depth 30, where it leaves out most ---
full && for s in keyword mesh; do
    "$RT" -d 30 --cutoff 0 "scenes/$s.txt" "$T/cut0.ppm" &&
        "$RT" -v -d 30 --cutoff 0.5 "scenes/$s.txt" "$T/cut.ppm" 2>"$T/err" &&
        cmp -s "$T/cut0.ppm" "$T/cut.ppm" && pass || fail "--cutoff 0.5 changes scenes/$s.txt at depth 30"
    expect_grep "--cutoff statistics" "pixels refined" "$T/err"
done
expect_exit "--cutoff bad" 2 "$RT" --cutoff -1 "$scene" "$T/x.ppm"
expect_grep "--cutoff bad message" "option '--cutoff' takes a number from 0 to 255, found '-1'" "$T/err"

finish
