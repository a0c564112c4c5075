/* bvh_query.c: the hierarchy's queries (bvh.h), in the build bvh_query.h
 * names: BVH_QUERY_AVX2 defined (with -mavx2 -mfma) for the AVX2 and FMA
 * one, whose functions end in _avx2; else _base. */
#include "bvh_query.h"

#include <float.h>
#include <math.h>
#include <string.h>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

/* A vector of one coordinate of BVH_LANES children's boxes, and a lane
 * mask; a row of a node's boxes is BVH_VECTORS of them. The base build
 * takes four lanes (SSE on x86-64, NEON on AArch64: every 64-bit processor
 * has them), the AVX2 one eight, and fuses the slab tests' multiply and
 * subtract (BVH_FMA: see below). */
#if defined(BVH_QUERY_AVX2)
#if !defined(__AVX2__) || !defined(__FMA__)
#error "bvh_query.c: BVH_QUERY_AVX2 needs -mavx2 -mfma"
#endif
#define BVH_QUERY(name) name##_avx2
#define BVH_FMA 1
#define BVH_VECTOR_BYTES 32
#else
#define BVH_QUERY(name) name##_base
#define BVH_FMA 0
#define BVH_VECTOR_BYTES 16
#endif
typedef float BvhLanes __attribute__((vector_size(BVH_VECTOR_BYTES)));
typedef int32_t BvhMask __attribute__((vector_size(BVH_VECTOR_BYTES)));
enum { BVH_LANES = BVH_VECTOR_BYTES / 4, BVH_VECTORS = BVH_WIDTH / BVH_LANES };

/*
 * The box tests run in floats, in the hierarchy's frame, with ray
 * parameters scaled by a power of two sigma of the ray's own (t' = t sigma)
 * that keeps them within floats' range. Each is conservative: when the
 * ray meets a box at some t in [0, tmax], the test says so.
 *
 * - The boxes are rounded outwards (bvh_collapse()).
 * - The origin o, in the frame, is rounded down to o- and up to o+; the
 *   near planes are measured from the one that makes their distances
 *   smaller (o+ when the direction is positive), the far ones from the
 *   other: distances from the true origin lie between.
 * - The reciprocal directions are rounded once from doubles: a slab
 *   distance (b - o) * inv is then within a relative 3 u (u = 2^-24: the
 *   subtraction, the reciprocal and the product; the double reciprocal's
 *   2^-53 and second-order terms are left to the margin below) plus
 *   2^-150 (a product in the subnormal range) of its value from that
 *   origin.
 * - So the computed entry t0 is at most T(1 + 3u) + 2^-150 and the computed
 *   exit at least T'(1 - 3u) - 2^-150 where the true T <= T'; widening the
 *   exit by BVH_WIDEN = 1 + 8u (1 + 7u after its own rounding, more than
 *   the 1 + 6u + O(u^2) needed) and adding BVH_TINY = 2^-140 keeps
 *   t0 <= t1 (pbrt-v3, 3.9.2, makes the same argument in one precision).
 * - tmax is rounded up (bvh_limit()).
 * Rays that would leave floats' range (an origin 2^100 beyond the scene's
 * size, or direction components 2^100 apart: a component that small is
 * not zero, yet its slab distances are not floats) enter every box.
 *
 * The AVX2 build computes a slab distance in one fused operation, b * inv
 * - oi, where oi is o * inv rounded once to a float (Embree's form, one
 * dependent step fewer), for rays with no zero direction component (o *
 * inv is NaN or infinite there: those take the form above). With P the
 * largest |o * inv| of the three axes, u as above:
 * - oi is o * inv (1 + e), |e| <= u + 2^-52 (the double product, the
 *   float, the frame's own double rounding of o), plus 2^-150 if
 *   subnormal; the result rounds once more. So the computed n is S (1 + d)
 *   + a with |d| <= u and |a| <= A = u (1 + 2^-20) P + 2^-149, where S =
 *   (b - o) * inv is the slab distance with the float reciprocal, which is
 *   within a relative u + 2^-53 of the true one.
 * - The true ray meets the box at some t* in [0, limit]. Then the entry t0
 *   <= r t* + A and the exit t1 >= q t* - A, with r = 1 + 2.01u and q = 1 -
 *   2.01u (the reciprocal's rounding and the result's; the limit is above
 *   t*), so t* <= (t1 + A) / q with t1 + A >= 0, and t0 <= R (t1 + A) + A,
 *   R = r / q < 1 + 4.1u.
 * - The widened exit fma(t1, BVH_WIDEN, C), one rounding, is at least
 *   (1 + 8u)(1 - u) s + (C - (1 + 8u) A)(1 - u) - 2^-150 for t1 = s - A, s
 *   >= 0; with (1 + 8u)(1 - u) > R and C >= (2 + 2^-20) A + 2^-149 that is
 *   at least R s + A >= t0. bvh_ray() takes C = P 2^-23 (1 + 2^-16) +
 *   2^-147, rounded up: about 2u P, a few units of a float from an origin
 *   within the frame.
 * The other rays' exit is widened by the same fused step with C =
 *   BVH_TINY, which rounds once instead of twice.
 */
