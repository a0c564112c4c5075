/* light_buffer.c: a light buffer around a point (see light_buffer.h). */
#include "accel/light_buffer.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "math/real.h"

/*
 * Why the lists hold every sphere a ray can cross. A cell is the set of
 * directions d from the centre whose largest coordinate, by magnitude, is
 * face's axis a with face's sign, and whose u = d_b / |d_a|, v = d_c / |d_a|
 * (b, c the other axes in order) fall in the cell's square of [-1, 1]^2.
 * A sphere of centre s and radius r, at distance D = |s - centre| > r, is
 * seen from the centre within the cap of directions at most
 * asin(r / D) from s - centre. The build lists it in every cell the cap
 * can reach, through bounds that are padded:
 *  - the radius by LB_SLACK M (M: the largest coordinate of the centre and
 *    the spheres), far beyond sphere_hit()'s rounding, a few units of the
 *    last place of |ray origin - sphere centre| <= 4 M;
 *  - the cap's angle, and its directions' coordinates, by LB_PAD, far beyond
 *    the rounding of a query's cell (a few units of the last place);
 *  - a shadow ray's direction is the light less its origin, rounded: the
 *    line the sphere test sees passes within 2 u |origin - centre| of the
 *    centre, so that seen from the centre its points at distance e lie
 *    within 2 u 4 M / e of the ray's direction. A sphere whose nearest
 *    point is nearer than LB_NEAR M, where that angle could pass LB_PAD,
 *    is listed in every cell (it holds the centre or nearly).
 * A list is sorted by each sphere's nearest distance (D - r, rounded down
 * to a float), so that a query may stop at the first sphere wholly beyond
 * what it could still meet, by a margin of 2^-20 (lb_beyond()): the
 * spheres after it are no nearer, but for the float's rounding (2^-24).
 */
#define LB_PAD 0x1p-20
#define LB_SLACK 0x1p-30
#define LB_NEAR 0x1p-26

enum {
    LB_FACES = 6,
    LB_RES_MAX = 1024,  /* cells along a face's edge, at most */
    LB_CELLS_A_SPHERE = 64, /* cells, at most, for each sphere */
    LB_HOLDERS_MAX = 8, /* spheres listed in every cell, at most */
    LB_BUCKETS = 64,    /* of the spheres' apparent sizes, by power of 2 */
    LB_STEPS = 8,       /* a buffer coarser than the resolution that pays
                           best by more than 2^(LB_STEPS / 4) = 4 is not
                           worth building */
    LB_SAMPLE = 1 << 16, /* spheres, at most, whose cells choose among
                            the steps (lb_choose()) */
    LB_SMALL = 2,        /* cells across, at the finest step: a sphere
                            seen smaller may be sampled */
    LB_AHEAD = 4,       /* a shadow query asks memory for the sphere this
                           many entries on... */
    LB_AHEAD_BYTES = 1 << 20 /* ...when the spheres take more than this */
};

/* The axes of face f / 2: the face's own, then u's and v's. */
static const int lb_axes[3][3] = {{0, 1, 2}, {1, 0, 2}, {2, 0, 1}};

/* Returns the index of a cell's row or column from u in [-1, 1], at res
 * cells along an edge. */
static inline int lb_step(int res, double u)
{
    int i = (int)((u + 1) * 0.5 * res);

    return i < 0 ? 0 : i >= res ? res - 1 : i;
}

/* Returns the cell of direction d, or -1 when d is 0 or not finite. */
static inline long lb_cell(const LightBuffer *lb, Vec3 d)
{
    double ax = fabs(d.x), ay = fabs(d.y), az = fabs(d.z);
    double m, u, v;
    int face;

    if (ax >= ay && ax >= az) {
        face = d.x < 0;
        m = ax, u = d.y, v = d.z;
    } else if (ay >= az) {
        face = 2 + (d.y < 0);
        m = ay, u = d.x, v = d.z;
    } else {
        face = 4 + (d.z < 0);
        m = az, u = d.x, v = d.y;
    }
    if (!(m > 0) || !isfinite(m))
        return -1;
    return ((long)face * lb->res + lb_step(lb->res, v / m)) * lb->res + lb_step(lb->res, u / m);
}

