/* polygon.c: polygons cut into triangles (see polygon.h). */
#include "geometry/polygon.h"

#include <math.h>
#include <stdint.h>

/* A corner in the polygon's plane. */
typedef struct {
    double u, v;
} PolygonPoint;

/* The ring of corners left to cut: each one's neighbours. */
typedef struct {
    PolygonPoint *q;
    unsigned *prev, *next;
} PolygonRing;

/* Corners whose room is on the stack; larger polygons use the caller's. */
enum { POLYGON_SMALL = 8 };

size_t polygon_work_size(size_t n)
{
    return n * (sizeof(PolygonPoint) + 2 * sizeof(unsigned));
}

/* Returns twice the signed area of the triangle a b c in the plane:
 * positive when it turns anticlockwise. */
static double polygon_cross(PolygonPoint a, PolygonPoint b, PolygonPoint c)
{
    return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
}

/* Projects the n corners p on the plane of the two axes Newell's normal
 * leans on least, turned to run anticlockwise, into q; returns 0, or -1
 * when the normal is zero (all corners on a line, or a loop with no
 * area). Coordinates are taken from the first corner, for precision. */
static int polygon_project(const Vec3 *p, size_t n, PolygonPoint *q)
{
    double nx = 0, ny = 0, nz = 0, ax, ay, az;
    int axis, flip;

    for (size_t i = 0; i < n; i++) {
        Vec3 a = vec3_sub(p[i], p[0]), b = vec3_sub(p[i + 1 < n ? i + 1 : 0], p[0]);
        nx += ((double)a.y - (double)b.y) * ((double)a.z + (double)b.z);
        ny += ((double)a.z - (double)b.z) * ((double)a.x + (double)b.x);
        nz += ((double)a.x - (double)b.x) * ((double)a.y + (double)b.y);
    }
    ax = fabs(nx), ay = fabs(ny), az = fabs(nz);
    if (!(ax > 0 || ay > 0 || az > 0))
        return -1;
    axis = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
    flip = (axis == 0 ? nx : axis == 1 ? ny : nz) < 0;
    for (size_t i = 0; i < n; i++) {
        Vec3 d = vec3_sub(p[i], p[0]);
        /* (y, z), (z, x) or (x, y): anticlockwise about +x, +y or +z. */
        double u = axis == 0 ? (double)d.y : axis == 1 ? (double)d.z : (double)d.x;
        double v = axis == 0 ? (double)d.z : axis == 1 ? (double)d.x : (double)d.y;
        q[i].u = flip ? v : u;
        q[i].v = flip ? u : v;
    }
    return 0;
}

/* Says whether the edge direction (u, v) points into the upper half of
 * the plane: angle in [0, pi). */
static int polygon_upper(double u, double v)
{
    return v > 0 || (v == 0 && u > 0);
}

/* Takes the turn from edge direction (pu, pv) to (eu, ev): counts in
 * *laps the times the direction passes angle 0, up on a turn to the left
 * (or straight back, taken as a half turn to the left) and down on one to
 * the right (a turn of less than a half turn passes 0 exactly when it
 * goes between the plane's halves that way), and clears *convex when it
 * turns right, beyond rounding, or straight back. */
static void polygon_turn(double pu, double pv, double eu, double ev, long *laps, int *convex)
{
    double c = pu * ev - pv * eu, d = pu * eu + pv * ev;
    double slack = 1e-9 * sqrt(pu * pu + pv * pv) * sqrt(eu * eu + ev * ev);

    if (c > 0 || (c == 0 && d < 0))
        *laps += !polygon_upper(pu, pv) && polygon_upper(eu, ev);
    else if (c < 0)
        *laps -= polygon_upper(pu, pv) && !polygon_upper(eu, ev);
    if (c < -slack || (!(c > slack) && d < 0))
        *convex = 0;
}

/* Returns how many times the n projected corners q go round (the turning
 * of their edges' direction, in whole turns: 1 for a simple polygon run
 * anticlockwise), and sets *convex when every turn is to the left or
 * straight on and they go round once. Repeated corners are passed over. */
static long polygon_laps(const PolygonPoint *q, size_t n, int *convex)
{
    double fu = 0, fv = 0, pu = 0, pv = 0;
    size_t edges = 0;
    long laps = 0;

    *convex = 1;
    for (size_t i = 0; i < n; i++) {
        size_t b = i + 1 < n ? i + 1 : 0;
        double eu = q[b].u - q[i].u, ev = q[b].v - q[i].v;
        if (eu == 0 && ev == 0)
            continue;
        if (edges++ == 0)
            fu = eu, fv = ev;
        else
            polygon_turn(pu, pv, eu, ev, &laps, convex);
        pu = eu, pv = ev;
    }
    if (edges < 3) {
        *convex = 0;
        return 0;
    }
    polygon_turn(pu, pv, fu, fv, &laps, convex);
    *convex = *convex && laps == 1;
    return laps;
}

