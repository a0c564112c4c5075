/*
 * compare.h: two renders side by side: what differs, where, and by how much.
 *
 * Images of any format raytrace reads (PPM P3/P6 of any maxval, PFM, PNG,
 * JPEG, BMP)
 * are loaded as Pictures: linear RGB on the scale 0..255 of an 8-bit image
 * (PPM samples times 255 / maxval, PFM values times 255), so that a
 * tolerance is in 8-bit levels whatever the formats.
 */
#ifndef RAYTRACE_COMPARE_H
#define RAYTRACE_COMPARE_H

#include <stddef.h>

#include "base/error.h"
#include "image/image.h"

typedef struct {
    int width, height;  /* pixels */
    char format[48];    /* "PPM P6, maxval 255", "PNG", "PFM"... for reports */
    double *rgb;        /* 3 * width * height values, rows top to bottom, owned */
    char warning[200];  /* damage its decoder passed over (a JPEG's), or "" */
} Picture;

/* Reads the image file at path, of whichever format its first bytes say,
 * into *pic; returns 0, or -1 with *err saying why. */
int picture_load(const char *path, Picture *pic, Error *err);

/* picture_load() on the len bytes at data, errors naming name. */
int picture_parse(const char *name, const char *data, size_t len, Picture *pic, Error *err);

/* Replaces pic by its box-filtered width x height copy (1 <= width <=
 * pic's width, likewise height): box (i, j) is the mean of the pixels
 * whose columns run from floor(i W / width) to floor((i + 1) W / width)
 * and rows likewise (W x H pic's size); returns 0, or -1 with *err set
 * when memory runs out (pic unchanged). */
int picture_box(Picture *pic, int width, int height, Error *err);

/* Clamps every value of pic to 0..255, as an 8-bit image shows it (a
 * PFM's unclamped colours against an 8-bit render). */
void picture_clamp(Picture *pic);

/* Replaces pic by its pixels that are not black in mask (of pic's size),
 * in reading order, as one row; returns 0, or -1 with *err set when
 * memory runs out or none is left (pic unchanged). */
int picture_select(Picture *pic, const Picture *mask, Error *err);

/* Releases pic's pixels. */
void picture_free(Picture *pic);

/* What compare_pictures() finds. */
typedef struct {
    double max_error;    /* largest |a - b| over all channels */
    int max_x, max_y;    /* the pixel where it is (the first, in reading order) */
    int max_channel;     /* 0 red, 1 green, 2 blue */
    double mean_error;   /* mean |a - b| over all channels */
    double rms_error;    /* root mean square of a - b */
    double psnr;         /* 20 log10(255 / rms_error), dB; infinite when equal */
    size_t over;         /* pixels with some channel more than tolerance apart */
    size_t channels_over; /* channels more than tolerance apart */
    size_t pixels;       /* pixels compared */
    double worst;        /* the error 1% of pixels pass: a pixel's error the
                            RMS over its channels, rounded up to a sixteenth
                            of a level; COMPARE_WORST_CAP when past it */
} Comparison;

/* The largest error Comparison.worst resolves, in levels. */
#define COMPARE_WORST_CAP 256

/* Compares two pictures of the same size, a pixel being over when some
 * channel differs by more than tolerance. */
Comparison compare_pictures(const Picture *a, const Picture *b, double tolerance);

/* Fills img (sized like a) with a darkened grey copy of a on which the
 * pixels over tolerance are pure red. */
void compare_diff_image(const Picture *a, const Picture *b, double tolerance, Image *img);

#endif
