#!/bin/sh
# tiles.sh: raytrace --tile K/N and raytrace-merge (`make test`).
#
#  1. Merged tiles are the whole render, byte for byte: seven scenes (with
#     anti-aliasing, depth of field, glass, textures, ambient occlusion and
#     global illumination), 1 to 16 tiles and, on small pictures, as many
#     as the picture has rows, both layouts, PPM and PNG tiles, merged to PPM, PNG and JPEG.
#  2. Bad sets of tiles are refused with exit 1, a message naming the tile
#     and what is wrong, and OUT as it was: missing, repeated, overlapping,
#     from another render (options, scene, a texture changed), truncated,
#     not a tile at all.
#  3. The recipes of docs/distributed.md: make -j on a generated makefile,
#     GNU parallel on this machine and through --sshlogin (the local login
#     ':'), and a Slurm job array on a single-node Slurm started here
#     (slurm-wlm and munge); each recipe's picture is the single render's.
#     A recipe whose tools are missing is skipped, saying so, unless
#     RAYTRACE_TEST_TOOLS=required (CI), where that fails; Slurm installed
#     on a machine that cannot run its daemons is skipped, saying why.
#
# The quick suite (make test, RAYTRACE_TEST_LEVEL=quick) merges two scenes
# cut 1, 3 and 16 ways and runs the make recipe only; make check runs all.
#
# Usage: sh tests/tiles.sh RAYTRACE RAYTRACE-MERGE   (from the repository root)

RT=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
MERGE=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
SUITE=tiles
. "$(dirname "$0")/check.sh"
TOP=$(pwd)

# tiles NAME N LAYOUT EXT OPTS...: renders the N tiles of scene NAME into
# $T/NAME-k.EXT with the given options.
tiles() {
    name=$1 n=$2 layout=$3 ext=$4
    shift 4
    k=1
    rm -f "$T/$name"-*."$ext"
    while [ $k -le "$n" ]; do
        # shellcheck disable=SC2086
        "$RT" -q "$@" --tile "$k/$n" --tile-layout "$layout" "scenes/$name.txt" \
            "$T/$name-$k.$ext" || fail "$name: tile $k/$n $layout $*"
        k=$((k + 1))
    done
}

# --- 1. the merged picture is the whole render ---
. "$(dirname "$0")/lib.sh"
resize scenes/course.txt 48 >scenes/.tiles-course.txt
# glass.txt: at its own size in full, at 160 pixels wide in the quick suite.
G=glass
full || { G=.tiles-glass && resize scenes/glass.txt 160 >scenes/.tiles-glass.txt; }
if full; then
    cases='course;.tiles-course;glass;focus --spp 4;textures;materials;ocaml-test;mpl --size 48x40;indirect --ao 3 --gi 2 --gi-bounces 2 --spp 2'
    counts="1 2 3 7 16"
else
    cases=".tiles-course;$G"
    counts="1 3 16"
fi
for case in $(printf '%s' "$cases" | tr ' ;' '@ '); do
    case=$(printf '%s' "$case" | tr '@' ' ')
    # shellcheck disable=SC2086
    set -- $case
    name=$1
    shift
    # Small pictures keep the suite quick: every scene at its own size but
    # indirect.txt, whose gathering is costly, at 40 x 40.
    if [ "$name" = indirect ]; then
        sed 's/^c Camera \(.*\) 400 400$/c Camera \1 40 40/' scenes/indirect.txt >scenes/.tiles-indirect.txt
        name=.tiles-indirect
    fi
    "$RT" -q "$@" "scenes/$name.txt" "$T/whole.ppm" || fail "$name: whole render"
    height=$(sed -n 2p "$T/whole.ppm" | cut -d' ' -f2)
    opts=$*
    # As many tiles as rows (one row each) where that is quick.
    all=
    full && [ "$height" -le 64 ] && all=$height
    for n in $counts $all; do
        for layout in rows bands; do
            # shellcheck disable=SC2086
            tiles "$name" "$n" "$layout" ppm $opts
            # In any order: the last tile first.
            set -- "$T/$name-$n.ppm"
            k=1
            while [ $k -lt "$n" ]; do set -- "$@" "$T/$name-$k.ppm"; k=$((k + 1)); done
            "$MERGE" -q "$T/merged.ppm" "$@" 2>"$T/err" && cmp -s "$T/merged.ppm" "$T/whole.ppm" && pass ||
                fail "$name $opts: $n tiles ($layout) merged differ from the whole" "$(cat "$T/err")"
        done
    done
    rm -f scenes/.tiles-indirect.txt
