#!/bin/sh
# install.sh: `make install` and `make uninstall` into a temporary DESTDIR,
# with a PREFIX of our own, and the manual pages rendered without warnings.
#
# Usage: sh tests/install.sh   (run from the repository root, after make)

SUITE=install
. "$(dirname "$0")/check.sh"


root="$T/root"
make -s install DESTDIR="$root" PREFIX=/opt/rt >"$T/log" 2>&1 && pass || fail "make install" "$(cat "$T/log")"
for f in bin/raytrace bin/raytrace-diff bin/raytrace-merge share/man/man1/raytrace.1 \
    share/man/man1/raytrace-diff.1 share/man/man1/raytrace-merge.1; do
    [ -f "$root/opt/rt/$f" ] && pass || fail "not installed: /opt/rt/$f"
done
[ -x "$root/opt/rt/bin/raytrace" ] && [ -x "$root/opt/rt/bin/raytrace-diff" ] && pass ||
    fail "installed commands are not executable"
"$root/opt/rt/bin/raytrace" --version | grep -q '^raytrace ' && pass || fail "installed raytrace does not run"
"$root/opt/rt/bin/raytrace-diff" --version | grep -q '^raytrace-diff ' && pass ||
    fail "installed raytrace-diff does not run"
"$root/opt/rt/bin/raytrace-merge" --version | grep -q '^raytrace-merge ' && pass ||
    fail "installed raytrace-merge does not run"
make -s uninstall DESTDIR="$root" PREFIX=/opt/rt >"$T/log" 2>&1 && pass || fail "make uninstall" "$(cat "$T/log")"
left=$(find "$root" -type f | head -5)
[ -z "$left" ] && pass || fail "uninstall left files" "$left"

# The manual pages format without a warning (when man is here; CI has it).
if command -v man >/dev/null 2>&1; then
    for page in docs/raytrace.1 docs/raytrace-diff.1 docs/raytrace-merge.1; do
        MANWIDTH=80 man --warnings -E UTF-8 -l "$page" >"$T/page" 2>"$T/warn"
        [ ! -s "$T/warn" ] && [ -s "$T/page" ] && pass || fail "man warnings for $page" "$(cat "$T/warn")"
    done
elif [ "${RAYTRACE_TEST_TOOLS:-}" = required ]; then
    fail "man is missing: the manual pages are not checked"
fi

finish
