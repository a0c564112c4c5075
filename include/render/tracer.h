/*
 * tracer.h: what tracing the rays of one sample carries along: the scene,
 * the depth limit, the cut-off's state and the counters of rays cast.
 *
 * The colour rules are in trace.h; its steps in visibility.h (which object
 * a ray meets, what a shadow ray crosses), shade.h (what a point looks
 * like and the light it receives) and cut.h (the rays that may be left
 * out). A Tracer is only read by them, but for the cut-off and counters it
 * points to: one per thread.
 */
#ifndef RAYTRACE_TRACER_H
#define RAYTRACE_TRACER_H

#include "scene/scene.h"

enum { TRACE_MAX_DEPTH_LIMIT = 1000 }; /* deepest max_depth accepted */

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

/* The kinds of ray that leave a surface. */
typedef enum { RAY_SHADOW, RAY_REFLECTION, RAY_REFRACTION } RayKind;

struct Cut;

typedef struct {
    const Scene *scene; /* what is traced */
    int max_depth;      /* deepest mirror or refracted ray traced,
                           0..TRACE_MAX_DEPTH_LIMIT */
    struct Cut *cut;    /* what may be left out, and what was (cut.h); NULL:
                           every ray is traced */
    RayCounts *counts;  /* the rays cast are added here */
} Tracer;

#endif
