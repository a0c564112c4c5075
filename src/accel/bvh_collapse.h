/*
 * bvh_collapse.h: the binary tree gathered into the wide nodes of bvh.h
 * (bvh_collapse.c), private to the build.
 */
#ifndef RAYTRACE_BVH_COLLAPSE_H
#define RAYTRACE_BVH_COLLAPSE_H

#include <stddef.h>

#include "bvh_box.h"

/* Plans how the binary tree nodes, over prims, is gathered into wide nodes:
 * which subtrees become a wide node's children, leaves or nodes, for the
 * least cost by the surface area heuristic; the plan replaces each
 * interior node's count (0). Each node has BVH_WIDTH children, or fewer
 * and all leaves. Returns how many wide nodes the plan makes; a node of
 * BVH_TASK_MIN primitives or more keeps its own count in its size. */
size_t bvh_plan(BuildNode *nodes, const BuildPrim *prims);

/* Writes the wide node made from planned binary node id, and its
 * subtree's, into bvh->nodes from self on; stores their bounds in *bounds and the depth of
 * the deepest in *deepest; returns how many it wrote. */
size_t bvh_collapse(const BuildNode *nodes, uint32_t id, size_t self, int depth, real pad,
                    Bvh *bvh, Box *bounds, int *deepest);

#endif
