/* bmp.c: reading and writing Windows bitmaps (see bmp.h). */
#include "image/bmp.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Sizes of the file header and of the DIB headers this reader knows. */
enum {
    BMP_FILE_HEADER = 14,
    BMP_CORE = 12,  /* BITMAPCOREHEADER: 16-bit sizes, 3-byte palette */
    BMP_INFO = 40,  /* BITMAPINFOHEADER; V2 (52), V3 (56), OS/2 (64), V4
                       (108) and V5 (124) extend it */
    BMP_V5 = 124,
    BMP_MAX_SIDE = 1 << 16 /* widest and tallest accepted */
};

/* Compression methods (biCompression). */
enum { BMP_RGB = 0, BMP_RLE8 = 1, BMP_RLE4 = 2, BMP_BITFIELDS = 3, BMP_JPEG = 4, BMP_PNG = 5,
       BMP_ALPHABITFIELDS = 6 };

static uint32_t bmp_u16(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8;
}

static uint32_t bmp_u32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* A channel's place in a 16- or 32-bit pixel: mask, shift and the largest
 * value it holds (0: the channel is absent, read as 0). */
typedef struct {
    uint32_t mask;
    int shift;
    uint32_t max;
} BmpChannel;

/* Returns the channel that mask selects. */
static BmpChannel bmp_channel(uint32_t mask)
{
    BmpChannel c = {mask, 0, 0};

    if (mask) {
        while (!(mask & 1)) {
            mask >>= 1;
            c.shift++;
        }
        c.max = mask;
    }
    return c;
}

/* Returns the channel c of pixel value px on the scale 0..255, rounded. */
static unsigned char bmp_scale(const BmpChannel *c, uint32_t px)
{
    uint64_t v;

    if (!c->max)
        return 0;
    v = (px & c->mask) >> c->shift;
    return (unsigned char)((v * 255 + c->max / 2) / c->max);
}

int bmp_is(const unsigned char *data, size_t len)
{
    return len >= 2 && data[0] == 'B' && data[1] == 'M';
}

void bmp_free(BmpImage *img)
{
    free(img->rgb);
    img->rgb = NULL;
}

/* What a bitmap's headers say, and where its parts are. */
typedef struct {
    uint32_t header, offset, compression, colours, bits;
    int64_t w, h;
    int top_down;
    int palette_entry;            /* bytes per palette colour: 3 or 4 */
    const unsigned char *palette; /* bits <= 8: the colours, else NULL */
    size_t palette_count, stride; /* colours in it; bytes per row */
    BmpChannel ch[3];             /* 16 and 32 bits: red, green, blue */
} BmpLayout;

/* Reads the file and DIB headers of the len bytes at data into *b;
 * returns 0, or -1 with *err. */
static int bmp_headers(const char *name, const unsigned char *data, size_t len, BmpLayout *b,
                       Error *err)
{
    memset(b, 0, sizeof *b);
    b->palette_entry = 4;
    if (!bmp_is(data, len) || len < BMP_FILE_HEADER + 4) {
        error_set(err, name, "not a BMP file: it is too short for its headers");
        return -1;
    }
    b->offset = bmp_u32(data + 10);
    b->header = bmp_u32(data + BMP_FILE_HEADER);
    if (b->header != BMP_CORE && (b->header < BMP_INFO || b->header > BMP_V5)) {
        error_set(err, name, "BMP: unknown header of %lu bytes (expected 12, or 40 to 124)",
                  (unsigned long)b->header);
        return -1;
    }
    if (len < BMP_FILE_HEADER + (size_t)b->header) {
        error_set(err, name, "BMP: the file ends inside its %lu-byte header",
                  (unsigned long)b->header);
        return -1;
    }
    if (b->header == BMP_CORE) {
        b->w = bmp_u16(data + 18);
        b->h = bmp_u16(data + 20);
        b->bits = bmp_u16(data + 24);
        b->palette_entry = 3;
    } else {
        b->w = (int32_t)bmp_u32(data + 18);
        b->h = (int32_t)bmp_u32(data + 22);
        b->bits = bmp_u16(data + 28);
        b->compression = bmp_u32(data + 30);
        b->colours = bmp_u32(data + 46);
    }
    if (b->h < 0) {
        b->top_down = 1;
        b->h = -b->h;
    }
    if (!(b->w >= 1 && b->w <= BMP_MAX_SIDE && b->h >= 1 && b->h <= BMP_MAX_SIDE)) {
        error_set(err, name, "BMP: a %lld x %lld image: each side must be 1 to %d pixels",
                  (long long)b->w, (long long)b->h, BMP_MAX_SIDE);
        return -1;
    }
    return 0;
}

