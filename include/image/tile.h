/*
 * tile.h: a part of a picture rendered on its own (raytrace --tile K/N),
 * and the record a tile's file keeps of where it belongs.
 *
 * A picture of width x height pixels is cut into N tiles of whole rows.
 * With the "rows" layout (the default) tile K takes rows K - 1, K - 1 + N,
 * K - 1 + 2N...: neighbouring rows cost alike, so every tile gets its share
 * of the cheap and the costly parts of the picture. With "bands" it takes
 * the rows from floor((K - 1) H / N) to floor(K H / N) - 1: one piece of
 * the picture, viewable as it is. N is at most the picture's height H, so
 * that every tile holds a row. A tile's file is a picture of width x
 * (its rows) pixels, whose record is one line of text:
 *
 *     raytrace-tile K/N layout LAYOUT first FIRST step STEP count COUNT
 *         of WIDTHxHEIGHT fingerprint HEX16
 *
 * (on one line), kept as a comment after a PPM's magic number, in a PNG's
 * tEXt chunk "Comment", or as a last line "# RECORD" after a PFM's pixels. The fingerprint (16 hex digits) stands for the
 * scene and every option that changes pixels, so that tiles of different
 * renders are never mixed.
 */
#ifndef RAYTRACE_TILE_H
#define RAYTRACE_TILE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

enum { TILE_MAX = 65536, TILE_RECORD_MAX = 160 };

typedef enum { TILE_ROWS, TILE_BANDS } TileLayout;

typedef struct {
    int k, n;              /* tile k of n, 1 <= k <= n <= TILE_MAX */
    TileLayout layout;
    int width, height;     /* the whole picture's */
    int first, step, count; /* its rows: first + i * step, 0 <= i < count */
    uint64_t fingerprint;  /* the render's (scene and options) */
} Tile;

/* Makes *t tile k of n of a width x height picture; returns 0, or -1 when
 * n > height (some tile would hold no row). */
int tile_make(Tile *t, int k, int n, TileLayout layout, int width, int height,
              uint64_t fingerprint);

/* Writes t's record (no newline) to buf, which holds TILE_RECORD_MAX
 * bytes. */
void tile_record(const Tile *t, char buf[TILE_RECORD_MAX]);

/* Finds the tile record in the len bytes of an image file at data (a PPM
 * comment, a PNG tEXt chunk) and reads it into *t; returns 1, 0 when the
 * file has none, or -1 with *err (naming name) when it has a malformed or
 * inconsistent one. */
int tile_find(const char *name, const unsigned char *data, size_t len, Tile *t, Error *err);

#endif
