/* scene_filter.c: the filters a scene's textures and stripes are read
 * with, and what averaging needs (see scene_filter.h). */
#include "scene/scene_filter.h"

#include <stdlib.h>

#include "scene/texture.h"

/* Calls visit(m, ctx) on every material a shape of scene holds (spheres
 * and triangles share the scene's table; the others hold their own). */
static void scene_filter_each(Scene *scene, void (*visit)(Material *m, void *ctx), void *ctx)
{
    for (size_t i = 0; i < scene->material_count; i++)
        visit(&scene->materials[i], ctx);
    for (int k = 0; k < SHAPE_KINDS; k++)
        for (size_t i = 0; (SHAPE_HOLDS >> k & 1) && i < scene_count_of(scene, (ShapeKind)k); i++)
            visit(scene_shape_material(scene, (ShapeKind)k, i), ctx);
    for (size_t i = 0; i < scene->named_count; i++)
        visit(&scene->named[i].base, ctx);
}

/* Sets m's filter to *(TextureFilter *)ctx when it reads a texture or
 * stripes. */
static void scene_filter_set(Material *m, void *ctx)
{
    if (m->texture >= 0 || m->stripes)
        m->filter = *(const TextureFilter *)ctx;
}

void scene_set_texture_filter(Scene *scene, TextureFilter filter)
{
    scene_filter_each(scene, scene_filter_set, &filter);
    scene->filter_override = (int)filter;
}

/* What scene_filter_note() gathers: whether any material averages, and
 * which textures it reads so (texture_count flags). */
typedef struct {
    int averages;
    unsigned char *wants; /* 1 for each texture read by an averaging filter */
} SceneFilterNeeds;

/* Notes in ctx (a SceneFilterNeeds) what m needs. */
static void scene_filter_note(Material *m, void *ctx)
{
    SceneFilterNeeds *n = ctx;

    if (!material_averages(m))
        return;
    n->averages = 1;
    if (m->texture >= 0 && n->wants)
        n->wants[m->texture] = 1;
}

/* Fills *needs for scene (wants NULL when there are no textures or no
 * memory for the flags: then every texture is taken as wanted); returns
 * the flags to free. */
static unsigned char *scene_filter_needs(const Scene *scene, SceneFilterNeeds *needs)
{
    needs->averages = 0;
    needs->wants = scene->texture_count ? calloc(scene->texture_count, 1) : NULL;
    scene_filter_each((Scene *)scene, scene_filter_note, needs);
    return needs->wants;
}

size_t scene_filters_memory(const Scene *scene)
{
    SceneFilterNeeds needs;
    unsigned char *wants = scene_filter_needs(scene, &needs);
    size_t m = 0;

    for (size_t i = 0; needs.averages && i < scene->texture_count; i++)
        if ((!wants || wants[i]) && !scene->textures[i].levels)
            m += texture_mipmap_memory(&scene->textures[i]);
    free(wants);
    return m;
}

int scene_prepare_filters(Scene *scene)
{
    SceneFilterNeeds needs;
    size_t need = scene_filters_memory(scene);
    unsigned char *wants;
    int rc = 0;

    if (need > scene_memory_left(scene))
        return SCENE_OVER_LIMIT;
    wants = scene_filter_needs(scene, &needs);
    scene->reads_footprint = needs.averages;
    for (size_t i = 0; needs.averages && i < scene->texture_count && rc == 0; i++)
        if (!wants || wants[i])
            rc = texture_build_mipmap(&scene->textures[i]);
    free(wants);
    return rc;
}
