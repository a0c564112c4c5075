/*
 * mtl.h: Wavefront MTL material libraries, which OBJ files name (obj.h),
 * read into the materials their faces use (mesh_file.h).
 *
 * Read: `newmtl NAME` (the rest of the line), then its `Ka`, `Kd`, `Ks`
 * (r g b, or one number for all three), `Ns`, `Ni`, `d` (or `Tr`, 1 - d),
 * `illum` (0 to 10) and `map_Kd [options] PATH` (PATH the rest of the
 * line: spaces kept; its -s and -o scale and offset the texture
 * coordinates, its other options are passed over). The other statements
 * of the format and its extensions (Ke, Tf, bump maps, PBR's Pr and Pm,
 * ...) are passed over; `map_d` (a cut-out mask) too, with a warning.
 * Paths are read as their exporter meant, on any system: relative to the
 * file that names them, '\' as a folder separator, and a path that is not
 * there (a drive letter, another machine's folder) looked for by its last
 * part beside that file. A library that cannot be read, a line that makes
 * no sense, a material no library describes: each is a warning naming its
 * file and line, and the picture still comes.
 */
#ifndef RAYTRACE_MTL_H
#define RAYTRACE_MTL_H

#include <stddef.h>

#include "base/error.h"
#include "scenefile/mesh_file.h"

/* A material library an OBJ file names (mtllib): the rest of its line,
 * and where it is (an error record with an empty message), for a warning
 * when it cannot be read. */
typedef struct {
    char *name;
    Error at;
} MtlLibrary;

/* Reads the n libraries the OBJ file at obj_path names (each relative to
 * its folder) into the materials of mesh they describe, then warns of each
 * material none describes (mesh_file_warn()). Returns 0, or -1 with *err
 * when memory runs out. */
int mtl_read_libraries(const char *obj_path, const MtlLibrary *libs, size_t n, MeshFile *mesh,
                       Error *err);

/* Reads the MTL text (len bytes; named name, the path its textures'
 * paths are relative to) into the materials of mesh it describes, a
 * material described before kept as it was. Returns 0, or -1 when memory
 * runs out. */
int mtl_parse(const char *name, const char *text, size_t len, MeshFile *mesh);

/* Returns, newly allocated, the path of the file `written` (len bytes, as
 * a file at `beside` names it) as its writer meant: '\' a separator,
 * relative to beside's folder; when that is not there but a file of its
 * last part is, beside beside, that one. NULL when memory runs out. */
char *mtl_find(const char *beside, const char *written, size_t len);

#endif
