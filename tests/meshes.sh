#!/bin/sh
# meshes.sh: mesh files read as their exporters meant (docs/scene-format.md,
# "Meshes: OBJ, PLY and STL"):
#
#  1. the same triangles in OBJ, PLY (ASCII, little- and big-endian) and
#     STL (ASCII, binary) render to the same bytes, in course and keyword
#     scenes, the format told by content whatever the file's name;
#  2. concave faces written as one face (a star, a comb, a spiral, a ring)
#     in OBJ and PLY cover the pixels of their true triangulations;
#  3. a mesh line without a material draws the file's own: an OBJ file's
#     MTL materials and textures (names with spaces, '\' separators, a
#     drive letter, map_Kd's -s and -o), a PLY file's vertex colours, a
#     grey otherwise; a material given overrides them; -v says what each
#     mesh held; --save keeps the line as it was;
#  4. a missing MTL file, material or texture is a warning naming its file
#     and line, and the picture comes;
#  5. damaged files: exit 1, a message naming the file and its line and
#     column or byte, no output, an existing one kept;
#  6. real exporters' files, from Debian's assimp-testmodels when installed
#     (RAYTRACE_TEST_TOOLS=required makes it a must, as in CI): the
#     spider's four textures, Wuson in OBJ, PLY and STL covering the same
#     pixels, LightWave's ring keeping its hole, the invalid folder's files
#     refused or read, never a crash.
#
# The quick suite (make test, RAYTRACE_TEST_LEVEL=quick) renders part 1 in
# course scenes alone, part 2 from OBJ and little-endian PLY, and of part
# 6's folders the invalid one.
#
# Usage: sh tests/meshes.sh RAYTRACE RAYTRACE-DIFF MESHGEN   (from the
# repository root)

RT=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
DIFF=$(cd "$(dirname "$2")" && pwd)/$(basename "$2")
GEN=$(cd "$(dirname "$3")" && pwd)/$(basename "$3")
SUITE=meshes
. "$(dirname "$0")/check.sh"
TOP=$(pwd)
cd "$T" || exit 2

# pixel PPM X Y: "R G B" of pixel (X, Y) of the binary PPM (no comment).
pixel() {
    w=$(sed -n 2p "$1" | cut -d' ' -f1)
    head=$(head -n 3 "$1" | wc -c)
    od -A n -t u1 -j $((head + 3 * ($3 * w + $2))) -N 3 "$1" | awk '{ print $1, $2, $3 }'
}

# mask PPM: one line a pixel, 1 where it is not the background (20 30 60).
mask() {
    head=$(head -n 3 "$1" | wc -c)
    od -A n -t u1 -v -w3 -j "$head" "$1" | awk '{ print ($1 != 20 || $2 != 30 || $3 != 60) }'
}

# course MESH-LINE: a course scene seeing [-4, 4]^2 in the plane z = 0
# from z = -10, on the background 20 30 60, with MESH-LINE.
course() {
    printf '0 0 -10\n-0.45 0.45 -9\n0.45 0.45 -9\n-0.45 -0.45 -9\n96\n20 30 60\n' >scene.txt
    printf -- '-3 4 -9 255 255 255\nambient: 40 40 40\n%s\n' "$1" >>scene.txt
}

# keyword MESH-LINE: the keyword scene of that view.
keyword() {
    printf 'camera 0 0 -10 0 0 0 0.9 96 96\nbackground 20 30 60\nambient 40 40 40\n' >scene.txt
    printf 'light 0.3 -0.4 1 255 255 255 1\nmaterial w 200 200 200 0.2 0.8 0.5 20\n%s\n' \
        "$1" >>scene.txt
}

