/*
 * png.h: PNG files (ISO/IEC 15948), written and read without a library.
 *
 * The writer makes 8-bit RGB, non-interlaced files: each row filtered with
 * the filter of the five that gives the smallest sum of absolute residuals
 * (the usual heuristic), the whole compressed as one zlib stream
 * (deflate.h) in IDAT chunks of at most 1 MiB. The reader takes 8-bit
 * greyscale, grey + alpha, RGB and RGBA files, non-interlaced, and returns
 * RGB (alpha is dropped).
 */
#ifndef RAYTRACE_PNG_H
#define RAYTRACE_PNG_H

#include <stdint.h>
#include <stdio.h>

#include "base/error.h"
#include "image/deflate.h"

/* Writes the width x height image rgb (rows top to bottom, 3 bytes a
 * pixel) to f as a PNG compressed with mode, with note (unless NULL) as a
 * tEXt chunk of keyword "Comment" before the pixels; returns 0, or -1 with
 * errno set (ENOMEM when memory runs out). */
int png_write(FILE *f, int width, int height, const unsigned char *rgb, DeflateMode mode,
              const char *note);

typedef struct {
    int width, height;  /* pixels */
    int channels;       /* channels in the file: 1 to 4 */
    unsigned char *rgb; /* 3 * width * height bytes, owned */
} PngImage;

/* Decodes the PNG file in the len bytes at data (errors naming name) into
 * *img; returns 0, or -1 with *err saying what is wrong and at which byte.
 * Free with png_free(). */
int png_parse(const char *name, const unsigned char *data, size_t len, PngImage *img,
              Error *err);

/* Releases img's pixels. */
void png_free(PngImage *img);

/* Returns the CRC-32 of n bytes (as PNG and zlib define it), continuing
 * from crc (0 to start). */
uint32_t png_crc32(uint32_t crc, const unsigned char *p, size_t n);

#endif
