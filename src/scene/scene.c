/* scene.c: the scene's storage (see scene.h). */
#include "scene/scene.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh.h"
#include "base/grow.h"
#include "scenefile/obj.h"
#include "base/threads.h"

/* Meshes of fewer triangles are made on one thread. */
enum { SCENE_PARALLEL_MIN = 4096 };

void scene_init(Scene *scene)
{
    memset(scene, 0, sizeof *scene);
    scene->lights = NULL;
    scene->spheres = NULL;
    scene->planes = NULL;
    scene->triangles = NULL;
    scene->textures = NULL;
    scene->phong = NULL;
    scene->meshes = NULL;
    scene->accel = NULL;
}

void scene_free(Scene *scene)
{
    if (scene->accel) {
        bvh_free(scene->accel);
        free(scene->accel);
    }
    for (size_t i = 0; i < scene->texture_count; i++)
        texture_free(&scene->textures[i]);
    free(scene->textures);
    for (size_t i = 0; i < scene->phong_count; i++)
        free(scene->phong[i].name);
    free(scene->phong);
    for (size_t i = 0; i < scene->mesh_count; i++) {
        free(scene->meshes[i].path);
        free(scene->meshes[i].opened);
    }
    free(scene->meshes);
    free(scene->lights);
    free(scene->spheres);
    free(scene->planes);
    free(scene->triangles);
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
    scene_sum(&m, scene->material_capacity * sizeof *scene->materials);
    scene_sum(&m, scene->shading_capacity * sizeof *scene->shading);
    scene_sum(&m, scene->texture_capacity * sizeof *scene->textures);
    scene_sum(&m, scene->phong_capacity * sizeof *scene->phong);
    scene_sum(&m, scene->mesh_capacity * sizeof *scene->meshes);
    for (size_t i = 0; i < scene->texture_count; i++) {
        const PpmImage *im = &scene->textures[i].image;
        scene_sum(&m, 3 * (size_t)im->width * (size_t)im->height * sizeof *im->samples);
    }
    if (scene->accel)
        scene_sum(&m, bvh_memory(scene->accel));
    return m;
}

