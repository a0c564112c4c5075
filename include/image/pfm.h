/*
 * pfm.h: Portable FloatMap files: linear, unclamped colours for accuracy
 * work.
 *
 * The header is "PF\n<width> <height>\n-1.0\n" (PF: three channels; a
 * negative scale: little-endian floats), then width x height pixels of three
 * 32-bit floats, rows from the BOTTOM of the image to the top, as the format
 * requires. raytrace writes colours on the scale 1.0 = 255 of the 8-bit
 * output, unclamped. The reader also takes "Pf" (one channel) and
 * big-endian files (a positive scale).
 */
#ifndef RAYTRACE_PFM_H
#define RAYTRACE_PFM_H

#include <stdio.h>

#include "base/error.h"

/* Writes the width x height image of 3 floats a pixel (rows top to bottom
 * in memory) to f, and after the pixels a newline and "# NOTE" unless note is
 * NULL (a tile's record: PFM has no comments, and readers stop at the
 * pixels' end); returns 0, or -1 with errno set. */
int pfm_write(FILE *f, int width, int height, const float *rgb, const char *note);

typedef struct {
    int width, height; /* pixels */
    int channels;      /* channels in the file: 1 or 3 */
    float *rgb;        /* 3 * width * height floats, rows top to bottom, owned */
} PfmImage;

/* Decodes the PFM file in the len bytes at data (errors naming name)
 * into *img; returns 0, or -1 with *err saying what is wrong. Free with
 * pfm_free(). */
int pfm_parse(const char *name, const char *data, size_t len, PfmImage *img, Error *err);

/* Releases img's pixels. */
void pfm_free(PfmImage *img);

#endif
