/* compare.c: loading and comparing renders (see compare.h). */
#include "image/compare.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "image/decode.h"

void picture_clamp(Picture *pic)
{
    size_t n = 3 * (size_t)pic->width * (size_t)pic->height;

    for (size_t i = 0; i < n; i++)
        pic->rgb[i] = pic->rgb[i] > 0 ? (pic->rgb[i] < 255 ? pic->rgb[i] : 255) : 0;
}

int picture_select(Picture *pic, const Picture *mask, Error *err)
{
    size_t n = (size_t)pic->width * (size_t)pic->height, kept = 0;
    double *rgb;

    for (size_t i = 0; i < n; i++)
        kept += mask->rgb[3 * i] != 0 || mask->rgb[3 * i + 1] != 0 || mask->rgb[3 * i + 2] != 0;
    if (kept == 0 || kept > (size_t)INT_MAX) {
        error_set(err, "", kept ? "too many pixels" : "the mask is black: no pixel to compare");
        return -1;
    }
    rgb = malloc(3 * kept * sizeof *rgb);
    if (!rgb) {
        error_set(err, "", "out of memory");
        return -1;
    }
    kept = 0;
    for (size_t i = 0; i < n; i++)
        if (mask->rgb[3 * i] != 0 || mask->rgb[3 * i + 1] != 0 || mask->rgb[3 * i + 2] != 0) {
            memcpy(rgb + 3 * kept, pic->rgb + 3 * i, 3 * sizeof *rgb);
            kept++;
        }
    free(pic->rgb);
    pic->rgb = rgb;
    pic->width = (int)kept;
    pic->height = 1;
    return 0;
}

void picture_free(Picture *pic)
{
    free(pic->rgb);
    memset(pic, 0, sizeof *pic);
}

/* Allocates pic's pixels for a width x height image; returns 0 or -1. */
static int picture_alloc(Picture *pic, int width, int height, const char *name, Error *err)
{
    pic->width = width;
    pic->height = height;
    pic->rgb = malloc(3 * (size_t)width * (size_t)height * sizeof *pic->rgb);
    if (!pic->rgb) {
        error_set(err, name, "out of memory for a %d x %d image", width, height);
        return -1;
    }
    return 0;
}

int picture_load(const char *path, Picture *pic, Error *err)
{
    char *data;
    size_t len;
    int rc;

    memset(pic, 0, sizeof *pic);
    if (strcmp(path, "-") == 0) {
        error_set(err, "<stdin>", "images are compared from files, not standard input");
        return -1;
    }
    if (file_read_all(path, &data, &len, err) != 0)
        return -1;
    rc = picture_parse(path, data, len, pic, err);
    free(data);
    return rc;
}

int picture_parse(const char *name, const char *data, size_t len, Picture *pic, Error *err)
{
    Decoded d;
    size_t count;

    memset(pic, 0, sizeof *pic);
    if (decoded_parse(name, data, len, 0, &d, err) != 0)
        return -1;
    count = 3 * (size_t)d.width * (size_t)d.height;
    snprintf(pic->format, sizeof pic->format, "%s", d.format);
    snprintf(pic->warning, sizeof pic->warning, "%s", d.warning);
    if (picture_alloc(pic, d.width, d.height, name, err) == 0)
        for (size_t k = 0; k < count; k++)
            pic->rgb[k] = d.linear ? d.linear[k] * 255.0 : d.samples[k] * 255.0 / d.maxval;
    decoded_free(&d);
    return pic->rgb ? 0 : -1;
}

