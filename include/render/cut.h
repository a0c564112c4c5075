/*
 * cut.h: the cut-off: rays left out because they could change their pixel
 * by less than a set number of levels, kept so that they can be traced
 * after all.
 *
 * A secondary ray whose weight (the product of the mirror and transparency
 * weights down to it, in its largest channel) times the most any ray at
 * its depth can see falls
 * below `cutoff` levels is not traced, nor a shadow ray whose light would
 * add less than that; each is kept in the Cut (unless there is no memory
 * for it: then it is traced). render.c decides, pixel by pixel, whether
 * what was left out could change its bytes, and if so traces it
 * (docs/design.md, "The cut-off").
 */
#ifndef RAYTRACE_CUT_H
#define RAYTRACE_CUT_H

#include <stddef.h>

#include "geometry/ray.h"
#include "math/colour.h"
#include "render/tracer.h"

/* A ray the cut-off left out: a mirror or refracted ray of depth `depth`,
 * whose colour the sample's sum takes times weight (channel by channel:
 * tinted mirrors and glass weigh the channels apart), or a shadow ray (up
 * to t = tmax), which adds weight x E x lit. */
typedef struct {
    Ray ray;
    RayKind kind;
    int depth;
    real tmax;
    Colour weight;
    Colour lit;
    int has_diff;  /* 1: the ray carries differentials (diff) */
    RayDiff diff;
} CutRay;

typedef struct Cut {
    double cutoff;    /* levels; 0 traces every ray */
    double base;      /* the most a ray with no levels left below it can see */
    double per_level; /* and what each level left below adds to that */
    double skipped;   /* sum of weight x bound over the rays left out: the
                         most the colour lacks because of them */
    CutRay *deferred; /* the rays left out, in the order met */
    size_t deferred_count;
    size_t deferred_capacity;
} Cut;

/* Sets up *cut for scene with the given cutoff (levels, >= 0), the bounds
 * of docs/design.md, nothing skipped or kept yet; cut_free() releases
 * what it comes to hold. */
void cut_init(Cut *cut, const Scene *scene, double cutoff);

/* Releases the rays cut keeps. */
void cut_free(Cut *cut);

/* The most a ray with `levels` levels of secondary rays left below it can
 * see, in any channel. */
static inline double cut_bound(const Cut *cut, int levels)
{
    return cut->base + levels * cut->per_level;
}

/* Keeps d, left out, and adds most to cut->skipped; returns 1, or 0 when
 * there is no memory for it (d must then be traced). */
int cut_keep_out(Cut *cut, double most, const CutRay *d);

/* Says whether cut allows leaving out d, a ray whose colour adds at most
 * `most` to its sample (cut NULL: never): when most is below the cut-off
 * and d could be kept, d is kept and most goes to cut->skipped. */
static inline int cut_leave_out(Cut *cut, double most, const CutRay *d)
{
    return cut && most < cut->cutoff && cut_keep_out(cut, most, d);
}

#endif