/* Where a sphere is seen from the centre. */
typedef struct {
    double dist;     /* from the centre to its centre */
    int holds;       /* listed in every cell */
    double lo[3], hi[3]; /* its cap's directions' coordinates (unit) */
} LbSight;

/* Returns how sphere s is seen from lb's centre, M being the largest
 * coordinate. */
static LbSight lb_sight(const LightBuffer *lb, const Sphere *s, double m)
{
    LbSight sight;
    Vec3 d = vec3_sub(s->centre, lb->centre);
    double dist = vec3_length(d);
    double reach = s->radius + LB_SLACK * m;
    double sb, cb, w[3] = {d.x / dist, d.y / dist, d.z / dist};

    sight.dist = dist;
    sight.holds = !(dist - reach > LB_NEAR * m + LB_PAD * dist);
    if (sight.holds)
        return sight;
    /* The cap's half-angle b, widened by LB_PAD (a sine grows no faster
     * than its angle): the range of coordinate i over it is
     * [cos(th + b), cos(th - b)], th = acos(w[i]), clamped where th - b < 0
     * or th + b > pi. */
    sb = reach / dist + LB_PAD;
    sb = sb < 1 ? sb : 1;
    cb = sqrt(1 - sb * sb);
    for (int i = 0; i < 3; i++) {
        double s2 = 1 - w[i] * w[i]; /* fmax(0, s2) without a library call */
        double st = sqrt(s2 > 0 ? s2 : 0);
        sight.lo[i] = (-w[i] >= cb ? -1 : w[i] * cb - st * sb) - LB_PAD;
        sight.hi[i] = (w[i] >= cb ? 1 : w[i] * cb + st * sb) + LB_PAD;
    }
    return sight;
}

/* The part of a face a sphere's cap may reach: u in [u0, u1], v in
 * [v0, v1] (within [-1, 1]). */
typedef struct {
    int face;
    double u0, u1, v0, v1;
} LbSpan;

/* A rectangle of a face's cells: rows v0..v1, columns u0..u1. */
typedef struct {
    int face, u0, u1, v0, v1;
} LbRect;

/* Returns x / a's bounds for x in [lo, hi], a in [amin, amax] (amin > 0),
 * clamped to [-1, 1], in *u0 and *u1. */
static void lb_range(double lo, double hi, double amin, double amax, double *u0, double *u1)
{
    double a = lo / (lo < 0 ? amin : amax), b = hi / (hi > 0 ? amin : amax);

    *u0 = a < -1 ? -1 : a > 1 ? 1 : a;
    *u1 = b < -1 ? -1 : b > 1 ? 1 : b;
}

/* Stores in span the parts of the faces sight's cap may reach; returns
 * how many (0 to 6). */
static int lb_spans(const LbSight *sight, LbSpan span[LB_FACES])
{
    const double least = 1 / sqrt(3.0) - LB_PAD; /* a face's axis' share */
    int n = 0;

    for (int face = 0; face < LB_FACES; face++) {
        const int *ax = lb_axes[face / 2];
        double amin, amax;
        if (face % 2 == 0) {
            amin = sight->lo[ax[0]];
            amax = sight->hi[ax[0]];
        } else {
            amin = -sight->hi[ax[0]];
            amax = -sight->lo[ax[0]];
        }
        if (amax < least)
            continue;
        amin = amin > least ? amin : least;
        span[n].face = face;
        lb_range(sight->lo[ax[1]], sight->hi[ax[1]], amin, amax, &span[n].u0, &span[n].u1);
        lb_range(sight->lo[ax[2]], sight->hi[ax[2]], amin, amax, &span[n].v0, &span[n].v1);
        n++;
    }
    return n;
}

/* Returns span's cells at res cells along an edge. */
static inline LbRect lb_rect(int res, const LbSpan *span)
{
    LbRect r = {span->face, lb_step(res, span->u0), lb_step(res, span->u1),
                lb_step(res, span->v0), lb_step(res, span->v1)};

    return r;
}

/* Returns the cells of the rectangles of sight's spans at res. */
static size_t lb_cells_at(int res, const LbSpan *span, int n)
{
    size_t cells = 0;

    for (int i = 0; i < n; i++) {
        LbRect r = lb_rect(res, &span[i]);
        cells += (size_t)(r.u1 - r.u0 + 1) * (size_t)(r.v1 - r.v0 + 1);
    }
    return cells;
}

