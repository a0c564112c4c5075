/*
 * bmp.h: Windows bitmap (BMP) files: reading them, as textures and as
 * pictures to compare (the MPL ray tracer saved its renders as BMP,
 * whatever their names said), and writing renders as the plainest BMP,
 * which every Windows viewer opens.
 *
 * The reader takes the headers of every Windows version (BITMAPCOREHEADER,
 * BITMAPINFOHEADER and its V2 to V5 extensions, OS/2's 64-byte one) with
 * uncompressed pixels of 1, 4, 8 (a palette), 16, 24 or 32 bits, their
 * channels at the default places or where BI_BITFIELDS masks put them,
 * rows bottom to top or, with a negative height, top to bottom. It returns
 * 8-bit RGB, rows top to bottom; alpha is dropped. Run-length encoded and
 * embedded JPEG or PNG bitmaps are refused with a message that says so.
 */
#ifndef RAYTRACE_BMP_H
#define RAYTRACE_BMP_H

#include <stddef.h>
#include <stdio.h>

#include "base/error.h"

typedef struct {
    int width, height;  /* pixels */
    int bits;           /* bits a pixel in the file: 1, 4, 8, 16, 24 or 32 */
    unsigned char *rgb; /* 3 * width * height bytes, rows top to bottom,
                           owned */
} BmpImage;

/* Says whether the len bytes at data start as a BMP file does ("BM"). */
int bmp_is(const unsigned char *data, size_t len);

/* Reads the BMP file in the len bytes at data into *img; returns 0, or -1
 * with *err, naming name, saying what is wrong. Free with bmp_free(). */
int bmp_parse(const char *name, const unsigned char *data, size_t len, BmpImage *img,
              Error *err);

/* Releases img's pixels. */
void bmp_free(BmpImage *img);

/* Writes the width x height pixels at rgb (rows top to bottom, 3 bytes a
 * pixel) to f as a 24-bit BMP: BITMAPINFOHEADER, rows bottom to top, each
 * padded to 4 bytes, 72 dpi. Returns 0, or -1 with errno set when a write
 * fails. */
int bmp_write(FILE *f, int width, int height, const unsigned char *rgb);

#endif
