/*
 * texture.h: images that give a surface its colour.
 *
 * A texture is a grid of texels read once per scene (scenefile/
 * texture_file.h reads them from image files). It is addressed by texture coordinates (u, v): u runs left to right across the
 * image, v bottom to top, one image per unit; outside [0, 1) the image
 * repeats (v may be clamped instead, for spheres, whose poles are edges).
 */
#ifndef RAYTRACE_TEXTURE_H
#define RAYTRACE_TEXTURE_H

#include <stddef.h>

#include "geometry/material.h"
#include "math/colour.h"

typedef struct {
    int width, height;      /* texels, >= 1 each */
    unsigned short *texels; /* 3 * width * height samples, rows top to
                               bottom, interleaved R, G, B; owned */
    double scale;           /* 255 / the largest sample value: a sample
                               times scale is a colour, 0..255 */
    char *path;             /* the file it was read from, as the scene
                               names it; owned */
    char warning[200];      /* damage its decoder passed over (a JPEG's,
                               jpeg.h), or "": the caller may say so */
} Texture;

/* Returns the bytes t's texels take. */
size_t texture_memory(const Texture *t);

/* Releases what *tex owns. */
void texture_free(Texture *tex);

/* Returns the colour at (u, v), 0..255 per channel, read with filter;
 * u repeats, and v repeats too unless clamp_v is set. */
Colour texture_lookup(const Texture *tex, double u, double v, TextureFilter filter, int clamp_v);

#endif
