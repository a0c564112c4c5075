/* bvh.c: building and querying the bounding volume hierarchy (see bvh.h). */
#include "accel/bvh.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>


enum {
    BVH_BINS = 16,        /* centroid bins per split */
    BVH_ALL_AXES = 4096,  /* at most this many primitives: SAH on every axis */
    BVH_TASK_MIN = 16384, /* fewer primitives: built by the thread at hand */
    BVH_FRAME_SAMPLE = 4095 /* centroids the frame's median is taken of */
};

/* A box, as lo and hi corners. */
typedef struct {
    real lo[3], hi[3];
} Box;

/* The box helpers' loops are unrolled: they run per primitive and bin. */
static void box_empty(Box *b)
{
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        b->lo[a] = INFINITY;
        b->hi[a] = -INFINITY;
    }
}

/* Boxes never hold NaN (they come from finite coordinates), so plain
 * comparisons do what fmin() and fmax() would, without a call. */
static inline void box_grow(Box *b, const Box *c)
{
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        b->lo[a] = c->lo[a] < b->lo[a] ? c->lo[a] : b->lo[a];
        b->hi[a] = c->hi[a] > b->hi[a] ? c->hi[a] : b->hi[a];
    }
}

static inline void box_grow_point(Box *b, const real p[3])
{
#pragma GCC unroll 3
    for (int a = 0; a < 3; a++) {
        b->lo[a] = p[a] < b->lo[a] ? p[a] : b->lo[a];
        b->hi[a] = p[a] > b->hi[a] ? p[a] : b->hi[a];
    }
}

/* Half the surface area of b (0 for an empty box). */
static real box_half_area(const Box *b)
{
    real dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
    return dx < 0 ? 0 : dx * dy + dy * dz + dz * dx;
}

/* What the build needs of each primitive. */
typedef struct {
    Box box;         /* padded bounds */
    uint32_t ref;    /* primitive reference */
} BuildPrim;

/* A node of the binary tree the build makes first. Its box is not kept:
 * the wide nodes' boxes are gathered again from the leaves up. */
typedef struct {
    uint32_t index;  /* interior: the right child (the left is the next
                        node); leaf: the first of its primitives */
    uint32_t count;  /* primitives in a leaf; 0 for an interior node */
    uint32_t size;   /* primitives in its subtree */
} BuildNode;

/* Returns coordinate axis of the centre of p's box, its centroid. */
static real bvh_centroid(const BuildPrim *p, int axis)
{
    return 0.5 * p->box.lo[axis] + 0.5 * p->box.hi[axis];
}

/* The padding of every box, in units of the scene's largest coordinate
 * times REAL_EPSILON. The primitive tests round at a few REAL_EPSILON of the
 * distances involved, all below twice that coordinate. Double takes 2^16
 * (boxes 1.5e-11 of the scene wider: a 10^4-fold margin that costs nothing
 * measurable); float takes 2^6 (7.6e-6 of the scene), as 2^16 would widen
 * every box by 1/128 of the scene. Spheres' radii grow by 1/16 of that. */
#ifdef RAYTRACE_REAL_FLOAT
#define BVH_PAD_ULPS 0x1p6
#else
#define BVH_PAD_ULPS 0x1p16
#endif

/* Returns the larger of m and vec3_max_abs(p), for finite coordinates,
 * by comparisons (fmax() is a library call, once per vertex here). */
static inline real bvh_farther(real m, Vec3 p)
{
    real x = fabs(p.x), y = fabs(p.y), z = fabs(p.z);

    m = x > m ? x : m;
    m = y > m ? y : m;
    return z > m ? z : m;
}

/* Returns the padding of every box for shapes and the reach bvh_build()
 * is given. */