#define BVH_WIDEN (1 + 4 * FLT_EPSILON)
#define BVH_TINY 0x1p-140f
#define BVH_FAR 0x1p100 /* the farthest origin and the widest ratio */

/* The ray, prepared for box tests: for each axis, the origins the near and
 * the far planes are measured from, the reciprocal direction (+-inf for
 * a zero component, by the sign of that zero) and, in the AVX2 build, the
 * origin times it (oi) in every lane, where the row of a node's boxes the
 * ray meets first starts (lo: a, or hi: 3 + a) and the other (in floats
 * from box[0][0]); sigma; whether every box is entered; whether the slab
 * tests take the fused form; the exit's widening term C, in every lane. */
typedef struct {
    BvhLanes near_o[3], far_o[3], inv[3];
#if BVH_FMA
    BvhLanes oi[3];
#endif
    BvhLanes grows;
    int near[3], far[3];
    double sigma;
    int all, fused;
    float grow;
} BvhRay;

/* Returns 2^e, for |e| <= 1022, from its bits. */
static inline double bvh_pow2(int e)
{
    uint64_t bits = (uint64_t)(e + 1023) << 52;
    double x;

    memcpy(&x, &bits, sizeof x);
    return x;
}

/* Returns the exponent of x, a positive normal double: x is in [2^e, 2^(e+1)). */
static inline int bvh_exponent(double x)
{
    uint64_t bits;

    memcpy(&bits, &x, sizeof bits);
    return (int)(bits >> 52 & 0x7ff) - 1023;
}

/* Returns x in every lane (one shuffle). */
static inline BvhLanes bvh_splat(float x)
{
#if BVH_VECTOR_BYTES == 32
    return (BvhLanes){x, x, x, x, x, x, x, x};
#else
    _Static_assert(BVH_LANES == 4, "bvh_splat() fills four lanes");
    return (BvhLanes){x, x, x, x};
#endif
}

