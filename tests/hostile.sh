#!/bin/sh
# hostile.sh: raytrace against hostile inputs (`make test`). Whatever it is
# fed, it must answer with an image or one clear, positioned error, never
# crash or hang, and never damage an existing output or leave a partial one.
#
# The committed inputs and their expected first lines are in
# tests/hostile/EXPECTED; the ones too large or too odd for git (a 10 MB
# line, 10^6 spheres on one line, a 32768 x 32768 image, devices, unreadable
# files, outputs that cannot be written) are made here.
#
# Usage: sh tests/hostile.sh RAYTRACE   (run from the repository root)

RT=$1
SUITE=hostile
. "$(dirname "$0")/check.sh"
TAB=$(printf '\t')

# check NAME CODE FIRST-LINE OUTPUT ARGS...: runs raytrace ARGS with OUTPUT
# holding "keep me"; checks the exit status, the first line on standard
# error ('-': none), that a failed run left OUTPUT as it was and nothing else
# beside it, and that a successful one wrote a PPM.
check() {
    name=$1 code=$2 first=$3 out=$4
    shift 4
    rm -rf "$T/o"
    mkdir "$T/o"
    [ -n "$out" ] && [ "${out#"$T"/o/}" != "$out" ] && printf 'keep me\n' >"$out"
    "$RT" -q "$@" >"$T/stdout" 2>"$T/err"
    got=$?
    line=$(head -n 1 "$T/err")
    [ -z "$line" ] && line=-
    if [ "$got" != "$code" ]; then
        fail "$name: exit $got, expected $code" "$(head -n 3 "$T/err")"
    elif [ "$line" != "$first" ]; then
        fail "$name: wrong message" "expected: $first
got:      $line"
    elif [ "$code" != 0 ] && [ -n "$out" ] && [ "${out#"$T"/o/}" != "$out" ] &&
        [ "$(cat "$out")" != "keep me" ]; then
        fail "$name: the existing output was changed"
    elif [ "$code" != 0 ] && [ "$(ls -A "$T/o" | wc -l)" -gt 1 ]; then
        fail "$name: a file was left behind" "$(ls -A "$T/o")"
    elif [ "$code" = 0 ] && [ -n "$out" ] && [ "$(head -c 2 "$out")" != P6 ]; then
        fail "$name: no image written"
    elif [ "$(wc -l <"$T/err")" -gt 4 ]; then
        fail "$name: more than one error printed" "$(cat "$T/err")"
    else
        passed=$((passed + 1))
    fi
}

# --- the committed inputs ---
while IFS="$TAB" read -r file code first; do
    case $file in '#'* | '') continue ;; esac
    check "$file" "$code" "$first" "$T/o/out.ppm" "tests/hostile/$file" "$T/o/out.ppm"
done <tests/hostile/EXPECTED
count=$(grep -cv '^#' tests/hostile/EXPECTED)
[ "$(ls tests/hostile/*.txt | wc -l)" = "$count" ] ||
    fail "tests/hostile/EXPECTED lists $count inputs, the directory holds $(ls tests/hostile/*.txt | wc -l)"

# --- the generated ones ---
H='0 0 -5
-1 1 0
1 1 0
-1 -1 0
8
0 0 0
5 5 -5 255 255 255'
S='sphere: 0 0 3 1 200 100 50 0'

# A 10 MB line: a comment is read past, junk at its end is pointed at, and
# the message quotes a window of the line, not all of it.
{ echo "$H"; printf '# '; head -c 10485760 /dev/zero | tr '\0' 'x'; echo; echo "$S"; } >"$T/long-comment.txt"
check "10 MB comment line" 0 - "$T/o/out.ppm" "$T/long-comment.txt" "$T/o/out.ppm"
{ echo "$H"; printf '%s' "$S"; head -c 10485760 /dev/zero | tr '\0' ' '; echo ' junk'; } >"$T/long-line.txt"
check "10 MB line" 1 "raytrace: $T/long-line.txt:8:10485790: error: expected 8 or 10 numbers for the sphere (cx cy cz radius r g b reflection [transparency index]), found 9" \
    "$T/o/out.ppm" "$T/long-line.txt" "$T/o/out.ppm"