/* Returns the largest coordinate's magnitude of the centre and spheres. */
static double lb_extent(Vec3 centre, const Sphere *spheres, size_t count, int threads)
{
    double m = fmax(fabs(centre.x), fmax(fabs(centre.y), fabs(centre.z)));

    (void)threads;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) reduction(max : m)
#endif
    for (size_t k = 0; k < count; k++) {
        Vec3 c = spheres[k].centre;
        double e = fmax(fabs(c.x), fmax(fabs(c.y), fabs(c.z))) + spheres[k].radius;
        m = e > m ? e : m;
    }
    return m;
}

/* Returns the cells along a face's edge that pay best (measured on fields
 * of 10^3 to 10^6 spheres): a cell about half as wide as the cap of a
 * sphere of median apparent size (its radius over its distance), as a
 * histogram by powers of two finds it. */
static int lb_resolution(const LightBuffer *lb, size_t count, size_t rays, int threads)
{
    size_t bucket[LB_BUCKETS] = {0}, seen = 0, half;
    int b = 0;
    double res;

    (void)threads;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : bucket[:LB_BUCKETS], seen)
#endif
    for (size_t k = 0; k < count; k++) {
        double dist = vec3_length(vec3_sub(lb->spheres[k].centre, lb->centre));
        double size = lb->spheres[k].radius / dist;
        int e;
        if (!(size < 1))
            continue;
        (void)frexp(size, &e);
        e = -e;
        bucket[e < 0 ? 0 : e >= LB_BUCKETS ? LB_BUCKETS - 1 : e]++;
        seen++;
    }
    if (seen == 0)
        return 1;
    for (half = 0; b < LB_BUCKETS && half + bucket[b] < (seen + 1) / 2; b++)
        half += bucket[b];
    /* Sizes in bucket b are in [2^-(b+1), 2^-b): a cap about 1.4 2^-b
     * across; a cell near a face's centre spans about 2 / res radians.
     * Nor do more cells than LB_CELLS_A_SPHERE a sphere, or than rays. */
    res = ldexp(1.0, b) * 3;
    res = fmin(res, sqrt((double)LB_CELLS_A_SPHERE * (double)count / LB_FACES));
    res = fmin(res, sqrt((double)rays / LB_FACES));
    return res < 1 ? 1 : res > LB_RES_MAX ? LB_RES_MAX : (int)res;
}

/* Says whether sphere a comes before sphere b in a list: nearer (by
 * near[], the nearest distances rounded down to floats), or as near and
 * of lower index (a total order, so the lists do not depend on threads). */
static inline int lb_before(const float *near, uint32_t a, uint32_t b)
{
    return near[a] < near[b] || (near[a] == near[b] && a < b);
}

/* Returns sphere k's place in lb_before()'s order as one number: its
 * near[] value's bits made to order as the floats do (0 and -0 alike),
 * then k. */
static inline uint64_t lb_key(const float *near, uint32_t k)
{
    float f = near[k] == 0 ? 0.0f : near[k];
    uint32_t bits;

    memcpy(&bits, &f, sizeof bits);
    bits = bits >> 31 ? ~bits : bits | 0x80000000u;
    return (uint64_t)bits << 32 | k;
}

enum { LB_SORT_LOCAL = 256 }; /* longer lists are sorted in place */

/* Sorts the n spheres of list by lb_before() (Shell's sort, Ciura's gaps:
 * lists are short, but a cell of a dense field may hold thousands). A
 * short list is sorted on its keys (lb_key()), each sphere's read once:
 * near[] is read at random. */
static void lb_sort(uint32_t *list, size_t n, const float *near)
{
    static const size_t gaps[] = {701, 301, 132, 57, 23, 10, 4, 1};

    if (n <= LB_SORT_LOCAL) {
        uint64_t key[LB_SORT_LOCAL];
        for (size_t i = 0; i < n; i++) {
            uint64_t x = lb_key(near, list[i]);
            size_t j = i;
            for (; j > 0 && x < key[j - 1]; j--)
                key[j] = key[j - 1];
            key[j] = x;
        }
        for (size_t i = 0; i < n; i++)
            list[i] = (uint32_t)key[i];
        return;
    }
    for (size_t g = 0; g < sizeof gaps / sizeof gaps[0]; g++)
        for (size_t i = gaps[g]; i < n; i++) {
            uint32_t x = list[i];
            size_t j = i;
            for (; j >= gaps[g] && lb_before(near, x, list[j - gaps[g]]); j -= gaps[g])
                list[j] = list[j - gaps[g]];
            list[j] = x;
        }
}

