/*
 * texture.h: images that give a surface its colour.
 *
 * A texture is a PPM image (P6 or P3, any maxval) read once per scene. It is
 * addressed by texture coordinates (u, v): u runs left to right across the
 * image, v bottom to top, one image per unit; outside [0, 1) the image
 * repeats (v may be clamped instead, for spheres, whose poles are edges).
 */
#ifndef RAYTRACE_TEXTURE_H
#define RAYTRACE_TEXTURE_H

#include "math/colour.h"
#include "base/error.h"
#include "geometry/material.h"
#include "image/ppm.h"

typedef struct {
    PpmImage image; /* the texels, rows top to bottom */
    double scale;   /* 255 / maxval: texel value to colour */
    char *path;     /* the file it was read from, as the scene names it */
} Texture;

/* Reads the PPM file at path into *tex, keeping a copy of path; returns 0,
 * or -1 with *err describing the fault in the file. */
int texture_load(Texture *tex, const char *path, Error *err);

/* Releases what *tex owns. */
void texture_free(Texture *tex);

/* Returns the colour at (u, v), 0..255 per channel, read with filter;
 * u repeats, and v repeats too unless clamp_v is set. */
Colour texture_lookup(const Texture *tex, double u, double v, TextureFilter filter, int clamp_v);

#endif
