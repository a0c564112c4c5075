/*
 * obj.h: Wavefront OBJ meshes, with the materials of their MTL files.
 *
 * Read: `v x y z [w]` (extra numbers, such as vertex colours, are
 * allowed and ignored), `vt u [v [w]]`, `vn x y z`, and `f` with any
 * number of corners of 3 or more, each `v`, `v/vt`, `v//vn` or `v/vt/vn`,
 * indices from 1 or negative (from the end of the list so far); faces of
 * more than three corners are written as fans and noted, for
 * mesh_file_cut() to cut into the triangles that cover them. `usemtl NAME` gives the faces after it a material (NAME
 * the rest of the line), which the MTL files that `mtllib NAME...` lines
 * name describe (mtl.h; paths relative to the OBJ file's folder, several
 * on a line unless the whole rest of the line names a file). `o`, `g`,
 * `s`, and the point and line records `p` and `l` (which have no area)
 * are accepted and ignored; `#` starts a comment. Lines may end in CRLF,
 * the last one without a newline, fields be separated by runs of spaces
 * or tabs, and the file start with a UTF-8 byte order mark. Anything else
 * is an error that names the file, line and column. A material library,
 * material or texture that cannot be had is a warning (mesh_file.h): its
 * faces get the default material.
 */
#ifndef RAYTRACE_OBJ_H
#define RAYTRACE_OBJ_H

#include <stddef.h>

#include "base/error.h"
#include "scenefile/mesh_file.h"

/* Reads the OBJ file at path, whose len bytes are at data, and the MTL
 * files it names, into *mesh, its arrays taking at most max_bytes (0: no
 * limit); returns 0, or -1 with *err naming the fault, its line and
 * column (mesh then empty). Free with mesh_file_free(). */
int obj_load(const char *path, const char *data, size_t len, size_t max_bytes, MeshFile *mesh,
             Error *err);

/* Reads the len bytes at text as obj_load() reads a file, errors naming
 * name, but no material library: the materials its faces name are left
 * undefined. */
int obj_parse(const char *name, const char *text, size_t len, size_t max_bytes, MeshFile *mesh,
              Error *err);

#endif
