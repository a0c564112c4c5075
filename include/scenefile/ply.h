/*
 * ply.h: PLY meshes (the Stanford polygon format: what scanners and every
 * paper's bunny, dragon and Lucy come in), ASCII and binary (little- and
 * big-endian), read into a mesh file (mesh_file.h).
 *
 * The header names elements and their properties, each of a type (char,
 * uchar, short, ushort, int, uint, float, double, or the int8 ... float64
 * spellings) or a list (a count, then that many items). Read: the
 * `vertex` element's x y z (any type), and when it has them nx ny nz
 * (smooth shading), u v (or s t, texture_u texture_v, texture_s
 * texture_t) and red green blue (integers scaled from their type's range,
 * floats from 0 to 1; the colours blend across faces); the `face`
 * element's `vertex_indices` or `vertex_index` list, of any count and
 * index types, faces of more than three corners cut into the triangles
 * that cover them. Every other element and property is passed over by
 * its declared type. A fault names the file and its line and column
 * (header and ASCII data) or byte offset (binary data): a header without
 * end_header, an unknown format or type, a count larger than the file
 * holds, an index out of range, a file cut short.
 */
#ifndef RAYTRACE_PLY_H
#define RAYTRACE_PLY_H

#include <stddef.h>

#include "base/error.h"
#include "scenefile/mesh_file.h"

/* Says whether the len bytes at data begin as a PLY file does ("ply" on
 * its own line). */
int ply_is(const char *data, size_t len);

/* Reads the len bytes at data, named name, as a PLY file into *mesh, its
 * arrays taking at most max_bytes (0: no limit); returns 0, or -1 with
 * *err naming the fault (mesh then empty). */
int ply_parse(const char *name, const char *data, size_t len, size_t max_bytes, MeshFile *mesh,
              Error *err);

#endif