/* Checks that b's compression and bits a pixel are ones this reader
 * reads; returns 0, or -1 with *err. */
static int bmp_supported(const char *name, const BmpLayout *b, Error *err)
{
    uint32_t c = b->compression, bits = b->bits;

    if (c == BMP_RLE8 || c == BMP_RLE4 || c == BMP_JPEG || c == BMP_PNG) {
        error_set(err, name, "BMP: %s bitmaps are not read (save it uncompressed, or as PNG)",
                  c == BMP_JPEG  ? "JPEG-compressed"
                  : c == BMP_PNG ? "PNG-compressed"
                                 : "run-length encoded");
        return -1;
    }
    if (c != BMP_RGB && c != BMP_BITFIELDS && c != BMP_ALPHABITFIELDS) {
        error_set(err, name, "BMP: unknown compression %lu", (unsigned long)c);
        return -1;
    }
    if (bits != 1 && bits != 4 && bits != 8 && bits != 16 && bits != 24 && bits != 32) {
        error_set(err, name, "BMP: %lu bits a pixel (expected 1, 4, 8, 16, 24 or 32)",
                  (unsigned long)bits);
        return -1;
    }
    if (c != BMP_RGB && bits != 16 && bits != 32) {
        error_set(err, name, "BMP: colour masks with %lu bits a pixel (expected 16 or 32)",
                  (unsigned long)bits);
        return -1;
    }
    return 0;
}

/* Finds in the len bytes at data where b's channels, palette and rows
 * are; returns 0, or -1 with *err when the file ends before them. */
static int bmp_locate(const char *name, const unsigned char *data, size_t len, BmpLayout *b,
                      Error *err)
{
    static const uint32_t masks[2][3] = {{0x7c00, 0x03e0, 0x001f}, {0xff0000, 0x00ff00, 0x0000ff}};

    if (b->compression != BMP_RGB) {
        /* The masks follow a 40-byte header, or are its V2+ fields. */
        size_t at = BMP_FILE_HEADER + BMP_INFO;
        if (len < at + 12) {
            error_set(err, name, "BMP: the file ends before its colour masks");
            return -1;
        }
        for (int c = 0; c < 3; c++)
            b->ch[c] = bmp_channel(bmp_u32(data + at + 4 * (size_t)c));
    } else {
        for (int c = 0; c < 3; c++)
            b->ch[c] = bmp_channel(masks[b->bits != 16][c]);
    }
    if (b->bits <= 8) {
        size_t at = BMP_FILE_HEADER + b->header, most = (size_t)1 << b->bits, room;
        b->palette_count = b->colours ? b->colours : most;
        room = b->offset > at ? (b->offset - at) / (size_t)b->palette_entry : 0;
        if (b->palette_count > most)
            b->palette_count = most;
        if (b->palette_count > room)
            b->palette_count = room;
        if (b->palette_count == 0 || at + b->palette_count * (size_t)b->palette_entry > len) {
            error_set(err, name, "BMP: an image of %lu bits a pixel without its palette",
                      (unsigned long)b->bits);
            return -1;
        }
        b->palette = data + at;
    }
    b->stride = (((size_t)b->w * b->bits + 31) / 32) * 4;
    if (b->offset > len || (len - b->offset) / b->stride < (size_t)b->h) {
        error_set(err, name, "BMP: the file ends before its %lld rows of pixels (%zu bytes each)",
                  (long long)b->h, b->stride);
        return -1;
    }
    return 0;
}

