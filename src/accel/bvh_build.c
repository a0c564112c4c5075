/* bvh_build.c: building the bounding volume hierarchy (see bvh.h): the boxes,
 * the frame and the steps in order; its queries are in bvh_query.c. */
#include "bvh_build.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

enum {
    BVH_FRAME_SAMPLE = 4095 /* centroids the frame's median is taken of */
};

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

void bvh_prim_box(const BvhShapes *shapes, uint32_t ref, real pad, BuildPrim *p)
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