/* Returns near as a float no larger. */
static float lb_float_below(double near)
{
    float f = (float)near;

    return (double)f > near ? nextafterf(f, -INFINITY) : f;
}

/* Returns the index of cell (u, v) of rect. */
static inline size_t lb_rect_cell(const LightBuffer *lb, const LbRect *rect, int u, int v)
{
    return ((size_t)rect->face * lb->res + v) * lb->res + u;
}

/* Counts at lb->res the spheres each cell lists into first[c + 1] (first
 * zeroed, of 6 res^2 + 1), then sums them into lists' ends; returns the
 * entries in all, or SIZE_MAX when more than LB_HOLDERS_MAX spheres hold
 * the centre or more than 2^32 entries would be listed. */
static size_t lb_count(LightBuffer *lb, size_t count, double m, int threads)
{
    size_t cells = (size_t)LB_FACES * lb->res * lb->res, total = 0;
    long holders = 0;

    (void)threads;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : holders)
#endif
    for (size_t k = 0; k < count; k++) {
        LbSight sight = lb_sight(lb, &lb->spheres[k], m);
        if (sight.holds) {
            holders++;
            continue;
        }
        LbSpan span[LB_FACES];
        int n = lb_spans(&sight, span);
        for (int i = 0; i < n; i++) {
            LbRect r = lb_rect(lb->res, &span[i]);
            for (int v = r.v0; v <= r.v1; v++)
                for (int u = r.u0; u <= r.u1; u++) {
                    size_t c = lb_rect_cell(lb, &r, u, v);
#ifdef _OPENMP
#pragma omp atomic
#endif
                    lb->first[c + 1]++;
                }
        }
    }
    if (holders > LB_HOLDERS_MAX)
        return SIZE_MAX;
    for (size_t c = 0; c < cells; c++) {
        total += lb->first[c + 1] + (size_t)holders;
        if (total > UINT32_MAX)
            return SIZE_MAX;
        lb->first[c + 1] = (uint32_t)total;
    }
    return total;
}

/* Returns the bytes of a buffer of res cells along an edge and entries. */
static size_t lb_bytes(int res, size_t entries)
{
    return ((size_t)LB_FACES * res * res + 1) * sizeof(uint32_t) + entries * sizeof(uint32_t);
}

/* Stores in r[j] the resolutions from res down to res / 4, in LB_STEPS
 * steps of a fourth root of 2. */
static void lb_steps(int res, int r[LB_STEPS + 1])
{
    /* 2^(-k/4), correctly rounded: res 2^(-j/4) with no libm pow(), whose
     * last bit may differ between C libraries. */
    static const double quarter[4] = {1, 0x1.ae89f995ad3adp-1, 0x1.6a09e667f3bcdp-1,
                                      0x1.306fe0a31b715p-1};

    for (int j = 0; j <= LB_STEPS; j++) {
        r[j] = (int)ldexp(res * quarter[j % 4], -(j / 4));
        r[j] = r[j] > 0 ? r[j] : 1;
    }
}

/* Returns the first of the steps r whose buffer takes at most max_bytes,
 * or LB_STEPS + 1 when none does. The cells are counted exactly for
 * fields of up to LB_SAMPLE spheres; a larger field's spheres seen
 * smaller than LB_SMALL cells of the finest step are counted one in k, k
 * times over (the rest, which may span many cells, each once). */
static int lb_choose(const LightBuffer *lb, const int r[LB_STEPS + 1], size_t count, double m,
                     size_t max_bytes, int threads)
{
    double entries[LB_STEPS + 1] = {0}, holders = 0;
    size_t stride = (count + LB_SAMPLE - 1) / LB_SAMPLE;
    double small = LB_SMALL / (double)r[0];

    (void)threads;
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static) \
    reduction(+ : entries[:LB_STEPS + 1], holders)