[ "$(wc -c <"$T/err")" -lt 1000 ] && passed=$((passed + 1)) || fail "10 MB line: the message quotes too much"

# 10^6 spheres on one line.
{ echo "$H"; awk 'BEGIN { for (i = 0; i < 1000000; i++) printf "sphere: %d 0 3 1 200 100 50 0 ", i; print "" }'; } >"$T/one-line.txt"
check "10^6 spheres on one line" 1 "raytrace: $T/one-line.txt:8:30: error: expected a number for the sphere's transparency, found 'sphere:'" \
    "$T/o/out.ppm" "$T/one-line.txt" "$T/o/out.ppm"

# 32768 x 32768 pixels: the limit stops it before a byte is allocated.
printf '0 0 -5\n-1 1 0\n1 1 0\n-1 -1 0\n32768\n0 0 0\n5 5 -5 255 255 255\n%s\n' "$S" >"$T/huge.txt"
check "32768 x 32768 PNG under the default limit" 1 "raytrace: $T/huge.txt: error: a 32768 x 32768 image needs 9.001 GiB to render and write: with the scene's 2.375 KiB, more than the memory limit of 4 GiB (raise it with --memory-limit)" \
    "$T/o/out.png" "$T/huge.txt" "$T/o/out.png"
check "32768 x 32768 PPM under a 1G limit" 1 "raytrace: $T/huge.txt: error: a 32768 x 32768 image needs 3 GiB to render and write: with the scene's 2.375 KiB, more than the memory limit of 1 GiB (raise it with --memory-limit)" \
    "$T/o/out.ppm" --memory-limit 1G "$T/huge.txt" "$T/o/out.ppm"

# The memory limit reached while reading: positioned at the element.
{ echo "$H"; awk 'BEGIN { for (i = 0; i < 2000; i++) printf "sphere: %d 0 3 1 200 100 50 0\n", i }'; } >"$T/many.txt"
check "memory limit while reading" 1 "raytrace: $T/many.txt:1032:1: error: the scene would pass the memory limit of 90 KiB here: raise it with --memory-limit" \
    "$T/o/out.ppm" --memory-limit 90K "$T/many.txt" "$T/o/out.ppm"
check "memory limit before the hierarchy" 1 "raytrace: $T/many.txt: error: the bounding volume hierarchy of 2000 objects needs up to 308.9 KiB, more than the 302.2 KiB the memory limit leaves (--memory-limit; --no-accel renders without it, slowly)" \
    "$T/o/out.ppm" --memory-limit 400K "$T/many.txt" "$T/o/out.ppm"
check "--memory-limit 0 is no limit" 0 - "$T/o/out.ppm" --memory-limit 0 "$T/many.txt" "$T/o/out.ppm"
check "a bad --memory-limit" 2 "raytrace: option '--memory-limit' takes a size in bytes such as 512M or 8G (0: no limit), found '1T'" \
    "" --memory-limit 1T "$T/many.txt" "$T/o/out.ppm"
# ... and while reading a mesh.
awk 'BEGIN { print "v 0 0 0"; print "v 1 0 0"; print "v 0 1 0"; printf "f"; for (i = 0; i < 100000; i++) printf " 1 2 3"; print "" }' >"$T/fan.obj"
{ echo "$H"; echo "mesh: fan.obj 200 200 200 0"; } >"$T/fan.txt"
check "memory limit while reading a mesh" 1 "raytrace: $T/fan.txt:8:7: error: cannot use the mesh 'fan.obj': $T/fan.obj:4:16391: the mesh needs more memory than the 1022 KiB the memory limit leaves it, after 8192 triangles" \
    "$T/o/out.ppm" --memory-limit 1M "$T/fan.txt" "$T/o/out.ppm"

# User bytes in messages are shown safely: control bytes and invalid UTF-8
# as \xNN, valid UTF-8 (a French name) as it is; every message is valid
# UTF-8 with no control byte but its newlines.
printf '%s\nsphere: 1 \033[2J\377 2 3 4 5 6 7\n' "$H" >"$T/bytes.txt"
check "control bytes and invalid UTF-8 in a token" 1 \
    "raytrace: $T/bytes.txt:8:11: error: expected a number for the sphere's centre y, found '\\x1B[2J\\xFF'" \
    "$T/o/out.ppm" "$T/bytes.txt" "$T/o/out.ppm"
