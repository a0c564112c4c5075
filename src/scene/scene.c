/* scene.c: the scene's storage (see scene.h). */
#include "scene/scene.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh.h"
#include "accel/light_buffer.h"
#include "base/grow.h"
#include "base/hash.h"

/* Returns where shape k of kind is held. */
static char *scene_item(const Scene *scene, ShapeKind kind, size_t k)
{
    return (char *)scene->shapes[kind].items + k * shape_size(kind);
}

void scene_init(Scene *scene)
{
    memset(scene, 0, sizeof *scene);
    scene->lights = NULL;
    for (int k = 0; k < SHAPE_KINDS; k++)
        scene->shapes[k].items = NULL;
    scene->textures = NULL;
    scene->named = NULL;
    scene->warnings = NULL;
    scene->accel = NULL;
    scene->ao_samples = scene->gi_samples = -1;
    scene->filter_override = -1;
}

/* Releases the scene's light buffers. */
static void scene_free_buffers(Scene *scene)
{
    if (scene->eye_buffer)
        light_buffer_free(scene->eye_buffer);
    free(scene->eye_buffer);
    for (size_t i = 0; scene->light_buffers && i < scene->light_count; i++)
        light_buffer_free(&scene->light_buffers[i]);
    free(scene->light_buffers);
    scene->eye_buffer = NULL;
    scene->light_buffers = NULL;
}

void scene_free(Scene *scene)
{
    scene_free_buffers(scene);
    if (scene->accel) {
        bvh_free(scene->accel);
        free(scene->accel);
    }
    for (size_t i = 0; i < scene->texture_count; i++)
        texture_free(&scene->textures[i]);
    free(scene->textures);
    for (size_t i = 0; i < scene->named_count; i++) {
        free(scene->named[i].name);
        free(scene->named[i].texture);
    }
    free(scene->named);
    free(scene->warnings);
    free(scene->lights);
    for (int k = 0; k < SHAPE_KINDS; k++)
        free(scene->shapes[k].items);
    free(scene->materials);
    free(scene->shading);
    scene_init(scene);
}

/* Adds b to *a, saturating at SIZE_MAX. */
static void scene_sum(size_t *a, size_t b)
{
    *a = b > SIZE_MAX - *a ? SIZE_MAX : *a + b;
}

size_t scene_memory(const Scene *scene)
{
    size_t m = 0;

    scene_sum(&m, scene->light_capacity * sizeof *scene->lights);
    for (int k = 0; k < SHAPE_KINDS; k++)
        scene_sum(&m, scene->shapes[k].capacity * shape_size((ShapeKind)k));
    scene_sum(&m, scene->material_capacity * sizeof *scene->materials);
    scene_sum(&m, scene->shading_capacity * sizeof *scene->shading);
    scene_sum(&m, scene->texture_capacity * sizeof *scene->textures);
    scene_sum(&m, scene->named_capacity * sizeof *scene->named);
    scene_sum(&m, scene->warnings ? SCENE_WARNINGS_MAX * sizeof *scene->warnings : 0);
    for (size_t i = 0; i < scene->texture_count; i++)
        scene_sum(&m, texture_memory(&scene->textures[i]));
    if (scene->accel)
        scene_sum(&m, bvh_memory(scene->accel));
    if (scene->eye_buffer)
        scene_sum(&m, light_buffer_memory(scene->eye_buffer));
    for (size_t i = 0; scene->light_buffers && i < scene->light_count; i++)
        scene_sum(&m, light_buffer_memory(&scene->light_buffers[i]));
    return m;
}

size_t scene_memory_left(const Scene *scene)
{
    size_t used = scene_memory(scene);

    if (scene->memory_limit == 0)
        return SIZE_MAX;
    return used >= scene->memory_limit ? 0 : scene->memory_limit - used;
}

int scene_set_aside(Scene *scene, size_t bytes)
{
    if (scene->memory_limit == 0)
        return 0;
    if (bytes > scene_memory_left(scene))
        return SCENE_OVER_LIMIT;
    scene->memory_limit -= bytes;
    return 0;
}

size_t scene_obj_budget(const Scene *scene)
{
    size_t left = scene_memory_left(scene);

    return scene->memory_limit == 0 ? 0 : left ? left : 1;
}

/* grow_reserve() under the memory limit: returns 0, -1 when memory runs
 * out, or SCENE_OVER_LIMIT when the grown array would pass the limit. */
static int scene_reserve(const Scene *scene, void **items, size_t *capacity, size_t count,
                         size_t size)
{
    size_t next = grow_next_capacity(*capacity);

    if (count < *capacity)
        return 0;
    if (scene->memory_limit && (next > SIZE_MAX / size ||
                                (next - *capacity) * size > scene_memory_left(scene)))
        return SCENE_OVER_LIMIT;
    return grow_reserve(items, capacity, count, size);
}

