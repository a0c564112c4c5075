/* bvh_collapse.c: the binary tree's nodes gathered into the wide nodes of
 * bvh.h (see bvh_collapse.h). */
#include "bvh_collapse.h"

#include <string.h>

/* Gathers in members the binary nodes that become the children of the
 * node made from binary node id: from id alone, the interior member with
 * the most primitives gives way to its two children until there are
 * BVH_WIDTH members or only leaves. Returns how many. */
static int bvh_members(const BuildNode *nodes, uint32_t id, uint32_t members[BVH_WIDTH])
{
    int m = 1;

    members[0] = id;
    while (m < BVH_WIDTH) {
        int best = -1;
        for (int k = 0; k < m; k++) {
            const BuildNode *b = &nodes[members[k]];
            if (b->count == 0 && (best < 0 || b->size > nodes[members[best]].size))
                best = k;
        }
        if (best < 0)
            break;
        members[m++] = nodes[members[best]].index;
        members[best] = members[best] + 1;
    }
    return m;
}

/* Returns how many nodes collapsing binary node id's subtree makes. */
size_t bvh_collapsed_count(const BuildNode *nodes, uint32_t id)
{
    uint32_t members[BVH_WIDTH];
    int m = bvh_members(nodes, id, members);
    size_t count = 1;

    for (int k = 0; k < m; k++)
        if (nodes[members[k]].count == 0)
            count += bvh_collapsed_count(nodes, members[k]);
    return count;
}

/* Writes the node made from binary node id into bvh->nodes[self] and its
 * subtree's after it, in depth-first order (a child's subtree right after
 * the previous child's); stores the box of its children's boxes in *bounds
 * and the depth of its deepest node (it being at depth) in *deepest;
 * returns how many nodes it wrote. A leaf's box is that of its primitives'
 * padded boxes in the frame (bvh_prim_box() with pad), as the build had
 * them. In an OpenMP parallel region, children of BVH_TASK_MIN primitives
 * or more are made by tasks, their places counted first: the nodes are
 * the same. */
size_t bvh_collapse(const BuildNode *nodes, uint32_t id, size_t self, int depth, real pad,
                    Bvh *bvh, Box *bounds, int *deepest)
{
    uint32_t members[BVH_WIDTH];
    int m = bvh_members(nodes, id, members), deep[BVH_WIDTH];
    BvhNode *w = &bvh->nodes[self];
    size_t next = self + 1;
    Box box[BVH_WIDTH];

    memset(w, 0, sizeof *w); /* padding too: nodes compare with memcmp() */
    for (int k = 0; k < BVH_WIDTH; k++) {
        box_empty(&box[k]); /* stays empty for an unused child */
        deep[k] = depth;
    }
    for (int k = 0; k < m; k++) {
        const BuildNode *c = &nodes[members[k]];
        if (c->count > 0) {
            for (uint32_t i = c->index; i < c->index + c->count; i++) {
                BuildPrim p;
                bvh_prim_box(bvh, bvh->prims[i], pad, &p);
                box_grow(&box[k], &p.box);
            }
            w->link[k] = bvh_link(c->index, c->count);
        } else if (c->size >= BVH_TASK_MIN) {
            size_t at = next;
            next += bvh_collapsed_count(nodes, members[k]);
            w->link[k] = bvh_link((uint32_t)at, 0);
#ifdef _OPENMP
#pragma omp task firstprivate(k, at) shared(box, deep)
#endif
            bvh_collapse(nodes, members[k], at, depth + 1, pad, bvh, &box[k], &deep[k]);
        } else {
            w->link[k] = bvh_link((uint32_t)next, 0);
            next += bvh_collapse(nodes, members[k], next, depth + 1, pad, bvh, &box[k], &deep[k]);
        }
    }
#ifdef _OPENMP
#pragma omp taskwait
#endif
    box_empty(bounds);
    *deepest = depth;
    for (int k = 0; k < BVH_WIDTH; k++) {
        for (int a = 0; a < 3; a++) {
            w->box[a][k] = box[k].lo[a];
            w->box[3 + a][k] = box[k].hi[a];
        }
        box_grow(bounds, &box[k]);
        *deepest = deep[k] > *deepest ? deep[k] : *deepest;
    }
    return next - self;
}