# --- 1. the same triangles in every format, the same bytes ---
formats="obj ply-ascii ply-le ply-be stl-ascii stl-binary"
for f in $formats; do "$GEN" $f bumpy 3000 >"bumpy.$f" || fail "meshgen $f"; done
scenes="course keyword"
full || scenes=course
for scene in $scenes; do
    first=
    for f in $formats; do
        # The name says nothing: the content tells the format.
        cp "bumpy.$f" "mesh-$f.dat"
        if [ $scene = course ]; then course "mesh: mesh-$f.dat"; else keyword "mesh mesh-$f.dat"; fi
        "$RT" -q scene.txt "$f.ppm" 2>err || fail "$scene scene of $f" "$(cat err)"
        if [ -z "$first" ]; then
            first=$f
        else
            cmp -s "$first.ppm" "$f.ppm" && pass ||
                fail "$scene: $f renders other bytes than $first" "$("$DIFF" "$first.ppm" "$f.ppm" 2>&1)"
        fi
    done
    # A material given: the same bytes again, and not the file's grey.
    if [ $scene = course ]; then course "mesh: mesh-ply-le.dat 250 180 40 0"; else keyword "mesh mesh-ply-le.dat w"; fi
    "$RT" -q scene.txt given.ppm && ! cmp -s given.ppm "$first.ppm" && pass ||
        fail "$scene: a mesh line's material does not change the picture"
done
course "mesh: mesh-obj.dat"
"$RT" -v scene.txt x.ppm 2>err
expect_grep "-v names a mesh" "raytrace: mesh mesh-obj.dat (OBJ): " err
expect_grep "-v: its own material" "1 material of its own, 0 textures" err
course "mesh: mesh-stl-binary.dat"
"$RT" -v scene.txt x.ppm 2>err
expect_grep "-v: binary STL" "raytrace: mesh mesh-stl-binary.dat (STL (binary)): " err

# --- 2. concave faces cover what their true triangulations cover ---
encodings="obj ply-ascii ply-le"
full || encodings="obj ply-le"
for s in star comb spiral ring; do
    for f in $encodings; do
        "$GEN" $f $s >"face.$f" && "$GEN" $f $s cut >"cut.$f" || fail "meshgen $f $s"
        # Flat white: ambient light alone, so that every triangle is alike.
        printf 'camera 0 0 -10 0 0 0 0.9 120 120\nmaterial w 255 255 255 1 0 0 1\n' >scene.txt
        printf 'ambient 255 255 255\nlight 0 0 1 0 0 0 1\nmesh face.%s w\n' $f >>scene.txt
        "$RT" -q scene.txt face.ppm 2>err || fail "$s as one $f face" "$(cat err)"
        sed "s/mesh face/mesh cut/" scene.txt >cut.txt
        "$RT" -q cut.txt cut.ppm 2>err || fail "$s cut, $f" "$(cat err)"
        cmp -s face.ppm cut.ppm && pass ||
            fail "$s as one $f face covers other pixels than its triangulation" \
                "$("$DIFF" cut.ppm face.ppm 2>&1)"
    done
    "$RT" -v scene.txt x.ppm 2>err
    expect_grep "-v counts $s's cut face" "1 face of more than 3 corners: 1 cut around its notches, 0 not simple" err
done
# A face that is not simple: read, and counted.
printf 'v 0 0 0\nv 2 2 0\nv 2 0 0\nv 0 2 0\nf 1 2 3 4\n' >bowtie.obj
course "mesh: bowtie.obj"
"$RT" -v scene.txt x.ppm 2>err && pass || fail "a bow-tie face" "$(cat err)"
expect_grep "-v counts a face that is not simple" "1 face of more than 3 corners: 0 cut around their notches, 1 not simple" err