unsigned scene_order_of(const Scene *scene, ShapeKind kind, size_t k)
{
    unsigned order;

    memcpy(&order, scene_item(scene, kind, k) + shape_order_offset(kind), sizeof order);
    return order;
}

void scene_walk_start(SceneWalk *w)
{
    memset(w, 0, sizeof *w);
}

int scene_walk_next(const Scene *scene, SceneWalk *w, ShapeKind *kind, size_t *index)
{
    unsigned best = ~0u;
    int found = 0;

    /* Each kind's array is in file order: the next shape is the least
     * order among the heads. */
    for (int k = 0; k < SHAPE_KINDS; k++) {
        size_t i = w->next[k];
        if (i < scene_count_of(scene, (ShapeKind)k) &&
            scene_order_of(scene, (ShapeKind)k, i) < best) {
            best = scene_order_of(scene, (ShapeKind)k, i);
            *kind = (ShapeKind)k;
            found = 1;
        }
    }
    if (found)
        *index = w->next[*kind]++;
    return found;
}

Material *scene_shape_material(const Scene *scene, ShapeKind kind, size_t k)
{
    if (kind == SHAPE_TRIANGLE)
        return scene_material_of(scene, &scene_triangles(scene)[k]);
    return (Material *)(void *)(scene_item(scene, kind, k) + shape_material_offset(kind));
}

Material *scene_material_edit(Scene *scene, ShapeKind kind, size_t k, int *rc)
{
    Sphere *s;
    Material m;
    long at;

    if (kind != SHAPE_SPHERE)
        return scene_shape_material(scene, kind, k);
    /* A copy of its own: spheres in a row may share one (scene_add_sphere()). */
    s = &scene_spheres(scene)[k];
    m = s->plain ? sphere_material(s) : scene->materials[s->material.index];
    if ((at = scene_add_material(scene, &m)) < 0) {
        *rc = (int)at;
        return NULL;
    }
    sphere_set_material_index(s, (int)at);
    return &scene->materials[at];
}

double scene_size(const Scene *scene)
{
    Vec3 lo = vec3(INFINITY, INFINITY, INFINITY), hi = vec3(-INFINITY, -INFINITY, -INFINITY);
    const Camera *cam = &scene->camera;

    for (int k = 0; k < SHAPE_KINDS; k++)
        for (size_t i = 0; i < scene->shapes[k].count; i++)
            shape_box((ShapeKind)k, scene->shapes[k].items, i, &lo, &hi);
    if (!(lo.x < hi.x || lo.y < hi.y || lo.z < hi.z)) {
        shape_widen(&lo, &hi, cam->eye, 0);
        shape_widen(&lo, &hi, cam->top_left, 0);
        shape_widen(&lo, &hi, vec3_add(cam->top_left, vec3_add(cam->u, cam->v)), 0);
    }
    return vec3_length(vec3_sub(hi, lo));
}

size_t scene_object_count(const Scene *scene)
{
    size_t n = 0;

    for (int k = 0; k < SHAPE_KINDS; k++)
        n += scene->shapes[k].count;
    return n;
}

int scene_add_light(Scene *scene, const Light *light)
{
    int rc = scene_reserve(scene, (void **)&scene->lights, &scene->light_capacity,
                           scene->light_count, sizeof *light);

    if (rc != 0)
        return rc;
    scene->lights[scene->light_count++] = *light;
    return 0;
}

/* Appends a copy of *item to the shapes of kind, giving it its position
 * among the objects and noting its material m's transparency; returns 0
 * or what scene_reserve() returned. */
static int scene_push_shape(Scene *scene, ShapeKind kind, const void *item, const Material *m)
{
    ShapeArray *a = &scene->shapes[kind];
    size_t size = shape_size(kind);
    int rc = scene_reserve(scene, &a->items, &a->capacity, a->count, size);
    unsigned position = (unsigned)scene_object_count(scene);
    char *at;

    if (rc != 0)
        return rc;
    at = (char *)a->items + a->count * size;
    memcpy(at, item, size);
    memcpy(at + shape_order_offset(kind), &position, sizeof position);
    a->count++;
    scene->kinds |= 1u << kind;
    scene->has_transparency |= m->transparency > 0;
    return 0;
}

