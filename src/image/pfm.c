/* pfm.c: PFM writing and reading (see pfm.h). */
#include "image/pfm.h"

#include <ctype.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>


int pfm_write(FILE *f, int width, int height, const float *rgb, const char *note)
{
    size_t row = 3 * (size_t)width;
    unsigned char *buf = malloc(4 * row);

    if (!buf)
        return -1;
    if (fprintf(f, "PF\n%d %d\n-1.0\n", width, height) < 0) {
        free(buf);
        return -1;
    }
    for (int y = height - 1; y >= 0; y--) {
        const float *src = rgb + (size_t)y * row;
        for (size_t i = 0; i < row; i++) {
            uint32_t bits;
            memcpy(&bits, &src[i], 4);
            buf[4 * i] = (unsigned char)bits;
            buf[4 * i + 1] = (unsigned char)(bits >> 8);
            buf[4 * i + 2] = (unsigned char)(bits >> 16);
            buf[4 * i + 3] = (unsigned char)(bits >> 24);
        }
        if (fwrite(buf, 1, 4 * row, f) != 4 * row) {
            free(buf);
            return -1;
        }
    }
    free(buf);
    /* PFM has no comments: a note follows the pixels, which readers stop
     * before. */
    if (note && fprintf(f, "\n# %s\n", note) < 0)
        return -1;
    return 0;
}

void pfm_free(PfmImage *img)
{
    free(img->rgb);
    memset(img, 0, sizeof *img);
}

/* Reads a header field (a token ending at whitespace) at *p into buf. */
static int pfm_token(const char **p, const char *end, char *buf, size_t size)
{
    size_t n = 0;

    while (*p < end && isspace((unsigned char)**p))
        (*p)++;
    while (*p < end && !isspace((unsigned char)**p) && n + 1 < size)
        buf[n++] = *(*p)++;
    buf[n] = '\0';
    return n > 0 && (*p == end || isspace((unsigned char)**p)) ? 0 : -1;
}

int pfm_parse(const char *name, const char *data, size_t n, PfmImage *img, Error *err)
{
    char tok[64], *endp;
    const char *p, *end;
    size_t count;
    long w, h;
    double scale;
    int big;

    memset(img, 0, sizeof *img);
    p = data;
    end = data + n;
    if (n < 2 || data[0] != 'P' || (data[1] != 'F' && data[1] != 'f')) {
        error_set(err, name, "not a PFM file: expected 'PF' or 'Pf' at the start");
        goto fail;
    }
    img->channels = data[1] == 'F' ? 3 : 1;
    p += 2;
    if (pfm_token(&p, end, tok, sizeof tok) != 0 || (w = strtol(tok, &endp, 10)) < 1 ||
        *endp || pfm_token(&p, end, tok, sizeof tok) != 0 ||
        (h = strtol(tok, &endp, 10)) < 1 || *endp || w > 1 << 20 || h > 1 << 20) {
        error_set(err, name, "bad PFM header: expected a width and a height of 1 or more");
        goto fail;
    }
    if (pfm_token(&p, end, tok, sizeof tok) != 0 || (scale = strtod(tok, &endp), *endp) ||
        !(scale != 0) || !isfinite(scale)) {
        error_set(err, name, "bad PFM header: expected a non-zero scale (its sign gives the "
                             "byte order)");
        goto fail;
    }
    big = scale > 0;
    p++; /* the one whitespace byte before the data */
    count = (size_t)w * (size_t)h * (size_t)img->channels;
    if (p > end || (size_t)(end - p) / 4 < count) {
        error_set(err, name, "truncated PFM data: a %ld x %ld image needs %zu bytes", w, h,
                  4 * count);
        goto fail;
    }
    img->width = (int)w;
    img->height = (int)h;
    img->rgb = malloc(3 * (size_t)w * (size_t)h * sizeof *img->rgb);
    if (!img->rgb) {
        error_set(err, name, "out of memory for a %ld x %ld image", w, h);
        goto fail;
    }
    for (size_t k = 0; k < count; k++) {
        const unsigned char *b = (const unsigned char *)p + 4 * k;
        uint32_t bits = big ? (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3]
                            : (uint32_t)b[3] << 24 | (uint32_t)b[2] << 16 | (uint32_t)b[1] << 8 | b[0];
        size_t pix = k / (size_t)img->channels, c = k % (size_t)img->channels;
        size_t x = pix % (size_t)w, y = (size_t)h - 1 - pix / (size_t)w;
        float v;

        memcpy(&v, &bits, 4);
        for (size_t j = c; j < 3; j += (size_t)img->channels == 1 ? 1 : 3)
            img->rgb[3 * (y * (size_t)w + x) + j] = v;
    }
    return 0;
fail:
    pfm_free(img);
    return -1;
}