#endif
    for (size_t k = 0; k < count; k++) {
        const Sphere *s = &lb->spheres[k];
        double weight = 1;
        LbSight sight;
        LbSpan span[LB_FACES];
        int n;
        if (stride > 1 && s->radius < small * vec3_length(vec3_sub(s->centre, lb->centre))) {
            if (k % stride != 0)
                continue;
            weight = (double)stride;
        }
        sight = lb_sight(lb, s, m);
        if (sight.holds) {
            holders += weight;
            continue;
        }
        n = lb_spans(&sight, span);
        for (int j = 0; j <= LB_STEPS; j++)
            entries[j] += weight * (double)lb_cells_at(r[j], span, n);
    }
    for (int j = 0; j <= LB_STEPS; j++)
        if (lb_bytes(r[j], (size_t)(entries[j] + holders * LB_FACES * r[j] * r[j])) <= max_bytes)
            return j;
    return LB_STEPS + 1;
}

/* Sets lb's resolution, the first of steps that fits max_bytes, and
 * counts its lists into lb->first, their entries in all into *total: the
 * choice made on a sample (lb_choose()), the count checks it, a step
 * finer than fits passed over for the next. Returns 0, 1 when no step
 * fits or the count refuses (nothing held), or -1 when memory runs out. */
static int lb_size(LightBuffer *lb, const int steps[LB_STEPS + 1], size_t count, double m,
                   size_t max_bytes, int threads, size_t *total)
{
    for (int j = lb_choose(lb, steps, count, m, max_bytes, threads); j <= LB_STEPS; j++) {
        lb->res = steps[j];
        lb->first = calloc((size_t)LB_FACES * lb->res * lb->res + 1, sizeof *lb->first);
        if (!lb->first)
            return -1;
        *total = lb_count(lb, count, m, threads);
        if (*total == SIZE_MAX)
            break;
        if (lb_bytes(lb->res, *total) <= max_bytes)
            return 0;
        free(lb->first);
        lb->first = NULL;
    }
    light_buffer_free(lb);
    lb->res = 0;
    return 1;
}

int light_buffer_build(LightBuffer *lb, Vec3 centre, const Sphere *spheres, size_t count,
                       size_t rays, size_t max_bytes, int threads)
{
    size_t cells, total, holders = 0;
    uint32_t holder[LB_HOLDERS_MAX];
    int steps[LB_STEPS + 1], rc;
    uint32_t *cursor;
    float *near;
    double m;

    memset(lb, 0, sizeof *lb);
    lb->centre = centre;
    lb->spheres = spheres;
    if (count == 0 || count >= UINT32_MAX)
        return 1;
    m = lb_extent(centre, spheres, count, threads);
    /* The lists' order keeps distances as floats, to 2^-24 of themselves
     * or of the slack (LB_SLACK m): the scene must lie well within floats'
     * range (the readers bring tiny scenes near 1: scale.h). */
    if (!(m >= 0x1p-60 && m <= 0x1p100))
        return 1;
    lb_steps(lb_resolution(lb, count, rays, threads), steps);
    rc = lb_size(lb, steps, count, m, max_bytes, threads, &total);
    if (rc != 0)
        return rc;
    cells = (size_t)LB_FACES * lb->res * lb->res;
    lb->entry_count = total;
    lb->entries = malloc(total * sizeof *lb->entries + 1);
    cursor = malloc(cells * sizeof *cursor + 1);
    near = malloc(count * sizeof *near);
    if (!lb->entries || !cursor || !near) {
        free(cursor);
        free(near);
        light_buffer_free(lb);
        return -1;
    }
    memcpy(cursor, lb->first, cells * sizeof *cursor);
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(static)
#endif
    for (size_t k = 0; k < count; k++) {
        LbSight sight = lb_sight(lb, &spheres[k], m);
        LbSpan span[LB_FACES];
        int n;
        near[k] = lb_float_below(sight.dist - spheres[k].radius);
        if (sight.holds) {
            size_t h;
#ifdef _OPENMP
#pragma omp atomic capture
#endif
            h = holders++;
            holder[h < LB_HOLDERS_MAX ? h : 0] = (uint32_t)k;
            continue;
        }
        n = lb_spans(&sight, span);
        for (int i = 0; i < n; i++) {
            LbRect r = lb_rect(lb->res, &span[i]);
            for (int v = r.v0; v <= r.v1; v++)
                for (int u = r.u0; u <= r.u1; u++) {
                    size_t c = lb_rect_cell(lb, &r, u, v);
                    uint32_t at;
#ifdef _OPENMP
#pragma omp atomic capture
#endif
                    at = cursor[c]++;
                    lb->entries[at] = (uint32_t)k;
                }
        }
    }
    /* The few spheres that hold the centre, in every cell. */
    for (size_t h = 0; h < holders; h++) {
        for (size_t c = 0; c < cells; c++)
            lb->entries[cursor[c]++] = holder[h];
    }
    free(cursor);
#ifdef _OPENMP
#pragma omp parallel for num_threads(threads) schedule(dynamic, 256)
#endif
    for (size_t c = 0; c < cells; c++)
        lb_sort(lb->entries + lb->first[c], lb->first[c + 1] - lb->first[c], near);
    free(near);
    lb->slack = LB_SLACK * m;
    lb->ahead = count * sizeof *spheres > LB_AHEAD_BYTES;
    return 0;
}