static real bvh_padding(const BvhShapes *shapes, real reach, int threads)
{
    real m = reach;
    size_t spheres = shapes->sphere_count, triangles = shapes->triangle_count;

    (void)threads;
    /* The largest of finite values, whatever the order: the same on any
     * number of threads. */
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) reduction(max : m) if (spheres >= BVH_TASK_MIN)
#endif
    for (size_t i = 0; i < spheres; i++) {
        const Sphere *sp = &shapes->spheres[i];
        real r = bvh_farther(0, sp->centre) + sp->radius;
        m = r > m ? r : m;
    }
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) reduction(max : m) if (triangles >= BVH_TASK_MIN)
#endif
    for (size_t i = 0; i < triangles; i++)
        for (int k = 0; k < 3; k++)
            m = bvh_farther(m, shapes->triangles[i].v[k]);
    return m * (REAL_EPSILON * BVH_PAD_ULPS);
}

static void bvh_prim_box(const BvhShapes *shapes, uint32_t ref, real pad, BuildPrim *p)
{
    p->ref = ref;
    if (ref & BVH_TRIANGLE) {
        const Triangle *t = &shapes->triangles[ref & ~BVH_TRIANGLE];
        box_empty(&p->box);
        for (int k = 0; k < 3; k++) {
            real v[3] = {t->v[k].x, t->v[k].y, t->v[k].z};
            box_grow_point(&p->box, v);
        }
        for (int a = 0; a < 3; a++) {
            p->box.lo[a] -= pad;
            p->box.hi[a] += pad;
        }
    } else {
        const Sphere *s = &shapes->spheres[ref];
        real c[3] = {s->centre.x, s->centre.y, s->centre.z};
        real r = s->radius * (1 + REAL_EPSILON * (BVH_PAD_ULPS / 16)) + pad;
        for (int a = 0; a < 3; a++) {
            p->box.lo[a] = c[a] - r;
            p->box.hi[a] = c[a] + r;
        }
    }
}

/* Orders prims[lo..hi) so that the k-th smallest centroid on axis is at k,
 * smaller ones before it and larger after (quickselect; each pass splits the
 * range three ways about the middle one's centroid, so the part equal to it
 * is never empty and every pass shrinks the range). */
static void bvh_select(BuildPrim *prims, size_t lo, size_t hi, size_t k, int axis)
{
    while (hi - lo > 1) {
        real pivot = bvh_centroid(&prims[lo + (hi - lo) / 2], axis);
        size_t less = lo, i = lo, more = hi; /* [lo, less) < pivot, [more, hi) > */
        while (i < more) {
            real c = bvh_centroid(&prims[i], axis);
            BuildPrim tmp = prims[i];
            if (c < pivot) {
                prims[i++] = prims[less];
                prims[less++] = tmp;
            } else if (c > pivot) {
                prims[i] = prims[--more];
                prims[more] = tmp;
            } else {
                i++;
            }
        }
        if (k < less)
            hi = less;
        else if (k >= more)
            lo = more;
        else
            return;
    }
}

/* A piece of work: build the subtree of prims[start..end) at depth, its
 * root at node. A subtree of m primitives takes nodes node .. node + 2m - 2
 * (fewer when leaves hold several): its left child is node + 1, its right
 * node + 2 m_left, so the tree is the same whichever thread builds what. */
typedef struct {
    size_t start, end;
    int depth;
    size_t node;
} BuildTask;

/* Returns the bin of p's centroid on axis, for bins of 1 / scale from lo. */
static int bvh_bin(const BuildPrim *p, int axis, real lo, real scale)
{
    int b = (int)((bvh_centroid(p, axis) - lo) * scale);

    return b < 0 ? 0 : b >= BVH_BINS ? BVH_BINS - 1 : b;
}

/* The surface area heuristic's best split of prims[start..end) into the
 * centroid bins of one axis: the cost (traversal 1, intersection 1 a
 * primitive, areas relative to the box of them all), and the first bin of
 * the right part (-1 when no split leaves both parts non-empty). */
