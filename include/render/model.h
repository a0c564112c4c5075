/*
 * model.h: the lighting models, one table entry each: how a primary ray's
 * colour is traced, the defaults a scene that says nothing takes, how the
 * picture is encoded, which options change nothing under it and the note
 * that says so. The command line and the renderer ask this table; none of
 * them tests which model or format a scene has.
 *
 * To add a model: its SceneModel (scene.h), its trace function, its entry
 * in model.c, and its word for --model (cli/options.c) and the scene
 * formats (scenefile/).
 */
#ifndef RAYTRACE_MODEL_H
#define RAYTRACE_MODEL_H

#include "render/tracer.h"
#include "scene/scene.h"

typedef struct Model {
    SceneModel id;
    const char *name;       /* its word for --model */
    /* The colour seen along primary ray `ray` (differentials diff, or
     * NULL), tracing deeper rays down to t->max_depth. */
    Colour (*trace)(const Tracer *t, const Ray *ray, const RayDiff *diff);
    /* What trace returns for a primary ray that meets nothing, and
     * whether that is the same colour for every ray. */
    Colour (*miss)(const Tracer *t, const Ray *ray);
    int (*miss_uniform)(const Tracer *t);
    int max_depth;          /* the deepest ray when no option says */
    int ao_rays, gi_rays;   /* occlusion and gathering rays when neither
                               the command line nor the scene says */
    double ao_distance;     /* the occlusion distance in the scene file's
                               units when none is given; 0: a tenth of the
                               scene's size */
    double gamma;           /* the picture's encoding gamma; 0: none, the
                               levels are linear */
    int may_cut;            /* 1: the cut-off may leave rays out (render.h) */
    const char *verbose;    /* what -v says of it (then its gamma), or NULL */
    const char *bounces_note; /* non-NULL: --gi-bounces changes nothing
                               under it while rays gather, and why */
    const char *cache_note; /* non-NULL: it gathers without the irradiance
                               cache (--gi-cache changes nothing), and why */
    /* Says whether ambient occlusion darkens anything in scene. */
    int (*occludes)(const Scene *scene);
} Model;

/* Returns the entry of scene's model. */
const Model *model_of(const Scene *scene);

/* Says whether scene's format lets --model choose its model (the MPL
 * format has two; the course and keyword formats one). */
int model_choosable(const Scene *scene);

/* Returns a Tracer of scene that traces to max_depth and counts its rays
 * into counts, its model's and rule's choices made (the rest zero:
 * no cut-off, no indirect light, no sample). */
Tracer model_tracer(const Scene *scene, int max_depth, RayCounts *counts);

#endif