sed -n 2p "$T/err" | grep -qF '    8 | sphere: 1 \x1B[2J\xFF 2 3 4 5 6 7' && pass ||
    fail "the excerpt is not escaped" "$(sed -n 2p "$T/err")"
fr=$(printf 'sc\303\250ne') # "scène", valid UTF-8
bad=$(printf 'sc\350ne-\001x') # Latin-1 "è" and a control byte
e=$(printf '\303\250')
printf '%s\nbogus\n' "$H" >"$T/$bad.txt"
printf '%s\nsph%sre: 1\n' "$H" "$e" >"$T/$fr.txt"
check "a French scene name and record" 1 \
    "raytrace: $T/$fr.txt:8:1: error: unknown record 'sph${e}re:' (expected 'sphere:', 'plane:', 'triangle:', 'cube:', 'square:', 'cylinder:', 'cone:', 'disk:', 'torus:', 'mesh:', 'light:', 'ambient:', 'samples:', 'lens:' or 'texture:')" \
    "$T/o/out.ppm" "$T/$fr.txt" "$T/o/out.ppm"
"$RT" -q "$T/$bad.txt" "$T/o/out.ppm" 2>"$T/err"
grep -qF 'sc\xE8ne-\x01x.txt' "$T/err" && pass ||
    fail "a file name with invalid UTF-8 and a control byte is not escaped" "$(cat "$T/err")"
for f in "$T/bytes.txt" "$T/$fr.txt" "$T/$bad.txt"; do
    "$RT" -q "$f" "$T/o/out.ppm" 2>"$T/err"
    if ! iconv -f UTF-8 -t UTF-8 "$T/err" >/dev/null 2>&1 || tr -d '\n' <"$T/err" | LC_ALL=C grep -q '[[:cntrl:]]'; then
        fail "a message that is not plain UTF-8 text" "$(od -c "$T/err" | head -5)"
    else
        pass
    fi
done
rm -f "$T"/sc*

# Inputs that are not files.
check "scene is a directory" 1 "raytrace: tests/hostile/files: error: cannot read: it is a directory, not a file" \
    "$T/o/out.ppm" tests/hostile/files "$T/o/out.ppm"
check "scene is a device" 1 "raytrace: /dev/zero: error: cannot read: not a regular file (a device or a socket): give a file or a pipe" \
    "$T/o/out.ppm" /dev/zero "$T/o/out.ppm"
check "missing scene" 1 "raytrace: $T/none.txt: error: cannot open: No such file or directory" \
    "$T/o/out.ppm" "$T/none.txt" "$T/o/out.ppm"
"$RT" -q - "$T/o/out.ppm" </dev/null 2>"$T/err"
[ $? = 1 ] && grep -q "^raytrace: <stdin>: error: the scene is empty: the file holds no byte" "$T/err" &&
    passed=$((passed + 1)) || fail "empty standard input" "$(cat "$T/err")"
printf '%s\n%s\n' "$H" "$S" >"$T/locked.txt"
chmod 000 "$T/locked.txt"
if ! cat "$T/locked.txt" >/dev/null 2>&1; then # not when running as root
    check "unreadable scene" 1 "raytrace: $T/locked.txt: error: cannot open: Permission denied" \
        "$T/o/out.ppm" "$T/locked.txt" "$T/o/out.ppm"
fi

# Outputs that cannot be written.
printf '%s\n%s\n' "$H" "$S" >"$T/ok.txt"
check "output in a missing directory" 1 "raytrace: $T/o/no/such/out.ppm: error: cannot create a file in directory '$T/o/no/such': No such file or directory" \
    "" "$T/ok.txt" "$T/o/no/such/out.ppm"
if [ -w /dev/full ]; then
    check "output on a full disk" 1 "raytrace: /dev/full: error: cannot write the image: No space left on device" \
        "" "$T/ok.txt" /dev/full
fi

finish
