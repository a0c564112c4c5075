/* obj.c: Wavefront OBJ reading (see obj.h), the whole of it: the lines
 * (obj_lines.c), on every thread for a large file (obj_parts.c), then the
 * material libraries (mtl.h) and the faces cut (mesh_file.h). */
#include "scenefile/obj.h"

#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "base/hash.h"
#include "base/threads.h"
#include "obj_read.h"

/* Gives each triangle of m its index among m's materials (OBJ_DEFAULT
 * becomes the default material, added at the end when some triangle has
 * it), taking over names' materials; NULL materials when no usemtl named
 * one. Returns 0, or -1 when memory runs out. */
static int obj_settle_materials(MeshFile *m, ObjNames *names)
{
    size_t defaults = 0;

    if (!m->tri_material)
        return 0;
    m->materials = names->mats;
    m->material_count = names->count;
    names->mats = NULL;
    names->count = names->capacity = 0;
    for (size_t t = 0; t < m->tri_count; t++)
        defaults += m->tri_material[t] == OBJ_DEFAULT;
    if (defaults > 0) {
        void *grown = realloc(m->materials, (m->material_count + 1) * sizeof *m->materials);
        if (!grown)
            return -1;
        m->materials = grown;
        mesh_material_default(&m->materials[m->material_count], NULL);
        for (size_t t = 0; t < m->tri_count; t++)
            if (m->tri_material[t] == OBJ_DEFAULT)
                m->tri_material[t] = (uint32_t)m->material_count;
        m->material_count++;
    }
    return 0;
}

/* obj_settle_materials() for the mesh named name; on failure, releases
 * both and says so in *err. */
static int obj_settle(const char *name, MeshFile *mesh, ObjNames *names, Error *err)
{
    if (obj_settle_materials(mesh, names) == 0)
        return 0;
    error_set(err, name, "out of memory");
    obj_names_free(names);
    mesh_file_free(mesh);
    return -1;
}

/* Reads the OBJ text into *mesh and the libraries it names into *names;
 * returns 0, or -1 with *err (both empty). */
static int obj_read(const char *name, const char *data, size_t len, size_t max_bytes,
                    MeshFile *mesh, ObjNames *names, Error *err)
{
    size_t caps[OBJ_CAPS] = {0, 0, 0, 0, 0, 0};
    const char *p = data, *end = data + len;
    ObjReader r = {name, NULL, 0, 0, err, max_bytes, 0, 0, 0, {NULL, 0, 0, NULL, 0, 0, 0}};
    int odd, threads = threads_count();

    mesh_file_init(mesh);
    mesh->format = "OBJ";
    memset(names, 0, sizeof *names);
    r.names.current = OBJ_DEFAULT;
    if (len >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0)
        p += 3;
    /* Lines are searched for NUL bytes and carriage returns only when the
     * file holds some; a large file without them is read by every thread. */
    odd = memchr(p, '\0', (size_t)(end - p)) || memchr(p, '\r', (size_t)(end - p));
    if (!odd && threads > 1 && (size_t)(end - p) >= OBJ_PARALLEL_MIN &&
        obj_parse_parallel(name, p, (size_t)(end - p), max_bytes, threads, mesh, names) == 0)
        return obj_settle(name, mesh, names, err);
    if (obj_parse_lines(&r, mesh, caps, p, end, odd) != 0) {
        obj_names_free(&r.names);
        mesh_file_free(mesh);
        return -1;
    }
    *names = r.names;
    return obj_settle(name, mesh, names, err);
}

int obj_parse(const char *name, const char *data, size_t len, size_t max_bytes, MeshFile *mesh,
              Error *err)
{
    ObjNames names;

    if (obj_read(name, data, len, max_bytes, mesh, &names, err) != 0)
        return -1;
    obj_names_free(&names);
    return 0;
}

int obj_load(const char *path, const char *data, size_t len, size_t max_bytes, MeshFile *mesh,
             Error *err)
{
    ObjNames names;
    int rc;

    rc = obj_read(file_display_name(path), data, len, max_bytes, mesh, &names, err);
    if (rc == 0) {
        mesh->hash = hash_bytes(HASH_START, data, len);
        rc = mtl_read_libraries(path, names.libs, names.lib_count, mesh, err);
        obj_names_free(&names);
        if (rc != 0)
            mesh_file_free(mesh);
    }
    /* The materials' positions in the text go with it. */
    for (size_t i = 0; i < mesh->material_count; i++)
        mesh->materials[i].used_at = NULL;
    return rc;
}
