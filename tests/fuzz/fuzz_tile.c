/* fuzz_tile.c: libFuzzer target for the tile record reader (tile.c) that
 * raytrace-merge trusts: an accepted record describes a real tile (1 <= K
 * <= N <= height, rows inside the picture) and reads back from its own
 * text. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "image/tile.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    Tile t, again;
    Error err;
    char record[TILE_RECORD_MAX], file[TILE_RECORD_MAX + 8];
    int n;

    if (tile_find("fuzz", data, size, &t, &err) != 1)
        return 0;
    if (!(t.k >= 1 && t.k <= t.n && t.n <= t.height && t.n <= TILE_MAX && t.count >= 1 &&
          t.first >= 0 && t.first + (long long)(t.count - 1) * t.step < t.height))
        abort();
    tile_record(&t, record);
    n = snprintf(file, sizeof file, "P6\n# %s\n", record);
    if (tile_find("again", (const uint8_t *)file, (size_t)n, &again, &err) != 1 ||
        again.k != t.k || again.n != t.n || again.layout != t.layout ||
        again.width != t.width || again.height != t.height || again.first != t.first ||
        again.step != t.step || again.count != t.count || again.fingerprint != t.fingerprint)
        abort();
    return 0;
}