# --- 3. the file's own materials ---
mkdir -p "tex dir/sub"
cp "$TOP/scenes/textures/checker.ppm" "tex dir/sub/my checker.ppm"
cp "$TOP/scenes/textures/checker.ppm" "tex dir/far away.ppm"
# Two quads side by side, each its own material: red paint on the left, a
# checker (scaled twice, moved a quarter) on the right; then a third,
# checkered through a Windows path with a drive letter.
cat >"tex dir/quads.obj" <<'EOF'
mtllib paint.mtl  textures.mtl
v -3 -2 0
v -0.1 -2 0
v -0.1 2 0
v -3 2 0
v 0.1 -2 0
v 3 -2 0
v 3 2 0
v 0.1 2 0
vt 0 0
vt 1 0
vt 1 1
vt 0 1
usemtl red paint
f 1/1 2/2 3/3 4/4
usemtl checker
f 5/1 6/2 7/3 8/4
EOF
printf 'newmtl red paint\nKa 0 0 0\nKd 1 0 0\nKs 0 0 0\nillum 1\n' >"tex dir/paint.mtl"
printf 'newmtl checker\nKd 1 1 1\nmap_Kd -s 2 2 1 -o 0.25 0 0 -bm 1 sub\\my checker.ppm\n' >"tex dir/textures.mtl"
# (A scene line cannot hold a space: the folder is reached by a link.)
ln -s "tex dir" texdir
course "mesh: texdir/quads.obj"
"$RT" -v scene.txt own.ppm 2>err && pass || fail "quads in their own materials" "$(cat err)"
[ "$(grep -c warning err)" = 0 ] && pass || fail "quads in their own materials: warnings" "$(cat err)"
expect_grep "-v: two materials, one texture" "2 materials of its own, 1 texture" err
set -- $(pixel own.ppm 30 48)
[ "$1" -gt 100 ] && [ "$2" -lt 20 ] && [ "$3" -lt 20 ] && pass || fail "the left quad is not red: $*"
course "mesh: texdir/quads.obj 200 200 200 0"
"$RT" -q scene.txt grey.ppm 2>err || fail "quads in a material given" "$(cat err)"
set -- $(pixel grey.ppm 30 48)
[ "$1" = "$2" ] && [ "$2" = "$3" ] && pass || fail "a material given does not override the file's: $*"
"$DIFF" -q grey.ppm own.ppm 2>/dev/null && fail "the checker does not show" || pass
# --save keeps 'mesh PATH' without a material.
printf 'camera 0 0 -10 0 0 0 0.9 96 96\nlight 0 0 1 255 255 255 1\nmesh texdir/quads.obj\n' >kw.txt
"$RT" --save saved.txt kw.txt 2>err && grep -qx 'mesh texdir/quads.obj' saved.txt && pass ||
    fail "--save of a mesh in its own materials" "$(cat err saved.txt)"
grep -q '^material' saved.txt && fail "--save writes the mesh file's materials" "$(cat saved.txt)" || pass
"$RT" -q kw.txt a.ppm && "$RT" -q saved.txt b.ppm && cmp -s a.ppm b.ppm && pass ||
    fail "the saved scene of a mesh in its own materials renders other bytes"
# A drive letter, another machine's folder: the last part, beside the MTL.
printf 'newmtl checker\nKd 1 1 1\nmap_Kd C:\\Users\\someone\\Models\\far away.ppm\n' >"tex dir/textures.mtl"
course "mesh: texdir/quads.obj"
"$RT" -v scene.txt drive.ppm 2>err
expect_grep "a drive letter's path read beside the MTL" "2 materials of its own, 1 texture" err
[ "$(grep -c warning err)" = 0 ] && pass || fail "a drive letter's path: warnings" "$(cat err)"
# A PLY file's vertex colours: red, green and blue corners blend.
cat >colours.ply <<'EOF'
ply
format ascii 1.0
element vertex 3
property float x
property float y
property float z
property uchar red
property uchar green
property uchar blue
element face 1
property list uchar int vertex_indices
end_header
-3 -3 0 255 0 0
3 -3 0 0 255 0
0 3 0 0 0 255
3 0 1 2
EOF
printf 'camera 0 0 -10 0 0 0 0.9 96 96\nambient 255 255 255\nlight 0 0 1 0 0 0 1\nmesh colours.ply\n' >kw.txt
"$RT" -q kw.txt colours.ppm 2>err || fail "a PLY of vertex colours" "$(cat err)"
# At the middle, a quarter red, a quarter green, half blue.
set -- $(pixel colours.ppm 48 48)
[ "$1" -gt 10 ] && [ $(($1 - $2)) -le 2 ] && [ $(($2 - $1)) -le 2 ] && [ "$3" -gt $(($1 + $1 / 2)) ] && pass ||
    fail "vertex colours do not blend at the middle: $*"
