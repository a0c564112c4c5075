/*
 * ppm.h: Netpbm PPM files: the P6 writer for renders, and a reader of P6 and
 * P3 for comparing them.
 *
 * The writer knows nothing of scenes: it takes bytes laid out as image.h
 * describes (rows top to bottom, interleaved R, G, B, one byte each) and
 * writes exactly the header "P6\n<width> <height>\n255\n" followed by them.
 */
#ifndef RAYTRACE_PPM_H
#define RAYTRACE_PPM_H

#include <stddef.h>
#include <stdio.h>

#include "base/error.h"

/* Writes a P6 image of width x height pixels from rgb to f, with the
 * one-line comment note after the magic number unless it is NULL; returns
 * 0, or -1 with errno set when a write fails (the caller closes f either
 * way). */
int ppm_write(FILE *f, int width, int height, const unsigned char *rgb, const char *note);

/* Writes the same image as ASCII P3 ("P3\n<width> <height>\n255\n", then
 * the samples in decimal, one pixel's three a group, at most 70 characters
 * a line); returns 0, or -1 with errno set. */
int ppm_write_ascii(FILE *f, int width, int height, const unsigned char *rgb, const char *note);

typedef struct {
    int width;               /* pixels per row */
    int height;              /* rows */
    int maxval;              /* largest sample value, 1..65535 */
    unsigned short *samples; /* 3 * width * height samples, rows top to
                                bottom, interleaved R, G, B; owned */
} PpmImage;

/* Decodes the P6 or P3 file in the len bytes at data (errors naming
 * name) into *img; returns 0, or -1 with *err describing what is wrong and
 * where. Free the result with ppm_free(). */
int ppm_parse(const char *name, const char *data, size_t len, PpmImage *img, Error *err);

/* Releases the samples of *img. */
void ppm_free(PpmImage *img);

#endif