static BvhRay bvh_ray(const Bvh *bvh, const Ray *r)
{
    BvhRay b;
    double o[3] = {r->origin.x, r->origin.y, r->origin.z};
    double d[3] = {r->dir.x, r->dir.y, r->dir.z}, inv[3], most = 0, down, p = 0;
    int e, ok;

    b.fused = BVH_FMA && d[0] != 0 && d[1] != 0 && d[2] != 0;
    for (int a = 0; a < 3; a++) {
        double m;
        inv[a] = 1 / d[a];
        m = d[a] != 0 ? fabs(inv[a]) : 0; /* inf for a subnormal component */
        most = m > most ? m : most;
    }
    /* Scaled by down, the largest reciprocal is in [1/2, 1): t' = t sigma.
     * (An infinite most has the exponent 1024.) */
    e = bvh_exponent(most) + 1;
    ok = e >= -1000 && e <= 1000;
    down = bvh_pow2(ok ? -e : 0);
    b.sigma = bvh->scale * down;
    ok &= b.sigma >= 0x1p-1000 && b.sigma <= 0x1p1000;
    for (int a = 0; a < 3; a++) {
        double oa = (o[a] - bvh->centre[a]) * bvh->scale, ia = inv[a] * down;
        float inv_a = (float)ia;
        ok &= fabs(oa) <= BVH_FAR && (d[a] == 0 || fabs(ia) >= 1 / BVH_FAR);
        b.inv[a] = bvh_splat(inv_a);
        b.near[a] = (ia < 0 ? 3 + a : a) * BVH_WIDTH;
        b.far[a] = (ia < 0 ? a : 3 + a) * BVH_WIDTH;
#if BVH_FMA
        if (b.fused) {
            double oi = oa * (double)inv_a;
            b.oi[a] = bvh_splat((float)oi);
            p = fabs(oi) > p ? fabs(oi) : p;
            continue;
        }
#endif
        {
            float lo = bvh_float_below(oa), hi = bvh_float_above(oa);
            b.near_o[a] = bvh_splat(ia > 0 ? hi : lo);
            b.far_o[a] = bvh_splat(ia > 0 ? lo : hi);
        }
    }
    b.all = !ok;
    b.grow = b.fused ? bvh_float_above(p * 0x1.0001p-23 + 0x1p-147) : BVH_TINY;
    b.grows = bvh_splat(b.grow);
    return b;
}

/* Returns the bound of box tests for ray parameters up to t. */
static float bvh_limit(const BvhRay *r, double t)
{
    return bvh_float_above(t * r->sigma);
}

/* Lane by lane, a > b ? a : b and a < b ? a : b (b when either is NaN):
 * what SSE's max and min instructions do. */
#if defined(BVH_QUERY_AVX2)
#define bvh_max(a, b) ((BvhLanes)_mm256_max_ps((a), (b)))
#define bvh_min(a, b) ((BvhLanes)_mm256_min_ps((a), (b)))
#define bvh_mask_bits(m) ((unsigned)_mm256_movemask_ps((__m256)(m)))
#elif defined(__SSE2__)
#define bvh_max(a, b) ((BvhLanes)_mm_max_ps((a), (b)))
#define bvh_min(a, b) ((BvhLanes)_mm_min_ps((a), (b)))
#define bvh_mask_bits(m) ((unsigned)_mm_movemask_ps((__m128)(m)))
#else
static inline BvhLanes bvh_pick(BvhMask m, BvhLanes a, BvhLanes b)
{
    return (BvhLanes)((m & (BvhMask)a) | (~m & (BvhMask)b));
}
#define bvh_max(a, b) bvh_pick((a) > (b), (a), (b))
#define bvh_min(a, b) bvh_pick((a) < (b), (a), (b))
static inline unsigned bvh_mask_bits(BvhMask m)
{
    unsigned bits = 0;

    for (int k = 0; k < BVH_LANES; k++)
        bits |= (unsigned)(m[k] & 1) << k;
    return bits;
}
#endif

/* Returns the row of node's boxes from offset on. */
static inline BvhLanes bvh_row(const BvhNode *node, int offset)
{
    BvhLanes x;

    memcpy(&x, &node->box[0][0] + offset, sizeof x);
    return x;
}

/* Returns x * BVH_WIDEN + the ray's C lane by lane, rounded once (AVX2 build)
 * or twice: the widened exit (above), monotonic in x. */
static inline BvhLanes bvh_widen(BvhLanes x, const BvhRay *r)
{
#if BVH_FMA
    return (BvhLanes)_mm256_fmadd_ps(x, bvh_splat(BVH_WIDEN), r->grows);
#else
    return x * BVH_WIDEN + r->grows;
#endif
}

/* bvh_children_enter() for a ray not entering every box, its slab tests
 * in the fused form or not (a constant where it is called). */
