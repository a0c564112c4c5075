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
fail() { failed=$((failed + 1)); echo "FAIL $1" >&2; [ -n "$2" ] && printf '%s\n' "$2" | sed 's/^/    /' >&2; }

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
    if [ "$got" = "$code" ]; then pass; else fail "$name: exit $got, expected $code" "$(cat "$T/err")"; fi
}

# expect_grep NAME PATTERN FILE: FILE has a line matching PATTERN (fixed string).
expect_grep() {
    if grep -qF -- "$2" "$3"; then pass; else fail "$1: no '$2' in $3" "$(cat "$3")"; fi
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
