/* obj_parts.c: a large OBJ file read by every thread (see obj_read.h). */
#include "obj_read.h"

#include <stdlib.h>
#include <string.h>

#include "base/grow.h"
#include "scenefile/lex.h"

enum { OBJ_PARTS_MAX = 64 };

/* What a part of the file holds, counted before it is read: v, vt, vn
 * records, triangles, faces of more than three corners, usemtl lines. */
enum { OBJ_COUNTS = 6 };

typedef struct {
    const char *start, *end; /* its lines */
    size_t lines;            /* line endings */
    size_t count[OBJ_COUNTS];
    ObjNames names;          /* the names its lines gave */
    int failed;
} ObjPart;

/* Counts the lines of part and the records they hold, as obj_record()
 * would read them if they are right (a wrong one is found when read). */
static void obj_count(ObjPart *part)
{
    const char *p = part->start, *end = part->end;

    memset(part->count, 0, sizeof part->count);
    part->lines = 0;
    while (p < end) {
        const char *eol = memchr(p, '\n', (size_t)(end - p)), *hash, *s;
        size_t len = (size_t)((eol ? eol : end) - p), i = 0, n;

        s = p;
        p = eol ? eol + 1 : end;
        part->lines += eol != NULL;
        hash = memchr(s, '#', len);
        if (hash)
            len = (size_t)(hash - s);
        while (i < len && (s[i] == ' ' || s[i] == '\t'))
            i++;
        for (n = 0; i + n < len && s[i + n] != ' ' && s[i + n] != '\t'; n++)
            ;
        if (n == 1 && s[i] == 'v') {
            part->count[0]++;
        } else if (n == 2 && s[i] == 'v') {
            part->count[1] += s[i + 1] == 't';
            part->count[2] += s[i + 1] == 'n';
        } else if (n == 1 && s[i] == 'f') {
            size_t corners = 0;
            for (i += n; i < len;) {
                while (i < len && (s[i] == ' ' || s[i] == '\t'))
                    i++;
                if (i == len)
                    break;
                corners++;
                while (i < len && s[i] != ' ' && s[i] != '\t')
                    i++;
            }
            part->count[3] += corners > 2 ? corners - 2 : 0;
            part->count[4] += corners > 3;
        } else if (n == 6 && memcmp(s + i, "usemtl", 6) == 0) {
            part->count[5]++;
        }
    }
}

/* Returns the capacity a growing array reaches for count items. */
static size_t obj_grown(size_t count)
{
    size_t cap = 0;

    while (cap < count)
        cap = grow_next_capacity(cap);
    return cap;
}

/* Reads part k of parts into its place in *mesh (whose arrays are sized
 * for all of them); sets its failed flag when anything is wrong. */
static void obj_read_part(const char *name, ObjPart *parts, int k, MeshFile *mesh)
{
    /* Part k's records go after those of the parts before it. */
    MeshFile view = *mesh;
    size_t caps[OBJ_CAPS], before[OBJ_COUNTS] = {0, 0, 0, 0, 0, 0};
    ObjReader r = {name, NULL, 0, 0, NULL, 0, 0, 1, 0, {NULL, 0, 0, NULL, 0, 0, OBJ_INHERIT}};
    Error err;

    r.err = &err;
    if (k == 0)
        r.names.current = OBJ_DEFAULT;
    for (int j = 0; j < k; j++) {
        r.lineno += (int)parts[j].lines;
        for (int a = 0; a < OBJ_COUNTS; a++)
            before[a] += parts[j].count[a];
    }
    view.v_count = before[0];
    view.vt_count = before[1];
    view.vn_count = before[2];
    view.tri_count = before[3];
    view.polygon_count = before[4];
    r.tri_base = 0; /* the view's triangles are the whole mesh's */
    caps[0] = before[0] + parts[k].count[0];
    caps[1] = before[1] + parts[k].count[1];
    caps[2] = before[2] + parts[k].count[2];
    caps[3] = caps[4] = before[3] + parts[k].count[3];
    caps[5] = before[4] + parts[k].count[4];
    parts[k].failed = obj_parse_lines(&r, &view, caps, parts[k].start, parts[k].end, 0) != 0 ||
                      view.v_count != caps[0] || view.vt_count != caps[1] ||
                      view.vn_count != caps[2] || view.tri_count != caps[3] ||
                      view.polygon_count != caps[5];
    parts[k].names = r.names;
}

/* Finds the material named name in names, adding it (taking *m's name)
 * when it is not there; returns its index, or -1 when memory runs out. */
static long obj_join_name(ObjNames *names, MeshMaterial *m)
{
    for (size_t i = 0; i < names->count; i++)
        if (strcmp(names->mats[i].name, m->name) == 0)
            return (long)i;
    if (grow_reserve((void **)&names->mats, &names->capacity, names->count,
                     sizeof *names->mats) != 0)
        return -1;
    names->mats[names->count] = *m;
    m->name = NULL;
    return (long)names->count++;
}

