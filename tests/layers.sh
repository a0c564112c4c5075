#!/bin/sh
# layers.sh: the code's layering holds (docs/design.md, "Layers").
#
#  1. Each folder of src/ and include/ includes only headers of its own
#     folder and of the folders below it, in the order of LAYERS (bottom
#     first, in tests/lib.sh); every folder is one of them.
#  2. No modules include each other in a circle (a module is a .c file and
#     its header, src/F/NAME.c and include/F/NAME.h or src/F/NAME.h).
#  3. The check itself fails on a tree with a backward include or a circle
#     planted in a copy of this one.
#
# Usage: sh tests/layers.sh   (from the repository root)

SUITE=layers
. "$(dirname "$0")/check.sh"
. "$(dirname "$0")/lib.sh"


# rank FOLDER: its place in LAYERS from 0, or nothing when it is not one.
rank() { echo "$LAYERS" | tr ' ' '\n' | awk -v f="$1" '$0 == f { print NR - 1 }'; }

# check ROOT: prints each breach of rules 1 and 2 in the tree at ROOT;
# prints nothing when it holds.
check() {
    module_edges "$1" >"$T/edges"
    for d in "$1"/src/* "$1"/include/*; do
        [ -d "$d" ] && [ -z "$(rank "${d##*/}")" ] && echo "folder ${d#"$1"/} is not a layer of tests/layers.sh"
    done
    while read -r from to; do
        rf=$(rank "${from%/*}") rt=$(rank "${to%/*}")
        [ -n "$rf" ] && [ -n "$rt" ] && [ "$rt" -gt "$rf" ] &&
            echo "$from includes $to: ${to%/*} is above ${from%/*}"
    done <"$T/edges"
    tsort "$T/edges" >/dev/null 2>"$T/tsort" || sed 's/^tsort: //' "$T/tsort"
}

breach=$(check .)
[ -z "$breach" ] && pass || fail "the layering does not hold" "$breach"

# The check sees a planted backward include, and a planted circle of
# modules that keeps to the layers (two headers of one folder).
mkdir -p "$T/tree"
cp -R src include "$T/tree/"
printf '#include "render/trace.h"\n' >>"$T/tree/src/geometry/sphere.c"
check "$T/tree" | grep -q 'geometry/sphere includes render/trace' && pass ||
    fail "a backward include goes unseen"
rm -rf "$T/tree" && mkdir -p "$T/tree" && cp -R src include "$T/tree/"
printf '#include "geometry/plane.h"\n' >>"$T/tree/include/geometry/ray.h"
printf '#include "geometry/ray.h"\n' >>"$T/tree/src/geometry/plane.c"
check "$T/tree" | grep -q 'loop' && pass || fail "a circle of modules goes unseen"

finish
