/* bvh_collapse.c: the binary tree's nodes gathered into the wide nodes of
 * bvh.h (see bvh_collapse.h). */
#include "bvh_collapse.h"

#include <string.h>

/* The plan's costs, relative to one primitive's test: a ray's test of a
 * wide node (eight boxes, the hits ordered and stacked), and of one
 * primitive, each paid in proportion to the area of the box the ray
 * entered to make it. A node costs four tests: measured, the fewest nodes
 * that are not slower (docs/log.md). */
#define BVH_NODE_COST 4.0f
#define BVH_PRIM_COST 1.0f

/* An interior binary node's plan, in its count: bits 3 (i - 2) to
 * 3 (i - 2) + 2 hold k - 1, for i = 2 .. BVH_WIDTH children made of its
 * subtree, k of them from its left child's; then four flags. */
#define BVH_PLAN_LEAF (1u << 21)     /* as one child, it is a leaf */
#define BVH_PLAN_SMALL (1u << 22)    /* as a node, its children are leaves
                                        alone (it has fewer than BVH_WIDTH
                                        binary leaves) */
#define BVH_PLAN_ONE_LEAF (1u << 23) /* as leaves alone, it is one */
#define BVH_PLAN_COUNTED (1u << 24)  /* a node of BVH_TASK_MIN primitives or
                                        more: its size now holds the wide
                                        nodes it makes as a node */
#define BVH_PLAN_NODE (1u << 31)     /* an interior node's plan, not a
                                        leaf's count */

/* Returns 1 when planned binary node b is a leaf of the binary tree. */
static int bvh_planned_leaf(const BuildNode *b)
{
    return !(b->count & BVH_PLAN_NODE);
}

/* What planning a binary subtree finds: its box, its binary leaves, the
 * least cost of its subtree made into children of a wide node, and the
 * wide nodes those children hold. */
typedef struct {
    Box box;
    size_t leaves;            /* binary leaves */
    float cut[BVH_WIDTH];     /* cut[i - 1]: as exactly i children, leaves
                                 or nodes (INFINITY when leaves < i) */
    float alone;              /* as leaves alone, however many */
    size_t made[BVH_WIDTH];   /* made[i - 1]: the wide nodes in the
                                 subtrees of those i children, as planned */
    size_t node;              /* the wide nodes it makes as a node */
} BvhPlanCost;

/* Plans binary node id's subtree: stores each interior node's plan in its
 * count, and fills *out. In an OpenMP parallel region, left subtrees of
 * BVH_TASK_MIN primitives or more are planned by tasks: the plan is the
 * same. */
