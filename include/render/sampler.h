/*
 * sampler.h: where in a pixel, and where on the lens, each sample goes.
 *
 * A pixel's n samples follow a multi-jittered pattern (Chiu, Shirley and
 * Wang, "Multi-jittered sampling", Graphics Gems IV): the pixel is cut into
 * m columns and n / m rows (m the largest divisor of n not above its square
 * root), every cell holds one sample, and, seen along either axis alone,
 * the n samples also fall one in each of n equal strips. Positions come
 * from a hash of the pixel's coordinates, the sample's number and the
 * dimension (pixel area, lens disk): no state, no allocation, and the same
 * numbers whichever thread renders the pixel.
 *
 * Under --noise (render.h) a pixel takes samples in rounds, as many as its
 * error needs, so its points must come as a sequence whose every prefix is
 * well spread: the progressive layout gives each pixel and dimension its
 * own Owen-scrambled Sobol sequence (Owen 1995; hashed as Burley,
 * "Practical hash-based Owen scrambling", JCGT 2020, the index shuffled
 * too, so that dimensions are not correlated). Its points 2^m j to
 * 2^m (j + 1) - 1, for any m and j, fill the square one to each of its
 * 2^m elementary boxes of every shape (a (0, m, 2)-net): the first 2^m
 * points, and each eighth of them, which noise.h compares.
 */
#ifndef RAYTRACE_SAMPLER_H
#define RAYTRACE_SAMPLER_H

#include <stdint.h>

#include "scene/camera.h"

enum {
    SAMPLER_MAX = CAMERA_MAX_SAMPLES, /* most samples per pixel */
    SAMPLER_DIM_PIXEL = 0, /* positions in the pixel */
    SAMPLER_DIM_LENS = 1   /* positions on the lens */
};

/* The layout of n samples: columns x rows = n; or progressive. */
typedef struct {
    unsigned n;    /* samples, 1..SAMPLER_MAX */
    unsigned cols; /* largest divisor of n at most sqrt(n) */
    unsigned rows; /* n / cols */
    int progressive; /* 1: Owen-scrambled Sobol points, as many as asked
                        for (n, cols and rows unused) */
} SamplerGrid;

/* Returns the layout of n samples (1 <= n <= SAMPLER_MAX). */
SamplerGrid sampler_grid(unsigned n);

/* Returns the progressive layout. */
SamplerGrid sampler_progressive(void);

/* Stores in xy point k (k < 2^32) of the Owen-scrambled Sobol sequence of
 * seed: a point of [0, 1)^2. */
void sampler_sobol(uint64_t seed, uint32_t k, double xy[2]);

/* Stores in xy sample k (0 <= k < g->n) of pixel (px, py) in dimension dim:
 * a point of the unit square [0, 1]^2. With one sample it is the centre,
 * (0.5, 0.5). In a progressive layout, point k of the pixel's sequence for
 * dim. */
void sampler_sample(const SamplerGrid *g, int px, int py, unsigned k, unsigned dim, double xy[2]);

/* Returns the key of the branch-th ray leaving a point whose ray had key
 * `key` (the primary rays' is 0): a hash, so that each path through a
 * pixel draws its own directions. */
uint64_t sampler_branch(uint64_t key, unsigned branch);

/* Stores in dir direction k (0 <= k < g->n) of pixel (px, py) over the
 * hemisphere around +z, for the rays of path `key`: the n directions are
 * cosine-weighted (density cos(theta) / pi) and stratified, the
 * multi-jittered points of the square carried to the disk by
 * sampler_disk() and lifted to the hemisphere (Malley's method); one
 * direction (n = 1) is random, not +z. */
void sampler_hemisphere(const SamplerGrid *g, int px, int py, unsigned k, uint64_t key,
                        double dir[3]);

/* Stores in xy point k (0 <= k < g->n) of pixel (px, py)'s multi-jittered
 * pattern for the rays of path `key`, as sampler_hemisphere() draws its
 * own: a point of [0, 1)^2, random for one point (progressive layout:
 * point k of the pixel's sequence for path key). */
void sampler_square(const SamplerGrid *g, int px, int py, unsigned k, uint64_t key,
                    double xy[2]);

/* Maps the point xy of the unit square to the unit disk, preserving area
 * and keeping neighbours together (Shirley and Chiu's concentric map); the
 * square's centre goes to the disk's. */
void sampler_disk(const double xy[2], double disk[2]);

#endif
