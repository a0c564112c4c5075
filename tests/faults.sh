#!/bin/sh
# faults.sh: what a render leaves behind when it is killed, or raced
# (`make test`).
#
#  1. SIGKILL at 50 moments spread over a render's whole life (reading
#     200,000 spheres, building their hierarchy, rendering, writing): the
#     output's folder must hold what it held before (the old output) or
#     the complete new image, and nothing else: no temporary file (or,
#     killed in the microseconds between the link and the rename that name
#     the image, the complete new image under a temporary name, which the
#     next render removes).
#  2. Two renders writing the same output at once, ten times: the output
#     is one of the two complete images, never a mix, and nothing is left
#     beside it.
#  3. Injected faults (INJECT, an LD_PRELOAD library: tests/inject.c): for
#     every call of write, read, fsync, rename, linkat, open and malloc that
#     a render makes, that call fails (ENOSPC, EIO, EACCES, ENOMEM), is
#     interrupted (EINTR) or moves half its bytes: every run must end with
#     the correct image (interrupted and short calls are retried), or with
#     exit 1 and a message naming the file and the cause, the old output as
#     it was and nothing beside it. Never a crash, a hang or a mix.
#  4. The same without unnamed files (a named temporary file instead).
#  5. A failed clean-up is said, naming the file left.
#  6. A kill made to land where a name is left (between an unnamed file's
#     link and its rename; while a named temporary file is written): the
#     next render to that output removes it, and only what dead processes
#     of this machine left.
#
# The quick suite (make test, RAYTRACE_TEST_LEVEL=quick) kills at 6
# moments, races twice and injects each fault at the first, a middle and
# the last of its calls; make check does all.
#
# Usage: sh tests/faults.sh RAYTRACE [INJECT]   (from the repository root)

RT=$1
INJECT=${2:-}
SUITE=faults
. "$(dirname "$0")/check.sh"

# A scene whose every phase takes a visible share of its half second.
awk 'BEGIN { srand(7); print "0 0 -60\n-1 1 -59\n1 1 -59\n-1 -1 -59\n400\n10 20 30"
             print "50 80 -100 255 255 255"
             for (i = 0; i < 200000; i++)
                 printf "sphere: %.3f %.3f %.3f 0.15 %d %d %d 0.2\n", rand() * 60 - 30,
                     rand() * 60 - 30, rand() * 40, rand() * 255, rand() * 255, rand() * 255 }' \
    >"$T/field.txt"
start=$(date +%s%N)
"$RT" -q "$T/field.txt" "$T/whole.ppm" || fail "the field does not render"
took=$((($(date +%s%N) - start) / 1000000))
[ "$took" -lt 50 ] && took=50

# --- 1. SIGKILL at 50 moments from 0 to 1.2 times the render's time ---
moments=50 races=10
full || moments=6 races=2
mkdir "$T/o"
survived=0 finished=0 committing=0
i=0
while [ $i -lt $moments ]; do
    rm -rf "$T/o"
    mkdir "$T/o"
    printf 'old output\n' >"$T/o/out.ppm"
    delay=$(awk -v i=$i -v t="$took" -v m=$moments 'BEGIN { printf "%.3f", i * t * 1.2 / m / 1000 }')
    "$RT" -q "$T/field.txt" "$T/o/out.ppm" 2>/dev/null &
    pid=$!
    sleep "$delay"
    kill -9 $pid 2>/dev/null
    wait $pid 2>/dev/null
    left=$(ls -A "$T/o")
    # A kill between the unnamed file's link to a temporary name and its
    # rename leaves the whole new image under that name; the next render to
    # out.ppm removes it (section 6 makes that moment on purpose).
    hidden=$(ls -A "$T/o" | grep '^\.out\.ppm\.[0-9a-f]\{8\}-[0-9]*-[0-9]*$')
    if [ -n "$hidden" ] && cmp -s "$T/o/$hidden" "$T/whole.ppm"; then
        "$RT" -q "$T/field.txt" "$T/o/out.ppm" 2>/dev/null
        left=$(ls -A "$T/o")
        committing=$((committing + 1))
    fi
    if [ "$left" != out.ppm ]; then
        fail "SIGKILL after ${delay} s left: $(echo $left)"
    elif [ -n "$hidden" ]; then
        pass
    elif cmp -s "$T/o/out.ppm" "$T/whole.ppm"; then
        finished=$((finished + 1))
        pass
    elif [ "$(cat "$T/o/out.ppm")" = "old output" ]; then
        survived=$((survived + 1))
        pass
    else
        fail "SIGKILL after ${delay} s left a damaged output ($(wc -c <"$T/o/out.ppm") bytes)"
    fi
    i=$((i + 1))