int scene_add_sphere(Scene *scene, Vec3 centre, real radius, const Material *m)
{
    Sphere s = {centre, radius, {0}, 0, {0, 0, 0}, 0};
    size_t count = scene->shapes[SHAPE_SPHERE].count;
    long at = -1;
    int rc, last = count > 0 ? sphere_material_index(&scene_spheres(scene)[count - 1]) : -1;

    if (sphere_plain(m))
        sphere_set_plain(&s, m);
    else if (last >= 0 && memcmp(&scene->materials[last], m, sizeof *m) == 0)
        sphere_set_material_index(&s, last); /* the previous sphere's: shared (an edit copies it first) */
    else if ((at = scene_add_material(scene, m)) < 0)
        return (int)at;
    else
        sphere_set_material_index(&s, (int)at);
    rc = scene_push_shape(scene, SHAPE_SPHERE, &s, m);
    if (rc != 0 && at >= 0)
        scene->material_count--;
    return rc;
}

int scene_add_shape(Scene *scene, ShapeKind kind, const void *shape)
{
    const Material *m =
        (const Material *)(const void *)((const char *)shape + shape_material_offset(kind));

    return scene_push_shape(scene, kind, shape, m);
}

int scene_add_any(Scene *scene, ShapeKind kind, const void *shape, const Material *m)
{
    const Sphere *s = shape;

    if (kind == SHAPE_SPHERE)
        return scene_add_sphere(scene, s->centre, s->radius, m);
    if (kind == SHAPE_TRIANGLE)
        return scene_add_triangle(scene, shape, m);
    return scene_add_shape(scene, kind, shape);
}

long scene_add_material(Scene *scene, const Material *m)
{
    int rc = scene_reserve(scene, (void **)&scene->materials, &scene->material_capacity,
                           scene->material_count, sizeof *m);

    if (rc != 0)
        return rc;
    scene->materials[scene->material_count] = *m;
    scene->has_transparency |= m->transparency > 0;
    return (long)scene->material_count++;
}

int scene_append_triangle(Scene *scene, const Triangle *t, size_t material,
                          const TriangleShading *sh)
{
    ShapeArray *a = &scene->shapes[SHAPE_TRIANGLE];
    int rc = scene_reserve(scene, &a->items, &a->capacity, a->count, sizeof *t);
    Triangle *at;

    if (rc != 0)
        return rc;
    at = &scene_triangles(scene)[a->count];
    *at = *t;
    at->order = (unsigned)scene_object_count(scene);
    at->shading = TRIANGLE_PLAIN;
    at->material = (unsigned)material;
    a->count++;
    scene->kinds |= 1u << SHAPE_TRIANGLE;
    if (sh && (rc = scene_shade_triangle(scene, a->count - 1, sh)) != 0)
        a->count--;
    return rc;
}

int scene_add_triangle(Scene *scene, const Triangle *t, const Material *m)
{
    long material = scene_add_material(scene, m);
    int rc;

    if (material < 0)
        return (int)material;
    if ((rc = scene_append_triangle(scene, t, (size_t)material, NULL)) != 0)
        scene->material_count--;
    return rc;
}

int scene_shade_triangle(Scene *scene, size_t i, const TriangleShading *sh)
{
    Triangle *tri = &scene_triangles(scene)[i];
    int rc;

    if (tri->shading != TRIANGLE_PLAIN) {
        scene->shading[tri->shading] = *sh;
        return 0;
    }
    rc = scene_reserve(scene, (void **)&scene->shading, &scene->shading_capacity,
                       scene->shading_count, sizeof *sh);
    if (rc != 0)
        return rc;
    scene->shading[scene->shading_count] = *sh;
    tri->shading = (unsigned)scene->shading_count++;
    return 0;
}

/* Gives back the room for items beyond capacity cap, of an array of items
 * of size bytes (cap at least the items held; 0 frees it). */
static void scene_fit(void **items, size_t *capacity, size_t cap, size_t size)
{
    void *fit;

    if (cap >= *capacity)
        return;
    if (cap == 0) {
        free(*items);
        *items = NULL;
        *capacity = 0;
    } else if ((fit = realloc(*items, cap * size)) != NULL) {
        *items = fit;
        *capacity = cap;
    }
}

/* Returns the capacity that adding count items one by one from capacity
 * entry makes, given capacity cap >= it reached by doubling. */
static size_t scene_fit_capacity(size_t cap, size_t count, size_t entry)
{
    size_t least = entry ? entry : 16;

    while (cap / 2 >= count && cap / 2 >= least)
        cap /= 2;
    return count == 0 && entry == 0 ? 0 : cap;
}

/* Grows *items (of size bytes each, *capacity of them) by doubling, as
 * adding items one by one would, until it holds need; returns 0 or what
 * scene_reserve() returned. */
static int scene_reserve_all(const Scene *scene, void **items, size_t *capacity, size_t need,
                             size_t size)
{
    int rc = 0;

    while (rc == 0 && *capacity < need)
        rc = scene_reserve(scene, items, capacity, *capacity, size);
    return rc;
}

