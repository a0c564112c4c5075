/* tile.c: tiles of a picture and their records (see tile.h). */
#include "image/tile.h"

#include <inttypes.h>
#include <stdio.h>
#include <string.h>

static const char *const tile_layouts[] = {"rows", "bands"};
static const char tile_magic[] = "raytrace-tile ";

int tile_make(Tile *t, int k, int n, TileLayout layout, int width, int height,
              uint64_t fingerprint)
{
    t->k = k;
    t->n = n;
    t->layout = layout;
    t->width = width;
    t->height = height;
    t->fingerprint = fingerprint;
    if (n > height)
        return -1;
    if (layout == TILE_ROWS) {
        t->first = k - 1;
        t->step = n;
        t->count = t->first < height ? (height - 1 - t->first) / n + 1 : 0;
    } else {
        long long lo = (long long)(k - 1) * height / n, hi = (long long)k * height / n;
        t->first = (int)lo;
        t->step = 1;
        t->count = (int)(hi - lo);
    }
    return t->count > 0 ? 0 : -1;
}

void tile_record(const Tile *t, char buf[TILE_RECORD_MAX])
{
    snprintf(buf, TILE_RECORD_MAX,
             "%s%d/%d layout %s first %d step %d count %d of %dx%d fingerprint %016" PRIx64,
             tile_magic, t->k, t->n, tile_layouts[t->layout], t->first, t->step, t->count,
             t->width, t->height, t->fingerprint);
}

/* Reads the record in the len bytes at s into *t; returns 0, or -1 with
 * *err when it is malformed or its rows are not those of its tile. */
static int tile_parse(const char *name, const char *s, size_t len, Tile *t, Error *err)
{
    char text[TILE_RECORD_MAX], layout[8], hex[17], canon[TILE_RECORD_MAX];
    int k, n, first, step, count, w, h, end = 0;
    Tile want;

    if (len >= sizeof text)
        goto bad;
    memcpy(text, s, len);
    text[len] = '\0';
    if (sscanf(text, "raytrace-tile %d/%d layout %7s first %d step %d count %d of %dx%d "
                     "fingerprint %16s%n",
               &k, &n, layout, &first, &step, &count, &w, &h, hex, &end) != 9 ||
        (size_t)end != len)
        goto bad;
    if (!(n >= 1 && n <= TILE_MAX && k >= 1 && k <= n && w >= 1 && h >= 1) ||
        (strcmp(layout, "rows") != 0 && strcmp(layout, "bands") != 0))
        goto bad;
    if (n > h ||
        tile_make(&want, k, n, strcmp(layout, "rows") == 0 ? TILE_ROWS : TILE_BANDS, w, h, 0) != 0)
        goto bad;
    if (sscanf(hex, "%" SCNx64, &want.fingerprint) != 1)
        goto bad;
    /* The text must be exactly what this tile's record would be. */
    tile_record(&want, canon);
    if (strcmp(canon, text) != 0)
        goto bad;
    *t = want;
    (void)first;
    (void)step;
    (void)count;
    return 0;
bad:
    error_set(err, name, "a malformed tile record: '%.*s'", (int)(len > 100 ? 100 : len), s);
    return -1;
}

/* Reads a big-endian 32-bit number. */
static uint32_t tile_u32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

int tile_find(const char *name, const unsigned char *data, size_t len, Tile *t, Error *err)
{
    size_t m = sizeof tile_magic - 1;

    if (len >= 8 && memcmp(data, "\x89PNG\r\n\x1a\n", 8) == 0) {
        /* Walk the chunks up to the pixels. */
        for (size_t at = 8; len - at >= 12;) {
            uint32_t n = tile_u32(data + at);
            const unsigned char *type = data + at + 4, *body = data + at + 8;
            if (n > len - at - 12 || memcmp(type, "IDAT", 4) == 0)
                return 0;
            if (memcmp(type, "tEXt", 4) == 0 && n > 8 && memcmp(body, "Comment", 8) == 0 &&
                n - 8 >= m && memcmp(body + 8, tile_magic, m) == 0)
                return tile_parse(name, (const char *)body + 8, n - 8, t, err) == 0 ? 1 : -1;
            at += 12 + (size_t)n;
        }
        return 0;
    }
    if (len >= 3 && data[0] == 'P' && (data[1] == 'F' || data[1] == 'f')) {
        /* PFM keeps it on the last line, after the pixels. */
        size_t from = len > TILE_RECORD_MAX + 4 ? len - TILE_RECORD_MAX - 4 : 0;
        for (size_t at = len - 1; at > from; at--)
            if (data[at - 1] == '\n' && data[at] == '#' && len - at >= 3 + m &&
                memcmp(data + at + 2, tile_magic, m) == 0) {
                size_t end = len;
                while (end > at && (data[end - 1] == '\n' || data[end - 1] == '\r'))
                    end--;
                return tile_parse(name, (const char *)data + at + 2, end - at - 2, t, err) == 0
                           ? 1
                           : -1;
            }
        return 0;
    }
    if (len >= 3 && data[0] == 'P' && (data[1] == '6' || data[1] == '3') &&
        (data[2] == '\n' || data[2] == '\r' || data[2] == ' ')) {
        /* The comment lines straight after the magic number. */
        size_t at = 3;
        while (at < len && data[at] == '#') {
            const unsigned char *eol = memchr(data + at, '\n', len - at);
            size_t end = eol ? (size_t)(eol - data) : len;
            if (end - at >= 2 + m && memcmp(data + at + 2, tile_magic, m) == 0)
                return tile_parse(name, (const char *)data + at + 2, end - at - 2, t, err) == 0
                           ? 1
                           : -1;
            at = end + 1;
        }
    }
    return 0;
}