done
echo "faults: SIGKILL at $moments moments of a ${took} ms render: $survived left the old output, $finished the new one, $committing the new one under a temporary name the next render removed, nothing else"

# --- 2. two renders writing the same output at once ---
printf '0 0 -5\n-1 1 -4\n1 1 -4\n-1 -1 -4\n300\n200 20 20\n5 5 -5 255 255 255\nsphere: 0 0 0 1 20 20 200 0\n' \
    >"$T/red.txt"
"$RT" -q "$T/red.txt" "$T/red.ppm"
sed 's/^400$/300/' "$T/field.txt" | head -n 40007 >"$T/small.txt"
"$RT" -q "$T/small.txt" "$T/small.ppm"
i=0
while [ $i -lt $races ]; do
    rm -rf "$T/o"
    mkdir "$T/o"
    "$RT" -q "$T/red.txt" "$T/o/out.ppm" &
    a=$!
    "$RT" -q "$T/small.txt" "$T/o/out.ppm" &
    b=$!
    wait $a
    wait $b
    left=$(ls -A "$T/o")
    if [ "$left" != out.ppm ]; then
        fail "two writers left: $(echo $left)"
    elif cmp -s "$T/o/out.ppm" "$T/red.ppm" || cmp -s "$T/o/out.ppm" "$T/small.ppm"; then
        pass
    else
        fail "two writers left a mix"
    fi
    i=$((i + 1))
done

# --- 3. injected faults, at every call a render makes ---
if [ -n "$INJECT" ] && ! LD_PRELOAD="$INJECT" "$RT" --version >"$T/probe" 2>&1; then
    # A sanitizer's runtime must come first: under ASan the injector cannot.
    echo "faults: skipped injection: this raytrace cannot be preloaded ($(grep -m 1 . "$T/probe"))"
    INJECT=
