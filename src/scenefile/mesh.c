/* mesh.c: mesh files into the scene's triangles (see mesh.h). */
#include "scenefile/mesh.h"

#include <ctype.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "base/hash.h"
#include "base/threads.h"
#include "scenefile/obj.h"
#include "scenefile/ply.h"
#include "scenefile/stl.h"
#include "scenefile/texture_file.h"

/* Meshes of fewer triangles are made on one thread. */
enum { MESH_PARALLEL_MIN = 4096 };

/* The formats of mesh files. */
typedef enum { MESH_OBJ, MESH_PLY, MESH_STL } MeshFormat;

/* Says whether path's extension is ext (".ply"), in any case. */
static int mesh_extension(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);

    if (n < e)
        return 0;
    for (size_t i = 0; i < e; i++)
        if (tolower((unsigned char)path[n - e + i]) != ext[i])
            return 0;
    return 1;
}

/* Returns the format of the len bytes at data: by their content, or when
 * that says nothing, by path's extension. */
static MeshFormat mesh_format(const char *path, const char *data, size_t len)
{
    if (ply_is(data, len))
        return MESH_PLY;
    if (stl_is_binary((const unsigned char *)data, len) || stl_is_ascii(data, len))
        return MESH_STL;
    if (mesh_extension(path, ".ply"))
        return MESH_PLY;
    /* Binary bytes named .stl: an STL file cut short, which its reader
     * says. */
    if (mesh_extension(path, ".stl"))
        return MESH_STL;
    return MESH_OBJ;
}

int mesh_read(const char *path, size_t max_bytes, MeshFile *mesh, Error *err)
{
    const char *name = file_display_name(path);
    char *data;
    size_t len;
    int rc;

    mesh_file_init(mesh);
    if (file_read_all(path, &data, &len, err) != 0)
        return -1;
    switch (mesh_format(path, data, len)) {
    case MESH_PLY:
        rc = ply_parse(name, data, len, max_bytes, mesh, err);
        if (rc == 0)
            mesh->hash = hash_bytes(HASH_START, data, len);
        break;
    case MESH_STL:
        rc = stl_parse(name, data, len, max_bytes, mesh, err);
        if (rc == 0)
            mesh->hash = hash_bytes(HASH_START, data, len);
        break;
    default: /* its material libraries too */
        rc = obj_load(path, data, len, max_bytes, mesh, err);
        break;
    }
    free(data);
    if (rc == 0 && mesh_file_cut(mesh) != 0) {
        error_set(err, name, "out of memory");
        mesh_file_free(mesh);
        rc = -1;
    }
    return rc;
}

/* The scene's materials a mesh's triangles take: the first's index, and
 * for each of the file's materials (or the one given) its offset. */
typedef struct {
    const MeshFile *m;
    size_t base;        /* the scene's material of the file's first */
    int own;            /* 1: the file's materials (else one for all) */
    int coloured;       /* 1: its vertices' colours colour it */
    int shaded;         /* 1: its triangles have shading entries */
} MeshBuild;

/* Returns the mean of the three channels of c. */
static double mesh_mean(const double c[3])
{
    return (c[0] + c[1] + c[2]) / 3;
}

/* Returns MTL's colour channel x (0 to 1) on the scale of 0 to 255. */
static double mesh_channel(double x)
{
    return x > 1 ? 255 : x > 0 ? 255 * x : 0;
}

/* Makes the renderer's material of MTL material mm (its texture index
 * tex, or -1) under the course's rule: the colour Kd (or the texture), the
 * mirror weight and glass its illum asks for (docs/scene-format.md). */
static Material mesh_course_material(const MeshMaterial *mm, int tex)
{
    static const int mirrors[11] = {0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 0};
    static const int refracts[11] = {0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0};
    int illum = mm->illum < 0 ? 2 : mm->illum;
    double t = 1 - mm->d, r = mirrors[illum] ? mesh_mean(mm->ks) : 0;
    Material m = material_plain(colour(mesh_channel(mm->kd[0]), mesh_channel(mm->kd[1]),
                                       mesh_channel(mm->kd[2])),
                                0);

    r = r > 1 ? 1 : r > 0 ? r : 0;
    m.reflection = r + t > 1 ? 1 - t : r;
    m.transparency = t;
    m.ior = t > 0 && refracts[illum] ? mm->ni : 1;
    m.texture = tex;
    m.filter = TEXTURE_BILINEAR;
    return m;
}

/* Adds the scene's material of MTL material mm (texture index tex) for a
 * mesh of scene: under the course's rule in a course scene, else
 * Blinn-Phong (a named material of the mesh's own: kd 1 and the colour Kd,
 * ka the ambient Ka over Kd, ks the highlight's Ks, alpha Ns); returns its
 * index, or -1 or SCENE_OVER_LIMIT. */
