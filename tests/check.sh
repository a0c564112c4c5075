# check.sh: the shell tests' harness (tests/*.sh); sourced, not run, after
# setting SUITE to the suite's name.
#
# It makes the scratch folder $T (removed on exit, made writable first so
# that tests may take permissions away), and gives pass, fail NAME
# [DETAILS], and finish, which prints "SUITE: N passed, N failed" and
# returns non-zero when a check failed; full, which says whether the suite
# runs in full (make check) or as its quick sample (make test, which sets
# RAYTRACE_TEST_LEVEL=quick); and the expect_* checks of a command.

T=$(mktemp -d "${TMPDIR:-/tmp}/raytrace-$SUITE.XXXXXX") || exit 2
trap 'chmod -R u+rwx "$T" 2>/dev/null; rm -rf "$T"' EXIT
passed=0
failed=0

pass() { passed=$((passed + 1)); }
# fail NAME [DETAILS]: counts a failure and prints NAME, then DETAILS
# indented: at most 40 lines, and never binary bytes (a file's picture
# printed by mistake): those are shown as their size and first bytes in hex.
fail() {
    failed=$((failed + 1))
    echo "FAIL $1" >&2
    [ -n "$2" ] || return 0
    if printf '%s' "$2" | LC_ALL=C grep -q '[^[:print:][:space:]]'; then
        printf '    (%s bytes of binary data; the first in hex:)\n' "$(printf '%s' "$2" | wc -c)" >&2
        printf '%s' "$2" | od -A n -t x1 -N 32 | sed 's/^/    /' >&2
    else
        printf '%s\n' "$2" | head -n 40 | sed 's/^/    /' >&2
    fi
}

# describe FILE: FILE for a failure's details: its text, or when it holds
# binary bytes (a picture), its size and first bytes in hex.
describe() {
    if [ ! -f "$1" ]; then
        echo "$1: no such file"
    elif LC_ALL=C grep -q '[^[:print:][:space:]]' "$1"; then
        echo "$1: $(wc -c <"$1") bytes of binary data, the first in hex:"
        od -A n -t x1 -N 32 "$1"
    else
        head -n 40 "$1"
    fi
}

finish() {
    echo "$SUITE: $passed passed, $failed failed"
    [ "$failed" -eq 0 ]
}

full() { [ "${RAYTRACE_TEST_LEVEL:-full}" != quick ]; }

# expect_exit NAME CODE COMMAND...: runs COMMAND, keeps its output in $T/out
# and $T/err, and checks its exit status.
expect_exit() {
    name=$1 code=$2
    shift 2
    "$@" >"$T/out" 2>"$T/err"
    got=$?
    if [ "$got" = "$code" ]; then pass; else fail "$name: exit $got, expected $code" "$(describe "$T/err")"; fi
}

# expect_grep NAME PATTERN FILE: FILE has a line matching PATTERN (fixed string).
expect_grep() {
    if grep -qF -- "$2" "$3"; then pass; else fail "$1: no '$2' in $3" "$(describe "$3")"; fi
}

# expect_line NAME N TEXT FILE: line N of FILE is exactly TEXT.
expect_line() {
    got=$(sed -n "$2p" "$4")
    if [ "$got" = "$3" ]; then pass; else fail "$1: line $2 is '$got', expected '$3'"; fi
}

# expect_clean NAME DIR: no temporary file left in DIR.
expect_clean() {
    if ls -A "$2" | grep -q '^\..*\.[A-Za-z0-9]\{6\}$'; then fail "$1: temporary file left" "$(ls -A "$2")"; else pass; fi
}

# awaits PID FILE TEXT: waits until FILE holds a line with TEXT (a fixed
# string), polling; returns non-zero when process PID ends first or 300 s
# pass. The sign a test waits for, never a fixed sleep.
awaits() {
    tries=0
    until grep -qF -- "$3" "$2" 2>/dev/null; do
        kill -0 "$1" 2>/dev/null || return 1
        [ $tries -lt 6000 ] || return 1
        sleep 0.05
        tries=$((tries + 1))
    done
}

# $DEFAULT_INT COMMAND...: runs COMMAND with SIGINT's default disposition,
# even as a background job of sh (which starts with SIGINT ignored); as a
# simple command's first words, so that $! is COMMAND's process.
if env --default-signal=INT true 2>/dev/null; then
    DEFAULT_INT="env --default-signal=INT"
else
    DEFAULT_INT="perl -e \$SIG{INT}='DEFAULT';exec(@ARGV)or(exit(127))"
fi
