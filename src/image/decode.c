/* decode.c: every image format, by its first bytes (see decode.h). */
#include "image/decode.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "image/bmp.h"
#include "image/jpeg.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/ppm.h"

int decoded_is_linear(const char *data, size_t len)
{
    return len >= 2 && data[0] == 'P' && (data[1] == 'F' || data[1] == 'f');
}

/* Says whether the len bytes at data start as a PNG file does. */
static int decoded_is_png(const unsigned char *data, size_t len)
{
    return len >= 8 && data[0] == 0x89 && memcmp(data + 1, "PNG", 3) == 0;
}

/* Makes d's samples the 8-bit RGB bytes rgb of width x height; returns 0,
 * or -1 with *err set when memory runs out. */
static int decoded_bytes(Decoded *d, const char *name, int width, int height,
                         const unsigned char *rgb, Error *err)
{
    size_t n = 3 * (size_t)width * (size_t)height;

    d->samples = malloc(n * sizeof *d->samples);
    if (!d->samples) {
        error_set(err, name, "out of memory for a %d x %d image", width, height);
        return -1;
    }
    for (size_t k = 0; k < n; k++)
        d->samples[k] = rgb[k];
    d->width = width;
    d->height = height;
    d->maxval = 255;
    return 0;
}

/* The decoders whose images are 8-bit RGB bytes: JPEG, PNG, BMP. */
static int decoded_8bit(Decoded *d, const char *name, const unsigned char *head, size_t len,
                        size_t max_bytes, Error *err)
{
    int rc;

    if (jpeg_is(head, len)) {
        JpegImage jpg;
        if (jpeg_parse(name, head, len, max_bytes, &jpg, err) != 0)
            return -1;
        snprintf(d->warning, sizeof d->warning, "%s", jpg.warning);
        snprintf(d->format, sizeof d->format, "JPEG, %d component%s", jpg.channels,
                 jpg.channels == 1 ? "" : "s");
        rc = decoded_bytes(d, name, jpg.width, jpg.height, jpg.rgb, err);
        jpeg_free(&jpg);
        return rc;
    }
    if (decoded_is_png(head, len)) {
        PngImage png;
        if (png_parse(name, head, len, &png, err) != 0)
            return -1;
        snprintf(d->format, sizeof d->format, "PNG, %d channel%s", png.channels,
                 png.channels == 1 ? "" : "s");
        rc = decoded_bytes(d, name, png.width, png.height, png.rgb, err);
        png_free(&png);
        return rc;
    }
    {
        BmpImage bmp;
        if (bmp_parse(name, head, len, &bmp, err) != 0)
            return -1;
        snprintf(d->format, sizeof d->format, "BMP, %d bits a pixel", bmp.bits);
        rc = decoded_bytes(d, name, bmp.width, bmp.height, bmp.rgb, err);
        bmp_free(&bmp);
        return rc;
    }
}

int decoded_parse(const char *name, const char *data, size_t len, size_t max_bytes,
                  Decoded *out, Error *err)
{
    const unsigned char *head = (const unsigned char *)data;

    memset(out, 0, sizeof *out);
    if (jpeg_is(head, len) || decoded_is_png(head, len) || bmp_is(head, len))
        return decoded_8bit(out, name, head, len, max_bytes, err);
    if (decoded_is_linear(data, len)) {
        PfmImage pfm;
        if (pfm_parse(name, data, len, &pfm, err) != 0)
            return -1;
        out->width = pfm.width;
        out->height = pfm.height;
        out->linear = pfm.rgb; /* taken over */
        snprintf(out->format, sizeof out->format, "PFM, %d channel%s", pfm.channels,
                 pfm.channels == 1 ? "" : "s");
        return 0;
    }
    if (len < 1 || data[0] != 'P') {
        error_set(err, name,
                  "not an image raytrace reads: expected PPM (P3, P6), PFM, PNG, JPEG or BMP");
        return -1;
    }
    {
        PpmImage ppm;
        if (ppm_parse(name, data, len, &ppm, err) != 0)
            return -1;
        out->width = ppm.width;
        out->height = ppm.height;
        out->samples = ppm.samples; /* taken over */
        out->maxval = ppm.maxval;
        snprintf(out->format, sizeof out->format, "PPM P%c, maxval %d", data[1], ppm.maxval);
        return 0;
    }
}

int decoded_read(const char *path, size_t max_bytes, Decoded *out, Error *err)
{
    char *data;
    size_t len;
    int rc;

    memset(out, 0, sizeof *out);
    if (file_read_all(path, &data, &len, err) != 0)
        return -1;
    rc = decoded_parse(file_display_name(path), data, len, max_bytes, out, err);
    free(data);
    return rc;
}

void decoded_free(Decoded *d)
{
    free(d->samples);
    free(d->linear);
    d->samples = NULL;
    d->linear = NULL;
}
