/*
 * scene_filter.h: how a scene's textures and stripes are read over a
 * pixel's footprint: the filter each material uses (its scene's word, or
 * the one the command line sets for all: --texture-filter), and what the
 * averaging filters need (material.h): ray differentials, which the
 * tracer carries when Scene.reads_footprint says so, and the mip-maps of
 * the textures they read (texture.h), within the memory limit. A scene
 * that reads no texture or stripes by an averaging filter pays nothing.
 */
#ifndef RAYTRACE_SCENE_FILTER_H
#define RAYTRACE_SCENE_FILTER_H

#include "scene/scene.h"

/* Makes every material of scene that has a texture or stripes read it
 * with filter (and notes it in scene->filter_override). */
void scene_set_texture_filter(Scene *scene, TextureFilter filter);

/* Sets scene->reads_footprint and builds the mip-map of every texture a
 * material reads by an averaging filter. Returns 0; SCENE_OVER_LIMIT when
 * the mip-maps would pass the memory limit, or -1 when memory runs out
 * (those built stay, counted in scene_memory()). */
int scene_prepare_filters(Scene *scene);

/* Returns the bytes scene_prepare_filters() would add. */
size_t scene_filters_memory(const Scene *scene);

#endif