fi
if [ -n "$INJECT" ]; then
    printf '0 0 -5\n-1 1 -4\n1 1 -4\n-1 -1 -4\n64\n20 30 40\n5 5 -5 255 255 255\n' >"$T/f.txt"
    printf 'sphere: 0 0 0 1 200 100 50 0.3\nplane: 0 -1 0 0 1 0 200 200 200 0.2\n' >>"$T/f.txt"
    # And the MPL ray tracer's room of every material, JPEG textures (more reads and
    # allocations: the decoder's, the hierarchy's, the named materials').
    sed 's/^c Camera \(.*\) 640 400$/c Camera \1 32 20/' scenes/materials.txt >scenes/.faults-m.txt
    trap 'chmod -R u+rwx "$T" 2>/dev/null; rm -rf "$T" scenes/.faults-m.txt' EXIT
    survived=0 runtime=0
    for fault in write:ENOSPC write:EIO write:EINTR write:short read:EIO read:EINTR read:short \
        fsync:EIO fsync:EINTR rename:EIO linkat:EIO open:EACCES malloc:ENOMEM \
        m:read:EIO m:read:short m:malloc:ENOMEM; do
        scene=$T/f.txt
        case $fault in m:*) scene=scenes/.faults-m.txt fault=${fault#m:} ;; esac
        "$RT" -q -j 1 "$scene" "$T/good.png"
        call=${fault%%:*}
        # How many times a render (over an old output) makes that call.
        rm -rf "$T/o" "$T/count"
        mkdir "$T/o"
        printf 'keep me\n' >"$T/o/out.png"
        RAYTRACE_FAULT_COUNT="$T/count" LD_PRELOAD="$INJECT" "$RT" -q -j 1 "$scene" "$T/o/out.png"
        count=$(sed -n "s/^$call //p" "$T/count")
        # Every call, or (quick) the first, a middle one and the last.
        step=1
        full || step=$(((${count:-0} + 1) / 2))
        [ "$step" -ge 1 ] || step=1
        n=1
        while [ "$n" -le "${count:-0}" ]; do
            rm -rf "$T/o"
            mkdir "$T/o"
            printf 'keep me\n' >"$T/o/out.png"
            RAYTRACE_FAULT="$call:$n:${fault#*:}" LD_PRELOAD="$INJECT" "$RT" -q -j 1 "$scene" \
                "$T/o/out.png" 2>"$T/err"
            code=$?
            left=$(ls -A "$T/o")
            first=$(grep -m 1 . "$T/err")
            if [ "$left" != out.png ]; then
                fail "$fault at call $n: left $(echo $left)"
            elif [ $code = 0 ] && cmp -s "$T/o/out.png" "$T/good.png"; then
                survived=$((survived + 1))
                pass
            elif [ $code = 0 ]; then
                fail "$fault at call $n: exit 0 with a wrong image"
            elif [ $code != 1 ]; then
                fail "$fault at call $n: exit $code" "$(cat "$T/err")"
            elif [ "$(cat "$T/o/out.png")" != "keep me" ]; then
                fail "$fault at call $n: the old output was changed"
            else
                case $fault:$first in
                *EINTR:* | *short:*)
                    fail "$fault at call $n: not retried" "$first" ;;
                *:"raytrace: $T/"*": error: "* | *:"raytrace: $scene"*": error: "*)
                    survived=$((survived + 1)); pass ;;
                # The OpenMP runtime's own allocations at start-up: it says
                # so and exits 1 itself, before raytrace has anything open.
                malloc:*:"libgomp: Out of memory"*)
                    runtime=$((runtime + 1)); pass ;;
                *) fail "$fault at call $n: the message names no file" "$first" ;;
                esac
            fi
            if [ "$n" -lt "$count" ] && [ $((n + step)) -gt "$count" ]; then
                n=$count
            else
                n=$((n + step))
            fi
        done
        if full; then
            echo "faults: $fault at each of the $count calls a render of ${scene##*/} makes"
        fi
    done
    echo "faults: $survived injected faults survived, $runtime more refused by the OpenMP runtime"

    # --- 4. the named temporary file (no O_TMPFILE): the same faults, and
    # exits the program did not choose (the OpenMP runtime's fatal errors
    # call exit() from its threads), at every call: nothing is left ---
    exits=0
    "$RT" -q -j 2 "$T/f.txt" "$T/good.png"
    for fault in write:ENOSPC fsync:EIO rename:EIO malloc:ENOMEM write:exit malloc:exit; do
        call=${fault%%:*}
        rm -rf "$T/o" "$T/count"
        mkdir "$T/o"
        RAYTRACE_NO_TMPFILE=1 RAYTRACE_FAULT_COUNT="$T/count" LD_PRELOAD="$INJECT" \
            "$RT" -q -j 2 "$T/f.txt" "$T/o/out.png"
        count=$(sed -n "s/^$call //p" "$T/count")
        step=1
        full || step=$(((${count:-0} + 3) / 4))
        n=1
        while [ "$n" -le "${count:-0}" ]; do
            rm -rf "$T/o"
            mkdir "$T/o"
            printf 'keep me\n' >"$T/o/out.png"
            RAYTRACE_NO_TMPFILE=1 RAYTRACE_FAULT="$call:$n:${fault#*:}" LD_PRELOAD="$INJECT" \
                "$RT" -q -j 2 "$T/f.txt" "$T/o/out.png" 2>"$T/err"
            code=$?
            left=$(ls -A "$T/o")
            if [ "$left" != out.png ]; then
                fail "no O_TMPFILE, $fault at call $n: left $(echo $left)" "$(cat "$T/err")"
            elif [ $code = 0 ] && cmp -s "$T/o/out.png" "$T/good.png"; then
                pass
            elif [ $code = 0 ]; then
                fail "no O_TMPFILE, $fault at call $n: exit 0 with a wrong image"
            elif [ "$(cat "$T/o/out.png")" != "keep me" ]; then
                fail "no O_TMPFILE, $fault at call $n: the old output was changed"
            else
                pass
                exits=$((exits + 1))
            fi
            n=$((n + step))
        done
    done
    echo "faults: without unnamed files, $exits injected failures and exits left the old output alone"

    # --- 5. a failed clean-up is said: the rename fails, then the removal
    # of the named temporary file: the message names it ---
    rm -rf "$T/o"
    mkdir "$T/o"
    printf 'keep me\n' >"$T/o/out.png"
    RAYTRACE_NO_TMPFILE=1 RAYTRACE_FAULT="rename:1:EIO" LD_PRELOAD="$INJECT" \
        "$RT" -q "$T/f.txt" "$T/o/out.png" 2>"$T/err"
    [ $? = 1 ] && [ "$(ls -A "$T/o")" = out.png ] && pass || fail "a failed rename" "$(cat "$T/err")"
    rm -rf "$T/o"
    mkdir "$T/o"
    printf 'keep me\n' >"$T/o/out.png"
    RAYTRACE_NO_TMPFILE=1 RAYTRACE_FAULT="rename:1:EIO" RAYTRACE_FAULT2="unlink:1:EACCES" \
        LD_PRELOAD="$INJECT" "$RT" -q "$T/f.txt" "$T/o/out.png" 2>"$T/err"
    left=$(ls -A "$T/o" | grep -v '^out.png$')
    if [ -n "$left" ] && grep -q "the temporary file '$T/o/$left' could not be removed" "$T/err"; then
        pass
    elif [ -z "$left" ]; then
        fail "a failed clean-up: nothing was left to name" "$(cat "$T/err")"
    else
        fail "a failed clean-up leaves $left unnamed" "$(cat "$T/err")"
    fi
    # The same with an unnamed file (O_TMPFILE): over an existing output it
    # is linked to a temporary name, then renamed; when both the rename and
    # the removal of that name fail, the message names it too.
    rm -rf "$T/o"
    mkdir "$T/o"
    printf 'keep me\n' >"$T/o/out.png"
    RAYTRACE_FAULT="rename:1:EIO" RAYTRACE_FAULT2="unlink:1:EACCES" \
        LD_PRELOAD="$INJECT" "$RT" -q "$T/f.txt" "$T/o/out.png" 2>"$T/err"
    left=$(ls -A "$T/o" | grep -v '^out.png$')
    if [ -z "$left" ] || grep -q "the temporary file '$T/o/$left' could not be removed" "$T/err"; then
        pass
    else
        fail "an unnamed file's failed clean-up leaves $left unnamed" "$(cat "$T/err")"
    fi
    [ "$(cat "$T/o/out.png")" = "keep me" ] && pass || fail "a failed rename changed the old output"

    # --- 6. killed where a name is left: between the unnamed file's link
    # and its rename (the whole new image), and while a named temporary file
    # is written (without unnamed files): the next render to that output
    # removes what a dead process of this machine left, and nothing else ---
    for how in rename:1:kill:unnamed write:1:kill:named; do
        rm -rf "$T/o"
        mkdir "$T/o"
        printf 'keep me\n' >"$T/o/out.png"
        if [ "${how##*:}" = named ]; then
            RAYTRACE_NO_TMPFILE=1 RAYTRACE_FAULT="${how%:*}" LD_PRELOAD="$INJECT" \
                "$RT" -q "$T/f.txt" "$T/o/out.png" 2>/dev/null
        else
            RAYTRACE_FAULT="${how%:*}" LD_PRELOAD="$INJECT" "$RT" -q "$T/f.txt" "$T/o/out.png" \
                2>/dev/null
        fi
        left=$(ls -A "$T/o" | grep -v '^out.png$')
        host=$(echo "$left" | sed -n 's/^\.out\.png\.\([0-9a-f]\{8\}\)-[0-9]*-0$/\1/p')
        if [ -z "$host" ] || [ "$(cat "$T/o/out.png")" != "keep me" ]; then
            fail "a kill at ${how%:*} left: $(ls -A "$T/o" | tr '\n' ' ')"
            continue
        fi
        if [ "${how##*:}" = unnamed ]; then
            cmp -s "$T/o/$left" "$T/good.png" && pass ||
                fail "a kill before the rename left something else than the new image"
        fi
        # Beside it: a name of this machine's live process (this shell), one
        # of another machine, and a file of the user's: all kept.
        other=00000000
        [ "$host" = $other ] && other=11111111
        : >"$T/o/.out.png.$host-$$-0"
        : >"$T/o/.out.png.$other-1-0"
        : >"$T/o/.out.png.mine"
        "$RT" -q "$T/f.txt" "$T/o/out.png" 2>"$T/err" || fail "the render after a kill" "$(cat "$T/err")"
        left=$(ls -A "$T/o" | LC_ALL=C sort | tr '\n' ' ')
        kept=$(printf '%s\n' ".out.png.$host-$$-0" ".out.png.$other-1-0" .out.png.mine out.png |
            LC_ALL=C sort | tr '\n' ' ')
        [ "$left" = "$kept" ] && pass ||
            fail "after a kill at ${how%:*}, the next render left: $left"
        cmp -s "$T/o/out.png" "$T/good.png" && pass || fail "the render after a kill differs"
    done
fi

finish
