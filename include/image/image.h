/*
 * image.h: the rendered picture, as 8-bit RGB bytes.
 *
 * Layout contract: rows top to bottom, pixels left to right within a row,
 * three interleaved bytes per pixel (red, green, blue); pixel (x, y) starts at
 * byte 3 * (y * width + x). Colours enter through image_set(), which
 * quantises with colour_quantise(), or, for an image gamma-encoded by
 * image_encode_gamma(), with colour_encode(). An image may also keep the colours
 * before quantising (image_keep_linear()), for formats that store them:
 * three floats per pixel, the same layout, on the scale 1.0 = 255.
 */
#ifndef RAYTRACE_IMAGE_H
#define RAYTRACE_IMAGE_H

#include <stddef.h>

#include "math/colour.h"

typedef struct {
    int width;          /* pixels per row, >= 1 */
    int height;         /* rows, >= 1 */
    unsigned char *rgb; /* 3 * width * height bytes, owned */
    float *linear;      /* 3 * width * height unclamped colours / 255, owned;
                           NULL unless image_keep_linear() was called */
    double *encode;     /* COLOUR_LEVELS - 1 thresholds of its encoding
                           (colour_encode()), owned; NULL: linear bytes */
    double gamma;       /* the encoding's gamma; 1 for linear bytes */
} Image;

/* Allocates a black width x height image; returns 0, or -1 when memory runs
 * out (the image is then empty and needs no image_free()). */
int image_init(Image *img, int width, int height);

/* Makes img also keep its colours before quantising; returns 0, or -1 when
 * memory runs out (the image is unchanged). */
int image_keep_linear(Image *img);

/* Makes img's bytes encode its colours with gamma: byte b stands for the
 * linear colour 255 (b / 255)^gamma, and a colour takes the nearest byte in
 * the encoded scale; returns 0, or -1 when memory runs out (the image is
 * unchanged). */
int image_encode_gamma(Image *img, double gamma);

/* Releases the pixels and leaves the image empty. */
void image_free(Image *img);

/* Returns the bytes the image needs: 3 * width * height. */
size_t image_size(int width, int height);

/* Stores colour c, quantised, at pixel (x, y). */
static inline void image_set(Image *img, int x, int y, Colour c)
{
    unsigned char *p = img->rgb + 3 * ((size_t)y * (size_t)img->width + (size_t)x);
    if (img->encode) {
        p[0] = colour_encode(img->encode, c.r);
        p[1] = colour_encode(img->encode, c.g);
        p[2] = colour_encode(img->encode, c.b);
    } else {
        p[0] = colour_quantise(c.r);
        p[1] = colour_quantise(c.g);
        p[2] = colour_quantise(c.b);
    }
    if (img->linear) {
        float *f = img->linear + (p - img->rgb);
        f[0] = (float)(c.r / 255);
        f[1] = (float)(c.g / 255);
        f[2] = (float)(c.b / 255);
    }
}

/* Stores colour c at every pixel of [x0, x1) x [y0, y1) (not empty), as
 * image_set() would at each, quantising once. */
void image_fill(Image *img, int x0, int y0, int x1, int y1, Colour c);

#endif
