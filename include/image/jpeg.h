/*
 * jpeg.h: JPEG files (ITU-T T.81, JFIF), read and written without a
 * library.
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
 */
#ifndef RAYTRACE_JPEG_H
#define RAYTRACE_JPEG_H

#include <stddef.h>
#include <stdio.h>

#include "base/error.h"

typedef struct {
    int width, height;  /* pixels, after the Exif orientation */
    int channels;       /* components in the file: 1 or 3 */
    unsigned char *rgb; /* 3 * width * height bytes, owned */
} JpegImage;

/* Reads the JPEG file at path into *img, its buffers taking at most
 * max_bytes (0: no limit); returns 0, or -1 with *err saying what is wrong
 * and where. Free with jpeg_free(). */
int jpeg_read(const char *path, size_t max_bytes, JpegImage *img, Error *err);

/* jpeg_read() on the len bytes at data, errors naming name. */
int jpeg_parse(const char *name, const unsigned char *data, size_t len, size_t max_bytes,
               JpegImage *img, Error *err);

/* Releases img's pixels. */
void jpeg_free(JpegImage *img);

/* Says whether the len bytes at data start like a JPEG file (SOI). */
int jpeg_is(const unsigned char *data, size_t len);

#endif