done
rm -f scenes/.tiles-course.txt
# PNG tiles, and PNG and JPEG out: the whole render's bytes in those formats.
tiles $G 5 rows png
"$RT" -q scenes/$G.txt "$T/whole.png"
"$MERGE" -q "$T/merged.png" "$T"/$G-*.png && cmp -s "$T/merged.png" "$T/whole.png" && pass ||
    fail "PNG tiles merged to PNG differ from the whole PNG"
"$RT" -q scenes/$G.txt "$T/whole.jpg"
"$MERGE" -q "$T/merged.jpg" "$T"/$G-*.png && cmp -s "$T/merged.jpg" "$T/whole.jpg" && pass ||
    fail "PNG tiles merged to JPEG differ from the whole JPEG"
# PFM tiles (linear colours, the record after the pixels) merge to the
# whole render's PFM; 8-bit and linear tiles do not mix.
tiles $G 3 bands pfm
"$RT" -q scenes/$G.txt "$T/whole.pfm"
"$MERGE" -q "$T/merged.pfm" "$T"/$G-*.pfm && cmp -s "$T/merged.pfm" "$T/whole.pfm" && pass ||
    fail "PFM tiles merged to PFM differ from the whole PFM"
"$MERGE" -q "$T/merged.ppm" "$T"/$G-*.pfm 2>"$T/err"
[ $? = 1 ] && grep -q "the tiles are PFM (linear colours): write a PFM" "$T/err" && pass ||
    fail "PFM tiles merged to PPM" "$(cat "$T/err")"
"$MERGE" -q "$T/merged.pfm" "$T/$G-1.pfm" "$T/$G-2.png" 2>"$T/err"
[ $? = 1 ] && grep -q "a PPM or PNG tile among PFM ones" "$T/err" && pass ||
    fail "PFM and PNG tiles mixed" "$(cat "$T/err")"
rm -f scenes/.tiles-glass.txt
# Each tile is a picture of its rows: its first row is the whole's row K - 1.
"$RT" -q --tile 2/4 scenes/course.txt "$T/t.ppm"
sed -n 2p "$T/t.ppm" | grep -q '^# raytrace-tile 2/4 layout rows first 1 step 4 count 100 of 400x400 fingerprint [0-9a-f]\{16\}$' &&
    pass || fail "tile record" "$(sed -n 2p "$T/t.ppm")"

# --- 2. bad sets of tiles: exit 1, a message naming the tile, OUT untouched ---
# refused NAME MESSAGE TILE...: raytrace-merge must refuse the tiles with
# MESSAGE as the start of its first line, leaving OUT as it was.
refused() {
    what=$1 want=$2
    shift 2
    printf 'keep me\n' >"$T/out.ppm"
    "$MERGE" "$T/out.ppm" "$@" 2>"$T/err"
    got=$?
    line=$(head -n 1 "$T/err")
    if [ $got != 1 ]; then
        fail "$what: exit $got, expected 1" "$line"
    elif [ "${line#"$want"}" = "$line" ]; then
        fail "$what: wrong message" "expected: $want...
got:      $line"
    elif [ "$(cat "$T/out.ppm")" != "keep me" ] || [ "$(ls "$T" | grep -c '^\.out\.ppm')" != 0 ]; then
        fail "$what: OUT was changed, or debris left beside it"
    else
        pass
    fi
}
tiles course 4 rows ppm
c=$T/course
# Its command line, read by the shared parser (cli/args.c): exit 2 and
# one clear line.
"$MERGE" --jpeg-quality 0 "$T/x.jpg" "$c-1.ppm" 2>"$T/err"
[ $? = 2 ] && grep -qF "raytrace-merge: option '--jpeg-quality' takes a whole number from 1 to 100, found '0'" "$T/err" &&
    pass || fail "--jpeg-quality 0 is not refused clearly" "$(cat "$T/err")"
"$MERGE" "$T/x.ppm" 2>"$T/err"
[ $? = 2 ] && grep -qF "raytrace-merge: missing TILE" "$T/err" && pass ||
    fail "a missing TILE is not said" "$(cat "$T/err")"
refused "missing" "raytrace-merge: $c-1.ppm: error: 2 tiles of this render are missing: 2/4, 4/4" \
    "$c-1.ppm" "$c-3.ppm"
refused "repeated" "raytrace-merge: $c-3.ppm: error: tile 3/4 again: $c-3.ppm is that tile" \
    "$c-1.ppm" "$c-3.ppm" "$c-3.ppm"
