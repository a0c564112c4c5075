#!/bin/sh
# report.sh: the course report (report/) still matches the code.
#
#  1. report/classes.dot, the class diagram drawn by hand, names only
#     classes, fields, functions and arrows the code has (report/classes.sh),
#     and the check sees one that is not there; docs/modules.dot, the module
#     graph, is what docs/modules.sh writes from the code's includes today,
#     and that check sees a planted include;
#  2. each drawing (classes.svg, activity.svg) has exactly the nodes of its
#     DOT source, and every module activity.dot names in brackets exists;
#  3. report.md holds 1,200 to 3,200 words of prose (tables and code aside:
#     about five pages with its figures, as the brief asks), every picture
#     it shows is under report/, and it names no file outside the
#     repository;
#  4. every picture of report/figures is the renderer's own: the same bytes
#     as docs/gallery/ (which tests/cli.sh renders again) or docs/trade-*.svg
#     (which make trade draws) or docs/bench-*.svg (make bench, make race);
#  5. every table and figure report.md quotes (report/quote.sh) is what its
#     page holds today, and a quote of one that is not there is refused;
#  6. report/report.pdf, once make report has built it, is at most 6 pages
#     of A4 (pdfinfo, from poppler-utils, when installed;
#     RAYTRACE_REPORT_PDF=required makes both the PDF and pdfinfo a must).
#
# Usage: sh tests/report.sh   (from the repository root)

SUITE=report
. "$(dirname "$0")/check.sh"

# 1. The class diagram names what the code has; the module graph is the code's.
sh report/classes.sh >"$T/out" 2>&1 && pass ||
    fail "report/classes.dot names what the code does not have" "$(cat "$T/out")"
sed 's/<br\/>depth</<br\/>height_of_tree</' report/classes.dot >"$T/planted-class.dot"
if sh report/classes.sh "$T/planted-class.dot" >"$T/out" 2>&1; then
    fail "report/classes.sh does not see a field the code lacks"
else
    grep -q "Bvh has no member height_of_tree" "$T/out" && pass ||
        fail "report/classes.sh misnames a field the code lacks" "$(cat "$T/out")"
fi
sh docs/modules.sh >"$T/modules.dot" 2>"$T/err"
if cmp -s "$T/modules.dot" docs/modules.dot; then
    pass
else
    fail "docs/modules.dot does not match the code: run make report (or sh docs/modules.sh >docs/modules.dot)" \
        "$(diff docs/modules.dot "$T/modules.dot" | head -20)"
fi
mkdir -p "$T/tree/tests" "$T/tree/docs"
cp -R src include "$T/tree/"
cp tests/lib.sh "$T/tree/tests/"
cp docs/modules.sh "$T/tree/docs/"
echo '#include "render/trace.h"' >>"$T/tree/src/base/grow.c" 2>/dev/null ||
    echo '#include "render/trace.h"' >"$T/tree/src/base/grow.c"
(cd "$T/tree" && sh docs/modules.sh >"$T/planted.dot" 2>/dev/null)
grep -q '"base/grow" -> "render/trace"' "$T/planted.dot" && pass ||
    fail "docs/modules.sh does not see an include planted in a copy of the tree"

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
[ "$words" -ge 1200 ] && [ "$words" -le 3200 ] && pass ||
    fail "report/report.md has $words words of prose, not 1,200 to 3,200"
grep -n '\.\./\|/work/\|/home/\|/tmp/' report/report.md >"$T/outside" && \
    fail "report/report.md names files outside the repository" "$(cat "$T/outside")" || pass
bad=""
for f in $(sed -n 's/.*!\[[^]]*\](\([^) ]*\).*/\1/p' report/report.md) \
    $(grep -o '\\includegraphics\(\[[^]]*\]\)\{0,1\}{[^}]*}' report/report.md | sed 's/.*{\(.*\)}/\1/'); do
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

# 5. The quoted tables are their pages' (make report brings them up to date).
if sh report/quote.sh >"$T/quoted.md" 2>"$T/err" && cmp -s "$T/quoted.md" report/report.md; then
    pass
else
    fail "report/report.md's quoted tables are not those of their pages: run make report" \
        "$(cat "$T/err"; diff report/report.md "$T/quoted.md" | head -20)"
fi
grep -c '^<!-- quote ' report/report.md >"$T/quotes"
[ "$(cat "$T/quotes")" -ge 1 ] && pass || fail "report/report.md quotes no table"
# refuses WHAT TEXT MESSAGE: report/quote.sh refuses a report of TEXT (a
# quote of WHAT that is not there), saying MESSAGE.
refuses() {
    printf '%s\n' "$2" >"$T/planted.md"
    if sh report/quote.sh "$T/planted.md" >"$T/out" 2>&1; then
        fail "report/quote.sh quotes $1 that is not there"
    else
        grep -qF "$3" "$T/out" && pass || fail "report/quote.sh misnames $1" "$(cat "$T/out")"
    fi
}
refuses "a table" '<!-- quote docs/benchmarks.md "## No such heading" columns 1 2 -->
<!-- end quote -->' 'no table after "## No such heading"'
refuses "a figure" 'a <!-- cell docs/trade.md "## Samples per pixel" "3" 5 -->x<!-- /cell --> b' \
    'no row "3" column 5'

# 6. The PDF: at most 6 pages of A4.
need=${RAYTRACE_REPORT_PDF:-}
if [ -f report/report.pdf ] && command -v pdfinfo >/dev/null 2>&1; then
    pdfinfo report/report.pdf >"$T/info" 2>&1
    pages=$(sed -n 's/^Pages: *//p' "$T/info")
    [ -n "$pages" ] && [ "$pages" -le 6 ] && pass ||
        fail "report/report.pdf has ${pages:-no} pages, more than 6" "$(cat "$T/info")"
    grep -q '^Page size:.*(A4)' "$T/info" && pass ||
        fail "report/report.pdf is not on A4 paper" "$(grep '^Page size' "$T/info")"
elif [ "$need" = required ]; then
    fail "report/report.pdf or pdfinfo (poppler-utils) is missing: run make report, install poppler-utils"
fi

finish
