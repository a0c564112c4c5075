#!/bin/sh
# make-roof.sh: draws roof.ppm, the roof tiles of scenes/models/house.mtl:
# 128 x 128 pixels that repeat seamlessly, four rows of four terracotta
# tiles, each row set half a tile across from the one below, each tile
# rounded (lighter along its middle), darker at its lower edge where the
# row above overlaps it, its shade a little its own. Plain awk: ours.
#
# Usage: sh scenes/textures/make-roof.sh   (from anywhere)
set -eu
cd "$(dirname "$0")"
awk 'BEGIN {
    n = 128; t = 32
    printf "P3\n# roof.ppm: drawn by make-roof.sh\n%d %d\n255\n", n, n
    for (y = 0; y < n; y++) {
        row = int(y / t); fy = (y % t + 0.5) / t          # 0 at the top of a tile
        for (x = 0; x < n; x++) {
            sx = (x + (row % 2) * t / 2) % n
            col = int(sx / t); fx = (sx % t + 0.5) / t
            # The tile: its own shade, rounded across, darker at its foot.
            h = ((row * 7 + col * 13) % 5) / 5
            round = 0.75 + 0.25 * sin(3.14159265 * fx)
            foot = fy > 0.82 ? 0.55 : 1
            edge = fx < 0.04 || fx > 0.96 ? 0.6 : 1
            k = round * foot * edge * (0.9 + 0.1 * h)
            r = int(188 * k); g = int(84 * k + 10 * h); b = int(52 * k)
            printf "%d %d %d%s", r, g, b, x == n - 1 ? "\n" : " "
        }
    }
}' >roof.ppm
