# lib.sh: shell helpers shared by the measurement and test scripts
# (tests/bench/bench.sh, tests/bench/trade.sh, tests/memcheck.sh); sourced,
# not run.

# now: nanoseconds since the epoch.
now() { date +%s%N; }

# median: the median of the numbers on standard input, one a line.
median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# resize SCENE WIDTH: SCENE (a file, or /dev/stdin) with its image WIDTH
# pixels wide, on standard output: a keyword scene's camera width (its
# height in proportion), a course scene's resolution (its fifth record).
# The format is told as raytrace tells it: by the first record's first word.
resize() {
    awk -v w="$2" '{ line = $0; sub(/#.*/, "", line) }
        line !~ /[^ \t]/ { print; next }
        ++n == 1 { kw = $1 ~ /^[A-Za-z]/ && $1 !~ /^(nan|inf)/ }
        kw && $1 == "camera" { $10 = int($10 * w / $9); $9 = w }
        !kw && n == 5 { print w; next }
        { print }' "$1"
}