/* Writes pixel x of row (as b lays it out) to out as 8-bit RGB. */
static void bmp_pixel(const BmpLayout *b, const unsigned char *row, int64_t x, unsigned char *out)
{
    uint32_t bits = b->bits;

    if (bits <= 8) {
        size_t bit = (size_t)x * bits, k, e = (size_t)b->palette_entry;
        k = (size_t)(row[bit / 8] >> (8 - bits - bit % 8)) & (((size_t)1 << bits) - 1);
        if (k >= b->palette_count)
            k = 0; /* an index past the palette: its first colour */
        out[0] = b->palette[k * e + 2];
        out[1] = b->palette[k * e + 1];
        out[2] = b->palette[k * e];
    } else if (bits == 24) {
        const unsigned char *p = row + 3 * (size_t)x;
        out[0] = p[2];
        out[1] = p[1];
        out[2] = p[0];
    } else {
        uint32_t px = bits == 16 ? bmp_u16(row + 2 * (size_t)x) : bmp_u32(row + 4 * (size_t)x);
        for (int c = 0; c < 3; c++)
            out[c] = bmp_scale(&b->ch[c], px);
    }
}

int bmp_parse(const char *name, const unsigned char *data, size_t len, BmpImage *img,
              Error *err)
{
    BmpLayout b;

    memset(img, 0, sizeof *img);
    if (bmp_headers(name, data, len, &b, err) != 0 || bmp_supported(name, &b, err) != 0 ||
        bmp_locate(name, data, len, &b, err) != 0)
        return -1;
    img->rgb = malloc(3 * (size_t)b.w * (size_t)b.h);
    if (!img->rgb) {
        error_set(err, name, "out of memory for a %lld x %lld image", (long long)b.w,
                  (long long)b.h);
        return -1;
    }
    img->width = (int)b.w;
    img->height = (int)b.h;
    img->bits = (int)b.bits;
    for (int64_t y = 0; y < b.h; y++) {
        const unsigned char *row =
            data + b.offset + (size_t)(b.top_down ? y : b.h - 1 - y) * b.stride;
        unsigned char *out = img->rgb + 3 * (size_t)y * (size_t)b.w;
        for (int64_t x = 0; x < b.w; x++)
            bmp_pixel(&b, row, x, out + 3 * x);
    }
    return 0;
}

/* Stores v at p, little-endian, in n bytes. */
static void bmp_put(unsigned char *p, uint32_t v, int n)
{
    for (int i = 0; i < n; i++)
        p[i] = (unsigned char)(v >> 8 * i);
}

int bmp_write(FILE *f, int width, int height, const unsigned char *rgb)
{
    size_t row = ((size_t)width * 3 + 3) / 4 * 4;
    unsigned char head[BMP_FILE_HEADER + BMP_INFO] = {'B', 'M'}, *line = calloc(row, 1);
    uint32_t data = (uint32_t)(row * (size_t)height);
    int rc = 0;

    if (!line)
        return -1;
    bmp_put(head + 2, (uint32_t)sizeof head + data, 4); /* the file's size */
    bmp_put(head + 10, sizeof head, 4);                 /* where the pixels start */
    bmp_put(head + 14, BMP_INFO, 4);
    bmp_put(head + 18, (uint32_t)width, 4);
    bmp_put(head + 22, (uint32_t)height, 4); /* positive: bottom to top */
    bmp_put(head + 26, 1, 2);                /* planes */
    bmp_put(head + 28, 24, 2);               /* bits a pixel */
    bmp_put(head + 30, BMP_RGB, 4);
    bmp_put(head + 34, data, 4);
    bmp_put(head + 38, 2835, 4); /* 72 dpi, in pixels a metre */
    bmp_put(head + 42, 2835, 4);
    if (fwrite(head, 1, sizeof head, f) != sizeof head)
        rc = -1;
    for (int y = height - 1; y >= 0 && rc == 0; y--) {
        const unsigned char *src = rgb + 3 * (size_t)width * (size_t)y;
        for (int x = 0; x < width; x++) { /* BGR */
            line[3 * x] = src[3 * x + 2];
            line[3 * x + 1] = src[3 * x + 1];
            line[3 * x + 2] = src[3 * x];
        }
        if (fwrite(line, 1, row, f) != row)
            rc = -1;
    }
    free(line);
    return rc;
}
