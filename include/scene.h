/*
 * scene.h: everything a render needs, as the parser builds it.
 *
 * A Scene owns its sphere array; scene_free() releases it. Spheres keep the
 * order of the scene file, which decides exact ties between hits.
 */
#ifndef RAYTRACE_SCENE_H
#define RAYTRACE_SCENE_H

#include <stddef.h>

#include "camera.h"
#include "colour.h"
#include "sphere.h"
#include "vec3.h"

typedef struct {
    Vec3 position; /* point light, scene units */
    Colour colour; /* Cs, 0..255 per channel */
} Light;

typedef struct {
    Camera camera;          /* eye, screen and image size */
    Colour background;      /* seen where a ray hits nothing, 0..255 */
    Light light;            /* the single point light */
    Sphere *spheres;        /* file order; NULL when there are none */
    size_t sphere_count;    /* spheres in use */
    size_t sphere_capacity; /* spheres allocated */
    int length_exponent;    /* every length above is the scene file's times
                               2^length_exponent: 0 unless scene_fit_scale()
                               enlarged a tiny scene */
} Scene;

/* Makes *scene an empty scene that owns nothing. */
void scene_init(Scene *scene);

/* Releases what *scene owns and leaves it empty. */
void scene_free(Scene *scene);

/* Appends a copy of *s; returns 0, or -1 with the scene unchanged when
 * memory runs out. */
int scene_add_sphere(Scene *scene, const Sphere *s);

/*
 * Enlarges a tiny scene, one whose every coordinate and radius is below
 * SCENE_TINY in magnitude, by the power of two that brings the largest into
 * [0.5, 1), and records it in length_exponent. Multiplying every length by a
 * power of two is exact and commutes with every operation the renderer
 * uses, so the picture does not change; but squares and products of lengths
 * no longer underflow. Other scenes are left as they are.
 */
void scene_fit_scale(Scene *scene);

#define SCENE_TINY 0x1p-64 /* ~5.4e-20: smaller scenes are enlarged */

#endif
