/*
 * tracer.h: what tracing the rays of one sample carries along: the scene,
 * the depth limit, the cut-off's state and the counters of rays cast.
 *
 * The colour rules are in trace.h; its steps in visibility.h (which object
 * a ray meets, what a shadow ray crosses), shade.h (what a point looks
 * like and the light it receives) and cut.h (the rays that may be left
 * out). A Tracer is only read by them, but for the cut-off, counters and
 * cache hints it points to (and the sample it is tracing): one per thread.
 */
#ifndef RAYTRACE_TRACER_H
#define RAYTRACE_TRACER_H

#include "geometry/ray.h"
#include "render/sampler.h"
#include "scene/scene.h"

enum { TRACE_MAX_DEPTH_LIMIT = 1000 }; /* deepest max_depth accepted */
enum { TRACE_OCCLUDERS = 8 };        /* lights with a shadow cache */

/* Rays cast, by kind. */
typedef struct {
    unsigned long long primary;    /* from the camera (counted by render.c) */
    unsigned long long shadow;     /* towards a light */
    unsigned long long reflection; /* mirror rays */
    unsigned long long refraction; /* refracted rays */
    unsigned long long cut;        /* secondary and shadow rays the cut-off left
                                      out, and no later pass traced */
    unsigned long long refined;    /* pixels whose left-out rays were traced */
    unsigned long long occlusion;  /* ambient occlusion rays */
    unsigned long long gather;     /* global illumination rays */
    unsigned long long lookups;    /* points that asked the irradiance cache */
    unsigned long long served;     /* of them, those it answered */
} RayCounts;

/* Adds the counts of b to a. */
static inline void ray_counts_add(RayCounts *a, const RayCounts *b)
{
    a->primary += b->primary;
    a->shadow += b->shadow;
    a->reflection += b->reflection;
    a->refraction += b->refraction;
    a->cut += b->cut;
    a->refined += b->refined;
    a->occlusion += b->occlusion;
    a->gather += b->gather;
    a->lookups += b->lookups;
    a->served += b->served;
}

/* The kinds of ray that leave a surface. */
typedef enum { RAY_SHADOW, RAY_REFLECTION, RAY_REFRACTION } RayKind;

/* The branches a path's key follows (sampler_branch()), for every model:
 * a mirror or refracted ray takes its RayKind's, a gathering ray
 * TRACER_GATHERED + its number; the occlusion and gathering rays of a
 * point draw from their own. */
enum { TRACER_OCCLUSION = 8, TRACER_GATHER = 9, TRACER_GATHERED = 16 };

struct Cut;
struct Model;
struct GiCache;

/* A point where a ray's path gathers light (trace.h): on its surface,
 * with the error bound of its position, the step back toward the ray that
 * met it its rays take (ray_back_step()), the normal facing the ray and
 * the shading normal on its side, and the diffuse bounces taken to it. */
typedef struct {
    Vec3 point, error, back, n, ns;
    int bounce;
} GatherPoint;

/* A list of them, as the irradiance cache's pre-pass collects them;
 * failed is set when memory ran out adding one. */
typedef struct {
    GatherPoint *items;
    size_t count, capacity;
    int failed;
} GatherPoints;

/* Appends *p to list (or sets its failed). */
void gather_points_add(GatherPoints *list, const GatherPoint *p);

/* Ambient occlusion and global illumination (trace.h): how many rays, how
 * far, how many bounces. Zero samples: off, and not a ray more. */
typedef struct {
    int ao_samples;     /* occlusion rays per primary hit, 0..SCENE_MAX_INDIRECT */
    double ao_distance; /* what is nearer occludes, > 0 */
    int gi_samples;     /* gathering rays at a primary hit, 0..SCENE_MAX_INDIRECT */
    int gi_bounces;     /* diffuse bounces gathered, 1..SCENE_MAX_BOUNCES */
    int gi_cache;       /* 1: gathered light through the irradiance cache
                           (irradiance.h): gi_samples rays a record */
    double gi_cache_error; /* the cache's accuracy a (gicache.h) */
} Indirect;

/* The sample being traced: the pixel, the sample's number among the
 * pixel's `of`; what the indirect rays' directions are drawn from. */
typedef struct {
    int x, y;         /* the pixel */
    unsigned k, of;   /* sample k of `of` (progressive layout: of unused) */
    const RayDiff *diff; /* the pixel's primary rays' differentials, or
                            NULL (render.c) */
} TraceSample;

/* What a render shows (--pass, pass.h): the picture, or one part of it. */
typedef enum {
    TRACE_PASS_FULL,     /* the picture */
    TRACE_PASS_DIRECT,   /* all but the gathered light */
    TRACE_PASS_INDIRECT, /* the gathered light alone */
    TRACE_PASS_AO,       /* the first surface's ambient share kept */
    TRACE_PASS_ALBEDO,   /* its colour */
    TRACE_PASS_NORMAL,   /* its shading normal */
    TRACE_PASS_DEPTH     /* its distance */
} TracePass;

typedef struct {
    const Scene *scene; /* what is traced */
    int max_depth;      /* deepest mirror or refracted ray traced,
                           0..TRACE_MAX_DEPTH_LIMIT */
    struct Cut *cut;    /* what may be left out, and what was (cut.h); NULL:
                           every ray is traced */
    RayCounts *counts;  /* the rays cast are added here */
    Indirect indirect;  /* ambient occlusion and global illumination */
    TraceSample *sample; /* the sample being traced (set by render.c) */
    SamplerGrid ao_grid;   /* ao_samples x the pixel's samples */
    SamplerGrid gi_grid;   /* gi_samples x the pixel's samples */
    SamplerGrid path_grid; /* the pixel's samples: one ray a later bounce */
    uint32_t *occluders; /* the thread's shadow cache: for each of the
                            first TRACE_OCCLUDERS lights, the hierarchy's
                            slot that last stopped a ray towards it
                            (visibility.h); NULL: none */
    int no_shadows;      /* 1: every light reaches every point facing it
                            (no shadow rays); 0: shadows */
    double footprint_scale; /* a sample's primary ray differentials are the
                            pixel's times this (render.c) */
    const struct Model *model; /* the scene's lighting model (model.h) */
    int named;           /* 1: the rules of named materials (the scene has
                            some), 0: the course's; chosen once, by
                            model_tracer() */
    const struct GiCache *gicache; /* where diffuse points look their
                            gathered light up first (gicache.h), or NULL */
    uint32_t *gicache_hint; /* the two records a gathering ray's hit tries
                            first (gicache_any()'s hint), set by the cache's
                            pre-pass afresh for each record's rays; NULL
                            elsewhere */
    int primary_misses;  /* 1: the primary rays traced are proven to meet
                            nothing; they take the model's miss colour
                            untraced (render.c) */
    uint64_t primary_skip; /* the spheres the primary rays traced are
                            proven not to meet, which they do not test
                            (visibility_nearest_skipping()); 0: none */
    GatherPoints *collect; /* non-NULL: diffuse points gather nothing, but
                            are added here (the cache's pre-pass) */
    TracePass pass;      /* what the camera's rays bring back (pass.h) */
    double depth_scale;  /* the depth pass's s (pass_depth_scale()) */
} Tracer;

#endif