"$RT" -q --tile 1/4 --tile-layout bands scenes/course.txt "$T/band-1.ppm"
refused "overlapping" "raytrace-merge: $T/band-1.ppm: error: overlaps $c-2.ppm: both hold row 1" \
    "$c-2.ppm" "$T/band-1.ppm"
"$RT" -q --tile 2/4 -d 3 scenes/course.txt "$T/depth-2.ppm"
refused "other options" "raytrace-merge: $T/depth-2.ppm: error: a tile of another render than $c-1.ppm" \
    "$c-1.ppm" "$T/depth-2.ppm" "$c-3.ppm" "$c-4.ppm"
sed 's/^80 80 100/80 80 101/' scenes/course.txt >"$T/other.txt"
"$RT" -q --tile 2/4 "$T/other.txt" "$T/other-2.ppm"
refused "another scene" "raytrace-merge: $T/other-2.ppm: error: a tile of another render than $c-1.ppm" \
    "$c-1.ppm" "$T/other-2.ppm" "$c-3.ppm" "$c-4.ppm"
"$RT" -q --tile 2/8 scenes/course.txt "$T/eighth-2.ppm"
refused "another cut" "raytrace-merge: $T/eighth-2.ppm: error: tile 2 of 8, but $c-1.ppm is one of 4" \
    "$c-1.ppm" "$T/eighth-2.ppm"
head -c 5000 "$c-2.ppm" >"$T/short-2.ppm"
refused "truncated" "raytrace-merge: $T/short-2.ppm: error: truncated" \
    "$c-1.ppm" "$T/short-2.ppm" "$c-3.ppm" "$c-4.ppm"
refused "not a tile" "raytrace-merge: tests/ref/course.ppm: error: not a tile of raytrace --tile" \
    "$c-1.ppm" tests/ref/course.ppm
refused "no such tile" "raytrace-merge: $T/none.ppm: error: cannot open" "$T/none.ppm"
# A texture changed between two tiles: its texels are in the fingerprint.
mkdir -p "$T/tex/textures"
cp scenes/textures.txt "$T/tex/"
cp scenes/textures/*.ppm "$T/tex/textures/"
"$RT" -q --tile 1/2 "$T/tex/textures.txt" "$T/tex-1.ppm"
printf 'P3\n1 1\n255\n9 9 9\n' >"$T/tex/textures/checker.ppm"
"$RT" -q --tile 2/2 "$T/tex/textures.txt" "$T/tex-2.ppm"
refused "a texture changed" "raytrace-merge: $T/tex-2.ppm: error: a tile of another render" \
    "$T/tex-1.ppm" "$T/tex-2.ppm"
# Two passes of one scene are two renders.
"$RT" -q --tile 1/2 --pass albedo scenes/course.txt "$T/pass-1.ppm"
"$RT" -q --tile 2/2 --pass normal scenes/course.txt "$T/pass-2.ppm"
refused "another pass" "raytrace-merge: $T/pass-2.ppm: error: a tile of another render" \
    "$T/pass-1.ppm" "$T/pass-2.ppm"
# raytrace itself: more tiles than rows, a bad K/N, a lossy or float tile.
"$RT" -q --tile 1/401 scenes/course.txt "$T/x.ppm" 2>"$T/err"
[ $? = 1 ] && grep -q "the picture has 400 rows, so at most 400 tiles" "$T/err" && pass ||
    fail "--tile 1/401 of 400 rows" "$(cat "$T/err")"
for bad in 0/3 4/3 3 1/65537 a/b 1/2x; do
    "$RT" -q --tile "$bad" scenes/course.txt "$T/x.ppm" 2>"$T/err"
    [ $? = 2 ] && grep -q "option '--tile' takes K/N" "$T/err" && pass || fail "--tile $bad" "$(cat "$T/err")"
done
"$RT" -q --tile 1/2 scenes/course.txt "$T/x.jpg" 2>"$T/err"
[ $? = 2 ] && grep -q "not JPEG" "$T/err" && pass || fail "--tile to JPEG" "$(cat "$T/err")"

# --- 3. the recipes of docs/distributed.md, each against the whole render ---
# have TOOL PACKAGE: says whether TOOL is here; when not, says what is
# skipped (or fails when the tools are required).
have() {
    command -v "$1" >/dev/null 2>&1 && return 0
    if [ "${RAYTRACE_TEST_TOOLS:-}" = required ]; then
        fail "$1 is missing (install $2)"
    else
        echo "tiles: skipped the $1 recipe ($2 is not installed)"
    fi
    return 1
}
mkdir -p "$T/bin" "$T/work"
ln -s "$RT" "$T/bin/raytrace"
ln -s "$MERGE" "$T/bin/raytrace-merge"
PATH=$T/bin:$PATH
export PATH
cp scenes/billiards.txt "$T/work/scene.txt"
cd "$T/work" || exit 2
raytrace -q scene.txt whole.png

# (a) make -j on a generated makefile (docs/distributed.md, "With make").
N=8
{
    printf 'picture.png:'
    k=1; while [ $k -le $N ]; do printf ' tile-%d.ppm' $k; k=$((k + 1)); done
    printf '\n\traytrace-merge -q $@ $^\n'
    printf 'tile-%%.ppm: scene.txt\n\traytrace -q -j 1 --tile $*/%d scene.txt $@\n' $N
} >tiles.mk
make -s -j 4 -f tiles.mk >make.log 2>&1 && cmp -s picture.png whole.png && pass ||
    fail "make -j recipe" "$(cat make.log)"