static real bvh_sah_axis(const BuildPrim *prims, size_t start, size_t end, int axis, real lo,
                         real scale, int *split)
{
    size_t count[BVH_BINS] = {0}, left_n[BVH_BINS], n = end - start;
    Box bin[BVH_BINS], acc;
    real left_area[BVH_BINS], best = INFINITY, per_area;

    *split = -1;
    for (int b = 0; b < BVH_BINS; b++)
        box_empty(&bin[b]);
    for (size_t i = start; i < end; i++) {
        int b = bvh_bin(&prims[i], axis, lo, scale);
        count[b]++;
        box_grow(&bin[b], &prims[i].box);
    }
    /* An empty bin changes neither box nor count: it takes its left
     * neighbour's area, and a split at it costs exactly what the split at
     * the next full bin costs, which the sweep below meets first and keeps
     * on a tie; so it is passed over. */
    box_empty(&acc);
    for (int b = 0, total = 0; b < BVH_BINS; b++) {
        if (count[b] == 0) {
            left_area[b] = b > 0 ? left_area[b - 1] : 0;
        } else {
            box_grow(&acc, &bin[b]);
            left_area[b] = box_half_area(&acc);
        }
        total += (int)count[b];
        left_n[b] = (size_t)total;
    }
    per_area = 1 / box_half_area(&acc); /* acc holds every bin */
    box_empty(&acc);
    for (int b = BVH_BINS - 1; b > 0; b--) {
        real cost;
        if (count[b] == 0)
            continue;
        box_grow(&acc, &bin[b]);
        if (left_n[b - 1] == 0 || left_n[b - 1] == n)
            continue;
        cost = 1 + (left_area[b - 1] * (real)left_n[b - 1] +
                    box_half_area(&acc) * (real)(n - left_n[b - 1])) *
                       per_area;
        if (cost < best) {
            best = cost;
            *split = b;
        }
    }
    return best;
}

/* Chooses how to split prims[start..end), of centroids' box cb (count >
 * BVH_LEAF_MAX or SAH says so); returns the index of the first primitive
 * of the right part, or start when it is better left a leaf. */
static size_t bvh_split(BuildPrim *prims, size_t start, size_t end, const Box *cb, int depth)
{
    size_t n = end - start, mid;
    real extent[3], scale[3], best = INFINITY;
    int best_split = -1, axis;

    for (int a = 0; a < 3; a++) {
        extent[a] = cb->hi[a] - cb->lo[a];
        scale[a] = BVH_BINS / extent[a];
    }
    axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : extent[1] >= extent[2] ? 1 : 2;
    if (!(extent[axis] > 0)) {
        /* All centroids at one point: split by count if the leaf is too big. */
        if (n <= BVH_LEAF_MAX)
            return start;
        return start + n / 2;
    }
    if (depth >= BVH_SAH_DEPTH) {
        mid = start + n / 2;
        bvh_select(prims, start, end, mid, axis);
        return mid;
    }
    /* Every axis with some extent: the cheapest split wins. Above
     * BVH_ALL_AXES primitives only the longest is binned: near the root,
     * where binning costs the most, it is nearly always the best. */
    for (int a = 0; a < 3; a++) {
        int split;
        real cost;
        if (!(extent[a] > 0) || (n > BVH_ALL_AXES && a != axis))
            continue;
        cost = bvh_sah_axis(prims, start, end, a, cb->lo[a], scale[a], &split);
        if (split >= 0 && cost < best) {
            best = cost;
            best_split = split;
            axis = a;
        }
    }
    if (best_split < 0 || (best >= (real)n && n <= BVH_LEAF_MAX))
        return n <= BVH_LEAF_MAX ? start : start + n / 2;
    /* Partition by bin. */
    {
        size_t i = start, j = end;
        while (i < j) {
            if (bvh_bin(&prims[i], axis, cb->lo[axis], scale[axis]) < best_split) {
                i++;
            } else {
                BuildPrim tmp = prims[i];
                prims[i] = prims[--j];
                prims[j] = tmp;
            }
        }
        mid = i;
    }
    if (mid == start || mid == end) { /* cannot happen, but never loop */
        mid = start + n / 2;
        bvh_select(prims, start, end, mid, axis);
    }
    return mid;
}

