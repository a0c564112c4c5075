/*
 * trace.h: following one ray through a scene: nearest hit, shadows and the
 * course's recursive shading, extended with its bonus features, and seed
 * 002's Blinn-Phong shading.
 *
 * The colour seen along a ray that hits an object at point P is
 *     C = (1 - R - T) * local + R * Cr + T * Ct
 *     local = Ca * Ci / 255 + sum over lights of E * max(0, N . L) * Ci * Cs / 255
 * channel by channel, with N the unit normal facing the ray, L the unit
 * vector from P to the light, Ci the object's colour (or its texture's at P),
 * Cs the light's colour, Ca the ambient colour (0 without an ambient:
 * record), R and T the object's mirror and transparency weights, Cr the
 * colour seen along the mirror ray d - 2 (d . N) N and Ct the colour seen
 * along the refracted ray. E is the share of the light that reaches P: the
 * product of T over every surface crossing strictly between P and the light
 * (1 with none, 0 when an opaque surface is crossed). Refraction follows
 * Snell and Descartes from index 1 into the object's index n when the ray
 * meets the outer side of its surface, from n into 1 when it leaves; on
 * total internal reflection the share T follows the mirror ray too. A ray
 * that hits nothing sees the background. The primary ray has depth 0; a
 * mirror or refracted ray of depth k is traced only when k <= max_depth,
 * otherwise it contributes 0. A material with a Blinn-Phong entry (the
 * keyword format) is shaded instead by Whitted's sum C = local + R Cr + T Ct
 * with the Blinn-Phong local term of docs/scene-format.md, lit by distant
 * lights whose shadow rays are unbounded. Functions here only read the scene and write
 * the counters they are given: safe to call from many threads at once, each
 * with its own counters.
 */
#ifndef RAYTRACE_TRACE_H
#define RAYTRACE_TRACE_H

#include "math/colour.h"
#include "geometry/ray.h"
#include "scene/scene.h"

enum { TRACE_MAX_DEPTH_LIMIT = 1000 }; /* deepest max_depth accepted */

/* The kinds of shape a ray can hit. */
typedef enum { SHAPE_SPHERE, SHAPE_PLANE, SHAPE_TRIANGLE } ShapeKind;

/* Rays cast, by kind. */
typedef struct {
    unsigned long long primary;    /* from the camera (counted by render.c) */
    unsigned long long shadow;     /* towards a light */
    unsigned long long reflection; /* mirror rays */
    unsigned long long refraction; /* refracted rays */
    unsigned long long cut;        /* secondary and shadow rays the cut-off left
                                      out, and no later pass traced */
    unsigned long long refined;    /* pixels whose left-out rays were traced */
} RayCounts;

typedef struct {
    real t;       /* ray parameter of the crossing, > 0 */
    ShapeKind kind; /* which array the object is in */
    size_t index;   /* its index there */
    unsigned order; /* its position among all objects */
} Hit;

/* Finds the object whose surface the ray crosses first at 0 < t < tmax, the
 * earliest-listed on an exact tie; returns 1 and fills *hit, or returns 0. */
int trace_nearest(const Scene *scene, const Ray *ray, real tmax, Hit *hit);

/* Returns 1 when some object's surface crosses the ray at 0 < t < tmax,
 * else 0: tmax = 1 tests the segment from ray->origin to ray->origin +
 * ray->dir (ends excluded), tmax = INFINITY the whole ray. */
int trace_occluded(const Scene *scene, const Ray *ray, real tmax);

/* Returns the share of light that passes along the ray from t = 0 to tmax:
 * the product of the transparency T of every surface crossing there. */
double trace_transmittance(const Scene *scene, const Ray *ray, real tmax);

/* The kinds of ray the cut-off leaves out. */
typedef enum { TRACE_SHADOW, TRACE_REFLECTION, TRACE_REFRACTION } TraceRayKind;

/* A ray the cut-off left out, kept so that it can be traced later: a
 * mirror or refracted ray of depth `depth`, whose colour the sample's sum
 * takes times weight, or a shadow ray (up to t = tmax), which adds weight x
 * E x lit. */
typedef struct {
    Ray ray;
    TraceRayKind kind;
    int depth;
    real tmax;
    double weight;
    Colour lit;
} TraceDeferred;

/* How much of a pixel's ray tree may be left out, and what was: a
 * secondary ray whose weight (the product of the mirror and transparency
 * weights down to it) times the most any ray at its depth can see falls
 * below `cutoff` levels is not traced, nor a shadow ray whose light, lit,
 * would add less than that; each is kept in deferred (unless there is no
 * memory for it: then it is traced). */
typedef struct {
    double cutoff;    /* levels; 0 traces every ray */
    double base;      /* the most a ray with no levels left below it can see */
    double per_level; /* and what each level left below adds to that */
    double skipped;   /* sum of weight x bound over the rays left out: the
                         most the colour lacks because of them */
    TraceDeferred *deferred; /* the rays left out, in the order met */
    size_t deferred_count;
    size_t deferred_capacity;
} TraceCut;

/* Sets up *cut for scene with the given cutoff (levels, >= 0), the bounds
 * proved in trace.c, nothing skipped or kept yet; trace_cut_free()
 * releases what it comes to hold. */
void trace_cut_init(TraceCut *cut, const struct Scene *scene, double cutoff);

/* Releases the rays cut keeps. */
void trace_cut_free(TraceCut *cut);

/* Traces the ray d that a cut-off left out, leaving out in turn what cut
 * allows (and keeping it in cut, which may move its deferred array);
 * returns what it adds to its sample's colour. */
Colour trace_deferred(const struct Scene *scene, TraceDeferred d, int max_depth, TraceCut *cut,
                      RayCounts *counts);

/* The most a ray with `levels` levels of secondary rays left below it can
 * see, in any channel. */
static inline double trace_cut_bound(const TraceCut *cut, int levels)
{
    return cut->base + levels * cut->per_level;
}

/* trace_ray() for a primary ray, leaving out the rays *cut allows and adding
 * what they could have brought to cut->skipped. */
Colour trace_ray_cut(const Scene *scene, const Ray *ray, int max_depth, TraceCut *cut,
                     RayCounts *counts);

/* Returns the colour seen along ray, a ray of depth `depth` (0 for primary
 * rays), tracing mirror and refracted rays down to max_depth; adds the
 * shadow, mirror and refracted rays it casts to *counts. */
Colour trace_ray(const Scene *scene, const Ray *ray, int depth, int max_depth,
                 RayCounts *counts);

#endif
