/*
 * mesh.h: a Wavefront OBJ mesh (obj.h) turned into the scene's triangles.
 */
#ifndef RAYTRACE_MESH_H
#define RAYTRACE_MESH_H

#include "scene/scene.h"
#include "scenefile/obj.h"

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

#endif
