/*
 * source.h: what a scene file said that the Scene does not keep in its own
 * terms, for writing the scene back (save.h) and knowing the files it read:
 * its mesh lines and its camera line as written.
 */
#ifndef RAYTRACE_SOURCE_H
#define RAYTRACE_SOURCE_H

#include <stddef.h>

#include "math/vec3.h"

/* A mesh line: its path as written, the path it was read from, the
 * scene's triangles it gave, and what the file held. */
typedef struct {
    char *path;          /* the mesh file's path as written in the scene file */
    char *opened;        /* the path it was read from */
    size_t first;        /* its first triangle in the scene's triangles */
    size_t count;        /* how many triangles it gave */
    int own_materials;   /* 1: drawn in the file's materials (the line named
                            none) */
    const char *format;  /* what it was read as: "OBJ", "PLY (ASCII)", ... */
    size_t materials;    /* the materials and textures its triangles use */
    size_t textures;
    size_t polygons;     /* its faces of more than three corners, those cut
                            by ear clipping, those not simple */
    size_t polygons_cut;
    size_t polygons_irregular;
    char **libraries;    /* the material libraries it read (paths, owned) */
    size_t library_count;
} SceneMesh;

typedef struct {
    SceneMesh *meshes;    /* the mesh lines (course and keyword formats), in
                             file order */
    size_t mesh_count;
    size_t mesh_capacity;
    int camera_line;      /* the file gave a camera line (the keyword format
                             always does, MPL may not) */
    Vec3 look_from;       /* keyword, MPL: the camera line as written (MPL:
                             fov in degrees, vertical; without a line, its
                             default camera's) */
    Vec3 look_at;
    double fov;
} SceneSource;

/* Makes *src empty, owning nothing. */
void source_init(SceneSource *src);

/* Releases what *src owns and leaves it empty. */
void source_free(SceneSource *src);

/* Appends *mesh, taking ownership of its strings (freed on failure);
 * returns 0, or -1 when memory runs out. */
int source_add_mesh(SceneSource *src, SceneMesh *mesh);

#endif
