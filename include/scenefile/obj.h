/*
 * obj.h: Wavefront OBJ meshes: vertices and faces, read into triangles.
 *
 * Read: `v x y z [w]` (extra numbers, such as vertex colours, are
 * allowed and ignored), `vt u [v [w]]`, `vn x y z`, and `f` with any
 * number of corners of 3 or more, each `v`, `v/vt`, `v//vn` or `v/vt/vn`,
 * indices from 1 or negative (from the end of the list so far); polygons
 * are cut into triangles as a fan from their first corner. `o`, `g`, `s`,
 * `usemtl`, `mtllib`, and the point and line records `p` and `l` (which
 * have no area) are accepted and ignored; `#` starts a comment. Lines may
 * end in CRLF, the last one without a newline, fields be separated by runs
 * of spaces or tabs, and the file start with a UTF-8 byte order mark.
 * Anything else is an error that names the file, line and column.
 */
#ifndef RAYTRACE_OBJ_H
#define RAYTRACE_OBJ_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "math/vec3.h"

/* One corner of a triangle: indices from 0, -1 when absent. */
typedef struct {
    long v, vt, vn;
} ObjCorner;

typedef struct ObjMesh {
    Vec3 *v;          /* positions */
    size_t v_count;
    double (*vt)[2];  /* texture coordinates */
    size_t vt_count;
    Vec3 *vn;         /* normals, as written (not normalised) */
    size_t vn_count;
    ObjCorner (*tri)[3]; /* triangles, after fan triangulation */
    size_t tri_count;
    uint64_t hash;    /* the fingerprint of the file's bytes (hash.h) */
} ObjMesh;

/* Reads the OBJ file at path into *mesh, its arrays taking at most
 * max_bytes (0: no limit); returns 0, or -1 with *err naming the fault, its
 * line and column. Free with obj_free(). */
int obj_load(const char *path, size_t max_bytes, ObjMesh *mesh, Error *err);

/* obj_load() on the len bytes at text, errors naming name. */
int obj_parse(const char *name, const char *text, size_t len, size_t max_bytes, ObjMesh *mesh,
              Error *err);

/* Returns the bytes the arrays of *mesh hold (at least). */
size_t obj_memory(const ObjMesh *mesh);

/* Releases what *mesh owns. */
void obj_free(ObjMesh *mesh);

#endif
