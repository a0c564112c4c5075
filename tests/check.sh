# check.sh: the shell tests' harness (tests/cli.sh, hostile.sh, install.sh,
# layers.sh); sourced, not run, after setting SUITE to the suite's name.
#
# It makes the scratch folder $T (removed on exit, made writable first so
# that tests may take permissions away), and gives pass, fail NAME
# [DETAILS], and finish, which prints "SUITE: N passed, N failed" and
# returns non-zero when a check failed.

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
