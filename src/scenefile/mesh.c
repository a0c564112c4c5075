/* mesh.c: OBJ meshes into the scene's triangles (see mesh.h). */
#include "scenefile/mesh.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/hash.h"
#include "base/threads.h"

/* Meshes of fewer triangles are made on one thread. */
enum { MESH_PARALLEL_MIN = 4096 };

/* Makes mesh m's triangle i into *tri, and its shading into *sh unless sh
 * is NULL: smooth when its corners have normals (unless one is zero),
 * textured when they have texture coordinates; returns -1 when it has no
 * area, else 0. */
static int mesh_triangle(const ObjMesh *m, size_t i, Triangle *tri, TriangleShading *sh)
{
    const ObjCorner *c = m->tri[i];

    if (triangle_make(tri, m->v[c[0].v], m->v[c[1].v], m->v[c[2].v]) != 0)
        return -1;
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

/* Makes every triangle of the mesh ctx into tris (and its shading into sh
 * unless NULL) on every thread, each in its place, then closes the gaps of
 * those without area; returns how many are kept, or SIZE_MAX when memory
 * for the marks runs out (scene_add_triangles()'s fill). */
static size_t mesh_fill(Triangle *tris, TriangleShading *sh, void *ctx)
{
    const ObjMesh *m = ctx;
    unsigned char *made = malloc(m->tri_count);
    size_t i = 0, kept;

    if (!made)
        return SIZE_MAX;
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for (size_t k = 0; k < m->tri_count; k++)
        made[k] = mesh_triangle(m, k, &tris[k], sh ? &sh[k] : NULL) == 0;
    while (i < m->tri_count && made[i])
        i++;
    for (kept = i; i < m->tri_count; i++) {
        if (!made[i])
            continue;
        tris[kept] = tris[i];
        if (sh)
            sh[kept] = sh[i];
        kept++;
    }
    free(made);
    return kept;
}

long mesh_add(Scene *scene, const ObjMesh *m, const Material *mat)
{
    scene->source_hash = hash_u64(scene->source_hash, m->hash);
    long added = 0, material;
    size_t left = scene_memory_left(scene), held = obj_memory(m);
    int shaded = m->vn_count > 0 || m->vt_count > 0, rc;
    size_t each = sizeof(Triangle) + (shaded ? sizeof(TriangleShading) : 0);

    /* The mesh's triangles must fit beside the mesh itself. */
    if (scene->memory_limit && (held > left || m->tri_count > (left - held) / each))
        return SCENE_OVER_LIMIT;
    /* One material for all its triangles. */
    material = scene_add_material(scene, mat);
    if (material < 0)
        return material;
    /* A large mesh is made on every thread when there is room for all its
     * triangles; else (or when that fails) one by one, which says what went
     * wrong. */
    if (m->tri_count >= MESH_PARALLEL_MIN && threads_count() > 1) {
        added = scene_add_triangles(scene, m->tri_count, (size_t)material, shaded, mesh_fill,
                                    (void *)m);
        if (added >= 0)
            return added;
        added = 0;
    }
    for (size_t i = 0; i < m->tri_count; i++) {
        Triangle tri;
        TriangleShading sh;
        if (mesh_triangle(m, i, &tri, shaded ? &sh : NULL) != 0)
            continue;
        rc = scene_append_triangle(scene, &tri, (size_t)material, shaded ? &sh : NULL);
        if (rc != 0)
            return rc;
        added++;
    }
    return added;
}

long mesh_load(Lexer *L, const Record *rec, const Token *t, const Material *mat, Scene *scene,
               SceneSource *source)
{
    SceneMesh sm = {NULL, lex_path(L, t), scene_count_of(scene, SHAPE_TRIANGLE), 0};
    ObjMesh mesh;
    Error inner;
    long added;
    int rc;

    if (!sm.opened)
        return MESH_FAULT;
    if (obj_load(sm.opened, scene_obj_budget(scene), &mesh, &inner) != 0) {
        lex_fail_file(L, rec, t, "mesh", &inner);
        free(sm.opened);
        return MESH_FAULT;
    }
    added = mesh_add(scene, &mesh, mat);
    obj_free(&mesh);
    if (added <= 0) {
        free(sm.opened);
        return added;
    }
    sm.count = (size_t)added;
    sm.path = malloc(t->len + 1);
    if (!sm.path) {
        free(sm.opened);
        return -1;
    }
    memcpy(sm.path, t->text, t->len);
    sm.path[t->len] = '\0';
    rc = source_add_mesh(source, &sm);
    return rc != 0 ? rc : added;
}
