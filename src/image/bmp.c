/* bmp.c: reading Windows bitmaps (see bmp.h). */
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

int bmp_parse(const char *name, const unsigned char *data, size_t len, BmpImage *img,
              Error *err)
{
    uint32_t header, offset, compression = BMP_RGB, colours = 0, bits;
    int64_t w, h;
    int top_down = 0, palette_entry = 4;
    const unsigned char *palette = NULL;
    size_t palette_count = 0, stride;
    BmpChannel ch[3];

    memset(img, 0, sizeof *img);
    if (!bmp_is(data, len) || len < BMP_FILE_HEADER + 4) {
        error_set(err, name, "not a BMP file: it is too short for its headers");
        return -1;
    }
    offset = bmp_u32(data + 10);
    header = bmp_u32(data + BMP_FILE_HEADER);
    if (header != BMP_CORE && (header < BMP_INFO || header > BMP_V5)) {
        error_set(err, name, "BMP: unknown header of %lu bytes (expected 12, or 40 to 124)",
                  (unsigned long)header);
        return -1;
    }
    if (len < BMP_FILE_HEADER + (size_t)header) {
        error_set(err, name, "BMP: the file ends inside its %lu-byte header",
                  (unsigned long)header);
        return -1;
    }
    if (header == BMP_CORE) {
        w = bmp_u16(data + 18);
        h = bmp_u16(data + 20);
        bits = bmp_u16(data + 24);
        palette_entry = 3;
    } else {
        w = (int32_t)bmp_u32(data + 18);
        h = (int32_t)bmp_u32(data + 22);
        bits = bmp_u16(data + 28);
        compression = bmp_u32(data + 30);
        colours = bmp_u32(data + 46);
    }
    if (h < 0) {
        top_down = 1;
        h = -h;
    }
    if (!(w >= 1 && w <= BMP_MAX_SIDE && h >= 1 && h <= BMP_MAX_SIDE)) {
        error_set(err, name, "BMP: a %lld x %lld image: each side must be 1 to %d pixels",
                  (long long)w, (long long)h, BMP_MAX_SIDE);
        return -1;
    }
    if (compression == BMP_RLE8 || compression == BMP_RLE4 || compression == BMP_JPEG ||
        compression == BMP_PNG) {
        error_set(err, name, "BMP: %s bitmaps are not read (save it uncompressed, or as PNG)",
                  compression == BMP_JPEG  ? "JPEG-compressed"
                  : compression == BMP_PNG ? "PNG-compressed"
                                           : "run-length encoded");
        return -1;
    }
    if (compression != BMP_RGB && compression != BMP_BITFIELDS &&
        compression != BMP_ALPHABITFIELDS) {
        error_set(err, name, "BMP: unknown compression %lu", (unsigned long)compression);
        return -1;
    }
    if (bits != 1 && bits != 4 && bits != 8 && bits != 16 && bits != 24 && bits != 32) {
        error_set(err, name, "BMP: %lu bits a pixel (expected 1, 4, 8, 16, 24 or 32)",
                  (unsigned long)bits);
        return -1;
    }
    if (compression != BMP_RGB && bits != 16 && bits != 32) {
        error_set(err, name, "BMP: colour masks with %lu bits a pixel (expected 16 or 32)",
                  (unsigned long)bits);
        return -1;
    }
    /* Where each channel is. */
    if (compression != BMP_RGB) {
        /* The masks follow a 40-byte header, or are its V2+ fields. */
        size_t at = BMP_FILE_HEADER + BMP_INFO;
        if (len < at + 12) {
            error_set(err, name, "BMP: the file ends before its colour masks");
            return -1;
        }
        for (int c = 0; c < 3; c++)
            ch[c] = bmp_channel(bmp_u32(data + at + 4 * (size_t)c));
    } else if (bits == 16) {
        ch[0] = bmp_channel(0x7c00);
        ch[1] = bmp_channel(0x03e0);
        ch[2] = bmp_channel(0x001f);
    } else {
        ch[0] = bmp_channel(0xff0000);
        ch[1] = bmp_channel(0x00ff00);
        ch[2] = bmp_channel(0x0000ff);
    }
    if (bits <= 8) {
        size_t at = BMP_FILE_HEADER + header, room;
        palette_count = colours ? colours : (size_t)1 << bits;
        room = offset > at ? (offset - at) / (size_t)palette_entry : 0;
        if (palette_count > ((size_t)1 << bits))
            palette_count = (size_t)1 << bits;
        if (palette_count > room)
            palette_count = room;
        if (palette_count == 0 || at + palette_count * (size_t)palette_entry > len) {
            error_set(err, name, "BMP: an image of %lu bits a pixel without its palette",
                      (unsigned long)bits);
            return -1;
        }
        palette = data + at;
    }
    stride = (((size_t)w * bits + 31) / 32) * 4;
    if (offset > len || (len - offset) / stride < (size_t)h) {
        error_set(err, name, "BMP: the file ends before its %lld rows of pixels (%zu bytes each)",
                  (long long)h, stride);
        return -1;
    }
    img->rgb = malloc(3 * (size_t)w * (size_t)h);
    if (!img->rgb) {
        error_set(err, name, "out of memory for a %lld x %lld image", (long long)w,
                  (long long)h);
        return -1;
    }
    img->width = (int)w;
    img->height = (int)h;
    img->bits = (int)bits;
    for (int64_t y = 0; y < h; y++) {
        const unsigned char *row = data + offset + (size_t)(top_down ? y : h - 1 - y) * stride;
        unsigned char *out = img->rgb + 3 * (size_t)y * (size_t)w;
        for (int64_t x = 0; x < w; x++, out += 3) {
            if (bits <= 8) {
                size_t bit = (size_t)x * bits, k;
                k = (size_t)(row[bit / 8] >> (8 - bits - bit % 8)) & (((size_t)1 << bits) - 1);
                if (k >= palette_count)
                    k = 0; /* an index past the palette: its first colour */
                out[0] = palette[k * (size_t)palette_entry + 2];
                out[1] = palette[k * (size_t)palette_entry + 1];
                out[2] = palette[k * (size_t)palette_entry];
            } else if (bits == 24) {
                const unsigned char *p = row + 3 * (size_t)x;
                out[0] = p[2];
                out[1] = p[1];
                out[2] = p[0];
            } else {
                uint32_t px = bits == 16 ? bmp_u16(row + 2 * (size_t)x) : bmp_u32(row + 4 * (size_t)x);
                for (int c = 0; c < 3; c++)
                    out[c] = bmp_scale(&ch[c], px);
            }
        }
    }
    return 0;
}
