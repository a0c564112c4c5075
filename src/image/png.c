/* png.c: PNG writing and reading (see png.h). */
#include "image/png.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>


static const unsigned char png_signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

enum { PNG_IDAT_MAX = 1 << 20 }; /* bytes per IDAT chunk written */

uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n)
{
    static uint32_t table[256];
    static int ready;

    /* The table is the same whoever fills it first, word for word. */
    if (!ready) {
        for (uint32_t k = 0; k < 256; k++) {
            uint32_t c = k;
            for (int j = 0; j < 8; j++)
                c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
            table[k] = c;
        }
        ready = 1;
    }
    crc = ~crc;
    while (n--)
        crc = table[(crc ^ *p++) & 0xff] ^ (crc >> 8);
    return ~crc;
}

static void png_put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static uint32_t png_get32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* Writes one chunk: length, type, data, CRC of type and data. */
static int png_chunk(FILE *f, const char *type, const unsigned char *data, size_t n)
{
    unsigned char head[8], tail[4];
    uint32_t crc = png_crc32(0, (const unsigned char *)type, 4);

    png_put32(head, (uint32_t)n);
    memcpy(head + 4, type, 4);
    png_put32(tail, png_crc32(crc, data, n));
    return fwrite(head, 1, 8, f) == 8 && (n == 0 || fwrite(data, 1, n, f) == n) &&
                   fwrite(tail, 1, 4, f) == 4
               ? 0
               : -1;
}

/* The Paeth predictor: of left a, up b and up-left c, the one nearest
 * a + b - c. */
