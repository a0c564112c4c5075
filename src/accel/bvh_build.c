/* bvh_build.c: building the bounding volume hierarchy (see bvh.h): its
 * frame and the steps in order (boxes: bvh_box.c; the binary tree:
 * bvh_sah.c; wide nodes: bvh_collapse.c); its queries are in bvh_query.c. */
#include "accel/bvh.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/aligned.h"

#include "bvh_box.h"
#include "bvh_collapse.h"
#include "bvh_sah.h"

enum {
    BVH_FRAME_SAMPLE = 4095 /* centroids the frame's median is taken of */
};

static int bvh_real_order(const void *a, const void *b)
{
    real x = *(const real *)a, y = *(const real *)b;

    return (x > y) - (x < y);
}

/* Returns the reference of the i-th primitive, first[k] the first of kind
 * k (first[SHAPE_KINDS] past the last). */
static uint32_t bvh_ref_at(const size_t first[SHAPE_KINDS + 1], size_t i)
{
    unsigned kind = 0;

    while (i >= first[kind + 1])
        kind++;
    return bvh_ref(kind, i - first[kind]);
}

/* Sets bvh's frame: on each axis the median of the centroids of up to
 * BVH_FRAME_SAMPLE of the n primitives, spread evenly over them (all of
 * them when there are no more), as the boxes' rounding margins grow with
 * their distance from it and most boxes are near it (the centre of all
 * the boxes would sit 10^5 away from spheres of radius 0.1 beside a floor
 * sphere of radius 10^5); and the power of two that brings the boxes'
 * half-extent within [1, 2) (within 2^+-1000). The boxes are bvh's shapes'
 * (first[k] the first of kind k) padded by pad, in scene coordinates. */
static void bvh_frame(Bvh *bvh, const size_t first[SHAPE_KINDS + 1], size_t n, real pad,
                      int threads)
{
    real lo0 = INFINITY, lo1 = INFINITY, lo2 = INFINITY;
    real hi0 = -INFINITY, hi1 = -INFINITY, hi2 = -INFINITY;
    double half = 0;
    real c[BVH_FRAME_SAMPLE];
    size_t m = n < BVH_FRAME_SAMPLE ? n : BVH_FRAME_SAMPLE;

    (void)threads;
    /* The smallest and largest of finite values: the same on any number of
     * threads. */
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) if (threads > 1 && n >= 2 * BVH_TASK_MIN) \
    reduction(min : lo0, lo1, lo2) reduction(max : hi0, hi1, hi2)
#endif
    for (size_t i = 0; i < n; i++) {
        real lo[3], hi[3];
        bvh_prim_bounds(&bvh->shapes, bvh_ref_at(first, i), pad, lo, hi);
        lo0 = lo[0] < lo0 ? lo[0] : lo0;
        lo1 = lo[1] < lo1 ? lo[1] : lo1;
        lo2 = lo[2] < lo2 ? lo[2] : lo2;
        hi0 = hi[0] > hi0 ? hi[0] : hi0;
        hi1 = hi[1] > hi1 ? hi[1] : hi1;
        hi2 = hi[2] > hi2 ? hi[2] : hi2;
    }
    for (int a = 0; a < 3; a++) {
        for (size_t i = 0; i < m; i++) {
            real lo[3], hi[3];
            size_t k = (size_t)((unsigned long long)i * n / m);
            bvh_prim_bounds(&bvh->shapes, bvh_ref_at(first, k), pad, lo, hi);
            c[i] = 0.5 * lo[a] + 0.5 * hi[a];
        }
        qsort(c, m, sizeof *c, bvh_real_order);
        bvh->centre[a] = c[m / 2];
    }
    half = fmax(fmax(0.5 * (double)hi0 - 0.5 * (double)lo0, 0.5 * (double)hi1 - 0.5 * (double)lo1),
                0.5 * (double)hi2 - 0.5 * (double)lo2);
    bvh->scale = half > 0 ? ldexp(1, -(ilogb(half) < -1000 ? -1000 : ilogb(half))) : 1;
}

/* Returns the references of the n primitives of prims, in their order, in
 * the memory prims held, given back but for their 4 bytes each: the build
 * never holds both. */
static uint32_t *bvh_refs_in_place(BuildPrim *prims, size_t n)
{
    unsigned char *at = (unsigned char *)prims;
    uint32_t *refs;

    /* Reference i goes to bytes 4 i, below primitive i + 1's, which is yet
     * to be read. */
    for (size_t i = 0; i < n; i++) {
        uint32_t ref = prims[i].ref;
        memcpy(at + i * sizeof ref, &ref, sizeof ref);
    }
    refs = realloc(prims, n * sizeof *refs);
    return refs ? refs : (uint32_t *)(void *)at;
}

