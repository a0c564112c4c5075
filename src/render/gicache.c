/* gicache.c: the irradiance cache's arithmetic: a record's gathering, its
 * gradients, its error and weight at a point (see gicache.h; its store of
 * records and their grid is gicache_grid.c). */
#include "render/gicache.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/hash.h"
#include "math/angle.h"

/* A record is in front of a point when their offset along the mean of
 * their normals is below -GICACHE_FRONT R (Ward's test). */
#define GICACHE_FRONT 0.05

void gicache_strata(int rays, int *m, int *n)
{
    int mm = (int)lround(sqrt(rays / ANGLE_PI));

    if (mm < 1)
        mm = 1;
    *m = mm;
    *n = (rays + mm / 2) / mm > 0 ? (rays + mm / 2) / mm : 1;
}

/* Returns a uniform number in [0, 1) from the 32 bits of h at shift. */
static double gicache_unit(uint64_t h, int shift)
{
    return (double)((h >> shift) & 0xffffffffu) * (1.0 / 4294967296.0);
}

/* Adds u times the channels of sum into the gradient vectors g[3]. */
static void gicache_add_sums(Vec3 g[3], Vec3 u, const double sum[3])
{
    for (int c = 0; c < 3; c++)
        g[c] = vec3_add(g[c], vec3_scale(u, (real)sum[c]));
}

/* Returns the translational gradient of the mean over the m x n strata of
 * colours lc met at distances whose reciprocals are q (Ward and
 * Heckbert's, for strata of equal projected solid angle): across each
 * boundary of constant theta and of constant phi, the change of colour
 * times how fast the boundary sweeps projected solid angle as the point
 * moves, over the nearer distance. sweep holds 2 m doubles of room. */
static void gicache_translation(Vec3 t1, Vec3 t2, int m, int n, const Colour *lc,
                                const double *q, double *sweep, Vec3 g[3])
{
    /* Band j's weights: sweep[j] across its boundary of constant theta
     * with band j - 1, across[j] across its boundaries of constant phi. */
    double *across = sweep + m;

    for (int j = 0; j < m; j++) {
        double s2 = (double)j / m;
        sweep[j] = 2 * ANGLE_PI / n * sqrt(s2) * (1 - s2);
        across[j] = sqrt((double)(j + 1) / m) - sqrt((double)j / m);
    }
    for (int c = 0; c < 3; c++)
        g[c] = vec3(0, 0, 0);
    for (int k = 0; k < n; k++) {
        double pc = 2 * ANGLE_PI * (k + 0.5) / n, pm = 2 * ANGLE_PI * k / n;
        Vec3 u = vec3_add(vec3_scale(t1, (real)cos(pc)), vec3_scale(t2, (real)sin(pc)));
        Vec3 v = vec3_add(vec3_scale(t1, (real)-sin(pm)), vec3_scale(t2, (real)cos(pm)));
        int kp = (k + n - 1) % n;
        double su[3] = {0, 0, 0}, sv[3] = {0, 0, 0};

        for (int j = 1; j < m; j++) {
            double w = sweep[j] * fmax(q[j * n + k], q[(j - 1) * n + k]);
            Colour d = colour_sub(lc[j * n + k], lc[(j - 1) * n + k]);
            su[0] += w * d.r;
            su[1] += w * d.g;
            su[2] += w * d.b;
        }
        for (int j = 0; n > 1 && j < m; j++) {
            double w = across[j] * fmax(q[j * n + k], q[j * n + kp]);
            Colour d = colour_sub(lc[j * n + k], lc[j * n + kp]);
            sv[0] += w * d.r;
            sv[1] += w * d.g;
            sv[2] += w * d.b;
        }
        gicache_add_sums(g, u, su);
        gicache_add_sums(g, v, sv);
    }
    for (int c = 0; c < 3; c++)
        g[c] = vec3_scale(g[c], (real)(1 / ANGLE_PI)); /* of E, to of E / pi */
}

/* Stores in s[j], for each band j of m, the integral of sin^2 theta over
 * its theta (the band's share of a turn's change of cos theta). */
static void gicache_band_turns(int m, double *s)
{
    for (int j = 0; j < m; j++) {
        double lo = asin(sqrt((double)j / m)), hi = asin(sqrt((double)(j + 1) / m));

        s[j] = (hi - lo) / 2 - (sin(2 * hi) - sin(2 * lo)) / 4;
    }
}

