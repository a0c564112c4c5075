/*
 * mesh.h: a Wavefront OBJ mesh (obj.h) turned into the scene's triangles.
 */
#ifndef RAYTRACE_MESH_H
#define RAYTRACE_MESH_H

#include "scene/scene.h"
#include "scenefile/lex.h"
#include "scenefile/obj.h"
#include "scenefile/source.h"

/* mesh_load()'s status when the fault is already recorded in the lexer. */
#define MESH_FAULT (-3)

/* Appends the triangles of mesh m to scene with material mat, smooth where
 * all three corners have a non-zero normal, with the texture coordinates
 * of their corners when all three have some (every triangle of a mesh with
 * normals or texture coordinates has a shading entry; of one without,
 * none); triangles without area are left out. Large meshes are made on
 * every thread (threads.h), into the same scene. Returns how many it
 * added, -1 when memory runs out (those added stay), or SCENE_OVER_LIMIT
 * (none added) when the triangles and the mesh together would pass the
 * scene's memory limit. */
long mesh_add(Scene *scene, const ObjMesh *m, const Material *mat);

/* Reads the OBJ file that token t of rec names (relative to the scene
 * file: lex_path()), adds its triangles to scene with material mat
 * (mesh_add()) and keeps its line in *source (the path as written and as
 * opened, for --save and for the files the scene reads). Returns the
 * triangles added (> 0); 0 when none has an area (nothing kept);
 * MESH_FAULT with the fault recorded in L when the file cannot be read;
 * -1 when memory runs out or SCENE_OVER_LIMIT, for the caller to report. */
long mesh_load(Lexer *L, const Record *rec, const Token *t, const Material *mat, Scene *scene,
               SceneSource *source);

#endif