/* Builds the binary subtree of task into nodes (see BuildTask), reordering
 * prims[task.start..task.end) by leaf; in an OpenMP parallel region, right
 * subtrees of BVH_TASK_MIN primitives or more become tasks. */
static void bvh_build_subtree(BuildPrim *prims, BuildNode *nodes, BuildTask root)
{
    /* Each step pops one task and pushes at most two, one of them deeper. */
    BuildTask stack[2 * (BVH_DEPTH_MAX + 1)];
    int top = 0;

    stack[top++] = root;
    while (top > 0) {
        BuildTask task = stack[--top], left, right;
        BuildNode *node = &nodes[task.node];
        size_t split;
        Box cb; /* the box of the primitives' centroids */

        box_empty(&cb);
        for (size_t i = task.start; i < task.end; i++) {
            real c[3] = {bvh_centroid(&prims[i], 0), bvh_centroid(&prims[i], 1),
                         bvh_centroid(&prims[i], 2)};
            box_grow_point(&cb, c);
        }
        node->size = (uint32_t)(task.end - task.start);
        split = task.end - task.start <= 1
                    ? task.start
                    : bvh_split(prims, task.start, task.end, &cb, task.depth);
        if (split == task.start) {
            node->index = (uint32_t)task.start;
            node->count = (uint32_t)(task.end - task.start);
            continue;
        }
        left = (BuildTask){task.start, split, task.depth + 1, task.node + 1};
        right = (BuildTask){split, task.end, task.depth + 1, task.node + 2 * (split - task.start)};
        node->count = 0;
        node->index = (uint32_t)right.node;
        if (task.end - split >= BVH_TASK_MIN) {
#ifdef _OPENMP
#pragma omp task firstprivate(right)
#endif
            bvh_build_subtree(prims, nodes, right);
        } else {
            stack[top++] = right;
        }
        stack[top++] = left;
    }
}

/* Moves the binary tree's nodes to the front of nodes in depth-first order
 * (each left child still right after its parent), closing the gaps the
 * fixed offsets leave; returns how many there are. In place: the walk meets
 * the nodes in increasing order, so a node only moves down, onto a slot
 * already moved or never used. */
static size_t bvh_compact(BuildNode *nodes)
{
    struct {
        size_t node;   /* where it is */
        size_t parent; /* where its parent went, or SIZE_MAX for a left child
                          or the root */
    } stack[2 * (BVH_DEPTH_MAX + 1)];
    int top = 0;
    size_t count = 0;

    stack[top].node = 0;
    stack[top++].parent = SIZE_MAX;
    while (top > 0) {
        size_t old = stack[--top].node, parent = stack[top].parent, at = count++;

        nodes[at] = nodes[old];
        if (parent != SIZE_MAX)
            nodes[parent].index = (uint32_t)at;
        if (nodes[at].count == 0) {
            stack[top].node = nodes[at].index;
            stack[top++].parent = at;
            stack[top].node = old + 1;
            stack[top++].parent = SIZE_MAX;
        }
    }
    return count;
}

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
static size_t bvh_collapsed_count(const BuildNode *nodes, uint32_t id)
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
 * padded boxes (bvh_prim_box() with pad), as the build had it. In an OpenMP
 * parallel region, children of BVH_TASK_MIN primitives or more are made
 * by tasks, their places counted first: the nodes are the same. */
