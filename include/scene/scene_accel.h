/*
 * scene_accel.h: what makes a read scene fast to query: its bounding volume
 * hierarchy (accel/bvh.h) over the bounded shapes and, for a scene of
 * spheres alone, its light buffers (accel/light_buffer.h) around the eye
 * and the point lights. Built once, after reading and before rendering,
 * within the scene's memory limit; the scene owns them (scene_free()
 * releases them) and every query gives the same answers without them.
 */
#ifndef RAYTRACE_SCENE_ACCEL_H
#define RAYTRACE_SCENE_ACCEL_H

#include <stddef.h>

#include "scene/scene.h"

/* Returns how many of the scene's shapes are bounded, and so go into the
 * hierarchy: spheres, triangles, cubes and squares. */
size_t scene_bounded_count(const Scene *scene);

/* Builds the acceleration structure (bvh.h) when the scene has enough
 * bounded shapes to gain from one, with up to threads threads, and moves
 * the spheres of a scene without transparency into its order (each keeps
 * its position among the objects: walks and the file-order loops are for
 * before); returns 0, SCENE_OVER_LIMIT (nothing allocated) when its estimated size
 * would pass the memory limit, or -1 when memory runs out (the scene is
 * then left without one, and still renders). */
int scene_build_accel(Scene *scene, int threads);

/* scene_build_accel() in its two steps: the hierarchy (and the spheres
 * moved into its order), returning as scene_build_accel() does; then the
 * light buffers, which need the hierarchy (without it, or built already,
 * nothing is done) and never fail (a buffer that cannot be built is left
 * out: the rays walk the hierarchy). */
int scene_build_hierarchy(Scene *scene, int threads);
void scene_build_buffers(Scene *scene, int threads);

#endif