rm -f tile-*.ppm picture.png

# (b) GNU parallel, here and through ssh logins (':' is this machine).
if full && have parallel parallel; then
    parallel -j 4 raytrace -q -j 1 --tile {}/8 scene.txt tile-{}.ppm ::: 1 2 3 4 5 6 7 8 &&
        raytrace-merge -q picture.png tile-*.ppm && cmp -s picture.png whole.png && pass ||
        fail "GNU parallel recipe"
    rm -f tile-*.ppm picture.png
    parallel --sshlogin : --workdir . --basefile scene.txt --return tile-{}.ppm --cleanup \
        raytrace -q -j 1 --tile {}/8 scene.txt tile-{}.ppm ::: 1 2 3 4 5 6 7 8 >parallel.log 2>&1 &&
        raytrace-merge -q picture.png tile-*.ppm && cmp -s picture.png whole.png && pass ||
        fail "GNU parallel --sshlogin recipe" "$(cat parallel.log)"
    rm -f tile-*.ppm picture.png
fi

# (c) A Slurm job array on a single-node Slurm started here.
if full && have sbatch slurm-wlm; then
    SLURM_CONF=$T/slurm/slurm.conf
    export SLURM_CONF
    mkdir -p "$T/slurm"
    if sh "$TOP/tests/slurm.sh" start "$T/slurm" >slurm.log 2>&1; then
        cp "$TOP/docs/tiles.sbatch" .
        # The recipe: the array, then the merge once it has succeeded.
        job=$(sbatch --parsable --array=1-8 tiles.sbatch scene.txt 2>>slurm.log) &&
            sbatch --wait --dependency=afterok:"$job" --wrap 'raytrace-merge -q picture.png tile-*.ppm' \
                >>slurm.log 2>&1 && cmp -s picture.png whole.png && pass ||
            fail "Slurm job array recipe" "$(cat slurm.log; cat slurm-*.out 2>/dev/null)"
        sh "$TOP/tests/slurm.sh" stop "$T/slurm" >>slurm.log 2>&1
    else
        # Installed but not runnable here (no root, no daemons): said, not failed.
        echo "tiles: skipped the Slurm recipe: this machine cannot start Slurm ($(tail -n 1 slurm.log))"
        sh "$TOP/tests/slurm.sh" stop "$T/slurm" >>slurm.log 2>&1
    fi
fi
cd "$TOP" || exit 2

# --- the irradiance cache: each tile runs the whole picture's pre-pass,
# so its tiles merge to the whole render, in both layouts ---
sed 's/^200 .*/40    # horizontal resolution/' scenes/room.txt >"$T/room.txt"
"$RT" -q --gi 24 --gi-cache --gi-bounces 2 "$T/room.txt" "$T/gc.ppm" || fail "--gi-cache: the whole render"
for layout in rows bands; do
    rm -f "$T"/gct-*.ppm
    for k in 1 2 3; do
        "$RT" -q --gi 24 --gi-cache --gi-bounces 2 --tile "$k/3" --tile-layout $layout "$T/room.txt" \
            "$T/gct-$k.ppm" || fail "--gi-cache: tile $k/3 $layout"
    done
    "$MERGE" -q "$T/gcm.ppm" "$T"/gct-*.ppm && cmp -s "$T/gcm.ppm" "$T/gc.ppm" && pass ||
        fail "--gi-cache: the $layout tiles merged differ from the whole picture"
done

finish