enum {
    BVH_MOVE_STRIDE = 64, /* every 64th slot starts a run of moves */
    BVH_MOVE_LANES = 32   /* runs a thread follows at once */
};

/* Follows the runs from marked slots first to first + count - 1 (count at
 * most BVH_MOVE_LANES) of bvh_move_spheres() together, a step of each in
 * turn, so that their reads from memory overlap (each run's next read
 * waits for its last). */
static void bvh_move_runs(Sphere *spheres, const uint32_t *from, unsigned char *moved,
                          const Sphere *saved, size_t first, size_t count)
{
    size_t k[BVH_MOVE_LANES];
    size_t live = count;

    for (size_t l = 0; l < count; l++)
        k[l] = (first + l) * BVH_MOVE_STRIDE;
    while (live > 0) {
        for (size_t l = 0; l < live;) {
            size_t src = from[k[l]];
            moved[k[l]] = 1;
            if (src % BVH_MOVE_STRIDE == 0) {
                spheres[k[l]] = saved[src / BVH_MOVE_STRIDE];
                k[l] = k[--live]; /* this run ends: the last takes its lane */
            } else {
                spheres[k[l]] = spheres[src];
                k[l++] = src;
            }
        }
    }
}

/* Moves spheres[from[k]] to spheres[k] for every k of n (from a
 * permutation), in place; moved[] (n bytes, zeroed) marks the slots done.
 * Runs start at every BVH_MOVE_STRIDE-th slot, whose spheres are saved
 * first, and follow from[] up to the next such slot, so that they run on
 * every thread apart, several on each at once (bvh_move_runs()); then the
 * cycles no run reached, one by one. Returns -1 (nothing moved) when
 * memory runs out. */
static int bvh_move_spheres(Sphere *spheres, const uint32_t *from, size_t n,
                            unsigned char *moved, int threads)
{
    size_t marks = (n + BVH_MOVE_STRIDE - 1) / BVH_MOVE_STRIDE;
    size_t groups = (marks + BVH_MOVE_LANES - 1) / BVH_MOVE_LANES;
    Sphere *saved = malloc(marks * sizeof *saved);

    (void)threads;
    if (!saved)
        return -1;
    for (size_t i = 0; i < marks; i++)
        saved[i] = spheres[i * BVH_MOVE_STRIDE];
    /* Each slot is the source of one slot alone: a run writes only the
     * slots it reaches, each after reading the next. */
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(dynamic, 1) if (n >= 2 * BVH_TASK_MIN)
#endif
    for (size_t g = 0; g < groups; g++) {
        size_t first = g * BVH_MOVE_LANES;
        bvh_move_runs(spheres, from, moved, saved, first,
                      marks - first < BVH_MOVE_LANES ? marks - first : BVH_MOVE_LANES);
    }
    free(saved);
    /* The cycles without a marked slot, round in place. */
    for (size_t j = 0; j < n; j++) {
        Sphere first = spheres[j];
        size_t k = j;
        if (moved[j])
            continue;
        while (from[k] != j) {
            spheres[k] = spheres[from[k]];
            moved[k] = 1;
            k = from[k];
        }
        spheres[k] = first;
        moved[k] = 1;
    }
    return 0;
}

/* Moves spheres, the array *bvh is built over, into the order of its
 * references (its leaves'), and renumbers them to match (bvh_build()'s
 * shapes->movable); returns 0, or -1 (nothing moved) when memory runs
 * out. */