static void bvh_plan_subtree(BuildNode *nodes, uint32_t id, const BuildPrim *prims,
                             BvhPlanCost *out)
{
    BuildNode *b = &nodes[id];
    BvhPlanCost l, r;
    uint32_t word = BVH_PLAN_NODE;
    float area, leaf, node;
    int small; /* few enough primitives for a leaf */

    if (b->count > 0) {
        box_empty(&out->box);
        for (uint32_t i = b->index; i < b->index + b->count; i++)
            box_grow(&out->box, &prims[i].box);
        out->leaves = 1;
        out->cut[0] = out->alone = box_half_area(&out->box) * BVH_PRIM_COST * (float)b->count;
        for (int i = 1; i < BVH_WIDTH; i++)
            out->cut[i] = INFINITY;
        memset(out->made, 0, sizeof out->made);
        out->node = 1; /* its one leaf */
        return;
    }
    if (b->size >= BVH_TASK_MIN) {
#ifdef _OPENMP
#pragma omp task shared(l)
#endif
        bvh_plan_subtree(nodes, id + 1, prims, &l);
        bvh_plan_subtree(nodes, b->index, prims, &r);
#ifdef _OPENMP
#pragma omp taskwait
#endif
    } else {
        bvh_plan_subtree(nodes, id + 1, prims, &l);
        bvh_plan_subtree(nodes, b->index, prims, &r);
    }
    out->box = l.box;
    box_grow(&out->box, &r.box);
    out->leaves = l.leaves + r.leaves;
    area = box_half_area(&out->box);
    small = b->size <= BVH_LEAF_MAX;
    leaf = area * BVH_PRIM_COST * (float)b->size;
    out->alone = l.alone + r.alone;
    if (small && leaf <= out->alone) {
        out->alone = leaf;
        word |= BVH_PLAN_ONE_LEAF;
    }
    /* k children from the left's l.leaves, i - k from the right's: the
     * counts, not the costs' infinities, say which are possible. */
    for (int i = 2; i <= BVH_WIDTH; i++) {
        int best = 0;
        out->cut[i - 1] = INFINITY;
        for (int k = 1; k < i; k++) {
            float cost = l.cut[k - 1] + r.cut[i - k - 1];
            if ((size_t)k <= l.leaves && (size_t)(i - k) <= r.leaves &&
                (best == 0 || cost < out->cut[i - 1])) {
                out->cut[i - 1] = cost;
                best = k;
            }
        }
        out->made[i - 1] = 0;
        if (best > 0) {
            word |= (uint32_t)(best - 1) << 3 * (i - 2);
            out->made[i - 1] = l.made[best - 1] + r.made[i - best - 1];
        }
    }
    /* A node of fewer children than BVH_WIDTH holds leaves alone, so that
     * the nodes are as few as bvh_build_memory() counts. */
    if (out->leaves < BVH_WIDTH) {
        node = area * BVH_NODE_COST + l.alone + r.alone;
        word |= BVH_PLAN_SMALL;
        out->node = 1;
    } else {
        node = area * BVH_NODE_COST + out->cut[BVH_WIDTH - 1];
        out->node = 1 + out->made[BVH_WIDTH - 1];
    }
    out->cut[0] = node;
    out->made[0] = out->node;
    if (small && leaf <= node) {
        out->cut[0] = leaf;
        out->made[0] = 0;
        word |= BVH_PLAN_LEAF;
    }
    /* The collapse hands such a node to a task at the place its count
     * leaves (its size is read no more). */
    if (b->size >= BVH_TASK_MIN) {
        word |= BVH_PLAN_COUNTED;
        b->size = (uint32_t)out->node;
    }
    b->count = word;
}

size_t bvh_plan(BuildNode *nodes, const BuildPrim *prims)
{
    BvhPlanCost root;

    bvh_plan_subtree(nodes, 0, prims, &root);
    return root.node;
}

/* A wide node's child, as planned: binary node id's subtree, as a leaf or
 * as a node. */
typedef struct {
    uint32_t id;
    int leaf;
} BvhMember;

/* Appends to members[m..] the i children binary node id's subtree makes
 * (as planned: exactly i children); returns how many there are then. */
static int bvh_cut(const BuildNode *nodes, uint32_t id, int i, BvhMember *members, int m)
{
    int k;

    if (i == 1) {
        members[m].id = id;
        members[m].leaf = bvh_planned_leaf(&nodes[id]) || (nodes[id].count & BVH_PLAN_LEAF);
        return m + 1;
    }
    k = (int)(nodes[id].count >> 3 * (i - 2) & 7) + 1;
    m = bvh_cut(nodes, id + 1, k, members, m);
    return bvh_cut(nodes, nodes[id].index, i - k, members, m);
}

/* Appends to members[m..] the leaves alone binary node id's subtree makes
 * (as planned); returns how many there are then. */
static int bvh_cut_leaves(const BuildNode *nodes, uint32_t id, BvhMember *members, int m)
{
    if (bvh_planned_leaf(&nodes[id]) || (nodes[id].count & BVH_PLAN_ONE_LEAF)) {
        members[m].id = id;
        members[m].leaf = 1;
        return m + 1;
    }
    m = bvh_cut_leaves(nodes, id + 1, members, m);
    return bvh_cut_leaves(nodes, nodes[id].index, members, m);
}