size_t scene_memory_left(const Scene *scene)
{
    size_t used = scene_memory(scene);

    if (scene->memory_limit == 0)
        return SIZE_MAX;
    return used >= scene->memory_limit ? 0 : scene->memory_limit - used;
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

/* Returns the larger of m and the largest magnitude of p's coordinates. */
static real scene_farther(real m, Vec3 p)
{
    real x = fabs(p.x), y = fabs(p.y), z = fabs(p.z);

    m = x > m ? x : m;
    m = y > m ? y : m;
    return z > m ? z : m;
}

/* Returns the hierarchy's reach (bvh.h): the largest coordinate of the
 * camera, its screen, the lights and the planes. */
static real scene_reach(const Scene *scene)
{
    const Camera *cam = &scene->camera;
    real m = scene_farther(scene_farther(scene_farther(0, cam->eye), cam->top_left),
                           vec3_add(cam->top_left, vec3_add(cam->u, cam->v)));

    for (size_t i = 0; i < scene->light_count; i++)
        m = scene_farther(m, scene->lights[i].position);
    for (size_t i = 0; i < scene->plane_count; i++)
        m = scene_farther(m, scene->planes[i].point);
    return m;
}

int scene_build_accel(Scene *scene, int threads)
{
    Bvh *bvh;
    size_t n = scene->sphere_count + scene->triangle_count;
    BvhShapes shapes = {scene->spheres, scene->sphere_count, scene->triangles,
                        scene->triangle_count};

    if (scene->accel || n < BVH_MIN_PRIMITIVES)
        return 0;
    if (scene->memory_limit && bvh_build_memory(n) > scene_memory_left(scene))
        return SCENE_OVER_LIMIT;
    bvh = malloc(sizeof *bvh);
    if (!bvh || bvh_build(bvh, &shapes, scene_reach(scene), threads) != 0) {
        free(bvh);
        return -1;
    }
    scene->accel = bvh;
    return 0;
}

size_t scene_object_count(const Scene *scene)
{
    return scene->sphere_count + scene->plane_count + scene->triangle_count;
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

int scene_add_sphere(Scene *scene, const Sphere *s)
{
    int rc = scene_reserve(scene, (void **)&scene->spheres, &scene->sphere_capacity,
                           scene->sphere_count, sizeof *s);

    if (rc != 0)
        return rc;
    scene->spheres[scene->sphere_count] = *s;
    scene->spheres[scene->sphere_count].order = (unsigned)scene_object_count(scene);
    scene->sphere_count++;
    scene->has_transparency |= s->material.transparency > 0;
    return 0;
}

int scene_add_plane(Scene *scene, const Plane *p)
{
    int rc = scene_reserve(scene, (void **)&scene->planes, &scene->plane_capacity,
                           scene->plane_count, sizeof *p);

    if (rc != 0)
        return rc;
    scene->planes[scene->plane_count] = *p;
    scene->planes[scene->plane_count].order = (unsigned)scene_object_count(scene);
    scene->plane_count++;
    scene->has_transparency |= p->material.transparency > 0;
    return 0;
}

/* Appends *m to the triangles' materials; returns 0 or what
 * scene_reserve() returned. */
static int scene_add_material(Scene *scene, const Material *m)
{
    int rc = scene_reserve(scene, (void **)&scene->materials, &scene->material_capacity,
                           scene->material_count, sizeof *m);

    if (rc != 0)
        return rc;
    scene->materials[scene->material_count++] = *m;
    scene->has_transparency |= m->transparency > 0;
    return 0;
}

/* Appends a copy of *t with material index material, plain; returns 0 or
 * what scene_reserve() returned. */
static int scene_append_triangle(Scene *scene, const Triangle *t, size_t material)
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
    return 0;
}

int scene_add_triangle(Scene *scene, const Triangle *t, const Material *m)
{
    int rc = scene_add_material(scene, m);

    if (rc == 0 && (rc = scene_append_triangle(scene, t, scene->material_count - 1)) != 0)
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

/* Makes mesh m's triangle i with material index material into *tri, and
 * its shading into *sh unless sh is NULL: smooth when its corners have
 * normals (unless one is zero), textured when they have texture
 * coordinates; returns -1 when it has no area, else 0. */
static int scene_mesh_triangle(const ObjMesh *m, size_t i, size_t material, Triangle *tri,
                               TriangleShading *sh)
{
    const ObjCorner *c = m->tri[i];

    if (triangle_make(tri, m->v[c[0].v], m->v[c[1].v], m->v[c[2].v]) != 0)
        return -1;
    tri->material = (unsigned)material;
    if (!sh)
        return 0;
    *sh = triangle_plain_shading(tri);
    if (c[0].vn >= 0 && c[1].vn >= 0 && c[2].vn >= 0) {
        sh->smooth = 1;
        for (int k = 0; k < 3; k++) {
            Vec3 vn = m->vn[c[k].vn];
            if (!(vec3_length(vn) > 0))
                sh->smooth = 0;
            else
                sh->vn[k] = vec3_normalize(vn);
        }
        if (!sh->smooth)
            sh->vn[0] = sh->vn[1] = sh->vn[2] = tri->normal;
    }
    if (c[0].vt >= 0 && c[1].vt >= 0 && c[2].vt >= 0)
        for (int k = 0; k < 3; k++) {
            sh->uv[k][0] = m->vt[c[k].vt][0];
            sh->uv[k][1] = m->vt[c[k].vt][1];
        }
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

/* Adds mesh m's triangles (with their shading when shaded), made on every
 * thread, into the room made for all of them, then closes the gaps of those
 * without area and gives back the room they took (the capacities are then
 * those that adding them one by one from the entry capacities makes);
 * returns the number added, or -1 when memory for the marks runs out
 * (nothing added). */
static long scene_add_mesh_parallel(Scene *scene, const ObjMesh *m, size_t material,
                                    int shaded, size_t entry_tris, size_t entry_shading)
{
    size_t first = scene->triangle_count, kept = first, i = 0;
    size_t others = scene->sphere_count + scene->plane_count; /* listed before */
    size_t shade = scene->shading_count;                        /* shading of first */
    unsigned char *made = malloc(m->tri_count);
    Triangle *tris = scene->triangles;
    TriangleShading *sh = scene->shading;

    if (!made)
        return -1;
    /* Each in its place, ordered as if none lacked area... */
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for (size_t k = 0; k < m->tri_count; k++) {
        made[k] = scene_mesh_triangle(m, k, material, &tris[first + k],
                                      shaded ? &sh[shade + k] : NULL) == 0;
        tris[first + k].order = (unsigned)(others + first + k);
        if (shaded)
            tris[first + k].shading = (unsigned)(shade + k);
    }
    /* ... then those after the first gap moved down and ordered again. */
    while (i < m->tri_count && made[i])
        i++;
    for (kept = first + i; i < m->tri_count; i++) {
        if (!made[i])
            continue;
        tris[kept] = tris[first + i];
        tris[kept].order = (unsigned)(others + kept);
        if (shaded) {
            sh[shade + kept - first] = sh[shade + i];
            tris[kept].shading = (unsigned)(shade + kept - first);
        }
        kept++;
    }
    free(made);
    scene->triangle_count = kept;
    scene_fit((void **)&scene->triangles, &scene->triangle_capacity,
              scene_fit_capacity(scene->triangle_capacity, kept, entry_tris), sizeof *tris);
    if (shaded) {
        scene->shading_count = shade + kept - first;
        scene_fit((void **)&scene->shading, &scene->shading_capacity,
                  scene_fit_capacity(scene->shading_capacity, scene->shading_count, entry_shading),
                  sizeof *sh);
    }
    return (long)(kept - first);
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
                               first + n, sizeof *scene->spheres), transparent = 0;
    Sphere *room = rc == 0 ? scene->spheres + first : NULL;

    if (rc != 0 || (rc = fill(room, ctx)) != 0) {
        scene_fit((void **)&scene->spheres, &scene->sphere_capacity, entry,
                  sizeof *scene->spheres);
        return rc;
    }
#ifdef _OPENMP
#pragma omp parallel for schedule(static) reduction(| : transparent)
#endif
    for (size_t k = 0; k < n; k++) {
        room[k].order = (unsigned)(others + k);
        transparent |= room[k].material.transparency > 0;
    }
    scene->sphere_count += n;
    scene->has_transparency |= transparent;
    return 0;
}

long scene_add_mesh(Scene *scene, const ObjMesh *m, const Material *mat)
{
    long added = 0;
    size_t left = scene_memory_left(scene), held = obj_memory(m), material;
    int shaded = m->vn_count > 0 || m->vt_count > 0, rc;
    size_t each = sizeof *scene->triangles + (shaded ? sizeof *scene->shading : 0);

    /* The mesh's triangles must fit beside the mesh itself. */
    if (scene->memory_limit && (held > left || m->tri_count > (left - held) / each))
        return SCENE_OVER_LIMIT;
    /* One material for all its triangles. */
    if ((rc = scene_add_material(scene, mat)) != 0)
        return rc;
    material = scene->material_count - 1;
    /* A large mesh is made on every thread when there is room for all its
     * triangles as adding them one by one would make it; else (or when
     * that fails) one by one, which says what went wrong. */
    if (m->tri_count >= SCENE_PARALLEL_MIN && threads_count() > 1) {
        size_t entry_tris = scene->triangle_capacity, entry_shading = scene->shading_capacity;
        rc = scene_reserve_all(scene, (void **)&scene->triangles, &scene->triangle_capacity,
                               scene->triangle_count + m->tri_count, sizeof *scene->triangles);
        if (rc == 0 && shaded)
            rc = scene_reserve_all(scene, (void **)&scene->shading, &scene->shading_capacity,
                                   scene->shading_count + m->tri_count, sizeof *scene->shading);
        if (rc == 0 && (added = scene_add_mesh_parallel(scene, m, material, shaded, entry_tris,
                                                        entry_shading)) >= 0)
            return added;
        added = 0;
        /* As it was: one by one decides. */
        scene_fit((void **)&scene->triangles, &scene->triangle_capacity, entry_tris,
                  sizeof *scene->triangles);
        scene_fit((void **)&scene->shading, &scene->shading_capacity, entry_shading,
                  sizeof *scene->shading);
    }
    for (size_t i = 0; i < m->tri_count; i++) {
        Triangle tri;
        TriangleShading sh;
        if (scene_mesh_triangle(m, i, material, &tri, shaded ? &sh : NULL) != 0)
            continue;
        rc = scene_append_triangle(scene, &tri, material);
        if (rc == 0 && shaded && (rc = scene_shade_triangle(scene, scene->triangle_count - 1,
                                                            &sh)) != 0)
            scene->triangle_count--;
        if (rc != 0)
            return rc;
        added++;
    }
    return added;
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
    return (int)scene->texture_count++;
}

int scene_add_phong(Scene *scene, PhongMaterial *m)
{
    int rc = scene_reserve(scene, (void **)&scene->phong, &scene->phong_capacity,
                           scene->phong_count, sizeof *m);

    if (rc != 0) {
        free(m->name);
        return rc;
    }
    scene->phong[scene->phong_count] = *m;
    return (int)scene->phong_count++;
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

/* Returns the largest magnitude of the components of the n points at p. */
static double scene_points_max(const Vec3 *p, size_t n)
{
    double m = 0;

    for (size_t i = 0; i < n; i++)
        m = fmax(m, vec3_max_abs(p[i]));
    return m;
}

/* Returns the largest magnitude of every length in the scene, or some
 * magnitude of SCENE_TINY or more when there is one (the objects are then
 * not looked at: a scene of 10^6 triangles is seldom tiny). */
static double scene_max_length(const Scene *scene)
{
    const Camera *cam = &scene->camera;
    double m = fmax(fmax(vec3_max_abs(cam->eye), vec3_max_abs(cam->top_left)),
                    fmax(vec3_max_abs(cam->u), vec3_max_abs(cam->v)));

    m = fmax(m, fmax(cam->aperture, cam->aperture > 0 ? cam->focus : 0));
    if (m >= SCENE_TINY)
        return m;
    for (size_t i = 0; i < scene->light_count; i++)
        if (!scene->lights[i].distant) /* a direction, not a place */
            m = fmax(m, vec3_max_abs(scene->lights[i].position));
    for (size_t i = 0; i < scene->sphere_count; i++)
        m = fmax(m, fmax(vec3_max_abs(scene->spheres[i].centre), scene->spheres[i].radius));
    for (size_t i = 0; i < scene->plane_count; i++)
        m = fmax(m, fmax(vec3_max_abs(scene->planes[i].point),
                        scene->planes[i].material.texture >= 0 ? scene->planes[i].tile : 0));
    for (size_t i = 0; i < scene->triangle_count; i++)
        m = fmax(m, scene_points_max(scene->triangles[i].v, 3));
    return m;
}

void scene_fit_scale(Scene *scene)
{
    Camera *cam = &scene->camera;
    double m = scene_max_length(scene);
    int k;

    if (!(m > 0 && m < SCENE_TINY))
        return;
    k = vec3_unit_exponent(m);
    cam->eye = vec3_ldexp(cam->eye, k);
    cam->top_left = vec3_ldexp(cam->top_left, k);
    cam->u = vec3_ldexp(cam->u, k);
    cam->v = vec3_ldexp(cam->v, k);
    cam->aperture = ldexp(cam->aperture, k);
    cam->focus = ldexp(cam->focus, k);
    for (size_t i = 0; i < scene->light_count; i++)
        if (!scene->lights[i].distant)
            scene->lights[i].position = vec3_ldexp(scene->lights[i].position, k);
    for (size_t i = 0; i < scene->sphere_count; i++) {
        scene->spheres[i].centre = vec3_ldexp(scene->spheres[i].centre, k);
        scene->spheres[i].radius = ldexp(scene->spheres[i].radius, k);
    }
    for (size_t i = 0; i < scene->plane_count; i++) {
        scene->planes[i].point = vec3_ldexp(scene->planes[i].point, k);
        scene->planes[i].tile = ldexp(scene->planes[i].tile, k);
    }
    for (size_t i = 0; i < scene->triangle_count; i++)
        for (int j = 0; j < 3; j++)
            scene->triangles[i].v[j] = vec3_ldexp(scene->triangles[i].v[j], k);
    scene->length_exponent = k;
}