/* Stores in dc[k] and ds[k], for each wedge k of n, the integral over its
 * phi of the unit vector turned a right angle from phi, (-sin phi,
 * cos phi): its parts along the frame's first and second tangents. */
static void gicache_wedge_turns(int n, double *dc, double *ds)
{
    for (int k = 0; k < n; k++) {
        double p0 = 2 * ANGLE_PI * k / n, p1 = 2 * ANGLE_PI * (k + 1) / n;

        dc[k] = cos(p1) - cos(p0);
        ds[k] = sin(p1) - sin(p0);
    }
}

/* Stores in *c and *s the cosine and sine of phi0 + d, from those of
 * phi0 (c0, s0) and d's series (|d| <= pi / 8: within 3e-14 of libm's
 * cos(phi0 + d) and sin(phi0 + d), at a fraction of their cost). */
static void gicache_turn_by(double c0, double s0, double d, double *c, double *s)
{
    static const double sn[5] = {-1.0 / 6, 1.0 / 120, -1.0 / 5040, 1.0 / 362880,
                                 -1.0 / 39916800};
    static const double cn[5] = {-1.0 / 2, 1.0 / 24, -1.0 / 720, 1.0 / 40320, -1.0 / 3628800};
    double d2 = d * d;
    double sd = d * (1 + d2 * (sn[0] + d2 * (sn[1] + d2 * (sn[2] + d2 * (sn[3] + d2 * sn[4])))));
    double cd = 1 + d2 * (cn[0] + d2 * (cn[1] + d2 * (cn[2] + d2 * (cn[3] + d2 * cn[4]))));

    *c = c0 * cd - s0 * sd;
    *s = s0 * cd + c0 * sd;
}

/* Returns the eighth of the tangent plane (GICACHE_SECTORS) the direction
 * a t1 + b t2 lies in: counterclockwise from t1, by comparisons alone. */
static int gicache_sector(double a, double b)
{
    if (b >= 0)
        return a >= 0 ? (a >= b ? 0 : 1) : (-a <= b ? 2 : 3);
    return a < 0 ? (-a >= -b ? 4 : 5) : (a <= -b ? 6 : 7);
}