int picture_box(Picture *pic, int width, int height, Error *err)
{
    double *out = malloc(3 * (size_t)width * (size_t)height * sizeof *out);

    if (!out) {
        error_set(err, "", "out of memory for a %d x %d box filter", width, height);
        return -1;
    }
    for (int j = 0; j < height; j++) {
        int y0 = (int)((long long)j * pic->height / height);
        int y1 = (int)((long long)(j + 1) * pic->height / height);
        for (int i = 0; i < width; i++) {
            int x0 = (int)((long long)i * pic->width / width);
            int x1 = (int)((long long)(i + 1) * pic->width / width);
            double sum[3] = {0, 0, 0}, n = (double)(x1 - x0) * (y1 - y0);
            for (int y = y0; y < y1; y++)
                for (int x = x0; x < x1; x++)
                    for (int c = 0; c < 3; c++)
                        sum[c] += pic->rgb[3 * ((size_t)y * (size_t)pic->width + (size_t)x) + c];
            for (int c = 0; c < 3; c++)
                out[3 * ((size_t)j * (size_t)width + (size_t)i) + c] = sum[c] / n;
        }
    }
    free(pic->rgb);
    pic->rgb = out;
    pic->width = width;
    pic->height = height;
    return 0;
}

enum { COMPARE_STEPS = 16 }; /* worst's resolution: steps a level */

/* Returns the least error that at most 1% of the n pixels counted in
 * hist (hist[i]: pixels whose error rounds up to i steps) pass. */
static double compare_worst(const size_t *hist, size_t bins, size_t n)
{
    size_t keep = n - n / 100, seen = 0; /* pixels at or below the answer */

    for (size_t i = 0; i < bins; i++) {
        seen += hist[i];
        if (seen >= keep)
            return (double)i / COMPARE_STEPS;
    }
    return COMPARE_WORST_CAP;
}

Comparison compare_pictures(const Picture *a, const Picture *b, double tolerance)
{
    static const size_t bins = COMPARE_WORST_CAP * COMPARE_STEPS + 1;
    size_t hist[COMPARE_WORST_CAP * COMPARE_STEPS + 1] = {0};
    Comparison c;
    size_t n = (size_t)a->width * (size_t)a->height;
    double sum = 0, sum2 = 0;

    memset(&c, 0, sizeof c);
    c.pixels = n;
    c.max_error = -1;
    for (size_t k = 0; k < n; k++) {
        int over = 0;
        double pixel2 = 0, steps;
        for (int ch = 0; ch < 3; ch++) {
            double d = fabs(a->rgb[3 * k + ch] - b->rgb[3 * k + ch]);
            /* NaN in a PFM counts as the largest difference. */
            if (isnan(d))
                d = INFINITY;
            sum += d;
            sum2 += d * d;
            pixel2 += d * d;
            if (d > c.max_error) {
                c.max_error = d;
                c.max_x = (int)(k % (size_t)a->width);
                c.max_y = (int)(k / (size_t)a->width);
                c.max_channel = ch;
            }
            over |= d > tolerance;
            c.channels_over += d > tolerance;
        }
        c.over += over;
        steps = ceil(sqrt(pixel2 / 3) * COMPARE_STEPS);
        hist[steps < (double)(bins - 1) ? (size_t)steps : bins - 1]++;
    }
    c.worst = compare_worst(hist, bins, n);
    if (c.max_error < 0)
        c.max_error = 0;
    c.mean_error = n ? sum / (3.0 * n) : 0;
    c.rms_error = n ? sqrt(sum2 / (3.0 * n)) : 0;
    c.psnr = c.rms_error > 0 ? 20 * log10(255 / c.rms_error) : INFINITY;
    return c;
}

void compare_diff_image(const Picture *a, const Picture *b, double tolerance, Image *img)
{
    size_t n = (size_t)a->width * (size_t)a->height;

    for (size_t k = 0; k < n; k++) {
        const double *p = a->rgb + 3 * k, *q = b->rgb + 3 * k;
        int over = 0;
        for (int ch = 0; ch < 3; ch++)
            over |= !(fabs(p[ch] - q[ch]) <= tolerance);
        if (over) {
            image_set(img, (int)(k % (size_t)a->width), (int)(k / (size_t)a->width),
                      colour(255, 0, 0));
        } else {
            /* About a third of the reference's luminance, in grey. */
            double grey = 0.35 * (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
            image_set(img, (int)(k % (size_t)a->width), (int)(k / (size_t)a->width),
                      colour(grey, grey, grey));
        }
    }
}
