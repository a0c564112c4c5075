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
    for (size_t i = 0; i < shapes->cube_count; i++)
        m = bvh_farther(bvh_farther(m, shapes->cubes[i].lo), shapes->cubes[i].hi);
    for (size_t i = 0; i < shapes->square_count; i++) {
        const Square *sq = &shapes->squares[i];
        real r = bvh_farther(0, sq->centre) + 2 * sq->half;
        m = r > m ? r : m;
    }
    return m * (REAL_EPSILON * BVH_PAD_ULPS);
}

/* Grows lo and hi by the corner p. */
static void bvh_bounds_grow(real lo[3], real hi[3], Vec3 p)
{
    real c[3] = {p.x, p.y, p.z};

    for (int a = 0; a < 3; a++) {
        lo[a] = c[a] < lo[a] ? c[a] : lo[a];
        hi[a] = c[a] > hi[a] ? c[a] : hi[a];
    }
}

void bvh_prim_bounds(const BvhShapes *shapes, uint32_t ref, real pad, real lo[3], real hi[3])
{
    size_t i = bvh_index(ref);
    real r = pad; /* the margin every side gets */

    for (int a = 0; a < 3; a++) {
        lo[a] = INFINITY;
        hi[a] = -INFINITY;
    }
    switch (bvh_kind(ref)) {
    case BVH_TRIANGLE:
        for (int k = 0; k < 3; k++)
            bvh_bounds_grow(lo, hi, shapes->triangles[i].v[k]);
        break;
    case BVH_CUBE:
        bvh_bounds_grow(lo, hi, shapes->cubes[i].lo);
        bvh_bounds_grow(lo, hi, shapes->cubes[i].hi);
        break;
    case BVH_SQUARE: {
        /* Its four corners; the plane test rounds like a triangle's. */
        const Square *sq = &shapes->squares[i];
        Vec3 u = vec3_scale(sq->axis_u, sq->half), v = vec3_scale(sq->axis_v, sq->half);
        for (int k = 0; k < 4; k++)
            bvh_bounds_grow(lo, hi, vec3_add(vec3_add(sq->centre, k & 1 ? u : vec3_neg(u)),
                                             k & 2 ? v : vec3_neg(v)));
        /* The corners round by a few ulps of the square's size too. */
        r += 2 * sq->half * REAL_EPSILON * BVH_PAD_ULPS;
        break;
    }
    default: {
        const Sphere *s = &shapes->spheres[i];
        bvh_bounds_grow(lo, hi, s->centre);
        r += s->radius * (1 + REAL_EPSILON * (BVH_PAD_ULPS / 16));
    }
    }
    for (int a = 0; a < 3; a++) {
        lo[a] -= r;
        hi[a] += r;
    }
}

void bvh_prim_prefetch(const BvhShapes *shapes, uint32_t ref)
{
    size_t i = bvh_index(ref);
    const char *at, *end; /* the first and last bytes bvh_prim_bounds() reads */

    switch (bvh_kind(ref)) {
    case BVH_TRIANGLE:
        at = (const char *)&shapes->triangles[i].v;
        end = at + sizeof shapes->triangles[i].v - 1;
        break;
    case BVH_CUBE:
        at = (const char *)&shapes->cubes[i];
        end = at + sizeof shapes->cubes[i] - 1;
        break;
    case BVH_SQUARE:
        at = (const char *)&shapes->squares[i];
        end = at + sizeof shapes->squares[i] - 1;
        break;
    default:
        at = (const char *)&shapes->spheres[i].centre;
        end = (const char *)&shapes->spheres[i].radius + sizeof shapes->spheres[i].radius - 1;
    }
    __builtin_prefetch(at);
    __builtin_prefetch(end);
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
