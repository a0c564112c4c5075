#!/bin/sh
# classes.sh: checks the report's class diagram (report/classes.dot, drawn
# by hand) against the code, so that it cannot drift: each class (a node)
# must be a structure its header (the node's comment) declares with
# "typedef struct ... } NAME;", each field listed in its second box a
# member of that structure (a field "a, b, ..." names a and b), each
# function of its third box ("name()") declared in include/, and each
# solid arrow A -> B a member of A whose type is B. Prints what does not
# hold, one line each, and exits 1 if anything does not.
#
# Usage: sh report/classes.sh [DOT]   (from the repository root; DOT
# defaults to report/classes.dot)

dot=${1:-report/classes.dot}
LC_ALL=C
export LC_ALL
T=${TMPDIR:-/tmp}/classes-check.$$
mkdir -p "$T" || exit 2
trap 'rm -rf "$T"' EXIT

# The classes: "NAME HEADER" lines, then "NAME field F" and "NAME func F".
awk '
    /^ *[A-Za-z_][A-Za-z0-9_]* \[comment="/ {
        name = $1
        header = $0; sub(/.*comment="/, "", header); sub(/".*/, "", header)
        print name, "header", header
        n = split($0, cells, /<td[^>]*>/)
        for (i = 3; i <= n; i++) {
            cell = cells[i]; sub(/<\/td>.*/, "", cell)
            m = split(cell, items, /<br\/>/)
            for (j = 1; j <= m; j++) {
                item = items[j]
                gsub(/<[^>]*>/, "", item)
                if (item ~ /\(\)$/) { sub(/\(\)$/, "", item); print name, "func", item; continue }
                k = split(item, parts, /, */)
                for (q = 1; q <= k; q++)
                    if (parts[q] != "..." && parts[q] != "") print name, "field", parts[q]
            }
        }
    }' "$dot" >"$T/items"
# The solid arrows: "A B".
awk '/^ *[A-Za-z_][A-Za-z0-9_]* -> [A-Za-z_][A-Za-z0-9_]*/ && !/style=dashed/ {
        print $1, $3 }' "$dot" >"$T/edges"

faults=0
fault() {
    echo "$dot: $*"
    faults=$((faults + 1))
}

# body NAME HEADER: the lines of the structure NAME in HEADER, from its
# "typedef struct" to its "} NAME;".
body() {
    awk -v name="$1" '/^typedef struct/ { n = 0; inside = 1 }
        inside { line[++n] = $0 }
        inside && $0 ~ "^} *" name " *;" { for (i = 1; i <= n; i++) print line[i]; exit }
        inside && /^} *[A-Za-z_]/ { inside = 0 }' "$2"
}

[ -s "$T/items" ] || fault "no class found"
while read -r name kind value; do
    case $kind in
    header)
        header=$value
        if [ ! -f "$header" ]; then
            fault "$name: its header $header does not exist"
            : >"$T/body.$name"
            continue
        fi
        body "$name" "$header" >"$T/body.$name"
        [ -s "$T/body.$name" ] || fault "$name: $header declares no structure $name"
        ;;
    field)
        # A member: the name, then an array bound, a comma or a semicolon.
        grep -v '^ */\?\*' "$T/body.$name" | sed 's|/\*.*||' |
            grep -Eq "[ *]$value(\[[^]]*\])*[;,]" ||
            fault "$name has no member $value"
        ;;
    func)
        grep -rEq "(^|[ *])$value\(" include/ || fault "no function $value() is declared in include/"
        ;;
    esac
done <"$T/items"
while read -r from to; do
    [ -f "$T/body.$from" ] || { fault "$from -> $to: $from is not a class"; continue; }
    sed 's|/\*.*||' "$T/body.$from" | grep -Eq "(^|[^A-Za-z0-9_])$to([^A-Za-z0-9_]|$)" ||
        fault "$from -> $to: $from has no member of type $to"
done <"$T/edges"
[ "$faults" -eq 0 ]
