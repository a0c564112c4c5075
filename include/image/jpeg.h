/*
 * jpeg.h: JPEG files (ITU-T T.81, JFIF), read (jpeg.c) and written
 * (jpeg_write.c) without a library.
 *
 * The reader takes Huffman-coded 8-bit JPEGs, baseline, extended
 * sequential and progressive, greyscale (one component) or YCbCr (three;
 * RGB when an Adobe marker or the components' names say so), any sampling
 * factors whose ratios to the largest are whole, restart markers, any size,
 * and turns the image as an Exif orientation tag says. Its pixels are those
 * of libjpeg's default decoder: the same integer inverse DCT (Loeffler,
 * Ligtenberg and Moschytz's, 13-bit constants), the same "fancy" triangle
 * upsampling of chroma halved across or down (nearest for other ratios),
 * the same fixed-point YCbCr conversion (JFIF's). Arithmetic coding,
 * lossless and hierarchical modes, 12-bit samples and four components
 * (CMYK) are refused with an error that names them. The output is 8-bit RGB,
 * rows top to bottom.
 *
 * Damage libjpeg passes over with a warning, the reader passes over alike,
 * with libjpeg's pixels, and says so in the image's warning: bytes between
 * segments, a missing end marker, a file cut short (what is missing is
 * grey), entropy-coded data that is damaged (a bad Huffman code decodes as
 * 0, a coefficient past the block's end lands on its last, data that runs
 * out leaves the rest of its restart interval grey) and found again at the
 * next restart marker as libjpeg's resynchronisation finds it.
 */
#ifndef RAYTRACE_JPEG_H
#define RAYTRACE_JPEG_H

#include <stddef.h>
#include <stdio.h>

#include "base/error.h"

enum { JPEG_WARNING_MAX = 200 }; /* room for a warning */

typedef struct {
    int width, height;  /* pixels, after the Exif orientation */
    int channels;       /* components in the file: 1 or 3 */
    unsigned char *rgb; /* 3 * width * height bytes, owned */
    char warning[JPEG_WARNING_MAX]; /* the first damage passed over ("at
                           byte N: ...", and how many more), or "" */
} JpegImage;

/* Decodes the JPEG file in the len bytes at data (errors naming name)
 * into *img, its buffers taking at most max_bytes (0: no limit); returns
 * 0, or -1 with *err saying what is wrong and where. Free with
 * jpeg_free(). */
int jpeg_parse(const char *name, const unsigned char *data, size_t len, size_t max_bytes,
               JpegImage *img, Error *err);

/* Releases img's pixels. */
void jpeg_free(JpegImage *img);

/* Writes the width x height image rgb (8-bit RGB, rows top to bottom) to f
 * as a baseline JFIF file: quality 1 to 100 (libjpeg's scaling of T.81's
 * example quantisers), chroma halved both ways (4:2:0) when subsample is
 * 1, else kept whole (4:4:4); Huffman tables made for the image (T.81
 * annex K.2). Returns 0, or -1 with errno set. */
int jpeg_write(FILE *f, int width, int height, const unsigned char *rgb, int quality,
               int subsample);

/* Returns the bytes jpeg_write() allocates for such an image. */
size_t jpeg_write_memory(int width, int height, int subsample);

/* Says whether the len bytes at data start like a JPEG file (SOI). */
int jpeg_is(const unsigned char *data, size_t len);

#endif
