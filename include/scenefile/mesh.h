/*
 * mesh.h: a mesh file (OBJ with its MTL materials, PLY or STL) turned into
 * the scene's triangles.
 *
 * The format is told by the file's content: a PLY file's first line is
 * `ply`; a binary STL file has 84 + 50 n bytes (n the count it holds at
 * byte 80); an ASCII STL file starts with the word `solid`; any other
 * text is OBJ. Only when the content says nothing of its own (a file cut
 * short, junk) does the name's extension (.ply, .stl, .obj) choose the
 * reader that says what is wrong.
 *
 * A mesh line that gives a material draws every triangle in it. One that
 * does not draws them in the file's own: an OBJ file's MTL materials and
 * textures, a PLY file's vertex colours, otherwise a default grey. In a
 * course scene they follow the course's rule (the colour, mirror weight
 * and glass of each MTL material); in a keyword scene, Blinn-Phong with
 * its highlights (docs/scene-format.md says how each MTL field maps).
 */
#ifndef RAYTRACE_MESH_H
#define RAYTRACE_MESH_H

#include "scene/scene.h"
#include "scenefile/lex.h"
#include "scenefile/mesh_file.h"
#include "scenefile/source.h"

/* mesh_load()'s status when the fault is already recorded in the lexer. */
#define MESH_FAULT (-3)

/* Reads the mesh file at path, whatever its format, into *mesh, its arrays
 * taking at most max_bytes (0: no limit); returns 0, or -1 with *err
 * naming the fault (mesh then empty). Free with mesh_file_free(). */
int mesh_read(const char *path, size_t max_bytes, MeshFile *mesh, Error *err);

/* Appends the triangles of mesh m to scene, in material mat, or in the
 * file's own materials when mat is NULL (their textures read, a texture
 * that cannot be a warning in the scene); smooth where all three corners
 * have a non-zero normal, with the texture coordinates of their corners
 * when all three have some; triangles without area are left out. Large
 * meshes are made on every thread (threads.h). What the file held goes to
 * *info (its materials and textures used, its faces). Returns how many
 * triangles it added, -1 when memory runs out (those added stay), or
 * SCENE_OVER_LIMIT (none added) when the triangles and the mesh together
 * would pass the scene's memory limit. */
long mesh_add(Scene *scene, const MeshFile *m, const Material *mat, SceneMesh *info);

/* Reads the mesh file that token t of rec names (relative to the scene
 * file: lex_path()), adds its triangles to scene in material mat (NULL:
 * the file's; mesh_add()), its warnings to the scene's, and keeps its line
 * in *source (the path as written and as opened, for --save and for the
 * files the scene reads). Returns the triangles added (> 0); 0 when none
 * has an area (nothing kept); MESH_FAULT with the fault recorded in L when
 * the file cannot be read; -1 when memory runs out or SCENE_OVER_LIMIT,
 * for the caller to report. */
long mesh_load(Lexer *L, const Record *rec, const Token *t, const Material *mat, Scene *scene,
               SceneSource *source);

#endif
