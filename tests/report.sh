#!/bin/sh
# report.sh: the course report (report/) still matches the code.
#
#  1. report/classes.dot is what report/classes.sh writes from the code's
#     modules and includes today, and the check sees a planted include (a
#     copy of the tree with one more arrow gives another diagram);
#  2. each drawing (classes.svg, activity.svg) has exactly the nodes of its
#     DOT source, and every module activity.dot names in brackets exists;
#  3. report.md holds 2,500 to 5,000 words of prose (tables and code
#     aside), and every picture it shows is under report/;
#  4. every picture of report/figures is the renderer's own: the same bytes
#     as docs/gallery/ (which tests/cli.sh renders again) or docs/trade-*.svg
#     (which make trade draws) or docs/bench-*.svg (make bench, make race).
#
# Usage: sh tests/report.sh   (from the repository root)

SUITE=report
. "$(dirname "$0")/check.sh"

# 1. The class diagram is the code's.
sh report/classes.sh >"$T/classes.dot" 2>"$T/err"
if cmp -s "$T/classes.dot" report/classes.dot; then
    pass
else
    fail "report/classes.dot does not match the code: run sh report/classes.sh >report/classes.dot and make report" \
        "$(diff report/classes.dot "$T/classes.dot" | head -20)"
fi
mkdir -p "$T/tree/tests"
cp -R src include report "$T/tree/"
cp tests/lib.sh "$T/tree/tests/"
echo '#include "render/trace.h"' >>"$T/tree/src/base/grow.c" 2>/dev/null ||
    echo '#include "render/trace.h"' >"$T/tree/src/base/grow.c"
(cd "$T/tree" && sh report/classes.sh >"$T/planted.dot" 2>/dev/null)
grep -q '"base/grow" -> "render/trace"' "$T/planted.dot" && pass ||
    fail "report/classes.sh does not see an include planted in a copy of the tree"

# 2. The drawings have their sources' nodes.
# nodes DOT: the node names a DOT file declares (lines "NAME [...]" or
# "\"NAME\" [...]"), sorted.
nodes() {
    sed -n 's/^ *"\{0,1\}\([A-Za-z_][A-Za-z0-9_/]*\)"\{0,1\} \[.*/\1/p' "$1" |
        grep -v '^\(node\|edge\|graph\)$' | sort -u
}
# titles SVG: the node names Graphviz wrote (each node's <title>), sorted.
titles() {
    sed -n 's/.*<title>\([^<]*\)<\/title>.*/\1/p' "$1" | grep -v -- '&gt;' |
        grep -v '^\(classes\|activity\|cluster_.*\)$' | sed 's/&#45;/-/g' | sort -u
}
for d in classes activity; do
    nodes "report/$d.dot" >"$T/nodes"
    titles "report/$d.svg" >"$T/titles"
    if [ -s "$T/nodes" ] && cmp -s "$T/nodes" "$T/titles"; then
        pass
    else
        fail "report/$d.svg is not drawn from report/$d.dot: run make report" \
            "$(diff "$T/nodes" "$T/titles" | head -10)"
    fi
done
missing=""
for m in $(grep -o '\[[a-z]*/[a-z_*]*' report/activity.dot | tr -d '[' | tr -d '*' | sort -u); do
    found=
    for f in src/"$m"*.c include/"$m"*.h; do [ -f "$f" ] && found=yes; done
    [ -n "$found" ] || missing="$missing $m"
done
[ -z "$missing" ] && pass || fail "report/activity.dot names modules that do not exist:$missing"

# 3. The text: its length and its pictures.
words=$(awk '/^```/ { code = !code; next } !code && !/^\|/ && !/^!\[/' report/report.md | wc -w)
[ "$words" -ge 2500 ] && [ "$words" -le 5000 ] && pass ||
    fail "report/report.md has $words words of prose, not 2,500 to 5,000"
bad=""
for f in $(sed -n 's/.*!\[[^]]*\](\([^) ]*\).*/\1/p' report/report.md); do
    case $f in
    /* | *..* | http*) bad="$bad $f (not under report/)" ;;
    *) [ -f "report/$f" ] || bad="$bad $f (missing)" ;;
    esac
done
[ -z "$bad" ] && pass || fail "report/report.md shows pictures it cannot:$bad"

# 4. Its pictures are the renderer's.
bad=""
for f in report/figures/*; do
    name=${f##*/}
    case $name in
    trade-*.svg | bench-*.svg) ref=docs/$name ;;
    *.png) ref=docs/gallery/$name ;;
    *) bad="$bad $name (neither a render nor a trade plot)"; continue ;;
    esac
    cmp -s "$f" "$ref" || bad="$bad $name (not $ref)"
done
[ -z "$bad" ] && pass || fail "report/figures holds pictures that are not the renderer's:$bad"

finish