set -- $(pixel colours.ppm 24 74)
[ "$1" -gt $((2 * $2)) ] && [ "$1" -gt $((2 * $3)) ] && pass || fail "the red corner is not red: $*"

# --- 4. what is missing: a warning naming it, and the picture ---
printf 'newmtl checker\nKd 1 1 1\nmap_Kd sub\\no such.ppm\n' >"tex dir/textures.mtl"
rm "tex dir/paint.mtl"
course "mesh: texdir/quads.obj"
"$RT" scene.txt missing.ppm 2>err && [ -s missing.ppm ] && pass || fail "missing files stop the picture" "$(cat err)"
expect_grep "a missing MTL file is named, with its line" "quads.obj:1:8: warning: cannot read the material library 'paint.mtl'" err
expect_grep "a material no library describes is named" "quads.obj:14:8: warning: no material library describes the material 'red paint'" err
expect_grep "a missing texture is named, with its line" "textures.mtl:3:8: warning: cannot use the texture" err

# --- 5. damaged files: exit 1, where, nothing written, the old output kept ---
"$GEN" ply-le bumpy 200 >good.ply
"$GEN" ply-ascii bumpy 200 >good-ascii.ply
"$GEN" stl-ascii bumpy 200 >good.stl
"$GEN" stl-binary bumpy 200 >good-binary.stl
size=$(wc -c <good.ply)
head -c $((size - 9)) good.ply >short.ply
sed 's/^element vertex .*/element vertex 99999999/' good.ply >count.ply
awk '/end_header/ { h = 1; print; next } h && NF == 4 && !done { print "3 0 1 99999"; done = 1; next } { print }' good-ascii.ply >index.ply
sed 's/^format .*/format binary_middle_endian 1.0/' good.ply >format.ply
sed 's/^property float x/property float128 x/' good-ascii.ply >type.ply
grep -v end_header good-ascii.ply >noend.ply
head -n -3 good.stl >open.stl
size=$(wc -c <good-binary.stl)
head -c $((size - 7)) good-binary.stl >short.stl
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >index.obj
# damaged FILE MESSAGE: FILE, as the mesh of a scene, fails with MESSAGE
# (which names its place: a line and column, or a byte), leaving the
# output as it was.
damaged() {
    course "mesh: $1"
    printf 'old\n' >out.ppm
    "$RT" scene.txt out.ppm 2>err
    code=$?
    [ $code = 1 ] && pass || fail "$1: exit $code, expected 1" "$(cat err)"
    expect_grep "$1 names its fault" "cannot use the mesh '$1': $2" err
    [ "$(cat out.ppm)" = old ] && pass || fail "$1 changed the old output"
    expect_clean "$1 leaves no temporary file" .
}
damaged short.ply "byte 4346: the file ends inside face 210 of 210 (element 'face'): a list of 3 items"
damaged count.ply "byte 194: the header declares 99999999 items of the element 'vertex': more than"
damaged index.ply "index.ply:131:7: vertex 99999 does not exist (the file has 120 vertices)"
damaged format.ply "format.ply:2:8: unknown PLY format 'binary_middle_endian'"
damaged type.ply "type.ply:5:10: unknown property type 'float128'"
damaged noend.ply "noend.ply:339:1: the header has no end_header line"
damaged open.stl "open.stl:1470:1: expected 'endloop' (a facet has three corners), found the end"
damaged short.stl "byte 80: a binary STL file of 210 facets has 84 + 50 x 210 = 10584 bytes, this one 10577"
damaged index.obj "index.obj:4:7: vertex 9 does not exist (3 vertices so far)"

