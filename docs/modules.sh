#!/bin/sh
# modules.sh: writes the module graph (Graphviz DOT) from the code itself,
# on standard output (docs/design.md shows it; the report's class diagram
# is report/classes.dot): one box per module (a .c file and its header,
# src/LAYER/NAME.c and include/LAYER/NAME.h or src/LAYER/NAME.h), grouped by
# layer, listing the structures its header declares (its main types), and
# an arrow from each module to each module it uses (includes), with the
# arrows another path of arrows already implies left out (the transitive
# reduction), so that the picture shows the direct dependencies only.
#
# Usage: sh docs/modules.sh >docs/modules.dot   (from the repository root)
# tests/report.sh fails when docs/modules.dot is not what this writes.

# LAYERS and module_edges.
. "$(dirname "$0")/../tests/lib.sh"
# One order on every machine, whatever its locale.
LC_ALL=C
export LC_ALL

# Every module "LAYER/NAME", once.
modules() {
    find src include -name '*.[ch]' | sed 's|^[a-z]*/\([a-z]*\)/\([A-Za-z0-9_]*\)\.[ch]$|\1/\2|' | sort -u
}

# The structures a module's headers declare: "MODULE TYPE" lines, in the
# order of the header.
types() {
    awk 'FNR == 1 { n = split(FILENAME, p, "/"); m = p[2] "/" p[3]; sub(/\.h$/, "", m) }
        /^typedef struct[^;]*$/ { s = 1; next }
        s && /^} *[A-Za-z_][A-Za-z0-9_]* *;/ { t = $2; sub(/;.*/, "", t); print m, t; s = 0 }' \
        include/*/*.h src/*/*.h
}

T=${TMPDIR:-/tmp}/modules.$$
mkdir -p "$T" || exit 2
trap 'rm -rf "$T"' EXIT
modules >"$T/modules"
module_edges . >"$T/edges"
types >"$T/types"

echo "// The modules of raytrace, their structures and who uses whom: written by"
echo "// docs/modules.sh from the code's includes (do not edit; rerun it)."
echo "digraph modules {"
echo "    rankdir=RL; nodesep=0.12; ranksep=0.3;"
echo "    node [shape=plaintext, fontname=\"Helvetica\", fontsize=9];"
echo "    edge [color=\"#555555\", arrowsize=0.5];"
for layer in $LAYERS; do
    echo "    subgraph cluster_$layer {"
    echo "        label=\"$layer\"; fontname=\"Helvetica-Bold\"; fontsize=11; style=rounded; color=\"#888888\";"
    grep "^$layer/" "$T/modules" | while read -r m; do
        rows=$(awk -v m="$m" '$1 == m { printf "<TR><TD ALIGN=\"LEFT\">%s</TD></TR>", $2 }' "$T/types")
        echo "        \"$m\" [label=<<TABLE BORDER=\"1\" CELLBORDER=\"0\" CELLSPACING=\"0\" BGCOLOR=\"#f4f4f4\"><TR><TD><B>${m#*/}</B></TD></TR>$rows</TABLE>>];"
    done
    echo "    }"
done
# The transitive reduction: an arrow A -> B stays unless some other arrow
# A -> C leads on to B.
awk 'NR == FNR { id[$1] = ++n; name[n] = $1; next }
    { a = id[$1]; b = id[$2]; if (a && b) { e[a, b] = 1; r[a, b] = 1 } }
    END {
        for (k = 1; k <= n; k++) for (i = 1; i <= n; i++) if (r[i, k])
            for (j = 1; j <= n; j++) if (r[k, j]) r[i, j] = 1
        for (i = 1; i <= n; i++) for (j = 1; j <= n; j++) if (e[i, j]) {
            keep = 1
            for (k = 1; k <= n && keep; k++) if (k != i && k != j && e[i, k] && r[k, j]) keep = 0
            if (keep) printf "    \"%s\" -> \"%s\";\n", name[i], name[j]
        }
    }' "$T/modules" "$T/edges"
echo "}"
