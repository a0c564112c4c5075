/* scene_accel.c: the scene's structures for fast queries, built once it
 * is read (see scene_accel.h). */
#include "scene/scene_accel.h"

#include <math.h>
#include <stdlib.h>

#include "accel/bvh.h"
#include "accel/light_buffer.h"

/* Returns the larger of m and the largest magnitude of p's coordinates. */
static real scene_farther(real m, Vec3 p)
{
    real x = fabs(p.x), y = fabs(p.y), z = fabs(p.z);

    m = x > m ? x : m;
    m = y > m ? y : m;
    return z > m ? z : m;
}

/* Returns the hierarchy's reach (bvh.h): the largest coordinate of the
 * camera, its screen, the lights and the unbounded shapes. */
static real scene_reach(const Scene *scene)
{
    const Camera *cam = &scene->camera;
    real m = scene_farther(scene_farther(scene_farther(0, cam->eye), cam->top_left),
                           vec3_add(cam->top_left, vec3_add(cam->u, cam->v)));

    for (size_t i = 0; i < scene->light_count; i++)
        m = scene_farther(m, scene->lights[i].position);
    for (int k = 0; k < SHAPE_KINDS; k++)
        for (size_t i = 0; !(SHAPE_BOUNDED >> k & 1) && i < scene_count_of(scene, (ShapeKind)k);
             i++) {
            Vec3 lo = vec3(INFINITY, INFINITY, INFINITY), hi = vec3_neg(lo);
            shape_box((ShapeKind)k, scene_items(scene, (ShapeKind)k), i, &lo, &hi);
            m = scene_farther(scene_farther(m, lo), hi);
        }
    return m;
}

size_t scene_bounded_count(const Scene *scene)
{
    size_t n = 0;

    for (int k = 0; k < SHAPE_KINDS; k++)
        n += SHAPE_BOUNDED >> k & 1 ? scene_count_of(scene, (ShapeKind)k) : 0;
    return n;
}

enum { SCENE_BUFFER_FLOOR = 4 << 20 }; /* bytes any light buffer may take */

/* Returns the bytes one of `buffers` light buffers may take: a share of
 * what the hierarchy's build held and gave back (so that they do not raise
 * the peak) and `more`, or SCENE_BUFFER_FLOOR if more, within the memory
 * limit. */
static size_t scene_buffer_budget(const Scene *scene, size_t buffers, size_t more)
{
    size_t share = bvh_build_scratch(scene_bounded_count(scene)) / buffers + more;
    size_t left = scene_memory_left(scene);

    share = share > SCENE_BUFFER_FLOOR ? share : SCENE_BUFFER_FLOOR;
    return share < left ? share : left;
}

/* Builds the light buffers of a scene of spheres alone (light_buffer.h):
 * around a pinhole eye for the primary rays, and around each point light
 * for the shadow rays of an opaque scene (a transparent one's shadow rays
 * multiply transparencies, which the hierarchy lists), when the image
 * has at least two pixels a sphere. Where a buffer would
 * not fit its budget or pay, the rays walk the hierarchy: the answers are
 * the same. */
void scene_build_buffers(Scene *scene, int threads)
{
    size_t buffers = 0, lights = 0, given = 0;
    size_t pixels = (size_t)scene->camera.width * (size_t)scene->camera.height;

    if (!scene->accel || scene->eye_buffer || scene->light_buffers)
        return;

    /* A buffer's build reads every sphere five times; the rays it saves
     * come from the pixels: it is built from two pixels a sphere, where
     * it breaks even on fields of spheres (docs/log.md). */
    if (scene->kinds != 1u << SHAPE_SPHERE || pixels / 2 < scene_count_of(scene, SHAPE_SPHERE))
        return;
    for (size_t i = 0; !scene->has_transparency && i < scene->light_count; i++)
        lights += !scene->lights[i].distant;
    buffers = lights + (scene->camera.aperture == 0);
    if (buffers == 0)
        return;
    /* The references the hierarchy gave back (spheres alone) go to the
     * lights' buffers: a shadow query walks its list up to the lit point,
     * a primary one stops at its first hit (10^6 spheres: 33 entries a
     * shadow query, 14 a primary one; docs/log.md). */
    if (lights > 0 && !scene->accel->prims)
        given = scene->accel->prim_count * sizeof(uint32_t) / lights;
    /* Each budget is taken when its buffer is built: the memory left
     * shrinks with every buffer. */
    if (scene->camera.aperture == 0) {
        scene->eye_buffer = calloc(1, sizeof *scene->eye_buffer);
        if (scene->eye_buffer &&
            light_buffer_build(scene->eye_buffer, scene->camera.eye, scene_spheres(scene),
                               scene_count_of(scene, SHAPE_SPHERE), pixels,
                               scene_buffer_budget(scene, buffers, 0), threads) != 0) {
            free(scene->eye_buffer);
            scene->eye_buffer = NULL;
        }
    }
    if (scene->has_transparency)
        return;
    scene->light_buffers = calloc(scene->light_count, sizeof *scene->light_buffers);
    for (size_t i = 0; scene->light_buffers && i < scene->light_count; i++)
        if (!scene->lights[i].distant)
            (void)light_buffer_build(&scene->light_buffers[i], scene->lights[i].position,
                                     scene_spheres(scene), scene_count_of(scene, SHAPE_SPHERE),
                                     pixels, scene_buffer_budget(scene, buffers, given),
                                     threads);
}

int scene_build_hierarchy(Scene *scene, int threads)
{
    Bvh *bvh;
    size_t n = scene_bounded_count(scene);
    BvhShapes shapes = {{NULL}, {0}, NULL};

    if (scene->accel || n < BVH_MIN_PRIMITIVES)
        return 0;
    for (int k = 0; k < SHAPE_KINDS; k++)
        if (SHAPE_BOUNDED >> k & 1) {
            shapes.items[k] = scene_items(scene, (ShapeKind)k);
            shapes.count[k] = scene_count_of(scene, (ShapeKind)k);
        }
    if (scene->memory_limit && bvh_build_memory(n) > scene_memory_left(scene))
        return SCENE_OVER_LIMIT;
    /* Spheres in the leaves' order are read from neighbouring memory. A
     * transparent scene's keep the file's: shadow rays multiply their
     * transparencies in that order (visibility.c). */
    if (!scene->has_transparency)
        shapes.movable = scene_spheres(scene);
    bvh = malloc(sizeof *bvh);
    if (!bvh || bvh_build(bvh, &shapes, scene_reach(scene), threads) != 0) {
        free(bvh);
        return -1;
    }
    scene->accel = bvh;
    return 0;
}

int scene_build_accel(Scene *scene, int threads)
{
    int rc = scene_build_hierarchy(scene, threads);

    if (rc == 0)
        scene_build_buffers(scene, threads);
    return rc;
}