void light_buffer_free(LightBuffer *lb)
{
    free(lb->first);
    free(lb->entries);
    lb->first = NULL;
    lb->entries = NULL;
    lb->entry_count = 0;
}

size_t light_buffer_memory(const LightBuffer *lb)
{
    return lb->first ? lb_bytes(lb->res, lb->entry_count) : 0;
}

/* Says whether sphere s lies wholly beyond distance limit (>= 0) of the
 * centre, with a margin: its nearest distance passes limit by 2^-21 of
 * (limit + radius), so that every later sphere of a list (whose rounded
 * nearest distances are no smaller) lies beyond limit too. */
static inline int lb_beyond(const LightBuffer *lb, const Sphere *s, double limit)
{
    Vec3 d = vec3_sub(s->centre, lb->centre);
    double q = (limit + s->radius) * (1 + 0x1p-20);

    return vec3_dot(d, d) > q * q;
}

int light_buffer_occluded(const LightBuffer *lb, const Ray *ray, real tmax, uint32_t *cache)
{
    Vec3 d = vec3_sub(ray->origin, lb->centre);
    long c = lb_cell(lb, d);
    double limit;
    real t;

    if (c < 0)
        return -1;
    if (*cache != UINT32_MAX &&
        sphere_hit(lb->spheres[*cache].centre, lb->spheres[*cache].radius, ray, 0, tmax, &t))
        return 1;
    limit = vec3_length(d) * (1 + LB_PAD) + lb->slack;
    for (uint32_t i = lb->first[c], end = lb->first[c + 1]; i < end; i++) {
        const Sphere *s = &lb->spheres[lb->entries[i]];
#if defined(__GNUC__)
        /* A lit point tests every sphere nearer than it: theirs are read
         * at random, and asked for ahead the waits overlap (both of the
         * cache lines its centre and radius may straddle). */
        if (lb->ahead && i + LB_AHEAD < end) {
            const char *next = (const char *)&lb->spheres[lb->entries[i + LB_AHEAD]];
            __builtin_prefetch(next);
            __builtin_prefetch(next + sizeof s->centre + sizeof s->radius - 1);
        }
#endif
        if (lb_beyond(lb, s, limit))
            break;
        if (sphere_hit(s->centre, s->radius, ray, 0, tmax, &t)) {
            *cache = lb->entries[i];
            return 1;
        }
    }
    return 0;
}

int light_buffer_nearest(const LightBuffer *lb, const Ray *ray, real tmax, real *t,
                         size_t *sphere)
{
    long c = lb_cell(lb, ray->dir);
    double len = vec3_length(ray->dir) * (1 + LB_PAD);
    real best = tmax;
    unsigned order = 0;
    int found = 0;

    if (c < 0)
        return -1;
    for (uint32_t i = lb->first[c], end = lb->first[c + 1]; i < end; i++) {
        const Sphere *s = &lb->spheres[lb->entries[i]];
        real th;
        if (lb_beyond(lb, s, best * len + lb->slack))
            break;
        /* An exact tie with a sphere of less order must be seen: the bound
         * is the next real above the best t. */
        if (sphere_hit(s->centre, s->radius, ray, 0, found ? real_next(best, 1) : tmax, &th) &&
            (!found || th < best || s->order < order)) {
            best = th;
            order = s->order;
            *sphere = lb->entries[i];
            found = 1;
        }
    }
    *t = best;
    return found;
}
