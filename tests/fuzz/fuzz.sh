#!/bin/sh
# fuzz.sh: runs each libFuzzer target for FUZZ_TIME seconds (`make fuzz`).
#
# Usage: sh tests/fuzz/fuzz.sh BUILD-DIR [TARGET...]
# Each target starts from its corpus (tests/fuzz/corpus/T) and the inputs
# that once crashed it (tests/fuzz/regress/T); what it learns is kept in
# BUILD-DIR/fuzz/corpus/T. It runs in scenes/ so that scene inputs can
# name the example textures and meshes. A crash leaves its input in
# BUILD-DIR/fuzz/crash-T-* and makes this script fail: add that file to
# tests/fuzz/regress/T once the fault is mended. (Inputs slower than 10 s
# are kept too, as crash-T-slow-unit-*, but do not fail it.)
# Environment: FUZZ_TIME (seconds a target, default 60). Each target's
# totals (executions, coverage, features, corpus, crashes) are added as a
# row to BUILD-DIR/fuzz/totals.md (`make fuzz-long` runs 30 minutes each).

BUILD=$1
shift
TIME=${FUZZ_TIME:-60}
TOP=$(pwd)
status=0
TARGETS=${*:-course keyword mpl obj ppm picture jpeg tile}
for t in $TARGETS; do
    mkdir -p "$BUILD/fuzz/corpus/$t" "tests/fuzz/regress/$t"
    echo "fuzz: $t for ${TIME} s"
    (cd scenes && "$TOP/$BUILD/fuzz/fuzz_$t" -max_total_time="$TIME" -timeout=60 \
        -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$TOP/$BUILD/fuzz/crash-$t-" "$TOP/$BUILD/fuzz/corpus/$t" \
        "$TOP/tests/fuzz/corpus/$t" "$TOP/tests/fuzz/regress/$t") \
        >"$BUILD/fuzz/$t.log" 2>&1 || status=1
    grep -E '^stat::number_of_executed_units|^#[0-9]+.*DONE|ERROR|SUMMARY' "$BUILD/fuzz/$t.log" | tail -3
    # A row of the campaign's totals: executions, coverage, corpus, crashes.
    awk -v t="$t" -v secs="$TIME" -v crashes="$(ls "$BUILD"/fuzz/crash-"$t"-* 2>/dev/null |
        grep -cv -- '-slow-unit-')" '
        /^stat::number_of_executed_units/ { runs = $2 }
        / cov: / { for (i = 1; i <= NF; i++) { if ($i == "cov:") cov = $(i + 1)
                                                if ($i == "ft:") ft = $(i + 1)
                                                if ($i == "corp:") corp = $(i + 1) } }
        END { printf "| %s | %d s | %s | %s | %s | %s | %s |\n", t, secs, runs, cov, ft,
              corp, crashes }' "$BUILD/fuzz/$t.log" >>"$BUILD/fuzz/totals.md"
done
echo "fuzz: totals in $BUILD/fuzz/totals.md (target, time, executions, coverage, features, corpus, crashes)"
# libFuzzer also keeps slow inputs (crash-T-slow-unit-*): they are not faults.
found=$(ls "$BUILD"/fuzz/crash-* 2>/dev/null | grep -v -- '-slow-unit-')
if [ -n "$found" ]; then
    echo "fuzz: crashes found:" $found >&2
    status=1
fi
exit $status