static size_t bvh_collapse(const BuildNode *nodes, uint32_t id, size_t self, int depth,
                           real pad, Bvh *bvh, Box *bounds, int *deepest)
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
                bvh_prim_box(&bvh->shapes, bvh->prims[i], pad, &p);
                box_grow(&box[k], &p.box);
            }
            w->child[k] = c->index;
            w->count[k] = (uint8_t)c->count;
        } else if (c->size >= BVH_TASK_MIN) {
            size_t at = next;
            next += bvh_collapsed_count(nodes, members[k]);
            w->child[k] = (uint32_t)at;
#ifdef _OPENMP
#pragma omp task firstprivate(k, at) shared(box, deep)
#endif
            bvh_collapse(nodes, members[k], at, depth + 1, pad, bvh, &box[k], &deep[k]);
        } else {
            w->child[k] = (uint32_t)next;
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
            w->box[a][k] = bvh_float_below(((double)box[k].lo[a] - bvh->centre[a]) * bvh->scale);
            w->box[3 + a][k] =
                bvh_float_above(((double)box[k].hi[a] - bvh->centre[a]) * bvh->scale);
        }
        box_grow(bounds, &box[k]);
        *deepest = deep[k] > *deepest ? deep[k] : *deepest;
    }
    return next - self;
}

static int bvh_real_order(const void *a, const void *b)
{
    real x = *(const real *)a, y = *(const real *)b;

    return (x > y) - (x < y);
}

/* Sets bvh's frame: on each axis the median of the centroids of up to
 * BVH_FRAME_SAMPLE of the n primitives, spread evenly over them (all of
 * them when there are no more), as the boxes' rounding margins grow with
 * their distance from it and most boxes are near it (the centre of all
 * the boxes would sit 10^5 away from spheres of radius 0.1 beside a floor
 * sphere of radius 10^5); and the power of two that brings the boxes'
 * half-extent within [1, 2) (within 2^+-1000). */
static void bvh_frame(Bvh *bvh, const BuildPrim *prims, size_t n)
{
    Box all;
    double half = 0;
    real c[BVH_FRAME_SAMPLE];
    size_t m = n < BVH_FRAME_SAMPLE ? n : BVH_FRAME_SAMPLE;

    box_empty(&all);
    for (size_t i = 0; i < n; i++)
        box_grow(&all, &prims[i].box);
    for (int a = 0; a < 3; a++) {
        for (size_t i = 0; i < m; i++)
            c[i] = bvh_centroid(&prims[(size_t)((unsigned long long)i * n / m)], a);
        qsort(c, m, sizeof *c, bvh_real_order);
        bvh->centre[a] = c[m / 2];
        half = fmax(half, 0.5 * (double)all.hi[a] - 0.5 * (double)all.lo[a]);
    }
    bvh->scale = half > 0 ? ldexp(1, -(ilogb(half) < -1000 ? -1000 : ilogb(half))) : 1;
}

/* Returns 1 when this program has the queries' AVX2 build and the
 * processor (and its system) runs AVX2 and FMA instructions. */
static int bvh_has_avx2(void)
{
#if defined(RAYTRACE_AVX2)
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    return 0;
#endif
}

