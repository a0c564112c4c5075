/*
 * texture.h: images that give a surface its colour.
 *
 * A texture is a grid of texels read once per scene (scenefile/
 * texture_file.h reads them from image files). It is addressed by texture coordinates (u, v): u runs left to right across the
 * image, v bottom to top, one image per unit; outside [0, 1) the image
 * repeats (v may be clamped instead, for spheres, whose poles are edges).
 *
 * Seen from afar a pixel covers many texels; reading one (or four) there
 * aliases. A texture that is to be read over a footprint gets a mip-map
 * (Williams 1983): level k + 1 is level k halved each way (a side of n
 * texels becomes floor(n / 2), at least 1), each texel the mean of the
 * texels of level k it covers (a box of 2 x 2, or up to 3 x 3 with the
 * partly covered ones weighted by their share when a side is odd), down
 * to 1 x 1. The footprint comes as the derivatives of (u, v) over a pixel
 * (du/dx, dv/dx, du/dy, dv/dy), from ray differentials (geometry/ray.h).
 */
#ifndef RAYTRACE_TEXTURE_H
#define RAYTRACE_TEXTURE_H

#include <stddef.h>

#include "geometry/material.h"
#include "math/colour.h"

/* A mip-map level past the first: colours, 0..255, as floats. */
typedef struct {
    int width, height;      /* texels, >= 1 each */
    float *texels;          /* 3 * width * height, rows top to bottom */
} TextureLevel;

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
    TextureLevel *levels;   /* the mip-map's levels 1, 2, ... (level 0 is
                               texels), owned; NULL until built */
    int level_count;        /* how many: 0, or until 1 x 1 */
} Texture;

/* Returns the bytes t's texels and its mip-map take. */
size_t texture_memory(const Texture *t);

/* Returns the bytes texture_build_mipmap() would add to t. */
size_t texture_mipmap_memory(const Texture *t);

/* Builds t's mip-map (nothing when it has one); returns 0, or -1 when
 * memory runs out (t unchanged). */
int texture_build_mipmap(Texture *t);

/* Releases what *tex owns. */
void texture_free(Texture *tex);

/* Returns the colour at (u, v), 0..255 per channel, read with filter (a
 * point: the averaging filters read as bilinear); u repeats, and v repeats
 * too unless clamp_v is set. */
Colour texture_lookup(const Texture *tex, double u, double v, TextureFilter filter, int clamp_v);

/* Returns the colour over the footprint d = {du/dx, dv/dx, du/dy, dv/dy}
 * around (u, v), read with filter: the averaging filters average it
 * (trilinear: the footprint's width w, the longer of its two derivative
 * vectors in texels (OpenGL's rho), picks levels k and k + 1 with 2^k <= w
 * < 2^(k+1), blended by w / 2^k - 1; EWA: a Gaussian over the ellipse the derivatives span,
 * its eccentricity at most 8, on the levels around its minor axis); a
 * footprint within one texel (both derivative vectors at most a texel
 * long), or a texture without a mip-map, reads as bilinear. The others read the point. */
Colour texture_lookup_footprint(const Texture *tex, double u, double v, const double d[4],
                                TextureFilter filter, int clamp_v);

/* Returns the share of [s - w/2, s + w/2] where the fraction of the
 * coordinate is below one half (the MPL ray tracer's coloured stripes): the stripes'
 * square wave box-filtered over a footprint w wide (w <= 0: the point's,
 * 1 or 0). */
double texture_stripe_cover(double s, double w);

#endif
