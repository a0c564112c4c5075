/*
 * writer.h: the last step of the pipeline: an Image to a file, in the format
 * the user asked for.
 *
 * Every lossless format holds the same pixels: PPM and PNG the 8-bit bytes,
 * PFM the colours before quantising (on the scale 1.0 = 255), which round
 * to those bytes. JPEG holds an approximation of the 8-bit bytes.
 */
#ifndef RAYTRACE_WRITER_H
#define RAYTRACE_WRITER_H

#include <stdio.h>

#include "image/deflate.h"
#include "image/image.h"

typedef enum {
    FORMAT_PPM, /* binary P6, or ASCII P3 with ascii set */
    FORMAT_PNG, /* 8-bit RGB PNG */
    FORMAT_PFM, /* linear float RGB */
    FORMAT_JPEG, /* baseline JPEG: lossy, smaller */
    FORMAT_BMP   /* 24-bit Windows bitmap */
} ImageFormat;

/* The formats written and their extensions, for messages. */
#define WRITER_FORMATS "PPM (.ppm), PNG (.png), PFM (.pfm), JPEG (.jpg, .jpeg) and BMP (.bmp)"

typedef struct {
    ImageFormat format;
    int ascii;              /* PPM: P3 instead of P6 */
    DeflateMode png_deflate; /* PNG: how to compress */
    int jpeg_quality;       /* JPEG: 1..100 */
    int jpeg_444;           /* JPEG: 1 keeps chroma whole (4:4:4), 0 halves
                               it both ways (4:2:0) */
    const char *note;       /* PPM, PNG and PFM: a line of text the file
                               keeps (a tile's record, tile.h), or NULL */
} WriterOptions;

/* Returns the format named name ("ppm", "png", "pfm", "jpeg", "jpg" or
 * "bmp"), or -1. */
int writer_format_named(const char *name);

/* Returns the format path's extension names (.ppm, .pnm, .png, .pfm, .jpg,
 * .jpeg or .bmp, in any case), or FORMAT_PPM for any other name and for
 * "-". */
ImageFormat writer_format_for(const char *path);

/* Returns the name of the image format path's extension names when it is
 * one of the other image formats ("TIFF" for .tif or .tiff, "GIF", "WebP",
 * "OpenEXR", ...), which raytrace cannot write; NULL otherwise (a format it
 * writes, an extension of no image format, none). */
const char *writer_unwritable(const char *path);

/* Returns the bytes a width x height image takes in memory, and writing it
 * as opts say on top of that (PNG: its filtered rows and their compressed
 * stream; PFM: the linear colours). */
size_t writer_memory(const WriterOptions *opts, int width, int height);

/* Writes img to f as opts say; img must keep its linear colours for PFM.
 * Returns 0, or -1 with errno set. */
int writer_write(FILE *f, const Image *img, const WriterOptions *opts);

#endif