int bvh_build(Bvh *bvh, const BvhShapes *shapes, real reach, int threads)
{
    size_t n = shapes->sphere_count + shapes->triangle_count;
    BuildPrim *prims;
    BuildNode *nodes;
    real pad = bvh_padding(shapes, reach, threads);

    memset(bvh, 0, sizeof *bvh);
    bvh->shapes = *shapes;
    bvh->avx2 = bvh_has_avx2();
    /* Binary nodes are numbered below 2n in 32 bits. */
    if (shapes->sphere_count >= BVH_TRIANGLE || shapes->triangle_count >= BVH_TRIANGLE || n == 0 ||
        n > UINT32_MAX / 2)
        return -1;
    prims = malloc(n * sizeof *prims);
    nodes = malloc((2 * n - 1) * sizeof *nodes);
    bvh->prims = malloc(n * sizeof *bvh->prims);
    if (!prims || !nodes || !bvh->prims) {
        free(prims);
        free(nodes);
        bvh_free(bvh);
        return -1;
    }
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) if (threads > 1 && n >= 2 * BVH_TASK_MIN)
#endif
    for (size_t i = 0; i < n; i++) {
        if (i < shapes->sphere_count)
            bvh_prim_box(shapes, (uint32_t)i, pad, &prims[i]);
        else
            bvh_prim_box(shapes, (uint32_t)(i - shapes->sphere_count) | BVH_TRIANGLE, pad,
                         &prims[i]);
    }
    bvh_frame(bvh, prims, n);
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if (threads > 1 && n >= 2 * BVH_TASK_MIN)
#pragma omp single
#endif
    bvh_build_subtree(prims, nodes, (BuildTask){0, n, 0, 0});
    (void)threads;
    for (size_t i = 0; i < n; i++)
        bvh->prims[i] = prims[i].ref;
    bvh->prim_count = n;
    free(prims);
    /* Give back the slots the fixed offsets left unused: the binary tree
     * and the nodes made from it are held together next. */
    {
        BuildNode *fit = realloc(nodes, bvh_compact(nodes) * sizeof *nodes);
        if (fit)
            nodes = fit;
    }
    bvh->node_count = bvh_collapsed_count(nodes, 0);
    bvh->nodes = aligned_alloc(_Alignof(BvhNode), bvh->node_count * sizeof *bvh->nodes);
    if (!bvh->nodes) {
        free(nodes);
        bvh_free(bvh);
        return -1;
    }
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if (threads > 1 && n >= 2 * BVH_TASK_MIN)
#pragma omp single
#endif
    {
        Box all;
        bvh_collapse(nodes, 0, 0, 0, pad, bvh, &all, &bvh->depth);
    }
    free(nodes);
    /* The spheres' copies come last, once the binary tree is gone. */
    if (shapes->sphere_count > 0 && !(bvh->balls = calloc(n, sizeof *bvh->balls))) {
        bvh_free(bvh);
        return -1;
    }
    for (size_t i = 0; i < n && bvh->balls; i++) {
        if (!(bvh->prims[i] & BVH_TRIANGLE)) {
            const Sphere *s = &shapes->spheres[bvh->prims[i]];
            bvh->balls[i][0] = s->centre.x;
            bvh->balls[i][1] = s->centre.y;
            bvh->balls[i][2] = s->centre.z;
            bvh->balls[i][3] = s->radius;
        }
    }
    return 0;
}

size_t bvh_build_memory(size_t n)
{
    /* Building: the primitives' boxes, the binary tree and the references.
     * Collapsing: the tree, the references and the nodes, at most
     * W n / (2 (W - 1)) of them (W = BVH_WIDTH): a node of W children
     * takes up W - 1 of the tree's interior nodes; one of m < W children has
     * only leaves, m >= 2 of them, and takes up m - 1. With F nodes of the
     * first kind and S of the second holding M leaves in all, the tree's
     * L <= n leaves give L - 1 = (W - 1) F + M - S, M >= 2 S and M <= L, so
     * F + S = (L - 1 - M + W S) / (W - 1) <= (L - 1 + (W - 2) S) / (W - 1)
     * <= W L / (2 (W - 1)). After: the nodes, the references and the
     * spheres' copies, 4 reals a primitive in place of the binary tree's two
     * nodes: the larger of the two is counted. */
    size_t build = sizeof(BuildPrim) + 2 * sizeof(BuildNode) + sizeof(uint32_t);
    size_t tree = 2 * sizeof(BuildNode) > 4 * sizeof(real) ? 2 * sizeof(BuildNode)
                                                            : 4 * sizeof(real);
    size_t collapse = tree + sizeof(uint32_t);

    if (n > (SIZE_MAX / 2 - 4096) / (build + sizeof(BvhNode)))
        return SIZE_MAX;
    collapse = n * collapse + (n / 2 * BVH_WIDTH / (BVH_WIDTH - 1) + 2) * sizeof(BvhNode);
    build *= n;
    return (build > collapse ? build : collapse) + 4096;
}

size_t bvh_memory(const Bvh *bvh)
{
    return bvh->node_count * sizeof *bvh->nodes + bvh->prim_count * sizeof *bvh->prims +
           (bvh->balls ? bvh->prim_count * sizeof *bvh->balls : 0);
}

void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->prims);
    free(bvh->balls);
    memset(bvh, 0, sizeof *bvh);
}