static int bvh_move_into_leaves(Bvh *bvh, Sphere *spheres, int threads)
{
    size_t n = bvh->shapes.count[SHAPE_SPHERE], next = 0;
    uint32_t *from = malloc(n * sizeof *from); /* from[j]: the sphere to move to j */
    unsigned char *moved = calloc(n + 1, 1);

    if (!from || !moved) {
        free(from);
        free(moved);
        return -1;
    }
    for (size_t k = 0; k < bvh->prim_count; k++)
        if (bvh_kind(bvh->prims[k]) == SHAPE_SPHERE)
            from[next++] = (uint32_t)bvh_index(bvh->prims[k]);
    if (bvh_move_spheres(spheres, from, n, moved, threads) != 0) {
        free(from);
        free(moved);
        return -1;
    }
    next = 0;
    for (size_t k = 0; k < bvh->prim_count; k++)
        if (bvh_kind(bvh->prims[k]) == SHAPE_SPHERE)
            bvh->prims[k] = bvh_ref(SHAPE_SPHERE, next++);
    free(from);
    free(moved);
    bvh->shapes.items[SHAPE_SPHERE] = spheres;
    if (n == bvh->prim_count) { /* slot k holds sphere k */
        free(bvh->prims);
        bvh->prims = NULL;
    }
    return 0;
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
    size_t n = 0, first[SHAPE_KINDS + 1];
    int over = 0;
    BuildPrim *prims;
    BuildNode *nodes;
    real pad = bvh_padding(shapes, reach, threads);

    memset(bvh, 0, sizeof *bvh);
    bvh->shapes = *shapes;
    bvh->avx2 = bvh_has_avx2();
    for (int k = 0; k < SHAPE_KINDS; k++) {
        first[k] = n;
        n += shapes->count[k];
        over |= shapes->count[k] >= BVH_MAX_OF_KIND;
    }
    first[SHAPE_KINDS] = n;
    /* Binary nodes are numbered below 2n in 32 bits; wide nodes and
     * primitives below BVH_MAX_LINK. */
    if (over || n == 0 || n >= BVH_MAX_LINK / 2)
        return -1;
    prims = malloc(n * sizeof *prims);
    nodes = malloc((2 * n - 1) * sizeof *nodes);
    if (!prims || !nodes) {
        free(prims);
        free(nodes);
        bvh_free(bvh);
        return -1;
    }
    bvh_frame(bvh, first, n, pad, threads);
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) if (threads > 1 && n >= 2 * BVH_TASK_MIN)
#endif
    for (size_t i = 0; i < n; i++)
        bvh_prim_box(bvh, bvh_ref_at(first, i), pad, &prims[i]);
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if (threads > 1 && n >= 2 * BVH_TASK_MIN)
#pragma omp single
#endif
    bvh_build_subtree(prims, nodes, (BuildTask){0, n, 0, 0});
    (void)threads;
    /* Plan the wide nodes on the primitives' boxes (in the leaves' order),
     * counting them as it goes (no walk of the tree on one thread), then
     * keep their references alone: the binary tree and the nodes
     * made from it are held together next. The slots the fixed offsets
     * left unused stay where they are (a few of them, never written, so
     * never resident): moving them out cost a pass on one thread. */
#ifdef _OPENMP
#pragma omp parallel num_threads(threads) if (threads > 1 && n >= 2 * BVH_TASK_MIN)
#pragma omp single
#endif
    bvh->node_count = bvh_plan(nodes, prims);
    bvh->prims = bvh_refs_in_place(prims, n);
    bvh->prim_count = n;
    /* Spheres moved before the collapse, which then reads them in order,
     * not at random (docs/log.md); a scene of spheres alone then gives the
     * references back before the nodes are made. */
    if (shapes->movable)
        (void)bvh_move_into_leaves(bvh, shapes->movable, threads);
    bvh->nodes = aligned_new(_Alignof(BvhNode), bvh->node_count * sizeof *bvh->nodes);
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
    return 0;
}

size_t bvh_build_memory(size_t n)
{
    /* Building: the primitives' boxes and the binary tree (the references
     * then take the boxes' place). Collapsing: the tree (its plan in it),
     * the references and the nodes, at most W n / (2 (W - 1)) of them (W =
     * BVH_WIDTH): a node of W children takes up W - 1 of the tree's
     * interior nodes; one of m < W children has only leaves, m >= 2 of
     * them, and takes up m - 1 (bvh_plan()). With F nodes of the first kind
     * and S of the second holding M leaves in all, the tree's L <= n leaves
     * (a leaf: a subtree of the tree made one) give L - 1 = (W - 1) F + M - S,
     * M >= 2 S and M <= L, so F + S = (L - 1 - M + W S) / (W - 1) <=
     * (L - 1 + (W - 2) S) / (W - 1) <= W L / (2 (W - 1)). Before the
     * nodes, moving the spheres takes the tree, the references and under
     * 6 bytes a primitive besides (whence to move each, a mark, and a
     * sphere every BVH_MOVE_STRIDE), less than the nodes would. */
    size_t build = sizeof(BuildPrim) + 2 * sizeof(BuildNode);
    size_t collapse = 2 * sizeof(BuildNode) + sizeof(uint32_t);

    if (n > (SIZE_MAX / 2 - 4096) / (build + sizeof(BvhNode)))
        return SIZE_MAX;
    collapse = n * collapse + (n / 2 * BVH_WIDTH / (BVH_WIDTH - 1) + 2) * sizeof(BvhNode);
    build *= n;
    return (build > collapse ? build : collapse) + 4096;
}

size_t bvh_build_scratch(size_t n)
{
    return n > SIZE_MAX / (2 * sizeof(BuildNode)) ? SIZE_MAX : n * 2 * sizeof(BuildNode);
}

size_t bvh_memory(const Bvh *bvh)
{
    return bvh->node_count * sizeof *bvh->nodes +
           (bvh->prims ? bvh->prim_count * sizeof *bvh->prims : 0);
}

void bvh_free(Bvh *bvh)
{
    aligned_free(bvh->nodes);
    free(bvh->prims);
    memset(bvh, 0, sizeof *bvh);
}