static long mesh_add_material(Scene *scene, const MeshMaterial *mm, int tex)
{
    Material m = mesh_course_material(mm, tex);
    NamedMaterial pm;
    double kd = mesh_mean(mm->kd), ka = mesh_mean(mm->ka);
    int index;

    if (scene->format == SCENE_COURSE)
        return scene_add_material(scene, &m);
    memset(&pm, 0, sizeof pm);
    pm.base = m;
    pm.model = MODEL_PHONG;
    pm.kd = 1;
    pm.ka = kd > 0 ? ka / kd : ka;
    pm.ka = pm.ka > 0 ? pm.ka : 0;
    /* An exponent under 1 spreads the "highlight" over the whole
     * hemisphere (3ds Max writes Ns 0 for glossiness 0): none. */
    pm.ks = mm->illum == 0 || mm->illum == 1 || mm->ns < 1 ? 0 : mesh_mean(mm->ks);
    pm.ks = pm.ks > 0 ? pm.ks : 0;
    pm.shininess = mm->ns;
    pm.from_mesh = 1;
    index = scene_add_named(scene, &pm);
    if (index < 0)
        return index;
    scene->named[index].base.named = index;
    return scene_add_material(scene, &scene->named[index].base);
}

/* Reads the texture of MTL material mm into the scene, or warns that it
 * cannot; returns its index, -1 without one, or -2 when memory runs out. */
static int mesh_texture(Scene *scene, const MeshMaterial *mm)
{
    Error inner, w;
    int tex;

    if (!mm->texture)
        return -1;
    tex = texture_file_add(scene, mm->texture, &inner);
    if (tex >= 0)
        return tex;
    if (tex != TEXTURE_FILE_FAULT)
        return -2;
    w = *mm->texture_at;
    snprintf(w.message, sizeof w.message, "cannot use the texture '%.200s': %.200s: its faces "
             "are drawn in their colour", mm->texture, inner.message);
    return scene_add_warning(scene, &w) != 0 ? -2 : -1;
}

/* Adds the scene's materials for mesh m (mat, or when NULL the file's)
 * into b and info; returns 0, or -1 or SCENE_OVER_LIMIT. */
static int mesh_materials(Scene *scene, const MeshFile *m, const Material *mat, MeshBuild *b,
                          SceneMesh *info)
{
    MeshMaterial grey;
    long index;
    size_t n = m->material_count ? m->material_count : 1;

    b->m = m;
    b->own = mat == NULL;
    b->coloured = b->own && m->vc != NULL;
    b->shaded = m->vn_count > 0 || m->vt_count > 0 || b->coloured;
    if (!b->own) {
        index = scene_add_material(scene, mat);
        b->base = (size_t)index;
        info->materials = 1;
        return index < 0 ? (int)index : 0;
    }
    mesh_material_default(&grey, NULL);
    for (size_t k = 0; k < n; k++) {
        const MeshMaterial *mm = m->material_count ? &m->materials[k] : &grey;
        int tex = mesh_texture(scene, mm);
        if (tex == -2)
            return -1;
        index = mesh_add_material(scene, mm, tex);
        if (index < 0)
            return (int)index;
        if (k == 0)
            b->base = (size_t)index;
        info->textures += tex >= 0;
    }
    info->materials = n;
    return 0;
}

/* Makes triangle i of the mesh b builds into *tri, and its shading into
 * *sh unless sh is NULL: smooth when its corners have normals (unless one
 * is zero), textured when they have texture coordinates (as its MTL
 * material's map scales and moves them), coloured by its vertices when
 * they have colours; returns -1 when it has no area, else 0. */
static int mesh_triangle(const MeshBuild *b, size_t i, Triangle *tri, TriangleShading *sh)
{
    const MeshFile *m = b->m;
    const MeshCorner *c = m->tri[i];
    const MeshMaterial *mm = b->own && m->tri_material ? &m->materials[m->tri_material[i]] : NULL;

    if (triangle_make(tri, m->v[c[0].v], m->v[c[1].v], m->v[c[2].v]) != 0)
        return -1;
    /* Its material among the mesh's: the scene's is b->base more. */
    tri->material = b->own && m->tri_material ? m->tri_material[i] : 0;
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
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 2; a++)
                sh->uv[k][a] = mm ? m->vt[c[k].vt][a] * mm->uv_scale[a] + mm->uv_offset[a]
                                  : m->vt[c[k].vt][a];
    if (b->coloured) {
        sh->coloured = 1;
        for (int k = 0; k < 3; k++)
            for (int a = 0; a < 3; a++)
                sh->rgb[k][a] = m->vc[c[k].v][a];
    }
    return 0;
}

