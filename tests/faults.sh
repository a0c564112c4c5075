#!/bin/sh
# faults.sh: what a render leaves behind when it is killed, or raced
# (`make test`).
#
#  1. SIGKILL at 50 moments spread over a render's whole life (reading
#     200,000 spheres, building their hierarchy, rendering, writing): the
#     output's folder must hold what it held before (the old output) or
#     the complete new image, and nothing else: no temporary file.
#  2. Two renders writing the same output at once, ten times: the output
#     is one of the two complete images, never a mix, and nothing is left
#     beside it.
#
# Usage: sh tests/faults.sh RAYTRACE   (from the repository root)

RT=$1
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
mkdir "$T/o"
survived=0 finished=0
i=0
while [ $i -lt 50 ]; do
    rm -rf "$T/o"
    mkdir "$T/o"
    printf 'old output\n' >"$T/o/out.ppm"
    delay=$(awk -v i=$i -v t="$took" 'BEGIN { printf "%.3f", i * t * 1.2 / 50 / 1000 }')
    "$RT" -q "$T/field.txt" "$T/o/out.ppm" 2>/dev/null &
    pid=$!
    sleep "$delay"
    kill -9 $pid 2>/dev/null
    wait $pid 2>/dev/null
    left=$(ls -A "$T/o")
    if [ "$left" != out.ppm ]; then
        fail "SIGKILL after ${delay} s left: $(echo $left)"
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
echo "faults: SIGKILL at 50 moments of a ${took} ms render: $survived left the old output, $finished the new one, nothing else"

# --- 2. two renders writing the same output at once ---
printf '0 0 -5\n-1 1 -4\n1 1 -4\n-1 -1 -4\n300\n200 20 20\n5 5 -5 255 255 255\nsphere: 0 0 0 1 20 20 200 0\n' \
    >"$T/red.txt"
"$RT" -q "$T/red.txt" "$T/red.ppm"
sed 's/^400$/300/' "$T/field.txt" | head -n 40007 >"$T/small.txt"
"$RT" -q "$T/small.txt" "$T/small.ppm"
i=0
while [ $i -lt 10 ]; do
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

finish