int scene_add_spheres(Scene *scene, size_t n, int (*fill)(Sphere *room, void *ctx), void *ctx)
{
    ShapeArray *a = &scene->shapes[SHAPE_SPHERE];
    size_t entry = a->capacity, first = a->count;
    size_t others = scene_object_count(scene); /* listed before */
    int rc = scene_reserve_all(scene, &a->items, &a->capacity, first + n, sizeof(Sphere));
    Sphere *room = rc == 0 ? scene_spheres(scene) + first : NULL;

    if (rc != 0 || (rc = fill(room, ctx)) != 0) {
        scene_fit(&a->items, &a->capacity, entry, sizeof(Sphere));
        return rc;
    }
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for (size_t k = 0; k < n; k++) {
        room[k].order = (unsigned)(others + k);
    }
    a->count += n;
    scene->kinds |= 1u << SHAPE_SPHERE;
    return 0;
}

long scene_add_triangles(Scene *scene, size_t n, size_t material, int shaded,
                         size_t (*fill)(Triangle *tris, TriangleShading *sh, void *ctx), void *ctx)
{
    ShapeArray *a = &scene->shapes[SHAPE_TRIANGLE];
    size_t entry_tris = a->capacity, entry_shading = scene->shading_capacity;
    size_t first = a->count, shade = scene->shading_count, kept;
    size_t others = scene_object_count(scene); /* listed before */
    int rc = scene_reserve_all(scene, &a->items, &a->capacity, first + n, sizeof(Triangle));
    Triangle *tris;

    if (rc == 0 && shaded)
        rc = scene_reserve_all(scene, (void **)&scene->shading, &scene->shading_capacity,
                               shade + n, sizeof *scene->shading);
    tris = rc == 0 ? scene_triangles(scene) + first : NULL;
    kept = rc == 0 ? fill(tris, shaded ? scene->shading + shade : NULL, ctx) : SIZE_MAX;
    if (kept > n) { /* as it was */
        scene_fit(&a->items, &a->capacity, entry_tris, sizeof(Triangle));
        scene_fit((void **)&scene->shading, &scene->shading_capacity, entry_shading,
                  sizeof *scene->shading);
        return rc != 0 ? rc : -1;
    }
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if (kept >= 65536)
#endif
    for (size_t k = 0; k < kept; k++) {
        tris[k].order = (unsigned)(others + k);
        tris[k].material += (unsigned)material;
        tris[k].shading = shaded ? (unsigned)(shade + k) : TRIANGLE_PLAIN;
    }
    /* Give back the room of those without area: the capacities are those
     * that adding the kept ones one by one would make. */
    a->count = first + kept;
    if (kept > 0)
        scene->kinds |= 1u << SHAPE_TRIANGLE;
    scene_fit(&a->items, &a->capacity, scene_fit_capacity(a->capacity, a->count, entry_tris),
              sizeof(Triangle));
    if (shaded) {
        scene->shading_count = shade + kept;
        scene_fit((void **)&scene->shading, &scene->shading_capacity,
                  scene_fit_capacity(scene->shading_capacity, scene->shading_count, entry_shading),
                  sizeof *scene->shading);
    }
    return (long)kept;
}

int scene_add_texture(Scene *scene, Texture *tex)
{
    int rc = scene_reserve(scene, (void **)&scene->textures, &scene->texture_capacity,
                           scene->texture_count, sizeof *tex);

    if (rc != 0) {
        texture_free(tex);
        return rc;
    }
    scene->textures[scene->texture_count] = *tex;
    scene->source_hash = hash_u64(hash_u64(scene->source_hash, (uint64_t)tex->width),
                                  (uint64_t)tex->height);
    scene->source_hash = hash_bytes(scene->source_hash, tex->texels,
                                    3 * (size_t)tex->width * (size_t)tex->height *
                                        sizeof *tex->texels);
    return (int)scene->texture_count++;
}

int scene_add_named(Scene *scene, NamedMaterial *m)
{
    int rc = scene_reserve(scene, (void **)&scene->named, &scene->named_capacity,
                           scene->named_count, sizeof *m);

    if (rc != 0) {
        free(m->name);
        free(m->texture);
        return rc;
    }
    scene->named[scene->named_count] = *m;
    return (int)scene->named_count++;
}

int scene_add_warning(Scene *scene, const Error *w)
{
    if (scene->warning_count == SCENE_WARNINGS_MAX) {
        scene->warnings_dropped++;
        return 0;
    }
    if (scene->warning_count == 0) {
        scene->warnings = malloc(SCENE_WARNINGS_MAX * sizeof *scene->warnings);
        if (!scene->warnings)
            return -1;
    }
    scene->warnings[scene->warning_count++] = *w;
    return 0;
}