static inline __attribute__((always_inline)) unsigned
bvh_rows_enter(const BvhNode *node, const BvhRay *r, BvhLanes limit, float enter[BVH_WIDTH],
               int fused)
{
    unsigned bits = 0;

    (void)fused;
    /* Unrolled: the loops are short and the body is a few instructions. */
#pragma GCC unroll 2
    for (int v = 0; v < BVH_VECTORS; v++) {
        int first = v * BVH_LANES;
        BvhLanes t0 = {0}, t1 = limit, n, f;
#pragma GCC unroll 3
        for (int a = 0; a < 3; a++) {
            BvhLanes lo = bvh_row(node, r->near[a] + first), hi = bvh_row(node, r->far[a] + first);
#if BVH_FMA
            if (fused) {
                n = (BvhLanes)_mm256_fmsub_ps(lo, r->inv[a], r->oi[a]);
                f = (BvhLanes)_mm256_fmsub_ps(hi, r->inv[a], r->oi[a]);
            } else
#endif
            {
                n = (lo - r->near_o[a]) * r->inv[a];
                f = (hi - r->far_o[a]) * r->inv[a];
            }
            t0 = bvh_max(n, t0);
            t1 = bvh_min(f, t1);
        }
        /* Widened once: the widening is monotonic, so the least of the
         * widened ends is the least end widened. */
        t1 = bvh_widen(t1, r);
        memcpy(enter + first, &t0, sizeof t0);
        bits |= bvh_mask_bits((BvhMask)(t0 <= t1)) << first;
    }
    return bits;
}

/* Says which of node's children's boxes the ray meets at some t' in [0,
 * limit] (a bvh_limit(), in every lane): bit k for child k; stores in
 * enter[k] where the ray enters child k's box (t', never later than the
 * true entry by more than the rounding above). The reciprocal directions are +-inf for a
 * zero component: the products then are +-inf (outside the slab or inside
 * it) or NaN (on its plane), which the comparisons ignore. */
static inline unsigned bvh_children_enter(const BvhNode *node, const BvhRay *r, BvhLanes limit,
                                          float enter[BVH_WIDTH])
{
    unsigned bits = 0;

    if (r->all) { /* every child in use, entered at 0 */
        memset(enter, 0, BVH_WIDTH * sizeof *enter);
        for (int v = 0; v < BVH_VECTORS; v++)
            bits |= bvh_mask_bits((BvhMask)(bvh_row(node, v * BVH_LANES) <=
                                             bvh_row(node, 3 * BVH_WIDTH + v * BVH_LANES)))
                    << v * BVH_LANES;
        return bits;
    }
#if BVH_FMA
    if (r->fused)
        return bvh_rows_enter(node, r, limit, enter, 1);
#endif
    return bvh_rows_enter(node, r, limit, enter, 0);
}

/* Returns the entry beyond which no box is entered before limit: as in
 * bvh_children_enter(). */
static float bvh_cull(const BvhRay *r, float limit)
{
#if BVH_FMA
    return fmaf(limit, BVH_WIDEN, r->grow);
#else
    return limit * BVH_WIDEN + r->grow;
#endif
}

/* Tests the primitive at slot k for a crossing at tmin < t < tmax;
 * returns 1 with *t. */
static inline int bvh_prim_hit(const Bvh *bvh, uint32_t k, const Ray *ray,
                               real tmin, real tmax, real *t)
{
    uint32_t ref = bvh_prim_ref(bvh, k);
    ShapeKind kind = (ShapeKind)bvh_kind(ref);
    const void *items = bvh->shapes.items[kind];

    /* Spheres and triangles inline: the hottest. */
    if (kind == SHAPE_SPHERE) {
        const Sphere *s = &((const Sphere *)items)[bvh_index(ref)];
        return sphere_hit(s->centre, s->radius, ray, tmin, tmax, t);
    }
    if (kind == SHAPE_TRIANGLE)
        return triangle_intersect(&((const Triangle *)items)[bvh_index(ref)], ray, tmin, tmax, t);
    return shape_intersect(kind, items, bvh_index(ref), ray, tmin, tmax, t);
}

static unsigned bvh_prim_order(const Bvh *bvh, uint32_t ref)
{
    ShapeKind kind = (ShapeKind)bvh_kind(ref);

    return shape_order(kind, bvh->shapes.items[kind], bvh_index(ref));
}

/* Asks for node's cache lines ahead of its visit: a large hierarchy's
 * nodes are mostly not in the caches, and a nearest-hit query reaches a
 * node it stacks only after sorting its siblings and testing the nearer
 * leaves; shadow rays' walks, which stop at their first hit, do not ask.
 * A hierarchy of at most BVH_PREFETCH_NODES nodes stays in a core's
 * caches: no asking there (docs/log.md has the measures). */
