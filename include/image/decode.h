/*
 * decode.h: one reader for every image format raytrace reads, told apart
 * by the file's first bytes, never by its name: PPM (P3, P6, any maxval),
 * PFM, PNG, JPEG and BMP (each decoded by its own module: ppm.h, pfm.h,
 * png.h, jpeg.h, bmp.h). Textures, raytrace-diff and raytrace-merge read
 * images through it alone.
 */
#ifndef RAYTRACE_DECODE_H
#define RAYTRACE_DECODE_H

#include <stddef.h>

#include "base/error.h"

enum { DECODED_WARNING_MAX = 200 };

/* A decoded image: integer samples (every format but PFM) or linear
 * colours (PFM), rows top to bottom, R, G, B interleaved. */
typedef struct {
    int width, height;        /* pixels */
    unsigned short *samples;  /* 3 * width * height samples, 0..maxval; NULL
                                 for a PFM; owned */
    int maxval;               /* the samples' full scale: a PPM's maxval, 255
                                 for the others */
    float *linear;            /* a PFM's 3 * width * height colours, 1.0 for
                                 full scale; NULL for the others; owned */
    char format[48];          /* what the file was, for reports ("PNG, 4
                                 channels", "PPM P6, maxval 255") */
    char warning[DECODED_WARNING_MAX]; /* damage the decoder passed over (a
                                 JPEG's), or "" */
} Decoded;

/* Decodes the len bytes at data (errors naming name) into *out, of
 * whichever format their first bytes say (a file that starts with P
 * and is no PFM as a PPM, whose reader says what is wrong); a JPEG's
 * buffers within max_bytes (0: no limit). Returns 0, or -1 with *err set. Free with decoded_free(). */
int decoded_parse(const char *name, const char *data, size_t len, size_t max_bytes,
                  Decoded *out, Error *err);

/* decoded_parse() on the file at path. */
int decoded_read(const char *path, size_t max_bytes, Decoded *out, Error *err);

/* Says whether the len bytes at data are a PFM file's (linear colours). */
int decoded_is_linear(const char *data, size_t len);

/* Releases what *d owns. */
void decoded_free(Decoded *d);

#endif
