/*
 * mesh_file.h: what a mesh file holds, whatever its format (OBJ, PLY or
 * STL: obj.h, ply.h, stl.h read them): positions with, when the file has
 * them, texture coordinates, normals and vertex colours; triangles of
 * corners that index them; the materials its faces name, as an MTL file
 * describes them; and what the reader assumed, as warnings. mesh.h turns
 * it into the scene's triangles.
 *
 * Faces of more than three corners are cut into triangles by
 * mesh_file_cut() (geometry/polygon.h): the readers first write each as a
 * fan from its first corner, and note where.
 */
#ifndef RAYTRACE_MESH_FILE_H
#define RAYTRACE_MESH_FILE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "math/vec3.h"

/* One corner of a triangle: indices from 0 of its position, texture
 * coordinates and normal; -1 when absent. */
typedef struct {
    long v, vt, vn;
} MeshCorner;

/* A material the faces name (OBJ's usemtl), in the terms of the MTL file
 * that describes it (docs/scene-format.md says how each maps onto the
 * renderer's). */
typedef struct {
    char *name;              /* as the faces name it (owned) */
    int defined;             /* 1: an MTL file describes it; 0: the default
                                material stands in for it */
    double ka[3], kd[3], ks[3]; /* Ka, Kd, Ks */
    double ns, ni, d;        /* Ns, Ni, d (1 - Tr) */
    int illum;               /* 0 to 10; -1 when not given */
    char *texture;           /* map_Kd: the path to open (owned), or NULL */
    Error *texture_at;       /* with it, where map_Kd is written (owned; an
                                empty message), for a warning when the
                                texture cannot be read */
    double uv_scale[2];      /* map_Kd's -s u v: texture coordinates scaled, */
    double uv_offset[2];     /* then moved by its -o u v */
    const char *used_at;     /* the reader's: the first line that names it */
    size_t used_len;         /* (in the file's text, while it is read), */
    int used_line, used_column; /* for a warning when no MTL describes it */
} MeshMaterial;

/* Sets *mat to the default material: MTL's defaults (Ka 0.2, Kd 0.8, no
 * highlight, opaque), named name (owned; may be NULL), not defined. */
void mesh_material_default(MeshMaterial *mat, char *name);

/* The warnings a mesh keeps; more are counted. */
enum { MESH_FILE_WARNINGS_MAX = 32 };

typedef struct MeshFile {
    Vec3 *v;                 /* positions */
    size_t v_count;
    double (*vt)[2];         /* texture coordinates */
    size_t vt_count;
    Vec3 *vn;                /* normals, as written (not normalised) */
    size_t vn_count;
    float (*vc)[3];          /* each position's colour, 0 to 255 a channel,
                                or NULL */
    MeshCorner (*tri)[3];    /* triangles, faces cut by mesh_file_cut() */
    size_t tri_count;
    uint32_t *tri_material;  /* each triangle's index in materials, or NULL:
                                all of the default material */
    MeshMaterial *materials; /* the materials the faces name */
    size_t material_count;
    size_t (*polygons)[2];   /* each face of more than three corners: its
                                first triangle and its corners */
    size_t polygon_count;
    size_t polygons_cut;     /* faces that were not convex, cut by ear
                                clipping (mesh_file_cut()) */
    size_t polygons_irregular; /* faces that are not simple, cut as well as
                                the rule allows */
    Error *warnings;         /* what the reader assumed: a missing MTL file,
                                material or texture, at most
                                MESH_FILE_WARNINGS_MAX */
    size_t warning_count;
    size_t warnings_dropped; /* past that, counted */
    char **libraries;        /* the material libraries read (their paths,
                                owned) */
    size_t library_count;
    const char *format;      /* "OBJ", "PLY (binary, little-endian)", ...:
                                what the file was read as */
    uint64_t hash;           /* the fingerprint of the file's bytes (hash.h),
                                and of the files it names */
} MeshFile;

/* Makes *m an empty mesh that owns nothing. */
void mesh_file_init(MeshFile *m);

/* Releases what *m owns and leaves it empty. */
void mesh_file_free(MeshFile *m);

/* Returns the bytes the arrays of *m hold (at least). */
size_t mesh_file_memory(const MeshFile *m);

/* Keeps warning *w, or counts it past MESH_FILE_WARNINGS_MAX; returns 0,
 * or -1 when memory runs out. */
int mesh_file_warn(MeshFile *m, const Error *w);

/* Cuts each face m->polygons notes, written as a fan from its first
 * corner, into the triangles that cover it (polygon.h), on every thread
 * for a large mesh, counting those cut by ear clipping and those not
 * simple; returns 0, or -1 when memory runs out. */
int mesh_file_cut(MeshFile *m);

#endif