enum { BVH_PREFETCH_NODES = 2048 }; /* 448 KiB of nodes */
static inline void bvh_prefetch(const BvhNode *node)
{
    const char *at = (const char *)node;

    for (size_t line = 0; line < sizeof *node; line += 64)
        __builtin_prefetch(at + line);
}

/* A child still to visit: a node or a leaf. */
typedef struct {
    uint32_t link; /* as in BvhNode */
    float enter;   /* where the ray enters its box (t') */
} BvhEntry;

int BVH_QUERY(bvh_nearest)(const Bvh *bvh, const Ray *ray, real tmax, BvhHit *hit)
{
    BvhRay r = bvh_ray(bvh, ray);
    BvhEntry stack[BVH_STACK];
    int top = 0, found = 0;
    uint32_t id = 0;
    real bound = tmax; /* primitives are tested below bound */
    float limit = bvh_limit(&r, tmax), cull = bvh_cull(&r, limit);
    int prefetch = bvh->node_count > BVH_PREFETCH_NODES;
    BvhLanes limits = bvh_splat(limit);

    for (;;) {
        /* The children the ray enters before the best hit so far go on the
         * stack, the nearest on top. A box entered exactly at the best t
         * may still hold an earlier-listed object at that t: the limit
         * keeps it. */
        const BvhNode *node = &bvh->nodes[id];
        float enter[BVH_WIDTH];
        unsigned bits = bvh_children_enter(node, &r, limits, enter);
        int base = top;

        /* One node alone: straight in. */
        if (bits != 0 && (bits & (bits - 1)) == 0 &&
            bvh_link_count(node->link[__builtin_ctz(bits)]) == 0) {
            id = bvh_link_index(node->link[__builtin_ctz(bits)]);
            continue;
        }
        for (unsigned m = bits; m != 0; m &= m - 1) {
            int k = __builtin_ctz(m), j = top++;
            BvhEntry e = {node->link[k], enter[k]};
            if (prefetch && bvh_link_count(e.link) == 0)
                bvh_prefetch(&bvh->nodes[bvh_link_index(e.link)]);
            while (j > base && stack[j - 1].enter < e.enter) {
                stack[j] = stack[j - 1];
                j--;
            }
            stack[j] = e;
        }
        /* The next stacked child the ray can still reach before its hit:
         * leaves are tested on the way, a node is visited. */
        for (;;) {
            BvhEntry e;
            uint32_t first, count;
            if (top == 0) {
                if (found)
                    hit->order = bvh_prim_order(bvh, hit->prim);
                return found;
            }
            e = stack[--top];
            if (e.enter > cull)
                continue;
            first = bvh_link_index(e.link);
            count = bvh_link_count(e.link);
            if (count == 0) {
                id = first;
                break;
            }
            for (uint32_t k = first; k < first + count; k++) {
                uint32_t ref = bvh_prim_ref(bvh, k);
                real t;
                if (!bvh_prim_hit(bvh, k, ray, 0, bound, &t))
                    continue;
                /* t <= hit->t: on a tie the earlier-listed object wins
                 * (their positions are read only then). */
                if (!found || t < hit->t ||
                    bvh_prim_order(bvh, ref) < bvh_prim_order(bvh, hit->prim)) {
                    hit->t = t;
                    hit->prim = ref;
                    found = 1;
                    /* An exact tie with an earlier-listed object must
                     * still be seen: the bound is the next real up. */
                    bound = real_next(t, 1);
                    limit = bvh_limit(&r, t);
                    limits = bvh_splat(limit);
                    cull = bvh_cull(&r, limit);
                }
            }
        }
    }
}

/* A walk over the leaves whose boxes a ray meets, in no particular order:
 * the children still to visit. */
typedef struct {
    uint32_t stack[BVH_STACK]; /* links, as in BvhNode */
    int top;
} BvhWalk;

static void bvh_walk_start(BvhWalk *w)
{
    w->stack[0] = bvh_link(0, 0); /* the root */
    w->top = 1;
}