/* Joins the parts' names into *names, in order, and gives each triangle of
 * mesh the index of its material among them (or OBJ_DEFAULT); returns 0,
 * or -1 when memory runs out. */
static int obj_join(ObjPart *parts, int n, MeshFile *mesh, ObjNames *names)
{
    uint32_t current = OBJ_DEFAULT;
    size_t t = 0;

    for (int k = 0; k < n; k++) {
        ObjNames *own = &parts[k].names;
        uint32_t *map = own->count ? malloc(own->count * sizeof *map) : NULL;
        size_t end = t + parts[k].count[3];
        if (own->count && !map)
            return -1;
        for (size_t i = 0; i < own->count; i++) {
            long g = obj_join_name(names, &own->mats[i]);
            if (g < 0) {
                free(map);
                return -1;
            }
            map[i] = (uint32_t)g;
        }
        for (; mesh->tri_material && t < end; t++) {
            uint32_t s = mesh->tri_material[t];
            mesh->tri_material[t] = s == OBJ_INHERIT ? current : s == OBJ_DEFAULT ? s : map[s];
        }
        t = end;
        if (own->current != OBJ_INHERIT)
            current = own->current == OBJ_DEFAULT ? OBJ_DEFAULT : map[own->current];
        free(map);
        for (size_t i = 0; i < own->lib_count; i++) {
            if (grow_reserve((void **)&names->libs, &names->lib_capacity, names->lib_count,
                             sizeof *names->libs) != 0)
                return -1;
            names->libs[names->lib_count++] = own->libs[i];
            own->libs[i].name = NULL;
        }
    }
    return 0;
}

/* Sizes *mesh's arrays for the parts' counts, within max_bytes; returns 0,
 * or -1 (mesh empty). */
static int obj_size(const ObjPart *parts, int n, size_t max_bytes, MeshFile *mesh)
{
    size_t total[OBJ_COUNTS] = {0, 0, 0, 0, 0, 0}, used;

    for (int k = 0; k < n; k++)
        for (int a = 0; a < OBJ_COUNTS; a++)
            total[a] += parts[k].count[a];
    /* What the serial reading takes. */
    used = obj_grown(total[0]) * sizeof *mesh->v + obj_grown(total[1]) * sizeof *mesh->vt +
           obj_grown(total[2]) * sizeof *mesh->vn + obj_grown(total[3]) * sizeof *mesh->tri +
           (total[5] ? obj_grown(total[3]) * sizeof *mesh->tri_material : 0) +
           obj_grown(total[4]) * sizeof *mesh->polygons;
    if (max_bytes && used > max_bytes)
        return -1;
    if ((total[0] && !(mesh->v = malloc(total[0] * sizeof *mesh->v))) ||
        (total[1] && !(mesh->vt = malloc(total[1] * sizeof *mesh->vt))) ||
        (total[2] && !(mesh->vn = malloc(total[2] * sizeof *mesh->vn))) ||
        (total[3] && !(mesh->tri = malloc(total[3] * sizeof *mesh->tri))) ||
        (total[3] && total[5] &&
         !(mesh->tri_material = malloc(total[3] * sizeof *mesh->tri_material))) ||
        (total[4] && !(mesh->polygons = malloc(total[4] * sizeof *mesh->polygons)))) {
        mesh_file_free(mesh);
        return -1;
    }
    mesh->v_count = total[0];
    mesh->vt_count = total[1];
    mesh->vn_count = total[2];
    mesh->tri_count = total[3];
    mesh->polygon_count = total[4];
    return 0;
}

int obj_parse_parallel(const char *name, const char *p, size_t len, size_t max_bytes,
                       int threads, MeshFile *mesh, ObjNames *names)
{
    ObjPart parts[OBJ_PARTS_MAX];
    const char *cut[OBJ_PARTS_MAX + 1];
    int n = threads < OBJ_PARTS_MAX ? threads : OBJ_PARTS_MAX, failed = 0;

    memset(parts, 0, sizeof parts);
    memset(names, 0, sizeof *names);
    lex_split(p, len, n, cut);
    for (int k = 0; k < n; k++) {
        parts[k].start = cut[k];
        parts[k].end = cut[k + 1];
    }
#ifdef _OPENMP
#pragma omp parallel for num_threads(n) schedule(static, 1)
#endif
    for (int k = 0; k < n; k++)
        obj_count(&parts[k]);
    mesh_file_init(mesh);
    mesh->format = "OBJ";
    if (obj_size(parts, n, max_bytes, mesh) != 0)
        return -1;
#ifdef _OPENMP
#pragma omp parallel for num_threads(n) schedule(static, 1)
#endif
    for (int k = 0; k < n; k++)
        obj_read_part(name, parts, k, mesh);
    for (int k = 0; k < n; k++)
        failed |= parts[k].failed;
    if (failed || obj_join(parts, n, mesh, names) != 0)
        failed = 1;
    for (int k = 0; k < n; k++)
        obj_names_free(&parts[k].names);
    if (failed) {
        obj_names_free(names);
        mesh_file_free(mesh);
        mesh->format = "OBJ";
        return -1;
    }
    return 0;
}
