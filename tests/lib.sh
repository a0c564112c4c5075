# lib.sh: shell helpers shared by the measurement and test scripts
# (tests/bench/*.sh, tests/memcheck.sh, tests/layers.sh) and the report's
# class diagram (report/classes.sh); sourced, not run.

# The layers of src/ and include/, bottom first (docs/design.md).
LAYERS="base math image geometry accel scene scenefile render cli"

# now: nanoseconds since the epoch.
now() { date +%s%N; }

# median: the median of the numbers on standard input, one a line.
median() { sort -n | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

# time_renders NAME OPTIONS...: runs "$RT" -v OPTIONS "$DIR/NAME.ppm" $RUNS
# times (RT, DIR and RUNS the caller's), the last run's report kept in
# $DIR/NAME.log; prints the median wall time in seconds, or fails with the
# first render that fails.
time_renders() {
    name=$1
    shift
    : >"$DIR/times"
    i=0
    while [ $i -lt "$RUNS" ]; do
        start=$(now)
        "$RT" -v "$@" "$DIR/$name.ppm" 2>"$DIR/$name.log" || { cat "$DIR/$name.log" >&2; return 1; }
        end=$(now)
        echo $(((end - start) / 1000000)) >>"$DIR/times"
        i=$((i + 1))
    done
    echo "$(median <"$DIR/times") / 1000" | bc -l
}

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

# seconds MS: MS milliseconds in seconds, two decimals.
seconds() { printf '%.2f' "$(echo "$1 / 1000" | bc -l)"; }

# module_edges ROOT: "FROM TO" once for each quoted include between two
# modules of the tree at ROOT (a module is FOLDER/NAME: src/F/NAME.c with
# include/F/NAME.h or src/F/NAME.h; a bare "NAME.h" is a header beside the
# file, in its own folder), sorted. One awk reads every file.
module_edges() {
    (cd "$1" && find src include -name '*.[ch]' | sort | xargs awk '
        FNR == 1 { n = split(FILENAME, p, "/"); name = p[3]; sub(/\.[ch]$/, "", name); from = p[2] "/" name }
        /^#[ \t]*include[ \t]*"/ {
            inc = $0; sub(/^#[ \t]*include[ \t]*"/, "", inc); sub(/".*/, "", inc)
            to = inc ~ /\// ? inc : p[2] "/" inc; sub(/\.h$/, "", to)
            if (from != to) print from, to
        }' | sort -u)
}