/* Finds the next leaf whose box the ray r meets at some t' in [0, limit]:
 * returns 1 with its primitives at *first, *count, or 0 when there are no
 * more; start w with bvh_walk_start(). */
static int bvh_next_leaf(const Bvh *bvh, const BvhRay *r, float limit, BvhWalk *w,
                         uint32_t *first, uint32_t *count)
{
    BvhLanes limits = bvh_splat(limit);

    while (w->top > 0) {
        const BvhNode *node;
        float enter[BVH_WIDTH];
        unsigned bits;
        uint32_t link = w->stack[--w->top];

        if (bvh_link_count(link) > 0) {
            *first = bvh_link_index(link);
            *count = bvh_link_count(link);
            return 1;
        }
        node = &bvh->nodes[bvh_link_index(link)];
        bits = bvh_children_enter(node, r, limits, enter);
        for (; bits != 0; bits &= bits - 1)
            w->stack[w->top++] = node->link[__builtin_ctz(bits)];
    }
    return 0;
}

int BVH_QUERY(bvh_occluder)(const Bvh *bvh, const Ray *ray, real tmax, uint32_t *slot)
{
    BvhRay r = bvh_ray(bvh, ray);
    BvhWalk w;
    uint32_t first, count;
    real t;

    bvh_walk_start(&w);
    while (bvh_next_leaf(bvh, &r, bvh_limit(&r, tmax), &w, &first, &count))
        for (uint32_t k = first; k < first + count; k++)
            if (bvh_prim_hit(bvh, k, ray, 0, tmax, &t)) {
                *slot = k;
                return 1;
            }
    return 0;
}

int BVH_QUERY(bvh_crossings)(const Bvh *bvh, const Ray *ray, real tmax, BvhVisit visit,
                             void *ctx)
{
    BvhRay r = bvh_ray(bvh, ray);
    BvhWalk w;
    uint32_t first, count;

    bvh_walk_start(&w);
    while (bvh_next_leaf(bvh, &r, bvh_limit(&r, tmax), &w, &first, &count)) {
        for (uint32_t k = first; k < first + count; k++) {
            uint32_t ref = bvh_prim_ref(bvh, k);
            ShapeKind kind = (ShapeKind)bvh_kind(ref);
            int rc, c = shape_crossings(kind, bvh->shapes.items[kind], bvh_index(ref), ray, 0,
                                        tmax);
            if (c != 0 && (rc = visit(ctx, ref, c)) != 0)
                return rc;
        }
    }
    return 0;
}

#if !defined(BVH_QUERY_AVX2)
/* The base build answers bvh.h's queries with the build bvh->avx2 names;
 * without the AVX2 build, bvh->avx2 stays 0 and its functions are never
 * called. */
#if !defined(RAYTRACE_AVX2)
#define bvh_nearest_avx2 bvh_nearest_base
#define bvh_occluder_avx2 bvh_occluder_base
#define bvh_crossings_avx2 bvh_crossings_base
#endif

int bvh_nearest(const Bvh *bvh, const Ray *ray, real tmax, BvhHit *hit)
{
    return bvh->avx2 ? bvh_nearest_avx2(bvh, ray, tmax, hit) : bvh_nearest_base(bvh, ray, tmax, hit);
}

int bvh_occluder(const Bvh *bvh, const Ray *ray, real tmax, uint32_t *slot)
{
    return bvh->avx2 ? bvh_occluder_avx2(bvh, ray, tmax, slot)
                     : bvh_occluder_base(bvh, ray, tmax, slot);
}

int bvh_slot_occludes(const Bvh *bvh, uint32_t slot, const Ray *ray, real tmax)
{
    real t;

    return slot < bvh->prim_count && bvh_prim_hit(bvh, slot, ray, 0, tmax, &t);
}

int bvh_crossings(const Bvh *bvh, const Ray *ray, real tmax, BvhVisit visit, void *ctx)
{
    return bvh->avx2 ? bvh_crossings_avx2(bvh, ray, tmax, visit, ctx)
                     : bvh_crossings_base(bvh, ray, tmax, visit, ctx);
}
#endif
