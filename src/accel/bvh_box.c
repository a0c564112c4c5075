/* bvh_box.c: the padded boxes of the hierarchy's primitives (see
 * bvh_box.h). */
#include "bvh_box.h"

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

real bvh_padding(const BvhShapes *shapes, real reach, int threads)
{
    real m = reach;

    (void)threads;
    for (int k = 0; k < SHAPE_KINDS; k++) {
        size_t n = shapes->count[k];
        const void *items = shapes->items[k];
        /* The largest of finite values, whatever the order: the same on
         * any number of threads. */
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) reduction(max : m) if (n >= BVH_TASK_MIN)
#endif
        for (size_t i = 0; i < n; i++) {
            real lo[3], hi[3];
            real r = shape_bounds((ShapeKind)k, items, i, BVH_PAD_ULPS, lo, hi);
            Vec3 l = vec3(lo[0], lo[1], lo[2]), h = vec3(hi[0], hi[1], hi[2]);
            r += bvh_farther(bvh_farther(0, l), h);
            m = r > m ? r : m;
        }
    }
    return m * (REAL_EPSILON * BVH_PAD_ULPS);
}

void bvh_prim_bounds(const BvhShapes *shapes, uint32_t ref, real pad, real lo[3], real hi[3])
{
    ShapeKind kind = (ShapeKind)bvh_kind(ref);
    /* The margin every side gets: the padding, and the shape's own. */
    real r = pad + shape_bounds(kind, shapes->items[kind], bvh_index(ref), BVH_PAD_ULPS, lo, hi);

    for (int a = 0; a < 3; a++) {
        lo[a] -= r;
        hi[a] += r;
    }
}

void bvh_prim_prefetch(const BvhShapes *shapes, uint32_t ref)
{
    ShapeKind kind = (ShapeKind)bvh_kind(ref);
    size_t size = shape_size(kind);
    const char *at = (const char *)shapes->items[kind] + bvh_index(ref) * size;

    __builtin_prefetch(at);
    __builtin_prefetch(at + size - 1);
}

void bvh_prim_box(const Bvh *bvh, uint32_t ref, real pad, BuildPrim *p)
{
    real lo[3], hi[3];

    bvh_prim_bounds(&bvh->shapes, ref, pad, lo, hi);
    p->ref = ref;
    for (int a = 0; a < 3; a++) {
        p->box.lo[a] = bvh_float_below(((double)lo[a] - bvh->centre[a]) * bvh->scale);
        p->box.hi[a] = bvh_float_above(((double)hi[a] - bvh->centre[a]) * bvh->scale);
    }
}