static int png_paeth(int a, int b, int c)
{
    int p = a + b - c, pa = abs(p - a), pb = abs(p - b), pc = abs(p - c);
    return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

/* Returns filter type f's residual of byte i of row (prev: the row above,
 * or NULL), bpp bytes a pixel. */
static unsigned char png_residual(int f, const unsigned char *row, const unsigned char *prev,
                                  size_t i, size_t bpp)
{
    int x = row[i], a = i >= bpp ? row[i - bpp] : 0, b = prev ? prev[i] : 0;
    int c = prev && i >= bpp ? prev[i - bpp] : 0;

    switch (f) {
    case 1:
        return (unsigned char)(x - a);
    case 2:
        return (unsigned char)(x - b);
    case 3:
        return (unsigned char)(x - (a + b) / 2);
    case 4:
        return (unsigned char)(x - png_paeth(a, b, c));
    default:
        return (unsigned char)x;
    }
}

/* Filters every row into out (1 + 3 width bytes a row), each with the
 * filter of least sum of |residual| read as signed bytes, or with none when
 * choose is 0 (for stored blocks, which filtering cannot shrink). */
static void png_filter(const unsigned char *rgb, int width, int height, int choose,
                       unsigned char *out)
{
    size_t stride = 3 * (size_t)width;

    for (int y = 0; y < height; y++) {
        const unsigned char *row = rgb + (size_t)y * stride;
        const unsigned char *prev = y > 0 ? row - stride : NULL;
        unsigned char *dst = out + (size_t)y * (stride + 1);
        unsigned long best_sum = (unsigned long)-1;
        int best = 0;

        for (int f = 0; f < (choose ? 5 : 1); f++) {
            unsigned long sum = 0;
            for (size_t i = 0; i < stride; i++) {
                int r = (signed char)png_residual(f, row, prev, i, 3);
                sum += (unsigned long)abs(r);
            }
            if (sum < best_sum) {
                best_sum = sum;
                best = f;
            }
        }
        dst[0] = (unsigned char)best;
        for (size_t i = 0; i < stride; i++)
            dst[1 + i] = png_residual(best, row, prev, i, 3);
    }
}

int png_write(FILE *f, int width, int height, const unsigned char *rgb, DeflateMode mode,
              const char *note)
{
    size_t raw_len = (3 * (size_t)width + 1) * (size_t)height;
    unsigned char *raw = malloc(raw_len), ihdr[13];
    ByteBuf z = {0};
    int rc = -1;

    if (!raw) {
        errno = ENOMEM;
        return -1;
    }
    png_filter(rgb, width, height, mode != DEFLATE_STORED, raw);
    if (deflate_zlib(&z, raw, raw_len, mode) != 0) {
        errno = ENOMEM;
        goto done;
    }
    png_put32(ihdr, (uint32_t)width);
    png_put32(ihdr + 4, (uint32_t)height);
    ihdr[8] = 8;  /* bits per sample */
    ihdr[9] = 2;  /* colour type: RGB */
    ihdr[10] = 0; /* deflate */
    ihdr[11] = 0; /* adaptive filtering */
    ihdr[12] = 0; /* not interlaced */
    if (fwrite(png_signature, 1, 8, f) != 8 || png_chunk(f, "IHDR", ihdr, 13) != 0)
        goto done;
    if (note) {
        size_t n = strlen(note);
        unsigned char *text = malloc(8 + n);
        int bad;
        if (!text) {
            errno = ENOMEM;
            goto done;
        }
        memcpy(text, "Comment", 8); /* the keyword and its NUL */
        memcpy(text + 8, note, n);
        bad = png_chunk(f, "tEXt", text, 8 + n) != 0;
        free(text);
        if (bad)
            goto done;
    }
    for (size_t off = 0; off < z.len; off += PNG_IDAT_MAX) {
        size_t n = z.len - off < PNG_IDAT_MAX ? z.len - off : PNG_IDAT_MAX;
        if (png_chunk(f, "IDAT", z.data + off, n) != 0)
            goto done;
    }
    if (png_chunk(f, "IEND", NULL, 0) != 0)
        goto done;
    rc = 0;
done:
    free(raw);
    bytebuf_free(&z);
    return rc;
}

void png_free(PngImage *img)
{
    free(img->rgb);
    img->rgb = NULL;
    img->width = img->height = img->channels = 0;
}

/* Undoes the filters of the height rows of raw (1 + stride bytes each) into
 * pixels (stride bytes a row), bpp bytes a pixel; returns the row with a bad
 * filter type, or -1 when all are good. */
static int png_unfilter(const unsigned char *raw, unsigned char *pixels, int height,
                        size_t stride, size_t bpp)
{
    for (int y = 0; y < height; y++) {
        const unsigned char *src = raw + (size_t)y * (stride + 1);
        unsigned char *row = pixels + (size_t)y * stride;
        const unsigned char *prev = y > 0 ? row - stride : NULL;
        int f = src[0];

        if (f > 4)
            return y;
        for (size_t i = 0; i < stride; i++) {
            int a = i >= bpp ? row[i - bpp] : 0, b = prev ? prev[i] : 0;
            int c = prev && i >= bpp ? prev[i - bpp] : 0, pred = 0;
            switch (f) {
            case 1:
                pred = a;
                break;
            case 2:
                pred = b;
                break;
            case 3:
                pred = (a + b) / 2;
                break;
            case 4:
                pred = png_paeth(a, b, c);
                break;
            }
            row[i] = (unsigned char)(src[1 + i] + pred);
        }
    }
    return -1;
}

/* Reads the chunks of the n bytes at data: checks IHDR into img and
 * gathers the IDAT data into z. */
static int png_chunks(const char *name, const unsigned char *data, size_t n, PngImage *img,
                      int *depth, ByteBuf *z, Error *err)
{
    size_t pos = 8;
    int seen_ihdr = 0;

    if (n < 8 || memcmp(data, png_signature, 8) != 0) {
        error_set(err, name, "not a PNG file: the 8-byte signature is missing");
        return -1;
    }
    for (;;) {
        uint32_t len;
        const unsigned char *type;

        if (n - pos < 12) {
            error_set(err, name, "the file ends inside a chunk, at byte %zu, before IEND", pos);
            return -1;
        }
        len = png_get32(data + pos);
        type = data + pos + 4;
        if (len > n - pos - 12) {
            error_set(err, name, "chunk '%.4s' at byte %zu is longer than the file", type, pos);
            return -1;
        }
        if (png_crc32(0, type, 4 + (size_t)len) != png_get32(data + pos + 8 + len)) {
            error_set(err, name, "chunk '%.4s' at byte %zu fails its CRC", type, pos);
            return -1;
        }
        if (!seen_ihdr && memcmp(type, "IHDR", 4) != 0) {
            error_set(err, name, "the first chunk is '%.4s', not IHDR", type);
            return -1;
        }
        if (memcmp(type, "IHDR", 4) == 0) {
            const unsigned char *h = type + 4;
            static const int channels[7] = {1, 0, 3, 0, 2, 0, 4};
            uint32_t w = png_get32(h), hh = png_get32(h + 4);
            if (len != 13 || w == 0 || hh == 0 || w > 0x7fffffff || hh > 0x7fffffff) {
                error_set(err, name, "IHDR is malformed");
                return -1;
            }
            if (h[9] > 6 || channels[h[9]] == 0 || h[8] != 8 || h[12] != 0) {
                error_set(err, name,
                          "unsupported PNG: bit depth %d, colour type %d, interlace %d (8-bit "
                          "grey, grey+alpha, RGB or RGBA, not interlaced, is read)",
                          h[8], h[9], h[12]);
                return -1;
            }
            img->width = (int)w;
            img->height = (int)hh;
            img->channels = channels[h[9]];
            *depth = h[8];
            seen_ihdr = 1;
        } else if (memcmp(type, "IDAT", 4) == 0) {
            bytebuf_append(z, type + 4, len);
        } else if (memcmp(type, "IEND", 4) == 0) {
            return 0;
        } else if (!(type[0] & 0x20)) {
            error_set(err, name, "unknown critical chunk '%.4s' at byte %zu", type, pos);
            return -1;
        }
        pos += 12 + (size_t)len;
    }
}

int png_parse(const char *name, const unsigned char *data, size_t n, PngImage *img, Error *err)
{
    char msg[200];
    size_t stride, npix;
    ByteBuf z = {0}, raw = {0};
    unsigned char *pixels = NULL;
    int depth = 0, rc = -1, bad;

    memset(img, 0, sizeof *img);
    if (png_chunks(name, data, n, img, &depth, &z, err) != 0)
        goto done;
    stride = (size_t)img->width * (size_t)img->channels;
    if ((size_t)img->height > ((size_t)-1 / 4) / (stride + 1)) {
        error_set(err, name, "image too large: %d x %d", img->width, img->height);
        goto done;
    }
    raw.max = (stride + 1) * (size_t)img->height;
    if (inflate_zlib(&raw, z.data, z.len, msg, sizeof msg) != 0) {
        error_set(err, name, "the image data is corrupt: %s", msg);
        goto done;
    }
    if (raw.len != (stride + 1) * (size_t)img->height) {
        error_set(err, name, "the image data holds %zu bytes, a %d x %d image needs %zu",
                  raw.len, img->width, img->height, (stride + 1) * (size_t)img->height);
        goto done;
    }
    pixels = malloc(stride * (size_t)img->height);
    npix = (size_t)img->width * (size_t)img->height;
    img->rgb = malloc(3 * npix);
    if (!pixels || !img->rgb) {
        error_set(err, name, "out of memory for a %d x %d image", img->width, img->height);
        goto done;
    }
    bad = png_unfilter(raw.data, pixels, img->height, stride, (size_t)img->channels);
    if (bad >= 0) {
        error_set(err, name, "row %d has an unknown filter type", bad);
        goto done;
    }
    for (size_t k = 0; k < npix; k++) {
        const unsigned char *p = pixels + k * (size_t)img->channels;
        int grey = img->channels < 3;
        img->rgb[3 * k] = p[0];
        img->rgb[3 * k + 1] = grey ? p[0] : p[1];
        img->rgb[3 * k + 2] = grey ? p[0] : p[2];
    }
    rc = 0;
done:
    if (rc != 0)
        png_free(img);
    (void)depth;
    free(pixels);
    bytebuf_free(&z);
    bytebuf_free(&raw);
    return rc;
}
