/*
 * stl.h: STL meshes (stereolithography: what 3D printing and CAD tools
 * write), binary or ASCII, read into a mesh file (mesh_file.h).
 *
 * A binary file is an 80-byte header, a 32-bit little-endian count n and
 * n facets of 50 bytes (a normal and three corners, 32-bit floats, and two
 * bytes of attributes): it is told by its size, 84 + 50 n bytes, never by
 * its first word (many binary files start their header with "solid"). Any
 * other file is read as ASCII: `solid [name]`, facets `facet normal nx ny
 * nz`, `outer loop`, three `vertex x y z`, `endloop`, `endfacet`, then
 * `endsolid [name]`, several solids in a row, words in any case. Each
 * facet is a flat triangle of three corners of its own, its front the
 * side its corners turn anticlockwise about; the stored normal is not
 * read (exporters often write zeros or wrong ones). A fault names the file
 * and, in ASCII, its line and column; in binary, its byte offset.
 */
#ifndef RAYTRACE_STL_H
#define RAYTRACE_STL_H

#include <stddef.h>

#include "base/error.h"
#include "scenefile/mesh_file.h"

/* Says whether the len bytes at data are a binary STL file by their size
 * (84 + 50 times the count in bytes 80 to 83). */
int stl_is_binary(const unsigned char *data, size_t len);

/* Says whether the len bytes at data begin as an ASCII STL file does: the
 * word solid, after blanks. */
int stl_is_ascii(const char *data, size_t len);

/* Reads the len bytes at data, named name, as an STL file into *mesh, its
 * arrays taking at most max_bytes (0: no limit); returns 0, or -1 with
 * *err naming the fault (mesh then empty). */
int stl_parse(const char *name, const char *data, size_t len, size_t max_bytes, MeshFile *mesh,
              Error *err);

#endif