# --- 6. real exporters' files (Debian: assimp-testmodels) ---
A=/usr/share/assimp/models
if [ -d "$A/OBJ" ]; then
    cp "$A/OBJ/spider.obj" "$A/OBJ/spider.mtl" "$A"/OBJ/*.jpg .
    printf 'camera 120 80 120 20 15 -12 0.7 160 120\nlight -1 -1 -1 255 255 255 1\nambient 60 60 60\nmesh spider.obj\n' >spider.txt
    "$RT" -v spider.txt spider.ppm 2>err && pass || fail "the spider" "$(cat err)"
    expect_grep "the spider's four materials and textures" "4 materials of its own, 4 textures" err
    [ "$(grep -c warning err)" = 0 ] && pass || fail "the spider: warnings" "$(cat err)"
    sed 's/^mesh spider.obj/material g 200 200 200 0.3 0.7 0 1\nmesh spider.obj g/' spider.txt >grey.txt
    "$RT" -q grey.txt grey.ppm && ! "$DIFF" -q --tolerance 8 --max-pixels 200 grey.ppm spider.ppm 2>/dev/null &&
        pass || fail "the spider's textures do not show"
    # Wuson in three formats: the same pixels covered.
    for f in OBJ/WusonOBJ.obj PLY/Wuson.ply STL/Wuson.stl; do
        printf 'camera 2 1.5 -3 0 0.6 0 0.7 96 96\nbackground 20 30 60\nlight -1 -2 1.5 255 255 255 1\nmesh %s\n' "$A/$f" >w.txt
        "$RT" -q w.txt w.ppm 2>err || fail "Wuson: $f" "$(cat err)"
        mask w.ppm >"mask-${f%%/*}"
    done
    cmp -s mask-OBJ mask-PLY && cmp -s mask-OBJ mask-STL && pass ||
        fail "Wuson in OBJ, PLY and STL covers other pixels"
    # The spider in ASCII and binary STL: the same pixels covered.
    for f in ascii binary; do
        printf 'camera 4 3 -3 1 0.8 0.5 0.8 96 96\nbackground 20 30 60\nlight -1 -1 1 255 255 255 1\nmesh %s\n' \
            "$A/STL/Spider_$f.stl" >s.txt
        "$RT" -q s.txt "spider-$f.ppm" 2>err || fail "the spider in $f STL" "$(cat err)"
        mask "spider-$f.ppm" >"mask-spider-$f"
    done
    cmp -s mask-spider-ascii mask-spider-binary && pass || fail "the ASCII and binary STL spiders cover other pixels"
    [ "$(grep -c 1 mask-spider-ascii)" -gt 300 ] && pass || fail "the STL spider is not in view"
    # The ring: one face of 66 corners, its hole kept.
    printf 'camera -6 2.4 2.35 -1.146 2.4 2.35 0.5 60 60\nbackground 20 30 60\nlight 1 -0.2 0.1 255 255 255 1\nmesh %s\n' \
        "$A/OBJ/concave_polygon.obj" >ring.txt
    "$RT" -q ring.txt ring.ppm 2>err || fail "the ring" "$(cat err)"
    [ "$(pixel ring.ppm 30 30)" = "20 30 60" ] && pass || fail "the ring's hole is filled: $(pixel ring.ppm 30 30)"
    [ "$(mask ring.ppm | grep -c 1)" -gt 40 ] && pass || fail "the ring itself is missing"
    # The invalid folder, and in full every file: refused with a message,
    # or read; never a crash.
    files="$A/invalid/*.obj $A/invalid/*.ply"
    full && files="$files $A/OBJ/*.obj $A/PLY/*.ply $A/STL/*.stl $A/STL/*.STL"
    # shellcheck disable=SC2086 # the patterns are meant to expand
    for f in $files; do
        course "mesh: $f"
        "$RT" -q scene.txt x.ppm 2>err
        code=$?
        [ $code = 0 ] || { [ $code = 1 ] && grep -q "error: " err; } && pass ||
            fail "$f: exit $code" "$(cat err)"
    done
elif [ "${RAYTRACE_TEST_TOOLS:-}" = required ]; then
    fail "Debian's assimp-testmodels is missing"
fi

finish
