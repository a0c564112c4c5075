#!/bin/sh
# layers.sh: the code's layering holds (docs/design.md, "Layers").
#
#  1. Each folder of src/ and include/ includes only headers of its own
#     folder and of the folders below it, in the order of LAYERS (bottom
#     first, in tests/lib.sh); every folder is one of them.
#  2. No modules include each other in a circle (a module is a .c file and
#     its header, src/F/NAME.c and include/F/NAME.h or src/F/NAME.h).
#  3. No source files call each other in a circle: from the object files
#     of src/ (in $BUILD, default build), file A calls file B when A uses
#     a function or object that B defines.
#  4. The house's sizes: no function in src/ over 100 lines (help texts,
#     functions named *_help, aside), no source file over 700 lines,
#     docs/design.md at most 450 lines.
#  5. Each tests/test_NAME.c is named after a module, src/*/NAME.c (or
#     NAME_ASPECT for one side of it, or NAME for a module cut into
#     src/*/NAME_*.c files), and README's table of tests names it.
#  6. The checks themselves fail on a tree with a backward include or a
#     circle planted in a copy of this one, and on two objects that call
#     each other.
#
# Usage: sh tests/layers.sh   (from the repository root, after make)

SUITE=layers
. "$(dirname "$0")/check.sh"
. "$(dirname "$0")/lib.sh"


# check ROOT: prints each breach of rules 1 and 2 in the tree at ROOT;
# prints nothing when it holds.
check() {
    module_edges "$1" >"$T/edges"
    for d in "$1"/src/* "$1"/include/*; do
        [ -d "$d" ] || continue
        case " $LAYERS " in *" ${d##*/} "*) ;; *) echo "folder ${d#"$1"/} is not a layer of tests/layers.sh" ;; esac
    done
    awk -v layers="$LAYERS" 'BEGIN { n = split(layers, l, " "); for (i = 1; i <= n; i++) rank[l[i]] = i }
        { f = $1; t = $2; sub(/\/.*/, "", f); sub(/\/.*/, "", t)
          if ((f in rank) && (t in rank) && rank[t] > rank[f]) print $1 " includes " $2 ": " t " is above " f }' "$T/edges"
    tsort "$T/edges" >/dev/null 2>"$T/tsort" || sed 's/^tsort: //' "$T/tsort"
}

# call_circles OBJECT...: prints the circles of calls between the object
# files (A calls B when A uses a symbol B defines); nothing when none.
call_circles() {
    # nm -A: each line "FILE:[VALUE] TYPE SYMBOL"; one nm for all files.
    split='{ i = index($0, ":"); n = split(substr($0, i + 1), w, " "); f = substr($0, 1, i - 1) }'
    nm -A -g --defined-only "$@" | awk "$split"' n == 3 { print w[3], f }' | sort >"$T/defined"
    nm -A -u "$@" | awk "$split"' n >= 2 { print w[n], f }' | sort >"$T/used"
    join "$T/used" "$T/defined" | awk '$2 != $3 { print $2, $3 }' | sort -u >"$T/calls"
    tsort "$T/calls" >/dev/null 2>"$T/tsort" || sed 's/^tsort: //' "$T/tsort"
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

objects=$(for d in src/*/; do d=${d%/}; ls "${BUILD:-build}/${d#src/}"/*.o 2>/dev/null; done)
if [ -z "$objects" ]; then
    fail "no object files in ${BUILD:-build} (run make first)"
else
    # shellcheck disable=SC2086 # one word per file
    circles=$(call_circles $objects)
    [ -z "$circles" ] && pass || fail "source files call each other in a circle" "$circles"
fi
# long_functions FILE...: "FILE:LINE NAME LENGTH" for each function over
# 100 lines (a definition starts at column 0 and ends at its closing
# brace at column 0).
long_functions() {
    awk 'FNR == 1 { start = 0 }
         /^[A-Za-z].*\(/ && !/;[ \t]*$/ && !start { start = FNR; name = $0 }
         /^}/ && start { if (FNR - start + 1 > 100 && name !~ /_help\(/)
                             print FILENAME ":" start " " FNR - start + 1 " lines: " name
                         start = 0 }' "$@"
}

long=$(long_functions src/*/*.c)
[ -z "$long" ] && pass || fail "functions over 100 lines" "$long"
big=$(wc -l src/*/*.c src/*/*.h include/*/*.h | awk '$2 != "total" && $1 > 700')
[ -z "$big" ] && pass || fail "source files over 700 lines" "$big"
[ "$(wc -l <docs/design.md)" -le 450 ] && pass || fail "docs/design.md is over 450 lines" "$(wc -l <docs/design.md)"
printf 'static int f(void)\n{\n' >"$T/long.c"
i=0; while [ $i -lt 100 ]; do echo '    ;' >>"$T/long.c"; i=$((i + 1)); done
printf '    return 0;\n}\n' >>"$T/long.c"
long_functions "$T/long.c" | grep -q 'long.c:1 ' && pass || fail "a function of 103 lines goes unseen"

for t in tests/test_*.c; do
    name=${t#tests/test_}
    name=${name%.c}
    found=
    for m in src/*/*.c; do
        m=${m##*/}
        m=${m%.c}
        case $name in "$m" | "$m"_*) found=1 ;; esac
        case $m in "$name"_*) found=1 ;; esac
    done
    [ -n "$found" ] || fail "$t is named after no module of src/"
    grep -q "\`${t#tests/}\`" README.md || fail "README's table of tests does not name ${t#tests/}"
done
pass

printf 'int b(void);\nint a(int n) { return n ? b() : 0; }\n' >"$T/a.c"
printf 'int a(int);\nint b(void) { return a(0); }\n' >"$T/b.c"
${CC:-cc} -c "$T/a.c" -o "$T/a.o" && ${CC:-cc} -c "$T/b.c" -o "$T/b.o" &&
    call_circles "$T/a.o" "$T/b.o" | grep -q 'loop' && pass || fail "a circle of calls goes unseen"

finish