/* Says whether points a and b are the same point. */
static int polygon_same(PolygonPoint a, PolygonPoint b)
{
    return a.u == b.u && a.v == b.v;
}

/* Says whether corner b of ring r, between a and c, is an ear: a strict
 * left turn whose triangle holds no other reflex or straight corner of
 * the ring, on its edges or inside (a corner at one of its corners'
 * places, as a ring's joined loops have, is passed over). */
static int polygon_ear(const PolygonRing *r, unsigned a, unsigned b, unsigned c)
{
    PolygonPoint pa = r->q[a], pb = r->q[b], pc = r->q[c];

    if (!(polygon_cross(pa, pb, pc) > 0))
        return 0;
    for (unsigned p = r->next[c]; p != a; p = r->next[p]) {
        PolygonPoint pp = r->q[p];
        if (polygon_cross(r->q[r->prev[p]], pp, r->q[r->next[p]]) > 0)
            continue; /* a convex corner cannot be inside an ear */
        if (polygon_same(pp, pa) || polygon_same(pp, pb) || polygon_same(pp, pc))
            continue;
        if (polygon_cross(pa, pb, pp) >= 0 && polygon_cross(pb, pc, pp) >= 0 &&
            polygon_cross(pc, pa, pp) >= 0)
            return 0;
    }
    return 1;
}

/* Returns the corner of ring r (from `from`, m of them) to cut when none
 * is an ear: one on a straight line first (its triangle has no area and
 * changes nothing), else the one turning most to the left; *bad set when
 * it is the latter. */
static unsigned polygon_fallback(const PolygonRing *r, unsigned from, size_t m, int *bad)
{
    unsigned best = from, p = from;
    double most = -INFINITY;

    for (size_t k = 0; k < m; k++, p = r->next[p]) {
        double c = polygon_cross(r->q[r->prev[p]], r->q[p], r->q[r->next[p]]);
        if (c == 0)
            return p;
        if (c > most)
            most = c, best = p;
    }
    *bad = 1;
    return best;
}

/* Cuts the ring of n projected corners q by ear clipping into tri;
 * returns 1 when it had to cut a corner that was not an ear. */
static int polygon_clip(PolygonPoint *q, size_t n, unsigned *prev, unsigned *next,
                        unsigned (*tri)[3])
{
    PolygonRing r = {q, prev, next};
    size_t m = n, out = 0, stall = 0;
    unsigned i = 0;
    int bad = 0;

    for (size_t k = 0; k < n; k++) {
        prev[k] = (unsigned)(k ? k - 1 : n - 1);
        next[k] = (unsigned)(k + 1 < n ? k + 1 : 0);
    }
    while (m > 3) {
        unsigned a = prev[i], c = next[i];
        if (!polygon_ear(&r, a, i, c)) {
            i = c;
            if (++stall < m)
                continue;
            i = polygon_fallback(&r, i, m, &bad);
            a = prev[i], c = next[i];
        }
        tri[out][0] = a, tri[out][1] = i, tri[out][2] = c;
        out++;
        next[a] = c, prev[c] = a;
        m--;
        stall = 0;
        i = a; /* the corner before may have become an ear */
    }
    tri[out][0] = prev[i], tri[out][1] = i, tri[out][2] = next[i];
    return bad;
}

/* Writes the fan of n corners from the first into tri. */
static void polygon_fan(size_t n, unsigned (*tri)[3])
{
    for (size_t k = 1; k + 1 < n; k++) {
        tri[k - 1][0] = 0;
        tri[k - 1][1] = (unsigned)k;
        tri[k - 1][2] = (unsigned)(k + 1);
    }
}

PolygonCut polygon_cut(const Vec3 *p, size_t n, unsigned (*tri)[3], void *work)
{
    PolygonPoint small_q[POLYGON_SMALL], *q = small_q;
    unsigned small_links[2 * POLYGON_SMALL], *links = small_links;
    int convex = 0, plane;
    long laps = 0;

    if (n == 3 || n > POLYGON_CLIP_MAX) {
        polygon_fan(n, tri);
        return n == 3 ? POLYGON_FAN : POLYGON_IRREGULAR;
    }
    if (n > POLYGON_SMALL) {
        q = work;
        links = (unsigned *)(q + n);
    }
    plane = polygon_project(p, n, q) == 0;
    if (plane)
        laps = polygon_laps(q, n, &convex);
    if (convex) {
        polygon_fan(n, tri);
        return POLYGON_FAN;
    }
    if (!plane) {
        polygon_fan(n, tri); /* all on a line */
        return POLYGON_IRREGULAR;
    }
    /* A loop that does not go round once is not simple: clipped all the
     * same, as well as the rule allows. */
    return polygon_clip(q, n, links, links + n, tri) || laps != 1 ? POLYGON_IRREGULAR
                                                                  : POLYGON_EARS;
}
