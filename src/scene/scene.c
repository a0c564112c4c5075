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

void scene_init(Scene *scene)
{
    memset(scene, 0, sizeof *scene);
    scene->lights = NULL;
    scene->spheres = NULL;
    scene->planes = NULL;
    scene->triangles = NULL;
    scene->textures = NULL;
    scene->named = NULL;
    scene->meshes = NULL;
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
    for (size_t i = 0; i < scene->mesh_count; i++) {
        free(scene->meshes[i].path);
        free(scene->meshes[i].opened);
    }
    free(scene->meshes);
    free(scene->warnings);
    free(scene->lights);
    free(scene->spheres);
    free(scene->planes);
    free(scene->triangles);
    free(scene->cubes);
    free(scene->squares);
    free(scene->cylinders);
    free(scene->cones);
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
    scene_sum(&m, scene->sphere_capacity * sizeof *scene->spheres);
    scene_sum(&m, scene->plane_capacity * sizeof *scene->planes);
    scene_sum(&m, scene->triangle_capacity * sizeof *scene->triangles);
    scene_sum(&m, scene->cube_capacity * sizeof *scene->cubes);
    scene_sum(&m, scene->square_capacity * sizeof *scene->squares);
    scene_sum(&m, scene->cylinder_capacity * sizeof *scene->cylinders);
    scene_sum(&m, scene->cone_capacity * sizeof *scene->cones);
    scene_sum(&m, scene->material_capacity * sizeof *scene->materials);
    scene_sum(&m, scene->shading_capacity * sizeof *scene->shading);
    scene_sum(&m, scene->texture_capacity * sizeof *scene->textures);
    scene_sum(&m, scene->named_capacity * sizeof *scene->named);
    scene_sum(&m, scene->mesh_capacity * sizeof *scene->meshes);
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

size_t scene_count_of(const Scene *scene, ShapeKind kind)
{
    switch (kind) {
    case SHAPE_SPHERE:
        return scene->sphere_count;
    case SHAPE_PLANE:
        return scene->plane_count;
    case SHAPE_TRIANGLE:
        return scene->triangle_count;
    case SHAPE_CUBE:
        return scene->cube_count;
    case SHAPE_SQUARE:
        return scene->square_count;
    case SHAPE_CYLINDER:
        return scene->cylinder_count;
    default:
        return scene->cone_count;
    }
}

unsigned scene_order_of(const Scene *scene, ShapeKind kind, size_t k)
{
    switch (kind) {
    case SHAPE_SPHERE:
        return scene->spheres[k].order;
    case SHAPE_PLANE:
        return scene->planes[k].order;
    case SHAPE_TRIANGLE:
        return scene->triangles[k].order;
    case SHAPE_CUBE:
        return scene->cubes[k].order;
    case SHAPE_SQUARE:
        return scene->squares[k].order;
    case SHAPE_CYLINDER:
        return scene->cylinders[k].order;
    default:
        return scene->cones[k].order;
    }
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
    switch (kind) {
    case SHAPE_PLANE:
        return &scene->planes[k].material;
    case SHAPE_TRIANGLE:
        return scene_material_of(scene, &scene->triangles[k]);
    case SHAPE_CUBE:
        return &scene->cubes[k].material;
    case SHAPE_SQUARE:
        return &scene->squares[k].material;
    case SHAPE_CYLINDER:
        return &scene->cylinders[k].material;
    default:
        return &scene->cones[k].material;
    }
}

Material *scene_material_edit(Scene *scene, ShapeKind kind, size_t k, int *rc)
{
    Sphere *s;
    Material m;
    long at;

    if (kind != SHAPE_SPHERE)
        return scene_shape_material(scene, kind, k);
    /* A copy of its own: spheres in a row may share one (scene_add_sphere()). */
    s = &scene->spheres[k];
    m = s->material < 0 ? sphere_material(s) : scene->materials[s->material];
    if ((at = scene_add_material(scene, &m)) < 0) {
        *rc = (int)at;
        return NULL;
    }
    s->material = (int)at;
    return &scene->materials[at];
}

/* Widens the box [lo, hi] to hold p, grown by r on each axis. */
static void scene_widen(Vec3 *lo, Vec3 *hi, Vec3 p, real r)
{
    lo->x = fmin(lo->x, p.x - r);
    lo->y = fmin(lo->y, p.y - r);
    lo->z = fmin(lo->z, p.z - r);
    hi->x = fmax(hi->x, p.x + r);
    hi->y = fmax(hi->y, p.y + r);
    hi->z = fmax(hi->z, p.z + r);
}

double scene_size(const Scene *scene)
{
    Vec3 lo = vec3(INFINITY, INFINITY, INFINITY), hi = vec3(-INFINITY, -INFINITY, -INFINITY);
    const Camera *cam = &scene->camera;

    for (size_t i = 0; i < scene->sphere_count; i++)
        scene_widen(&lo, &hi, scene->spheres[i].centre, scene->spheres[i].radius);
    for (size_t i = 0; i < scene->triangle_count; i++)
        for (int k = 0; k < 3; k++)
            scene_widen(&lo, &hi, scene->triangles[i].v[k], 0);
    for (size_t i = 0; i < scene->cube_count; i++) {
        scene_widen(&lo, &hi, scene->cubes[i].lo, 0);
        scene_widen(&lo, &hi, scene->cubes[i].hi, 0);
    }
    for (size_t i = 0; i < scene->square_count; i++)
        scene_widen(&lo, &hi, scene->squares[i].centre, scene->squares[i].half * (real)1.5);
    for (size_t i = 0; i < scene->plane_count; i++)
        scene_widen(&lo, &hi, scene->planes[i].point, 0);
    for (size_t i = 0; i < scene->cylinder_count; i++)
        scene_widen(&lo, &hi, scene->cylinders[i].centre, scene->cylinders[i].radius);
    for (size_t i = 0; i < scene->cone_count; i++) {
        scene_widen(&lo, &hi, scene->cones[i].base, scene->cones[i].radius);
        scene_widen(&lo, &hi, scene->cones[i].apex, 0);
    }
    if (!(lo.x < hi.x || lo.y < hi.y || lo.z < hi.z)) {
        scene_widen(&lo, &hi, cam->eye, 0);
        scene_widen(&lo, &hi, cam->top_left, 0);
        scene_widen(&lo, &hi, vec3_add(cam->top_left, vec3_add(cam->u, cam->v)), 0);
    }
    return vec3_length(vec3_sub(hi, lo));
}

size_t scene_object_count(const Scene *scene)
{
    return scene->sphere_count + scene->plane_count + scene->triangle_count + scene->cube_count +
           scene->square_count + scene->cylinder_count + scene->cone_count;
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

/* Appends the size bytes at item to the array *items of *count items (room
 * for *capacity), giving it its position among the objects (the unsigned
 * at byte `order` of it) and noting its material m's transparency;
 * returns 0 or what scene_reserve() returned. */
static int scene_push_shape(Scene *scene, ShapeKind kind, void **items, size_t *capacity,
                            size_t *count, const void *item, size_t size, size_t order,
                            const Material *m)
{
    int rc = scene_reserve(scene, items, capacity, *count, size);
    unsigned position = (unsigned)scene_object_count(scene);
    char *at;

    if (rc != 0)
        return rc;
    at = (char *)*items + *count * size;
    memcpy(at, item, size);
    memcpy(at + order, &position, sizeof position);
    (*count)++;
    scene->kinds |= 1u << kind;
    scene->has_transparency |= m->transparency > 0;
    return 0;
}

int scene_add_sphere(Scene *scene, Vec3 centre, real radius, const Material *m)
{
    Sphere s = {centre, radius, 0, 0, -1, {0, 0, 0}};
    long at = -1;
    int rc, last = scene->sphere_count > 0 ? scene->spheres[scene->sphere_count - 1].material : -1;

    if (sphere_plain(m))
        sphere_set_plain(&s, m);
    else if (last >= 0 && memcmp(&scene->materials[last], m, sizeof *m) == 0)
        s.material = last; /* the previous sphere's: shared (an edit copies it first) */
    else if ((at = scene_add_material(scene, m)) < 0)
        return (int)at;
    else
        s.material = (int)at;
    rc = scene_push_shape(scene, SHAPE_SPHERE, (void **)&scene->spheres, &scene->sphere_capacity,
                          &scene->sphere_count, &s, sizeof s, offsetof(Sphere, order), m);
    if (rc != 0 && at >= 0)
        scene->material_count--;
    return rc;
}

int scene_add_plane(Scene *scene, const Plane *p)
{
    return scene_push_shape(scene, SHAPE_PLANE, (void **)&scene->planes, &scene->plane_capacity,
                            &scene->plane_count, p, sizeof *p, offsetof(Plane, order),
                            &p->material);
}

int scene_add_cube(Scene *scene, const Cube *c)
{
    return scene_push_shape(scene, SHAPE_CUBE, (void **)&scene->cubes, &scene->cube_capacity,
                            &scene->cube_count, c, sizeof *c, offsetof(Cube, order), &c->material);
}

int scene_add_square(Scene *scene, const Square *s)
{
    return scene_push_shape(scene, SHAPE_SQUARE, (void **)&scene->squares, &scene->square_capacity,
                            &scene->square_count, s, sizeof *s, offsetof(Square, order),
                            &s->material);
}

int scene_add_cylinder(Scene *scene, const Cylinder *c)
{
    return scene_push_shape(scene, SHAPE_CYLINDER, (void **)&scene->cylinders, &scene->cylinder_capacity,
                            &scene->cylinder_count, c, sizeof *c, offsetof(Cylinder, order),
                            &c->material);
}

int scene_add_cone(Scene *scene, const Cone *c)
{
    return scene_push_shape(scene, SHAPE_CONE, (void **)&scene->cones, &scene->cone_capacity,
                            &scene->cone_count, c, sizeof *c, offsetof(Cone, order), &c->material);
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
    int rc = scene_reserve(scene, (void **)&scene->triangles, &scene->triangle_capacity,
                           scene->triangle_count, sizeof *t);

    if (rc != 0)
        return rc;
    scene->triangles[scene->triangle_count] = *t;
    scene->triangles[scene->triangle_count].order = (unsigned)scene_object_count(scene);
    scene->triangles[scene->triangle_count].shading = TRIANGLE_PLAIN;
    scene->triangles[scene->triangle_count].material = (unsigned)material;
    scene->triangle_count++;
    scene->kinds |= 1u << SHAPE_TRIANGLE;
    if (sh && (rc = scene_shade_triangle(scene, scene->triangle_count - 1, sh)) != 0)
        scene->triangle_count--;
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
    Triangle *tri = &scene->triangles[i];
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
    size_t entry = scene->sphere_capacity, first = scene->sphere_count;
    size_t others = scene_object_count(scene); /* listed before */
    int rc = scene_reserve_all(scene, (void **)&scene->spheres, &scene->sphere_capacity,
                               first + n, sizeof *scene->spheres);
    Sphere *room = rc == 0 ? scene->spheres + first : NULL;

    if (rc != 0 || (rc = fill(room, ctx)) != 0) {
        scene_fit((void **)&scene->spheres, &scene->sphere_capacity, entry,
                  sizeof *scene->spheres);
        return rc;
    }
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for (size_t k = 0; k < n; k++) {
        room[k].order = (unsigned)(others + k);
    }
    scene->sphere_count += n;
    scene->kinds |= 1u << SHAPE_SPHERE;
    return 0;
}

long scene_add_triangles(Scene *scene, size_t n, size_t material, int shaded,
                         size_t (*fill)(Triangle *tris, TriangleShading *sh, void *ctx), void *ctx)
{
    size_t entry_tris = scene->triangle_capacity, entry_shading = scene->shading_capacity;
    size_t first = scene->triangle_count, shade = scene->shading_count, kept;
    size_t others = scene_object_count(scene); /* listed before */
    int rc = scene_reserve_all(scene, (void **)&scene->triangles, &scene->triangle_capacity,
                               first + n, sizeof *scene->triangles);
    Triangle *tris;

    if (rc == 0 && shaded)
        rc = scene_reserve_all(scene, (void **)&scene->shading, &scene->shading_capacity,
                               shade + n, sizeof *scene->shading);
    kept = rc == 0 ? fill(scene->triangles + first, shaded ? scene->shading + shade : NULL, ctx)
                   : SIZE_MAX;
    if (kept > n) { /* as it was */
        scene_fit((void **)&scene->triangles, &scene->triangle_capacity, entry_tris,
                  sizeof *scene->triangles);
        scene_fit((void **)&scene->shading, &scene->shading_capacity, entry_shading,
                  sizeof *scene->shading);
        return rc != 0 ? rc : -1;
    }
    tris = scene->triangles + first;
#ifdef _OPENMP
#pragma omp parallel for schedule(static) if (kept >= 65536)
#endif
    for (size_t k = 0; k < kept; k++) {
        tris[k].order = (unsigned)(others + k);
        tris[k].material = (unsigned)material;
        tris[k].shading = shaded ? (unsigned)(shade + k) : TRIANGLE_PLAIN;
    }
    /* Give back the room of those without area: the capacities are those
     * that adding the kept ones one by one would make. */
    scene->triangle_count = first + kept;
    if (kept > 0)
        scene->kinds |= 1u << SHAPE_TRIANGLE;
    scene_fit((void **)&scene->triangles, &scene->triangle_capacity,
              scene_fit_capacity(scene->triangle_capacity, scene->triangle_count, entry_tris),
              sizeof *scene->triangles);
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

int scene_add_mesh_record(Scene *scene, SceneMesh *mesh)
{
    int rc = scene_reserve(scene, (void **)&scene->meshes, &scene->mesh_capacity,
                           scene->mesh_count, sizeof *mesh);

    if (rc != 0) {
        free(mesh->path);
        free(mesh->opened);
        return rc;
    }
    scene->meshes[scene->mesh_count++] = *mesh;
    return 0;
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