/* Makes every triangle of the mesh ctx builds into tris (and its shading
 * into sh unless NULL) on every thread, each in its place, then closes the
 * gaps of those without area; returns how many are kept, or SIZE_MAX when
 * memory for the marks runs out (scene_add_triangles()'s fill). */
static size_t mesh_fill(Triangle *tris, TriangleShading *sh, void *ctx)
{
    const MeshBuild *b = ctx;
    size_t n = b->m->tri_count, i = 0, kept;
    unsigned char *made = malloc(n);

    if (!made)
        return SIZE_MAX;
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for (size_t k = 0; k < n; k++)
        made[k] = mesh_triangle(b, k, &tris[k], sh ? &sh[k] : NULL) == 0;
    while (i < n && made[i])
        i++;
    for (kept = i; i < n; i++) {
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

long mesh_add(Scene *scene, const MeshFile *m, const Material *mat, SceneMesh *info)
{
    long added = 0;
    size_t left = scene_memory_left(scene), held = mesh_file_memory(m), each;
    MeshBuild b;
    int rc;

    scene->source_hash = hash_u64(scene->source_hash, m->hash);
    b.coloured = mat == NULL && m->vc != NULL;
    each = sizeof(Triangle) +
           (m->vn_count > 0 || m->vt_count > 0 || b.coloured ? sizeof(TriangleShading) : 0);
    /* The mesh's triangles must fit beside the mesh itself. */
    if (scene->memory_limit && (held > left || m->tri_count > (left - held) / each))
        return SCENE_OVER_LIMIT;
    rc = mesh_materials(scene, m, mat, &b, info);
    if (rc != 0)
        return rc;
    info->format = m->format;
    info->polygons = m->polygon_count;
    info->polygons_cut = m->polygons_cut;
    info->polygons_irregular = m->polygons_irregular;
    /* A large mesh is made on every thread when there is room for all its
     * triangles; else (or when that fails) one by one, which says what went
     * wrong. The material each triangle gets is set by mesh_triangle(). */
    if (m->tri_count >= MESH_PARALLEL_MIN && threads_count() > 1) {
        added = scene_add_triangles(scene, m->tri_count, b.base, b.shaded, mesh_fill, &b);
        if (added >= 0)
            return added;
        added = 0;
    }
    for (size_t i = 0; i < m->tri_count; i++) {
        Triangle tri;
        TriangleShading sh;
        if (mesh_triangle(&b, i, &tri, b.shaded ? &sh : NULL) != 0)
            continue;
        rc = scene_append_triangle(scene, &tri, b.base + tri.material, b.shaded ? &sh : NULL);
        if (rc != 0)
            return rc;
        added++;
    }
    return added;
}

/* Keeps the warnings of mesh m in the scene's; returns 0, or -1. */
static int mesh_warnings(Scene *scene, const MeshFile *m)
{
    for (size_t i = 0; i < m->warning_count; i++)
        if (scene_add_warning(scene, &m->warnings[i]) != 0)
            return -1;
    scene->warnings_dropped += m->warnings_dropped;
    return 0;
}

long mesh_load(Lexer *L, const Record *rec, const Token *t, const Material *mat, Scene *scene,
               SceneSource *source)
{
    SceneMesh sm;
    MeshFile mesh;
    Error inner;
    long added;
    int rc;

    memset(&sm, 0, sizeof sm);
    sm.opened = lex_path(L, t);
    sm.first = scene_count_of(scene, SHAPE_TRIANGLE);
    sm.own_materials = mat == NULL;
    if (!sm.opened)
        return MESH_FAULT;
    if (mesh_read(sm.opened, scene_obj_budget(scene), &mesh, &inner) != 0) {
        lex_fail_file(L, rec, t, "mesh", &inner);
        free(sm.opened);
        return MESH_FAULT;
    }
    /* The reader's warnings first: they come from the files mesh_add()'s
     * textures are named in. */
    added = mesh_warnings(scene, &mesh) != 0 ? -1 : mesh_add(scene, &mesh, mat, &sm);
    sm.libraries = mesh.libraries;
    sm.library_count = mesh.library_count;
    mesh.libraries = NULL;
    mesh.library_count = 0;
    mesh_file_free(&mesh);
    if (added > 0)
        sm.path = malloc(t->len + 1);
    if (added <= 0 || !sm.path) {
        for (size_t k = 0; k < sm.library_count; k++)
            free(sm.libraries[k]);
        free(sm.libraries);
        free(sm.opened);
        return added <= 0 ? added : -1;
    }
    sm.count = (size_t)added;
    memcpy(sm.path, t->text, t->len);
    sm.path[t->len] = '\0';
    rc = source_add_mesh(source, &sm);
    return rc != 0 ? rc : added;
}