int gicache_gather(Vec3 normal, int m, int n, uint64_t key, double near, GiSample sample,
                   void *ctx, GiValue *v, double *harmonic, double *open,
                   float sees[GICACHE_SECTORS])
{
    size_t cells = (size_t)m * (size_t)n;
    Colour *lc = malloc(cells * sizeof *lc);
    double *r = malloc(cells * sizeof *r), inverse = 0, escaped = 0;
    double *band = malloc((3 * (size_t)m + 4 * (size_t)n) * sizeof *band);
    double *dc = band + m, *ds = dc + n, *c0 = ds + n, *s0 = c0 + n, *sweep = s0 + n;
    double turn_c[3] = {0, 0, 0}, turn_s[3] = {0, 0, 0}, wedge = 2 * ANGLE_PI / n;
    Vec3 t1 = vec3_from_frame(normal, 1, 0, 0), t2 = vec3_from_frame(normal, 0, 1, 0);
    Colour sum = colour(0, 0, 0);

    if (!lc || !r || !band) {
        free(lc);
        free(r);
        free(band);
        return -1;
    }
    memset(v, 0, sizeof *v);
    memset(sees, 0, GICACHE_SECTORS * sizeof *sees);
    gicache_band_turns(m, band);
    gicache_wedge_turns(n, dc, ds);
    for (int k = 0; k < n; k++) {
        c0[k] = cos(wedge * k);
        s0[k] = sin(wedge * k);
    }
    for (int j = 0; j < m; j++)
        for (int k = 0; k < n; k++) {
            size_t i = (size_t)j * (size_t)n + (size_t)k;
            uint64_t h = hash_u64(key, i);
            double u1 = (j + gicache_unit(h, 0)) / m, d = wedge * gicache_unit(h, 32);
            double st = sqrt(u1), ct = sqrt(1 - u1), cp, sp, bc = band[j] * dc[k];
            double bs = band[j] * ds[k];
            Vec3 dir;

            if (n >= 16) {
                gicache_turn_by(c0[k], s0[k], d, &cp, &sp);
            } else {
                cp = cos(wedge * k + d);
                sp = sin(wedge * k + d);
            }
            /* vec3_from_frame()'s sum, its frame's vectors t1 and t2 made once */
            dir = vec3_add(vec3_add(vec3_scale(t1, (real)(st * cp)),
                                    vec3_scale(t2, (real)(st * sp))),
                           vec3_scale(normal, (real)ct));
            r[i] = sample(ctx, dir, &lc[i]);
            if (r[i] < INFINITY)
                inverse += 1 / r[i];
            else
                escaped++;
            /* Within 30 degrees of the plane: how far along it, that way. */
            if (ct <= 0.5 && r[i] < INFINITY && r[i] * st > 0) {
                int s = gicache_sector(cp, sp);
                double q = 1 / (r[i] * st);
                float f = q < FLT_MAX ? (float)q : FLT_MAX;
                sees[s] = f > sees[s] ? f : sees[s];
            }
            r[i] = 1 / (r[i] > near ? r[i] : near); /* nearness, for the gradient */
            sum = colour_add(sum, lc[i]);
            /* Turning the normal about w changes cos theta by w . (N x dir),
             * N x dir = sin theta (-sin phi t1 + cos phi t2): over the
             * stratum, its light times the integral of that over the solid
             * angle (band j's share times wedge k's vector), over pi (exact
             * for light constant over each stratum; a tan theta weight at
             * the ray itself grows without bound near the horizon). Summed
             * along t1 and t2 apart. */
            turn_c[0] += bc * lc[i].r;
            turn_c[1] += bc * lc[i].g;
            turn_c[2] += bc * lc[i].b;
            turn_s[0] += bs * lc[i].r;
            turn_s[1] += bs * lc[i].g;
            turn_s[2] += bs * lc[i].b;
        }
    for (int c = 0; c < 3; c++)
        v->rot[c] = vec3_add(vec3_scale(t1, (real)(turn_c[c] / ANGLE_PI)),
                             vec3_scale(t2, (real)(turn_s[c] / ANGLE_PI)));
    v->g = colour_scale(sum, 1.0 / (double)cells);
    gicache_translation(t1, t2, m, n, lc, r, sweep, v->trans);
    *harmonic = inverse > 0 ? (double)cells / inverse : INFINITY;
    *open = escaped / (double)cells;
    free(lc);
    free(r);
    free(band);
    return 0;
}

void gicache_limit(GiValue *v, double reach)
{
    double g[3] = {v->g.r, v->g.g, v->g.b};

    for (int c = 0; c < 3; c++) {
        double slope = (double)vec3_length(v->trans[c]);
        if (slope * reach > g[c])
            v->trans[c] = slope > 0 ? vec3_scale(v->trans[c], (real)(g[c] / (slope * reach)))
                                    : v->trans[c];
    }
}

double gicache_error(const GiPlace *place, Vec3 x, Vec3 nx)
{
    Vec3 d = vec3_sub(x, place->point);
    double cosine = (double)vec3_dot(nx, place->normal);
    double ahead = (double)vec3_dot(d, vec3_add(nx, place->normal)) / 2, a, b;

    if (ahead < -GICACHE_FRONT * place->radius)
        return INFINITY;
    /* x along the record's plane, in gicache_gather()'s frame */
    a = (double)vec3_dot(d, vec3_from_frame(place->normal, 1, 0, 0));
    b = (double)vec3_dot(d, vec3_from_frame(place->normal, 0, 1, 0));
    if (sqrt(a * a + b * b) * place->near[gicache_sector(a, b)] > 1)
        return INFINITY;
    return (double)vec3_length(d) / place->radius + sqrt(cosine < 1 ? 1 - cosine : 0);
}

double gicache_weight(double e, double a)
{
    if (!(e < a))
        return 0;
    return e > 1e-12 ? 1 / e - 1 / a : 1e12;
}

Colour gicache_extrapolate(const GiPlace *place, const GiValue *v, Vec3 x, Vec3 nx)
{
    Vec3 turn = vec3_cross(place->normal, nx), move = vec3_sub(x, place->point);
    double c[3] = {v->g.r, v->g.g, v->g.b};

    for (int k = 0; k < 3; k++) {
        c[k] += (double)vec3_dot(turn, v->rot[k]) + (double)vec3_dot(move, v->trans[k]);
        c[k] = c[k] > 0 ? c[k] : 0;
    }
    return colour(c[0], c[1], c[2]);
}