/* Gathers in members the children of the wide node made from binary node
 * id, as planned (a binary leaf, the root of a small tree, is its only
 * child); returns how many. */
static int bvh_members(const BuildNode *nodes, uint32_t id, BvhMember members[BVH_WIDTH])
{
    if (bvh_planned_leaf(&nodes[id]))
        return bvh_cut_leaves(nodes, id, members, 0);
    if (nodes[id].count & BVH_PLAN_SMALL)
        return bvh_cut_leaves(nodes, nodes[id].index, members,
                              bvh_cut_leaves(nodes, id + 1, members, 0));
    return bvh_cut(nodes, id, BVH_WIDTH, members, 0);
}

/* Returns the first primitive of binary node id's subtree. */
static uint32_t bvh_first_prim(const BuildNode *nodes, uint32_t id)
{
    while (!bvh_planned_leaf(&nodes[id]))
        id++;
    return nodes[id].index;
}

/* Writes the node made from binary node id into bvh->nodes[self] and its
 * subtree's after it, in depth-first order (a child's subtree right after
 * the previous child's); stores the box of its children's boxes in *bounds
 * and the depth of its deepest node (it being at depth) in *deepest;
 * returns how many nodes it wrote. A leaf's box is that of its primitives'
 * padded boxes in the frame (bvh_prim_box() with pad), as the build had
 * them. In an OpenMP parallel region, children of BVH_TASK_MIN primitives
 * or more are made by tasks, at the places the plan's counts leave them:
 * the nodes are the same. */
size_t bvh_collapse(const BuildNode *nodes, uint32_t id, size_t self, int depth, real pad,
                    Bvh *bvh, Box *bounds, int *deepest)
{
    BvhMember members[BVH_WIDTH];
    int m = bvh_members(nodes, id, members), deep[BVH_WIDTH];
    BvhNode *w = &bvh->nodes[self];
    size_t next = self + 1;
    Box box[BVH_WIDTH];
    uint32_t first[BVH_WIDTH]; /* a leaf's first primitive */

    /* The leaves' primitives are read where the file put them (at random,
     * unless the spheres were moved into the leaves' order): memory is
     * asked for all of them before the first is read. */
    for (int k = 0; k < m; k++)
        if (members[k].leaf) {
            first[k] = bvh_first_prim(nodes, members[k].id);
            for (uint32_t i = first[k]; i < first[k] + nodes[members[k].id].size; i++)
                bvh_prim_prefetch(&bvh->shapes, bvh_prim_ref(bvh, i));
        }
    memset(w, 0, sizeof *w); /* padding too: nodes compare with memcmp() */
    for (int k = 0; k < BVH_WIDTH; k++) {
        box_empty(&box[k]); /* stays empty for an unused child */
        deep[k] = depth;
    }
    for (int k = 0; k < m; k++) {
        const BuildNode *c = &nodes[members[k].id];
        if (members[k].leaf) {
            for (uint32_t i = first[k]; i < first[k] + c->size; i++) {
                BuildPrim p;
                bvh_prim_box(bvh, bvh_prim_ref(bvh, i), pad, &p);
                box_grow(&box[k], &p.box);
            }
            w->link[k] = bvh_link(first[k], c->size);
        } else if (c->count & BVH_PLAN_COUNTED) {
            size_t at = next;
            next += c->size;
            w->link[k] = bvh_link((uint32_t)at, 0);
#ifdef _OPENMP
#pragma omp task firstprivate(k, at) shared(box, deep)
#endif
            bvh_collapse(nodes, members[k].id, at, depth + 1, pad, bvh, &box[k], &deep[k]);
        } else {
            w->link[k] = bvh_link((uint32_t)next, 0);
            next += bvh_collapse(nodes, members[k].id, next, depth + 1, pad, bvh, &box[k],
                                 &deep[k]);
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
