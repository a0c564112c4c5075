#!/bin/sh
# make-jpeg.sh: renders the JPEG textures of scenes/mpl.txt with
# raytrace itself and encodes them with cjpeg (Debian's
# libjpeg-turbo-progs): all of them ours, none taken from elsewhere.
#
# Usage: sh scenes/textures/make-jpeg.sh   (from the repository root,
# after make)
set -eu
cd "$(dirname "$0")"
HERE=$(pwd)
T=$(mktemp -d "${TMPDIR:-/tmp}/raytrace-tex.XXXXXX")
trap 'rm -rf "$T"' EXIT
RT=../../raytrace

# render NAME: renders $T/NAME.txt (a course scene) to NAME.jpg.
render() {
    "$RT" -q "$T/$1.txt" "$T/$1.ppm"
    cjpeg -quality 88 -optimize -outfile "$1.jpg" "$T/$1.ppm"
}

# A camera 1 unit from a 2 x 2 screen on z = 0: looks at [-1, 1]^2.
head='0 0 -2
-1 1 -1
1 1 -1
-1 -1 -1
256
40 40 40
0 0 -6 255 255 255
ambient: 60 60 60'

# Wallpaper: a pale gradient tiled, and rows of small gilt dots.
{
    echo "$head"
    echo "plane: 0 0 1 0 0 -1 250 240 220 0"
    echo "texture: $HERE/gradient.ppm bilinear 2"
    for y in -0.5 0.5; do
        for x in -0.5 0.5; do
            echo "sphere: $x $y 0.9 0.12 200 160 60 0.4"
        done
    done
} >"$T/Wallpaper.txt"
render Wallpaper

# Floor tiles: the 2 x 2 checker, once.
{
    echo "$head"
    echo "plane: 0 0 1 0 0 -1 235 230 225 0"
    echo "texture: $HERE/checker.ppm nearest 2"
} >"$T/carrelage.txt"
render carrelage

# A painting: the course's own scene.
sed 's/^400$/256/' ../course.txt >"$T/painting.txt"
render painting

# Marble: the planet's clouds, tiled at an angle, washed out.
{
    echo "$head" | sed 's/^ambient: 60 60 60$/ambient: 150 150 150/'
    echo "plane: 0 0 1 0.3 0.2 -1 255 255 255 0"
    echo "texture: $HERE/planet.ppm bilinear 1.3"
} >"$T/marble.txt"
render marble
