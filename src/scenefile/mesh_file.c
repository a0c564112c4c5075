/* mesh_file.c: what a mesh file holds (see mesh_file.h). */
#include "scenefile/mesh_file.h"

#include <stdlib.h>
#include <string.h>

#include "base/grow.h"
#include "geometry/polygon.h"

/* Faces of fewer corners in all are cut on one thread. */
enum { MESH_FILE_PARALLEL_MIN = 1 << 16 };

void mesh_file_init(MeshFile *m)
{
    memset(m, 0, sizeof *m);
}

void mesh_material_default(MeshMaterial *mat, char *name)
{
    memset(mat, 0, sizeof *mat);
    mat->name = name;
    for (int c = 0; c < 3; c++) {
        mat->ka[c] = 0.2;
        mat->kd[c] = 0.8;
    }
    mat->ni = 1;
    mat->d = 1;
    mat->illum = -1;
    mat->uv_scale[0] = mat->uv_scale[1] = 1;
}

void mesh_file_free(MeshFile *m)
{
    free(m->v);
    free(m->vt);
    free(m->vn);
    free(m->vc);
    free(m->tri);
    free(m->tri_material);
    for (size_t i = 0; i < m->material_count; i++) {
        free(m->materials[i].name);
        free(m->materials[i].texture);
        free(m->materials[i].texture_at);
    }
    free(m->materials);
    free(m->polygons);
    free(m->warnings);
    for (size_t i = 0; i < m->library_count; i++)
        free(m->libraries[i]);
    free(m->libraries);
    mesh_file_init(m);
}

size_t mesh_file_memory(const MeshFile *m)
{
    return m->v_count * sizeof *m->v + m->vt_count * sizeof *m->vt +
           m->vn_count * sizeof *m->vn + (m->vc ? m->v_count * sizeof *m->vc : 0) +
           m->tri_count * (sizeof *m->tri + (m->tri_material ? sizeof *m->tri_material : 0)) +
           m->material_count * sizeof *m->materials + m->polygon_count * sizeof *m->polygons;
}

int mesh_file_warn(MeshFile *m, const Error *w)
{
    size_t cap = m->warning_count;
    void *items = m->warnings;

    if (m->warning_count >= MESH_FILE_WARNINGS_MAX) {
        m->warnings_dropped++;
        return 0;
    }
    /* Grown one at a time: there are few. */
    items = realloc(items, (cap + 1) * sizeof *m->warnings);
    if (!items)
        return -1;
    m->warnings = items;
    m->warnings[m->warning_count++] = *w;
    return 0;
}

/* Cuts face k of m (its fan, as read) into the triangles that cover it,
 * with the room of corners and work for its corners; returns how. */
static PolygonCut mesh_file_cut_one(MeshFile *m, size_t k, MeshCorner *corners, Vec3 *p,
                                    unsigned (*tri)[3], void *work)
{
    size_t first = m->polygons[k][0], n = m->polygons[k][1];
    PolygonCut cut;

    corners[0] = m->tri[first][0];
    corners[1] = m->tri[first][1];
    for (size_t t = 0; t + 2 < n; t++)
        corners[t + 2] = m->tri[first + t][2];
    for (size_t i = 0; i < n; i++)
        p[i] = m->v[corners[i].v];
    cut = polygon_cut(p, n, tri, work);
    if (cut != POLYGON_FAN)
        for (size_t t = 0; t + 2 < n; t++)
            for (int c = 0; c < 3; c++)
                m->tri[first + t][c] = corners[tri[t][c]];
    return cut;
}

int mesh_file_cut(MeshFile *m)
{
    size_t most = 3, corners_all = 0, cut = 0, irregular = 0;
    int failed = 0;

    for (size_t k = 0; k < m->polygon_count; k++) {
        size_t n = m->polygons[k][1];
        corners_all += n;
        if (n <= POLYGON_CLIP_MAX && n > most)
            most = n;
    }
    if (m->polygon_count == 0)
        return 0;
    (void)corners_all; /* without OpenMP: one thread whatever the size */
#ifdef _OPENMP
#pragma omp parallel if (corners_all >= MESH_FILE_PARALLEL_MIN) reduction(+ : cut, irregular) \
    reduction(| : failed)
#endif
    {
        size_t room = most * (sizeof(MeshCorner) + sizeof(Vec3) + 3 * sizeof(unsigned)) +
                      polygon_work_size(most);
        char *scratch = malloc(room);

        if (!scratch)
            failed = 1;
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 1024)
#endif
        for (size_t k = 0; k < m->polygon_count; k++) {
            /* The work room first: polygon.c keeps doubles in it. */
            void *work = scratch;
            Vec3 *p = (Vec3 *)(scratch + polygon_work_size(most));
            MeshCorner *corners = (MeshCorner *)(p + most);
            unsigned(*tri)[3] = (unsigned(*)[3])(corners + most);
            PolygonCut c;
            if (!scratch || m->polygons[k][1] > POLYGON_CLIP_MAX) {
                irregular += m->polygons[k][1] > POLYGON_CLIP_MAX;
                continue;
            }
            c = mesh_file_cut_one(m, k, corners, p, tri, work);
            cut += c == POLYGON_EARS;
            irregular += c == POLYGON_IRREGULAR;
        }
        free(scratch);
    }
    m->polygons_cut = cut;
    m->polygons_irregular = irregular;
    return failed ? -1 : 0;
}
